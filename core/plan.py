"""GEPLAD, the planning pre-pass of a positioning machine (manual §2.2.2 C, 001 L473-476;
the overlay list, 001 L311-318; IGEFLG, 001 L17369-17375).

"If the modifier PLAN is given in the MACHIN statement and option 1 is + 1, the GEPLAD
overlay is called in to process and redevelop a new CL tape before continuing with the
regular GECENT III sequence"; GEPLAD is "the planning overlay which produces tool setups and
machinability features for positioning machines". The manual's "Section 4.10 on GEPLAD" is
not in it (§4.10 is the dwell section), so the pass is built as a 1970 drill post's planning
most likely was (docs/decisions.md, "issue 22 wave 7"):

* the new CL tape: each run of holes a tool drills under one CYCLE at one hole-top height
  (single-point GOTOs with nothing but comments between them) is put in nearest-neighbour
  order, starting from where the table stands before the run, to shorten the table travel.
  The order of holes is free there (each runs the same cycle), and nothing else moves:
  statements, heights, cycles and tools keep their places. The new tape numbers its
  records in their new order (a hole keeps its source line);
* the tool setups: one note per tool loaded (LOADTL, TOOLNO, TURRET), in the order of the
  tape, with the holes it makes; and one note with the table travel between holes as
  programmed and as planned;
* machinability (speeds and feeds from the work material) needs material tables the manual
  does not give: the planned tape keeps the part program's FEDRAT, SPINDL and CYCLE feeds.

Only the first MACHIN/GECENT's PLAN calls GEPLAD (GEMON asks GEINIT through IGEFLG once,
before the run); the planned tape carries that MACHIN without PLAN, so the run does not
meet it again.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field, replace
from math import dist

from gecent.core.cl.records import (
    Comment,
    Motion,
    MotionSubtype,
    PartText,
    Record,
    Statement,
    Word,
)
from gecent.core.errors import Diagnostic, GecentError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.selection import POSTPROCESSOR_NAME, MachinRequest, apply_machin_options
from gecent.core.motion.cycles import spindle_axis

PLAN = "PLAN"
TOOL_LOADS = ("LOADTL", "TOOLNO", "TURRET")
SAME_HEIGHT = 1e-9  # hole tops this close are one height (one cycle block on the tape)


def plans(machine: MachineDefinition, request: MachinRequest | None) -> bool:
    """GEMON calls GEPLAD when the first MACHIN/GECENT has PLAN and leaves option 1 = +1."""
    if request is None or PLAN not in request.modifiers:
        return False
    try:
        changed = apply_machin_options(machine, request)[0]
    except GecentError:  # (the run reports a bad MACHIN at its statement)
        return False
    return changed.option(1) == 1.0


@dataclass
class _Hole:
    """One hole of a run: its point and the text records that came just before it."""

    texts: list[Record]
    motion: Motion
    point: tuple[float, ...]


@dataclass
class ToolSetup:
    tool: str  # the load statement as written, e.g. "LOADTL/3"
    holes: int = 0


@dataclass
class PlannedTape:
    records: list[Record]
    setups: list[ToolSetup] = field(default_factory=list)
    travel_programmed: float = 0.0
    travel_planned: float = 0.0
    where: Record | None = None  # the MACHIN statement that asked for the plan

    def notes(self) -> list[Diagnostic]:
        at = self.where.where if self.where is not None else None
        notes = [
            Diagnostic(f"GEPLAD TOOL SETUP {n}: {s.tool}, {s.holes} HOLES", at)
            for n, s in enumerate(self.setups, 1)
        ]
        notes.append(
            Diagnostic(
                f"GEPLAD: TABLE TRAVEL BETWEEN HOLES {self.travel_programmed:.4f} AS "
                f"PROGRAMMED, {self.travel_planned:.4f} AS PLANNED",
                at,
            )
        )
        return notes


def planned_records(
    records: Iterable[Record], machine: MachineDefinition, warn: Callable[[Diagnostic], None]
) -> Iterator[Record]:
    """The planned tape for the run, made when the run starts reading (so a reading error
    stops the run as any other does); the setup notes go to ``warn`` first."""
    axis = spindle_axis(machine)
    tape = geplad(records, 2 if axis is None else axis)
    for note in tape.notes():
        warn(note)
    yield from tape.records


def geplad(records: Iterable[Record], spindle: int = 2) -> PlannedTape:
    """Plan the CL tape (the records of the whole part): see the module's docstring.
    ``spindle`` is the CL axis the holes are drilled along (option 59's Z, cycles.py
    ``spindle_axis``); the other two are the table's."""
    tape = PlannedTape([])
    table = tuple(k for k in range(3) if k != spindle)

    def across(point: tuple[float, ...]) -> tuple[float, float]:
        return (point[table[0]], point[table[1]])

    out = tape.records
    position: tuple[float, ...] | None = None  # where the table stands (None: not known)
    programmed: tuple[float, ...] | None = None  # where it would stand on the tape as given
    cycle_on = False
    run: list[_Hole] = []
    texts: list[Record] = []  # comments waiting for the next record

    def close_run() -> None:
        nonlocal position, programmed
        if not run:
            return
        before = programmed if programmed is not None else run[0].point
        tape.travel_programmed += _travel(across(before), [across(h.point) for h in run])
        programmed = run[-1].point
        start = position if position is not None else run[0].point
        ordered = _nearest_first(across(start), run, across)
        tape.travel_planned += _travel(across(start), [across(h.point) for h in ordered])
        for hole in ordered:
            out.extend(hole.texts)
            out.append(hole.motion)
        position = ordered[-1].point
        run.clear()

    for record in records:
        if isinstance(record, Comment | PartText):
            texts.append(record)
            continue
        hole_point = _single_hole(record) if cycle_on else None
        height = run[0].point[spindle] if run else None
        if (
            hole_point is not None
            and height is not None
            and abs(hole_point[spindle] - height) > SAME_HEIGHT
        ):
            close_run()  # a new hole-top height: a new cycle block, in its programmed place
        if hole_point is not None:
            assert isinstance(record, Motion)
            run.append(_Hole(texts, record, hole_point))
            texts = []
            if setup := tape.setups[-1:]:
                setup[0].holes += 1
            continue
        close_run()
        out.extend(texts)
        texts = []
        if isinstance(record, Statement):
            if record.major == "CYCLE" and record.args and isinstance(record.args[0], Word):
                cycle_on = record.args[0].name not in ("OFF", "INHIBT")
            elif record.major in TOOL_LOADS:
                tape.setups.append(ToolSetup(_written(record)))
            elif record.major == "MACHIN" and tape.where is None and _has_plan(record):
                tape.where = record
                record = replace(record, args=tuple(a for a in record.args if not _is_plan(a)))
        if isinstance(record, Motion):
            if record.subtype is MotionSubtype.GODLTA:
                position = programmed = None  # (an increment: the place is not followed)
            elif record.points:
                position = programmed = record.points[-1][:3]
        out.append(record)
    close_run()
    out.extend(texts)
    # a new tape numbers its records in their new order: the k-th record takes the k-th
    # number (the moved holes swap numbers among themselves; the N words keep climbing)
    numbers = sorted(r.number for r in out)
    out[:] = [
        r if r.number == n else replace(r, number=n) for r, n in zip(out, numbers, strict=True)
    ]
    return tape


def _single_hole(record: Record) -> tuple[float, ...] | None:
    """A hole's point: a GOTO record with one point (a hole under the cycle in force)."""
    if (
        isinstance(record, Motion)
        and record.subtype is MotionSubtype.GOTO
        and len(record.points) == 1
    ):
        return record.points[0][:3]
    return None


def _nearest_first(
    start: tuple[float, float],
    holes: list[_Hole],
    across: Callable[[tuple[float, ...]], tuple[float, float]],
) -> list[_Hole]:
    """Nearest-neighbour order from ``start`` on the table; ties keep the programmed order,
    so a run already in a good order (a row, a circle) stays as written."""
    left = list(holes)
    ordered: list[_Hole] = []
    here = start
    while left:
        best = min(range(len(left)), key=lambda i: (dist(here, across(left[i].point)), i))
        hole = left.pop(best)
        ordered.append(hole)
        here = across(hole.point)
    return ordered


def _travel(start: tuple[float, float], points: list[tuple[float, float]]) -> float:
    """The table's travel from ``start`` through ``points`` (the spindle's axis is not
    table travel)."""
    total = 0.0
    here = start
    for point in points:
        total += dist(here, point)
        here = point
    return total


def _has_plan(statement: Statement) -> bool:
    args = statement.args
    named_gecent = bool(args) and isinstance(args[0], Word) and args[0].name == POSTPROCESSOR_NAME
    return named_gecent and any(_is_plan(a) for a in args)


def _is_plan(arg: object) -> bool:
    return isinstance(arg, Word) and arg.name == PLAN


def _written(statement: Statement) -> str:
    shown = ",".join(str(a) if isinstance(a, Word) else f"{float(a):g}" for a in statement.args)
    return f"{statement.major}/{shown}"
