"""Finishing and emitting command blocks on a single-head contouring machine (OUTPUT and the
GEOUT conversion: manual §3.5, flow charts 8 and 12, 001 L19737-19848, L20074-20192).

OUTPUT completes a block: the CODE, the sequence number (negative under OPSKIP), for motion
the dimension G code (SELG) and the feed (FEDIPM, or a rapid marker), then the pending spindle
command and M code, which ride in the next block output. The conversion then turns the feed
into the control's command (CONTUR, core/feed/contour.py) and formats each register.
The sequence number and GEOUT's conversion are core/output/geout.py.
"""

from __future__ import annotations

from collections.abc import Callable
from math import asin, hypot

from gecent.core.absent import ABSENT, Absent
from gecent.core.errors import Diagnostic, InputError, SourcePosition
from gecent.core.feed.accel import AccelerationTest, acceleration_test
from gecent.core.feed.contour import FeedCommand, RapidCommand
from gecent.core.feed.limits import FeedLimits, HeadFeedLimit
from gecent.core.feed.optimise import FeedOptimiser
from gecent.core.feed.positioning import FeedType
from gecent.core.motion.cycles import CYCLE_TYPES
from gecent.core.motion.gcode import (
    CircularCodes,
    DimensionCode,
    LinearCodes,
    RotaryCodes,
    circle_code,
)
from gecent.core.motion.limits import SlideLimits
from gecent.core.motion.linear import TWO_AXIS
from gecent.core.motion.rotary import UNITS_PER_DEGREE
from gecent.core.output.block import Block, Code
from gecent.core.output.codes import (
    ABSOLUTE_CODES as ABSOLUTE_CODES,
)
from gecent.core.output.codes import (
    CIRCLE_CODES as CIRCLE_CODES,
)
from gecent.core.output.codes import (
    G_FILLED as G_FILLED,
)
from gecent.core.output.codes import (
    MOTION_CODES as MOTION_CODES,
)
from gecent.core.output.codes import (
    MOVING_CODES as MOVING_CODES,
)
from gecent.core.output.codes import (
    PLACED_CODES as PLACED_CODES,
)
from gecent.core.output.codes import (
    POSITION_CODES as POSITION_CODES,
)
from gecent.core.output.codes import (
    THREAD_CODES as THREAD_CODES,
)
from gecent.core.output.codes import (
    UNSHUFFLED as UNSHUFFLED,
)
from gecent.core.output.dwells import Dwells
from gecent.core.output.geout import GeoutConversion
from gecent.core.output.marks import stand_in
from gecent.core.output.modern import (
    CL_PLANES,
    INVERSE_TIME,
    SECOND_G,
    TOOL_LENGTH_ON,
    TOOL_LENGTH_REGISTER,
    ModernControl,
    machine_planes,
)
from gecent.core.output.other_blocks import OtherBlocks
from gecent.core.output.program import ModernProgram
from gecent.core.output.words import Word, WordFormatter
from gecent.core.state import SPINDLE_COMMAND, PostState

# comment 22 (001 L29355-29358): a TABLEM code the machine does not have
NOT_AVAILABLE = "REQUESTED MISCELLANEOUS FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE"
# non-motion blocks that may carry an option-98 F or an option-148 dwell (001 L9204-9258)
NON_MOTION_DWELL = frozenset({Code.NONMOTION, Code.G_ONLY, Code.END})
# option 1 = 2: a TOOLNO or SPINDL with no positioning move after it before the END
NO_MOVE_FOR_S_T = "NO MOTION BLOCK FOLLOWED THE LAST SPINDL OR TOOLNO: ITS S OR T IS NOT OUTPUT"


class OutputElement(ModernProgram, OtherBlocks, Dwells, GeoutConversion):
    def __init__(self, state: PostState) -> None:
        machine = state.machine
        self.state = state
        self.step = machine.number_option(14)
        self.linear_codes = LinearCodes(machine, self.step)
        self.circular_codes = CircularCodes(machine)
        self.feed = FeedCommand(machine)
        self.cut_minutes = 0.0
        self.dwell_minutes = 0.0
        self.words = WordFormatter(machine)
        self.rapid = RapidCommand(machine, self.words.shuffle[:3])
        self.optimiser = FeedOptimiser(machine, self.linear_codes, self.feed, self.words.shuffle)
        self.slide_limits = SlideLimits(machine, self.words.shuffle)
        dwell_g = machine.g_code(5)
        self.dwell_g: float | Absent = ABSENT if dwell_g is None else dwell_g
        # the F-register dwell's G: TABLEG(5), else the smallest code from G11 (GDIMUL 1) up
        self.dwell_code = (
            DimensionCode(int(dwell_g), 5, 1.0)
            if dwell_g is not None
            else next((c for c in self.linear_codes.codes[1:] if c is not None), None)
        )
        per_degree = UNITS_PER_DEGREE.get(machine.number_option(118), 1.0)
        self.rotary_codes = RotaryCodes(machine, machine.number_option(111) * per_degree)
        # option 38 = +-1: blocks without a G get TABLEG(5) (001 L24890-24907); -1: the
        # current cycle G code instead, the cycle-off TABLEG(1) until a cycle G is output
        self.fill_g = self.dwell_g if machine.number_option(38) in (1.0, -1.0) else ABSENT
        self.cycle_g_codes: frozenset[float] = frozenset()
        if machine.number_option(38) == -1.0:
            cells = [1, *(cell for _, cell in CYCLE_TYPES.values())]
            codes = [code for cell in cells if (code := machine.g_code(cell)) is not None]
            self.cycle_g_codes = frozenset(float(code) for code in codes)
            cycle_off = machine.g_code(1)
            self.fill_g = self.fill_g if cycle_off is None else float(cycle_off)
        self.tmark_code = stand_in(machine, 65)
        n_format = machine.registers.formats[1]
        # SEQLIM: the largest N the format holds (999 for format 30)
        self.sequence_limit = 10**n_format.left - 1 if n_format is not None else 1 << 62
        # where finished blocks go (core/output/sinks.py); the run sets it
        self.sink: Callable[[Block], None] = _nowhere
        # a register macro's place (core/macros): each block's words pass through it
        self.register_hook: Callable[[Block, list[Word]], list[Word]] | None = None
        self.diagnostics: list[Diagnostic] = []
        self.feed.diagnostics = self.diagnostics  # EIACOM's comment (magic three)
        self.assumed_feed = False
        # a positioning machine's feed type (option 78), set by the run; CYCLE/MILL in force
        self.positioning_feed: FeedType | None = None
        self.milling = False
        # option 1 = 1: a positioning block with a T repeats the spindle command (-1: not;
        # 2: as 1, in the motion block that takes the T)
        self.merge_s_with_t = machine.number_option(1) in (1.0, 2.0)
        # option 1 = 2: the S and T wait for the next motion block (001 L24332-24358)
        self.merge_into_motion = machine.number_option(1) == 2
        self.repeats_suppressed = machine.number_option(40) == 1
        axes = 2 if machine.number_option(22) in TWO_AXIS else 3
        self.modern = ModernControl(machine, self.step, axes)
        # options 252 != 0: G02/G03 in the machine's plane, mirrored by SHUFFL's signs
        self.mirrored = tuple(
            mirrored if machine.number_option(252) else False
            for _, mirrored in machine_planes(self.words.shuffle[:3])
        )
        self.separator = " " if machine.number_option(256) == 1 else ""
        end_code = machine.m_code(3)
        self.end_code: float | Absent = ABSENT if end_code is None else end_code
        length_code = machine.g_code(TOOL_LENGTH_ON)
        self.tool_length_code: float | Absent = ABSENT if length_code is None else length_code
        # a five-axis machine by data (docs/five-axis.md): its rotary step, G93, and the
        # control's tool-centre-point words in place of G43 (option 265 = 1)
        self.rotary_step = machine.number_option(119) or 0.0001
        self.inverse_time_code = machine.g_code(INVERSE_TIME) is not None
        f_format = machine.registers.formats[11]
        self.inverse_time_limit = f_format.largest if f_format is not None else 1e9
        chain = machine.kinematics
        tcp = chain is not None and machine.number_option(265) == 1
        self.tcp_on = chain.tcp_on if tcp and chain is not None else ""
        self.tcp_off = chain.tcp_off if tcp and chain is not None else ""
        self.tcp_active = False
        # slides computed for a head that swings the tool: the control's length offset
        # along Z would be wrong at any tilt (the tool's length is in the slides)
        self.no_length_offset = chain is not None and not tcp and bool(chain.heads)
        # option 25 < 0: each axis's own feed limits (FEDLIM); a multiaxis machine's
        # rotary axes have theirs after the linear ones
        self.feed_limits = FeedLimits(machine) if machine.number_option(25) < 0 else None
        self.head_limit = HeadFeedLimit(machine) if HeadFeedLimit.applies(machine) else None
        # pass 1 of a multihead run (manual §3.4.8.1): OUTPUT finishes the block and dumps
        # it; the GEOUT conversion waits for the merge pass (core/multihead)
        self.dump_only = state.head != 0
        # option 55 = 1: A/D testing holds each feed block for the corner after it
        self.accel_ipm: float | None = None
        # (a multihead head's run, dump-only, is refused A/D rather than left without it)
        self.accel: AccelerationTest | None = acceleration_test(self)

    # -- OUTPUT (flow chart 8) ------------------------------------------------------------

    def output(self, block: Block) -> None:
        state = self.state
        if block.code is Code.TMARK:
            self._tmark(block)
            return
        if self.optimiser.segmenting and block.code is Code.LINEAR and not state.feed.rapid_ipm:
            parts = self.optimiser.segmented(block, state.feed.ipm)
            if parts is not None:
                for part in parts:
                    self._output(part)
                return
        self._output(block)

    def _output(self, block: Block) -> None:
        state = self.state
        if self.merge_into_motion and _spindle_block(block, state):
            return  # SPINDL's own block under option 1 = 2: its S and M ride in the move
        if self.modern.frame and not self.modern.started:
            self._start_block(block.record)
        block.cells[15] = float(int(block.code))
        if block.code is Code.FROM and state.pending.m_code is not ABSENT:
            self.output(Block(Code.AUX_ONLY, block.record))  # "forced out" (001 L31370-31374)
        block.skipped = state.skipping
        restart = state.spindle.restart
        if restart is not None and block.code in MOVING_CODES:
            # the spindle the tool change stopped turns again before the tool moves
            state.spindle.restart = None
            state.spindle.on = True
            if state.pending.spindle is ABSENT:
                state.pending.spindle = restart[0]
            self.store_m(restart[1])
        if state.tool.length_pending and block.code in MOVING_CODES:
            # option 263 = 1: G43 H with the first move after a tool change, in a block of
            # its own before an arc or a cycle (G43 goes with a straight move)
            if self.no_length_offset:
                state.tool.length_pending = False
            elif self.tcp_on:
                self._tcp_block(block.record)
            elif block.code is Code.LINEAR:
                state.tool.length_pending = False
                block.cells[SECOND_G] = self.tool_length_code
                block.cells[TOOL_LENGTH_REGISTER] = float(state.tool.offset or 0)
            else:
                self.tool_length_block(block.record)
        if block.code in MOTION_CODES:
            self._motion(block)
        elif block.code in POSITION_CODES:
            self._position(block)
        elif block.code is Code.ROTARY_INCREMENTAL:
            self._rotary(block)
        elif block.code in THREAD_CODES:
            self._thread(block)
        elif block.code is Code.CYCLE:
            self._cycle(block)
        else:
            if block.code in NON_MOTION_DWELL or block.code is Code.DWELL:
                self._non_motion_dwell(block)
            if block.code in G_FILLED and block.cells[2] is ABSENT:
                block.cells[2] = self.fill_g
        held = block.cells[2]
        if self.cycle_g_codes and block.code in ABSOLUTE_CODES and held is not ABSENT:
            self.fill_g = held if float(held) in self.cycle_g_codes else self.fill_g  # 38 = -1
        if block.dwell_minutes:
            self.dwell_minutes += block.dwell_minutes
        waiting = self._merge_into_motion(block) if self.merge_into_motion else None
        if (
            self.merge_s_with_t
            and block.cells[13] is not ABSENT
            and state.pending.spindle is ABSENT
        ):
            # a tool change keeps its speed: the spindle command rides with the T (001 L1165)
            command = state.conditions.values.get(SPINDLE_COMMAND)
            if command is not None and command >= 0:
                state.pending.spindle = command
                state.pending.rpm = state.spindle.speed
        block.cells[12] = state.pending.spindle
        block.cells[14] = state.pending.m_code
        if (
            self.tcp_active
            and self.tcp_off
            and (block.cells[14] == self.end_code or block.cells[13] is not ABSENT)
        ):
            self._tcp_off(block.record)  # the tool centre point ends before M30 or M06
        if state.pending.spindle is not ABSENT and state.pending.rpm is not None:
            block.cells[20] = state.pending.rpm  # the speed in RPM, for the listing
        state.pending.rpm = None
        state.pending.spindle = ABSENT
        state.pending.m_code = ABSENT
        if waiting is not None:
            state.pending.spindle, state.pending.rpm = waiting
        if self.accel is not None:
            self.accel.take(block)  # A/D (option 55): numbered when it lets the block go
            return
        # numbered last: a block the move needs first (G95, a plane) takes the N before it
        block.cells[1] = self._sequence_number(block)
        self._emit(block)

    def finish_program(self, record: int | None) -> None:
        """FINI: an S or T still waiting under option 1 = 2 never went out (the part
        programmer gives SPINDL and TOOLNO right before a move, 001 L24346-24349)."""
        super().finish_program(record)
        pending = self.state.pending
        if self.merge_into_motion and (pending.tool is not ABSENT or pending.spindle is not ABSENT):
            self.diagnostics.append(Diagnostic(NO_MOVE_FOR_S_T, None))

    def flush_m(self, record: int | None = None) -> None:
        """STOREM(130): a waiting M code goes out in a block of its own now."""
        if self.state.pending.m_code is not ABSENT:
            self.output(Block(Code.AUX_ONLY, record))

    def _tmark(self, block: Block) -> None:
        """No N: the end-of-record code stands in its place; the pending S and M wait for
        the next block; an option-98 F is punched but not printed (001 L9298-9304)."""
        block.cells[15] = float(int(block.code))
        words = self.words.words(block, suppress=False, sequence=self.state.sequence)
        block.words = tuple((loc, printed) for loc, _, printed, _ in words if loc != 11)
        block.punch = self.tmark_code + "".join(letter + punched for _, letter, _, punched in words)
        self.emit(block)

    def store_m(self, code: float) -> None:
        """STOREM (001 L38041-38087): one M code waits for the next block; a second one
        first goes out in a block of its own with the waiting one (the same code again
        is the same request and waits once)."""
        pending = self.state.pending.m_code
        if pending is not ABSENT and pending != code:
            self.output(Block(Code.AUX_ONLY))
        self.state.pending.m_code = code

    def store_cell(
        self, cell: int, warn: Callable[[Diagnostic], None], where: SourcePosition | None
    ) -> float | None:
        """STOREM(cell): the machine's TABLEM(cell) waits for the next block; comment 22
        (and None) when the machine has no such code."""
        code = self.state.machine.m_code(cell)
        if code is None:
            warn(Diagnostic(NOT_AVAILABLE, where))
            return None
        self.store_m(code)
        return code

    def motion(self, block: Block) -> None:
        """A motion block's dimension G, feed command and cutting time (OUTPUT's CONTUR
        part): the multihead merge pass finishes the pieces of a split move with it."""
        self._motion(block)

    @property
    def emit(self) -> Callable[[Block], None]:
        """Where a finished block goes; under A/D, after the block it holds."""
        return self.sink if self.accel is None else self.accel.passing

    @emit.setter
    def emit(self, sink: Callable[[Block], None]) -> None:
        self.sink = sink

    def _motion(self, block: Block) -> None:
        assert block.steps is not None
        if block.code in CIRCLE_CODES:
            assert block.radius is not None
            clockwise = (int(block.code) > 0) != self.mirrored[abs(int(block.code)) - 10]
            turn = self._rotary_departure(block)
            code = (
                circle_code(self.circular_codes, self.rotary_codes, block.radius, clockwise, turn)
                if turn
                else self.circular_codes.select(block.radius, clockwise)
            )
            offsets = [float(v) for v in block.cells[8:11] if v is not ABSENT]
            # R from the arc offsets (an R-word arc, option 252 = 3, has none)
            length = sum(o * o for o in offsets) ** 0.5 if offsets else block.radius
        else:
            code = self.linear_codes.select(max(abs(s) for s in block.steps))
            turn = self._rotary_departure(block)
            if turn:
                code = self.rotary_codes.with_linear(code, turn)
            # a multiaxis move's feed goes by its path in part coordinates (E2, 001
            # L10985-11038), given with the block
            length = block.feed_length or sum((s * self.step) ** 2 for s in block.steps) ** 0.5
        block.cells[2] = float(code.code)
        if self.slide_limits.limits and self.accel_ipm is None:  # (A/D: tested whole)
            assert block.position is not None
            self.diagnostics.extend(self.slide_limits.test(block.position))
        feed = self.state.feed
        if feed.rapid_ipm:
            departures = tuple(s * self.step for s in block.steps)
            rapid, ipm = self.rapid.command(
                departures, code.gdimul, feed.rapid_ipm, low=feed.rapid_low
            )
            block.cells[11] = ABSENT if rapid is None else rapid
            if self.modern.rapid_code is not None:  # G00: the control's own rapid, no F
                block.cells[2] = self.modern.rapid_code
                block.cells[11] = ABSENT
            block.cells[19] = ipm
            block.rapid = True
            block.cut_minutes = sum(d * d for d in departures) ** 0.5 / ipm
            self.cut_minutes += block.cut_minutes
            return
        self._check_feed()
        wanted = feed.ipm if self.accel_ipm is None else self.accel_ipm
        if self.feed_limits is not None:
            # SELG and SELGCR both call FEDLIM (001 L1425-1436): an arc's axis feeds are
            # taken from its chord over its length, their mean along the arc
            path = _arc_length(block, self.step) if block.code in CIRCLE_CODES else length
            wanted, note = self.feed_limits.block_feed(block, wanted, path, feed.range)
            if note is not None:
                self.diagnostics.append(Diagnostic(note, None))
        if self.head_limit is not None:  # option 192, the rotary head's RPM
            path = _arc_length(block, self.step) if block.code in CIRCLE_CODES else length
            wanted, note = self.head_limit.block_feed(block, wanted, path)
            if note is not None:
                self.diagnostics.append(Diagnostic(note, None))
        multiplied = (
            self.optimiser.multiplied(block, wanted, code.gdimul, length, code.size_class)
            if self.optimiser.multiplying
            and block.code is Code.LINEAR
            and not self.modern.direct_feed
            else None
        )
        if self.optimiser.ijk_minimum > 0 and block.code is Code.LINEAR and not turn:
            multiplied = self.optimiser.ijk_command(  # option 224, the 100S in metric
                block, wanted, code.gdimul, length, code.size_class
            )
        if self.modern.direct_feed:
            command, ipm, f_format = self._direct_feed(block), wanted, None
            if wanted != feed.ipm and feed.ipm > 0:
                command *= wanted / feed.ipm  # (held by FEDLIM: per minute or per turn)
        elif multiplied is not None:
            command, ipm, f_format = multiplied
        else:
            command, ipm, f_format = self.feed.command(wanted, code.gdimul, length, code.size_class)
        block.cells[11] = command
        block.cells[19] = ipm
        block.f_format = f_format
        if block.code in CIRCLE_CODES:
            assert block.radius is not None
            arc = _arc_length(block, self.step)
            block.cut_minutes = arc / ipm
        else:
            block.cut_minutes = length / ipm
        self.cut_minutes += block.cut_minutes

    def _check_feed(self) -> None:
        """No FEDRAT before the first cut: option 23, once, with the manual's comment
        (001 L34083, L24674-24679)."""
        feed = self.state.feed
        if feed.programmed is None and not self.assumed_feed:
            assumed = self.state.machine.number_option(23)
            if assumed <= 0:
                raise InputError(
                    f"a feed move before any FEDRAT, and option 23 = {assumed:g} assumes no "
                    "feedrate (processing stops)",
                )  # (the run names the record being posted)
            self.assumed_feed = True
            self.diagnostics.append(Diagnostic("OPTION FEEDRATE ASSUMED."))
            feed.ipm = assumed


def _spindle_block(block: Block, state: PostState) -> bool:
    """A block with nothing of its own while an S waits: SPINDL's speed block."""
    return (
        block.code is Code.NONMOTION
        and state.pending.spindle is not ABSENT
        and not block.dwell_minutes
        and all(cell is ABSENT for cell in block.cells)
    )


def _nowhere(block: Block) -> None:
    raise RuntimeError("the output element has no sinks")


def _arc_length(block: Block, step: float) -> float:
    """The length of a quadrant segment: its chord over the radius gives the angle; a whole
    arc (option 253) knows its angle."""
    assert block.steps is not None and block.radius is not None
    if block.sweep is not None:  # a helix (option 261) rises along the plane's normal
        rise = block.steps[CL_PLANES[abs(int(block.code)) - 10][2]] * step
        return hypot(block.radius * block.sweep, rise)
    chord = sum((s * step) ** 2 for s in block.steps) ** 0.5
    ratio = min(1.0, chord / (2 * block.radius)) if block.radius else 0.0
    return 2 * block.radius * asin(ratio)
