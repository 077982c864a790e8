"""Golden tests: rounding and segmentation of linear moves (spec 03 worked examples)."""

from __future__ import annotations

import pytest
from gecent.core.errors import FatalError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.motion.gcode import LinearCodes
from gecent.core.motion.rounding import round_to_step, to_steps
from gecent.core.motion.segments import segment_count, segments
from gecent.core.plugins import get_plugins
from hypothesis import given
from hypothesis import strategies as st

STEP = 0.0001


@pytest.mark.parametrize(
    ("value", "rounded"),
    [
        (22.24686231, 222469),
        (22.24685231, 222469),  # printed "22 .. 24685231" [OCR]
        (22.24684231, 222468),
        (0.00005, 1),
        (0.000005, 0),
        (24.678891, 246789),  # xref L1287-1291
        (-22.24686231, -222469),
    ],
)
def test_w1_srarec_rounding(value: float, rounded: int) -> None:
    """W1 (001 L3976-3989): sign(v) * int(|v| / STEP + 0.5001) * STEP."""
    assert to_steps(value, STEP) == rounded
    assert round_to_step(value, STEP) == pytest.approx(rounded * STEP, abs=1e-12)


def test_w14_srorec_rounding() -> None:
    """W14 (001 L5508-5509): option 119 = 0.001, R = 10.246890 -> 10.247."""
    assert to_steps(10.246890, 0.001) == 10247


def test_w6_half_step_difference_is_one_step() -> None:
    """W6 (001 L4276-4280): 0.0005 - 0.0004 computes as 0.00009999 in floating point; as
    whole steps it is exactly one step, a valid move."""
    assert to_steps(0.0005, STEP) - to_steps(0.0004, STEP) == 1


def test_w7_even_split() -> None:
    """W7 (001 L4339-4341, L4385-4417): DEPMAX 9.9999, (0,0) -> (40,30): five blocks of 8, 6."""
    depmax = to_steps(9.9999, STEP)
    move = (400000, 300000)
    count = segment_count(move, (depmax, depmax))
    assert count == 5
    assert list(segments(move, count)) == [(80000, 60000)] * 5
    # "with DEPMAX = 9.999 a 40-inch X move becomes five 8-inch segments"
    assert segment_count((400000,), (to_steps(9.999, STEP),)) == 5


def test_w9_accurate_segmentation_adds_the_missing_pulse() -> None:
    """W9 (001 L4514-4559): DEPMAX 3.9999, dX = 10 from X = 8 -> 3.3333, 3.3334, 3.3333;
    W8's naive 3 x 3.3333 = 9.9999 would lose a pulse."""
    count = segment_count((100000,), (to_steps(3.9999, STEP),))
    assert count == 3
    parts = [p[0] for p in segments((100000,), count)]
    assert parts == [33333, 33334, 33333]
    positions = [80000 + sum(parts[: i + 1]) for i in range(3)]
    assert positions == [113333, 146667, 180000]


def test_a_move_within_depmax_is_one_segment() -> None:
    assert segment_count((99999, -99999), (99999, 99999)) == 1


@given(
    move=st.lists(st.integers(-(10**7), 10**7), min_size=1, max_size=6),
    limit=st.integers(10**4, 10**6),
)
def test_segments_lose_no_pulse_and_stay_on_the_path(move: list[int], limit: int) -> None:
    """Appendix 7.2: the segments add up to the move exactly, each fits DEPMAX, and after
    every segment each axis is within half a step of the exact path point (0.5001: the
    manual's rounding constant rounds 0.4999 of a step up)."""
    count = segment_count(move, [limit] * len(move))
    parts = list(segments(move, count))
    assert len(parts) == count
    assert [sum(p[k] for p in parts) for k in range(len(move))] == move
    running = [0] * len(move)
    for index, part in enumerate(parts, start=1):
        for axis, step in enumerate(part):
            assert abs(step) <= limit
            running[axis] += step
            assert abs(running[axis] - move[axis] * index / count) <= 0.5001 + 1e-6


def _machine_with(tableg: dict[int, int], **options: float) -> MachineDefinition:
    text = '[machine]\nnumber = 88\nname = "selg"\ntitle = "SELG TEST"\n[tableg]\n' + "".join(
        f"{k} = {v}\n" for k, v in tableg.items()
    )
    if options:
        text += "[optab]\n" + "".join(f"{k[1:]} = {v}\n" for k, v in options.items())
    return load_machine_text(text, "selg-test.toml")


def test_w21_linear_g_selection_all_codes_available() -> None:
    """W21 (001 L6019-6036): with every dimension code present, Ex. 1 (0.2, 2, 20) takes
    TABLEG(11), GDIMUL 100; Ex. 2 (-0.001, 0, 0) TABLEG(13), GDIMUL 0.1; 8 -> (2), 80 -> (11)."""
    machine = _machine_with({11: 10, 12: 11, 13: 12, 14: 13, 15: 14}, o4=99.9999)
    codes = LinearCodes(machine, STEP)
    assert (codes.select(200000).location, codes.select(200000).gdimul) == (11, 100.0)
    assert (codes.select(10).location, codes.select(10).gdimul) == (13, 0.1)
    assert codes.select(80000).location == 2
    assert codes.select(800000).location == 11
    assert codes.select(99999).location == 2  # 9.9999 is still under 10
    assert codes.select(100000).location == 11


def test_selg_skips_absent_codes_upward_and_fails_past_the_last() -> None:
    standard = LinearCodes(standard_machine(), STEP)
    first = standard.select(10)
    assert (first.code, first.location, first.gdimul) == (1, 2, 10.0)  # only G01 on the standard
    with pytest.raises(FatalError) as caught:
        standard.select(100000)  # 10.0 > option 4 = 9.9999: should have been segmented
    assert caught.value.number == 139
    mach23 = LinearCodes(get_plugins().machine("mach23").load(), STEP)
    assert (mach23.select(5000).code, mach23.select(5000).gdimul) == (11, 1.0)
    assert mach23.select(500000).code == 10
