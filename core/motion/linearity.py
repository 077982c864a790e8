"""LINTOL's linearity test and correction, LINRTY (manual §3.4.7.3, 001 L6753-7168; flow
chart 10, L19936-20040; spec 03 §15).

A move that turns the tool while it moves does not keep the tool tip on the straight cut
vector between two CL points: the machine interpolates its own axes. LINRTY takes the
machine's midpoint of the move, carries it back to the part (the class's inverse) and
compares it with the part's own midpoint: a tip farther than r from it (the tolerance
sphere), or a tool axis more than the cone's half-angle from the midpoint's, is an error.
The move is then cut at its part midpoint, which is tested again towards the start until
a half passes; the last midpoint that failed is the point inserted (the direct transform
of the part point, not the machine midpoint), and the rest of the move is tested from it.
"""

from __future__ import annotations

from math import atan2, pi, radians, sqrt

import numpy as np
from gecent.core.multiaxis.transform import Kinematics, TransformClass
from gecent.core.state import Linearity

MAX_HALVINGS = 30  # a move is not cut finer than 2^-30 of itself (spec 03 open question 18)

Point = tuple[float, float, float, float, float, float]


def unwrapped(angles: np.ndarray, near: np.ndarray, columns: tuple[int, ...]) -> np.ndarray:
    """Machine points whose rotary angles are taken the shorter way from ``near``'s."""
    out = angles.copy()
    for column in columns:
        out[column] = near[column] + (angles[column] - near[column] + pi) % (2 * pi) - pi
    return out


class LinearityTest:
    def __init__(self, transform: TransformClass, kinematics: Kinematics) -> None:
        self.transform = transform
        self.kinematics = kinematics

    def machine(self, part: Point, near: np.ndarray) -> np.ndarray:
        """The direct transform of a part point, its angles near ``near``'s."""
        axes = self.transform.direct(np.array([part]), self.kinematics, near.reshape(1, 6))
        return unwrapped(axes.axes[0], near, self.transform.rotary)

    def points(
        self, start: Point, start_machine: np.ndarray, end: Point, rule: Linearity, limit: int
    ) -> tuple[list[Point], bool]:
        """The part points the move from ``start`` to ``end`` goes through, ``end`` last,
        and False when the tolerance could not be met: a piece still fails after
        MAX_HALVINGS halvings (a tool axis the class cannot follow smoothly); the rest of
        the move then goes untested (the caller says so). More than ``limit`` points is
        refused as a too-fine tolerance (the run's segment bound)."""
        cone = None if rule.cone is None else radians(rule.cone)
        out: list[Point] = []
        met = True
        while met:
            # the end's machine point from where the move stands now: a machine with two
            # ways to a tool axis takes the one nearest the last point (core/multiaxis/chain)
            target, target_machine = end, self.machine(end, start_machine)
            inserted: Point | None = None
            for _ in range(MAX_HALVINGS):
                half = _midpoint(start, target)
                back = self.transform.inverse(
                    ((start_machine + target_machine) / 2.0).reshape(1, 6), self.kinematics
                )[0]
                if not _outside(np.asarray(back), half, rule.radius, cone):
                    break
                inserted = half
                target, target_machine = half, self.machine(half, start_machine)
            else:
                met = False  # (the last half still fails: the tolerance cannot be met)
            if inserted is None or not met:
                break
            out.append(inserted)
            if 0 < limit < len(out):
                raise LinearityLimit(len(out))
            start, start_machine = inserted, target_machine
        out.append(end)
        return out, met


class LinearityLimit(Exception):
    """More points than the run's segment bound."""

    def __init__(self, count: int) -> None:
        super().__init__(count)
        self.count = count


def _midpoint(a: Point, b: Point) -> Point:
    """The part midpoint: the tip halfway, the tool axis the normalised mean (the manual
    does not say how the axis is interpolated, spec 03 §15.5)."""
    i, j, k = (a[3] + b[3]) / 2.0, (a[4] + b[4]) / 2.0, (a[5] + b[5]) / 2.0
    length = sqrt(i * i + j * j + k * k) or 1.0
    return (
        (a[0] + b[0]) / 2.0,
        (a[1] + b[1]) / 2.0,
        (a[2] + b[2]) / 2.0,
        i / length,
        j / length,
        k / length,
    )


def _outside(back: np.ndarray, half: Point, radius: float, cone: float | None) -> bool:
    tip = sqrt(sum((float(back[a]) - half[a]) ** 2 for a in range(3)))
    if tip > radius:
        return True
    if cone is None:
        return False
    # the angle between the axes by atan2 of their cross and dot products: acos of the dot
    # product loses angles below about 1e-8 radians
    a = (float(back[3]), float(back[4]), float(back[5]))
    b = (half[3], half[4], half[5])
    cross = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
    dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    return atan2(sqrt(sum(c * c for c in cross)), dot) > cone
