"""CLASS 7 (manual §4.2.7): a column swivelling about Y (B) over venetian blinds turning
about X (A)."""

from __future__ import annotations

import numpy as np
import pytest
from gecent.core.errors import InputError
from gecent.core.multiaxis.transform import A, B, Kinematics
from gecent.plugins.classes.class7 import Class7

# Q = -13 (pivot plane at z = 13), S1 = 2, S2 = 3: the blind's axis at y = -3, z = -2
KINEMATICS = Kinematics(reach=7.5, options=(-13.0, 2.0, 3.0, 0.0, 0.0, 0.0))


def test_a_tool_along_z_leaves_the_point_where_it_is() -> None:
    """(1, 2, 3) with the tool along Z: T7 = 15 - 5 = 10, X Y Z = x y z, A = B = 0."""
    result = Class7().direct(np.array([[1.0, 2.0, 3.0, 0.0, 0.0, 1.0]]), KINEMATICS)
    assert result.axes.tolist() == [[1.0, 2.0, 3.0, 0.0, 0.0, 0.0]]
    assert result.singular.tolist() == [False]


def test_a_quarter_turn_of_the_blind() -> None:
    """(i, j, k) = (0, -1, 0): A = 90 degrees; the point, 5 across and 5 above the blind's
    axis, turns to 5 across and -5 above it: Y = -3 + 5 = 2, T7 = 15 + 5 = 20, X = 1,
    Z = 13 - 20 = -7."""
    result = Class7().direct(np.array([[1.0, 2.0, 3.0, 0.0, -1.0, 0.0]]), KINEMATICS)
    assert result.axes[0] == pytest.approx([1.0, 2.0, -7.0, np.pi / 2, 0.0, 0.0], abs=1e-12)
    back = Class7().inverse(result.axes, KINEMATICS)
    assert back[0] == pytest.approx([1.0, 2.0, 3.0, 0.0, -1.0, 0.0], abs=1e-12)


def test_a_swivelled_column() -> None:
    """(i, j, k) = (0.6, 0, 0.8): T7 = (15 * 0.8 - 5 * 0.8) / 0.64 = 12.5, X = 8.5, Y = 2,
    Z = 0.5, A = 0, B = atan(0.6/0.8): CLASS 6's column with the blind at rest."""
    result = Class7().direct(np.array([[1.0, 2.0, 3.0, 0.6, 0.0, 0.8]]), KINEMATICS)
    assert result.axes[0] == pytest.approx([8.5, 2.0, 0.5, 0.0, np.arctan(0.75), 0.0], abs=1e-12)


def test_the_inverse_j_is_minus_sin_a_cos_b() -> None:
    """j = -sin A cos B (the print has -sin B cos B)."""
    machine = np.array([[0.0, 0.0, 0.0, np.pi / 6, np.pi / 3, 0.0]])
    part = Class7().inverse(machine, KINEMATICS)
    assert part[0, 3:] == pytest.approx([np.sqrt(3) / 2, -0.25, np.sqrt(3) / 4], abs=1e-12)


def test_the_reach_does_not_count() -> None:
    part = np.array([[1.0, 2.0, 3.0, 0.6, 0.0, 0.8]])
    near = Class7().direct(part, Kinematics(0.0, KINEMATICS.options)).axes
    assert near.tolist() == Class7().direct(part, KINEMATICS).axes.tolist()


def test_the_blind_turns_past_90_degrees_and_the_column_stays_within() -> None:
    """k < 0: A = atan2(-j, k) beyond 90 degrees; i < 0: B in -90..0; undone by the inverse."""
    part = np.array([[1.0, 2.0, 3.0, -0.6, -0.48, -0.64]])
    result = Class7().direct(part, KINEMATICS)
    assert result.axes[0, A] == pytest.approx(np.arctan2(0.48, -0.64), abs=1e-12)
    assert np.degrees(result.axes[0, A]) > 90.0
    assert result.axes[0, B] == pytest.approx(np.arcsin(-0.6), abs=1e-12)
    assert Class7().inverse(result.axes, KINEMATICS) == pytest.approx(part, abs=1e-12)


@pytest.mark.parametrize("i", [1.0, -1.0])
def test_a_tool_axis_along_x_is_refused(i: float) -> None:
    """j = k = 0: the blind's angle is indeterminate and T7 infinite."""
    part = np.array([[1.0, 2.0, 3.0, 0.0, 0.0, 1.0], [1.0, 2.0, 3.0, i, 0.0, 0.0]])
    with pytest.raises(InputError, match=r"CLASS7 cannot reach .* point 2 "):
        Class7().direct(part, KINEMATICS)
