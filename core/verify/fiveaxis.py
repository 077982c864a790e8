"""`gecent verify` on a five-axis machine by data (docs/five-axis.md): LinuxCNC's rs274
reads the tape (X, Y, Z and the rotary words), the machine's own kinematics carry every
move's end back to the part (the tool tip and the tool axis), and the CL file's points must
be reached in order, each within the tolerance in the tip and within the angle tolerance
in the axis.

Between two CL points the tape may make more moves (LINTOL's inserted points): each must
end on the CL segment, its axis between the two CL axes; a rapid move may go anywhere. A
feed move's F must be the CL feed at the tool tip: the feed itself under G94, or under G93
(inverse time) the tip's path over the move's minutes. Inside each feed move the control
interpolates the machine's axes; the tip's largest departure from the CL line (the
linearity error the manual's LINTOL bounds, §3.4.7.3) is measured at its quarter points and
reported, and where LINTOL is in force its midpoint must keep within LINTOL's radius (and
the tolerance: the post tests the machine points before they are rounded to the tape).
The CL side, each CL point as a pose, is core/verify/fiveaxis_cl.py.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from math import acos, degrees, radians, sqrt

from gecent.core.machine.definition import MachineDefinition
from gecent.core.multiaxis.chain import KinematicChain, unit
from gecent.core.multiaxis.transform import Kinematics
from gecent.core.verify.clpath import Point
from gecent.core.verify.fiveaxis_cl import Pose
from gecent.core.verify.rs274 import Interpretation, TapeMove

DEFAULT_AXIS_TOLERANCE = 0.001  # degrees
QUARTERS = (0.25, 0.5, 0.75)


@dataclass(frozen=True, slots=True)
class Miss:
    pose: Pose
    move: TapeMove | None
    reason: str


@dataclass
class FiveAxisComparison:
    poses: int
    moves: int
    feeds: int = 0
    tip_deviation: float = 0.0
    axis_deviation: float = 0.0  # degrees
    linearity: float = 0.0  # the tip's largest departure from the CL line inside a move
    miss: Miss | None = None
    lintol_checked: int = 0

    @property
    def passed(self) -> bool:
        return self.miss is None


def _angle(a: Point, b: Point) -> float:
    cosine = max(-1.0, min(1.0, a[0] * b[0] + a[1] * b[1] + a[2] * b[2]))
    return degrees(acos(cosine))


def _segment_distance(point: Point, start: Point, end: Point) -> tuple[float, float]:
    """The distance from the point to the segment, and where along it (0..1) it is nearest."""
    d = [end[a] - start[a] for a in range(3)]
    w = [point[a] - start[a] for a in range(3)]
    length = sum(c * c for c in d)
    t = (
        0.0
        if length == 0
        else max(0.0, min(1.0, sum(p * q for p, q in zip(w, d, strict=True)) / length))
    )
    return sqrt(sum((w[a] - t * d[a]) ** 2 for a in range(3))), t


def _axis_between(axis: Point, start: Point, end: Point) -> float:
    """How far (degrees) the axis is from the great-circle arc between two axes."""
    whole = _angle(start, end)
    if whole < 1e-9:
        return _angle(axis, start)
    normal = unit(
        (
            start[1] * end[2] - start[2] * end[1],
            start[2] * end[0] - start[0] * end[2],
            start[0] * end[1] - start[1] * end[0],
        )
    )
    height = sum(a * n for a, n in zip(axis, normal, strict=True))
    flat = tuple(a - height * n for a, n in zip(axis, normal, strict=True))
    nearest = min(_angle(axis, start), _angle(axis, end))
    if sum(c * c for c in flat) < 1e-18:
        return nearest
    foot = unit(flat)
    if abs(_angle(start, foot) + _angle(foot, end) - whole) < 1e-7:
        return _angle(axis, foot)
    return nearest


class FiveAxisKinematics:
    """The machine's forward kinematics on rs274's moves: the part pose of a machine point."""

    def __init__(
        self, machine: MachineDefinition, chain: KinematicChain, lengths: dict[int, float]
    ) -> None:
        self.chain = replace(chain, tool_centre_point=machine.number_option(265) == 1)
        self.lengths = lengths
        self.rollover = tuple(axis.wrap == "rollover" for axis in chain.axes)
        self.table_radius = machine.number_option(112)
        self.head_radius = machine.number_option(128)
        self.step = machine.number_option(14)
        f_format = machine.registers.formats[11]
        self.inverse_limit = f_format.largest if f_format is not None else 1e9

    def angles(self, move: TapeMove) -> tuple[float, float]:
        first, second = (move.rotary[axis.column - 3] for axis in self.chain.axes)
        return (first, second)

    def pose(self, slides: Point, angles: tuple[float, float], tool: int) -> tuple[Point, Point]:
        import numpy as np

        row = np.zeros((1, 6))
        row[0, 0:3] = slides
        for axis, angle in zip(self.chain.axes, angles, strict=True):
            row[0, axis.column] = radians(angle)
        reach = self.lengths.get(tool, 0.0) if self.chain.needs_tool_length else 0.0
        part = self.chain.inverse(row, Kinematics(reach=reach))[0]
        return (
            (float(part[0]), float(part[1]), float(part[2])),
            (float(part[3]), float(part[4]), float(part[5])),
        )

    def turns(self, start: tuple[float, float], end: tuple[float, float]) -> list[float]:
        """Each axis's turn (degrees) between two machine points: a rollover axis the
        shorter way, as the control turns it."""
        turns = []
        for index, (a, b) in enumerate(zip(start, end, strict=True)):
            turn = b - a
            if self.rollover[index]:
                turn = (turn + 180.0) % 360.0 - 180.0
            turns.append(turn)
        return turns

    def between(self, before: TapeMove, after: TapeMove, s: float) -> tuple[Point, Point]:
        """The part pose a fraction s into the move (the control interpolates its axes; a
        rollover axis the shorter way)."""
        start = self.angles(before)
        turns = self.turns(start, self.angles(after))
        angles = [a + s * t for a, t in zip(start, turns, strict=True)]
        slides = tuple(before.end[a] + s * (after.end[a] - before.end[a]) for a in range(3))
        return self.pose((slides[0], slides[1], slides[2]), (angles[0], angles[1]), after.tool)


def compare_poses(
    poses: list[Pose],
    moves: list[TapeMove],
    kinematics: FiveAxisKinematics,
    tolerance: float,
    axis_tolerance: float,
    feed_decimals: int,
) -> FiveAxisComparison:
    result = FiveAxisComparison(len(poses), len(moves))
    index = 0
    previous: Pose | None = None
    before: TapeMove | None = None
    before_tip: Point | None = None
    for move in moves:
        tip, axis = kinematics.pose(move.end, kinematics.angles(move), move.tool)
        if index >= len(poses):
            result.miss = Miss(poses[-1], move, "the tape moves on after the last CL point")
            return result
        pose = poses[index]
        reached = (
            all(abs(tip[a] - pose.tip[a]) <= tolerance for a in range(3))
            and _angle(axis, pose.axis) <= axis_tolerance
        )
        feed_move = move.kind == "feed"
        if (
            not reached
            and previous is not None
            and all(abs(tip[a] - previous.tip[a]) <= tolerance for a in range(3))
            and _angle(axis, previous.axis) <= axis_tolerance
        ):
            before, before_tip = move, tip  # still at the CL point just reached (a turn there)
            continue
        if feed_move and pose.kind == "rapid" and not reached:
            result.miss = Miss(pose, move, "a feed move where the CL moves at rapid")
            return result
        if move.kind == "rapid" and pose.kind == "feed":
            result.miss = Miss(pose, move, "a rapid move where the CL cuts")
            return result
        if not reached and pose.kind == "feed":
            start = previous.tip if previous is not None else before_tip
            if start is None:
                result.miss = Miss(pose, move, "the tape cuts before the first CL point")
                return result
            off, _ = _segment_distance(tip, start, pose.tip)
            turn = _axis_between(axis, previous.axis if previous else pose.axis, pose.axis)
            if off > tolerance or turn > axis_tolerance:
                result.miss = Miss(
                    pose,
                    move,
                    f"the move ends {off:.4f} off the CL line and its tool axis {turn:.4f} "
                    "degrees off the CL's",
                )
                return result
        if feed_move and before is not None and before_tip is not None:
            problem = _feed(result, kinematics, before, move, pose, tip, before_tip, feed_decimals)
            if problem is not None:
                result.miss = Miss(pose, move, problem)
                return result
            _linearity(result, kinematics, before, move, previous, pose, tolerance)
        if reached:
            result.tip_deviation = max(
                result.tip_deviation, max(abs(tip[a] - pose.tip[a]) for a in range(3))
            )
            result.axis_deviation = max(result.axis_deviation, _angle(axis, pose.axis))
            previous = pose
            index += 1
        before, before_tip = move, tip
    if index < len(poses):
        result.miss = Miss(poses[index], None, "the tape ends before this CL point")
    return result


def _feed(
    result: FiveAxisComparison,
    kinematics: FiveAxisKinematics,
    before: TapeMove,
    move: TapeMove,
    pose: Pose,
    tip: Point,
    before_tip: Point,
    decimals: int,
) -> str | None:
    """The tip's feed against the CL's: F itself under G94 (G95), and under G93 the move's
    minutes: the tip's path in the part at the CL feed, or for a turn of the tool alone (a
    tip that moves less than a step) each axis's arc at its radius (options 112, 128), F
    held to what its register holds; to F's rounding and the positions'."""
    if pose.feed is None:
        return None
    value, per_revolution = pose.feed
    path = sqrt(sum((tip[a] - before_tip[a]) ** 2 for a in range(3)))
    half = 0.5 * 10.0**-decimals
    turns = kinematics.turns(kinematics.angles(before), kinematics.angles(move))
    turning = any(abs(t) > 1e-9 for t in turns)
    if not move.inverse_time:
        if turning and not kinematics.chain.tool_centre_point:
            return (
                "a move that turns the part under G94: F is the slides' feed, not the tool "
                "tip's (the post times such moves, G93)"
            )
        result.feeds += 1
        if abs(move.feed - value) > half + 1e-9:
            return f"F is {move.feed:.4f}, the CL's feed {value:.4f}"
        return None
    if per_revolution:
        if pose.rpm is None:
            return None
        value *= pose.rpm
    # rs274 reports G93's F as a feed over the move's X, Y, Z travel (over A, B, C when the
    # slides stand), and never below 0.1
    travel = sqrt(sum((move.end[a] - before.end[a]) ** 2 for a in range(3)))
    written = [move.rotary[a] - before.rotary[a] for a in range(3)]  # (rs274: no rollover)
    measure = travel if travel > 1e-9 else sqrt(sum(t * t for t in written))
    if measure <= 0.0:
        return None
    inverse = move.feed / measure
    swing = kinematics.chain.swing(turns, kinematics.table_radius, kinematics.head_radius)
    step = kinematics.step
    lengths = [length for length in (path, swing) if length > 0.0]
    if path < 2.0 * step:  # (the post's "less than a step" on the unrounded path)
        lengths = [swing] + ([path] if path >= step / 2 else [])
    if not lengths or max(lengths) <= 0.0:
        return None
    result.feeds += 1
    expected = []
    for length in lengths:
        wanted = min(value / length, kinematics.inverse_limit)
        if move.feed <= 0.1 + 1e-9 and wanted * measure < 0.1:
            return None  # (rs274's floor: F is not read back)
        # the tape's positions are rounded to the step: its path is off by up to 2 steps
        allowed = half + wanted * (2.0 * sqrt(3.0) * step / length + 1e-4) + 1e-9
        if abs(inverse - wanted) <= allowed:
            return None
        expected.append(f"{wanted:.4f} over {length:.4f}")
    return f"G93's F is {inverse:.4f} (1/min), the CL's feed gives {' or '.join(expected)}"


def _linearity(
    result: FiveAxisComparison,
    kinematics: FiveAxisKinematics,
    before: TapeMove,
    move: TapeMove,
    previous: Pose | None,
    pose: Pose,
    tolerance: float,
) -> None:
    """The tip's departure from the CL line inside the move; LINTOL's radius holds at the
    midpoint, to the tape's rounding (the post tests the unrounded machine points)."""
    if previous is None:
        return
    for s in QUARTERS:
        tip, _ = kinematics.between(before, move, s)
        off, _ = _segment_distance(tip, previous.tip, pose.tip)
        result.linearity = max(result.linearity, off)
        if s == 0.5 and pose.lintol > 0.0:
            result.lintol_checked += 1
            if off > pose.lintol + tolerance and result.miss is None:
                result.miss = Miss(
                    pose,
                    move,
                    f"the tool tip leaves the CL line by {off:.4f} in the middle of the move, "
                    f"more than LINTOL's {pose.lintol:g}",
                )


@dataclass
class FiveAxisVerification:
    machine: MachineDefinition
    interpretation: Interpretation
    comparison: FiveAxisComparison | None
    tolerance: float
    axis_tolerance: float
    unit: str
    tape_lines: list[str]
    problem: str | None = None
    notes: list[str] = field(default_factory=list)

    @property
    def passed(self) -> bool:
        return self.problem is None and self.comparison is not None and self.comparison.passed

    def report(self) -> list[str]:
        if self.problem is not None:
            return [f"verify: FAILED: {self.problem}"]
        if self.comparison is None:
            line = self.interpretation.error_line
            text = self._tape_text(line)
            return [
                "verify: FAILED: rs274 stopped reading the tape"
                + (f" at tape line {line}: {text}" if line else ""),
                f"  rs274: {self.interpretation.error}",
            ]
        result = self.comparison
        chain = self.machine.kinematics
        assert chain is not None
        mode = (
            "the control's tool centre point"
            if self.machine.number_option(265) == 1
            else "slides computed"
        )
        lines = [
            f"verify: {result.moves} tape moves (rs274), {result.poses} CL points with their "
            f"tool axes, {result.feeds} feeds checked, through the machine's kinematics "
            f"({''.join(a.letter for a in chain.axes)}, {mode}); tolerance "
            f"{self.tolerance:g} {self.unit}, {self.axis_tolerance:g} degrees",
            f"max deviation: tool tip {result.tip_deviation:.4f} {self.unit}, tool axis "
            f"{result.axis_deviation:.4f} degrees",
            f"linearity: the tool tip leaves the CL line by at most {result.linearity:.4f} "
            f"{self.unit} inside a move"
            + (
                f" ({result.lintol_checked} midpoints held to LINTOL)"
                if result.lintol_checked
                else ""
            ),
            *self.notes,
        ]
        miss = result.miss
        if miss is None:
            lines.append("verify: passed: every CL point and tool axis reached in order")
            return lines
        lines.append(
            f"verify: FAILED: first mismatch at CL {miss.pose.where}: {miss.pose.statement}"
        )
        if miss.move is not None:
            line = miss.move.line
            lines.append(f"  tape line {line}: {self._tape_text(line)}")
        lines.append(f"  {miss.reason}")
        return lines

    def _tape_text(self, line: int | None) -> str:
        if line is None or not 1 <= line <= len(self.tape_lines):
            return "?"
        return self.tape_lines[line - 1].strip()
