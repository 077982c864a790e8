"""Canned cycles on a multiaxis machine: CYCLGX (001 L30206-30246; spec 08 §3.3).

The manual says only that CYCLGX "issues a command block for the programmed canned cycle"
(MACH40's MACFUN makes that block for OFF, TAP, OUT and IN, 001 L28129-28161: the plugin
gecent.plugins.macfuns.macf40). The other cycles, on the manual's transform classes and on
the five-axis machines by data (docs/five-axis.md) alike, are drilled by moves, as
core/motion/cycles.py drills them on a three-axis machine, but along the tool axis:

* each CL point under CYCLE is a hole's top, its tool axis (i, j, k, from the tip towards
  the holder) the hole's axis: given with the point, or the one in force;
* the hole's moves are worked out in a frame whose third axis is the tool axis (the same
  legs, R plane, pecks, dwells and ways out as on a mill, the "level" measured along the
  tool axis), then carried back to part coordinates and sent, each with the tool axis,
  through the multiaxis element (GOLINE, the transform class or the kinematic chain);
* RETURN,0 goes back to the level along the tool axis the cycle's first hole started from.

A hole whose tool axis is not the one the tool stands at (a five-axis hole pattern, as NX's
5-axis drilling writes it) is reached as a commercial post reaches it: the tool, at the
clearance level along the old axis after the hole before, goes at rapid to the new hole's
clearance point along the NEW axis (the level it leaves the hole at: R, RETURN's level),
the kinematic chain turning the rotary axes on the way, and drills along the new axis from
there; OUT goes to the new hole's R point and drills in, staying at the bottom; IN
withdraws along the axis in force, as it does, then goes at rapid to the point at its level
along the new axis. A tool CYCLE/OUT left at the bottom of a hole cannot turn there: a hole
on a new axis then is bad input (take it out with CYCLE/IN first).
"""

from __future__ import annotations

from dataclasses import replace
from math import dist, isfinite, sqrt
from weakref import WeakKeyDictionary

from gecent.core.cl.records import Motion, MotionSubtype
from gecent.core.errors import InputError
from gecent.core.feed.rapid import RapidTraverse
from gecent.core.motion.cycles import CYCLE_TYPES, Cycle, Leg, cycle_legs
from gecent.core.motion.guard import check_segments
from gecent.core.motion.linear import godlta_delta, path_length
from gecent.core.motion.multiaxis import MultiaxisMotion
from gecent.core.output.element import OutputElement
from gecent.core.state import PostState

Vector = tuple[float, float, float]
# a hole's tool axis this near the one the tool stands at is the same axis (CL files print
# direction cosines to 6 decimals or so; 1e-5 is 0.0006 degrees)
SAME_AXIS = 1e-5


def _dot(a: Vector, b: Vector) -> float:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def hole_frame(axis: Vector) -> tuple[Vector, Vector, Vector]:
    """Unit vectors (e1, e2, axis), right-handed, the third along the tool axis; for the
    tool along +Z exactly the part's own axes, so a vertical hole is drilled to the same
    numbers as on a three-axis mill."""
    reference: Vector = (1.0, 0.0, 0.0) if abs(axis[0]) < 0.9 else (0.0, 1.0, 0.0)
    along = _dot(reference, axis)
    first: Vector = (
        reference[0] - along * axis[0],
        reference[1] - along * axis[1],
        reference[2] - along * axis[2],
    )
    length = sqrt(_dot(first, first))
    e1: Vector = (first[0] / length, first[1] / length, first[2] / length)
    e2: Vector = (
        axis[1] * e1[2] - axis[2] * e1[1],
        axis[2] * e1[0] - axis[0] * e1[2],
        axis[0] * e1[1] - axis[1] * e1[0],
    )
    return e1, e2, axis


def turns_the_tool(axis: Vector, standing: Vector) -> bool:
    """True when a hole's unit tool axis is not the one the tool stands at."""
    return max(abs(a - s) for a, s in zip(axis, standing, strict=True)) > SAME_AXIS


def tool_axis_legs(
    cycle: Cycle,
    at: Vector,
    hole: Vector,
    axis: Vector,
    first_level: float,
    standing: Vector | None = None,
    left_in: Vector | None = None,
) -> list[tuple[tuple[float, ...], Leg]]:
    """The moves that drill ``hole`` (its top, a CL point) along the unit tool ``axis`` from
    ``at``: each leg of core/motion/cycles.py worked out in the hole's frame, with its end
    carried back to a CL point with the tool axis (x, y, z, i, j, k). ``first_level``: the
    level along the axis the cycle started from (RETURN,0). ``standing``: the tool axis the
    tool is at; when the hole's differs, the first leg is a rapid to the hole's clearance
    point along the new axis (where the hole's way out ends), the tool turning on the way.
    ``left_in``: the top of the hole CYCLE/OUT left the tool in, which IN withdraws from."""
    e1, e2, _ = hole_frame(axis)

    def framed(p: Vector) -> Vector:
        return (_dot(p, e1), _dot(p, e2), _dot(p, axis))

    def carried(p: tuple[float, float, float]) -> tuple[float, ...]:
        a, b, c = p
        return (*(a * e1[n] + b * e2[n] + c * axis[n] for n in range(3)), *axis)

    along = replace(cycle, axis=2)
    start, top = framed(at), framed(hole)
    legs = []
    if standing is not None and turns_the_tool(axis, standing):
        way_out = CYCLE_TYPES[cycle.kind][0]
        if way_out == "withdraw":
            # IN: out along the axis the tool stands at, as IN withdraws, then at rapid to
            # the point at its level along the new axis, the tool turning on the way
            out_of = left_in if left_in is not None else hole
            withdrawal = tool_axis_legs(cycle, at, out_of, standing, first_level)[0]
            arrival = cycle_legs(along, top, top, first_level)[0].point
            return [withdrawal, (carried(arrival), Leg(arrival, rapid=True))]
        # the clearance point: where this hole's way out ends (its last leg), R or RETURN's;
        # OUT stays at the bottom, so its R point (its first leg from the top)
        clearance = cycle_legs(along, top, top, first_level)[0 if way_out == "stay" else -1].point
        legs.append((carried(clearance), Leg(clearance, rapid=True)))
        start = clearance
    for leg in cycle_legs(along, start, top, first_level):
        legs.append((carried(leg.point), leg))
    return legs


# where CYCLE/OUT left the tool (the bottom, and the top of that hole), per multiaxis
# element: a MultiaxisHoles is made for each record, the tool stays in the hole across them
_LEFT_IN_HOLE: WeakKeyDictionary[MultiaxisMotion, tuple[Vector, Vector]] = WeakKeyDictionary()


class MultiaxisHoles:
    """CYCLGX's holes: the legs of core/motion/cycles.py along the tool axis, through the
    multiaxis element."""

    def __init__(
        self,
        state: PostState,
        output: OutputElement,
        rapid: RapidTraverse,
        multiaxis: MultiaxisMotion,
    ) -> None:
        self.state = state
        self.output = output
        self.rapid = rapid
        self.multiaxis = multiaxis

    def record(self, record: Motion, cycle: Cycle, first_level: float | None) -> float:
        """Every point of ``record`` drilled as a hole; returns the level along the tool
        axis the cycle started from (``first_level``, or this record's start the first
        time)."""
        position = self.state.position
        for point in record.points:
            tx, ty, tz = position.translation
            previous = position.previous_part
            at: Vector = (previous[0] - tx, previous[1] - ty, previous[2] - tz)
            standing = self.multiaxis.tool_axis
            if record.subtype is MotionSubtype.GODLTA:
                delta = godlta_delta(point)
                hole: Vector = (at[0] + delta[0], at[1] + delta[1], at[2] + delta[2])
                axis = standing
            else:
                hole = (point[0], point[1], point[2])
                axis = self._axis(record, point, standing)
            if first_level is None:
                first_level = _dot(at, axis)
            bottom, top = _LEFT_IN_HOLE.get(self.multiaxis, (None, None))
            in_hole = bottom is not None and dist(at, bottom) < 1e-9
            withdraws = CYCLE_TYPES[cycle.kind][0] == "withdraw"
            if turns_the_tool(axis, standing) and in_hole and not withdraws:
                raise InputError(
                    f"CYCLE/{cycle.kind}: the hole's tool axis ({axis[0]:.6g}, {axis[1]:.6g}, "
                    f"{axis[2]:.6g}) is not the one the tool stands at ({standing[0]:.6g}, "
                    f"{standing[1]:.6g}, {standing[2]:.6g}), and CYCLE/OUT left the tool at the "
                    "bottom of the hole before, where it cannot turn: take it out first "
                    "(CYCLE/IN)",
                    record.where,
                )
            self._drill(
                record, cycle, axis, standing, at, hole, first_level, top if in_hole else None
            )
            if CYCLE_TYPES[cycle.kind][0] == "stay":
                tx, ty, tz = position.translation
                here = position.previous_part
                _LEFT_IN_HOLE[self.multiaxis] = ((here[0] - tx, here[1] - ty, here[2] - tz), hole)
            else:
                _LEFT_IN_HOLE.pop(self.multiaxis, None)
        assert first_level is not None
        return first_level

    def _axis(self, record: Motion, point: tuple[float, ...], standing: Vector) -> Vector:
        """The hole's tool axis, a unit vector (``standing`` when the point gives none)."""
        if len(point) < 6:
            return standing
        i, j, k = point[3:6]
        length = sqrt(i * i + j * j + k * k)
        if length == 0.0 or not isfinite(length):
            raise InputError(f"the tool axis {i:g}, {j:g}, {k:g} has no direction", record.where)
        return (i / length, j / length, k / length)

    def _drill(
        self,
        record: Motion,
        cycle: Cycle,
        axis: Vector,
        standing: Vector,
        at: Vector,
        hole: Vector,
        first_level: float,
        left_in: Vector | None = None,
    ) -> None:
        if cycle.kind == "DEEP" and cycle.step:
            pecks = int(min(abs(cycle.depth / cycle.step), 1e18))
            check_segments(pecks, self.state.max_segments, record.where, "deep-hole cycle")
        machine = self.state.machine
        for point, leg in tool_axis_legs(cycle, at, hole, axis, first_level, standing, left_in):
            if leg.dwell:
                block = self.output.dwell(leg.dwell)
                block.record = record.number
                self.output.output(block)
            code = None if leg.m_code_cell is None else machine.m_code(leg.m_code_cell)
            if code is not None:
                self.output.store_m(code)
            self._leg(record, point, leg.rapid)

    def _leg(self, record: Motion, point: tuple[float, ...], rapid: bool) -> None:
        """One move of the hole, as a one-point record with the record's number (a rapid
        one through RAPID's test, as any move)."""
        leg = Motion(record.file, record.line, record.number, MotionSubtype.GOTO, (point,))
        feed = self.state.feed
        if rapid:
            self.rapid.request()
        if feed.rapid_requested or feed.rapid_mode:
            self.rapid.motion(path_length(self.state.position, leg))
        self.multiaxis.goline(leg, point)
