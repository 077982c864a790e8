"""What the CL file asks of a five-axis machine, for `gecent verify` (core/verify/fiveaxis.py):
each CL point as a pose, the tool tip and the tool axis, in the order the post reaches
them, with the moves a five-axis canned cycle makes along each hole's own axis."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from math import dist

from gecent.core.cl.records import Motion, MotionSubtype, Record, Statement, Word
from gecent.core.errors import SourcePosition
from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.cycles import CYCLE_TYPES
from gecent.core.motion.multiaxis_cycles import tool_axis_legs
from gecent.core.multiaxis.chain import unit
from gecent.core.verify.clpath import ArcSpec, Point, _Reader


@dataclass(frozen=True, slots=True)
class Pose:
    """A CL point with its tool axis, the kind of move that reaches it and the feed, the
    tool's length and LINTOL's radius in force (0: no linearity test)."""

    tip: Point
    axis: Point
    kind: str
    where: SourcePosition
    statement: str
    feed: tuple[float, bool] | None
    tool: int | None
    lintol: float
    rpm: float | None = None  # the spindle's speed in force (a feed per revolution)


class _PoseReader(_Reader):
    """The CL path as clpath reads it, each point with the tool axis in force."""

    def __init__(self, machine: MachineDefinition) -> None:
        super().__init__(machine)
        self.axis: Point = (0.0, 0.0, 1.0)
        self.poses: list[Pose] = []
        self.lintol = 0.0
        self.lintol_off = False  # LINTOL/OFF: one-point records untested
        self.rpm: float | None = None
        self.lengths: dict[int, float] = {}  # T code: LOADTL LENGTH (machine units)
        self._axes: list[Point] = []
        self.left_in: tuple[Point, Point] | None = None  # CYCLE/OUT's bottom and hole top

    def _points(self, record: Motion) -> list[Point]:
        if record.subtype is MotionSubtype.GODLTA:
            self._axes = []
            return super()._points(record)
        tx, ty, tz = self.translation
        points, axes = [], []
        for p in record.points:
            if len(p) >= 6 and any(p[3:6]):
                self.axis = unit(p[3:6])
            points.append((p[0] + tx, p[1] + ty, p[2] + tz))
            axes.append(self.axis)
        self._axes = axes
        return points

    def _target(self, point: Point, kind: str, record: Motion, arc: ArcSpec | None) -> None:
        super()._target(point, kind, record, arc)
        axis = self._axes.pop(0) if self._axes else self.axis
        text = f"{record.subtype.name}/" + ",".join(f"{v:.4f}" for v in (*point, *axis))
        lintol = 0.0 if self.lintol_off and len(record.points) == 1 else self.lintol
        pose = Pose(
            point, axis, kind, record.where, text, self.feed, self.state.tool, lintol, self.rpm
        )
        last = self.poses[-1] if self.poses else None
        if last is not None and last.tip == pose.tip and last.axis == pose.axis:
            return  # a point repeated: the tape does not move for it
        self.poses.append(pose)

    def _holes(self, record: Motion, points: list[Point]) -> None:
        """Each point a hole drilled along its tool axis, as the post drills it on a
        multiaxis machine (core/motion/multiaxis_cycles.py): its first leg a cycle entry
        (any moves may lead there: on a new tool axis the rapid that turns the tool to the
        hole's clearance point), then the post's own rapid and feed moves."""
        assert self.cycle is not None
        self.rapid_once = False
        axes = self._axes or [self.axis] * len(points)
        for hole, axis in zip(points, axes, strict=True):
            if self.cycle_first_z is None:  # (the level along the tool axis, RETURN,0)
                self.cycle_first_z = sum(a * b for a, b in zip(self.at, axis, strict=True))
            standing = self.poses[-1].axis if self.poses else (0.0, 0.0, 1.0)
            bottom, top = self.left_in or (None, None)
            in_hole = bottom is not None and dist(self.at, bottom) < 1e-9
            left_in = top if in_hole else None
            legs = tool_axis_legs(
                self.cycle, self.at, hole, axis, self.cycle_first_z, standing, left_in
            )
            for index, (point, leg) in enumerate(legs):
                kind = "cycle-entry" if index == 0 else "rapid" if leg.rapid else "feed"
                self._axes = [(point[3], point[4], point[5])]  # (IN's way out: the old axis)
                self._target((point[0], point[1], point[2]), kind, record, None)
            stays = CYCLE_TYPES[self.cycle.kind][0] == "stay"  # (the post's MultiaxisHoles)
            self.left_in = (self.at, hole) if stays else None
        self._axes = []

    def _statement(self, statement: Statement) -> None:
        super()._statement(statement)
        major = statement.major
        if major == "LINTOL":
            numbers = statement.numbers()
            words = statement.words()
            if "OFF" in words or "ON" in words:
                self.lintol_off = "OFF" in words  # (one-point records untested under OFF)
            if numbers:
                self.lintol = self.units.length(abs(numbers[0]))
                self.lintol_off = False  # (LINTOL/r tests one-point records again)
        elif major == "SPINDL":
            numbers = statement.numbers()
            if numbers and "OFF" not in statement.words():
                self.rpm = abs(numbers[0])
        elif major in ("LOADTL", "TOOLNO") and self.state.tool is not None:
            args = statement.args
            for index, arg in enumerate(args[:-1]):
                following = args[index + 1]
                if (
                    isinstance(arg, Word)
                    and arg.name == "LENGTH"
                    and not isinstance(following, Word)
                ):
                    self.lengths[self.state.tool] = self.units.length(float(following))


def cl_poses(
    records: Iterable[Record], machine: MachineDefinition
) -> tuple[list[Pose], dict[int, float]]:
    reader = _PoseReader(machine)
    path = reader.read(records)
    if path.unfollowed:
        first = path.unfollowed[0]
        raise ValueError(f"the CL file moves the tool by {first.major} at {first.where}")
    return reader.poses, reader.lengths
