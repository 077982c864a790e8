"""The spindle: SPINDL with RPM, ON and OFF (manual §4.5, subroutine SPINDL 001
L37566-37637; options 19, 27, 34, 89, 127, 129), read in docs/research/spindle-tool.md.

The kernel keeps the spindle's state and its M codes; the spindle-type plugin selected by
option 19 turns a speed into the S command (``select``). An RPM SPINDL outputs a non-motion
block of its own at once, carrying S and, when the spindle starts or reverses, the
direction M code (TABLEM 4 CLW, 5 CCLW); OFF outputs TABLEM(6) (or S0 under option 127).
A machine without an S register (REGFOR(12) = 0) gets no S word and no speed comment.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from itertools import pairwise
from typing import Protocol, runtime_checkable

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import (
    Diagnostic,
    FatalError,
    InputError,
    MachineDefinitionError,
    NotYetSupported,
    SourcePosition,
)
from gecent.core.families import HookPoint, MacfunHandler
from gecent.core.machine.definition import MachineDefinition
from gecent.core.output.block import Block, Code
from gecent.core.output.element import OutputElement
from gecent.core.reinstate import SPINDLE_COMMAND, SPINDLE_M, SPINDLE_RANGE
from gecent.core.state import PostState

CLW, CCLW = 1, -1
_DIRECTION_WORDS = {"CLW": CLW, "CCLW": CCLW}
_M_CELL = {CLW: 4, CCLW: 5}
_OFF_CELL = 6


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
    number: int
    name: str
    section: str

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
TOO_FAST_FOR_THREADING = "SPINDLE SPEED IS TOO HIGH FOR THREADING"
NO_DIRECTION = "NO DIRECTION GIVEN IN FIRST SPINDLE STATEMENT"
_EXACT = 1e-6  # RPM: a table speed this close to the request is the request


def lowest_range(ranges: tuple[tuple[float, ...], ...], speed: float) -> int | None:
    """LOCRNG: the lowest range (1-based) whose speeds span ``speed`` (001 L33927-33960)."""
    for number, speeds in enumerate(ranges, start=1):
        if speeds and min(speeds) - _EXACT <= speed <= max(speeds) + _EXACT:
            return number
    return None


def limited(speed: float, low: float, high: float) -> tuple[float, tuple[str, ...]]:
    """A speed outside the table: the nearer listed extreme, with DSRROW's comment 80 or
    63 (001 L14588-14590, L30766-30777)."""
    if speed < low - _EXACT:
        return low, (LOWEST_OUTPUT,)
    if speed > high + _EXACT:
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
    spans it (LOCRNG), else the range holding the nearer end of the whole table."""
    if requested is not None:
        return max(1, min(requested, len(ranges)))
    number = lowest_range(ranges, speed)
    if number is not None:
        return number
    everything = [s for speeds in ranges for s in speeds]
    target = min(everything) if speed < min(everything) else max(everything)
    return next(n for n, speeds in enumerate(ranges, start=1) if target in speeds)


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
        if abs(table_speed - wanted) <= _EXACT:
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
    """Table types scan each range upward: a range out of order is a machine-file error."""
    for number, speeds in enumerate(ranges, start=1):
        if not speeds or any(b < a for a, b in pairwise(speeds)):
            raise MachineDefinitionError(
                machine.origin,
                "spindle_table",
                "speeds",
                f"{kind}: range {number} must hold its speeds in ascending order; "
                f"found {list(speeds)}",
            )


class SpindleElement:
    """SPINDL on a single-head machine."""

    def __init__(
        self,
        state: PostState,
        output: OutputElement,
        spindle_type: Callable[[int], SpindleType | None],
        warn: Callable[[Diagnostic], None],
        macfun: Callable[[HookPoint], MacfunHandler | None] | None = None,
    ) -> None:
        machine = state.machine
        self.state = state
        self.output = output
        self.warn = warn
        self.macfun = macfun
        self.has_s_register = machine.registers.formats[12] is not None
        self.type_number = int(machine.number_option(19))
        self.spindle_type = spindle_type(self.type_number) if self.has_s_register else None

    def statement(self, statement: Statement) -> None:
        words = [a.name for a in statement.args if isinstance(a, Word)]
        unbuilt = [w for w in words if w not in ("RPM", "CLW", "CCLW", "RANGE", "ON", "OFF")]
        if unbuilt:
            raise NotYetSupported(f"SPINDL/{unbuilt[0]}", statement.where)
        if "OFF" in words:
            if len(statement.args) != 1:
                raise InputError("SPINDL/OFF takes nothing else", statement.where)
            self._off(statement)
            return
        speed, requested_range = _speed_and_range(statement)
        self._on(statement.where, statement.number, speed, requested_range, words)

    def change_speed(
        self, speed: float, where: SourcePosition, record: int, in_range: int | None = None
    ) -> None:
        """A speed change the postprocessor makes itself (COUPLE's drop to the lowest
        speed of the range and the return to speed), as SPINDL/speed[,RANGE,r] would."""
        self._on(where, record, speed, in_range, [])

    def _on(
        self,
        where: SourcePosition,
        record: int,
        speed: float | None,
        requested_range: int | None,
        words: list[str],
    ) -> None:
        machine = self.state.machine
        spindle = self.state.spindle
        if speed is None:
            speed = spindle.speed
        if speed is None:
            speed = assumed_speed(machine, where)
            self.warn(Diagnostic("OPTION VALUE IS ASSUMED FOR THE SPINDLE SPEED", where))
        if speed < 0:
            raise InputError(f"SPINDL expects a speed >= 0, found {speed:g}", where)
        directions = [_DIRECTION_WORDS[w] for w in words if w in _DIRECTION_WORDS]
        if len(directions) > 1:
            raise InputError("SPINDL takes one of CLW and CCLW", where)
        direction = directions[0] if directions else spindle.direction
        if direction == 0:
            assumed = machine.number_option(34)
            if assumed == 0:
                raise InputError(
                    "SPINDL needs CLW or CCLW: option 34 = 0 assumes no direction", where
                )
            direction = CLW if assumed > 0 else CCLW
        reversed_ = spindle.on and direction != spindle.direction
        was_on = spindle.on
        if reversed_:
            self.warn(Diagnostic("WARNING--SPINDLE DIRECTION HAS CHANGED", where))
            delay = machine.number_option(89)
            if delay:
                self._store(_OFF_CELL, where)
                self.output.output(self.output.dwell(delay))
                spindle.on = False  # stopped for the reversal: no protective shift after it
        if requested_range is not None and requested_range > machine.number_option(7):
            self.warn(Diagnostic("RANGE REQUESTED IS NOT AVAILABLE, USE HIGHEST", where))
            requested_range = int(machine.number_option(7))
        selection = None
        if self.has_s_register:
            if self.spindle_type is None:
                raise NotYetSupported(f"spindle type {self.type_number} (option 19)", where)
            running = (
                Running(spindle.speed, spindle.range)
                if spindle.on and spindle.speed is not None
                else None
            )
            tool = self.state.tool.number
            request = SpindleRequest(
                speed,
                requested_range,
                direction,
                running,
                None if tool is None else int(tool),
                macfun=self.macfun,
            )
            selection = self.spindle_type.select(machine, request)
            for comment in selection.comments:
                self.warn(Diagnostic(comment, where))
            range_change = running is not None and selection.range != running.range
            if range_change and machine.number_option(194) == 1 and selection.stop_cell is None:
                self._store(_OFF_CELL, where)  # option 194: stop before a range change
                self.output.output(Block(Code.AUX_ONLY, record))
                was_on = False
            if selection.stop_cell is not None:
                self._store(selection.stop_cell, where)
                self.output.output(Block(Code.AUX_ONLY, record))
            if selection.stop_comment:
                self.warn(Diagnostic(selection.stop_comment, where))
            for step in selection.steps:
                # protective shifting: each intermediate speed in a block of its own, with
                # its dwell (001 L14773-14800, L15080-15111)
                self.state.pending.spindle = step.command
                if step.dwell:
                    block = self.output.dwell(step.dwell)
                    block.record = record
                else:
                    block = Block(Code.NONMOTION, record)
                self.output.output(block)
        cells = selection.direction_cells if selection and selection.direction_cells else _M_CELL
        range_changed = selection is not None and selection.range != spindle.range
        if not was_on or reversed_ or (cells is not _M_CELL and range_changed):
            self._store(cells[direction], where)
        if selection is not None and selection.range_cell is not None:
            code = machine.m_code(selection.range_cell)
            if code is None:
                self._store(selection.range_cell, where)  # comment 22
            elif code != spindle.range_code:
                self.output.store_m(code)
                spindle.range_code = code
        spindle.speed, spindle.direction, spindle.on = speed, direction, True
        if selection is not None:
            spindle.speed, spindle.range = selection.speed, selection.range
            self.state.pending.spindle = selection.command
            self.state.remember(SPINDLE_COMMAND, selection.command)
            self.state.remember(SPINDLE_RANGE, float(selection.range))
        self.state.remember(SPINDLE_M, machine.m_code(cells[direction]))
        if self.state.threading.coupled and spindle.speed > machine.number_option(175):
            self.warn(Diagnostic(TOO_FAST_FOR_THREADING, where))
        if selection is not None and selection.dwell_after:
            block = self.output.dwell(selection.dwell_after)
            block.record = record
            self.output.output(block)
            return
        self.output.output(Block(Code.NONMOTION, record))
        if selection is not None and range_changed and not selection.steps:
            seconds = machine.number_option(54)
            if seconds > 0 and not getattr(self.spindle_type, "own_dwells", False):
                block = self.output.dwell(seconds)  # option 54: the range-change dwell
                block.record = record
                self.output.output(block)

    def _off(self, statement: Statement) -> None:
        machine = self.state.machine
        spindle = self.state.spindle
        spindle.on = False
        spindle.range_code = None
        if machine.number_option(129) == 0:
            spindle.range = 1
        if machine.number_option(127) == 1:
            if not self.has_s_register:
                raise NotYetSupported("spindle off by S0 (option 127 = 1) without an S register")
            self.state.pending.spindle = 0.0
            self.output.output(Block(Code.NONMOTION, statement.number))
            return
        self._store(_OFF_CELL, statement.where)
        self.state.remember(SPINDLE_M, None)
        self.output.output(Block(Code.AUX_ONLY, statement.number))

    def _store(self, cell: int, where: SourcePosition) -> None:
        self.output.store_cell(cell, self.warn, where)


def assumed_speed(machine: MachineDefinition, where: SourcePosition | None) -> float:
    """Option 27, the speed assumed when none was ever given; 0 stops processing and a
    negative value means "error if no initial spindle speed": fatal 24 (001 L24722-24727)."""
    speed = machine.number_option(27)
    if speed <= 0:
        raise FatalError(24, f"option 27 = {speed:g}", where)
    return speed


def _speed_and_range(statement: Statement) -> tuple[float | None, int | None]:
    """The speed is the first number not taken by RANGE,r; minor words may come before or
    after it (SPINDL/10,RPM,CLW or SPINDL/RPM,10,CLW as Creo writes it)."""
    speed: float | None = None
    requested_range: int | None = None
    args = statement.args
    index = 0
    while index < len(args):
        arg = args[index]
        if isinstance(arg, Word) and arg.name == "RANGE":
            if index + 1 >= len(args) or isinstance(args[index + 1], Word):
                raise InputError("SPINDL RANGE expects a range number", statement.where)
            requested_range = int(float(args[index + 1]))  # type: ignore[arg-type]
            index += 2
            continue
        if not isinstance(arg, Word):
            if speed is not None:
                raise InputError("SPINDL expects one speed", statement.where)
            speed = float(arg)
        index += 1
    return speed, requested_range
