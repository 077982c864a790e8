"""CLASS 3 (manual §4.2.3): hand-checkable points, the quadrants of the three angles (X = H >= 0,
cos A >= 0, cos B of k's sign) and the singular cases H = 0 and G = 0."""

from __future__ import annotations

import numpy as np
from gecent.core.multiaxis.transform import A, B, C, Kinematics
from gecent.plugins.classes.class3 import Class3

TL = Kinematics(reach=5.0)


def test_a_vertical_tool_with_its_pivot_on_y() -> None:
    """Tip (0, 7, 1), tool axis (0, 0, 1), TL = 5: the pivot (0, 7, 6) is on the Y = 0 line
    already: X = H = 7, Y = 0, Z = 6, A = B = C = 0."""
    part = np.array([[0.0, 7.0, 1.0, 0.0, 0.0, 1.0]])
    result = Class3().direct(part, TL)
    assert result.axes[0].tolist() == [7.0, 0.0, 6.0, 0.0, 0.0, 0.0]
    assert result.singular.tolist() == [False]
    assert Class3().inverse(result.axes, TL).tolist() == part.tolist()


def test_the_table_brings_the_pivot_to_the_y_zero_line() -> None:
    """Pivot (3, 0, 6): C = atan2(-Xe, Ye) = -90 degrees, X = 3."""
    part = np.array([[3.0, 0.0, 1.0, 0.0, 0.0, 1.0]])
    axes = Class3().direct(part, TL).axes[0]
    assert np.allclose(axes, [3.0, 0.0, 6.0, 0.0, 0.0, -np.pi / 2])
    assert np.allclose(Class3().inverse(axes, TL), part)


def test_head_angles_by_the_printed_equations() -> None:
    """At C = 0, i' = j and j' = -i: A = atan(-j' sign k / |k|), B = atan(i' / (G sign k))."""
    part = np.array(
        [
            [3.0, 10.0, 0.0, -0.6, 0.0, 0.8],  # pivot (0, 10, 4): A alone
            [0.0, 7.0, 1.0, 0.0, 0.6, 0.8],  # pivot (0, 10, 5): B alone
        ]
    )
    result = Class3().direct(part, TL)
    assert np.allclose(result.axes[0], [10.0, 0.0, 4.0, np.arctan(-0.6 / 0.8), 0.0, 0.0])
    assert np.allclose(result.axes[1], [10.0, 0.0, 5.0, 0.0, np.arctan(0.6 / 0.8), 0.0])
    assert np.allclose(Class3().inverse(result.axes, TL), part)


def test_a_tool_axis_below_the_horizontal_turns_b_past_90_degrees() -> None:
    """k < 0: A stays in -90..90 (cos A > 0) and cos B takes k's sign."""
    part = np.array([[0.0, 7.0, 9.0, 0.0, 0.6, -0.8], [1.8, 7.6, 9.0, -0.36, 0.48, -0.8]])
    result = Class3().direct(part, TL)
    assert np.allclose(result.axes[0, [A, B]], [0.0, np.pi - np.arctan(0.6 / 0.8)])
    assert np.all(np.cos(result.axes[:, A]) > 0.0) and np.all(np.cos(result.axes[:, B]) < 0.0)
    assert np.allclose(Class3().inverse(result.axes, TL), part, rtol=0.0, atol=1e-12)


def test_a_horizontal_tool_axis_takes_sign_k_as_plus() -> None:
    """k = 0 is not singular while j' != 0: sign k = +1 (Fortran's SIGN), A = -90 degrees
    sign j', B = atan2(i', G) in -90..90."""
    part = np.array(
        [
            [-5.0, 10.0, 0.0, 1.0, 0.0, 0.0],
            [5.0, 10.0, 0.0, -1.0, 0.0, 0.0],
            [-4.0, 7.0, 0.0, 0.8, 0.6, 0.0],
        ]
    )
    result = Class3().direct(part, TL)
    assert result.singular.tolist() == [False, False, False]
    assert np.allclose(np.degrees(result.axes[:, A]), [90.0, -90.0, 90.0])
    assert np.allclose(result.axes[:, B], [0.0, 0.0, np.arctan(0.6 / 0.8)])
    assert np.allclose(Class3().inverse(result.axes, TL), part, rtol=0.0, atol=1e-12)


def test_x_is_never_negative() -> None:
    """X = H >= 0: a machine point with X < 0 is the same part point as X > 0 with the table
    a half turn on and both head angles the other way."""
    machine = np.array([[-6.0, 0.0, 2.0, 0.4, -0.3, 0.2]])
    part = Class3().inverse(machine, TL)
    again = Class3().direct(part, TL).axes[0]
    assert np.allclose(again, [6.0, 0.0, 2.0, -0.4, 0.3, 0.2 - np.pi])
    assert np.allclose(Class3().inverse(again, TL), part, rtol=0.0, atol=1e-12)


def test_a_pivot_on_the_table_axis_keeps_the_table_angle() -> None:
    """H = 0: C is indeterminate; it stays where it was (the point before in the run, or the
    previous machine point), X = 0, and the move is singular; the head angles are found in
    the frame of the kept C, so the point is still reached exactly."""
    part = np.array([[3.0, 10.0, 0.0, -0.6, 0.0, 0.8], [-3.0, 0.0, 0.0, 0.6, 0.0, 0.8]])
    result = Class3().direct(part, TL)
    assert result.singular.tolist() == [False, True]
    assert result.axes[1, C] == result.axes[0, C] and result.axes[1, 0] == 0.0
    assert np.allclose(Class3().inverse(result.axes, TL), part, rtol=0.0, atol=1e-12)
    previous = np.array([[0.0, 0.0, 0.0, 0.0, 0.0, 0.5]])
    alone = Class3().direct(part[1:], TL, previous)
    assert alone.axes[0, C] == 0.5 and alone.singular.tolist() == [True]
    assert np.allclose(Class3().inverse(alone.axes, TL), part[1:], rtol=0.0, atol=1e-12)


def test_a_tool_axis_along_the_turned_x_keeps_the_head_angle_a() -> None:
    """G = 0 (j' = k = 0, B = 90 degrees): A is indeterminate and stays where it was."""
    part = np.array([[0.0, 5.0, 0.0, 0.0, 1.0, 0.0]])  # pivot (0, 10, 0), i' = 1
    previous = np.array([[0.0, 0.0, 0.0, 0.3, 0.0, 0.0]])
    result = Class3().direct(part, TL, previous)
    assert result.singular.tolist() == [True]
    assert result.axes[0, A] == 0.3 and np.isclose(result.axes[0, B], np.pi / 2)
    assert np.allclose(Class3().inverse(result.axes, TL), part, rtol=0.0, atol=1e-12)
    first = Class3().direct(part, TL)
    assert first.axes[0, A] == 0.0


def test_the_inverse_by_the_printed_equations() -> None:
    a, b, c = 0.3, -0.7, 1.1
    machine = np.array([[6.0, 0.0, 2.0, a, b, c]])
    part = Class3().inverse(machine, TL)[0]
    i = -np.sin(c) * np.sin(b) + np.cos(c) * np.cos(b) * np.sin(a)
    j = np.cos(c) * np.sin(b) + np.sin(c) * np.cos(b) * np.sin(a)
    k = np.cos(b) * np.cos(a)
    expected = [-6.0 * np.sin(c) - 5.0 * i, 6.0 * np.cos(c) - 5.0 * j, 2.0 - 5.0 * k, i, j, k]
    assert np.allclose(part, expected)
    assert np.isclose(np.linalg.norm(part[3:]), 1.0)
