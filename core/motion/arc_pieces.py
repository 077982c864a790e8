"""An arc output in pieces rather than as quadrant blocks (manual §3.4.4, §4.4): as chords
within option 262's tolerance (or one step) and option 4, and under SFM (SFMCIR, 001
L5152-5163) cut at the spindle's shift radii along the arc. Mixed into CircularMotion
(core/motion/circle.py); Arc is the arc CircularMotion collects."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from math import acos, asin, atan2, ceil, cos, pi, sin

from gecent.core.cl.records import Motion
from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.guard import check_segments
from gecent.core.motion.quadrants import arc_sweep, goes_linear
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


class ArcPieces:
    """What it needs of CircularMotion is declared here."""

    state: PostState
    machine: MachineDefinition
    step: float
    depmax: float
    plane: int
    chord_tolerance: float
    centre_moved: Point
    _line: Callable[[Motion, Point], None]
    _segment: Callable[[Arc, Point, Code, int, int, list[Point]], None]

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
            self._line(arc.record, point)

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
