"""CLASS 8 (manual §4.2.8): a table about Z and a head about Y on CLASS 9's inclined ram,
checked by hand (spec 05 §8.9 and E23; the manual prints no numeric example)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from gecent.core.multiaxis.transform import A, B, C, Kinematics, X, Y, Z
from gecent.plugins.classes.class1 import Class1
from gecent.plugins.classes.class8 import Class8
from gecent.plugins.classes.class9 import Class9

# a Ram Angle (option 100, degrees) with sin = 0.6 and cos = 0.8
TILTED = math.degrees(math.atan2(0.6, 0.8))


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


def test_a_tool_in_the_heads_plane() -> None:
    """Ram Angle with sin .6, cos .8, TL 5, option 101 = 20 (ZMO = 18.75), tip (1, 2, 3), tool
    axis (.6, 0, .8): C = 0, A = atan2(.8, .6), Z = (3 - 5 (1 - .8)) / .8 = 2.5,
    X = 1 + 5 (.6) = 4, Y = (2.5 - 18.75)(.6) + 2 = -7.75."""
    kinematics = ram(5.0, TILTED, 20.0)
    part = np.array([[1.0, 2.0, 3.0, 0.6, 0.0, 0.8]])
    result = Class8().direct(part, kinematics)
    expected = [4.0, -7.75, 2.5, math.atan2(0.8, 0.6), 0.0, 0.0]
    assert result.axes[0] == pytest.approx(expected, abs=1e-12)
    assert result.singular.tolist() == [False]
    assert Class8().inverse(result.axes, kinematics) == pytest.approx(part, abs=1e-12)


def test_a_tool_along_the_ram() -> None:
    """The ram leans, going up, towards -Y: a tool axis (0, -.6, .8) along it turns the
    table to C = -90 degrees to bring it into the head's XZ plane: X = -y + 5 (.6) = 1,
    Y = (2.5 - 18.75)(.6) + x = -8.75, Z = 2.5. A move along that tool axis is not Z
    alone, as it is on CLASS 9: the head swings across the ram, not along it."""
    kinematics = ram(5.0, TILTED, 20.0)
    tip = np.array([1.0, 2.0, 3.0, 0.0, -0.6, 0.8])
    result = Class8().direct(tip, kinematics)
    expected = [1.0, -8.75, 2.5, math.atan2(0.8, 0.6), 0.0, -math.pi / 2]
    assert result.axes[0] == pytest.approx(expected, abs=1e-12)
    drilled = tip + 4.0 * np.array([0.0, -0.6, 0.8, 0.0, 0.0, 0.0])
    moved = Class8().direct(drilled, kinematics).axes[0] - result.axes[0]
    assert moved == pytest.approx([2.4, 2.4, 4.0, 0.0, 0.0, 0.0], abs=1e-12)


def test_with_no_inclination_it_is_class_1_turned_a_quarter() -> None:
    """Ram Angle 0: X is CLASS 1's Y, Y is CLASS 1's -X, A and C are CLASS 1's, Z CLASS 1's
    less TL (the tip's height with the tool vertical rather than the head's)."""
    part = unit_axes(50, seed=8)
    reach = 7.5
    eight = Class8().direct(part, ram(reach, 0.0, 3.0)).axes
    one = Class1().direct(part, Kinematics(reach=reach)).axes
    assert np.allclose(eight[:, X], one[:, Y], rtol=0.0, atol=1e-12)
    assert np.allclose(eight[:, Y], -one[:, X], rtol=0.0, atol=1e-12)
    assert np.allclose(eight[:, [A, C]], one[:, [A, C]], rtol=0.0, atol=1e-12)
    assert np.allclose(eight[:, Z], one[:, Z] - reach, rtol=0.0, atol=1e-12)


def test_the_head_about_y_puts_the_tool_length_on_x() -> None:
    """The one difference from CLASS 9 beyond the table's quarter turn: TL cos A goes to X
    (CLASS 9: to Y); the ram's term stays in Y on both."""
    part = unit_axes(20, seed=88)
    cos_a = np.hypot(part[:, 3], part[:, 4])
    for plugin, column in ((Class8(), X), (Class9(), Y)):
        long = plugin.direct(part, ram(5.0, TILTED, 20.0)).axes
        short = plugin.direct(part, ram(0.0, TILTED, 20.0 - 5.0)).axes  # same ZMO
        change = np.zeros_like(long)
        change[:, column] = 5.0 * cos_a
        change[:, Z] = -5.0 * (1.0 - part[:, 5]) / 0.8
        change[:, Y] += change[:, Z] * 0.6  # Z's change carried by the ram into Y
        assert np.allclose(long - short, change, rtol=0.0, atol=1e-12)


def test_the_vertical_tool_keeps_the_table_angle() -> None:
    """k = 1, no previous point (C = 0), TL 10, no inclination, tip (1, 2, 3): A = 90 degrees,
    C = 0, X = 1 (TL cos A = 0), Y = 2, Z = 3 (the tip's height); the move is singular."""
    result = Class8().direct(np.array([[1.0, 2.0, 3.0, 0.0, 0.0, 1.0]]), ram(10.0, 0.0, 0.0))
    assert result.axes[0, :3].tolist() == [1.0, 2.0, 3.0]
    assert np.degrees(result.axes[0, A]) == 90.0 and result.axes[0, C] == 0.0
    assert result.singular.tolist() == [True]


def test_a_singular_point_keeps_the_angle_of_the_point_before() -> None:
    kinematics = ram(10.0, 15.0, 30.0)
    part = np.array([[1.0, 2.0, 3.0, 0.0, 0.6, 0.8], [1.0, 2.0, 3.0, 0.0, 0.0, 1.0]])
    result = Class8().direct(part, kinematics)
    assert result.axes[1, C] == result.axes[0, C] == np.arctan2(0.6, 0.0)
    assert result.singular.tolist() == [False, True]
    previous = np.array([[0.0, 0.0, 0.0, 0.0, 0.0, 0.5]])
    alone = Class8().direct(part[1:], kinematics, previous)
    assert alone.axes[0, C] == 0.5
    assert Class8().inverse(alone.axes, kinematics) == pytest.approx(part[1:], abs=1e-12)


def test_a_tool_pointing_straight_down_is_singular_at_minus_90_degrees() -> None:
    """k = -1: A = -90 degrees, Z = [z - TL (1 - (-1))] / cos(Ram Angle) = (3 - 20) / .8."""
    kinematics = ram(10.0, TILTED, 0.0)
    result = Class8().direct(np.array([[1.0, 2.0, 3.0, 0.0, 0.0, -1.0]]), kinematics)
    assert np.degrees(result.axes[0, A]) == -90.0
    assert result.axes[0, Z] == pytest.approx(-17.0 / 0.8, abs=1e-12)
    assert result.singular.tolist() == [True]


def test_c_is_atan2_of_j_and_i() -> None:
    """CLASS 1's table angle: a tool leaning to part +y turns the table to C = 90 degrees, one
    leaning to -x to +180 (also from a -0.0), never -180."""
    kinematics = ram(5.0, 20.0, 10.0)
    part = np.array(
        [
            [0.0, 0.0, 0.0, 0.0, 0.6, 0.8],
            [0.0, 0.0, 0.0, -0.6, 0.0, 0.8],
            [0.0, 0.0, 0.0, -0.6, -0.0, 0.8],
            [0.0, 0.0, 0.0, 0.6, 0.0, 0.8],
        ]
    )
    degrees = np.degrees(Class8().direct(part, kinematics).axes[:, C])
    assert degrees.tolist() == [90.0, 180.0, 180.0, 0.0]


def test_the_tool_axis_comes_into_the_heads_plane_leaning_to_plus_x() -> None:
    """Turned by C, every tool axis is (cos A, 0, sin A): in the machine's XZ plane, the head
    turning about Y; A is within -90..90 degrees (cos A >= 0), downward tools below 0."""
    part = unit_axes(200, seed=18)
    machine = Class8().direct(part, ram(5.0, 12.0, 40.0)).axes
    i, j, k = part[:, 3], part[:, 4], part[:, 5]
    cos_c, sin_c = np.cos(machine[:, C]), np.sin(machine[:, C])
    head = machine[:, A]
    assert np.allclose(i * cos_c + j * sin_c, np.cos(head), atol=1e-12)
    assert np.allclose(-i * sin_c + j * cos_c, 0.0, atol=1e-12)
    assert np.all(np.abs(head) <= np.pi / 2)
    assert np.array_equal(head < 0.0, k < 0.0)
    assert np.all(machine[:, B] == 0.0)


def test_the_inverse() -> None:
    """XIVAL = X - TL cos A, TIVAL = Y - (Z - ZMO) sin(Ram Angle), x = -TIVAL sin C + XIVAL
    cos C, y = TIVAL cos C + XIVAL sin C, z = Z cos(Ram Angle) + TL (1 - sin A),
    i = cos A cos C, j = cos A sin C, k = sin A, worked for one point."""
    big_x, big_y, big_z, head, table = 1.5, -2.0, 4.0, math.radians(30.0), math.radians(45.0)
    angle, reach, height = math.radians(20.0), 4.0, 12.0
    zmo = (height - reach) / math.cos(angle)
    xival = big_x - reach * math.cos(head)
    tival = big_y - (big_z - zmo) * math.sin(angle)
    expected = [
        -tival * math.sin(table) + xival * math.cos(table),
        tival * math.cos(table) + xival * math.sin(table),
        big_z * math.cos(angle) + reach * (1.0 - math.sin(head)),
        math.cos(head) * math.cos(table),
        math.cos(head) * math.sin(table),
        math.sin(head),
    ]
    machine = np.array([[big_x, big_y, big_z, head, 0.0, table]])
    part = Class8().inverse(machine, ram(reach, 20.0, height))
    assert part[0] == pytest.approx(expected, abs=1e-12)


def test_a_ram_lying_level_is_refused() -> None:
    with pytest.raises(ValueError, match="option 100"):
        Class8().inverse(np.zeros((1, 6)), ram(5.0, -90.0, 0.0))
