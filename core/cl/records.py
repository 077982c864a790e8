"""The CL record model (manual §3.3, 001 L2859-3656): one typed, immutable record per CL
record, whichever reader produced it, each with its source position.

Record types: 1000 part-program text, 2000 postprocessor statement, 3000 surface data
(circle), 5000 motion (subtype 3 FROM, 4 GODLTA, 5 GOTO, 6 continuation), 6000 ARELEM
flags, 9000 multiaxis, 14000 FINI. Comments (``$$`` in APT source) are kept as records of
their own so listings can show them; they have no manual type.
"""

from __future__ import annotations

from dataclasses import dataclass
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


@dataclass(frozen=True, slots=True)
class Word:
    """A vocabulary word as it appears in a statement; ``code`` is None for a word the
    vocabulary does not know (kept, never dropped: the dispatcher decides)."""

    name: str
    code: int | None

    def __str__(self) -> str:
        return self.name


Arg = Word | int | float | str


@dataclass(frozen=True, slots=True)
class Record:
    file: str
    line: int | None
    number: int

    @property
    def where(self) -> SourcePosition:
        return SourcePosition(self.file, self.line, None, self.number)


@dataclass(frozen=True, slots=True)
class Comment(Record):
    text: str


@dataclass(frozen=True, slots=True)
class PartText(Record):
    """Type 1000: the source statement text (binary CL files carry one per statement)."""

    text: str


@dataclass(frozen=True, slots=True)
class Statement(Record):
    """Type 2000: a postprocessor statement, ``MAJOR/args``.

    ``args`` keeps the order and the int/float/text distinction of the source; ``text``
    holds the verbatim text of PARTNO, PPRINT and INSERT.
    """

    major: str
    code: int | None
    args: tuple[Arg, ...] = ()
    text: str | None = None

    def words(self) -> tuple[str, ...]:
        return tuple(a.name for a in self.args if isinstance(a, Word))

    def numbers(self) -> tuple[float, ...]:
        return tuple(float(a) for a in self.args if isinstance(a, int | float))


@dataclass(frozen=True, slots=True)
class Circle(Record):
    """Type 3000 circle (canonical form xc, yc, zc, i, j, k, r) governing the next motion."""

    values: tuple[float, ...]
    name: str = ""


@dataclass(frozen=True, slots=True)
class Motion(Record):
    """Type 5000: points of a FROM, GODLTA, GOTO or continuation record.

    Each point is (x, y, z) or, under MULTAX, (x, y, z, i, j, k). RAPID stays a statement
    record of its own before the motion it governs, as in the binary CL file.
    """

    subtype: MotionSubtype
    points: tuple[tuple[float, ...], ...]


@dataclass(frozen=True, slots=True)
class Arelem(Record):
    """Type 6000 ARELEM flags: 4 INTOL, 5 OUTTOL, 6 CUTTER (others are read and kept)."""

    subtype: int
    values: tuple[float, ...]


@dataclass(frozen=True, slots=True)
class Multiax(Record):
    """Type 9000: multiaxis on (subtype 2) or off; points then carry i, j, k."""

    on: bool


@dataclass(frozen=True, slots=True)
class Fini(Record):
    """Type 14000: the end of the CL file."""
