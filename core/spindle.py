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
from typing import Protocol, runtime_checkable

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import (
    Diagnostic,
    FatalError,
    InputError,
    NotYetSupported,
    SourcePosition,
)
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
class SpindleSelection:
    """What a spindle type makes of a requested speed: the speed the spindle will turn,
    the S command, the range, and the manual's comments. A type with range-and-direction
    M codes gives their TABLEM cells (``direction_cells``, by CLW/CCLW); a protective shift
    is the S command to go through first and its dwell in seconds."""

    speed: float
    command: float
    range: int = 1
    comments: tuple[str, ...] = field(default=())
    direction_cells: dict[int, int] | None = None
    shift: tuple[float, float] | None = None


@dataclass(frozen=True, slots=True)
class Running:
    """The spindle as it turns before the statement: its speed and range."""

    speed: float
    range: int


@runtime_checkable
class SpindleType(Protocol):
    number: int
    name: str
    section: str

    def select(
        self,
        machine: MachineDefinition,
        speed: float,
        requested_range: int | None,
        running: Running | None = None,
    ) -> SpindleSelection: ...


LOWEST_OUTPUT = "LOWEST SPEED IN RANGE IS OUTPUT."
NOT_FOUND = "SPINDLE SPEED COULD NOT BE FOUND."
TOO_FAST_FOR_THREADING = "SPINDLE SPEED IS TOO HIGH FOR THREADING"


def lowest_range(ranges: tuple[tuple[float, ...], ...], speed: float) -> int | None:
    """LOCRNG: the lowest range (1-based) whose speeds span ``speed`` (001 L33927-33960)."""
    for number, speeds in enumerate(ranges, start=1):
        if speeds and min(speeds) <= speed <= max(speeds):
            return number
    return None


def limited(speed: float, low: float, high: float) -> tuple[float, tuple[str, ...]]:
    """A speed outside the table: the nearer listed extreme, with DSRROW's comment 80 or
    63 (001 L14588-14590, L30766-30777)."""
    if speed < low:
        return low, (LOWEST_OUTPUT,)
    if speed > high:
        return high, (NOT_FOUND,)
    return speed, ()


class SpindleElement:
    """SPINDL on a single-head machine."""

    def __init__(
        self,
        state: PostState,
        output: OutputElement,
        spindle_type: Callable[[int], SpindleType | None],
        warn: Callable[[Diagnostic], None],
    ) -> None:
        machine = state.machine
        self.state = state
        self.output = output
        self.warn = warn
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
            selection = self.spindle_type.select(machine, speed, requested_range, running)
            for comment in selection.comments:
                self.warn(Diagnostic(comment, where))
            if selection.shift is not None:
                # protective shifting: the shift-point speed of the present range first, with
                # its dwell (001 L15080-15111)
                command, seconds = selection.shift
                self.state.pending.spindle = command
                block = self.output.dwell(seconds)
                block.record = record
                self.output.output(block)
        cells = selection.direction_cells if selection and selection.direction_cells else _M_CELL
        range_changed = selection is not None and selection.range != spindle.range
        if not was_on or reversed_ or (cells is not _M_CELL and range_changed):
            self._store(cells[direction], where)
        spindle.speed, spindle.direction, spindle.on = speed, direction, True
        if selection is not None:
            spindle.speed, spindle.range = selection.speed, selection.range
            self.state.pending.spindle = selection.command
            self.state.remember(SPINDLE_COMMAND, selection.command)
            self.state.remember(SPINDLE_RANGE, float(selection.range))
        self.state.remember(SPINDLE_M, machine.m_code(cells[direction]))
        if self.state.threading.coupled and spindle.speed > machine.number_option(175):
            self.warn(Diagnostic(TOO_FAST_FOR_THREADING, where))
        self.output.output(Block(Code.NONMOTION, record))

    def _off(self, statement: Statement) -> None:
        machine = self.state.machine
        spindle = self.state.spindle
        spindle.on = False
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
