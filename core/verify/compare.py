"""The tape's path (rs274's moves) against the CL path: every CL point reached in order
within the tolerance, by the kind of move the CL asks for; arcs with the CL's centre, radius
and sense; feeds equal to the programmed ones. Between two CL points a straight cut may be
split into several moves, each ending on the CL segment; a rapid move may go anywhere on its
way (the control's own path); inside a canned cycle the control's moves stay on the hole's
axis.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from math import hypot

from gecent.core.verify.clpath import PLANE_AXES, ClPath, Point, Target, radius_of
from gecent.core.verify.rs274 import OffsetWords, TapeMove

AXIS_NAMES = "XYZ"


@dataclass(frozen=True, slots=True)
class Mismatch:
    target: Target
    move: TapeMove | None
    reason: str


@dataclass
class Comparison:
    targets: int
    moves: int
    arcs: int = 0
    feeds: int = 0
    deviation: list[float] = field(default_factory=lambda: [0.0, 0.0, 0.0])
    mismatch: Mismatch | None = None

    @property
    def passed(self) -> bool:
        return self.mismatch is None


def _segment_distance(point: Point, start: Point, end: Point, axes: tuple[int, ...]) -> float:
    """The distance from ``point`` to the segment start-end over the compared axes."""
    d = [end[a] - start[a] for a in axes]
    w = [point[a] - start[a] for a in axes]
    length = sum(c * c for c in d)
    t = (
        0.0
        if length == 0
        else max(0.0, min(1.0, sum(p * q for p, q in zip(w, d, strict=True)) / length))
    )
    return float(sum((w[i] - t * d[i]) ** 2 for i in range(len(axes))) ** 0.5)


class _Walk:
    def __init__(
        self,
        path: ClPath,
        moves: list[TapeMove],
        tolerance: float,
        feed_tol: float,
        offsets: list[OffsetWords],
        arc_tolerance: float,
    ):
        self.path = path
        self.moves = moves
        self.tolerance = tolerance
        self.arc_tolerance = arc_tolerance  # centre and radius: the I/J/K words round too
        self.feed_tolerance = feed_tol
        self.offsets = offsets
        self.axes = path.compared
        self.result = Comparison(len(path.targets), len(moves))
        self.start: Point = (0.0, 0.0, 0.0)  # where the move being checked begins

    def close(self, a: Point, b: Point) -> bool:
        return all(abs(a[i] - b[i]) <= self.tolerance for i in self.axes)

    def note(self, tape: Point, cl: Point) -> None:
        deviation = self.result.deviation
        for i in self.axes:
            deviation[i] = max(deviation[i], abs(tape[i] - cl[i]))

    def run(self) -> Comparison:
        at: Point = (0.0, 0.0, 0.0)  # rs274 starts at the origin
        cl_at: Point | None = None
        index = 0
        for target in self.path.targets:
            if (target.arc is None or not target.arc.full) and self.close(at, target.point):
                # (an arc whose end rounds onto its start is no move: the post gives none)
                self.note(at, target.point)
                cl_at = target.point
                continue
            reached = False
            while index < len(self.moves):
                move = self.moves[index]
                index += 1
                if move.kind != "arc" and move.end == at:
                    continue  # no move (a canned cycle's rapid to the level it is at)
                self.start = at
                problem = self.check(move, target, cl_at)
                if problem is not None:
                    self.result.mismatch = Mismatch(target, move, problem)
                    return self.result
                at = move.end
                if self.close(at, target.point):
                    self.note(at, target.point)
                    reached = True
                    break
                if target.arc is not None and not target.arc.chords and move.kind != "arc":
                    # (an arc split at the quadrants goes on in arcs about the same centre)
                    self.result.mismatch = Mismatch(
                        target, move, "the arc does not end at the CL point"
                    )
                    return self.result
            if not reached:
                self.result.mismatch = Mismatch(target, None, "the tape ends before this point")
                return self.result
            cl_at = target.point
        return self.result

    def check(self, move: TapeMove, target: Target, cl_at: Point | None) -> str | None:
        kind = target.kind
        if kind == "rapid":
            if move.kind != "rapid":
                return f"a {move.kind} move where the CL has RAPID"
            return self.rapid_problem(move, target, cl_at)
        if move.kind != "rapid":
            problem = self.machine_problem(move, target)
            if problem is not None:
                return problem
        if kind in ("cycle-entry", "cycle"):
            if kind == "cycle" and cl_at is not None:
                off = hypot(*(move.end[i] - cl_at[i] for i in self.axes if i != 2))
                if off > self.tolerance:
                    return f"leaves the hole's axis by {off:.4f}"
            return self.feed_problem(move, target) if move.kind != "rapid" else None
        if move.kind == "rapid":
            return "a rapid move where the CL cuts at feed"
        problem = self.feed_problem(move, target)
        if problem is not None:
            return problem
        if target.arc is not None:
            return self.arc_problem(move, target)
        if move.kind == "arc":
            return "an arc where the CL has a straight cut"
        if cl_at is not None and not self.close(move.end, target.point):
            off = _segment_distance(move.end, cl_at, target.point, self.axes)
            if off > self.tolerance:
                return f"ends {off:.4f} off the CL segment"
        return None

    def rapid_problem(self, move: TapeMove, target: Target, cl_at: Point | None) -> str | None:
        """A rapid move stays within the box of the CL's two points (the control's own way
        between them, never a dip below both or a detour beyond them)."""
        if cl_at is None:
            return None
        for axis in self.axes:
            low = min(cl_at[axis], target.point[axis]) - self.tolerance
            high = max(cl_at[axis], target.point[axis]) + self.tolerance
            if not low <= move.end[axis] <= high:
                return (
                    f"a rapid move to {AXIS_NAMES[axis]} {move.end[axis]:.4f}, outside the way "
                    f"between the CL's points ({low + self.tolerance:.4f} to "
                    f"{high - self.tolerance:.4f})"
                )
        return None

    def machine_problem(self, move: TapeMove, target: Target) -> str | None:
        """While the tool cuts: the tool the CL loaded, its spindle turning as SPINDL says,
        cutter compensation on the CL's side, and a modern mill's H (with G43) and D."""
        state = target.machine
        if state is None:
            return None
        # inside a canned cycle the control reverses the spindle to tap out: the sense is
        # the control's there
        tapping_out = target.kind == "cycle" and move.spindle != 0 and state.spindle != 0
        if state.spindle is not None and state.spindle != move.spindle and not tapping_out:
            if move.spindle == 0:
                return "the spindle is stopped where the CL cuts"
            if state.spindle == 0:
                return "the spindle turns where the CL has it off"
            return "the spindle turns the other way than the CL's SPINDL"
        if state.tool is not None and state.tool != move.tool:
            return f"tool T{move.tool} cuts where the CL has loaded T{state.tool}"
        if state.side is not None and state.side != move.side:
            where = move.side or "off"
            return f"cutter compensation {where} where the CL has {state.side or 'it off'}"
        words = self.offsets[move.line - 1] if 0 < move.line <= len(self.offsets) else None
        if words is not None and state.h is not None:
            if not words.length_on:
                return "tool length compensation (G43) is off where the tool cuts"
            if words.h != state.h:
                return f"H{words.h} where the tool's offset number is {state.h}"
        if words is not None and state.side and state.d is not None and words.d != state.d:
            return f"D{words.d} where the CL's compensation is D{state.d}"
        return None

    def feed_problem(self, move: TapeMove, target: Target) -> str | None:
        if target.feed is None:
            return None
        value, per_revolution = target.feed
        self.result.feeds += 1
        if per_revolution != move.per_revolution:
            mode = "per revolution" if per_revolution else "per minute"
            return f"feed mode: the CL's feed is {mode}"
        if abs(move.feed - value) > self.feed_tolerance:
            return f"feed {move.feed:g} where the CL has {value:g}"
        return None

    def tilted_chord_problem(self, move: TapeMove, target: Target) -> str | None:
        """A circle about a tilted axis, given as chords in its own plane: each move ends
        on the circle, turns the circle's way about the axis and falls inside the arc no
        more than the chord tolerance."""
        arc = target.arc
        assert arc is not None and arc.normal is not None
        if move.kind == "arc":
            return "an arc where the machine posts straight moves along it"
        n = arc.normal
        end = tuple(e - c for e, c in zip(move.end, arc.centre, strict=True))
        along = sum(e * k for e, k in zip(end, n, strict=True))
        low, high = sorted(arc.rise)
        if not low - self.tolerance <= along <= high + self.tolerance:
            return f"a move along the arc leaves its plane by {max(low - along, along - high):.4f}"
        a = _in_plane(tuple(s - c for s, c in zip(self.start, arc.centre, strict=True)), n)
        b = _in_plane(end, n)
        radius = hypot(*b)
        if abs(radius - arc.radius) > self.arc_tolerance:
            return f"a move along the arc ends {abs(radius - arc.radius):.4f} off it"
        cross = (
            (a[1] * b[2] - a[2] * b[1]) * n[0]
            + (a[2] * b[0] - a[0] * b[2]) * n[1]
            + (a[0] * b[1] - a[1] * b[0]) * n[2]
        )
        if abs(cross) > self.tolerance * arc.radius and (cross > 0) != arc.counterclockwise:
            return "a move along the arc goes back against the arc's sense"
        half = hypot(*(q - p for p, q in zip(a, b, strict=True))) / 2
        sag = arc.radius - max(0.0, arc.radius * arc.radius - half * half) ** 0.5
        if half > arc.radius or sag > arc.sag + self.arc_tolerance:
            return (
                f"a straight move along the arc falls {sag:.4f} inside it, more than "
                f"the machine's chord tolerance {arc.sag:g}"
            )
        if self.close(move.end, target.point):
            self.result.arcs += 1
        return None

    def arc_problem(self, move: TapeMove, target: Target) -> str | None:
        arc = target.arc
        assert arc is not None
        if arc.normal is not None:
            return self.tilted_chord_problem(move, target)
        if arc.chords:  # straight moves along the arc (options 261/262): each ends on it
            if move.kind == "arc":
                return "an arc where the machine posts straight moves along it"
            radius = radius_of(move.end, arc.centre, arc.plane)
            if abs(radius - arc.radius) > self.arc_tolerance:
                return f"a move along the arc ends {abs(radius - arc.radius):.4f} off it"
            first, second = PLANE_AXES[arc.plane]
            a = (self.start[first] - arc.centre[first], self.start[second] - arc.centre[second])
            b = (move.end[first] - arc.centre[first], move.end[second] - arc.centre[second])
            cross = a[0] * b[1] - a[1] * b[0]
            if abs(cross) > self.tolerance * arc.radius and (cross > 0) != arc.counterclockwise:
                return "a move along the arc goes back against the arc's sense"
            half = hypot(b[0] - a[0], b[1] - a[1]) / 2
            sag = arc.radius - max(0.0, arc.radius * arc.radius - half * half) ** 0.5
            if half > arc.radius or sag > arc.sag + self.arc_tolerance:
                return (
                    f"a straight move along the arc falls {sag:.4f} inside it, more than "
                    f"the machine's chord tolerance {arc.sag:g}"
                )
            if self.close(move.end, target.point):
                self.result.arcs += 1
            return None
        if move.kind != "arc" or move.centre is None:
            return "a straight move where the CL has an arc"
        self.result.arcs += 1
        if abs(move.rotation) != 1:
            return f"the arc turns {abs(move.rotation)} times (a P word): the CL's turns once"
        if move.plane != arc.plane:
            return f"an arc in the {move.plane} plane, the CL's is in {arc.plane}"
        first, second = PLANE_AXES[arc.plane]
        for axis in (first, second):
            off = abs(move.centre[axis] - arc.centre[axis])
            if off > self.arc_tolerance:
                return f"arc centre {AXIS_NAMES[axis]} is {off:.4f} off the CL's"
        radius = radius_of(move.end, move.centre, arc.plane)
        if abs(radius - arc.radius) > self.arc_tolerance:
            return f"arc radius {radius:.4f}, the CL's is {arc.radius:.4f}"
        if (move.rotation > 0) != arc.counterclockwise:
            sense = "counterclockwise" if arc.counterclockwise else "clockwise"
            return f"the arc turns the wrong way (the CL's goes {sense})"
        for point in arc.on_arc:
            off = abs(radius_of(point, move.centre, arc.plane) - radius)
            if off > self.tolerance + arc.slack:
                return f"a CL point of the arc is {off:.4f} off the tape's arc"
        return None


def _in_plane(offset: Sequence[float], normal: Point) -> tuple[float, float, float]:
    """``offset`` less its component along the unit ``normal``."""
    along = sum(a * b for a, b in zip(offset, normal, strict=True))
    return (
        offset[0] - along * normal[0],
        offset[1] - along * normal[1],
        offset[2] - along * normal[2],
    )


def compare(
    path: ClPath,
    moves: list[TapeMove],
    tolerance: float,
    feed_tolerance: float,
    offsets: list[OffsetWords] | None = None,
    arc_tolerance: float | None = None,
) -> Comparison:
    """``offsets``: the tape's offset words per line; ``arc_tolerance``: for an arc's centre
    and radius (the tolerance and a step: the centre words round as the end point does)."""
    arc = tolerance if arc_tolerance is None else arc_tolerance
    return _Walk(path, moves, tolerance, feed_tolerance, offsets or [], arc).run()
