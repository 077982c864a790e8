"""Multiaxis circular interpolation (manual §3.4.7.1, 001 L6447-6542; xref L1830-1880;
SELGCR and SELGRO L6150-6282; spec 03 §13, §11.5, W24, open questions 11, 14, 15).

GOCIRC's tests, its continuation records and its quadrant logic are the three-axis
circle's (core/motion/circle.py): a CIRCLE record makes the next GOTO a circle when it
passes them, and this module outputs the finished arc through the transform class.

* The tool axis at a point of the arc is interpolated on the sphere between the start's
  and the end's, by the fraction of the arc swept (slerp, spec 03 §13 step 4); parallel
  axes keep the start's.
* The class carries the arc to the machine. The control interpolates a circle in a plane
  of its own slides, the rotary axes in proportion to the angle: the arc is output as
  circular blocks only when that motion, carried back to the part, stays within the
  linearity tolerance (LINTOL's r, else one step) of the part's arc all along it, with
  the tool axis within LINTOL's cone when one is given. The quadrant points, the centre
  offsets I, J, K (unsigned, from each block's start), the direction and the plane code
  are then the machine circle's; a block whose rotary departure passes ROTMAX is cut into
  equal arcs. The manual transforms the part's quadrant points; they are the machine's
  whenever the class turns the plane by a multiple of 90 degrees (MACH40's class 1 with
  the tool along Z, for one).
* Otherwise (the class maps the arc to no circle of the machine, or its radius passes
  option 4) the arc goes out as straight multiaxis moves (GOLINE, tested by LINTOL when on)
  through the quadrant points, each quadrant in equal chords within the same tolerance
  (option 262 when given).
* The G code is OUTPUT's (core/output/element.py): SELGCR's for the machine radius, then
  SELGRO's, a rotary departure beyond the circular code's rotary range taking the circular
  band that covers it (W24: TABLEG(21) CLW, (31) CCLW; core/motion/gcode.py's
  :func:`circle_code`).
* D and E (DBFSEG 16, 17), the rotary "supplementary constants", the "equivalent of rotary
  axes 'arc center offsets'" (001 L1830-1842; open question 14, docs/decisions.md wave 7): as
  a circle's interpolator turns its centre offsets into the slides' rates, it turns a
  constant into a rotary axis's rate in proportion to the angle, so the constant is the
  rotary axis's "radius": the block's rotary departure over its sweep in radians
  (|dA| / theta: D with A, DBFSEG 6; E with B, DBFSEG 7), unsigned as I, J, K are, in the
  rotary register's units. They go out on a machine whose registers 16 and 17 are D and
  E; a control without them moves the rotary axes in proportion to the angle itself (the
  motion _follows checks), and the blocks carry the rotary departures alone.
"""

from __future__ import annotations

from math import acos, atan2, ceil, cos, hypot, pi, sin, sqrt, tau

import numpy as np
from gecent.core.errors import Diagnostic, FatalError, InputError
from gecent.core.motion.arc_pieces import Arc
from gecent.core.motion.circle import PLANES, CentreWords, CircularMotion
from gecent.core.motion.gcode import circular_departure
from gecent.core.motion.multiaxis import NOT_UNIT, UNIT_TOLERANCE, MultiaxisMotion, PartPoint
from gecent.core.motion.quadrants import arc_sweep, goes_linear, quadrant_crossings
from gecent.core.motion.rounding import to_steps
from gecent.core.motion.segments import segment_count
from gecent.core.output.block import Block, Code

SAMPLES_PER_QUADRANT = 16  # the arc is checked at this many points per 90 degrees (8 at least)
# the supplementary constants' registers by the rotary register they go with (001 L1839-1842)
SUPPLEMENTARY = {6: (16, "D"), 7: (17, "E")}

Axis = tuple[float, float, float]


def slerp(start: Axis, end: Axis, fraction: float) -> Axis:
    """The tool axis ``fraction`` of the way from ``start`` to ``end`` on the unit sphere
    (001 L6493-6518: alpha = sin(W - g)/sin W, beta = sin g/sin W, normalised); parallel
    axes keep the start's."""
    cross = (
        start[1] * end[2] - start[2] * end[1],
        start[2] * end[0] - start[0] * end[2],
        start[0] * end[1] - start[1] * end[0],
    )
    omega = atan2(
        sqrt(sum(c * c for c in cross)), sum(a * b for a, b in zip(start, end, strict=True))
    )
    if sin(omega) < 1e-9:
        return start
    alpha = sin(omega * (1.0 - fraction)) / sin(omega)
    beta = sin(omega * fraction) / sin(omega)
    i, j, k = (alpha * a + beta * b for a, b in zip(start, end, strict=True))
    length = sqrt(i * i + j * j + k * k)
    return (i / length, j / length, k / length)


class MultiaxisCircle:
    """PROCQD on a multiaxis machine: CircularMotion's finisher."""

    def __init__(self, motion: MultiaxisMotion, circle: CircularMotion) -> None:
        self.motion = motion
        self.circle = circle
        machine = motion.state.machine
        self.step = motion.step
        self.depmax = circular_departure(machine)  # the radius test of a circular block

    def finish(self, arc: Arc) -> None:
        try:
            self._finish(arc)
        except FatalError as error:
            if error.where is None:  # (the arc goes out when the record after it arrives)
                error.where = arc.record.where
            raise

    # -- the part's arc -------------------------------------------------------------------

    def _finish(self, arc: Arc) -> None:
        machine = self.motion.state.machine
        self._arc = arc
        if arc.axis is not None:
            self._tilted(arc)
            return
        position = self.motion.state.position
        start = position.previous_part
        axis = (start[3], start[4], start[5])
        self._axes = (axis, self._end_axis(arc, axis))
        u, v, _ = PLANES[self.circle.plane]
        c = self.circle.centre_moved
        first = (arc.start[u] - c[u], arc.start[v] - c[v])
        last = (arc.end[u] - c[u], arc.end[v] - c[v])
        self._first, self._last = first, last
        self._sweep = arc_sweep(first, last, arc.clockwise, self.step)
        rule = self.motion.state.linearity
        self.tolerance = rule.radius if rule.radius > 0 else self.step
        self.cone = None if rule.radius <= 0 or rule.cone is None else rule.cone * pi / 180
        if machine.number_option(262) <= 0 and self._circular():
            return
        self._chords()
        self.motion.tool_axis = self._axes[1]

    def _tilted(self, arc: Arc) -> None:
        """A circle about a tilted axis: the three-axis circle's chords in its own plane
        (core/motion/arc_pieces.py), each a straight multiaxis move, the tool axis slerped
        by the fraction of the arc."""
        start = self.motion.state.position.previous_part
        first = (start[3], start[4], start[5])
        last = self._end_axis(arc, first)
        tx, ty, tz = self.motion.state.position.translation
        for (x, y, z), fraction in self.circle._tilted_path(arc):
            i, j, k = slerp(first, last, fraction)
            self.motion.goline(arc.record, (x - tx, y - ty, z - tz, i, j, k))
        self.motion.tool_axis = last

    def _end_axis(self, arc: Arc, start: Axis) -> Axis:
        """The tool axis of the circle's last CL point (FROM5's check), or the one in force."""
        axis = self.motion.tool_axis
        for record in arc.records:
            for point in record.points:
                if len(point) < 6:
                    continue
                i, j, k = point[3:6]
                length = sqrt(i * i + j * j + k * k)
                if length == 0.0:
                    raise InputError("the tool axis i, j, k is 0, 0, 0", record.where)
                if abs(length - 1.0) > UNIT_TOLERANCE:
                    self.motion.warn(Diagnostic(NOT_UNIT, record.where))
                axis = (i / length, j / length, k / length)
        if sum(a * b for a, b in zip(start, axis, strict=True)) < -1.0 + 1e-9:
            raise InputError("the tool axis turns right round over the circle", arc.record.where)
        return axis

    def _part(self, fraction: float) -> PartPoint:
        """The part point ``fraction`` of the way along the arc, with its tool axis."""
        arc = self._arc
        u, v, normal = PLANES[self.circle.plane]
        c = self.circle.centre_moved
        axis = slerp(self._axes[0], self._axes[1], fraction)
        if fraction >= 1.0:
            x, y, z = arc.end
            return (x, y, z, *axis)
        begin = atan2(self._first[1], self._first[0])
        angle = begin + (-1.0 if arc.clockwise else 1.0) * fraction * self._sweep
        radius = arc.radius + fraction * (hypot(*self._last) - arc.radius)
        point = [0.0, 0.0, 0.0]
        point[u] = c[u] + radius * cos(angle)
        point[v] = c[v] + radius * sin(angle)
        point[normal] = arc.start[normal] + fraction * (arc.end[normal] - arc.start[normal])
        return (point[0], point[1], point[2], *axis)

    def _machine(self, fractions: list[float]) -> tuple[np.ndarray, np.ndarray]:
        """The class's machine points of the arc at ``fractions`` (rotary angles unwrapped
        from the axes' present angles, radians) and their singular flags."""
        motion = self.motion
        parts = np.array([self._part(f) for f in fractions])
        result = motion.transform.direct(parts, motion.kinematics, previous=motion.machine_previous)
        axes = result.axes.copy()
        for index, column in enumerate(motion.columns):
            before = np.radians(motion.angles[index])
            for row in range(len(axes)):
                before += (axes[row, column] - before + pi) % tau - pi
                axes[row, column] = before
        singular = result.singular if result.singular.size else np.zeros(len(axes), dtype=bool)
        return axes, singular

    # -- circular blocks ------------------------------------------------------------------

    def _circular(self) -> bool:
        """The arc as circular blocks of the machine, when the class makes it one: False
        (nothing output) when it does not."""
        count = max(8, ceil(self._sweep / (pi / 2) * SAMPLES_PER_QUADRANT))
        fractions = [n / count for n in range(count + 1)]
        axes, singular = self._machine(fractions)
        linear = axes[:, :3]
        spread = linear.max(axis=0) - linear.min(axis=0)
        normal = int(np.argmin(spread))
        if spread[normal] > self.tolerance:
            return False
        plane = next(p for p, (_, _, n) in enumerate(PLANES) if n == normal)
        u, v, _ = PLANES[plane]
        picks = (0, count // 3, 2 * count // 3) if self._sweep >= tau else (0, count // 2, count)
        centre = _circumcentre(*[(linear[i, u], linear[i, v]) for i in picks])
        if centre is None:
            return False
        radius = hypot(linear[0, u] - centre[0], linear[0, v] - centre[1])
        if not self.step <= radius <= self.depmax:
            return False
        angles = np.unwrap(np.arctan2(linear[:, v] - centre[1], linear[:, u] - centre[0]))
        turning = np.diff(angles)
        if not (np.all(turning > 0) or np.all(turning < 0)):
            return False
        clockwise = bool(turning[0] < 0)
        sweep = float(angles[-1] - angles[0])
        if not self._follows(fractions, axes, plane, centre, radius, sweep):
            return False
        self._blocks(axes, bool(singular[-1]), plane, (centre, radius), clockwise, abs(sweep))
        return True

    def _follows(
        self,
        fractions: list[float],
        axes: np.ndarray,
        plane: int,
        centre: tuple[float, float],
        radius: float,
        sweep: float,
    ) -> bool:
        """The control's motion (the slides on the machine circle, the rotary axes and the
        plane's normal in proportion to the angle) carried back to the part stays within
        the tolerance of the part's arc (and its tool axis within LINTOL's cone)."""
        motion = self.motion
        u, v, _ = PLANES[plane]
        begin = atan2(axes[0, v] - centre[1], axes[0, u] - centre[0])
        control = axes[0] + np.outer(fractions, axes[-1] - axes[0])
        control[:, u] = centre[0] + radius * np.cos(begin + np.array(fractions) * sweep)
        control[:, v] = centre[1] + radius * np.sin(begin + np.array(fractions) * sweep)
        back = motion.transform.inverse(control, motion.kinematics)
        for row, fraction in enumerate(fractions):
            ideal = self._part(fraction)
            if sqrt(sum((float(back[row, a]) - ideal[a]) ** 2 for a in range(3))) > self.tolerance:
                return False
            if self.cone is not None:
                dot = sum(float(back[row, 3 + a]) * ideal[3 + a] for a in range(3))
                if acos(max(-1.0, min(1.0, dot))) > self.cone:
                    return False
        return True

    def _blocks(
        self,
        axes: np.ndarray,
        singular: bool,
        plane: int,
        circle: tuple[tuple[float, float], float],
        clockwise: bool,
        sweep: float,
    ) -> None:
        """PROCQD: the machine circle's quadrant segments (cut under ROTMAX), the special
        cases of §3.4.4.1, the offsets from each block's start, CODE +-10/11/12."""
        motion, step = self.motion, self.step
        position = motion.state.position
        u, v, _ = PLANES[plane]
        centre, radius = circle
        start, end = axes[0], axes[-1]
        first = (start[u] - centre[0], start[v] - centre[1])
        last = (end[u] - centre[0], end[v] - centre[1])
        begin = atan2(first[1], first[0])
        sense = -1.0 if clockwise else 1.0
        fractions = [
            ((atan2(dv, du) - begin) * sense) % tau / sweep
            for du, dv in quadrant_crossings(first, _ending(first, last, sweep), clockwise)
        ]
        # a control taking whole arcs (option 253) needs no quadrant points: one block,
        # cut only under ROTMAX
        corners = [1.0] if self.circle.whole else [*fractions, 1.0]
        corners = self._under_rotmax(corners, start, end)
        code = Code((10 + plane) * (1 if clockwise else -1))
        self.circle.select_plane(plane, self._arc.record.number)
        centre_steps = [0, 0, 0]
        centre_steps[u], centre_steps[v] = to_steps(centre[0], step), to_steps(centre[1], step)
        constants = self._constant_cells()
        previous_offset = first
        previous_fraction = 0.0
        for index, fraction in enumerate(corners):
            point = start + fraction * (end - start)
            if fraction < 1.0:
                angle = begin + sense * fraction * sweep
                point[u] = centre[0] + radius * cos(angle)
                point[v] = centre[1] + radius * sin(angle)
            else:
                point = end.copy()
            linear = [to_steps(float(point[a]), step) for a in range(3)]
            rotary = [
                round(float(np.degrees(point[column])) * motion.per_degree / motion.rotary_step)
                for column in motion.columns
            ]
            departures = [linear[a] - position.previous[a] for a in range(3)]
            turns = [r - p for r, p in zip(rotary, motion.rotary_previous, strict=True)]
            offset = (float(point[u]) - centre[0], float(point[v]) - centre[1])
            part = self._part(fraction)
            if not any(departures) and not any(turns):
                previous_offset = offset
                continue
            # PROCQD's special cases are the Mark Century's; a whole arc is always an arc
            straight = not self.circle.whole and goes_linear(
                index, len(corners), (departures[u], departures[v]), previous_offset, last
            )
            block = Block.motion(
                Code.LINEAR if straight else code,
                self._arc.record.number,
                tuple(departures),
                tuple(linear),
                step,
            )
            for cell, steps in zip(motion.cells, turns, strict=True):
                block.cells[cell] = steps * motion.rotary_step
            block.angles = tuple(rotary)  # (absolute output, option 251: the angles reached)
            if straight:
                before = position.previous_part
                block.feed_length = sqrt(sum((part[a] - before[a]) ** 2 for a in range(3)))
            else:
                self._centre_words(block, centre_steps, (u, v))
                block.radius = radius
                theta = (fraction - previous_fraction) * sweep  # this block's sweep (radians)
                if self.circle.whole:
                    block.sweep = theta  # (the cutting time of a whole arc)
                for cell, steps in zip(motion.cells, turns, strict=True):
                    if steps and cell in constants and theta > 0:
                        block.cells[constants[cell]] = abs(steps) * motion.rotary_step / theta
            previous_fraction = fraction
            motion.emit(block)
            position.present[:3] = linear
            position.present_part[:] = list(part)
            position.previous[:] = position.present
            position.previous_part[:] = position.present_part
            motion.rotary_previous = rotary
            motion.angles = [float(np.degrees(point[column])) for column in motion.columns]
            motion.machine_raw = point
            motion.machine_previous = point.reshape(1, 6)
            previous_offset = offset
        motion.singular = singular
        motion.tool_axis = self._axes[1]

    def _centre_words(self, block: Block, centre: list[int], plane: tuple[int, int]) -> None:
        """I, J, K of the machine circle by option 252: the manual's unsigned offsets from
        the block's start (0), signed offsets (1; also 3, as a circular block of the
        quadrant split takes them: an R cannot carry the rotary axes' sweep, decision),
        or the absolute centre (2)."""
        previous = self.motion.state.position.previous
        words = self.circle.centre_words
        for axis in plane:
            if words == CentreWords.ABSOLUTE:
                steps = centre[axis]
            elif words:
                steps = centre[axis] - previous[axis]
            else:
                steps = abs(centre[axis] - previous[axis])
            block.cells[8 + axis] = steps * self.step

    def _constant_cells(self) -> dict[int, int]:
        """The rotary cells whose supplementary constant the machine has a register for:
        DBFSEG 16 = D (with A, cell 6), 17 = E (with B, cell 7), by their letters, since a
        machine may give those locations other registers (MACH40's 17 is MACF40's H)."""
        registers = self.motion.state.machine.registers
        return {
            rotary: cell
            for rotary, (cell, letter) in SUPPLEMENTARY.items()
            if registers.formats[cell] is not None and registers.letters[cell] == letter
        }

    def _under_rotmax(
        self, corners: list[float], start: np.ndarray, end: np.ndarray
    ) -> list[float]:
        """Each quadrant segment cut into equal arcs when its rotary departure passes ROTMAX
        (the rotary axes turn in proportion to the angle)."""
        motion = self.motion
        out: list[float] = []
        before = 0.0
        for fraction in corners:
            turns = [
                round(
                    float(np.degrees((end[c] - start[c]) * (fraction - before)))
                    * motion.per_degree
                    / motion.rotary_step
                )
                for c in motion.columns
            ]
            count = segment_count(turns, [motion.rotmax] * len(turns)) if turns else 1
            out.extend(before + (fraction - before) * n / count for n in range(1, count + 1))
            before = fraction
        return out

    # -- straight moves -------------------------------------------------------------------

    def _chords(self) -> None:
        """The arc as straight multiaxis moves through its quadrant points, each quadrant in
        equal chords within the tolerance (option 262 when given), the tool axis slerped."""
        arc = self._arc
        chord = self.motion.state.machine.number_option(262)
        tolerance = chord if chord > 0 else self.tolerance
        radius = max(arc.radius, hypot(*self._last))
        widest = 2 * acos(1 - tolerance / radius) if 0 < tolerance < radius else pi / 2
        begin = atan2(self._first[1], self._first[0])
        sense = -1.0 if arc.clockwise else 1.0
        corners = [
            ((atan2(dv, du) - begin) * sense) % tau / self._sweep
            for du, dv in quadrant_crossings(
                self._first, _ending(self._first, self._last, self._sweep), arc.clockwise
            )
        ]
        tx, ty, tz = self.motion.state.position.translation
        before = 0.0
        for fraction in [*corners, 1.0] if self._sweep > 0 else [1.0]:
            count = max(1, ceil((fraction - before) * self._sweep / widest - 1e-9))
            for n in range(1, count + 1):
                x, y, z, i, j, k = self._part(before + (fraction - before) * n / count)
                self.motion.goline(arc.record, (x - tx, y - ty, z - tz, i, j, k))
            before = fraction


def _ending(
    first: tuple[float, float], last: tuple[float, float], sweep: float
) -> tuple[float, float]:
    """The end QUADNT is given: a full circle's is its start, exactly (a float's noise
    would otherwise put it before or after the start and lose the circle)."""
    return first if sweep >= tau - 1e-9 else last


def _circumcentre(
    a: tuple[float, float], b: tuple[float, float], c: tuple[float, float]
) -> tuple[float, float] | None:
    """The centre of the circle through three points (None: they lie on a line)."""
    d = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]))
    if abs(d) < 1e-12:
        return None
    a2, b2, c2 = a[0] ** 2 + a[1] ** 2, b[0] ** 2 + b[1] ** 2, c[0] ** 2 + c[1] ** 2
    x = (a2 * (b[1] - c[1]) + b2 * (c[1] - a[1]) + c2 * (a[1] - b[1])) / d
    y = (a2 * (c[0] - b[0]) + b2 * (a[0] - c[0]) + c2 * (b[0] - a[0])) / d
    return (x, y)
