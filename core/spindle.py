"""The spindle: SPINDL with RPM, ON, OFF and NEUTRL (manual §4.5, subroutine SPINDL 001
L37566-37637; options 19, 27, 34, 89, 127, 129), read in docs/research/spindle-tool.md.

The kernel keeps the spindle's state and its M codes; the spindle-type plugin selected by
option 19 turns a speed into the S command (``select``). An RPM SPINDL outputs a non-motion
block of its own at once, carrying S and, when the spindle starts or reverses, the
direction M code (TABLEM 4 CLW, 5 CCLW); OFF outputs TABLEM(6) (or S0 under option 127).
A machine without an S register (REGFOR(12) = 0) gets no S word and no speed comment.

``SPINDL/f,SFM[,CLW|CCLW][,RANGE,r][,RADIUS,XCOORD|YCOORD|ZCOORD|R][,MAXIPM,v][,MAXRPM,s]``
establishes the SFM mode of manual §4.4 (001 L14436-14462; core/motion/sfm.py): the
spindle range is locked (SFMLOK: LOCRNG does nothing, RANGE,r chooses it), and every
cutting path is split into pieces, each carrying its own S in its block. A spindle that is
off, reverses or changes range is started by the statement at the speed for the present
point's radius. Any other SPINDL statement ends the mode ("RPM MODE ESTABLISHED"), and so
does FEDRAT/n,IPM under option 2 = 1.
"""

from __future__ import annotations

from collections.abc import Callable
from math import inf

from gecent.core.absent import ABSENT
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
from gecent.core.motion.ladder import SpeedLadder
from gecent.core.motion.linear import TWO_AXIS
from gecent.core.motion.sfm import (
    ESTABLISHED,
    MAXIPM_EXCEEDED,
    RPM_ESTABLISHED,
    piece_feed,
    plan,
    range_feed_limits,
    spindle_speed,
    step_fraction,
)
from gecent.core.output.block import Block, Code
from gecent.core.output.element import OutputElement
from gecent.core.spindle_sfm import leave_sfm, machine_mm, radial_axis, sfm_request
from gecent.core.spindle_types import (
    CCLW,
    CLW,
    NO_DIRECTION,
    SAME_SPEED,
    Running,
    SpindleRequest,
    SpindleType,
)
from gecent.core.spindle_words import HOLDING, check_rpm_words, hold, neutral, speed_and_range
from gecent.core.state import SFM, SPINDLE_COMMAND, SPINDLE_M, SPINDLE_RANGE, PostState

TOO_FAST_FOR_THREADING = "SPINDLE SPEED IS TOO HIGH FOR THREADING"
MACFUN_TYPE = 7  # option 19 = 7: the machine's MACFUN computes S (§4.5.8)
_DIRECTION_WORDS = {"CLW": CLW, "CCLW": CCLW}
_M_CELL = {CLW: 4, CCLW: 5}
_OFF_CELL = 6


class SpindleElement:
    """SPINDL on a single-head machine."""

    def __init__(
        self,
        state: PostState,
        output: OutputElement,
        spindle_type: Callable[[int], SpindleType | None],
        warn: Callable[[Diagnostic], None],
        macfun: Callable[[HookPoint], MacfunHandler | None] | None = None,
        length: Callable[[float], float] | None = None,
    ) -> None:
        machine = state.machine
        self.state = state
        # a length of a statement in the CL unit, in machine units (UNITS; SFM's RADIUS,r)
        self.length = length if length is not None else float
        self.output = output
        self.warn = warn
        self.macfun = macfun
        self.has_s_register = machine.registers.formats[12] is not None
        self.type_number = int(machine.number_option(19))
        self.spindle_type: SpindleType | None = None
        if self.has_s_register:
            if self.type_number == MACFUN_TYPE:  # SPTYPE's own branch to MACSRT
                from gecent.core.spindle_macfun import MachineComputedSpindle

                self.spindle_type = MachineComputedSpindle()
            else:
                self.spindle_type = spindle_type(self.type_number)
        self._ladder: SpeedLadder | None = None  # the locked range's speeds while in SFM
        # option 171 = 1: "should redundant S words be output? 1 = no" (001 L26354-26368);
        # the S command the control holds (None: not known, as after NEUTRL)
        self.drop_redundant_s = machine.number_option(171) == 1
        self.s_in_force: float | None = None

    def statement(self, statement: Statement) -> None:
        words = [a.name for a in statement.args if isinstance(a, Word)]
        if "SFM" in words:
            self._sfm(statement, words)
            return
        if "NEUTRL" in words:
            neutral(self.state, self.output, statement, self.has_s_register)
            self.s_in_force = None  # (option 99's S, or none: not known here)
            return
        held = [w for w in words if w in HOLDING]
        if not held:
            check_rpm_words(statement, words)
        if self.state.sfm.active:
            leave_sfm(self.state)  # any other SPINDL ends the SFM mode (option 2, L24361)
            self.warn(Diagnostic(RPM_ESTABLISHED, statement.where))
        if held:
            hold(self.state, self.output, self.warn, statement, held[0])
            return
        if "OFF" in words:
            if len(statement.args) != 1:
                raise InputError("SPINDL/OFF takes nothing else", statement.where)
            self._off(statement)
            return
        speed, requested_range = speed_and_range(statement)
        self._on(statement.where, statement.number, speed, requested_range, words)

    def change_speed(
        self, speed: float, where: SourcePosition, record: int, in_range: int | None = None
    ) -> None:
        """A speed change the postprocessor makes itself (COUPLE's drop to the lowest
        speed of the range and the return to speed), as SPINDL/speed[,RANGE,r] would."""
        self._on(where, record, speed, in_range, [])

    # -- SFM (manual §4.4) ------------------------------------------------------------------

    def _sfm(self, statement: Statement, words: list[str]) -> None:
        """SPINDL/f,SFM (001 L14436-14462): SFMFLG, SFMDES, SPNDIR, ISRNGE, ISFMOD/SFMRAD,
        SFMAXI, SFMAXR, SFMLOK. The spindle is started (or reversed, or shifted to RANGE,r)
        at the speed for the present point's radius; a spindle turning as asked is left
        alone, and the first cut gives it its speed."""
        where = statement.where
        machine = self.state.machine
        request = sfm_request(statement, words, radial_axis(machine))
        if not self.has_s_register:
            raise InputError("SPINDL/SFM needs an S register (REGFOR(12) is 0)", where)
        if self.spindle_type is None:
            raise NotYetSupported(f"spindle type {self.type_number} (option 19)", where)
        if request.radius_axis == 2 and machine.number_option(22) in TWO_AXIS:
            raise InputError("SPINDL/SFM RADIUS,ZCOORD on a machine with two axes", where)
        ranges = self.spindle_type.range_count(machine)
        requested_range = request.range
        if requested_range is not None and requested_range > ranges:
            self.warn(Diagnostic("RANGE REQUESTED IS NOT AVAILABLE, USE HIGHEST", where))
            requested_range = ranges
        sfm = self.state.sfm
        sfm.active = True
        sfm.surface_feet = request.surface_feet
        sfm.radius_axis = request.radius_axis
        sfm.fixed_radius = self.length(request.fixed_radius)
        sfm.maximum_rpm = request.maximum_rpm
        sfm.locked_range = None  # the statement itself may choose the range (LOCRNG)
        if request.maximum_ipm is not None:
            feed = self.state.feed
            high = range_feed_limits(machine, feed.range)[1]
            feed.maximum_ipm = min(request.maximum_ipm * 25.4 / machine_mm(machine), high)
        self.warn(Diagnostic(ESTABLISHED, where))
        spindle = self.state.spindle
        direction = request.direction
        if (
            not spindle.on
            or spindle.speed is None
            or (direction is not None and direction != spindle.direction)
            or (requested_range is not None and requested_range != spindle.range)
        ):
            number = self._starting_range(requested_range)
            speed = self._starting_speed(number)
            turning = [w for w in words if w in _DIRECTION_WORDS]
            self._on(where, statement.number, speed, number, turning)
        sfm.locked_range = spindle.range
        self._ladder = self._speed_ladder(spindle.range)
        sfm.driver = self
        self.state.remember(SFM, request.surface_feet)
        if self.state.head:
            # a multihead program's SFM information block (CODE 17, DBFSEG(11) = 4): the
            # merge pass compares the heads' surface speeds (001 L7336-7346, L7626-7645)
            block = Block(Code.MULTIHEAD_1, statement.number)
            block.cells[2] = float(self.state.multihead_op)
            block.cells[3] = request.surface_feet
            block.cells[8] = float(self.state.head)
            block.cells[11] = 4.0
            block.cells[15] = float(Code.MULTIHEAD_1)
            self.output.emit(block)

    def _starting_range(self, requested_range: int | None) -> int:
        """The range SFM will lock: RANGE,r; else the present one of a turning spindle; else
        LOCRNG's, the lowest range holding the speed for the present radius (the highest
        range on the centre line)."""
        assert self.spindle_type is not None
        machine = self.state.machine
        spindle = self.state.spindle
        if requested_range is not None:
            return requested_range
        if spindle.on and spindle.speed is not None:
            return spindle.range
        sfm = self.state.sfm
        speed = spindle_speed(sfm.surface_feet, self._present_radius())
        if sfm.maximum_rpm is not None:
            speed = min(speed, sfm.maximum_rpm)
        if speed == inf:
            return self.spindle_type.range_count(machine)
        request = SpindleRequest(speed, None, spindle.direction or CLW)
        return self.spindle_type.select(machine, request).range

    def _starting_speed(self, range_number: int) -> float:
        """The speed SFMO would give the present point in that range (the bracket rule of a
        table, MAXRPM, the range's top on the centre line); the exact speed when SFM cannot
        start there, which the type then holds to its range with its comment."""
        radius = self._present_radius()
        surface = self.state.sfm.surface_feet
        start = plan(surface, radius, radius, self._speed_ladder(range_number))
        return start.pieces[0].speed if start.pieces else start.start_speed

    def _present_radius(self) -> float:
        """The radius of the present point in inches: SFMRAD's fixed radius, or the absolute
        value of the RADIUS coordinate on the step grid."""
        sfm = self.state.sfm
        inches = machine_mm(self.state.machine) / 25.4
        if sfm.radius_axis is None:
            return sfm.fixed_radius * inches
        step = self.state.machine.number_option(14)
        return abs(self.state.position.present[sfm.radius_axis]) * step * inches

    def _speed_ladder(self, range_number: int) -> SpeedLadder:
        """The locked range's speeds as the type gives them (speed_limits, table_speeds)."""
        assert self.spindle_type is not None
        machine = self.state.machine
        low, high = self.spindle_type.speed_limits(machine, range_number)
        table = self.spindle_type.table_speeds(machine, range_number)
        if table is not None:
            return SpeedLadder(table[0], table[-1], table, maximum=self.state.sfm.maximum_rpm)
        option_15 = machine.number_option(15)
        if option_15 == 0:
            raise MachineDefinitionError(
                machine.origin,
                "optab",
                15,
                "SFM on a variable spindle (types 1, 10, 18) steps the speed by option 15; "
                "it must not be 0",
            )
        return SpeedLadder(low, high, None, step_fraction(option_15), self.state.sfm.maximum_rpm)

    def ladder(self) -> SpeedLadder:
        """The speeds of the locked range (SurfaceSpeedDriver)."""
        assert self._ladder is not None, "no SPINDL/SFM has been given"
        return self._ladder

    def turn(self, speed: float, where: SourcePosition, record: int) -> None:
        """A piece of an SFM path turns at ``speed`` (SurfaceSpeedDriver): SPTYPE's S command
        waits for the piece's own block (SPNCOM rides in the block OUTPUT emits next); then
        TSTSAF's feed, F_IPM = F_IPR x S in IPR mode, within FRMAX and MAXIPM."""
        spindle = self.state.spindle
        if not spindle.on or spindle.speed is None or abs(spindle.speed - speed) > SAME_SPEED:
            self._on(where, record, speed, self.state.sfm.locked_range, [], ride=True)
        feed = self.state.feed
        assert spindle.speed is not None
        ipm, exceeded = piece_feed(self.state.machine, feed, spindle.speed)
        if exceeded and feed.ipm != ipm:  # once as the feed comes to MAXIPM, not per piece
            self.warn(Diagnostic(MAXIPM_EXCEEDED, where))
        if ipm is not None:
            feed.ipm = ipm

    def _on(
        self,
        where: SourcePosition,
        record: int,
        speed: float | None,
        requested_range: int | None,
        words: list[str],
        *,
        ride: bool = False,
    ) -> None:
        """The speed block of SPINDL; with ``ride`` the S command waits for the next block
        instead (an SFM piece's own motion block)."""
        machine = self.state.machine
        spindle = self.state.spindle
        if requested_range is None and self.state.sfm.locked_range is not None:
            requested_range = self.state.sfm.locked_range  # SFMLOK: LOCRNG does nothing
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
            if getattr(self.spindle_type, "names_missing_direction", False):
                self.warn(Diagnostic(NO_DIRECTION, where))  # (TYPE03/04/10/13/16's comment)
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
        running: Running | None = None
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
                self.state.pending.rpm = None
                if step.dwell:
                    block = self.output.dwell(step.dwell)
                    block.record = record
                else:
                    block = Block(Code.NONMOTION, record)
                self.output.output(block)
        if selection is not None and selection.range_cell is not None:
            # the gear first, then the spindle's direction (TYPE03, 001 L39227-39290)
            code = machine.m_code(selection.range_cell)
            if code is None:
                self._store(selection.range_cell, where)  # comment 22
            elif code != spindle.range_code:
                self.output.store_m(code)
                spindle.range_code = code
        cells = selection.direction_cells if selection and selection.direction_cells else _M_CELL
        range_changed = selection is not None and selection.range != spindle.range
        # option 77: the spindle-on M code in the S block (0), a block before it (+1) or a
        # block after it (-1); an SFM piece's S rides in its motion block with its M
        placement = 0.0 if ride else machine.number_option(77)
        turn_on_cell = None
        if not was_on or reversed_ or (cells is not _M_CELL and range_changed):
            if placement < 0:
                turn_on_cell = cells[direction]
            else:
                self._store(cells[direction], where)
                if placement > 0:
                    self.output.flush_m(record)
        spindle.speed, spindle.direction, spindle.on = speed, direction, True
        spindle.restart = None  # (a tool change's stop: this SPINDL starts it)
        if selection is not None:
            spindle.speed, spindle.range = selection.speed, selection.range
            # option 171 = 1: an S the control holds already is not output
            redundant = self.drop_redundant_s and selection.command == self.s_in_force
            if not redundant or selection.steps:
                self.state.pending.spindle = selection.command
                self.s_in_force = selection.command
            self.state.pending.rpm = selection.speed
            self.state.remember(SPINDLE_COMMAND, selection.command)
            self.state.remember(SPINDLE_RANGE, float(selection.range))
        self.state.remember(SPINDLE_M, machine.m_code(cells[direction]))
        if self.state.threading.coupled and spindle.speed > machine.number_option(175):
            self.warn(Diagnostic(TOO_FAST_FOR_THREADING, where))
        if selection is not None and selection.dwell_after:
            block = self.output.dwell(selection.dwell_after)
            block.record = record
            self.output.output(block)
            self._turn_on_after(turn_on_cell, where, record)
            return
        if ride:
            return
        pending = self.state.pending
        if self.drop_redundant_s and pending.spindle is ABSENT and pending.m_code is ABSENT:
            # its S was redundant (option 171) and it has no M: no block
            self._turn_on_after(turn_on_cell, where, record)
            return
        self.output.output(Block(Code.NONMOTION, record))
        self._turn_on_after(turn_on_cell, where, record)
        if selection is None:
            return
        seconds = 0.0
        own_dwells = getattr(self.spindle_type, "own_dwells", False)
        if range_changed and not selection.steps and not own_dwells:
            seconds = machine.number_option(54)  # option 54: the range-change dwell
        if running is not None and abs(selection.speed - running.speed) > SAME_SPEED:
            # option 193: the dwell for a change of speed (one dwell block: the longer)
            seconds = max(seconds, machine.number_option(193))
        if seconds > 0:
            block = self.output.dwell(seconds)
            block.record = record
            self.output.output(block)

    def _turn_on_after(self, cell: int | None, where: SourcePosition, record: int) -> None:
        """Option 77 = -1: the spindle-on M code in a block of its own after the S block."""
        if cell is not None and self.output.store_cell(cell, self.warn, where) is not None:
            self.output.flush_m(record)

    def _off(self, statement: Statement) -> None:
        machine = self.state.machine
        spindle = self.state.spindle
        spindle.on = False
        spindle.restart = None
        spindle.range_code = None
        if machine.number_option(129) == 0:
            spindle.range = 1
        if machine.number_option(127) == 1:
            if not self.has_s_register:
                # the S0 is the only way off the machine file gives (no M05 fallback):
                # the file contradicts itself, whatever the part program says
                raise MachineDefinitionError(
                    machine.origin,
                    "optab",
                    127,
                    "option 127 = 1 turns the spindle off by an S0 code (001 L25902-25910), "
                    f"but machine {machine.label} has no S register (REGFOR(12)) to punch "
                    "it in; give the S register or option 127 = 0 (TABLEM(6), M05)",
                )
            self.state.pending.spindle = 0.0
            self.s_in_force = 0.0
            self.state.pending.rpm = 0.0
            self.output.output(Block(Code.NONMOTION, statement.number))
            return
        self.state.remember(SPINDLE_M, None)
        if self.output.store_cell(_OFF_CELL, self.warn, statement.where) is not None:
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
