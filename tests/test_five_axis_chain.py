"""Five-axis kinematics from machine data (core/multiaxis/chain.py, docs/five-axis.md): the
chain's two ways to a tool axis, its choice within travel and nearest the last point, the
pole, and the direct transform undone by the inverse for table-table, head-table and
head-head machines, with the control's tool centre point and without."""

from __future__ import annotations

from math import cos, degrees, radians, sin

import numpy as np
import pytest
from gecent.core.multiaxis.chain import (
    KinematicChain,
    RotaryAxis,
    Unreachable,
    turned,
    two_turns,
    unit,
)
from gecent.core.multiaxis.transform import Kinematics

TRUNNION_A = RotaryAxis(
    "A", "table", (1.0, 0.0, 0.0), (0.0, 0.0, -50.0), (-120.0, 120.0), "limited"
)
TABLE_C = RotaryAxis("C", "table", (0.0, 0.0, 1.0), (10.0, 5.0, 0.0))
HEAD_B = RotaryAxis("B", "head", (0.0, 1.0, 0.0), (0.0, 0.0, 150.0), (-110.0, 110.0), "limited")
HEAD_C = RotaryAxis("C", "head", (0.0, 0.0, 1.0), (0.0, 0.0, 200.0))
HEAD_A = RotaryAxis("A", "head", (1.0, 0.0, 0.0), (0.0, 0.0, 120.0), (-100.0, 100.0), "limited")

CHAINS = {
    "table-table": KinematicChain((TRUNNION_A, TABLE_C)),
    "head-table": KinematicChain(
        (HEAD_B, RotaryAxis("C", "table", (0.0, 0.0, 1.0), (0.0, 0.0, 0.0)))
    ),
    "head-head": KinematicChain((HEAD_C, HEAD_A)),
}


def _part_points(count: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    axes = rng.normal(size=(count, 3))
    axes[:, 2] = np.abs(axes[:, 2]) + 0.2  # tool axes above the horizon: within travel
    axes /= np.linalg.norm(axes, axis=1)[:, None]
    return np.hstack([rng.uniform(-60.0, 60.0, size=(count, 3)), axes])


@pytest.mark.parametrize("structure", sorted(CHAINS))
@pytest.mark.parametrize("tcp", [False, True])
def test_the_inverse_undoes_the_direct_transform(structure: str, tcp: bool) -> None:
    chain = KinematicChain(CHAINS[structure].axes, tool_centre_point=tcp)
    part = _part_points(40, 7)
    kinematics = Kinematics(reach=87.5)
    machine = chain.direct(part, kinematics)
    assert np.abs(chain.inverse(machine.axes, kinematics) - part).max() < 1e-10


@pytest.mark.parametrize("structure", sorted(CHAINS))
def test_every_way_found_turns_the_spindle_onto_the_tool_axis(structure: str) -> None:
    chain = CHAINS[structure]
    for row in _part_points(30, 11):
        tool_axis = unit(row[3:6])
        ways = chain.solutions(tool_axis)
        assert len(ways) == 2
        for first, second in ways:
            assert first is not None and second is not None
            reached = chain.tool_axis_in_part((first, second))
            assert np.allclose(reached, tool_axis, atol=1e-12)


def test_two_turns_has_no_way_when_the_cones_do_not_meet() -> None:
    # about Z then about a 45-degree axis: a vector along Z cannot be turned onto -Z
    tilted = unit((1.0, 0.0, 1.0))
    assert two_turns((0.0, 0.0, 1.0), tilted, (0.0, 0.0, 1.0), (0.0, 0.0, -1.0)) == []


def test_a_trunnion_takes_the_preferred_sign_first_then_the_nearest_way() -> None:
    chain = KinematicChain((TRUNNION_A, TABLE_C), prefer=-1.0)
    lean_x = (-0.5, 0.0, cos(radians(30.0)))
    # the first point: A negative (the pack's preference); C turns the lean under A
    (a, c), singular = chain.choose(lean_x, None)  # type: ignore[misc]
    assert (round(degrees(a), 9), round(degrees(c), 9)) == (-30.0, 90.0) and not singular
    # through the pole to a lean towards +X: the nearest way keeps C and turns A over
    (a2, c2), _ = chain.choose((0.5, 0.0, cos(radians(30.0))), (a, c))  # type: ignore[misc]
    assert (round(degrees(a2), 9), round(degrees(c2), 9)) == (30.0, 90.0)


def test_at_the_pole_the_inner_axis_keeps_its_angle() -> None:
    chain = KinematicChain((TRUNNION_A, TABLE_C))
    (a, c), singular = chain.choose((0.0, 0.0, 1.0), (radians(-30.0), radians(137.0)))  # type: ignore[misc]
    assert singular and round(degrees(a), 9) == 0.0 and round(degrees(c), 9) == 137.0


def test_a_continuous_axis_counts_on_past_a_turn() -> None:
    chain = KinematicChain((TRUNNION_A, TABLE_C))
    before = (radians(-30.0), radians(350.0))
    lean = turned((0.0, -0.5, cos(radians(30.0))), (0.0, 0.0, 1.0), radians(-370.0))
    (a, c), _ = chain.choose(lean, before)  # type: ignore[misc]
    assert round(degrees(a), 6) == -30.0 and round(degrees(c), 6) == 370.0


def test_a_tool_axis_beyond_travel_is_unreachable() -> None:
    chain = CHAINS["head-table"]  # B within +-110 degrees: the tool cannot point up
    with pytest.raises(Unreachable, match=r"beyond the rotary axes' travel \(B -110 to 110\)"):
        chain.direct(np.array([[0.0, 0.0, 0.0, 0.0, 0.0, -1.0]]), Kinematics())


def test_slides_of_a_trunnion_by_hand() -> None:
    """The tip (-20, -30, 2) leaning 30 degrees towards -X: C = 90 turns it to (30, -20, 2),
    A = -30 about the line 50 below the origin lifts it to (30, 8.6795, 5.0333)."""
    chain = KinematicChain(
        (
            RotaryAxis(
                "A", "table", (1.0, 0.0, 0.0), (0.0, 0.0, -50.0), (-120.0, 120.0), "limited"
            ),
            RotaryAxis("C", "table", (0.0, 0.0, 1.0), (0.0, 0.0, 0.0)),
        )
    )
    slides = chain.slides((-20.0, -30.0, 2.0), (radians(-30.0), radians(90.0)), 0.0)
    expected = (30.0, -20.0 * cos(radians(30.0)) + 26.0, 10.0 + 52.0 * cos(radians(30.0)) - 50.0)
    assert np.allclose(slides, expected, atol=1e-12)
    assert round(expected[1], 4) == 8.6795 and round(expected[2], 4) == 5.0333


def test_a_head_swings_the_tool_about_its_pivot() -> None:
    """B = 30 about a pivot 150 above the gauge point, tool 100 long: the tip sits at
    250 sin 30 = 125 along X and 250 cos 30 below the pivot."""
    chain = CHAINS["head-table"]
    tip = chain.tip_from_slides((radians(30.0), 0.0), 100.0)
    assert np.allclose(tip, (-250.0 * sin(radians(30.0)), 0.0, 150.0 - 250.0 * cos(radians(30.0))))
