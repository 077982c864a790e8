"""The CL record model (manual §3.3, 001 L2859-3656): one typed, immutable record per CL
record, whichever reader produced it, each with its source position.

Record types: 1000 part-program text, 2000 postprocessor statement, 3000 surface data
(circle), 5000 motion (subtype 3 FROM, 4 GODLTA, 5 GOTO, 6 continuation), 6000 ARELEM
flags, 9000 multiaxis, 14000 FINI. Comments (``$$`` in APT source) are kept as records of
their own so listings can show them; they have no manual type.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import IntEnum

from gecent.core.errors import SourcePosition


class RecordType(IntEnum):
    COMMENT = 0
    TEXT = 1000
    STATEMENT = 2000
    SURFACE = 3000
    MOTION = 5000
    ARELEM = 6000
    MULTIAX = 9000
    FINI = 14000


class MotionSubtype(IntEnum):
    FROM = 3
    GODLTA = 4
    GOTO = 5
    CONTINUATION = 6


@dataclass(frozen=True, slots=True, eq=False)
class Word:
    """A vocabulary word as it appears in a statement; ``code`` is None for a word the
    vocabulary does not know (kept, never dropped: the dispatcher decides).

    Two words are the same word when they have the same code, as for the postprocessor,
    which reads only codes: MMPM and PREHET share code 171, and a binary CL file can only
    say 171.
    """

    name: str
    code: int | None

    def __str__(self) -> str:
        return self.name

    def _key(self) -> int | str:
        return self.code if self.code is not None else self.name

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Word) and self._key() == other._key()

    def __hash__(self) -> int:
        return hash(self._key())


Arg = Word | int | float
"""A statement argument: a word, an APT integer (binary CL only) or a number.

Numbers in postprocessor statements are always floating point, as an APT processor
writes them; ``int`` is kept for the integer items of binary CL files."""


@dataclass(slots=True, unsafe_hash=True)
class Record:
    """Where a record came from: ``line`` is the source line (APT text) or the ISN of the
    statement that produced it (binary CL); ``number`` the CL record number; ``offset`` the
    byte offset of a binary record. Records compare by position and content, not by file."""

    file: str = field(compare=False)
    line: int | None
    number: int
    offset: int | None = field(default=None, kw_only=True, compare=False)

    @property
    def where(self) -> SourcePosition:
        return SourcePosition(self.file, self.line, None, self.number, self.offset)


@dataclass(slots=True, unsafe_hash=True)
class Comment(Record):
    text: str


@dataclass(slots=True, unsafe_hash=True)
class PartText(Record):
    """Type 1000: the source statement text (binary CL files carry one per statement)."""

    text: str


@dataclass(slots=True, eq=False)
class Statement(Record):
    """Type 2000: a postprocessor statement, ``MAJOR/args``.

    ``args`` keeps the order and the word/number distinction of the source; ``text``
    holds the verbatim text of PARTNO, PPRINT and INSERT. Statements compare by major
    code (by name when the vocabulary has no code), like words.
    """

    major: str
    code: int | None
    args: tuple[Arg, ...] = ()
    text: str | None = None

    def _key(self) -> tuple[object, ...]:
        major = self.code if self.code is not None else self.major
        return (self.line, self.number, major, self.args, self.text)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Statement) and self._key() == other._key()

    def __hash__(self) -> int:
        return hash(self._key())

    def words(self) -> tuple[str, ...]:
        return tuple(a.name for a in self.args if isinstance(a, Word))

    def numbers(self) -> tuple[float, ...]:
        return tuple(float(a) for a in self.args if isinstance(a, int | float))

    def value_after(self, name: str) -> float | None:
        """The number right after the word ``name`` (OFSETL, k), or None."""
        args = self.args
        for index, arg in enumerate(args[:-1]):
            following = args[index + 1]
            if isinstance(arg, Word) and arg.name == name and not isinstance(following, Word):
                return float(following)
        return None


@dataclass(slots=True, unsafe_hash=True)
class Circle(Record):
    """Type 3000 circle (canonical form xc, yc, zc, i, j, k, r) governing the next motion."""

    values: tuple[float, ...]
    name: str = ""
    subscript: int = 0
    position: int = 0


@dataclass(slots=True, unsafe_hash=True)
class Surface(Record):
    """Type 3000 data for a drive surface that is not a circle (GECENT ignores it, §3.3.5)."""

    surface_type: int
    values: tuple[float, ...]
    name: str = ""
    subscript: int = 0
    position: int = 0
    use: int = 2


@dataclass(slots=True, unsafe_hash=True)
class Motion(Record):
    """Type 5000: points of a FROM, GODLTA, GOTO or continuation record.

    Each point is (x, y, z) or, under MULTAX, (x, y, z, i, j, k). RAPID stays a statement
    record of its own before the motion it governs, as in the binary CL file.
    """

    subtype: MotionSubtype
    points: tuple[tuple[float, ...], ...]
    name: str = ""
    subscript: int = 0


@dataclass(slots=True, unsafe_hash=True)
class Arelem(Record):
    """Type 6000 ARELEM flags: 4 INTOL, 5 OUTTOL, 6 CUTTER (others are read and kept)."""

    subtype: int
    values: tuple[float, ...]


@dataclass(slots=True, unsafe_hash=True)
class Multiax(Record):
    """Type 9000: multiaxis on (subtype 2) or off; points then carry i, j, k."""

    on: bool


@dataclass(slots=True, unsafe_hash=True)
class Fini(Record):
    """Type 14000: the end of the CL file."""


@dataclass(slots=True, unsafe_hash=True)
class Other(Record):
    """A record of a type GECENT reads and ignores (4000, 7000, 8000, 10000-13000, and
    unused subtypes), kept so that nothing is lost on the way through."""

    record_type: int
    subtype: int
    items: tuple[Arg, ...] = ()
