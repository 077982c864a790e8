"""Finishing and emitting command blocks on a single-head contouring machine (OUTPUT and the
GEOUT conversion: manual §3.5, flow charts 8 and 12, 001 L19737-19848, L20074-20192).

OUTPUT completes a block: the CODE, the sequence number (negative under OPSKIP), for motion
the dimension G code (SELG) and the feed (FEDIPM, or a rapid marker), then the pending spindle
command and M code, which ride in the next block output. The conversion then turns the feed
into the control's command (CONTUR, core/feed/contour.py) and formats each register.
"""

from __future__ import annotations

from math import asin, pi, radians

from gecent.core.absent import ABSENT, Absent
from gecent.core.errors import Diagnostic, FatalError, RunStopped, SourcePosition
from gecent.core.feed.contour import FeedCommand, RapidCommand
from gecent.core.machine.regformat import decode_regfor
from gecent.core.machine.shuffle import cell_map
from gecent.core.motion.gcode import CircularCodes, LinearCodes, RotaryCodes
from gecent.core.motion.segments import segments
from gecent.core.output.block import Block, Code
from gecent.core.output.format import FormatOverflow, RegisterFormatter
from gecent.core.output.marks import stand_in
from gecent.core.state import PostState

CIRCLE_CODES = frozenset(
    {
        Code.CIRCLE_XY_CLW,
        Code.CIRCLE_XY_CCLW,
        Code.CIRCLE_ZX_CLW,
        Code.CIRCLE_ZX_CCLW,
        Code.CIRCLE_YZ_CLW,
        Code.CIRCLE_YZ_CCLW,
    }
)
MOTION_CODES = frozenset({Code.LINEAR}) | CIRCLE_CODES
NEVER_OUTPUT = frozenset({15, 19, 20})  # CODE, feed in IPM, speed in RPM: not registers
ZERO_RULE_CELLS = frozenset({3, 4, 5, 6, 7, 8, 9, 10, 16})  # option 51 (001 L25024-25049)
# blocks whose cells 3..10 are registers already, not internal axes for SHUFFL
UNSHUFFLED = frozenset({Code.DWELL})
# numeric blocks that get TABLEG(5) when they have no G and option 38 = +-1 (001 L24890-24907)
G_FILLED = frozenset({Code.NONMOTION, Code.AUX_ONLY, Code.END, Code.DWELL})


class OutputElement:
    def __init__(self, state: PostState) -> None:
        machine = state.machine
        self.state = state
        self.step = machine.number_option(14)
        self.linear_codes = LinearCodes(machine, self.step)
        self.circular_codes = CircularCodes(machine)
        self.feed = FeedCommand(machine)
        self.rapid = RapidCommand(machine)
        self.cut_minutes = 0.0
        self._f_formats: dict[float, RegisterFormatter] = {}
        registers = machine.registers
        contouring = machine.number_option(1) == 0
        order = [k for k in (machine.output_order or ()) if k not in NEVER_OUTPUT] or [
            k for k in range(1, 31) if k not in NEVER_OUTPUT
        ]
        self.formatters: list[RegisterFormatter] = []
        for location in order:
            fmt = registers.formats[location]
            if fmt is None:
                continue
            drop = contouring or location not in (3, 4, 5)
            self.formatters.append(
                RegisterFormatter(location, registers.letters[location], fmt, drop_trailing=drop)
            )
        try:
            self.shuffle = cell_map(machine.number_option(59), "XYZ") + cell_map(
                machine.number_option(60), "IJK"
            )
        except ValueError as exc:
            raise FatalError(7, str(exc)) from None
        self.zero_rule = machine.number_option(51)
        self.limit_action = machine.number_option(110)
        self.limits_exceeded = False
        self.slide_limits: tuple[tuple[float, float, int], ...] = ()
        if self.limit_action != 0:
            signs = [1 if target is None else target[1] for target in self.shuffle[:3]]
            self.slide_limits = tuple(
                (machine.number_option(lower), machine.number_option(upper), signs[axis])
                for axis, (upper, lower) in enumerate(((121, 122), (123, 124), (125, 126)))
            )
        # option 170 = 1: G-code segmentation of command-limited feed moves (option 10 = 0)
        self.segment_by_code = (
            machine.number_option(170) == 1 and machine.number_option(10) == 0 and contouring
        )
        # option 26 = 0: the feedrate multiplier constant, on a contouring machine
        self.multiplier = machine.number_option(26) == 0 and contouring
        self.offset_capacity = {
            location: 10**fmt.left - 10**-fmt.right
            for location in (8, 9, 10)
            if (fmt := registers.formats[location]) is not None
        }
        self.long_formatters = self._long_departure_formatters()
        per_degree = {0.0: 1 / 360, 1.0: 1.0, -1.0: 100 / 360}.get(machine.number_option(118), 1.0)
        self.rotary_codes = RotaryCodes(machine, machine.number_option(111) * per_degree)
        self.leading_zero_codes = {
            float(code): extra
            for location, extra in ((12, 0), (13, 1))
            if (code := machine.tableg[location]) is not ABSENT
        }
        self.suppress_g = machine.number_option(38) == 0
        dwell_g = machine.tableg[5]
        self.fill_g: float | Absent = (
            float(dwell_g)
            if machine.number_option(38) in (1.0, -1.0) and dwell_g is not ABSENT
            else ABSENT
        )
        self.suppress_f = machine.number_option(107) in (1.0, 2.0)
        self.previous_g: float | Absent = ABSENT
        self.previous_f: float | Absent = ABSENT
        self.tmark_code = stand_in(machine, 65)
        n_format = registers.formats[1]
        # SEQLIM: the largest N the format holds (999 for format 30)
        self.sequence_limit = 10**n_format.left - 1 if n_format is not None else 1 << 62
        self.emitted: list[Block] = []
        self.diagnostics: list[Diagnostic] = []
        self._assumed_feed = False

    # -- OUTPUT (flow chart 8) ------------------------------------------------------------

    def output(self, block: Block) -> None:
        state = self.state
        if block.code is Code.TMARK:
            self._tmark(block)
            return
        if self.segment_by_code and block.code is Code.LINEAR and not state.feed.rapid_ipm:
            parts = self._segmented_by_code(block)
            if parts is not None:
                for part in parts:
                    self._output(part)
                return
        self._output(block)

    def _output(self, block: Block) -> None:
        state = self.state
        block.cells[15] = float(int(block.code))
        sequence = block.record if block.record is not None else state.sequence
        if sequence > self.sequence_limit:
            sequence %= self.sequence_limit  # "N = N modulus SEQLIM" (001 L9117-9126)
        block.cells[1] = float(-sequence if state.skipping else sequence)
        if block.code in MOTION_CODES:
            self._motion(block)
        elif block.code is Code.ROTARY_INCREMENTAL:
            self._rotary(block)
        elif block.code in G_FILLED and block.cells[2] is ABSENT:
            block.cells[2] = self.fill_g
        block.cells[12] = state.pending.spindle
        block.cells[14] = state.pending.m_code
        state.pending.spindle = ABSENT
        state.pending.m_code = ABSENT
        self._emit(block)

    def _tmark(self, block: Block) -> None:
        """No N: the end-of-record code stands in its place; the pending S and M wait for
        the next block; an option-98 F is punched but not printed (001 L9298-9304)."""
        block.cells[15] = float(int(block.code))
        words = self._words(block, suppress=False)
        block.words = tuple((loc, printed) for loc, _, printed, _ in words if loc != 11)
        block.punch = self.tmark_code + "".join(letter + punched for _, letter, _, punched in words)
        self.emitted.append(block)

    def dwell(self, seconds: float) -> Block:
        """A dwell block: G = TABLEG(5), the time divided by option 56 in the option-57
        register (001 L16315-16330, L25109-25140)."""
        machine = self.state.machine
        block = Block(Code.DWELL)
        dwell_g = machine.tableg[5]
        block.cells[2] = ABSENT if dwell_g is ABSENT else float(dwell_g)
        block.cells[int(machine.number_option(57))] = seconds / (machine.number_option(56) or 1.0)
        return block

    def store_m(self, code: float) -> None:
        """STOREM (001 L38041-38087): one M code waits for the next block; a second one
        first goes out in a block of its own with the waiting one."""
        if self.state.pending.m_code is not ABSENT:
            self.output(Block(Code.AUX_ONLY))
        self.state.pending.m_code = code

    def _motion(self, block: Block) -> None:
        assert block.steps is not None
        if block.code in CIRCLE_CODES:
            assert block.radius is not None
            code = self.circular_codes.select(block.radius, int(block.code) > 0)
            offsets = [float(v) for v in block.cells[8:11] if v is not ABSENT]
            length = sum(o * o for o in offsets) ** 0.5  # R from the arc offsets
        else:
            code = self.linear_codes.select(max(abs(s) for s in block.steps))
            length = sum((s * self.step) ** 2 for s in block.steps) ** 0.5
        block.cells[2] = float(code.code)
        if self.slide_limits:
            self._test_slide_limits(block)
        feed = self.state.feed
        if feed.rapid_ipm:
            departures = tuple(s * self.step for s in block.steps)
            rapid, ipm = self.rapid.command(
                departures, code.gdimul, feed.rapid_ipm, low=feed.rapid_low
            )
            block.cells[11] = ABSENT if rapid is None else rapid
            block.cells[19] = ipm
            block.rapid = True
            self.cut_minutes += sum(d * d for d in departures) ** 0.5 / ipm
            return
        if feed.programmed is None and not self._assumed_feed:
            self._assumed_feed = True
            self.diagnostics.append(Diagnostic("OPTION FEEDRATE ASSUMED."))
            feed.ipm = self.state.machine.number_option(23)
        multiplied = (
            self._multiplied(block, feed.ipm, code.gdimul, length, code.size_class)
            if self.multiplier and block.code is Code.LINEAR
            else None
        )
        if multiplied is not None:
            command, ipm, f_format = multiplied
        else:
            command, ipm, f_format = self.feed.command(
                feed.ipm, code.gdimul, length, code.size_class
            )
        block.cells[11] = command
        block.cells[19] = ipm
        block.f_format = f_format
        if block.code in CIRCLE_CODES:
            assert block.radius is not None
            arc = _arc_length(block, self.step)
            self.cut_minutes += arc / ipm
        else:
            self.cut_minutes += length / ipm

    def _rotary(self, block: Block) -> None:
        """An incremental rotary block: SELGRO's G code, and the feed over the arc the part
        radius (option 112) sweeps, held to the table's feed range (options 113, 114 in
        RPM) (001 L10936-10984, L6171-6282)."""
        assert block.rotary is not None
        cell, degrees = block.rotary
        code = self.rotary_codes.select(abs(float(block.cells[cell])))  # type: ignore[arg-type]
        block.cells[2] = float(code.code)
        machine = self.state.machine
        radius = machine.number_option(112)
        length = radians(degrees) * radius
        per_rpm = 2 * pi * radius
        low, high = machine.number_option(113) * per_rpm, machine.number_option(114) * per_rpm
        feed = self.state.feed
        if feed.programmed is None and not self._assumed_feed:
            self._assumed_feed = True
            self.diagnostics.append(Diagnostic("OPTION FEEDRATE ASSUMED."))
            feed.ipm = machine.number_option(23)
        ipm = min(max(feed.ipm, low), high)
        command, ipm, f_format = self.feed.command(ipm, code.gdimul, length, code.size_class)
        block.cells[11] = command
        block.cells[19] = ipm
        block.f_format = f_format
        self.cut_minutes += length / ipm

    def _test_slide_limits(self, block: Block) -> None:
        """TSTLIM (001 L38955-39010, options 110 and 121-126): the point reached, on the
        CL axes with option 59's signs, against each axis's limits; a 0/0 pair is not
        tested. "AXIS SLIDE LIMIT HAS BEEN EXCEEDED *** WARNING", naming the axis."""
        assert block.position is not None
        for axis, (low, high, sign) in enumerate(self.slide_limits):
            if axis >= len(block.position) or (low == 0 and high == 0):
                continue
            value = sign * block.position[axis] * self.step
            if low - 1e-9 <= value <= high + 1e-9:
                continue
            text = f"{'XYZ'[axis]} AXIS SLIDE LIMIT HAS BEEN EXCEEDED *** WARNING"
            if self.limit_action == -1:
                raise RunStopped(f"{text} ({value:g} outside {low:g}..{high:g}; option 110 = -1)")
            self.diagnostics.append(Diagnostic(text))
            self.limits_exceeded = True

    def _segmented_by_code(self, block: Block) -> list[Block] | None:
        """TSTFCM (option 170 = 1, manual §4.1.5.1, 001 L11920-11987): a linear block whose
        feed command would exceed option 24 is cut into the fewest equal segments that a
        smaller dimension code can carry with a command within it, trying each smaller code
        in turn; None keeps the block whole (and the command is limited as usual)."""
        assert block.steps is not None and block.position is not None
        largest = max(abs(s) for s in block.steps)
        code = self.linear_codes.select(largest)
        length = sum((s * self.step) ** 2 for s in block.steps) ** 0.5
        ipm = self.state.feed.ipm
        if code.gdimul * ipm / length <= self.feed.maximum:
            return None
        for candidate, limit in self.linear_codes.smaller(code):
            count = int(largest / limit) + 1  # every departure / count under the limit
            if candidate.gdimul * ipm * count / length > self.feed.maximum:
                continue
            start = [p - s for p, s in zip(block.position, block.steps, strict=True)]
            parts = []
            for steps in segments(block.steps, count):
                start = [a + s for a, s in zip(start, steps, strict=True)]
                parts.append(
                    Block.motion(Code.LINEAR, block.record or 0, steps, tuple(start), self.step)
                )
            return parts
        return None

    def _multiplied(
        self, block: Block, ipm: float, gdimul: float, length: float, size_class: int
    ) -> tuple[float, float, float | None] | None:
        """Option 26 = 0: the command divided by c and the departures times c in I, J, K,
        if every product fits its register; otherwise None (the command is clamped)."""
        found = self.feed.multiplier(ipm, gdimul, length, size_class)
        if found is None:
            return None
        constant, command, f_format = found
        assert block.steps is not None
        products = {}
        for axis, steps in enumerate(block.steps):
            if steps == 0:
                continue
            target = self.shuffle[3 + axis]
            capacity = self.offset_capacity.get(target[0]) if target is not None else None
            value = abs(steps) * self.step * constant
            if capacity is None or value > capacity:
                return None
            products[8 + axis] = value
        for cell, value in products.items():
            block.cells[cell] = value
        return command, ipm, f_format

    # -- GEOUT: words and the tape line (flow chart 12) ----------------------------------

    def _emit(self, block: Block) -> None:
        if block.code is Code.FROM:  # printed in the absolute columns only, never punched
            self.emitted.append(block)
            return
        if block.code not in UNSHUFFLED:
            self._shuffle(block)
        words = self._words(
            block, suppress=block.code in MOTION_CODES or block.code is Code.ROTARY_INCREMENTAL
        )
        block.words = tuple((location, printed) for location, _, printed, _ in words)
        if block.punched:
            punch = "".join(letter + punched for _, letter, _, punched in words)
            skip = block.cells[1] is not ABSENT and float(block.cells[1]) < 0
            block.punch = "/" + punch if skip else punch
        self.emitted.append(block)

    def _long_departure_formatters(self) -> dict[int, RegisterFormatter]:
        """Option 41 <= 0 (§4.8, 001 L16144-16269): in a G10 block (TABLEG(11)) X, Y and Z
        take format 23 (24 under -2), with the sign rule of their own format."""
        machine = self.state.machine
        variable = machine.number_option(41)
        if variable > 0 or machine.tableg[11] is ABSENT:
            return {}
        size = 24.0 if variable == -2 else 23.0
        formatters = {}
        for location in (3, 4, 5):
            regfor = machine.registers.regfor[location]
            if regfor:
                fmt = decode_regfor(-size if regfor < 0 else size)
                assert fmt is not None
                formatters[location] = RegisterFormatter(
                    location, machine.registers.letters[location], fmt, drop_trailing=True
                )
        return formatters

    def _leading_zero_rule(self, block: Block) -> dict[int, int] | None:
        """Option 51 = -2 (100M, §4.9): in G11 (TABLEG(12)) blocks X, Y, Z lose their
        leading zeros left of the point, in G12 (TABLEG(13)) one zero right of it too."""
        if self.zero_rule != -2 or block.code is not Code.LINEAR or block.cells[2] is ABSENT:
            return None
        extra = self.leading_zero_codes.get(float(block.cells[2]))
        return None if extra is None else {3: extra, 4: extra, 5: extra}

    def _f_formatter(self, regfor: float) -> RegisterFormatter:
        """FVARGO: inverse time changes the F format with the block's G code."""
        formatter = self._f_formats.get(regfor)
        if formatter is None:
            fmt = decode_regfor(regfor)
            assert fmt is not None
            letter = self.state.machine.registers.letters[11]
            formatter = self._f_formats[regfor] = RegisterFormatter(
                11, letter, fmt, drop_trailing=False
            )
        return formatter

    def _shuffle(self, block: Block) -> None:
        """SHUFFL (001 L37532-37564): options 59/60 put the internal X, Y, Z and I, J, K on
        the machine's axes with their signs, for every block at output."""
        cells = block.cells
        internal = [cells[k] for k in (3, 4, 5, 8, 9, 10)]
        for k in (3, 4, 5, 8, 9, 10):
            cells[k] = ABSENT
        for value, target in zip(internal, self.shuffle, strict=True):
            if target is not None and value is not ABSENT:
                cell, sign = target
                cells[cell] = sign * float(value) if cell < 8 else float(value)

    def _words(self, block: Block, *, suppress: bool) -> list[tuple[int, str, str, str]]:
        """(location, letter, printed, punched) of each register the block outputs."""
        words: list[tuple[int, str, str, str]] = []
        long_departure = (
            self.long_formatters
            and block.code is Code.LINEAR
            and block.cells[2] is not ABSENT
            and float(block.cells[2]) == float(self.state.machine.tableg[11])  # type: ignore[arg-type]
        )
        leading = self._leading_zero_rule(block)
        for formatter in self.formatters:
            location = formatter.location
            if long_departure and location in self.long_formatters:
                formatter = self.long_formatters[location]
            value = block.cells[location]
            if value is ABSENT:
                continue
            number = float(value)
            if location == 1:
                number = abs(number)
            if suppress and location == 2:
                if self.suppress_g and number == self.previous_g:
                    continue
                self.previous_g = number
            if suppress and location == 11:
                if self.suppress_f and number == self.previous_f:
                    continue
                self.previous_f = number
            if location == 11 and block.f_format is not None:
                formatter = self._f_formatter(block.f_format)
            try:
                text = formatter.format(
                    number,
                    leading.get(location) if leading is not None else None,
                )
            except FormatOverflow as overflow:
                record = block.record if block.record is not None else self.state.sequence
                overflow.where = SourcePosition("", None, None, record)
                raise
            if location in ZERO_RULE_CELLS and text.punched.strip("+-0") == "":
                if self.zero_rule in (0, -2):  # delete value and address (standard)
                    continue
                if self.zero_rule == 1:  # the address alone
                    words.append((location, formatter.letter, text.printed, ""))
                    continue
            words.append((location, formatter.letter, text.printed, text.punched))
        return words


def _arc_length(block: Block, step: float) -> float:
    """The length of a quadrant segment: its chord over the radius gives the angle."""
    assert block.steps is not None and block.radius is not None
    chord = sum((s * step) ** 2 for s in block.steps) ** 0.5
    ratio = min(1.0, chord / (2 * block.radius)) if block.radius else 0.0
    return 2 * block.radius * asin(ratio)
