"""The fast path for plain GOTO runs (issue 15): one CL point to one linear block, with the
arithmetic of the general path and none of its machinery.

A one-point GOTO on a contouring machine, while nothing special is in force, goes through
the general path as: round the point to steps (SRAREC), take the departures, choose the
dimension G code (SELG), the feed command (CONTUR, or the feed itself under option 254),
N from the record number, the absolute words of a modern control, SHUFFL, the register
formats with G and F modal suppression and option 51's zero rule, then the tape line.
:class:`FastLinear` does exactly that in one routine, over precompiled per-machine tables,
and builds a :class:`Block` only when a sink needs one (the listing, JSON lines).

It is taken only while :meth:`FastLinear.ready` holds, which the run checks again after
every record the general path handled; a point it cannot do (a move to segment, a value
out of reach, a number not finite) is declined before anything changes, and the general
path does the record. ``tests/test_fast_path.py`` proves both paths write byte-identical
tapes and listings.
"""

from __future__ import annotations

from bisect import bisect_right
from collections.abc import Callable
from math import isclose, log10

from gecent.core.absent import ABSENT
from gecent.core.cl.records import Motion
from gecent.core.motion.gcode import DimensionCode, LinearCodes
from gecent.core.motion.guard import CoordinateGuard
from gecent.core.motion.linear import LinearMotion
from gecent.core.output.block import Block, Code
from gecent.core.output.element import OutputElement
from gecent.core.output.format import RegisterFormatter
from gecent.core.output.sinks import Sinks
from gecent.core.output.words import ZERO_RULE_CELLS
from gecent.core.state import PostState
from gecent.core.units import UnitScale

# a register whose last decimal is the machine step formats whole steps without floats,
# exactly as from the value, while the step count stays well inside a float's precision
EXACT_UNITS = 10**9
WORDS_KEPT = 4096  # G and F word texts remembered at most


class FastLinear:
    """A precompiled routine for one machine: :meth:`goto` posts a one-point GOTO record
    exactly as the general path would, or returns False having changed nothing."""

    def __init__(
        self,
        state: PostState,
        output: OutputElement,
        motion: LinearMotion,
        sinks: Sinks,
        guard: CoordinateGuard,
        rapid_motion: Callable[[float], None],
        units: UnitScale,
    ) -> None:
        machine = state.machine
        self.state = state
        self.output = output
        self.motion = motion
        self.sinks = sinks
        self.rapid_motion = rapid_motion  # TSTFLG: enter or leave rapid before a move
        self.units = units  # UNITS: the record comes unscaled (x 1.0 changes no float)
        self.step = motion.step
        self.axes = motion.axes
        self.depmax = motion.depmax
        self.reach = tuple(guard.reach)
        self.words = output.words
        self.modern = output.modern
        self.sequence_limit = output.sequence_limit
        self.separator = output.separator
        decimals = -log10(self.step) if self.step > 0 else 0.5
        whole = round(decimals)
        self.step_decimals = whole if isclose(decimals, whole, abs_tol=1e-9) else None
        words = self.words
        # the machine as a whole: what this routine does not do, the general path does
        self.possible = (
            machine.number_option(1) == 0
            and not output.optimiser.segmenting
            and (not output.optimiser.multiplying or output.modern.direct_feed)
            and output.optimiser.ijk_minimum <= 0  # (option 224 puts I, J, K in long moves)
            and not output.slide_limits.limits
            and output.feed_limits is None  # (FEDLIM's per-axis limits, option 25 < 0)
            and output.accel is None  # (A/D testing holds blocks, option 55 = 1)
            and not motion.variable_format
            and not words.long_formatters
            and words.zero_rule != -2
            and words.zero_rule in (0.0, 1.0)
            and not words.unpunched_g  # (option 147: the tape line differs from the words)
        )
        # the words a linear block can have, in the machine's output order: N, G, the axes
        # (internal axis, sign and diameter factor after SHUFFL), F
        targets: dict[int, tuple[int, float, int]] = {}
        for axis, target in enumerate(words.shuffle[: self.axes]):
            if target is not None:
                cell, direction = target
                signed = cell < 8 or words.signed_centre  # SHUFFL's rule
                factor = 2 if words.diameter and cell == 3 else 1
                targets[cell] = (axis, float(direction) if signed else 1.0, factor)
        self.slots: list[tuple[int, RegisterFormatter, int, float, int, int | None]] = []
        for formatter in words.formatters:
            location = formatter.location
            if location == 1:
                scale = 1 if formatter.fmt.right == 0 else None
                self.slots.append((location, formatter, -1, 1.0, 1, scale))
            elif location in (2, 11):
                self.slots.append((location, formatter, -1, 1.0, 1, None))
            elif location in targets:
                axis, sign, factor = targets[location]
                scale = self._unit_scale(formatter)
                self.slots.append((location, formatter, axis, sign, factor, scale))
        # option 46: rapid shifts gears by M codes, which would ride in the move's block;
        # without, entering and leaving rapid changes only the feed's flags
        self.gear_shifts = machine.number_option(46) != 0
        self.blocks_wanted = not sinks.lines_only
        self.goto = self.compile()

    def _unit_scale(self, formatter: RegisterFormatter) -> int | None:
        """Units of the format's last decimal per step, when whole (format as fine as the
        step or finer); None: format from the value."""
        if self.step_decimals is None or formatter.fmt.right < self.step_decimals:
            return None
        return int(10 ** (formatter.fmt.right - self.step_decimals))

    def ready(self, special: bool) -> bool:
        """Nothing special in force (``special``: the run has a circle or cycle going): no
        rapid (but the move after a one-shot rapid on a machine without gear shifts), thread,
        SFM, stop or END awaiting its FROM, OPSKIP, pending S or M code,
        unfinished program start, feed mode to change or note to report, N without repeats;
        a feed given."""
        state = self.state
        feed = state.feed
        modes = state.modes
        modern = self.modern
        output = self.output
        return (
            self.possible
            and not special
            and (
                not (feed.rapid_requested or feed.rapid_mode or feed.rapid_ipm)
                or not self.gear_shifts
            )
            and not state.threading.armed
            and not state.sfm.active
            and not modes.ended
            and not modes.stopped
            and not state.skipping
            and not state.numbering.unrepeated
            and state.pending.spindle is ABSENT
            and state.pending.m_code is ABSENT
            and not state.tool.length_pending
            and state.spindle.restart is None
            and (feed.programmed is not None or output.assumed_feed)
            and feed.ipm > 0
            and (not modern.frame or modern.started)
            and (not modern.direct_feed or modern.per_revolution == feed.per_revolution)
            and not output.diagnostics
        )

    def compile(self) -> Callable[[Motion], bool]:
        """The routine itself: a closure over this machine's constants and the run's state
        objects, so the loop reads locals rather than attributes."""
        state = self.state
        output = self.output
        words = self.words
        modern = self.modern
        position = state.position
        previous = position.previous
        present = position.present
        present_part = position.present_part
        previous_part = position.previous_part
        feed = state.feed
        pending = state.pending
        numbering = state.numbering
        step = self.step
        units = self.units
        reach_x, reach_y, reach_z = self.reach
        depmax = self.depmax
        two_axes = self.axes == 2
        select = _selector(output.linear_codes)
        feed_command = output.feed.command
        rapid_command = output.rapid.command
        rapid_motion = self.rapid_motion
        rapid_code = modern.rapid_code
        direct_feed = modern.direct_feed
        placed = modern.absolute
        modern_active = modern.active
        sequence_limit = self.sequence_limit
        frame = modern.frame
        separator = self.separator
        suppress_g = words.suppress_g
        suppress_f = words.suppress_f
        zero_rule = words.zero_rule
        f_formatter = words.f_formatter
        # G codes and feeds recur along a path: their word texts are made once each
        texts: dict[tuple[RegisterFormatter, float], tuple[str, str]] = {}

        def remembered(formatter: RegisterFormatter, value: float) -> tuple[str, str]:
            found = texts.get((formatter, value))
            if found is None:
                if len(texts) >= WORDS_KEPT:
                    texts.clear()
                text = formatter.format(value)
                found = texts[formatter, value] = (text.printed, text.punched)
            return found

        slots = [
            (location, formatter, axis, sign, factor, scale, formatter.texts, letter)
            for (location, formatter, axis, sign, factor, scale) in self.slots
            for letter in (formatter.letter,)
        ]
        blocks_wanted = self.blocks_wanted
        emit_line = self.sinks.emit_line
        emit_known = self.sinks.emit_known
        linear = Code.LINEAR

        def goto(record: Motion) -> bool:
            points = record.points
            if len(points) != 1:
                return False
            series = numbering.series
            if frame and series is not None and series[0] > sequence_limit and not numbering.off:
                return False  # N beyond its digits: the general path stops numbering
            point = points[0]
            if len(point) != 3:
                return False
            tx, ty, tz = position.translation
            scale_units = units.factor
            px = point[0] * scale_units + tx
            py = point[1] * scale_units + ty
            pz = point[2] * scale_units + tz
            # "not <=" also refuses NaN: the general path reports it
            if not (abs(px) <= reach_x and abs(py) <= reach_y and abs(pz) <= reach_z):
                return False
            sx = int(abs(px) / step + 0.5001)
            sy = int(abs(py) / step + 0.5001)
            sz = int(abs(pz) / step + 0.5001)
            if px < 0:
                sx = -sx
            if py < 0:
                sy = -sy
            if pz < 0:
                sz = -sz
            dx = sx - previous[0]
            dy = sy - previous[1]
            dz = sz - previous[2]
            ax = -dx if dx < 0 else dx
            ay = -dy if dy < 0 else dy
            largest = ax if ax > ay else ay
            if not two_axes:
                az = -dz if dz < 0 else dz
                if az > largest:
                    largest = az
            if largest > depmax:
                return False  # to be segmented: the general path
            if feed.rapid_requested or feed.rapid_mode:
                # PLENTH from the previous point, as the general path measures it
                path = (
                    0
                    + (px - previous_part[0]) ** 2
                    + (py - previous_part[1]) ** 2
                    + (pz - previous_part[2]) ** 2
                ) ** 0.5
                rapid_motion(0.0 + path)
            present_part[0] = px
            present_part[1] = py
            present_part[2] = pz
            present[0] = sx
            present[1] = sy
            present[2] = sz
            if not largest:
                return True  # no move: the previous point stays (001 L4283-4290)
            code = select(largest)
            if two_axes:
                length = (0 + (dx * step) ** 2 + (dy * step) ** 2) ** 0.5
            else:
                length = (0 + (dx * step) ** 2 + (dy * step) ** 2 + (dz * step) ** 2) ** 0.5
            f_format = None
            rapid = bool(feed.rapid_ipm)
            g_code = float(code.code)
            command: float | None
            if rapid:
                departures = (
                    (dx * step, dy * step) if two_axes else (dx * step, dy * step, dz * step)
                )
                command, ipm = rapid_command(
                    departures, code.gdimul, feed.rapid_ipm, low=feed.rapid_low
                )
                if rapid_code is not None:  # G00: the control's own rapid, no F
                    g_code = rapid_code
                    command = None
                distance = 0.0
                for departure in departures:
                    distance += departure * departure
                cut_minutes = distance**0.5 / ipm
            elif direct_feed:
                command = feed.per_revolution_value if feed.per_revolution else feed.ipm
                ipm = feed.ipm
                cut_minutes = length / ipm
            else:
                command, ipm, f_format = feed_command(
                    feed.ipm, code.gdimul, length, code.size_class
                )
                cut_minutes = length / ipm
            output.cut_minutes += cut_minutes
            pending.rpm = None
            number = record.number
            numbered = not numbering.off
            if not numbered:
                sequence = 0
            elif series is not None:  # SEQNO's series, or counting blocks (option 143 = 1)
                sequence, increment = series
                numbering.series = (sequence + increment, increment)
            else:
                sequence = number
            if sequence > sequence_limit:
                sequence %= sequence_limit
            # the point reached: a two-axis machine's third axis stays where it was
            reached = (sx, sy, previous[2]) if two_axes else (sx, sy, sz)
            if placed:
                at = modern.at
                if at is None:
                    moved: tuple[bool, bool, bool] = (True, True, True)
                else:
                    moved = (at[0] != sx, at[1] != sy, two_axes or at[2] != sz)
                modern.at = [sx, sy] if two_axes else [sx, sy, sz]
                values = (sx, sy, sz)
            else:
                moved = (True, True, True)
                values = (dx, dy, dz)
            if modern_active:
                modern.ended = False
            printed_words: list[tuple[int, str]] = []
            punched_words: list[str] = []
            for location, formatter, axis, sign, factor, scale, text_of, letter in slots:
                if axis >= 0:
                    if not moved[axis]:
                        continue
                    steps = values[axis]
                    if scale is not None and -EXACT_UNITS < steps < EXACT_UNITS:
                        negative = steps < 0 if sign > 0 else steps > 0
                        magnitude = (steps if steps >= 0 else -steps) * factor * scale
                        printed, punched = text_of(magnitude, negative)
                    else:
                        text = formatter.format(sign * (steps * step) * factor)
                        printed, punched = text.printed, text.punched
                    if (
                        (not placed or location > 7)
                        and location in ZERO_RULE_CELLS
                        and punched.strip("+-0.") == ""
                    ):
                        if zero_rule == 0:
                            continue
                        if blocks_wanted:
                            printed_words.append((location, printed))
                        punched_words.append(letter)
                        continue
                elif location == 1:
                    if not numbered:
                        continue
                    if scale is not None:
                        printed, punched = text_of(sequence, False)
                    else:
                        text = formatter.format(float(sequence))
                        printed, punched = text.printed, text.punched
                elif location == 2:
                    if suppress_g and g_code == words.previous_g:
                        continue
                    words.previous_g = g_code
                    printed, punched = remembered(formatter, g_code)
                else:
                    if command is None:
                        continue
                    if suppress_f and command == words.previous_f:
                        continue
                    words.previous_f = command
                    if f_format is not None:
                        formatter = f_formatter(f_format)
                    printed, punched = remembered(formatter, command)
                if blocks_wanted:  # the listing and JSON lines print the words
                    printed_words.append((location, printed))
                punched_words.append(letter + punched)
            line = separator.join(punched_words)
            previous_part[:] = present_part
            previous[:] = present
            if not blocks_wanted:
                emit_line(line)
                return True
            block = Block(linear, number)
            cells = block.cells
            if numbered:
                cells[1] = float(sequence)
            cells[2] = g_code
            if command is not None:
                cells[11] = command
            cells[15] = 0.0
            cells[19] = ipm
            block.rapid = rapid
            for location, _, axis, sign, factor, _, _, _ in slots:
                if axis >= 0 and moved[axis]:
                    cells[location] = sign * (values[axis] * step) * factor
            block.f_format = f_format
            block.steps = (dx, dy) if two_axes else (dx, dy, dz)
            block.position = reached
            block.cut_minutes = cut_minutes
            block.words = tuple(printed_words)
            block.punch = line
            emit_known(block, line)
            return True

        return goto


def _selector(codes: LinearCodes) -> Callable[[int], DimensionCode]:
    """SELG by bisection over the range limits, each range's code worked out once (the
    smallest available range from it up); the general ``select`` where the limits are not
    ascending or no code covers the size (it raises the manual's fatal error)."""
    limits = codes.limits
    if list(limits) != sorted(limits):
        return codes.select
    covering: list[DimensionCode | None] = []
    for index in range(len(limits) + 1):
        covering.append(next((c for c in codes.codes[index:] if c is not None), None))

    def select(largest: int) -> DimensionCode:
        code = covering[bisect_right(limits, largest)]
        return code if code is not None else codes.select(largest)

    return select
