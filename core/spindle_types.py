"""The spindle-type protocol and the table logic every type shares (manual §4.5, 001
L14550-14603; SPTYPE L37732-37765, LOCRNG L33927-33960, DSRROW L30726-30790).

A spindle-type plugin (option 19) answers a :class:`SpindleRequest` with a
:class:`SpindleSelection`. What the types have in common lives here once: LOCRNG
(:func:`range_for`), DSRROW with option 90 (:func:`choose_speed`), the clamp to a range
with comments 80 and 63 (:func:`limited`), and :class:`TableSpindle`, the range, limit and
table answers of a type whose SRTAB holds its speeds.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from itertools import pairwise
from typing import Protocol, runtime_checkable

from gecent.core.errors import MachineDefinitionError
from gecent.core.families import HookPoint, MacfunHandler
from gecent.core.machine.definition import MachineDefinition

CLW, CCLW = 1, -1


@dataclass(frozen=True, slots=True)
class SpindleStep:
    """An intermediate speed a type outputs before the requested one (protective multiple
    shifting, §4.5.3.1 and §4.5.11.1): its S command, the range it turns in, and the dwell
    that follows it in the same block (None: a plain non-motion block)."""

    command: float
    range: int
    dwell: float | None = None


@dataclass(frozen=True, slots=True)
class SpindleSelection:
    """What a spindle type makes of a requested speed.

    ``speed`` is the speed the spindle will turn, ``command`` the S command, ``range`` the
    range, ``row`` the 0-based row of the speed in its range (None for variable types) and
    ``comments`` the manual's diagnostics. M codes, each a TABLEM cell:

    * ``direction_cells`` (by CLW/CCLW): combined range-and-direction codes that replace
      TABLEM 4/5, output when the spindle starts, reverses or changes range;
    * ``range_cell``: a range-only (or mode) code, output when its code differs from the
      last one output (types 3a, 14, 15, 16);

    ``steps`` are intermediate speeds output first (protective shifting); ``dwell_after`` a
    dwell block after the speed block (type 12's cross-over); ``stop_cell`` and
    ``stop_comment`` a stop block and a comment before the speed block (type 19).
    """

    speed: float
    command: float
    range: int = 1
    comments: tuple[str, ...] = field(default=())
    direction_cells: dict[int, int] | None = None
    range_cell: int | None = None
    steps: tuple[SpindleStep, ...] = field(default=())
    dwell_after: float | None = None
    stop_cell: int | None = None
    stop_comment: str | None = None
    row: int | None = None


@dataclass(frozen=True, slots=True)
class Running:
    """The spindle as it turns before the statement: its speed and range."""

    speed: float
    range: int


@dataclass(frozen=True, slots=True)
class SpindleRequest:
    """A SPINDL speed request as the kernel hands it to the type: the speed (RPM), the
    programmed RANGE,n (None: the type chooses), the direction (CLW = 1, CCLW = -1), the
    spindle as it turns (None when stopped), the tool in use (type 9), the head (type 13)
    and the machine's MACFUN handler lookup (type 7)."""

    speed: float
    range: int | None = None
    direction: int = 1
    running: Running | None = None
    tool: int | None = None
    head: int = 1
    macfun: Callable[[HookPoint], MacfunHandler | None] | None = None


@runtime_checkable
class SpindleType(Protocol):
    @property
    def number(self) -> int: ...

    @property
    def name(self) -> str: ...

    @property
    def section(self) -> str: ...

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection: ...

    def range_count(self, machine: MachineDefinition) -> int:
        """How many ranges the type offers on this machine (RANGE,n accepts 1..this)."""
        ...

    def speed_limits(self, machine: MachineDefinition, range_number: int) -> tuple[float, float]:
        """The lowest and highest speed of a range (SFM's "cannot start" test)."""
        ...

    def table_speeds(
        self, machine: MachineDefinition, range_number: int
    ) -> tuple[float, ...] | None:
        """The discrete speeds of a range, ascending, which SFM steps through; None for a
        type that is variable in SFM (types 1, 10, 18: SFM steps by option 15)."""
        ...


LOWEST_OUTPUT = "LOWEST SPEED IN RANGE IS OUTPUT."
NOT_FOUND = "SPINDLE SPEED COULD NOT BE FOUND."
NO_DIRECTION = "NO DIRECTION GIVEN IN FIRST SPINDLE STATEMENT"
SAME_SPEED = 1e-6  # RPM: a table speed this close to the request is the request


def lowest_range(ranges: tuple[tuple[float, ...], ...], speed: float) -> int | None:
    """LOCRNG: the lowest range (1-based) whose speeds span ``speed`` (001 L33927-33960)."""
    for number, speeds in enumerate(ranges, start=1):
        if speeds and min(speeds) - SAME_SPEED <= speed <= max(speeds) + SAME_SPEED:
            return number
    return None


def limited(speed: float, low: float, high: float) -> tuple[float, tuple[str, ...]]:
    """A speed outside the table: the nearer listed extreme, with DSRROW's comment 80 or
    63 (001 L14588-14590, L30766-30777)."""
    if speed < low - SAME_SPEED:
        return low, (LOWEST_OUTPUT,)
    if speed > high + SAME_SPEED:
        return high, (NOT_FOUND,)
    return speed, ()


@dataclass(frozen=True, slots=True)
class TableChoice:
    """DSRROW's answer: the range (1-based), the row (0-based within the range), the table
    speed chosen, and comment 80 or 63 when the request lay outside the range."""

    range: int
    row: int
    speed: float
    comments: tuple[str, ...] = ()


def range_for(ranges: tuple[tuple[float, ...], ...], speed: float, requested: int | None) -> int:
    """The range a speed is looked up in: the programmed one, else the lowest range that
    spans it (LOCRNG), else the range with the nearest end."""
    if requested is not None:
        return max(1, min(requested, len(ranges)))
    number = lowest_range(ranges, speed)
    if number is not None:
        return number
    # outside every range: the range whose end is nearest (the table's own end beyond it,
    # the nearer neighbour in a gap between ranges; a tie takes the lower range)
    return min(
        (n for n, speeds in enumerate(ranges, start=1) if speeds),
        key=lambda n: (min(abs(speed - s) for s in (ranges[n - 1][0], ranges[n - 1][-1])), n),
    )


def choose_speed(
    ranges: tuple[tuple[float, ...], ...],
    speed: float,
    requested_range: int | None,
    selection_rule: float,
) -> TableChoice:
    """DSRROW (001 L30726-30790, §4.5 common rules): the range by :func:`range_for`, then
    the exact table speed, or by option 90 (``selection_rule``) the next lower (-1), the
    closest (0; a tie takes the lower) or the next higher (+1) speed; outside the range its
    nearer end with comment 80 (below) or 63 (above). Speeds ascend within a range."""
    number = range_for(ranges, speed, requested_range)
    speeds = ranges[number - 1]
    wanted, comments = limited(speed, speeds[0], speeds[-1])
    if comments:
        row = 0 if wanted == speeds[0] else len(speeds) - 1
        return TableChoice(number, row, speeds[row], comments)
    for row, table_speed in enumerate(speeds):
        if abs(table_speed - wanted) <= SAME_SPEED:
            return TableChoice(number, row, table_speed)
    above = next(row for row, table_speed in enumerate(speeds) if table_speed > wanted)
    below = above - 1
    if selection_rule < 0:
        row = below
    elif selection_rule > 0:
        row = above
    else:
        row = above if speeds[above] - wanted < wanted - speeds[below] else below
    return TableChoice(number, row, speeds[row])


def check_ascending(
    machine: MachineDefinition, ranges: tuple[tuple[float, ...], ...], kind: str
) -> None:
    """Table types scan each range upward: no table, or a range empty or out of order, is
    a machine-file error."""
    if not ranges:
        raise MachineDefinitionError(
            machine.origin, "spindle_table", "speeds", f"{kind} needs a table of speeds"
        )
    for number, speeds in enumerate(ranges, start=1):
        if not speeds or any(b < a for a, b in pairwise(speeds)):
            raise MachineDefinitionError(
                machine.origin,
                "spindle_table",
                "speeds",
                f"{kind}: range {number} must hold its speeds in ascending order; "
                f"found {list(speeds)}",
            )


def speed_table(machine: MachineDefinition, kind: str) -> tuple[tuple[float, ...], ...]:
    """SRTAB's speeds, option 7 ranges of option 8, each ascending (a machine-file error
    naming ``kind`` otherwise)."""
    ranges = machine.spindle_ranges()
    check_ascending(machine, ranges, kind)
    return ranges


class TableSpindle:
    """What a discrete type answers from its table: ``ranges`` (by default SRTAB's speeds,
    :func:`speed_table`) gives the range count, each range's limits and its speeds."""

    number: int

    @property
    def kind(self) -> str:
        return f"spindle type {self.number}"

    def ranges(self, machine: MachineDefinition) -> tuple[tuple[float, ...], ...]:
        return speed_table(machine, self.kind)

    def range_count(self, machine: MachineDefinition) -> int:
        return len(self.ranges(machine))

    def speed_limits(self, machine: MachineDefinition, range_number: int) -> tuple[float, float]:
        speeds = self.ranges(machine)[range_number - 1]
        return speeds[0], speeds[-1]

    def table_speeds(
        self, machine: MachineDefinition, range_number: int
    ) -> tuple[float, ...] | None:
        return self.ranges(machine)[range_number - 1]


class OneRangeSpindle:
    """A variable type with one range, SRTAB(1) lowest .. SRTAB(2) highest: ``limits``
    (checked by each type) gives the range's limits; SFM steps through it by option 15
    unless the type lists the speeds it can be commanded (``table_speeds``)."""

    def limits(self, machine: MachineDefinition) -> tuple[float, float]:
        raise NotImplementedError

    def range_count(self, machine: MachineDefinition) -> int:
        return 1

    def speed_limits(self, machine: MachineDefinition, range_number: int) -> tuple[float, float]:
        return self.limits(machine)

    def table_speeds(
        self, machine: MachineDefinition, range_number: int
    ) -> tuple[float, ...] | None:
        return None  # variable: SFM steps by option 15
