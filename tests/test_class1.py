"""CLASS 1 (manual §4.2.1): the hand-checkable cases of spec 05 E23."""

from __future__ import annotations

import numpy as np
from gecent.core.multiaxis.transform import A, C, Kinematics
from gecent.plugins.classes.class1 import Class1


def test_the_singular_case_keeps_the_table_angle() -> None:
    """E23: k = 1, previous C = 0, R + TL = 10, (x, y, z) = (1, 2, 3): A = 90 degrees,
    C = 0, X = -2, Y = 1, Z = 13; the move is singular (no linearity test)."""
    result = Class1().direct(np.array([[1.0, 2.0, 3.0, 0.0, 0.0, 1.0]]), Kinematics(reach=10.0))
    X, Y, Z = result.axes[0, :3]
    assert (X, Y, Z) == (-2.0, 1.0, 13.0)
    assert np.degrees(result.axes[0, A]) == 90.0 and result.axes[0, C] == 0.0
    assert result.singular.tolist() == [True]


def test_a_singular_point_keeps_the_angle_of_the_point_before() -> None:
    part = np.array([[1.0, 2.0, 3.0, 0.0, 0.6, 0.8], [1.0, 2.0, 3.0, 0.0, 0.0, 1.0]])
    result = Class1().direct(part, Kinematics(reach=10.0))
    assert result.axes[1, C] == result.axes[0, C] == np.arctan2(0.6, 0.0)
    previous = np.array([[0.0, 0.0, 0.0, 0.0, 0.0, 0.5]])
    alone = Class1().direct(part[1:], Kinematics(reach=10.0), previous)
    assert alone.axes[0, C] == 0.5
