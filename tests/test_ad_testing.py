"""A/D testing (manual §4.3, options 3, 32, 55, 69-74; spec 06 §1, worked examples AD-1..AD-10).

The golden values are the manual's own (001 L13529-14216). AD-4 (".000010 inch position
error develops full system torque", L13596-13598) is a measured property of a hydraulic
drive, not something the analysis computes: it has no test. AD-5's "maximum overshoot at
about .125 seconds" needs the servo's response curve (Diagram 4.3.1B, lost in the scan);
its other values are tested. AD-8's last term is the manual's slip, corrected below.

The postings use MACH23, the manual's sample mill, with its own servo constants (001
L27800-27857: Ts .15, k_ao 1.2, K_o .00286, K_B .00615, Kv 28, Kc 145) and its inverse-time
F = GDIMUL x FIPM / D (G11 below 1 inch: x 1; G01: x 10).
"""

from __future__ import annotations

from math import degrees, pi, radians
from pathlib import Path

import pytest
from gecent.core.dispatch.post import post
from gecent.core.errors import InputError
from gecent.core.feed.servo import (
    arc_feed_limit,
    bisector_slope,
    bisector_time,
    circle_error_constant,
    closed_loop_terms,
    crossover_phase_lag,
    departing_feed,
    overshoot_error,
    overshoot_feed,
    slope_error,
    slowdown_distance,
    steady_lag,
    undershoot_constant,
    undershoot_error,
    velocity_gain,
)
from gecent.core.output.block import Code
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins

# -- the manual's worked examples ------------------------------------------------------------


def test_ad1_gain_of_1_2_ipm_per_thousandth_is_20_and_lags_50_thousandths() -> None:
    gain = velocity_gain(1.2)
    assert gain == pytest.approx(20.0)
    assert steady_lag(60.0, gain) == pytest.approx(0.050)  # .050" in distance
    assert 1 / gain == pytest.approx(0.05)  # .05 s in time


def test_ad2_gains_from_0_5_to_3_lag_120_to_20_thousandths_at_60_ipm() -> None:
    assert steady_lag(60.0, velocity_gain(0.5)) == pytest.approx(0.120)
    assert steady_lag(60.0, velocity_gain(3.0)) == pytest.approx(0.020)


def test_ad3_one_percent_gain_change_on_a_45_degree_slope_errs_3_ten_thousandths() -> None:
    assert slope_error(60.0, velocity_gain(1.0), 0.01, 45.0) == pytest.approx(0.0003)
    assert slope_error(60.0, velocity_gain(1.0), 0.01, 0.0) == 0.0  # along an axis: none


def test_ad5_right_angle_corner_at_60_ipm() -> None:
    undershoot, overshoot = 0.00905, 0.0129
    # the bisector is crossed at 1/Kv = .050 s when the feed does not change
    assert bisector_time(1.0, 20.0, undershoot) == pytest.approx(0.050)
    # BO = 1.414 K_B per in/s; the overshoot is the X servo's stop overshoot K_o
    assert undershoot_error(60.0, pi / 2, undershoot) / undershoot == pytest.approx(1.414, abs=5e-4)
    assert overshoot_error(60.0, pi / 2, overshoot) == pytest.approx(overshoot)


def test_ad6_departing_at_half_the_approach_feed_gives_slope_minus_one() -> None:
    assert bisector_slope(0.5) == pytest.approx(-1.0)


def test_ad7_closed_loop_coefficients_of_the_typical_servo() -> None:
    c2, c4, c6, c8 = closed_loop_terms(16.0, (40.0, 64.0, 128.0))
    assert round(c2, 3) == -0.550
    assert round(c4, 3) == 0.263
    assert round(c6, 4) == 0.0135
    assert round(c8, 6) == 0.000156


def test_ad8_terms_at_half_the_crossover_with_the_manuals_slip_corrected() -> None:
    c2, c4, c6, c8 = closed_loop_terms(16.0, (40.0, 64.0, 128.0))
    assert round(c2 / 4, 3) == -0.138
    assert round(c4 / 16, 4) == 0.0164
    assert round(c6 / 64, 4) == 0.0002
    # the manual prints .000006: .000156 / 256 is .00000061 (a digit lost; spec 06 §13 q7)
    assert round(c8 / 256, 8) == 0.00000061
    assert round((c4 / 16) / abs(c2 / 4), 2) == 0.12  # the 4th-order term is 12% of the 2nd


def test_ad9_c2_zero_is_half_a_radian_of_phase_lag() -> None:
    breaks = (4.0, 8.0, 8.0)  # wc/wi = .25 + .125 + .125 = 1/2: c2 = 0
    assert closed_loop_terms(1.0, breaks)[0] == pytest.approx(0.0)
    assert round(degrees(0.5), 1) == 28.6
    # "approximately": the lag itself is the arctangents' sum, a little under 1/2 radian
    assert crossover_phase_lag(1.0, breaks) == pytest.approx(28.6, abs=0.4)


def test_ad10_circle_error_constant_of_the_typical_servo() -> None:
    assert circle_error_constant(16.0, (40.0, 64.0, 128.0)) / 16.0 == pytest.approx(1.907, abs=5e-4)
    with pytest.raises(ValueError, match="c2 >= 0"):
        circle_error_constant(1.0, (10.0, 10.0, 10.0))  # no resonant peak: (16) is void


# -- the standard constants (spec 06 §1.8: computed, not printed in the manual) -------------


def test_standard_constants_feeds_and_distances() -> None:
    assert overshoot_feed(0.0005, pi / 2, 0.0129) == pytest.approx(2.3256, abs=1e-4)
    assert arc_feed_limit(0.0005, 1.0, 28.0) == pytest.approx(37.566, abs=1e-3)
    assert slowdown_distance(2.326, 30.0, 0.12, 1.3, 0.0129) == pytest.approx(0.008385)
    # past 90 degrees the whole overshoot counts (docs/decisions.md)
    assert overshoot_feed(0.0005, radians(150), 0.0129) == overshoot_feed(0.0005, pi, 0.0129)
    assert overshoot_feed(0.0005, 0.0, 0.0129) == float("inf")


def test_undershoot_constant_and_the_departing_feed() -> None:
    gain, undershoot = 14.5, 0.00905
    assert undershoot_constant(1.0, gain, undershoot) == pytest.approx(undershoot)
    assert undershoot_constant(0.0, gain, undershoot) == pytest.approx(0.0, abs=1e-12)
    ratios = [0.1, 0.5, 1.0, 2.0, 8.0]
    values = [undershoot_constant(r, gain, undershoot) for r in ratios]
    assert values == sorted(values) and values[-1] < 1 / gain
    # spec 06 §1.6's check: K2B = .005 needs F2/F1 = .473 (F1 = 4.2426 IPM at 90 degrees)
    approach = 60 * 0.0005 / (2 * 0.005 * 0.70710678)
    assert departing_feed(approach, pi / 2, 0.0005, gain, undershoot) / approach == (
        pytest.approx(0.473, abs=1e-3)
    )
    assert departing_feed(approach, 0.0, 0.0005, gain, undershoot) == float("inf")


# -- posting on MACH23 ---------------------------------------------------------------------


def _post(tmp_path: Path, machin: str, *body: str) -> list[str]:
    return tape_lines(_result(tmp_path, machin, *body).blocks)


def _result(tmp_path: Path, machin: str, *body: str):  # type: ignore[no-untyped-def]
    source = tmp_path / "p.apt"
    source.write_text("\n".join(["PARTNO AD", machin, "FROM/0,0,0", *body, "FINI", ""]))
    return post(str(source), get_plugins())


SQUARE = ("FEDRAT/60", "GOTO/2,0,0", "GOTO/2,2,0")

# F1 = E / K_o = .0005 / (.00286 / 60) = 10.4895 IPM; D = max(.15 x 10.4895,
# 1.2 x .00286 x 60) / 60 = .02622 before the corner. F2 from (9): F2/F1 = .2341, 2.4551 IPM;
# U = .15 x 2.4551 / 60 = .00614 after it. The end (FINI) is a stop: slowed again at D.
CORNER = [
    "AD",
    "N005G01X+019738F304",  # 10 x 60 / 1.9738 = 303.98
    "N005G11X+000262F400",  # 10.4895 / .0262 = 400.4
    "N006G11Y+000061F402",  # 2.4551 / .0061 = 402.5
    "N006G01Y+019677F305",  # 10 x 60 / 1.9677 = 304.9
    "N006G11Y+000262F400",
]


def test_a_right_angle_corner_slows_down_at_d_and_speeds_up_at_u(tmp_path: Path) -> None:
    assert _post(tmp_path, "MACHIN/GECENT,23,OPTAB,55,1", *SQUARE) == CORNER
    approach = overshoot_feed(0.0005, pi / 2, 0.00286)
    assert approach == pytest.approx(10.4895, abs=1e-4)
    leave = departing_feed(approach, pi / 2, 0.0005, 28.0, 0.00615)
    assert leave == pytest.approx(2.4551, abs=1e-4)


def test_option_55_zero_leaves_the_feeds_alone(tmp_path: Path) -> None:
    assert _post(tmp_path, "MACHIN/GECENT,23", *SQUARE) == [
        "AD",
        "N005G01X+02F300",
        "N006G01Y+02",
    ]


def test_option_3_steps_the_slowdown(tmp_path: Path) -> None:
    """50 percent: 60 -> 30 -> 15 -> 10.49, each change its own DO before the next:
    .15 x 30 / 60 = .075, .15 x 15 / 60 = .0375, then .0262 (001 L24375-24386)."""
    lines = _post(tmp_path, "MACHIN/GECENT,23,OPTAB,55,1,OPTAB,3,50", "FEDRAT/60", "GOTO/2,0,0")
    assert lines == [
        "AD",
        "N005G01X+018613F322",
        "N005G11X+00075F400",  # 30 / .075
        "N005G11X+000375",  # 15 / .0375
        "N005G11X+000262",  # 10.49 / .0262
    ]


def test_mchtol_gives_the_dynamic_tolerance(tmp_path: Path) -> None:
    """E = .002: F1 = .002 / (.00286 / 60) = 41.958 IPM, D = .15 x 41.958 / 60 = .1049."""
    lines = _post(
        tmp_path, "MACHIN/GECENT,23,OPTAB,55,1", "MCHTOL/0.002", "FEDRAT/60", "GOTO/2,0,0"
    )
    assert lines == ["AD", "N006G01X+018951F317", "N006G11X+001049F400"]


def test_collinear_moves_keep_their_feed(tmp_path: Path) -> None:
    lines = _post(tmp_path, "MACHIN/GECENT,23,OPTAB,55,1", "FEDRAT/60", "GOTO/1,0,0", "GOTO/2,0,0")
    # 10 x 60 / 1 = 600 is held to option 24's 500 (50 IPM); the piece before D is under
    # an inch, G11, and takes the programmed 60 again: 60 / .9738 = 61.6
    assert lines == ["AD", "N005G01X+01F500", "N006G11X+009738F062", "N006G11X+000262F400"]


def test_a_small_arc_is_held_to_60_kc_root_er(tmp_path: Path) -> None:
    """MCHTOL .0001, r = .09: 60 x 145 x sqrt(.0001 x .09) = 26.1 IPM on the arc (001
    L13787-13814); the line into it is slowed to that feed D = .15 x 26.1 / 60 = .0653 before
    it (docs/decisions.md)."""
    result = _result(
        tmp_path,
        "MACHIN/GECENT,23,OPTAB,55,1",
        "MCHTOL/0.0001",
        "FEDRAT/60",
        "GOTO/0.91,2,0",
        "GOTO/0.91,1,0",  # into the arc along its tangent: no corner
        "CIRCLE/1,1,0,0,0,1,0.09",
        "GOTO/1,0.91,0",
        "GOTO/2,0.91,0",  # and out of it so: the stop at the end slows this line
    )
    arcs = [b for b in result.blocks if b.code is Code.CIRCLE_XY_CCLW]
    limit = arc_feed_limit(0.0001, 0.09, 145)
    assert limit == pytest.approx(26.1)
    assert arcs and float(arcs[0].cells[19]) == pytest.approx(limit)
    before = result.blocks[result.blocks.index(arcs[0]) - 1]
    assert before.code is Code.LINEAR and float(before.cells[19]) == pytest.approx(limit)
    assert before.steps == (0, -652, 0)  # D at .9348 of the line: .06525 -> .0652


def test_cut_time_is_the_pieces_time(tmp_path: Path) -> None:
    result = _result(tmp_path, "MACHIN/GECENT,23,OPTAB,55,1", *SQUARE)
    moves = [b for b in result.blocks if b.code is Code.LINEAR]
    assert result.cut_minutes == pytest.approx(sum(b.cut_minutes for b in moves))
    lengths = [sum((s * 0.0001) ** 2 for s in b.steps or ()) ** 0.5 for b in moves]
    assert result.cut_minutes == pytest.approx(
        sum(length / float(b.cells[19]) for length, b in zip(lengths, moves, strict=True))
    )


def test_comments_stay_after_the_held_move_and_punched_text_stops(tmp_path: Path) -> None:
    result = _result(
        tmp_path,
        "MACHIN/GECENT,23,OPTAB,55,1",
        "FEDRAT/60",
        "GOTO/2,0,0",
        "PPRINT AFTER THE FIRST MOVE",
        "GOTO/2,2,0",
    )
    texts = [b.text for b in result.blocks if b.code in (Code.PPRINT, Code.LINEAR)]
    assert texts.index("AFTER THE FIRST MOVE") == 2  # after both pieces of the first move
    # an INSERT is a block on the tape: the tool stops before it (slowed as for a stop)
    lines = _post(
        tmp_path,
        "MACHIN/GECENT,23,OPTAB,55,1",
        "FEDRAT/60",
        "GOTO/2,0,0",
        "INSERT X1",
        "GOTO/2,2,0",
    )
    assert lines[1:4] == ["N005G01X+019738F304", "N005G11X+000262F400", "X1"]


def test_no_room_to_slow_down_is_warned(tmp_path: Path) -> None:
    """Option 3 = 10 percent: 60 IPM comes down to 10.49 in 17 steps, each .15 f / 60 from
    the next, about 1.1 inches; the approach is .5 long, so it starts lower and says so."""
    result = _result(
        tmp_path,
        "MACHIN/GECENT,23,OPTAB,55,1,OPTAB,3,10",
        "FEDRAT/60",
        "GOTO/0.5,0,0",
        "GOTO/0.5,1,0",
    )
    texts = [d.text for d in result.diagnostics]
    assert any(
        t.startswith("A/D: NO ROOM TO SLOW DOWN TO 10.49 IPM BEFORE THE CORNER (")
        and t.endswith(" NEEDED, 0.5 THERE)")
        for t in texts
    ), texts
    first = next(b for b in result.blocks if b.code is Code.LINEAR)
    assert float(first.cells[19]) < 60 * 0.9**7  # the steps that do not fit are not made


@pytest.mark.parametrize(
    ("machin", "error", "text"),
    [
        ("MACHIN/GECENT,23,OPTAB,55,1,OPTAB,71,0", InputError, "option 71 = 0"),
        ("MACHIN/GECENT,23,OPTAB,55,1,OPTAB,72,0.1", InputError, "option 72"),
    ],
)
def test_bad_or_unbuilt_settings(tmp_path: Path, machin: str, error: type, text: str) -> None:
    with pytest.raises(error, match=text):
        _post(tmp_path, machin, *SQUARE)


def test_mchtol_needs_one_positive_tolerance(tmp_path: Path) -> None:
    with pytest.raises(InputError, match="MCHTOL expects") as caught:
        _post(tmp_path, "MACHIN/GECENT,23,OPTAB,55,1", "MCHTOL/0")
    assert caught.value.where is not None and caught.value.where.line == 4
    # with A/D off it is accepted and does nothing (used only when option 55 = 1)
    assert _post(tmp_path, "MACHIN/GECENT,23", "MCHTOL/0.001", *SQUARE) == [
        "AD",
        "N006G01X+02F300",
        "N007G01Y+02",
    ]
