"""Golden tests: the worked examples of spec 08 (the manual's §6 subroutines and §7
appendix, 001 L28580-41349) that issue 22 lists as not yet golden: W-2, W-3, W-6, W-8,
W-11 and W-14. W-5 and W-12 are in tests/test_multihead_split.py, W-13 in
tests/test_cycles_manual.py. W-4 (SAFEGX's R code) and W-15 (option 37's formula) cannot be
posted: gecent has no single-head SAFETY, and it reads option 37 from the machine file
instead of working it out."""

from __future__ import annotations

import math

import pytest
from gecent.core.feed.positioning import FeedContext
from gecent.core.machine.loader import standard_machine
from gecent.core.motion.rounding import round_to_step, to_steps
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins
from gecent.plugins.feedtypes.rotary1 import RATIO, rotary_feeds

from tests.test_feed_types import example as rotary_example
from tests.test_feed_types import rotary_type
from tests.test_post_linear import STEP, decode, post
from tests.test_spindle_types_discrete import example as spindle_example
from tests.test_spindle_types_discrete import select, tape

# -- W-2, W-3: appendix 7.2, error accumulation (001 L40175-40246) ------------------------


def test_w2_a_true_value_is_rounded_to_the_step() -> None:
    """W-2 (001 L40188-40192): the true 5.1235678 at a step of 0.0001 is 5.1236, in the
    rounding routine and on the tape."""
    assert round_to_step(5.1235678, STEP) == pytest.approx(5.1236, abs=1e-12)
    assert to_steps(5.1235678, STEP) == 51236
    machine = standard_machine()
    (line,) = tape_lines(post(["FROM/0,0,0", "FEDRAT/10", "GOTO/5.1235678,0,0"]).blocks)
    assert decode(line, machine)["X"] == 5.1236


def test_w3_the_largest_vector_error_is_root_3_steps() -> None:
    """W-3 (001 L40238-40245): per axis E = e_1 - e_n, the rounding losses of the first and
    last points, at most one step; the largest vector error sqrt(3) x STEP = 0.00017 in.
    The worst case: every axis starts just below half a step (rounded down) and ends just
    above one (rounded up), so each axis's tape travel is almost a step longer than the
    true travel."""
    machine = standard_machine()
    start, end = 0.000049, 1.000051
    program = ["FROM/0.000049,0.000049,0.000049", "FEDRAT/10", "GOTO/1.000051,1.000051,1.000051"]
    travelled = {letter: 0.0 for letter in "XYZ"}
    for line in tape_lines(post(program).blocks):
        for letter, value in decode(line, machine).items():
            if letter in travelled:
                travelled[letter] += value
    errors = [travelled[letter] - (end - start) for letter in "XYZ"]
    assert all(0 < error <= STEP for error in errors)
    vector = math.sqrt(sum(error * error for error in errors))
    assert vector <= math.sqrt(3) * STEP
    assert round(vector, 5) == 0.00017
    assert round(math.sqrt(3) * STEP, 5) == 0.00017


def test_w3_errors_do_not_accumulate_on_a_closed_path() -> None:
    """W-3's premise (001 L40210-40237): departures come from the rounded points, so a path
    that comes back to its start has travelled nothing on the tape (e_1 = e_n), however
    many moves of odd lengths it took."""
    machine = standard_machine()
    points = [(0.12345, 0.00007, 0.0), (0.77777, 0.33333, 0.0), (0.00003, 0.99999, 0.0)]
    program = ["FROM/0.00004,0.00006,0", "FEDRAT/10"]
    for _ in range(20):
        program += [f"GOTO/{x},{y},{z}" for x, y, z in points]
        program.append("GOTO/0.00004,0.00006,0")
    totals = {"X": 0, "Y": 0}
    lines = tape_lines(post(program).blocks)
    assert len(lines) == 80  # every move is on the tape
    for line in lines:
        for letter, value in decode(line, machine).items():
            if letter in totals:
                totals[letter] += to_steps(value, STEP)
    assert totals == {"X": 0, "Y": 0}


# -- W-6: option 13, the tape reader's time for the longest block (001 L24515-24536) ------

# TRS (characters per second) -> the printed option 13 (minutes), C(MAX) = 45 characters
READER_TABLE = [(100, 0.0075), (300, 0.0025), (400, 0.001875), (500, 0.0015), (1200, 0.000625)]


@pytest.mark.parametrize(("characters_per_second", "minutes"), READER_TABLE)
def test_w6_option_13_is_45_characters_over_the_reader_speed(
    characters_per_second: int, minutes: float
) -> None:
    """W-6: option 13 = C(MAX) / (60 TRS) with C(MAX) = 45; each printed row agrees. A
    rapid that the reader limits (TEST1: F = S / TMAX, 001 L38173-38215) then takes exactly
    option 13 for its block: MACH24, its rapid rates raised so that the reader decides,
    rapids 1 in at 1 / option 13 IPM."""
    assert 45 / (60 * characters_per_second) == pytest.approx(minutes, rel=1e-12)
    fast = {42: 100000.0, 43: 100000.0, 44: 100000.0}
    machine = get_plugins().machine("mach24").load().with_options({13: minutes, **fast})
    program = ["FROM/0,0,0", "FEDRAT/10", "RAPID", "GOTO/1,0,0"]
    (block,) = [b for b in post(program, machine).blocks if b.punch]
    assert block.cut_minutes == pytest.approx(minutes, rel=1e-12)
    assert block.cells[19] == pytest.approx(1 / minutes, rel=1e-12)


def test_w6_the_standard_0_012_minutes_is_a_62_5_character_reader() -> None:
    """W-6: the standard option 13, 0.012 min, is 45 characters at 62.5 characters/s."""
    assert standard_machine().number_option(13) == 0.012
    assert math.isclose(45 / (60 * 62.5), 0.012)


# -- W-8: spindle type 9, the tool's range (TYPE09, 001 L39446-39452) ---------------------


def test_w8_type9_tools_cycle_through_the_ranges() -> None:
    """W-8 prints TYPE09's list: tools 3, 6, 9, 12 in range 1, 2, 5, 8, 11 in range 2, 1, 4,
    7, 10 in range 3. That order contradicts the manual's own §4.5.10 table ("Range 1 =
    Tools 1 & 4") and its example (speed 50 is code 04 with tool 1, range 1 row 4), so
    gecent follows the example (docs/decisions.md, spindle type 9): tool t turns in range
    ((t - 1) mod 3) + 1. Range 2 is the same either way; ranges 1 and 3 are the corrected
    ones."""
    machine = spindle_example(9).with_options({88: 12.0})
    ranges = {tool: select(9, machine, 50, tool=tool).range for tool in range(1, 13)}
    assert [t for t in ranges if ranges[t] == 1] == [1, 4, 7, 10]
    assert [t for t in ranges if ranges[t] == 2] == [2, 5, 8, 11]  # as printed
    assert [t for t in ranges if ranges[t] == 3] == [3, 6, 9, 12]
    # on tape: 50 RPM is row 4 of range 1 under tool 7 (S04); 70 RPM is row 0 of range 3
    # under tool 12 (S00), row 3 of range 2 under tool 11 (S03)
    program = ["TOOLNO/7", "SPINDL/50,CLW", "TOOLNO/12", "SPINDL/70", "TOOLNO/11", "SPINDL/70"]
    speeds = [line for line in tape(program, machine) if "S" in line]
    assert speeds == ["N002S04M03", "N004S00", "N006S03"]


# -- W-11, W-14: the rotary table's ten feeds in the ratio 1.43 ---------------------------


def test_w11_rotyp1_frot_is_circum_over_1_43_to_the_10_minus_i() -> None:
    """W-11 (ROTYP1, 001 L36405-36415): FROT(I) = CIRCUM / 1.43**(10 - I), I = 1..10, with
    CIRCUM the table's top feed in IPM from option 114 (RPM) at the radius option 112.
    gecent's rows 0..9 are I - 1. I = 10 is CIRCUM, I = 9 CIRCUM / 1.43, I = 1 CIRCUM /
    1.43**9. The digest's "CIRCUM / 24.98" is its own slip (derived, not printed by the
    manual): 1.43**9 = 25.005."""
    machine = rotary_example(rotary_type(1))
    circum = 2 * math.pi * machine.number_option(112) * machine.number_option(114)
    feeds = rotary_feeds(machine)
    assert len(feeds) == 10
    for i in range(1, 11):
        assert feeds[i - 1] == pytest.approx(circum / 1.43 ** (10 - i), rel=1e-12)
    assert feeds[9] == pytest.approx(circum, rel=1e-12)
    assert feeds[8] == pytest.approx(circum / 1.43, rel=1e-12)
    assert circum / feeds[0] == pytest.approx(25.005, abs=0.001)
    assert RATIO == 1.43


def test_w14_option_141_fcom_is_option_114_over_1_43_to_the_9_minus_n() -> None:
    """W-14 (option 141 = 1, 001 L26063-26068): FCOM(N) = option 114 / 1.43**(9 - N) RPM,
    N = 1..9; the command for the feed FCOM(N) (in IPM at the option-112 radius) is N."""
    plugin = rotary_type(1)
    machine = rotary_example(plugin)
    top_rpm, radius = machine.number_option(114), machine.number_option(112)
    for n in range(1, 10):
        fcom = top_rpm / 1.43 ** (9 - n)
        ipm = 2 * math.pi * radius * fcom
        assert rotary_feeds(machine)[n] / (2 * math.pi * radius) == pytest.approx(fcom)
        assert plugin.command(machine, ipm, FeedContext()).command == float(n)
    assert rotary_feeds(machine)[9] / (2 * math.pi * radius) == pytest.approx(top_rpm)
