"""CLASS 9 (manual §4.2.9): a table about Z and a head about X on an inclined ram, checked
by hand (spec 05 §8.10 and E23; the manual prints no numeric example)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from gecent.core.multiaxis.transform import A, B, C, Kinematics, X, Y, Z
from gecent.plugins.classes.class1 import Class1
from gecent.plugins.classes.class9 import Class9
from gecent.plugins.classes.inclined_ram import Ram

# a Ram Angle (option 100, degrees) with sin = -0.6 and cos = 0.8: the ram leans, going up,
# towards machine +Y, the way the head leans the tool
TOWARDS_Y = math.degrees(math.atan2(-0.6, 0.8))


def ram(reach: float, angle: float, height: float) -> Kinematics:
    """Option 100 = Ram Angle (degrees), option 101 = ZMO's height (option 125 + 50.3389)."""
    return Kinematics(reach=reach, options=(angle, height, 0.0, 0.0, 0.0, 0.0))


def unit_axes(count: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    part = np.zeros((count, 6))
    part[:, :3] = rng.uniform(-20.0, 20.0, (count, 3))
    axes = rng.normal(size=(count, 3))
    part[:, 3:] = axes / np.linalg.norm(axes, axis=1, keepdims=True)
    return part


def test_zmo_is_option_101_less_the_reach_over_the_ram_cosine() -> None:
    constants = Ram.of(ram(5.0, TOWARDS_Y, 20.0))
    assert constants.cos == pytest.approx(0.8, abs=1e-15)
    assert constants.sin == pytest.approx(-0.6, abs=1e-15)
    assert constants.zmo == pytest.approx((20.0 - 5.0) / 0.8, abs=1e-12)  # 18.75


def test_a_tool_along_the_ram() -> None:
    """Ram Angle with sin -0.6, cos 0.8, TL 5, option 101 = 20 (ZMO = 18.75), tip (1, 2, 3),
    tool axis (0, .6, .8) along the ram: C = 0, A = atan2(.8, .6),
    Z = (3 - 5 (1 - .8)) / .8 = 2.5, Y = (2.5 - 18.75)(-.6) + 5 (.6) + 2 = 14.75, X = 1."""
    kinematics = ram(5.0, TOWARDS_Y, 20.0)
    part = np.array([[1.0, 2.0, 3.0, 0.0, 0.6, 0.8]])
    result = Class9().direct(part, kinematics)
    expected = [1.0, 14.75, 2.5, math.atan2(0.8, 0.6), 0.0, 0.0]
    assert result.axes[0] == pytest.approx(expected, abs=1e-12)
    assert result.singular.tolist() == [False]
    assert Class9().inverse(result.axes, kinematics) == pytest.approx(part, abs=1e-12)


def test_a_move_along_a_tool_axis_that_lies_along_the_ram_is_a_move_of_z_alone() -> None:
    kinematics = ram(5.0, TOWARDS_Y, 20.0)
    tip = np.array([1.0, 2.0, 3.0, 0.0, 0.6, 0.8])
    drilled = tip + 4.0 * np.array([0.0, 0.6, 0.8, 0.0, 0.0, 0.0])
    result = Class9().direct(np.array([tip, drilled]), kinematics).axes
    assert result[1] - result[0] == pytest.approx([0.0, 0.0, 4.0, 0.0, 0.0, 0.0], abs=1e-12)


def test_with_no_inclination_it_is_class_1_a_quarter_turn_back_and_tl_lower() -> None:
    """Ram Angle 0: X and Y are CLASS 1's, C is CLASS 1's less 90 degrees, Z CLASS 1's less TL
    (the tip's height with the tool vertical rather than the head's)."""
    part = unit_axes(50, seed=9)
    reach = 7.5
    nine = Class9().direct(part, ram(reach, 0.0, 3.0)).axes
    one = Class1().direct(part, Kinematics(reach=reach)).axes
    assert np.allclose(nine[:, [X, Y, A]], one[:, [X, Y, A]], rtol=0.0, atol=1e-12)
    assert np.allclose(nine[:, Z], one[:, Z] - reach, rtol=0.0, atol=1e-12)
    turn = np.angle(np.exp(1j * (nine[:, C] - (one[:, C] - np.pi / 2))))
    assert np.allclose(turn, 0.0, rtol=0.0, atol=1e-12)


def test_the_vertical_tool_keeps_the_table_angle() -> None:
    """k = 1, no previous point (C = 0), TL 10, no inclination, tip (1, 2, 3): A = 90 degrees,
    C = 0, X = 1, Y = 2 (TL cos A = 0), Z = 3 (the tip's height); the move is singular."""
    result = Class9().direct(np.array([[1.0, 2.0, 3.0, 0.0, 0.0, 1.0]]), ram(10.0, 0.0, 0.0))
    assert result.axes[0, :3].tolist() == [1.0, 2.0, 3.0]
    assert np.degrees(result.axes[0, A]) == 90.0 and result.axes[0, C] == 0.0
    assert result.singular.tolist() == [True]


def test_a_singular_point_keeps_the_angle_of_the_point_before() -> None:
    kinematics = ram(10.0, 15.0, 30.0)
    part = np.array([[1.0, 2.0, 3.0, 0.6, 0.0, 0.8], [1.0, 2.0, 3.0, 0.0, 0.0, 1.0]])
    result = Class9().direct(part, kinematics)
    assert result.axes[1, C] == result.axes[0, C] == np.arctan2(-0.6, 0.0)
    assert result.singular.tolist() == [False, True]
    previous = np.array([[0.0, 0.0, 0.0, 0.0, 0.0, 0.5]])
    alone = Class9().direct(part[1:], kinematics, previous)
    assert alone.axes[0, C] == 0.5
    assert Class9().inverse(alone.axes, kinematics) == pytest.approx(part[1:], abs=1e-12)


def test_a_tool_pointing_straight_down_is_singular_at_minus_90_degrees() -> None:
    """k = -1: A = -90 degrees, Z = [z - TL (1 - (-1))] / cos(Ram Angle) = (3 - 20) / .8."""
    kinematics = ram(10.0, TOWARDS_Y, 0.0)
    result = Class9().direct(np.array([[1.0, 2.0, 3.0, 0.0, 0.0, -1.0]]), kinematics)
    assert np.degrees(result.axes[0, A]) == -90.0
    assert result.axes[0, Z] == pytest.approx(-17.0 / 0.8, abs=1e-12)
    assert result.singular.tolist() == [True]


def test_c_is_atan2_of_minus_i_and_j() -> None:
    """The printed tan^-1(i/j) loses the sign the inverse's i = -(cos A sin C) demands: a tool
    leaning to part +x turns the table to C = -90 degrees, one leaning to -y to +180 (also
    from a -0.0), never -180."""
    kinematics = ram(5.0, 20.0, 10.0)
    part = np.array(
        [
            [0.0, 0.0, 0.0, 0.6, 0.0, 0.8],
            [0.0, 0.0, 0.0, 0.0, -0.6, 0.8],
            [0.0, 0.0, 0.0, -0.0, -0.6, 0.8],
            [0.0, 0.0, 0.0, 0.0, 0.6, 0.8],
        ]
    )
    degrees = np.degrees(Class9().direct(part, kinematics).axes[:, C])
    assert degrees.tolist() == [-90.0, 180.0, 180.0, 0.0]


def test_the_tool_axis_comes_into_the_heads_plane_leaning_to_plus_y() -> None:
    """Turned by C, every tool axis is (0, cos A, sin A): in the machine's YZ plane, the head
    turning about X; A is within -90..90 degrees (cos A >= 0), downward tools below 0."""
    part = unit_axes(200, seed=19)
    machine = Class9().direct(part, ram(5.0, 12.0, 40.0)).axes
    i, j, k = part[:, 3], part[:, 4], part[:, 5]
    cos_c, sin_c = np.cos(machine[:, C]), np.sin(machine[:, C])
    head = machine[:, A]
    assert np.allclose(i * cos_c + j * sin_c, 0.0, atol=1e-12)
    assert np.allclose(-i * sin_c + j * cos_c, np.cos(head), atol=1e-12)
    assert np.all(np.abs(head) <= np.pi / 2)
    assert np.array_equal(head < 0.0, k < 0.0)
    assert np.all(machine[:, B] == 0.0)


def test_the_inverse_is_the_printed_one() -> None:
    """TIVAL = Y - [(Z - ZMO) sin(Ram Angle) + TL cos A], x = -TIVAL sin C + X cos C,
    y = TIVAL cos C + X sin C, z = Z cos(Ram Angle) + TL (1 - sin A), i = -(cos A sin C),
    j = cos A cos C, k = sin A, worked for one point."""
    big_x, big_y, big_z, head, table = 1.5, -2.0, 4.0, math.radians(30.0), math.radians(45.0)
    angle, reach, height = math.radians(20.0), 4.0, 12.0
    zmo = (height - reach) / math.cos(angle)
    tival = big_y - ((big_z - zmo) * math.sin(angle) + reach * math.cos(head))
    expected = [
        -tival * math.sin(table) + big_x * math.cos(table),
        tival * math.cos(table) + big_x * math.sin(table),
        big_z * math.cos(angle) + reach * (1.0 - math.sin(head)),
        -(math.cos(head) * math.sin(table)),
        math.cos(head) * math.cos(table),
        math.sin(head),
    ]
    machine = np.array([[big_x, big_y, big_z, head, 0.0, table]])
    part = Class9().inverse(machine, ram(reach, 20.0, height))
    assert part[0] == pytest.approx(expected, abs=1e-12)


def test_a_ram_lying_level_is_refused() -> None:
    with pytest.raises(ValueError, match="option 100"):
        Class9().direct(np.array([[0.0, 0.0, 0.0, 0.0, 0.0, 1.0]]), ram(5.0, 90.0, 0.0))
