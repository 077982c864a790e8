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

from math import isclose, log10

from gecent.core.absent import ABSENT
from gecent.core.cl.records import Motion
from gecent.core.motion.guard import CoordinateGuard
from gecent.core.motion.linear import LinearMotion
from gecent.core.output.block import Block, Code
from gecent.core.output.element import OutputElement
from gecent.core.output.format import Formatted, RegisterFormatter
from gecent.core.output.sinks import Sinks
from gecent.core.output.words import ZERO_RULE_CELLS
from gecent.core.state import PostState

# a register whose last decimal is the machine step formats whole steps without floats,
# exactly as from the value, while the step count stays well inside a float's precision
EXACT_UNITS = 10**9


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
    ) -> None:
        machine = state.machine
        self.state = state
        self.output = output
        self.motion = motion
        self.sinks = sinks
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
            and not output.slide_limits.limits
            and not motion.variable_format
            and not words.long_formatters
            and words.zero_rule != -2
            and words.zero_rule in (0.0, 1.0)
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
        self.g_words: dict[float, Formatted] = {}
        self.blocks_wanted = not sinks.lines_only

    def _unit_scale(self, formatter: RegisterFormatter) -> int | None:
        """Units of the format's last decimal per step, when whole (format as fine as the
        step or finer); None: format from the value."""
        if self.step_decimals is None or formatter.fmt.right < self.step_decimals:
            return None
        return int(10 ** (formatter.fmt.right - self.step_decimals))

    def ready(self, special: bool) -> bool:
        """Nothing special in force (``special``: the run has a circle or cycle going): no
        thread, rapid, SFM, stop or END awaiting its
        FROM, circle, OPSKIP, SEQNO series, pending S or M code, unfinished program start,
        feed mode to change, note to report; and a feed programmed."""
        state = self.state
        feed = state.feed
        modes = state.modes
        modern = self.modern
        output = self.output
        return (
            self.possible
            and not special
            and not feed.rapid_requested
            and not feed.rapid_mode
            and not feed.rapid_ipm
            and not state.threading.armed
            and not state.sfm.active
            and not modes.ended
            and not modes.stopped
            and not state.skipping
            and state.numbering.series is None
            and not state.numbering.off
            and state.pending.spindle is ABSENT
            and state.pending.m_code is ABSENT
            and (feed.programmed is not None or output._assumed_feed)
            and feed.ipm > 0
            and (not modern.frame or modern.started)
            and (not modern.direct_feed or modern.per_revolution == feed.per_revolution)
            and not output.diagnostics
        )

    def goto(self, record: Motion) -> bool:
        points = record.points
        if len(points) != 1:
            return False
        point = points[0]
        if len(point) != 3:
            return False
        state = self.state
        position = state.position
        tx, ty, tz = position.translation
        px, py, pz = point[0] + tx, point[1] + ty, point[2] + tz
        reach = self.reach
        # "not <=" also refuses NaN: the general path reports it
        if not (abs(px) <= reach[0] and abs(py) <= reach[1] and abs(pz) <= reach[2]):
            return False
        step = self.step
        sx = int(abs(px) / step + 0.5001)
        sy = int(abs(py) / step + 0.5001)
        sz = int(abs(pz) / step + 0.5001)
        if px < 0:
            sx = -sx
        if py < 0:
            sy = -sy
        if pz < 0:
            sz = -sz
        previous = position.previous
        dx, dy, dz = sx - previous[0], sy - previous[1], sz - previous[2]
        two_axes = self.axes == 2
        largest = max(abs(dx), abs(dy)) if two_axes else max(abs(dx), abs(dy), abs(dz))
        if largest > self.depmax:
            return False  # to be segmented: the general path
        present_part = position.present_part
        present_part[0], present_part[1], present_part[2] = px, py, pz
        present = position.present
        present[0], present[1], present[2] = sx, sy, sz
        if not largest:
            return True  # no move: the previous point stays (001 L4283-4290)
        output = self.output
        code = output.linear_codes.select(largest)
        if two_axes:
            length = (0 + (dx * step) ** 2 + (dy * step) ** 2) ** 0.5
        else:
            length = (0 + (dx * step) ** 2 + (dy * step) ** 2 + (dz * step) ** 2) ** 0.5
        feed = state.feed
        f_format = None
        if self.modern.direct_feed:
            command = feed.per_revolution_value if feed.per_revolution else feed.ipm
            ipm = feed.ipm
        else:
            command, ipm, f_format = output.feed.command(
                feed.ipm, code.gdimul, length, code.size_class
            )
        cut_minutes = length / ipm
        output.cut_minutes += cut_minutes
        state.pending.rpm = None
        number = record.number
        sequence = number % self.sequence_limit if number > self.sequence_limit else number
        g_code = float(code.code)
        modern = self.modern
        placed = modern.absolute
        # the point reached: a two-axis machine's third axis stays where it was
        reached = (sx, sy, previous[2]) if two_axes else (sx, sy, sz)
        if placed:
            at = modern.at
            if at is None:
                moved = (True, True, True)
            else:
                moved = (at[0] != sx, at[1] != sy, two_axes or at[2] != sz)
            modern.at = [sx, sy] if two_axes else [sx, sy, sz]
            values = (sx, sy, sz)
        else:
            moved = (True, True, True)
            values = (dx, dy, dz)
        if modern.active:
            modern.ended = False
        words = self.words
        printed_words: list[tuple[int, str]] = []
        punched_words: list[str] = []
        zero_rule = words.zero_rule
        for location, formatter, axis, sign, factor, scale in self.slots:
            if axis >= 0:
                if not moved[axis]:
                    continue
                steps = values[axis]
                if scale is not None and -EXACT_UNITS < steps < EXACT_UNITS:
                    negative = steps < 0 if sign > 0 else steps > 0
                    text = formatter.format_units(abs(steps) * factor * scale, negative)
                else:
                    text = formatter.format(sign * (steps * step) * factor)
                if (
                    (not placed or location > 7)
                    and location in ZERO_RULE_CELLS
                    and text.punched.strip("+-0.") == ""
                ):
                    if zero_rule == 0:
                        continue
                    printed_words.append((location, text.printed))
                    punched_words.append(formatter.letter)
                    continue
            elif location == 1:
                if scale is not None:
                    text = formatter.format_units(sequence, False)
                else:
                    text = formatter.format(float(sequence))
            elif location == 2:
                if words.suppress_g and g_code == words.previous_g:
                    continue
                words.previous_g = g_code
                text = self.g_words.get(g_code) or self._g_word(formatter, g_code)
            else:
                if words.suppress_f and command == words.previous_f:
                    continue
                words.previous_f = command
                if f_format is not None:
                    formatter = words._f_formatter(f_format)
                text = formatter.format(command)
            printed_words.append((location, text.printed))
            punched_words.append(formatter.letter + text.punched)
        line = self.separator.join(punched_words)
        position.previous_part[:] = present_part
        previous[:] = present
        if not self.blocks_wanted:
            self.sinks.emit_line(line)
            return True
        block = Block(Code.LINEAR, number)
        cells = block.cells
        cells[1] = float(sequence)
        cells[2] = g_code
        cells[11] = command
        cells[15] = 0.0
        cells[19] = ipm
        block.f_format = f_format
        for location, _, axis, sign, factor, _ in self.slots:
            if axis >= 0 and moved[axis]:
                cells[location] = sign * (values[axis] * step) * factor
        block.steps = (dx, dy) if two_axes else (dx, dy, dz)
        block.position = reached
        block.cut_minutes = cut_minutes
        block.words = tuple(printed_words)
        block.punch = line
        self.sinks.emit_known(block, line)
        return True

    def _g_word(self, formatter: RegisterFormatter, code: float) -> Formatted:
        text = self.g_words[code] = formatter.format(code)
        return text
