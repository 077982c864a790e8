"""ROTATE/TABLE|HEAD on a positioning machine: the absolute rotary system, ROTABA (manual
§3.4.5.1, 001 L5550-5626; ROTABA L35892-35937, ROTABL L36012-36053, RFTYPE L35850-35890,
ROTYP1 L36384-36446; §4.1.3, L11713-11808).

The register holds the table's position, not a travel. The control takes the shorter way
to a position, so a programmed travel of 180 degrees or more goes in moves of 179 degrees
along the programmed direction until the rest is shorter (W17: 90 -> 180 CLW via 271).
Each block is CODE +2 with the positioning G code (SET12) and, when the table has a feed
register of its own (option 139, type option 141), the rotary feed command in it.

Options: 117 (which way the scale counts up), 118 and 119 (output units and step), 120 = -2
(the sign of the output shows the direction of turning only), 206 (the way a CLW turns the
table), 220 and 221 (the table's travel limits), 115 (rapid speed, RPM), 112 (the part
radius the feeds are measured at). A RAPID before it makes the table move at rapid, one
shot: TABLEM(42) before, TABLEM(43) after (001 L5619-5626).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

from gecent.core.absent import ABSENT
from gecent.core.cl.records import Statement, Word
from gecent.core.errors import Diagnostic, InputError, MachineDefinitionError, NotYetSupported
from gecent.core.feed.positioning import FeedContext, FeedType
from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.positioning import set12
from gecent.core.motion.rotary import (
    HEAD_CELL,
    TABLE_CELL,
    UNITS_PER_DEGREE,
    TorchRotation,
    long_way_targets,
    parse_rotate,
    rotary_move,
    travel_limit_warning,
)
from gecent.core.motion.rotary_devices import checked_table_speed, is_table_speed
from gecent.core.motion.rounding import to_steps
from gecent.core.output.block import Block, Code
from gecent.core.state import PostState

SIGNED_DIRECTION = -2.0  # option 120: + for CLW, - for CCLW on absolute machines
RAPID_TABLE, FEED_TABLE = 42, 43  # TABLEM cells: table to rapid, back to feed
ASSUMED_FEED = "OPTION FEEDRATE IS ASSUMED."  # ROTATE's comment (001 L36080-36082)


@dataclass(frozen=True, slots=True)
class RotaryFeed:
    """The table's own feed register (option 139) and its command type (option 141)."""

    cell: int
    kind: FeedType


def rotary_feed(machine: MachineDefinition, kinds: Callable[[int], object]) -> RotaryFeed | None:
    """Option 141's rotary feed type in option 139's register; None when option 141 = 0
    (the table has no feed command of its own)."""
    number = int(machine.number_option(141))
    if number == 0:
        return None
    kind = kinds(number)
    if not isinstance(kind, FeedType):
        raise NotYetSupported(f"rotary feed type {number} (option 141): not installed")
    cell = int(machine.number_option(139))
    if not 1 <= cell < len(machine.registers.formats) or machine.registers.formats[cell] is None:
        raise MachineDefinitionError(
            machine.origin,
            "optab",
            139,
            f"rotary feed type {number} (option 141) needs the table's feed register: option "
            f"139 must name a DBFSEG cell with a REGFOR format, found {cell}",
        )
    return RotaryFeed(cell, kind)


class AbsoluteRotary:
    """ROTABA for a single-head positioning machine. ``positions`` is shared with the
    incremental element so that a MACHIN keeps nothing the other does not."""

    def __init__(
        self,
        state: PostState,
        emit: Callable[[Block], None],
        store_m: Callable[[float], None],
        warn: Callable[[Diagnostic], None],
        feed: RotaryFeed | None,
        positions: dict[int, float],
    ) -> None:
        machine = state.machine
        self.state = state
        self.emit = emit
        self.store_m = store_m
        self.warn = warn
        self.feed = feed
        self.positions = positions
        scaling = machine.number_option(118)
        if scaling not in UNITS_PER_DEGREE:
            raise NotYetSupported(f"rotary scaling option 118 = {scaling:g}")
        self.per_degree = UNITS_PER_DEGREE[scaling]
        self.step = machine.number_option(119) or 0.0001
        self.clw_increases = machine.number_option(117) >= 0
        self.signed = machine.number_option(120) == SIGNED_DIRECTION
        self.radius = machine.number_option(112)
        self.rapid_rpm = machine.number_option(115)
        cycle_off = machine.g_code(1)
        self.cycle_off = ABSENT if cycle_off is None else float(cycle_off)
        self.cut_minutes = 0.0  # the table's moves, added by the caller to the run's CUTIME
        self.torch = TorchRotation()

    def statement(self, statement: Statement) -> None:
        words = [a.name for a in statement.args if isinstance(a, Word)]
        if words[:1] == ["TORCH"]:
            self.torch.statement(statement, self.state.machine, self.emit, self.warn)
            return
        if is_table_speed(statement):
            checked_table_speed(statement, self.state.machine)  # refused: overlay GEMILL
        request = parse_rotate(statement, self.state.machine)
        cell = _register(self.state.machine, request.cell, statement)
        previous = self.positions[cell]
        move = rotary_move(
            previous,
            request.value,
            absolute=request.absolute,
            direction=request.direction,
            clw_increases=self.clw_increases,
        )
        if request.cell in (TABLE_CELL, HEAD_CELL):
            text = travel_limit_warning(
                self.state.machine,
                previous,
                move.travel,
                self.clw_increases,
                "TABLE" if request.cell == TABLE_CELL else "HEAD",
            )
            if text:
                self.warn(Diagnostic(text, statement.where))
        targets = long_way_targets(previous, move.travel, self.clw_increases)
        self.positions[cell] = move.position
        feed = self.state.feed
        rapid = feed.rapid_requested
        machine = self.state.machine
        if rapid and machine.m_code(RAPID_TABLE) is not None:
            self.store_m(machine.m_code(RAPID_TABLE))  # type: ignore[arg-type]
        ipm = self.rapid_ipm() if rapid else self._feed_ipm(statement)
        # SET12 (001 L35892-35937, L5612-5614): the positioning mode's G code, else TABLEG(1)
        mode_g = set12(self.state, statement.where)
        g_code = self.cycle_off if mode_g is None else mode_g
        part = abs(move.travel) / len(targets) if targets else 0.0
        direction = 1.0 if move.travel >= 0 else -1.0
        for index, target in enumerate(targets):
            block = Block(Code.ROTARY_ABSOLUTE, statement.number)
            block.cells[2] = g_code
            units = to_steps(target * self.per_degree, self.step) * self.step
            block.cells[cell] = direction * abs(units) if self.signed else units
            block.rapid = rapid
            block.segment = (index == 0, index == len(targets) - 1) if len(targets) > 1 else None
            if not rapid and self.feed is not None:
                command = self.feed.kind.command(machine, ipm, FeedContext())
                for comment in command.comments:
                    self.warn(Diagnostic(comment, statement.where))
                block.cells[self.feed.cell] = command.command
                ipm = command.ipm
            block.cells[19] = ipm
            length = math.radians(part) * self.radius
            block.cut_minutes = length / ipm if ipm > 0 and length > 0 else 0.0
            self.cut_minutes += block.cut_minutes
            self.emit(block)
        if rapid:
            feed.rapid_requested = False  # a table's rapid is one shot (001 L5625-5626)
            back = machine.m_code(FEED_TABLE)
            if back is not None and machine.m_code(RAPID_TABLE) is not None:
                self.store_m(back)

    def rapid_ipm(self) -> float:
        """ROTRAP: option 115's RPM at the part radius (option 112), in IPM."""
        return 2 * math.pi * self.radius * self.rapid_rpm

    def _feed_ipm(self, statement: Statement) -> float:
        """The feed in force; none programmed: option 23's, with ROTATE's comment."""
        feed = self.state.feed
        if feed.programmed is not None or feed.ipm > 0:
            return feed.ipm
        assumed = self.state.machine.number_option(23)
        if assumed <= 0:
            raise InputError(
                f"ROTATE before any FEDRAT, and option 23 = {assumed:g} assumes no feedrate",
                statement.where,
            )
        self.warn(Diagnostic(ASSUMED_FEED, statement.where))
        return assumed


def _register(machine: MachineDefinition, cell: int, statement: Statement) -> int:
    """The head's DBFSEG(6) or the table's DBFSEG(7); a machine with one rotary register
    drives either device with it (001 L1793-1796)."""
    if machine.registers.formats[cell] is not None:
        return cell
    other = TABLE_CELL if cell == HEAD_CELL else HEAD_CELL
    if machine.registers.formats[other] is None:
        raise InputError(
            f"ROTATE: machine {machine.label} has no rotary register (DBFSEG 6 or 7)",
            statement.where,
        )
    return other
