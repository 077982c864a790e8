"""CAM dialects (issue 19): what a CAM system writes that the post does not, mapped onto the
post's statements by user-defined macros, as a stage between the reader and the run::

    reader -> dialect stage (the dialect's macros; CSYS/MSYS frames) -> run

A dialect is a plugin (``register_dialects``): its name, how to recognise a file of its CAM
system from the file's first 64 KB (``sniff``), its macros (syntax macros only: they see
each record, and ignore it, pass it on, or issue others in its place) and the words that set
a coordinate frame (``frames``: the record's numbers to a rigid transform, part to machine).
The same stage serves ``gecent post``, ``gecent verify`` and ``gecent cl``, so the three read
a file alike. ``--dialect`` forces one (or ``none``).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from math import isclose
from typing import Any

from gecent.core.cl.apt_source import AptSourceReader, read_apt_source
from gecent.core.cl.nurbs import NurbsCollector
from gecent.core.cl.records import (
    Arelem,
    Circle,
    Comment,
    Motion,
    MotionSubtype,
    Record,
    Statement,
)
from gecent.core.cl.stream import read_cl
from gecent.core.errors import Diagnostic, InputError, SourcePosition
from gecent.core.macros.engine import MacroEngine
from gecent.core.macros.model import Kind, Macro
from gecent.core.macros.table import BUILT_IN_LAYER, MacroTable, Placed

SNIFF_CHARACTERS = 1 << 16
Matrix = tuple[tuple[float, float, float, float], ...]  # 3 rows of r1, r2, r3, t


@dataclass(frozen=True)
class Dialect:
    name: str
    title: str
    section: str
    sniff: Callable[[str], bool]
    macros: tuple[Macro, ...] = ()
    frames: dict[str, Callable[[Statement], Matrix]] = field(default_factory=dict)
    priority: int = 50  # lower is tried first (the more specific dialects)
    nurbs: bool = False  # NURBS/KNOT/CNTRL curves become straight moves (core/cl/nurbs.py)
    # comments that hold a statement (Creo's "$$-> CUTTER / 3.0"): read as that statement
    comment_words: frozenset[str] = frozenset()
    # the beginnings of the lines the tool list reads besides LOADTL, CUTTER... (uppercase)
    tool_lines: tuple[str, ...] = ()
    columns: int | None = None  # read no further along a line (CATIA: 72, tags after)
    # the macros see the tool's CL position in ``ctx.globals["position"]`` (APT geometry)
    track_position: bool = False

    def __post_init__(self) -> None:
        for macro in self.macros:
            if macro.kind is not Kind.SYNTAX:
                raise ValueError(f"dialect {self.name}: {macro.key} is not a user-defined macro")


def rigid(statement: Statement, rows: Matrix) -> Matrix:
    """The matrix, checked to be a rotation (orthonormal, not a mirror) and a translation."""
    columns = [[rows[r][c] for r in range(3)] for c in range(3)]
    for a in range(3):
        for b in range(3):
            dot = sum(columns[a][n] * columns[b][n] for n in range(3))
            if not isclose(dot, 1.0 if a == b else 0.0, abs_tol=1e-5):
                raise InputError(
                    f"{statement.major}: the axes are not a rotation (unit and square to "
                    "each other)",
                    statement.where,
                )
    (r11, r12, r13), (r21, r22, r23), (r31, r32, r33) = (row[:3] for row in rows)
    determinant = (
        r11 * (r22 * r33 - r23 * r32)
        - r12 * (r21 * r33 - r23 * r31)
        + r13 * (r21 * r32 - r22 * r31)
    )
    if determinant < 0:
        raise InputError(f"{statement.major}: the axes are mirrored (left-handed)", statement.where)
    return rows


def note_once(ctx: Any, word: str, text: str) -> None:
    """A word the dialect ignores, said once per file in the listing."""
    noted = ctx.globals.setdefault("noted", set())
    if word not in noted:
        noted.add(word)
        ctx.warn(text)


def ignore_noted(macros: Any, sdl: str, why: str) -> None:
    """A user-defined macro that ignores what it matches, with a note once per word."""

    def ignored(ctx: Any) -> None:
        word = getattr(ctx.record, "major", sdl)
        note_once(ctx, word, f"{word} IGNORED: {why}")

    macros.syntax(sdl, name=f"ignore {sdl}")(ignored)


IDENTITY: Matrix = ((1.0, 0.0, 0.0, 0.0), (0.0, 1.0, 0.0, 0.0), (0.0, 0.0, 1.0, 0.0))


def _point(rows: Matrix, x: float, y: float, z: float) -> tuple[float, float, float]:
    return tuple(r[0] * x + r[1] * y + r[2] * z + r[3] for r in rows)  # type: ignore[return-value]


def _vector(rows: Matrix, i: float, j: float, k: float) -> tuple[float, float, float]:
    return tuple(r[0] * i + r[1] * j + r[2] * k for r in rows)  # type: ignore[return-value]


def transformed(record: Record, rows: Matrix) -> Record:
    """A motion or circle record in the frame (part to machine); others as they are."""
    if isinstance(record, Motion):
        if record.subtype is MotionSubtype.GODLTA:
            values = record.points[0]
            delta = (0.0, 0.0, values[0]) if len(values) == 1 else values[:3]
            points: tuple[tuple[float, ...], ...] = (_vector(rows, *delta),)
        else:
            points = tuple(
                (*_point(rows, *p[:3]), *(_vector(rows, *p[3:6]) if len(p) >= 6 else ()))
                for p in record.points
            )
        return Motion(record.file, record.line, record.number, record.subtype, points,
                      record.name, record.subscript, offset=record.offset)  # fmt: skip
    if isinstance(record, Circle):
        v = record.values
        values = (*_point(rows, *v[:3]), *_vector(rows, *v[3:6]), *v[6:])
        return Circle(record.file, record.line, record.number, values, record.name,
                      record.subscript, record.position, offset=record.offset)  # fmt: skip
    return record


class _Collector:
    """The host the dialect's macros run on: what they pass on or issue is collected."""

    def __init__(self, warn: Callable[[Diagnostic], None] | None) -> None:
        self.collected: list[Record] = []
        self.current_record: Record | None = None
        self._warn = warn

    def builtin(self, record: Record) -> None:
        self.collected.append(record)

    def warn(self, diagnostic: Diagnostic) -> None:
        if self._warn is not None:
            self._warn(diagnostic)


class DialectStage:
    """The dialect's translation of a record stream (a generator: memory stays flat)."""

    def __init__(
        self,
        dialect: Dialect,
        warn: Callable[[Diagnostic], None] | None = None,
        metric: bool = False,
    ) -> None:
        self.dialect = dialect
        placed = [Placed(m, BUILT_IN_LAYER, n, "gecent") for n, m in enumerate(dialect.macros)]
        self.table = MacroTable.build(placed)
        self.host = _Collector(warn)
        self.engine = MacroEngine(self.table, self.host)  # type: ignore[arg-type]
        self.frame: Matrix | None = None
        self.tolerances: dict[int, float] = {}
        self.metric = metric  # until a UNITS says: the machine's unit, as the post takes it
        self._plain_goto = not self.table.covers((5000, int(MotionSubtype.GOTO)))

    def translate(self, records: Iterable[Record]) -> Iterator[Record]:
        nurbs: NurbsCollector | None = None
        plain = self._plain_goto
        track = self.dialect.track_position
        goto = MotionSubtype.GOTO
        # a GOTO passes untouched while no frame turns it and no NURBS is being collected
        # (the frame changes only in _translate, so this is settled after each other record)
        passing = plain and self.frame is None
        for record in records:
            if passing and type(record) is Motion and record.subtype is goto:
                if track:
                    self._follow(record)
                yield record  # the common case, as fast as it can be
                continue
            if nurbs is not None:
                if isinstance(record, Statement) and nurbs.take(record):
                    continue
                yield from self._translate(nurbs.motion(self._tolerance()))
                nurbs = None
            if self.dialect.nurbs and isinstance(record, Statement) and record.major == "NURBS":
                nurbs = NurbsCollector(record)
                passing = False
                continue
            self._note_tolerance(record)
            yield from self._translate(record)
            passing = plain and self.frame is None
        if nurbs is not None:
            yield from self._translate(nurbs.motion(self._tolerance()))

    def _note_tolerance(self, record: Record) -> None:
        """UNITS and INTOL/OUTTOL: what a NURBS curve is cut to."""
        if isinstance(record, Arelem) and record.subtype in (4, 5) and record.values:
            self.tolerances[record.subtype] = abs(record.values[0])
        elif isinstance(record, Statement) and record.major in ("UNITS", "UNIT"):
            self.metric = "MM" in record.words()

    def _tolerance(self) -> float:
        """INTOL (chords lie inside a curve), else OUTTOL, else 0.01 mm or 0.0004 in."""
        for subtype in (4, 5):
            if self.tolerances.get(subtype, 0.0) > 0:
                return self.tolerances[subtype]
        return 0.01 if self.metric else 0.0004

    def _translate(self, record: Record) -> Iterator[Record]:
        """One record through the frame and the dialect's macros."""
        if isinstance(record, Comment) and self.dialect.comment_words:
            record = self._commented(record)
        frames = self.dialect.frames
        if isinstance(record, Statement) and record.major in frames:
            rows = frames[record.major](record)
            self.frame = None if rows == IDENTITY else rows
            return
        if self.frame is not None:
            record = transformed(record, self.frame)
        elif self._plain_goto and type(record) is Motion and record.subtype is MotionSubtype.GOTO:
            yield record
            return
        if self.dialect.track_position and isinstance(record, Motion):
            self._follow(record)
        if not self.table.candidates(record):
            yield record
            return
        host = self.host
        host.current_record = record
        self.engine.dispatch(record)
        if host.collected:
            if self.dialect.track_position:
                for made in host.collected:
                    if isinstance(made, Motion):
                        self._follow(made)  # (a macro's own GOTO moves the tool too)
            yield from host.collected
            host.collected.clear()

    def _follow(self, record: Motion) -> None:
        """Where the tool is (CL units), for macros that work from it."""
        last = record.points[-1]
        if record.subtype is MotionSubtype.GODLTA:
            delta = last if len(last) >= 3 else (0.0, 0.0, last[0])
            x, y, z = self.engine.globals.get("position", (0.0, 0.0, 0.0))
            self.engine.globals["position"] = (x + delta[0], y + delta[1], z + delta[2])
        else:
            self.engine.globals["position"] = tuple(last[:3])

    def _commented(self, comment: Comment) -> Record:
        """A comment "-> WORD / ..." whose WORD the dialect lists, as that statement."""
        text = comment.text.lstrip()
        if not text.startswith("->"):
            return comment
        statement = text[2:].strip()
        word = statement.split("/", 1)[0].strip().upper()
        if word not in self.dialect.comment_words:
            return comment
        reader = AptSourceReader(comment.file)
        reader.number = comment.number - 1
        read = list(reader.read_lines([statement]))
        if len(read) != 1:
            return comment
        made = read[0]
        made.line = comment.line
        return made


def sniff_text(path: str) -> str:
    """A text CL file's first characters, for a dialect to recognise (binary: empty)."""
    try:
        with open(path, "rb") as handle:
            head = handle.read(SNIFF_CHARACTERS)
    except OSError:
        return ""
    if b"\0" in head:
        return ""
    return head.decode("latin-1")


def choose_dialect(path: str, plugins: Any, forced: str | None = None) -> Dialect | None:
    """The dialect named by ``forced`` ("none": none), else the first whose sniff knows
    the file; None when no dialect is needed."""
    dialects: list[Dialect] = sorted(
        (info.obj for info in plugins.family("dialects").values()),
        key=lambda d: (d.priority, d.name),
    )
    if forced is not None:
        if forced.lower() in ("none", "apt"):
            return None
        for dialect in dialects:
            if dialect.name == forced.lower():
                return dialect
        names = ", ".join(d.name for d in dialects) or "none installed"
        raise InputError(
            f"no dialect {forced!r} (dialects: {names}, or none)", SourcePosition(path)
        )
    head = sniff_text(path)
    if not head:
        return None
    for dialect in dialects:
        if dialect.sniff(head):
            return dialect
    return None


def in_dialect(
    records: Iterable[Record],
    dialect: Dialect | None,
    warn: Callable[[Diagnostic], None] | None,
    metric: bool = False,
) -> Iterator[Record]:
    if dialect is None:
        return iter(records)
    return DialectStage(dialect, warn, metric).translate(records)


def read_in_dialect(
    path: str,
    plugins: Any,
    dialect: Dialect | None,
    warn: Callable[[Diagnostic], None] | None = None,
    metric: bool = False,
) -> Iterator[Record]:
    """A CL file's records as the post reads them: through its dialect, if it has one
    (``metric``: the machine's unit is the millimetre, a file's unit until UNITS says)."""
    return in_dialect(read_raw(path, plugins, dialect), dialect, warn, metric)


def read_raw(path: str, plugins: Any, dialect: Dialect | None) -> Iterator[Record]:
    """A CL file's records before its dialect's words are mapped, read as the dialect
    wants its lines read (CATIA: to column 72)."""
    if dialect is not None and dialect.columns is not None and sniff_text(path):
        return read_apt_source(path, dialect.columns)
    return read_cl(path, plugins)
