"""The OUTPUT element's blocks other than contouring moves (flow chart 8): a positioning
machine's absolute blocks and their feed command (POSIT, POSFED), a thread block, an
incremental rotary block (SELGRO's code, the table's feed) and a control's canned-cycle
block. Mixed into OutputElement (core/output/element.py)."""

from __future__ import annotations

from collections.abc import Callable
from math import pi, radians

from gecent.core.absent import ABSENT, Absent
from gecent.core.errors import Diagnostic
from gecent.core.feed.contour import FeedCommand
from gecent.core.feed.positioning import XY, FeedContext, FeedType, Z
from gecent.core.machine.definition import ROTARY_CELLS
from gecent.core.motion.gcode import RotaryCodes
from gecent.core.motion.limits import SlideLimits
from gecent.core.motion.rounding import half_up_float
from gecent.core.output.block import Block, Code
from gecent.core.output.codes import MOVING_CODES
from gecent.core.output.modern import ModernControl
from gecent.core.output.words import WordFormatter
from gecent.core.state import PostState

# POSFED's range test (001 L11214-11216): gecent's wording, the manual gives none
COMMAND_ABOVE = "FEEDRATE COMMAND {:g} ABOVE THE MAXIMUM (OPTION 24); {:g} USED"
COMMAND_BELOW = "FEEDRATE COMMAND {:g} BELOW THE MINIMUM (OPTION 49); {:g} USED"


class OtherBlocks:
    """Mixed into OutputElement: what it needs of it is declared here."""

    state: PostState
    step: float
    diagnostics: list[Diagnostic]
    slide_limits: SlideLimits
    positioning_feed: FeedType | None
    milling: bool
    cut_minutes: float
    rotary_codes: RotaryCodes
    feed: FeedCommand
    modern: ModernControl
    words: WordFormatter
    repeats_suppressed: bool
    _check_feed: Callable[[], None]
    _direct_feed: Callable[[Block], float]

    def _cycle(self, block: Block) -> None:
        """A control's canned-cycle block (core/motion/control_cycles.py): its F is the
        feed itself (option 254)."""
        self._check_feed()
        feed = self.state.feed
        if self.modern.direct_feed:
            block.cells[11] = self._direct_feed(block)
        block.cells[19] = feed.ipm
        block.cut_minutes = block.feed_length / feed.ipm if feed.ipm > 0 else 0.0
        self.cut_minutes += block.cut_minutes
        self.modern.at = list(block.position or ())[: self.modern.axes] or None

    def _position(self, block: Block) -> None:
        """POSIT and POSFED (001 L34780-34878): an absolute positioning block's F command
        from the feed type, or the rapid marker: option 45's command (none when negative)
        at the rapid rate."""
        assert block.steps is not None and block.position is not None
        if self.slide_limits.limits:
            self.diagnostics.extend(self.slide_limits.test(block.position))
        length = sum((s * self.step) ** 2 for s in block.steps) ** 0.5
        feed = self.state.feed
        if block.rapid:
            limit = self.state.machine.number_option(45)
            block.cells[11] = limit if limit >= 0 else ABSENT
            ipm = abs(feed.rapid_ipm)
        else:
            assert self.positioning_feed is not None
            self._check_feed()
            spindle = self.state.spindle
            context = FeedContext(
                spindle.speed,
                spindle.range,
                feed.range,
                self.milling,
                Z if block.code is Code.POSITION_Z else XY,
            )
            command = self.positioning_feed.command(self.state.machine, feed.ipm, context)
            self.diagnostics.extend(Diagnostic(text) for text in command.comments)
            block.cells[11], ipm = self._position_command_limits(command.command, command.ipm)
        block.cells[19] = ipm
        block.cut_minutes = length / ipm if ipm > 0 else 0.0
        self.cut_minutes += block.cut_minutes

    def _position_command_limits(
        self, command: float | Absent, ipm: float
    ) -> tuple[float | Absent, float]:
        """POSFED's only test (001 L11214-11216, spec 05 §4): the feed command within its
        range extremes, options 49 and 24; the feed made then follows the command (a
        command is proportional to its feed in every positioning type)."""
        if command is ABSENT or not isinstance(command, float | int) or command <= 0:
            return command, ipm
        machine = self.state.machine
        highest, lowest = machine.number_option(24), machine.number_option(49)
        if highest > 0 and command > highest:
            self.diagnostics.append(Diagnostic(COMMAND_ABOVE.format(command, highest)))
            return highest, ipm * highest / command
        if lowest > 0 and command < lowest:
            self.diagnostics.append(Diagnostic(COMMAND_BELOW.format(command, lowest)))
            return lowest, ipm * lowest / command
        return command, ipm

    def _thread(self, block: Block) -> None:
        """A thread block comes finished from THREDO: no CONTUR, the lead and G are set;
        the F register the control may have held is overwritten by a threading rate."""
        if self.slide_limits.limits:
            assert block.position is not None
            self.diagnostics.extend(self.slide_limits.test(block.position))
        self.cut_minutes += block.cut_minutes
        self.words.previous_f = ABSENT

    def _rotary(self, block: Block) -> None:
        """An incremental rotary block: SELGRO's G code, and the feed over the arc the part
        radius (option 112) sweeps, held to the table's feed range (options 113, 114 in
        RPM) (001 L10936-10984, L6171-6282); after a RAPID, the table's rapid instead."""
        assert block.rotary is not None
        cell, degrees = block.rotary
        code = self.rotary_codes.select(abs(float(block.cells[cell])))  # type: ignore[arg-type]
        block.cells[2] = float(code.code)
        machine = self.state.machine
        radius = machine.number_option(112)
        length = radians(degrees) * radius
        per_rpm = 2 * pi * radius
        if block.rapid or self.state.feed.rapid_requested:
            # chart 8: DBFSEG(11) = -ROTRAP, option 115's RPM at the part radius, then
            # RAPFLG = 0 (001 L19839-19842, L18231-18235); the marker becomes the F as a
            # linear rapid's does: the feedrate number at that speed held to |option 45|,
            # none when option 45 < 0 (CONTUR, 001 L12530-12638)
            self.state.feed.rapid_requested = False
            ipm = machine.number_option(115) * per_rpm
            limit = machine.number_option(45)
            command = code.gdimul * ipm / length
            if command > abs(limit):
                command = abs(limit)
                ipm = command * length / code.gdimul
            f_register = machine.registers.formats[11]
            decimals = f_register.right if f_register is not None else 0
            block.cells[11] = half_up_float(command, decimals) if limit >= 0 else ABSENT
            block.cells[19] = ipm
            block.rapid = True
            block.cut_minutes = length / ipm
            self.cut_minutes += block.cut_minutes
            return
        low, high = machine.number_option(113) * per_rpm, machine.number_option(114) * per_rpm
        self._check_feed()
        ipm = min(max(self.state.feed.ipm, low), high)
        command, ipm, f_format = self.feed.command(ipm, code.gdimul, length, code.size_class)
        block.cells[11] = command
        block.cells[19] = ipm
        block.f_format = f_format
        block.cut_minutes = length / ipm
        self.cut_minutes += block.cut_minutes

    def _merge_into_motion(self, block: Block) -> tuple[float, float | None] | None:
        """Option 1 = 2: the held T goes into the next positioning move (with its X and Y,
        which option 40 never leaves out of a block with a T, 001 L24919-24927); any other
        block leaves the S waiting, returned to be put back after it."""
        pending = self.state.pending
        if block.code in MOVING_CODES:
            if pending.tool is not ABSENT:
                block.cells[13] = pending.tool
                pending.tool = ABSENT
                if self.repeats_suppressed and block.code is Code.POSITION_XY:
                    self._restore_positions(block)
            return None
        if pending.spindle is ABSENT:
            return None
        waiting = (pending.spindle, pending.rpm)
        pending.spindle, pending.rpm = ABSENT, None
        return waiting

    def _restore_positions(self, block: Block) -> None:
        """X and Y that option 40 left out of a positioning block as repeats, put back."""
        if block.position is None:
            return
        for axis in (0, 1):
            if block.cells[3 + axis] is ABSENT:
                block.cells[3 + axis] = block.position[axis] * self.step

    def _rotary_departure(self, block: Block) -> float:
        """SELGRO's measure for a multiaxis block (CODE 0 or a circle): the largest rotary
        departure in DBFSEG 6, 7, 18 (output units), 0.0 when it turns nothing. A
        five-axis machine by data (machine.kinematics) or absolute output (option
        251 = 1) has G01/G02/G03 without ranges: 0.0 there too (001 L6052-6069,
        L6150-6170, L6171-6282)."""
        machine = self.state.machine
        if machine.kinematics is not None or machine.number_option(251) == 1:
            return 0.0
        return max(
            (abs(float(v)) for cell in ROTARY_CELLS if (v := block.cells[cell]) is not ABSENT),
            default=0.0,
        )
