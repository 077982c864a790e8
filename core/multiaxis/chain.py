"""A five-axis machine described by data (gecent, docs/five-axis.md): the machine file's
``[kinematics]`` table names two rotary axes, each on the table (turning the part) or on
the head (turning the tool), with its direction, a point on it and its travel, and the chain
carries CL points (tool tip x y z, tool axis i j k) to the machine's X Y Z and angles and
back, as the manual's nine classes do (core/multiaxis/transform.py).

The geometry, in machine coordinates with every angle 0 and the part's origin at the
machine's (the work offset):
* a table axis turns the part about its line (``pivot``, ``direction``) by the right-hand
  rule for a positive angle; the axes are listed from the bed outwards, so the last table
  axis carries the part and the first carries it and the other;
* a head axis turns the tool about its line, the pivot given from the controlled point (the
  spindle's gauge point); listed from the column to the spindle;
* the tool axis at zero angles is ``spindle`` (from the tip towards the holder).

Two rotary axes reach a tool axis in at most two ways (Paden and Kahan's second
sub-problem: two rotations carrying one unit vector onto another). The chain takes the way
within the axes' travel nearest the machine's last angles, the preferred one at the first
point; where the tool axis lies along the inner axis (the pole) that axis's angle is
indeterminate and keeps its last value.

With the control's tool-centre-point mode (gecent option 265 = 1: Fanuc G43.4, LinuxCNC's
TCP kinematics) X Y Z are the tool tip in the part, and the control moves the slides; without
it (0) they are the slides themselves: the tip carried through the table's turn, less the
head's swing of the tool (its pivot and the tool's length).
"""

from __future__ import annotations

from dataclasses import dataclass
from math import atan2, cos, degrees, radians, sin, sqrt
from typing import TYPE_CHECKING

from gecent.core.multiaxis.transform import (
    SINGULAR,
    Kinematics,
    MachinePoints,
    Points,
    as_points,
)

if TYPE_CHECKING:
    from collections.abc import Sequence

Vector = tuple[float, float, float]
COLUMNS = {"A": 3, "B": 4, "C": 5}
LIMITED, CONTINUOUS, ROLLOVER = "limited", "continuous", "rollover"


@dataclass(frozen=True, slots=True)
class RotaryAxis:
    """One rotary axis of the chain (degrees for its travel)."""

    letter: str  # A, B or C
    carrier: str  # "table" or "head"
    direction: Vector  # unit
    pivot: Vector
    limits: tuple[float, float] | None = None
    wrap: str = CONTINUOUS  # limited (travel within limits), continuous, rollover

    @property
    def column(self) -> int:
        return COLUMNS[self.letter]

    def within(self, angle: float) -> float | None:
        """The angle (degrees), or the same angle a turn away, within the travel (None: out
        of reach)."""
        if self.limits is None:
            return angle
        low, high = self.limits
        for turn in (0.0, 360.0, -360.0):
            if low - 1e-9 <= angle + turn <= high + 1e-9:
                return angle + turn
        return None


def _dot(a: Vector, b: Vector) -> float:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a: Vector, b: Vector) -> Vector:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _scaled(a: Vector, s: float) -> Vector:
    return (a[0] * s, a[1] * s, a[2] * s)


def _plus(a: Vector, b: Vector) -> Vector:
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def _minus(a: Vector, b: Vector) -> Vector:
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def unit(a: Sequence[float]) -> Vector:
    length = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])
    return (a[0] / length, a[1] / length, a[2] / length)


def turned(v: Vector, axis: Vector, angle: float) -> Vector:
    """v turned by ``angle`` (radians) about the unit ``axis`` (Rodrigues)."""
    c, s = cos(angle), sin(angle)
    along = _scaled(axis, _dot(axis, v) * (1.0 - c))
    return _plus(_plus(_scaled(v, c), _scaled(cross(axis, v), s)), along)


def turned_about(point: Vector, axis: RotaryAxis, angle: float) -> Vector:
    """A point turned about the axis's line."""
    return _plus(axis.pivot, turned(_minus(point, axis.pivot), axis.direction, angle))


def _angle_between(p: Vector, q: Vector, axis: Vector) -> float | None:
    """The turn about ``axis`` carrying p onto q (both at the same height on it), or None
    when p lies along the axis (any angle does)."""
    p_flat = _minus(p, _scaled(axis, _dot(axis, p)))
    q_flat = _minus(q, _scaled(axis, _dot(axis, q)))
    if _dot(p_flat, p_flat) < SINGULAR**2 or _dot(q_flat, q_flat) < SINGULAR**2:
        return None  # (along the axis to 1e-9 radians: nearer, the angle is still defined)
    return atan2(_dot(axis, cross(p_flat, q_flat)), _dot(p_flat, q_flat))


def two_turns(
    first: Vector, second: Vector, a: Vector, b: Vector
) -> list[tuple[float | None, float | None]]:
    """The angles (t1, t2) with R(first, t1) R(second, t2) a = b, up to two; an angle is
    None where it is indeterminate (a along ``second``, b along ``first``)."""
    cosine = _dot(first, second)
    across = cross(first, second)
    span = _dot(across, across)
    if span < SINGULAR:
        raise ValueError("the two rotary axes are parallel")
    target_first, target_second = _dot(first, b), _dot(second, a)
    # c = R(second, t2) a = R(first, -t1) b keeps its height on both axes
    alpha = (cosine * target_second - target_first) / (cosine * cosine - 1.0)
    beta = (cosine * target_first - target_second) / (cosine * cosine - 1.0)
    rest = 1.0 - alpha * alpha - beta * beta - 2.0 * alpha * beta * cosine
    if rest < -1e-9:
        return []
    gamma = sqrt(max(rest, 0.0) / span)
    found = []
    for sign in (1.0, -1.0) if gamma > 1e-12 else (1.0,):
        c = _plus(_scaled(first, alpha), _scaled(second, beta))
        c = _plus(c, _scaled(across, sign * gamma))
        t2 = _angle_between(a, c, second)
        back = _angle_between(b, c, first)
        found.append((None if back is None else -back, t2))
    return found


@dataclass(frozen=True, slots=True)
class KinematicChain:
    """The transform of a machine file's ``[kinematics]`` (the TransformClass protocol)."""

    axes: tuple[RotaryAxis, RotaryAxis]
    spindle: Vector = (0.0, 0.0, 1.0)
    tool_centre_point: bool = False
    prefer: float = -1.0  # the sign of the first axis's angle at the first point
    pole_zone: float = 1.0  # degrees
    tcp_on: str = ""  # the control's words for tool-centre-point mode (H follows)
    tcp_off: str = ""
    number: int = 0
    name: str = "KINEMATICS"
    section: str = "gecent [kinematics]"

    @property
    def structure(self) -> str:
        tables = sum(1 for axis in self.axes if axis.carrier == "table")
        return f"5(3,{tables},{2 - tables})"

    @property
    def rotary(self) -> tuple[int, ...]:
        return tuple(axis.column for axis in self.axes)

    @property
    def tables(self) -> tuple[RotaryAxis, ...]:
        return tuple(axis for axis in self.axes if axis.carrier == "table")

    @property
    def heads(self) -> tuple[RotaryAxis, ...]:
        return tuple(axis for axis in self.axes if axis.carrier == "head")

    @property
    def needs_tool_length(self) -> bool:
        """Slides computed for a tool the head swings: its length moves the tip."""
        return not self.tool_centre_point and bool(self.heads)

    @property
    def pole(self) -> RotaryAxis:
        """The axis whose angle the tool axis along it leaves open: the inner table axis, or
        the head axis nearest the spindle."""
        return self.tables[-1] if len(self.tables) == 2 else self.axes[-1]

    # -- the chain's two directions, one point --------------------------------------------

    def tool_axis_in_part(self, angles: tuple[float, float]) -> Vector:
        """The tool axis in the part at these angles (radians, in ``axes`` order)."""
        v = self.spindle
        for axis, angle in reversed(list(zip(self.axes, angles, strict=True))):
            if axis.carrier == "head":
                v = turned(v, axis.direction, angle)
        for axis, angle in zip(self.axes, angles, strict=True):
            if axis.carrier == "table":
                v = turned(v, axis.direction, -angle)
        return v

    def part_to_table(self, point: Vector, angles: tuple[float, float]) -> Vector:
        """A part point where the table's turn has carried it (machine coordinates)."""
        for axis, angle in reversed(list(zip(self.axes, angles, strict=True))):
            if axis.carrier == "table":
                point = turned_about(point, axis, angle)
        return point

    def table_to_part(self, point: Vector, angles: tuple[float, float]) -> Vector:
        for axis, angle in zip(self.axes, angles, strict=True):
            if axis.carrier == "table":
                point = turned_about(point, axis, -angle)
        return point

    def tip_from_slides(self, angles: tuple[float, float], length: float) -> Vector:
        """Where the tool tip is from the controlled point at these head angles."""
        tip = _scaled(self.spindle, -length)
        for axis, angle in reversed(list(zip(self.axes, angles, strict=True))):
            if axis.carrier == "head":
                tip = turned_about(tip, axis, angle)
        return tip

    def solutions(self, tool_axis: Vector) -> list[tuple[float | None, float | None]]:
        """The (first, second) angles (radians) that turn the spindle onto the tool axis."""
        first, second = self.axes
        if first.carrier == "table" and second.carrier == "table":
            # R1 R2 v = spindle
            return two_turns(first.direction, second.direction, tool_axis, self.spindle)
        if first.carrier == "head" and second.carrier == "head":
            # v = R1 R2 spindle
            return two_turns(first.direction, second.direction, self.spindle, tool_axis)
        table, head = (first, second) if first.carrier == "table" else (second, first)
        # R(table) v = R(head) spindle, so R(head, -h) R(table, t) v = spindle
        found = []
        for minus_head, table_angle in two_turns(
            head.direction, table.direction, tool_axis, self.spindle
        ):
            head_angle = None if minus_head is None else -minus_head
            found.append((table_angle, head_angle) if first is table else (head_angle, table_angle))
        return found

    def choose(
        self, tool_axis: Vector, before: tuple[float, float] | None
    ) -> tuple[tuple[float, float], bool] | None:
        """The angles (radians) for the tool axis: within travel, nearest ``before`` (the
        preferred sign of the first axis with none); an indeterminate angle keeps its value
        before. None when no way is within travel; the flag says a way was indeterminate."""
        best: tuple[float, tuple[float, float], bool] | None = None
        last = before if before is not None else (0.0, 0.0)
        for pair in self.solutions(tool_axis):
            chosen, singular, cost = [], False, 0.0
            for index, axis in enumerate(self.axes):
                angle = pair[index]
                if angle is None:
                    singular = True
                    angle = last[index]
                turn = (degrees(angle - last[index]) + 180.0) % 360.0 - 180.0
                wanted = degrees(last[index]) + turn if axis.limits is None else degrees(angle)
                placed = axis.within(wanted)
                if placed is None:
                    break
                chosen.append(radians(placed))
                cost += abs(placed - degrees(last[index]))
            else:
                if before is None:
                    cost = 0.0 if chosen[0] * self.prefer >= -1e-12 else 1.0
                key = (cost, (chosen[0], chosen[1]), singular)
                preferred = chosen[0] * self.prefer > 1e-12
                if (
                    best is None
                    or key[0] < best[0] - 1e-9
                    or (abs(key[0] - best[0]) <= 1e-9 and preferred)
                ):
                    best = key
        if best is None:
            return None
        return best[1], best[2]

    def slides(self, tip: Sequence[float], angles: tuple[float, float], length: float) -> Vector:
        """X, Y, Z for the tool tip at a part point with these angles: the tip itself under
        the control's tool centre point, else the slides."""
        point = (float(tip[0]), float(tip[1]), float(tip[2]))
        if self.tool_centre_point:
            return point
        carried = self.part_to_table(point, angles)
        return _minus(carried, self.tip_from_slides(angles, length))

    def swing(self, turns: Sequence[float], table_radius: float, head_radius: float) -> float:
        """The longest arc the axes' turns (degrees) sweep at their radii (options 112 and
        128): what times a move that turns the tool more than it moves it."""
        return max(
            (
                radians(abs(turn)) * (head_radius if axis.carrier == "head" else table_radius)
                for axis, turn in zip(self.axes, turns, strict=True)
            ),
            default=0.0,
        )

    def radius_about(
        self, axis: RotaryAxis, tip: Sequence[float], angles: tuple[float, float]
    ) -> float:
        """How far the tool tip at a part point is from a table axis's line (the radius it
        sweeps when that axis turns)."""
        point = self.part_to_table((float(tip[0]), float(tip[1]), float(tip[2])), angles)
        offset = _minus(point, axis.pivot)
        along = _scaled(axis.direction, _dot(offset, axis.direction))
        across = _minus(offset, along)
        return sqrt(_dot(across, across))

    def angles_of(self, row: Points) -> tuple[float, float]:
        """The chain's two angles (radians) of a machine row."""
        return (float(row[self.axes[0].column]), float(row[self.axes[1].column]))

    # -- the TransformClass protocol --------------------------------------------------------

    def direct(
        self, part: Points, kinematics: Kinematics, previous: Points | None = None
    ) -> MachinePoints:
        import numpy as np

        rows = as_points(part)
        machine = np.zeros_like(rows)
        singular = np.zeros(len(rows), dtype=bool)
        last = None if previous is None else self.angles_of(as_points(previous)[-1])
        for n, row in enumerate(rows):
            tool_axis = unit(row[3:6])
            answer = self.choose(tool_axis, last)
            if answer is None:
                raise Unreachable(self, tool_axis)
            angles, singular[n] = answer
            tip = (float(row[0]), float(row[1]), float(row[2]))
            machine[n, 0:3] = self.slides(tip, angles, kinematics.reach)
            machine[n, self.axes[0].column] = angles[0]
            machine[n, self.axes[1].column] = angles[1]
            last = angles
        return MachinePoints(machine, singular)

    def inverse(self, machine: Points, kinematics: Kinematics) -> Points:
        import numpy as np

        rows = as_points(machine)
        part = np.zeros_like(rows)
        for n, row in enumerate(rows):
            angles = self.angles_of(row)
            slides = (float(row[0]), float(row[1]), float(row[2]))
            if self.tool_centre_point:
                tip = slides
            else:
                carried = _plus(slides, self.tip_from_slides(angles, kinematics.reach))
                tip = self.table_to_part(carried, angles)
            part[n, 0:3] = tip
            part[n, 3:6] = self.tool_axis_in_part(angles)
        return part


class Unreachable(ValueError):
    """No way of the two rotary axes within their travel points the tool along this axis."""

    def __init__(self, chain: KinematicChain, tool_axis: Vector) -> None:
        travel = ", ".join(
            f"{axis.letter} {axis.limits[0]:g} to {axis.limits[1]:g}"
            for axis in chain.axes
            if axis.limits is not None
        )
        i, j, k = tool_axis
        super().__init__(
            f"the tool axis ({i:.6f}, {j:.6f}, {k:.6f}) is beyond the rotary axes' travel"
            + (f" ({travel})" if travel else "")
        )
