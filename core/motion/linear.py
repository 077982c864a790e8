"""Linear motion on a contouring machine (manual §3.4.2-3.4.3, 001 L4061-4673; flow charts
5 and 7): FROM, GOTO, GODLTA and continuation records become CODE 3 and CODE 0 blocks.

* each CL point plus TRANS is rounded to whole steps (SRAREC); departures are differences of
  rounded points, so no error accumulates (appendix 7.2);
* a move of no whole step is no move: nothing is output and the previous point stays;
* a departure beyond DEPMAX (option 4) is segmented (core/motion/segments.py);
* the motion element works in CL axis order; options 59/60 are applied at output (SHUFFL);
* in SFM mode (SFMFLG) every feed move goes to SFMO (core/motion/sfm.py), after DEPMAX's
  segmentation as SEGMNT calls it per segment (001 L1310-1330): each segment is split at
  the shift radii and each piece carries its spindle speed; rapid moves are not.
"""

from __future__ import annotations

from collections.abc import Callable

from gecent.core.cl.records import Motion, MotionSubtype
from gecent.core.errors import InputError
from gecent.core.motion.guard import check_segments
from gecent.core.motion.rounding import to_steps
from gecent.core.motion.segments import segment_count, segment_place, segments
from gecent.core.motion.sfm import surface_cuts
from gecent.core.output.block import Block, Code
from gecent.core.state import Position, PostState

TWO_AXIS = frozenset({11.0, 101.0, 110.0})  # option 22: the machine has two linear axes


def godlta_delta(values: tuple[float, ...]) -> tuple[float, ...]:
    """GODLTA's increments: dx, dy, dz, or one value along the tool axis z."""
    return (0.0, 0.0, values[0]) if len(values) == 1 else values[:3]


def godlta_point(position: Position, record: Motion) -> tuple[float, ...]:
    """GODLTA adds its increments to the previous point (001 L4103-4128); TRANS is in the
    previous point already, so the CL point is that less TRANS. One value moves along the
    tool axis (z)."""
    delta = godlta_delta(record.points[0])
    previous = position.previous_part
    return tuple(previous[a] + delta[a] - position.translation[a] for a in range(3))


class LinearMotion:
    """The motion element for a non-multiaxis contouring machine."""

    def __init__(self, state: PostState, emit: Callable[[Block], None]) -> None:
        machine = state.machine
        self.state = state
        self.emit = emit
        self.step = machine.number_option(14)
        # CL x, y (two-axis machines such as the lathe MACH04) or x, y, z (001 L1318-1320)
        self.axes = 2 if machine.number_option(22) in TWO_AXIS else 3
        self.depmax = round(machine.number_option(4) / self.step)
        # option 41 = 0, the 100M's variable format (§4.8, 001 L16144-16269): a feed move
        # over 9.9999 in is segmented to 9.9999; a longer rapid goes in G10 with STEP x 10
        self.variable_format = machine.number_option(41) == 0
        self.short_max = round(9.9999 / self.step)
        # SFM's radii are in inches whatever the machine's unit (option 138 = 1: millimetres)
        self.inches_per_unit = 1.0 / 25.4 if machine.number_option(138) == 1 else 1.0

    def record(self, record: Motion) -> None:
        if record.subtype is MotionSubtype.FROM:
            self._from(record)
        elif record.subtype is MotionSubtype.GODLTA:
            self._godlta(record)
        else:
            for point in record.points:
                self._goto(record, point)

    def machine_point(self, part: list[float]) -> list[int]:
        return [to_steps(part[axis], self.step) for axis in range(3)]

    def _from(self, record: Motion) -> None:
        position = self.state.position
        tx, ty, tz = position.translation
        x, y, z = record.points[0][:3]
        position.present_part[:3] = [x + tx, y + ty, z + tz]
        position.present[:3] = self.machine_point(position.present_part)
        block = Block(Code.FROM, record.number)
        for axis in range(3):
            block.cells[3 + axis] = position.present[axis] * self.step
        block.position = tuple(position.present[:3])
        position.previous_part[:] = position.present_part
        position.previous[:] = position.present
        position.from_given = True
        self.emit(block)

    def _godlta(self, record: Motion) -> None:
        self._goto(record, self.godlta_point(record))

    def godlta_point(self, record: Motion) -> tuple[float, ...]:
        return godlta_point(self.state.position, record)

    def _goto(self, record: Motion, point: tuple[float, ...]) -> None:
        if len(point) != 3:
            raise InputError(
                "a multiaxis (6-value) point on a 3-axis contouring machine", record.where
            )
        position = self.state.position
        tx, ty, tz = position.translation
        position.present_part[:3] = [point[0] + tx, point[1] + ty, point[2] + tz]
        position.present[:3] = self.machine_point(position.present_part)
        departures = [position.present[a] - position.previous[a] for a in range(self.axes)]
        if not any(departures):
            return  # RETURN = -1: no move, the previous point stays (001 L4283-4290)
        depmax, coarse = self.depmax, False
        if self.variable_format and max(abs(d) for d in departures) > self.short_max:
            if self.state.feed.rapid_ipm:
                coarse = True
            else:
                depmax = self.short_max
        count = segment_count(departures, [depmax] * self.axes)
        if count > 1:
            check_segments(count, self.state.max_segments, record.where, "move")
        reached = list(position.previous[:3])
        carry = [0] * self.axes
        surface = self.state.sfm.active and not self.state.feed.rapid_ipm
        parts = segments(departures, count) if count > 1 else (tuple(departures),)
        for index, part in enumerate(parts):
            if coarse:
                part = _truncated_to_thousandths(part, carry)
            start = tuple(reached)
            for axis, steps in enumerate(part):
                reached[axis] += steps
            if surface:
                self._surface_cut(record, start, tuple(reached))
            else:
                block = Block.motion(Code.LINEAR, record.number, part, tuple(reached), self.step)
                block.segment = segment_place(index, count)
                self.emit(block)
        if coarse:
            # the truncated remnant is taken off the present point, so the next departure
            # recovers it (truncate and carry, 001 L16200-16245)
            position.present[: self.axes] = reached[: self.axes]
        position.previous_part[:] = position.present_part
        position.previous[:] = position.present

    def _surface_cut(self, record: Motion, start: tuple[int, ...], end: tuple[int, ...]) -> None:
        """SFMO (manual §4.4): the segment from ``start`` to ``end`` (steps) in pieces at the
        shift radii, each piece's speed set before its block is output, so its S rides in
        it; a path on which SFM cannot start keeps the current speed."""
        sfm = self.state.sfm
        driver = sfm.driver
        assert driver is not None, "SFM mode without its spindle"
        path = surface_cuts(
            start,
            end,
            sfm.radius_axis,
            sfm.fixed_radius * self.inches_per_unit,
            sfm.surface_feet,
            driver.ladder(),
            self.step * self.inches_per_unit,
        )
        last = path.ends[-1] if path.ends else None
        sfm.last_end = 0 if last is None else int(last)
        at = start
        for cut in path.cuts:
            if cut.speed is not None:
                driver.turn(cut.speed, record.where, record.number)
            part = tuple(cut.point[axis] - at[axis] for axis in range(self.axes))
            self.emit(Block.motion(Code.LINEAR, record.number, part, cut.point, self.step))
            at = cut.point


def _truncated_to_thousandths(part: tuple[int, ...], carry: list[int]) -> tuple[int, ...]:
    """A G10 departure under option 41 = 0: truncated (not rounded) to whole tens of steps,
    STEP x 10 (0.001 in on the 0.0001-in 100M); the remnant is carried into the next
    segment."""
    out = []
    for axis, steps in enumerate(part):
        wanted = steps + carry[axis]
        kept = int(wanted / 10) * 10  # toward zero
        carry[axis] = wanted - kept
        out.append(kept)
    return tuple(out)


def path_length(position: Position, record: Motion) -> float:
    """PLENTH: the length of the whole record's path from the previous point."""
    tx, ty, tz = position.translation
    at = position.previous_part[:3]
    total = 0.0
    for point in record.points:
        if record.subtype is MotionSubtype.GODLTA:
            delta = godlta_delta(point)
            nxt = [at[k] + delta[k] for k in range(3)]
        else:
            nxt = [point[0] + tx, point[1] + ty, point[2] + tz]
        total += sum((nxt[k] - at[k]) ** 2 for k in range(3)) ** 0.5
        at = nxt
    return total
