"""CLASS 4 (manual §4.2.4): the hand-checkable case of spec 05 E23, the singular case and the
table's range 0 <= A < 2 pi."""

from __future__ import annotations

import numpy as np
from gecent.core.multiaxis.transform import A, Kinematics
from gecent.plugins.classes.class4 import Class4, full_turn


def test_the_e23_case() -> None:
    """E23: (x, y, z) = (1, 2, 3), (i, j, k) = (0, 1, 0): A = 0, X = 1, Y = -3, Z = 2; and
    back."""
    part = np.array([[1.0, 2.0, 3.0, 0.0, 1.0, 0.0]])
    result = Class4().direct(part, Kinematics())
    assert result.axes[0].tolist() == [1.0, -3.0, 2.0, 0.0, 0.0, 0.0]
    assert result.singular.tolist() == [False]
    assert Class4().inverse(result.axes, Kinematics()).tolist() == part.tolist()


def test_there_are_no_offsets() -> None:
    """The part's origin is on the table's axis: the reach plays no part."""
    part = np.array([[1.0, 2.0, 3.0, 0.0, 0.6, 0.8]])
    near = Class4().direct(part, Kinematics(reach=0.0)).axes
    far = Class4().direct(part, Kinematics(reach=12.0)).axes
    assert near.tolist() == far.tolist()
    # Y = y k - z j, Z = y j + z k, A = atan(k / j)
    assert np.allclose(near[0], [1.0, 1.6 - 1.8, 1.2 + 2.4, np.arctan(0.8 / 0.6), 0.0, 0.0])


def test_the_table_angle_is_within_0_and_2_pi() -> None:
    """0 <= A <= 2 pi as printed: the lower half turn gives pi..2 pi, not negative angles."""
    degrees = {
        (1.0, 0.0): 0.0,
        (0.0, 1.0): 90.0,
        (-1.0, 0.0): 180.0,
        (0.0, -1.0): 270.0,
        (0.6, -0.8): 360.0 - np.degrees(np.arctan(0.8 / 0.6)),
        (-0.6, -0.8): 180.0 + np.degrees(np.arctan(0.8 / 0.6)),
    }
    part = np.array([[1.0, 2.0, 3.0, 0.0, j, k] for j, k in degrees])
    result = Class4().direct(part, Kinematics())
    angles = result.axes[:, A]
    assert np.all((angles >= 0.0) & (angles < 2.0 * np.pi))
    assert np.allclose(np.degrees(angles), list(degrees.values()))
    assert np.allclose(Class4().inverse(result.axes, Kinematics()), part)


def test_an_angle_next_to_a_whole_turn_is_zero() -> None:
    """A small negative atan2 plus 2 pi rounds to 2 pi itself: it is given as 0, and -0.0 as
    a plain 0.0."""
    turned = full_turn(np.array([-1e-17, -0.0, -np.pi / 2, np.pi]))
    assert turned.tolist() == [0.0, 0.0, 1.5 * np.pi, np.pi]
    assert not np.signbit(turned[1])


def test_a_tool_axis_along_x_keeps_the_table_angle() -> None:
    """j = k = 0: A is indeterminate; it stays where it was and the move is singular."""
    part = np.array([[1.0, 2.0, 3.0, 0.0, 0.6, -0.8], [1.0, 2.0, 3.0, -1.0, 0.0, 0.0]])
    result = Class4().direct(part, Kinematics())
    assert result.singular.tolist() == [False, True]
    assert result.axes[1, A] == result.axes[0, A] == full_turn(np.arctan2(-0.8, 0.6))
    previous = np.array([[0.0, 0.0, 0.0, 4.0, 0.0, 0.0]])
    alone = Class4().direct(part[1:], Kinematics(), previous)
    assert alone.axes[0, A] == 4.0 and alone.singular.tolist() == [True]
    y, z = 2.0 * np.sin(4.0) - 3.0 * np.cos(4.0), 2.0 * np.cos(4.0) + 3.0 * np.sin(4.0)
    assert np.allclose(alone.axes[0, :3], [1.0, y, z])


def test_a_tool_axis_off_the_yz_plane_is_projected_on_it() -> None:
    """The table cannot tilt the part about Y: i != 0 is taken as the tool axis's projection
    on the YZ plane."""
    tilted = np.array([[1.0, 2.0, 3.0, 0.6, 0.48, 0.64]])
    plane = np.array([[1.0, 2.0, 3.0, 0.0, 0.6, 0.8]])
    assert np.allclose(
        Class4().direct(tilted, Kinematics()).axes, Class4().direct(plane, Kinematics()).axes
    )


def test_the_inverse_gives_i_zero_and_x_unchanged() -> None:
    machine = np.array([[4.0, -7.0, 9.0, 5.5, 0.0, 0.0]])
    part = Class4().inverse(machine, Kinematics(reach=3.0))
    assert part[0, 0] == 4.0 and part[0, 3] == 0.0
    assert np.allclose(part[0, 3:], [0.0, np.cos(5.5), np.sin(5.5)])
