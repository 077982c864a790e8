"""NURBS motion (NX's ``NURBS/``, ``KNOT/``, ``CNTRL/``; shared/corpus/dialects.md):
the curve evaluated and cut into straight moves that stay within the tolerance of it.

``NURBS/`` starts a curve; ``KNOT/`` records give the knot vector (over as many records as
needed), each ``CNTRL/x,y,z[,w]`` a control point with its weight (1 when left out). The
degree is the knot count less the control point count less one. The curve starts at the
tool's position (the first control point) and the moves end on it: each chord's midpoint
and quarter points lie within the tolerance of the curve, found by halving the parameter
span (at most 2^16 pieces per knot span: a tolerance that needs more is an error). The
moves begin with one to the curve's start, which is the tool's position when the CAM
system has put it there.
"""

from __future__ import annotations

from collections.abc import Sequence
from itertools import pairwise
from math import dist

from gecent.core.cl.records import Motion, MotionSubtype, Statement
from gecent.core.errors import InputError, SourcePosition

Point = tuple[float, float, float]
MAX_DEPTH = 16
MAX_MOVES = 100_000  # a curve cut finer than this is refused (a tolerance far too fine)


class NurbsCurve:
    def __init__(
        self, knots: Sequence[float], points: Sequence[Sequence[float]], where: SourcePosition
    ) -> None:
        if len(points) < 2:
            raise InputError("NURBS needs at least two CNTRL points", where)
        degree = len(knots) - len(points) - 1
        if degree < 1:
            raise InputError(
                f"NURBS: {len(knots)} knots for {len(points)} CNTRL points give no degree "
                "(knots = points + degree + 1)",
                where,
            )
        if len(points) < degree + 1:
            raise InputError(
                f"NURBS: {len(knots)} knots and {len(points)} CNTRL points make degree {degree}, "
                f"which needs {degree + 1} points",
                where,
            )
        if any(b < a for a, b in pairwise(knots)):
            raise InputError("NURBS: the knots must not decrease", where)
        for point in points:
            if len(point) not in (3, 4) or (len(point) == 4 and not point[3] > 0):
                raise InputError("CNTRL takes x, y, z and a weight above 0", where)
        self.where = where
        self.degree = degree
        self.knots = tuple(float(k) for k in knots)
        if not self.knots[degree] < self.knots[-degree - 1]:
            raise InputError("NURBS: the knots leave the curve no span (all the same)", where)
        # homogeneous control points: (w x, w y, w z, w)
        self.points = tuple(
            (p[0] * w, p[1] * w, p[2] * w, w)
            for p in points
            for w in (float(p[3]) if len(p) == 4 else 1.0,)
        )

    @property
    def span(self) -> tuple[float, float]:
        return self.knots[self.degree], self.knots[-self.degree - 1]

    def at(self, u: float) -> Point:
        """The curve's point at ``u`` (de Boor's algorithm on the homogeneous points)."""
        p, knots = self.degree, self.knots
        low, high = self.span
        u = min(max(u, low), high)
        k = p
        while k < len(self.points) - 1 and not knots[k] <= u < knots[k + 1]:
            k += 1
        d = [list(self.points[j + k - p]) for j in range(p + 1)]
        for r in range(1, p + 1):
            for j in range(p, r - 1, -1):
                left, right = knots[j + k - p], knots[j + 1 + k - r]
                alpha = 0.0 if right == left else (u - left) / (right - left)
                d[j] = [(1.0 - alpha) * a + alpha * b for a, b in zip(d[j - 1], d[j], strict=True)]
        x, y, z, w = d[p]
        return (x / w, y / w, z / w)

    def chords(self, tolerance: float) -> list[Point]:
        """The points the straight moves end at: the curve's start (the tool goes there
        first, if it is not there), then along the curve to its end."""
        low, high = self.span
        breaks = sorted({k for k in self.knots if low <= k <= high})
        ends: list[Point] = [self.at(low)]
        for a, b in pairwise(breaks):
            self._cut(a, b, self.at(a), self.at(b), tolerance, 0, ends)
        return ends

    def _cut(
        self, a: float, b: float, start: Point, end: Point, tol: float, depth: int, out: list[Point]
    ) -> None:
        middle = (a + b) / 2
        mid = self.at(middle)
        checks = (mid, self.at((a + middle) / 2), self.at((middle + b) / 2))
        off = max(_off_chord(point, start, end) for point in checks)
        if off <= tol:
            out.append(end)
            return
        if depth >= MAX_DEPTH:
            raise InputError(
                f"NURBS: no straight moves keep within {tol:g} of the curve here (is INTOL "
                "meant so fine?)",
                self.where,
            )
        self._cut(a, middle, start, mid, tol, depth + 1, out)
        self._cut(middle, b, mid, end, tol, depth + 1, out)


def _off_chord(point: Point, start: Point, end: Point) -> float:
    """How far a point lies from the chord (the segment start-end)."""
    chord = tuple(e - s for s, e in zip(start, end, strict=True))
    length = sum(c * c for c in chord)
    if length == 0.0:
        return dist(point, start)
    t = sum((p - s) * c for p, s, c in zip(point, start, chord, strict=True)) / length
    t = min(max(t, 0.0), 1.0)
    return dist(point, tuple(s + t * c for s, c in zip(start, chord, strict=True)))


class NurbsCollector:
    """Gathers ``NURBS/``, ``KNOT/`` and ``CNTRL/`` records into the curve's GOTO records."""

    def __init__(self, opening: Statement) -> None:
        self.opening = opening
        self.knots: list[float] = []
        self.points: list[tuple[float, ...]] = []

    def take(self, statement: Statement) -> bool:
        """True when the statement belongs to the curve."""
        if statement.major not in ("KNOT", "CNTRL"):
            return False
        values = statement.numbers()
        if len(values) != len(statement.args):
            raise InputError(f"{statement.major} takes numbers only", statement.where)
        if statement.major == "KNOT":
            self.knots.extend(values)
        else:
            self.points.append(values)
        return True

    def motion(self, tolerance: float) -> Motion:
        where = self.opening.where
        curve = NurbsCurve(self.knots, self.points, where)
        points = tuple(curve.chords(tolerance))
        if len(points) > MAX_MOVES:
            raise InputError(
                f"NURBS: {len(points)} moves to keep within {tolerance:g} of the curve (more "
                f"than {MAX_MOVES}: is INTOL meant so fine?)",
                where,
            )
        opening = self.opening
        return Motion(opening.file, opening.line, opening.number, MotionSubtype.GOTO, points)
