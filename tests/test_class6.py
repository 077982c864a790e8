"""CLASS 6 (manual §4.2.6): head tilt A about X on a column swivelling about Y (B)."""

from __future__ import annotations

import numpy as np
import pytest
from gecent.core.errors import InputError
from gecent.core.multiaxis.transform import A, B, Kinematics
from gecent.plugins.classes.class6 import Class6

# Q = -13: the pivot plane is 13 above the part origin (z = -Q = 13)
KINEMATICS = Kinematics(reach=7.5, options=(-13.0, 0.0, 0.0, 0.0, 0.0, 0.0))


def test_a_tool_along_z_leaves_the_point_where_it_is() -> None:
    """(1, 2, 3) with the tool along Z: t = 10, X Y Z = x y z, A = B = 0."""
    result = Class6().direct(np.array([[1.0, 2.0, 3.0, 0.0, 0.0, 1.0]]), KINEMATICS)
    assert result.axes.tolist() == [[1.0, 2.0, 3.0, 0.0, 0.0, 0.0]]
    assert result.singular.tolist() == [False]


def test_a_swivelled_column() -> None:
    """(i, j, k) = (0.6, 0, 0.8): t = (13 - 3)/0.8 = 12.5, X = 1 + 0.6 t = 8.5, Y = 2,
    Z = 13 - 12.5 = 0.5, A = 0, B = atan(0.6/0.8)."""
    result = Class6().direct(np.array([[1.0, 2.0, 3.0, 0.6, 0.0, 0.8]]), KINEMATICS)
    assert result.axes[0] == pytest.approx([8.5, 2.0, 0.5, 0.0, np.arctan(0.75), 0.0], abs=1e-12)


def test_a_tilted_head() -> None:
    """(i, j, k) = (0, -0.6, 0.8): X = 1, Y = 2 - 0.6 t = -5.5, Z = 0.5, A = atan(0.6/0.8),
    B = 0."""
    result = Class6().direct(np.array([[1.0, 2.0, 3.0, 0.0, -0.6, 0.8]]), KINEMATICS)
    assert result.axes[0] == pytest.approx([1.0, -5.5, 0.5, np.arctan(0.75), 0.0, 0.0], abs=1e-12)


def test_the_inverse_z_carries_minus_q() -> None:
    """z = -Q + (Z + Q) k (the print has +Q): the swivelled point comes back to z = 3."""
    machine = np.array([[8.5, 2.0, 0.5, 0.0, np.arctan(0.75), 0.0]])
    part = Class6().inverse(machine, KINEMATICS)
    assert part[0] == pytest.approx([1.0, 2.0, 3.0, 0.6, 0.0, 0.8], abs=1e-12)


def test_the_reach_does_not_count() -> None:
    part = np.array([[1.0, 2.0, 3.0, 0.6, 0.0, 0.8]])
    near = Class6().direct(part, Kinematics(0.0, KINEMATICS.options)).axes
    assert near.tolist() == Class6().direct(part, KINEMATICS).axes.tolist()


def test_the_head_tilt_stays_within_90_degrees_and_the_column_swings_past() -> None:
    """A tool pointing up (k < 0): A in -90..90, B beyond 90 degrees, undone by the inverse."""
    part = np.array([[1.0, 2.0, 3.0, 0.48, -0.6, -0.64]])
    result = Class6().direct(part, KINEMATICS)
    assert result.axes[0, A] == pytest.approx(np.arcsin(0.6), abs=1e-12)
    assert result.axes[0, B] == pytest.approx(np.arctan2(0.48, -0.64), abs=1e-12)
    assert np.degrees(result.axes[0, B]) > 90.0
    assert Class6().inverse(result.axes, KINEMATICS) == pytest.approx(part, abs=1e-12)


@pytest.mark.parametrize(
    "axis", [(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, -1.0, 0.0), (0.6, 0.8, 0.0)]
)
def test_a_tool_axis_parallel_to_the_pivot_plane_is_refused(axis: tuple[float, ...]) -> None:
    """k = 0 never meets the pivot plane (j = +-1, where B is indeterminate, among them)."""
    part = np.array([[1.0, 2.0, 3.0, 0.0, 0.0, 1.0], [1.0, 2.0, 3.0, *axis]])
    with pytest.raises(InputError, match=r"CLASS6 cannot reach .* point 2 "):
        Class6().direct(part, KINEMATICS)
