"""An arc output in pieces rather than as quadrant blocks (manual §3.4.4, §4.4): as chords
within option 262's tolerance (or one step) and option 4, and under SFM (SFMCIR, 001
L5152-5163) cut at the spindle's shift radii along the arc: quadrant blocks on the
manual's controls, whole arcs between the shift points on a control that takes whole arcs
(option 253), chords cut at the shift points as a line is (option 262, helices). Mixed
into CircularMotion (core/motion/circle.py); Arc is the arc CircularMotion collects."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from math import acos, asin, atan2, ceil, cos, pi, sin, tau

from gecent.core.cl.records import Motion
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.guard import check_segments
from gecent.core.motion.quadrants import arc_sweep, goes_linear, quadrant_crossings
from gecent.core.motion.rounding import to_steps
from gecent.core.motion.sfm import arc_cuts, surface_cuts
from gecent.core.output.block import Code
from gecent.core.output.modern import CL_PLANES as PLANES
from gecent.core.state import PostState

Point = tuple[float, float, float]


@dataclass(slots=True)
class Arc:
    record: Motion
    clockwise: bool
    radius: float
    start: tuple[float, float, float]
    end: tuple[float, float, float]
    helix: bool = False  # the end leaves the plane of the start
    # the circle's records, the first and its continuations (a multiaxis circle reads the
    # tool axes of their points)
    records: list[Motion] = field(default_factory=list)
    # a circle about an axis along none of X, Y, Z: its unit axis (its arc goes out as
    # chords in its own plane)
    axis: Point | None = None


class ArcPieces:
    """What it needs of CircularMotion is declared here."""

    state: PostState
    machine: MachineDefinition
    step: float
    depmax: float
    plane: int
    chord_tolerance: float
    centre_moved: Point
    exact_centre: Point
    _line: Callable[[Motion, Point], None]
    _segment: Callable[[Arc, Point, Code, int, int, list[Point]], None]
    _whole: Callable[[Arc, Code, tuple[float, float], tuple[float, float]], None]

    def _chords(self, arc: Arc, first: tuple[float, float], last: tuple[float, float]) -> None:
        """The arc (or helix) as straight moves: equal angles, each chord within the
        tolerance of the arc (option 262, or one step) and no longer than option 4; the
        normal axis moves in proportion; the last point is the record's own."""
        u, v, normal = PLANES[self.plane]
        tolerance = self.chord_tolerance if self.chord_tolerance > 0 else self.step
        sweep = arc_sweep(first, last, arc.clockwise, self.step)
        radius = arc.radius
        widest = 2 * acos(1 - tolerance / radius) if tolerance < radius else pi
        if radius > 0 and 2 * radius > self.depmax:  # a chord of 2r sin(a/2) within option 4
            widest = min(widest, 2 * asin(min(1.0, self.depmax / (2 * radius))))
        count = max(1, ceil(sweep / widest - 1e-9)) if radius > 0 else 1
        check_segments(count, self.state.max_segments, arc.record.where, "arc as chords")
        c = self.centre_moved
        begin = atan2(first[1], first[0])
        turn = -sweep if arc.clockwise else sweep
        rise = arc.end[normal] - arc.start[normal]
        # under SFM each chord is a line to SFMO, cut at the shift radii (001 L14230-14549)
        line = self._surface_line if self.state.sfm.active else self._line
        for index in range(1, count + 1):
            if index == count:
                point = arc.end
            else:
                angle = begin + turn * index / count
                place = [0.0, 0.0, 0.0]
                place[u] = c[u] + radius * cos(angle)
                place[v] = c[v] + radius * sin(angle)
                place[normal] = arc.start[normal] + rise * index / count
                point = (place[0], place[1], place[2])
            line(arc.record, point)

    def _begin_tilted(self, record: Motion, axis: Point) -> Arc | None:
        """A one-point circle about a tilted axis (i, j, k with two or more components):
        the arc from the tool's point to the record's, counterclockwise about the axis as
        every one-point circle is; a start off the end's plane rises along the axis (a
        helix). None when there is no arc: a record of several points (APT's points are
        chords of the circle already, within the part program's tolerance: they go out
        linear, as a circle CHKAX finds in no plane does, 001 L4710-4712, L29153-29175)."""
        if len(record.points) != 1:
            return None
        position = self.state.position
        tx, ty, tz = position.translation
        centre = [a + t for a, t in zip(self.exact_centre, (tx, ty, tz), strict=True)]
        before = position.previous_part
        start = (before[0], before[1], before[2])
        x, y, z = record.points[0][:3]
        end = (x + tx, y + ty, z + tz)
        radius, ending = (_across(p, centre, axis) for p in (start, end))
        if abs(ending - radius) > max(10 * self.step, 1e-4 * radius):
            raise InputError(
                f"CIRCLE: the arc ends {abs(ending - radius):.4g} off its circle (radius "
                f"{radius:.4g} at its start, {ending:.4g} at its end)",
                record.where,
            )
        if radius < self.step:
            return None  # the tool on the axis: no arc, a straight move
        self.centre_moved = (centre[0], centre[1], centre[2])
        return Arc(record, False, radius, start, end, False, [record], axis)

    def _tilted_path(self, arc: Arc) -> list[tuple[Point, float]]:
        """The chords of a circle about a tilted axis, with the fraction of the arc at each
        end: equal angles, each chord within option 262's tolerance of the arc (one step
        when 0: the control cannot interpolate a circle outside its planes, so the chords
        are the post's, as a helix's are) and no longer than option 4."""
        assert arc.axis is not None
        n = arc.axis
        c = self.centre_moved
        s = [a - b for a, b in zip(arc.start, c, strict=True)]
        e = [a - b for a, b in zip(arc.end, c, strict=True)]
        rise0, rise1 = _dot(s, n), _dot(e, n)
        a = [s[k] - rise0 * n[k] for k in range(3)]
        across = _dot(a, a) ** 0.5
        a = [value / across for value in a]
        b = [n[1] * a[2] - n[2] * a[1], n[2] * a[0] - n[0] * a[2], n[0] * a[1] - n[1] * a[0]]
        e_flat = [e[k] - rise1 * n[k] for k in range(3)]
        if sum((e_flat[k] - across * a[k]) ** 2 for k in range(3)) ** 0.5 <= 0.01 * self.step:
            sweep = tau  # back where it started: a full circle (quadrants.FULL_CIRCLE)
        else:
            sweep = atan2(_dot(e_flat, b), _dot(e_flat, a)) % tau
        radius = arc.radius
        tolerance = self.chord_tolerance if self.chord_tolerance > 0 else self.step
        widest = 2 * acos(1 - tolerance / radius) if tolerance < radius else pi
        if 2 * radius > self.depmax:
            widest = min(widest, 2 * asin(min(1.0, self.depmax / (2 * radius))))
        count = max(1, ceil(sweep / widest - 1e-9))
        check_segments(count, self.state.max_segments, arc.record.where, "arc as chords")
        path: list[tuple[Point, float]] = []
        for index in range(1, count + 1):
            fraction = index / count
            if index == count:
                path.append((arc.end, 1.0))
                continue
            angle = sweep * fraction
            rise = rise0 + (rise1 - rise0) * fraction
            place = [
                c[k] + radius * (cos(angle) * a[k] + sin(angle) * b[k]) + rise * n[k]
                for k in range(3)
            ]
            path.append(((place[0], place[1], place[2]), fraction))
        return path

    def _tilted_chords(self, arc: Arc) -> None:
        """A tilted circle's chords as straight moves (under SFM each cut as a line)."""
        line = self._surface_line if self.state.sfm.active else self._line
        for point, _ in self._tilted_path(arc):
            line(arc.record, point)

    def _sfm_terms(self) -> tuple[tuple[int | None, float, float], float]:
        """SFMO's terms: (radius axis, fixed radius, surface feet) and inches per step."""
        sfm = self.state.sfm
        inches = 1.0 / 25.4 if self.machine.number_option(138) == 1 else 1.0
        return (sfm.radius_axis, sfm.fixed_radius * inches, sfm.surface_feet), self.step * inches

    def _surface_line(self, record: Motion, point: Point) -> None:
        """A chord under SFM: SFMO cuts it at the shift radii as it cuts a line, each
        piece's speed set before its block (the S rides in it)."""
        position = self.state.position
        sfm = self.state.sfm
        driver = sfm.driver
        assert driver is not None, "SFM mode without its spindle"
        start = tuple(position.previous[:3])
        end = tuple(to_steps(value, self.step) for value in point)
        arguments, per_step = self._sfm_terms()
        path = surface_cuts(start, end, *arguments, driver.ladder(), per_step)
        sfm.last_end = int(path.ends[-1] or 0) if path.ends else 0
        for cut in path.cuts:
            if cut.speed is not None:
                driver.turn(cut.speed, record.where, record.number)
            target = point if cut.point == end else tuple(k * self.step for k in cut.point)
            self._line(record, (target[0], target[1], target[2]))

    def _surface_whole(self, arc: Arc, code: Code) -> None:
        """SFM on a control that takes whole arcs (option 253): SFMO's shift points are
        found as SFMCIR finds them, quadrant segment by quadrant segment (001 L5152-5163),
        but only a change of speed cuts the arc: each piece between two shift points is
        one whole-arc block with option 252's centre words and its own S. A helix rises
        in proportion to the angle swept."""
        position = self.state.position
        sfm = self.state.sfm
        driver = sfm.driver
        assert driver is not None, "SFM mode without its spindle"
        u, v, normal = PLANES[self.plane]
        step = self.step
        c = self.centre_moved
        first = (arc.start[u] - c[u], arc.start[v] - c[v])
        last = (arc.end[u] - c[u], arc.end[v] - c[v])
        sweep = arc_sweep(first, last, arc.clockwise, step)
        ending = first if sweep >= tau else last  # a full circle goes round all four
        corners: list[tuple[int, ...]] = []
        for du, dv in quadrant_crossings(first, ending, arc.clockwise):
            crossing = [0, 0, 0]
            crossing[u] = to_steps(c[u] + du * arc.radius, step)
            crossing[v] = to_steps(c[v] + dv * arc.radius, step)
            crossing[normal] = position.previous[normal]
            corners.append(tuple(crossing))
        corners.append(tuple(to_steps(value, step) for value in arc.end))
        arguments, per_step = self._sfm_terms()
        centre = tuple(value / step for value in c)
        at = tuple(position.previous[:3])
        pieces: list[tuple[tuple[int, ...], float | None]] = []  # (end, speed from its start)
        for corner in corners:
            path = arc_cuts(
                at, corner, centre, arc.radius / step, (u, v), *arguments, driver.ladder(), per_step
            )
            if path.ends:
                sfm.last_end = int(path.ends[-1] or 0)
            for cut in path.cuts:
                same = pieces and (
                    cut.speed is None
                    or (pieces[-1][1] is not None and abs(cut.speed - pieces[-1][1]) < 1e-6)
                )
                if same:
                    pieces[-1] = (cut.point, pieces[-1][1])
                else:
                    pieces.append((cut.point, cut.speed))
            at = corner
        if not pieces:
            self._whole(arc, code, first, last)  # no move within a step
            return
        begin = atan2(first[1], first[0])
        rise = arc.end[normal] - arc.start[normal]
        for index, (point, speed) in enumerate(pieces):
            if speed is not None:
                driver.turn(speed, arc.record.where, arc.record.number)
            before = position.previous_part
            if index == len(pieces) - 1:
                end = arc.end
            else:
                place = [k * step for k in point]
                if rise:
                    turned = atan2(place[v] - c[v], place[u] - c[u]) - begin
                    fraction = ((-turned if arc.clockwise else turned) % tau) / sweep
                    place[normal] = arc.start[normal] + rise * fraction
                end = (place[0], place[1], place[2])
            begun = (before[0], before[1], before[2])
            piece = Arc(arc.record, arc.clockwise, arc.radius, begun, end, arc.helix)
            self._whole(
                piece,
                code,
                (before[u] - c[u], before[v] - c[v]),
                (end[u] - c[u], end[v] - c[v]),
            )

    def _surface_segment(
        self,
        arc: Arc,
        corner: tuple[float, float, float],
        code: Code,
        index: int,
        count: int,
        points: list[tuple[float, float, float]],
    ) -> None:
        """SFMCIR = 1 (001 L5152-5163): PROCQD's special tests are made on the quadrant
        segment first; then SFMO cuts it at the shift radii, along the arc (each piece a
        circular block whose I, J, K OFFARC takes from the piece's start) or, when the
        segment goes linear, along its chord. A piece with a zero in-plane departure goes
        linear as such a segment would (docs/decisions.md)."""
        position = self.state.position
        sfm = self.state.sfm
        driver = sfm.driver
        assert driver is not None, "SFM mode without its spindle"
        u, v, _ = PLANES[self.plane]
        step = self.step
        start = tuple(position.previous[:3])
        end = tuple(to_steps(value, step) for value in corner)
        c = self.centre_moved
        before = points[index - 1] if index else arc.start
        linear = goes_linear(
            index,
            count,
            (end[u] - start[u], end[v] - start[v]),
            (before[u] - c[u], before[v] - c[v]),
            (arc.end[u] - c[u], arc.end[v] - c[v]),
        )
        inches = 1.0 / 25.4 if self.machine.number_option(138) == 1 else 1.0
        arguments = (sfm.radius_axis, sfm.fixed_radius * inches, sfm.surface_feet)
        if linear:
            path = surface_cuts(start, end, *arguments, driver.ladder(), step * inches)
        else:
            centre = tuple(value / step for value in c)
            radius = arc.radius / step
            path = arc_cuts(
                start, end, centre, radius, (u, v), *arguments, driver.ladder(), step * inches
            )
        sfm.last_end = int(path.ends[-1] or 0) if path.ends else 0
        where, number = arc.record.where, arc.record.number
        for cut in path.cuts:
            if cut.speed is not None:
                driver.turn(cut.speed, where, number)
            point = corner if cut.point == end else tuple(k * step for k in cut.point)
            flat = cut.point[u] == position.previous[u] or cut.point[v] == position.previous[v]
            if linear or flat:
                self._line(arc.record, (point[0], point[1], point[2]))
            else:
                self._segment(arc, (point[0], point[1], point[2]), code, index, count, points)


def _dot(a: Sequence[float], b: Sequence[float]) -> float:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _across(point: Point, centre: Sequence[float], axis: Point) -> float:
    """How far ``point`` is from the line through ``centre`` along the unit ``axis``."""
    offset = [p - q for p, q in zip(point, centre, strict=True)]
    along = _dot(offset, axis)
    return float(max(0.0, _dot(offset, offset) - along * along) ** 0.5)
