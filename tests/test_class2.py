"""CLASS 2 (manual §4.2.2): the hand-checkable case of spec 05 E23, the singular case and the
quadrant of the table's angle."""

from __future__ import annotations

import numpy as np
from gecent.core.multiaxis.transform import B, Kinematics
from gecent.plugins.classes.class2 import Class2


def test_the_e23_case() -> None:
    """E23: (x, y, z) = (1, 2, 3), (i, j, k) = (0, 0, 1), R + TL = 5: X = 1, Y = 2, Z = 8,
    B = 0; and back."""
    part = np.array([[1.0, 2.0, 3.0, 0.0, 0.0, 1.0]])
    result = Class2().direct(part, Kinematics(reach=5.0))
    assert result.axes[0].tolist() == [1.0, 2.0, 8.0, 0.0, 0.0, 0.0]
    assert result.singular.tolist() == [False]
    assert Class2().inverse(result.axes, Kinematics(reach=5.0)).tolist() == part.tolist()


def test_a_tilted_tool_axis_by_the_printed_equations() -> None:
    """(i, k) = (0.6, 0.8): X = x k - z i, Z = x i + z k + (R + TL), B = atan(i / k)."""
    part = np.array([[1.0, 2.0, 3.0, 0.6, 0.0, 0.8]])
    axes = Class2().direct(part, Kinematics(reach=5.0)).axes[0]
    assert np.allclose(axes, [0.8 - 1.8, 2.0, 0.6 + 2.4 + 5.0, 0.0, np.arctan(0.75), 0.0])


def test_the_table_angle_takes_every_quadrant() -> None:
    """B = atan2(i, k), -180..180 degrees: a tool axis below the table (k < 0) is reached."""
    degrees = {
        (0.0, 1.0): 0.0,
        (1.0, 0.0): 90.0,
        (0.0, -1.0): 180.0,
        (-1.0, 0.0): -90.0,
        (0.6, -0.8): 180.0 - np.degrees(np.arctan(0.75)),
        (-0.6, -0.8): np.degrees(np.arctan(0.75)) - 180.0,
    }
    part = np.array([[1.0, 2.0, 3.0, i, 0.0, k] for i, k in degrees])
    result = Class2().direct(part, Kinematics(reach=5.0))
    assert np.allclose(np.degrees(result.axes[:, B]), list(degrees.values()))
    assert np.allclose(Class2().inverse(result.axes, Kinematics(reach=5.0)), part)


def test_a_tool_axis_along_y_keeps_the_table_angle() -> None:
    """i = k = 0: B is indeterminate; it stays where it was (the point before in the run, or
    the previous machine point) and the move is singular."""
    part = np.array([[1.0, 2.0, 3.0, 0.6, 0.0, 0.8], [1.0, 2.0, 3.0, 0.0, 1.0, 0.0]])
    result = Class2().direct(part, Kinematics(reach=5.0))
    assert result.singular.tolist() == [False, True]
    assert result.axes[1, B] == result.axes[0, B] == np.arctan2(0.6, 0.8)
    previous = np.array([[0.0, 0.0, 0.0, 0.0, 0.5, 0.0]])
    alone = Class2().direct(part[1:], Kinematics(reach=5.0), previous)
    assert alone.axes[0, B] == 0.5 and alone.singular.tolist() == [True]
    x, z = 1.0 * np.cos(0.5) - 3.0 * np.sin(0.5), 1.0 * np.sin(0.5) + 3.0 * np.cos(0.5) + 5.0
    assert np.allclose(alone.axes[0, :3], [x, 2.0, z])


def test_a_tool_axis_off_the_xz_plane_is_projected_on_it() -> None:
    """The table cannot tilt the part about X: j != 0 is taken as the tool axis's projection
    on the XZ plane, the same machine point as the unit axis (i, 0, k) in that direction."""
    tilted = np.array([[1.0, 2.0, 3.0, 0.48, 0.6, 0.64]])
    plane = np.array([[1.0, 2.0, 3.0, 0.6, 0.0, 0.8]])
    kinematics = Kinematics(reach=5.0)
    assert np.allclose(
        Class2().direct(tilted, kinematics).axes, Class2().direct(plane, kinematics).axes
    )


def test_the_inverse_gives_j_zero_and_y_unchanged() -> None:
    machine = np.array([[4.0, -7.0, 9.0, 0.0, 1.1, 0.0]])
    part = Class2().inverse(machine, Kinematics(reach=3.0))
    assert part[0, 1] == -7.0 and part[0, 4] == 0.0
    assert np.allclose(part[0, 3:], [np.sin(1.1), 0.0, np.cos(1.1)])
