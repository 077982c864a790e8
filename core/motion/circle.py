"""Circular interpolation (manual §3.4.4-3.4.4.1, 001 L4675-5383; flow chart 6; GOCIRC,
SRFCHK, CHKAX, DETDIR, COMPR, QUADNT, QUADET, PROCQD, OFFARC).

A type-3000 circle record (option 9 = 1) makes the next motion record a circle when it
passes the tests: LINCIR mode (option 28 = 1), every point in the plane (option 5), the
tool-path radius within the circular maximum departure (option 223, else option 4), no
threading. APT writes several points on the arc and
DETDIR finds the direction from the first two; CAM systems write one point, the arc's end,
and the direction is then counterclockwise about the circle axis. The points then only serve
the tests and the end point: the arc from the previous point to the last point of the record
and its continuation records is cut where it crosses a quadrant boundary (a Mark Century
control does at most 90 degrees per block) and output as CODE +-10/11/12 blocks whose I, J, K
are the unsigned offsets of the centre from each block's start. A first or last block with
a zero in-plane departure, or a last block that seems to reverse, goes out linear.

Modern controls (gecent options 252, 253; docs/modern-controls.md) take the whole arc, full
circles included, in one block whose I, J, K are the signed offsets of the centre from the
arc's start or the absolute centre, or whose R is the radius, and the plane code names the
machine's plane after SHUFFL. A one-point circle whose end leaves the plane is a helix: one
block with the normal axis moving too (option 261), or straight moves along it within a
chord tolerance, as is every arc under option 262.
"""

from __future__ import annotations

from collections.abc import Callable
from math import hypot, pi, tau

from gecent.core.absent import ABSENT
from gecent.core.cl.records import Circle, Motion, MotionSubtype
from gecent.core.errors import Diagnostic, FatalError, InputError
from gecent.core.machine.shuffle import cell_map
from gecent.core.motion.arc_pieces import Arc, ArcPieces
from gecent.core.motion.gcode import circular_departure
from gecent.core.motion.quadrants import (
    arc_sweep,
    goes_linear,
    quadrant_crossings,
)
from gecent.core.motion.rounding import round_to_step, to_steps
from gecent.core.output.block import Block, Code
from gecent.core.output.modern import CL_PLANES, machine_planes
from gecent.core.state import PostState

PLANES = CL_PLANES  # IPLANE 0 = XY, 1 = ZX, 2 = YZ
# where an arc leaves quadrant q, as (du, dv) on the unit circle
NEAR = 0.95  # a whole arc's centre stays this many steps from the record's on each axis
PLANE_CODES = (18, 19, 20)  # TABLEG: XY, ZX, YZ plane selection (001 L5124-5133)


class CentreWords:
    """Option 252: how a modern arc block states its centre."""

    UNSIGNED, SIGNED, ABSOLUTE, RADIUS = 0, 1, 2, 3


class CircularMotion(ArcPieces):
    def __init__(
        self,
        state: PostState,
        emit: Callable[[Block], None],
        warn: Callable[[Diagnostic], None],
    ) -> None:
        machine = state.machine
        self.state = state
        self.emit = emit
        self.warn = warn
        self.step = machine.number_option(14)
        self.available = machine.number_option(9) == 1
        self.epsilon = machine.number_option(5)
        self.depmax = machine.number_option(4)  # a chord is a straight move (option 262)
        self.circular_depmax = circular_departure(machine)
        self.three_axes = machine.number_option(22) == 111
        self.machine = machine
        self.centre: tuple[float, float, float] | None = None  # CIRDAT, rounded to the step
        self.plane = 0
        self.last_plane = 0  # LSTPLN: XY at the start (decision: no plane block before FROM)
        self.arc: Arc | None = None
        # who outputs a finished circle instead of finish's own blocks (a multiaxis
        # machine's circle goes through its transform class)
        self.finisher: Callable[[Arc], None] | None = None
        self.centre_moved: tuple[float, float, float] = (0.0, 0.0, 0.0)  # CIRDAT + TRANS
        self.exact_centre: tuple[float, float, float] = (0.0, 0.0, 0.0)  # the record's, unrounded
        self.axis_sense = 0.0  # the circle axis component along the plane normal
        self.tilted = False  # the axis is along none of X, Y, Z
        self.circle_axis: tuple[float, float, float] = (0.0, 0.0, 1.0)  # the record's, unit
        self._reference = 0.0
        self.centre_words = int(machine.number_option(252))  # CentreWords
        self.whole = machine.number_option(253) == 1
        self.helical = self.whole and machine.number_option(261) == 1
        # option 262: arcs as chords within this tolerance (helices the control cannot
        # take: within one step when it is 0)
        self.chord_tolerance = machine.number_option(262)
        self.machine_plane: tuple[int | None, ...] = PLANE_CODES
        if self.centre_words:
            try:
                shuffle = cell_map(machine.number_option(59), "XYZ")
            except ValueError as exc:
                raise FatalError(7, str(exc)) from None
            self.machine_plane = tuple(location for location, _ in machine_planes(shuffle))

    @property
    def collecting(self) -> bool:
        return self.arc is not None

    def surface(self, record: Circle) -> None:
        """SRFCHK (001 L37913-37960): only the centre and the axis i, j are read."""
        if not self.available:
            self.centre = None
            return
        x, y, z, i, j, k = record.values[:6]
        radius = record.values[6] if len(record.values) > 6 else None
        if abs(i) <= self.epsilon and abs(j) <= self.epsilon and abs(k) <= self.epsilon:
            raise InputError("CIRCLE has no axis: i, j and k are all 0", record.where)
        if radius is not None and not radius > 0:
            raise InputError(f"CIRCLE radius must be more than 0, found {radius:g}", record.where)
        components = sum(abs(c) > self.epsilon for c in (i, j, k))
        self.tilted = components > 1
        length = (i * i + j * j + k * k) ** 0.5
        self.circle_axis = (i / length, j / length, k / length)
        self.exact_centre = (x, y, z)
        self.centre = (
            round_to_step(x, self.step),
            round_to_step(y, self.step),
            round_to_step(z, self.step),
        )
        self.plane = 2 if abs(i) > self.epsilon else 1 if abs(j) > self.epsilon else 0
        self.axis_sense = (k, j, i)[self.plane]

    def begin(self, record: Motion) -> bool:
        """GOCIRC's first entry: True when the record starts a circle (nothing output yet)."""
        centre, self.centre = self.centre, None  # CIRFLG is spent by this motion either way
        if centre is None or record.subtype is not MotionSubtype.GOTO:
            return False
        if self.state.feed.rapid_ipm:
            return False  # a rapid move is never an arc (decision, PROCQD reads FRAPID)
        points = [p[:3] for p in record.points]
        u, v, normal = PLANES[self.plane]
        if self.machine.number_option(28) != 1:
            return False
        if self.tilted:  # in a plane of none of the control's: chords (arc_pieces.py)
            self.arc = self._begin_tilted(record, self.circle_axis)
            return self.arc is not None
        position = self.state.position
        self._reference = points[0][normal]
        if not self._planar(points, normal):
            return False
        helix = False
        if len(points) == 1:
            # one point, as CAM systems write a circle: the arc's sense is the axis's,
            # counterclockwise about (i, j, k) (decision; DETDIR needs two points)
            if abs(self.axis_sense) <= self.epsilon:
                return False
            tz = position.translation[normal]
            # a start off the end's plane: a helix along the circle axis on a three-axis
            # machine (decision); elsewhere not a circle, as the manual has it
            helix = abs(position.previous_part[normal] - tz - self._reference) > self.epsilon
            if helix and not self.three_axes:
                return False
            clockwise: bool | None = self.axis_sense < 0
        else:
            clockwise = self._direction(points, centre, u, v)
        if clockwise is None:
            return False
        tx, ty, tz = position.translation
        moved = (centre[0] + tx, centre[1] + ty, centre[2] + tz)
        start = tuple(position.previous_part[:3])
        radius = hypot(start[u] - moved[u], start[v] - moved[v])
        if radius > self.circular_depmax:
            return False
        last = points[-1]
        if len(points) == 1 and self.whole:
            # a CAM arc's end lies on the circle through its start: one off it is no arc
            ending = hypot(
                last[u] + (tx, ty, tz)[u] - moved[u], last[v] + (tx, ty, tz)[v] - moved[v]
            )
            if abs(ending - radius) > max(10 * self.step, 1e-4 * radius):
                raise InputError(
                    f"CIRCLE: the arc ends {abs(ending - radius):.4g} off its circle (radius "
                    f"{radius:.4g} at its start, {ending:.4g} at its end)",
                    record.where,
                )
        self.centre_moved = moved
        self.arc = Arc(
            record,
            clockwise,
            radius,
            (start[0], start[1], start[2]),
            (last[0] + tx, last[1] + ty, last[2] + tz),
            helix,
            [record],
        )
        return True

    def add(self, record: Motion) -> None:
        """A continuation record carries on the circle: only its last point matters."""
        assert self.arc is not None
        points = [p[:3] for p in record.points]
        if not self._planar(points, PLANES[self.plane][2]):
            self.warn(Diagnostic("WARNING - CIRCLE DOES NOT LIE IN A PLANE", record.where))
        tx, ty, tz = self.state.position.translation
        x, y, z = points[-1]
        self.arc.end = (x + tx, y + ty, z + tz)
        self.arc.records.append(record)

    def finish(self) -> None:
        """The circle is complete: split it at the quadrant boundaries and output it."""
        arc, self.arc = self.arc, None
        assert arc is not None
        if self.finisher is not None:
            self.finisher(arc)  # a multiaxis machine's circle (core/motion/multiaxis_circle.py)
            return
        u, v, normal = PLANES[self.plane]
        c = self.centre_moved
        first = (arc.start[u] - c[u], arc.start[v] - c[v])
        last = (arc.end[u] - c[u], arc.end[v] - c[v])
        ccw = not arc.clockwise
        points: list[tuple[float, float, float]] = []
        for du, dv in quadrant_crossings(first, last, arc.clockwise):
            point = [0.0, 0.0, 0.0]
            point[u] = c[u] + du * arc.radius
            point[v] = c[v] + dv * arc.radius
            point[normal] = arc.start[normal]
            points.append((point[0], point[1], point[2]))
        points.append(arc.end)
        code = Code(int((10 + self.plane) * (-1 if ccw else 1)))
        try:
            if arc.axis is not None:
                self._tilted_chords(arc)
                return
            if self.chord_tolerance > 0 or (arc.helix and not self.helical):
                self._chords(arc, first, last)  # (under SFM, each chord cut as a line)
                return
            self._plane_block(arc.record)
            if self.whole and self.state.sfm.active:
                self._surface_whole(arc, code)  # whole arcs between the shift points
                return
            if self.whole:
                self._whole(arc, code, first, last)
                return
            for index, corner in enumerate(points):
                if self.state.sfm.active:
                    self._surface_segment(arc, corner, code, index, len(points), points)
                else:
                    self._segment(arc, corner, code, index, len(points), points)
        except FatalError as error:
            # the arc goes out when the record after it arrives: the error is the arc's
            if error.where is None:
                error.where = arc.record.where
            raise

    def _line(self, record: Motion, point: tuple[float, float, float]) -> None:
        position = self.state.position
        position.present_part[:3] = list(point)
        position.present[:3] = [to_steps(value, self.step) for value in point]
        departures = [position.present[a] - position.previous[a] for a in range(3)]
        if not any(departures):
            return
        block = Block.motion(
            Code.LINEAR, record.number, tuple(departures), tuple(position.present[:3]), self.step
        )
        self.emit(block)
        position.previous_part[:] = position.present_part
        position.previous[:] = position.present

    def _plane_block(self, record: Motion) -> None:
        self.select_plane(self.plane, record.number)

    def select_plane(self, plane: int, record: int) -> None:
        """The plane code (G17/G18/G19) when the control is in another plane: before an
        arc, and before what works in a plane too (a control's canned cycle drills along
        the plane's normal; cutter compensation offsets in it)."""
        if plane == self.last_plane or not (self.three_axes or self.centre_words):
            return
        self.last_plane = plane
        location = self.machine_plane[plane]
        g = ABSENT if location is None else self.machine.tableg[location]
        if g is ABSENT:
            return
        block = Block(Code.G_ONLY, record)
        block.cells[2] = float(g)
        self.emit(block)

    def _segment(
        self,
        arc: Arc,
        point: tuple[float, float, float],
        code: Code,
        index: int,
        count: int,
        points: list[tuple[float, float, float]],
    ) -> None:
        position = self.state.position
        u, v, _ = PLANES[self.plane]
        position.present_part[:3] = list(point)
        position.present[:3] = [to_steps(value, self.step) for value in point]
        departures = [position.present[a] - position.previous[a] for a in range(3)]
        if not any(departures):
            return
        c = self.centre_moved
        before = points[index - 1] if index else arc.start
        circular = not goes_linear(
            index,
            count,
            (departures[u], departures[v]),
            (before[u] - c[u], before[v] - c[v]),
            (arc.end[u] - c[u], arc.end[v] - c[v]),
        )
        block = Block.motion(
            code if circular else Code.LINEAR,
            arc.record.number,
            tuple(departures),
            tuple(position.present[:3]),
            self.step,
        )
        if circular:
            c = self.centre_moved
            for axis in (u, v):
                if self.centre_words == CentreWords.ABSOLUTE:
                    steps = to_steps(c[axis], self.step)
                elif self.centre_words:  # signed from the block's start (R: I/J/K here)
                    steps = to_steps(c[axis], self.step) - position.previous[axis]
                else:  # the manual's unsigned offsets
                    steps = to_steps(abs(c[axis] - position.previous[axis] * self.step), self.step)
                block.cells[8 + axis] = steps * self.step
            block.radius = arc.radius
        self.emit(block)
        position.previous_part[:] = position.present_part
        position.previous[:] = position.present

    def _whole(
        self,
        arc: Arc,
        code: Code,
        first: tuple[float, float],
        last: tuple[float, float],
    ) -> None:
        """The whole arc in one block: the end point, the centre words of option 252 and the
        swept angle (for the cutting time). An arc that ends where it began is a full
        circle; one whose end only rounds onto its start is no move."""
        position = self.state.position
        u, v, _ = PLANES[self.plane]
        step = self.step
        position.present_part[:3] = list(arc.end)
        position.present[:3] = [to_steps(value, step) for value in arc.end]
        departures = [position.present[a] - position.previous[a] for a in range(3)]
        sweep = arc_sweep(first, last, arc.clockwise, step)
        if sweep < tau and not any(departures):
            return  # a short arc within one step: no move (RETURN = -1, 001 L4283-4290)
        block = Block.motion(
            code, arc.record.number, tuple(departures), tuple(position.present[:3]), step
        )
        centre = self._grid_centre(arc.radius / step, u, v)
        radius_word = (
            self._radius_word(centre, sweep, arc.clockwise, u, v)
            if self.centre_words == CentreWords.RADIUS and sweep < tau
            else None
        )
        if radius_word is not None:
            block.cells[16] = radius_word
        else:
            for axis, value in zip((u, v), centre, strict=True):
                relative = self.centre_words in (CentreWords.SIGNED, CentreWords.RADIUS)
                offset = value - position.previous[axis] if relative else value
                block.cells[8 + axis] = offset * step
        block.radius = arc.radius
        block.sweep = sweep
        self.emit(block)
        position.previous_part[:] = position.present_part
        position.previous[:] = position.present

    def _radius_word(
        self, centre: tuple[int, int], sweep: float, clockwise: bool, u: int, v: int
    ) -> float | None:
        """R (option 252 = 3): the radius from the grid centre, negative beyond a half
        circle (Fanuc, LinuxCNC), as the R register rounds it; None when the centre the
        control works out from that R and the end points lies more than a step from the
        grid centre (near a half circle, or a short arc of a large radius: R cannot say
        where the centre is), and I, J, K are given instead."""
        position = self.state.position
        step = self.step
        start = (position.previous[u], position.previous[v])
        end = (position.present[u], position.present[v])
        fmt = self.machine.registers.formats[16]
        decimals = fmt.right if fmt is not None else 4
        radius = round(hypot(start[0] - centre[0], start[1] - centre[1]) * step, decimals)
        chord = (end[0] - start[0], end[1] - start[1])
        half = hypot(*chord) / 2 * step
        if radius < half or half == 0:
            return None
        rise = (radius * radius - half * half) ** 0.5 / step
        normal = (-chord[1] / (2 * half / step), chord[0] / (2 * half / step))
        # the centre lies left of the chord for a counterclockwise arc up to a half circle
        side = (1 if not clockwise else -1) * (1 if sweep <= pi else -1)
        implied = (
            (start[0] + end[0]) / 2 + side * rise * normal[0],
            (start[1] + end[1]) / 2 + side * rise * normal[1],
        )
        if hypot(implied[0] - centre[0], implied[1] - centre[1]) > 1.0:
            return None
        return -radius if sweep > pi else radius

    def _grid_centre(self, radius: float, u: int, v: int) -> tuple[int, int]:
        """The centre on the step grid for a whole arc between rounded end points: of the
        grid points within NEAR steps of the record's centre on each axis, the one whose distances
        to the rounded start and end differ least from the radius (plain rounding can put
        the two more than a step apart, which a control reads as a spiral)."""
        position = self.state.position
        moved = [a + t for a, t in zip(self.exact_centre, position.translation, strict=True)]
        true_u, true_v = moved[u] / self.step, moved[v] / self.step
        start = (position.previous[u], position.previous[v])
        end = (position.present[u], position.present[v])
        best: tuple[float, float, tuple[int, int]] | None = None
        base_u, base_v = round(true_u), round(true_v)
        for du in (-1, 0, 1):
            for dv in (-1, 0, 1):
                cu, cv = base_u + du, base_v + dv
                if abs(cu - true_u) > NEAR or abs(cv - true_v) > NEAR:
                    continue
                error = max(
                    abs(hypot(start[0] - cu, start[1] - cv) - radius),
                    abs(hypot(end[0] - cu, end[1] - cv) - radius),
                )
                key = (error, hypot(cu - true_u, cv - true_v), (cu, cv))
                if best is None or key[:2] < best[:2]:
                    best = key
        assert best is not None
        return best[2]

    def _planar(self, points: list[tuple[float, ...]], normal: int) -> bool:
        return all(abs(p[normal] - self._reference) <= self.epsilon for p in points)

    @staticmethod
    def _direction(
        points: list[tuple[float, ...]], centre: tuple[float, float, float], u: int, v: int
    ) -> bool | None:
        """DETDIR (001 L4950-4986): the sign of the cross product of the first two record
        points about the centre; negative is clockwise. Equal points: try the next one."""
        a = (points[0][u] - centre[u], points[0][v] - centre[v])
        for point in points[1:]:
            b = (point[u] - centre[u], point[v] - centre[v])
            cross = a[0] * b[1] - b[0] * a[1]
            if cross:
                return cross < 0
        return None
