"""The merge pass's arithmetic (core/multihead/split.py and common_axis.py): equal-time
splitting (SPLIT, CIRSEG, GMLINE, GMCIRL), Rule 2 and option 151, the linear head's arc
centre offsets, and common-axis segmentation (FXMULT, FXTOL). Worked examples W1-W6 and W19
of spec 04; the manual is seed 001, cited by line."""

from __future__ import annotations

import itertools
from collections.abc import Iterator
from math import atan, cos, hypot, isclose, pi, sin, sqrt, tan, tau

import pytest
from gecent.core.multihead.common_axis import (
    AxisRule,
    CommonAxisStep,
    common_axis_step,
    component_feed,
    component_feeds_agree,
)
from gecent.core.multihead.split import (
    Arc,
    MergedPair,
    MergeRule,
    Move,
    Plane,
    arc_sweep,
    equal_time_merge,
    equal_time_step,
    linear_head_offsets,
    move_time,
    split_arc,
    split_line,
    split_move,
    tape_reader_limit,
)
from hypothesis import given, settings
from hypothesis import strategies as st

TMAX = tape_reader_limit(0.012, 0.12)  # the Standard Machine's options 13 and 69

# The §5.3 example's circle Ca1 (R 5, 2 rad): A at the origin, chord along +X, centre below.
R, THETA = 5.0, 2.0
CHORD = (2 * R * sin(THETA / 2), 0.0, 0.0)  # 8.41471
CENTRE = (R * sin(THETA / 2), -R * cos(THETA / 2), 0.0)  # (4.20735, -2.70151)


def _close(actual: tuple[float, ...], expected: tuple[float, ...], places: int) -> None:
    assert tuple(round(a, places) for a in actual) == pytest.approx(expected, abs=1e-12)


def _near(actual: tuple[float, ...], expected: tuple[float, ...], tol: float = 1e-9) -> None:
    assert actual == pytest.approx(expected, abs=tol)


# --- times, TMAX, dwells -------------------------------------------------------------


def test_tmax_is_the_larger_of_option_13_minutes_and_option_69_seconds() -> None:
    # 0.012 min against 0.12 s = 0.002 min (001 L7553-7557, L24515-24540, L25243-25246)
    assert tape_reader_limit(0.012, 0.12) == 0.012
    assert tape_reader_limit(0.001, 0.12) == pytest.approx(0.002)


def test_move_time_and_a_dwell_is_a_move_with_no_feed_whose_time_is_the_dwell() -> None:
    assert move_time(12.0, 10.0) == pytest.approx(1.2)
    assert move_time(0.0, 0.0) == 0.0
    with pytest.raises(ValueError):
        move_time(1.0, 0.0)
    dwell = Move.dwell(0.25)
    assert (dwell.length, dwell.feed, dwell.time) == (0.0, 0.0, 0.25)
    with pytest.raises(ValueError):
        Move((1.0, 0.0, 0.0), 0.0, dwell_minutes=0.25)
    with pytest.raises(ValueError):
        Move.line((1.0, 0.0, 0.0), 0.0)


# --- W1, W2, W4, W5: the equal-time decision --------------------------------------------


def test_w1_the_longer_line_is_split_at_the_time_ratio() -> None:
    # Ta1 = 10/20 = 0.5, Tb1 = 12/10 = 1.2: split Lb1 into 5 and 7 in (001 L7736-7756)
    step = equal_time_step(0.5, 1.2, TMAX, 0.0)
    assert (step.rule, step.head) == (MergeRule.SPLIT, 2)
    assert step.fraction == pytest.approx(0.5 / 1.2)
    assert step.time == pytest.approx(0.5)
    first, rest = split_line((12.0, 0.0, 0.0), step.fraction)
    _near(first, (5.0, 0.0, 0.0), 1e-12)
    _near(rest, (7.0, 0.0, 0.0), 1e-12)


def test_w2_circle_against_the_rest_of_the_line_radio_0_7() -> None:
    # S0 = 2 * 5 = 10 in at 10 ipm: 1 min; Lb12 7 in: 0.7 min; dT 0.3 (001 L7757-7784)
    circle = Move.circle(CHORD, CENTRE, Plane.XY, True, 10.0)
    assert circle.length == pytest.approx(10.0)
    step = equal_time_step(circle.time, Move.line((7.0, 0.0, 0.0), 10.0).time, TMAX, 0.0)
    assert (step.rule, step.head) == (MergeRule.SPLIT, 1)
    assert step.fraction == pytest.approx(0.7)  # RADIO
    assert step.difference == pytest.approx(0.3)


def test_w4_the_second_line_is_split_against_the_circles_rest() -> None:
    # T_b2 = 8.544/10, T_s2 = 3/10: Lb21 = (2.8090, 1.0534); the manual prints 2.81 and 1.05
    # from its rounded 0.854 (001 L7868-7890)
    lb2 = Move.line((8.0, 3.0, 0.0), 10.0)
    step = equal_time_step(0.3, lb2.time, TMAX, 0.0)
    assert (step.rule, step.head) == (MergeRule.SPLIT, 2)
    first, rest = split_line(lb2.departures, step.fraction)
    _close(first, (2.8090, 1.0534, 0.0), 4)
    _close(first, (2.81, 1.05, 0.0), 2)
    _close(rest, (5.1910, 1.9466, 0.0), 4)


def test_w5_rule_2_slows_the_other_head_instead_of_leaving_a_short_rest() -> None:
    # Ta1 = 1.0, Tb1 = 0.99: dT 0.01 < TMAX 0.012, so Fb1 = (Tb1/Ta1) * 10 = 9.9 (001 L7560-7596)
    step = equal_time_step(1.0, 0.99, TMAX, 0.0)
    assert (step.rule, step.head, step.time) == (MergeRule.RULE_2, 2, 1.0)
    assert step.feed_factor * 10.0 == pytest.approx(9.9)
    slowed = Move.line((9.9, 0.0, 0.0), 10.0).slowed(step.feed_factor)
    assert slowed.feed == pytest.approx(9.9)
    assert slowed.time == pytest.approx(1.0)


def test_a_difference_of_exactly_tmax_splits_and_just_below_it_does_not() -> None:
    # Rule 2 when the rest is "less than TMAX" (001 L7563-7567, L33178): at TMAX it splits
    assert equal_time_step(1.0, 0.5, 0.5, 0.0).rule is MergeRule.SPLIT
    assert equal_time_step(1.0, 0.5, 0.5000001, 0.0).rule is MergeRule.RULE_2


def test_option_151_compares_the_difference_with_the_unsplit_heads_time() -> None:
    # 1.0 against 1.25: dT/T(unsplit) = 25 %, dT/T(split) = 20 % (001 L7619-7627)
    assert equal_time_step(1.0, 1.25, 0.0, 22.0).rule is MergeRule.SPLIT
    step = equal_time_step(1.0, 1.25, 0.0, 25.5)
    assert (step.rule, step.head) == (MergeRule.TOLERANCE_BAND, 1)
    assert step.feed_factor == pytest.approx(0.8)  # a 20 % slower feed, within the band
    assert equal_time_step(1.0, 1.25, 0.0, 25.0).rule is MergeRule.SPLIT  # "less than"
    assert equal_time_step(1.0, 1.25, 0.0, 0.0).rule is MergeRule.SPLIT  # standard 0: off
    # Rule 2 is tested first: both apply, Rule 2 is reported
    assert equal_time_step(1.0, 1.01, TMAX, 50.0).rule is MergeRule.RULE_2


def test_equal_times_go_out_as_they_are() -> None:
    step = equal_time_step(0.7, 0.7, TMAX, 10.0)
    assert (step.rule, step.head, step.fraction, step.feed_factor) == (
        MergeRule.EQUAL,
        None,
        1.0,
        1.0,
    )
    # the float noise of an earlier split is no difference, even with TMAX 0
    assert equal_time_step(0.1 + 0.2, 0.3, 0.0, 0.0).rule is MergeRule.EQUAL


def test_equal_time_step_refuses_what_has_no_ratio() -> None:
    for bad in ((0.0, 1.0, TMAX, 0.0), (1.0, 1.0, -1.0, 0.0), (1.0, 2.0, TMAX, 101.0)):
        with pytest.raises(ValueError):
            equal_time_step(*bad)


# --- W3: CIRSEG --------------------------------------------------------------------------


def test_w3_cirseg_self_consistent_recomputation() -> None:
    # R 5, theta 2 rad, RADIO 0.7, A at the origin, chord on +X, centre below (spec 04 W3)
    pieces = split_arc(CHORD, CENTRE, Plane.XY, True, 0.7)
    _close(pieces.first_departures, (6.15445, 1.90379, 0.0), 5)  # AP
    _close(pieces.first_offsets, (4.20735, -2.70151, 0.0), 5)  # AO, unchanged
    _close(pieces.rest_departures, (2.26026, -1.90379, 0.0), 5)  # PB
    _close(pieces.rest_offsets, (-1.94709, -4.60530, 0.0), 5)  # PO


def test_w3_the_example_arc_is_clockwise() -> None:
    # Centre below a chord along +X, the arc above it: from A the arc climbs and comes down
    # to B, turning clockwise seen from +Z. That way it turns 2 rad (S0 = 10 = R * 2, 001
    # L7757-7770); counterclockwise it would go round under the centre, 2*pi - 2 rad.
    assert arc_sweep(CHORD, CENTRE, Plane.XY, True) == pytest.approx(2.0)
    assert arc_sweep(CHORD, CENTRE, Plane.XY, False) == pytest.approx(tau - 2.0)
    top = split_arc(CHORD, CENTRE, Plane.XY, True, 0.5).first_departures
    _near(top, (CHORD[0] / 2, R - R * cos(1.0), 0.0))  # midway, the arc's top, above AB


def _manual_cirseg(
    ab: tuple[float, float], ao: tuple[float, float], radio: float, theta: float
) -> tuple[float, float]:
    """CIRSEG as §5.4 writes it, with the signed D-W distance: AP for an arc under pi."""
    chord = hypot(*ab)
    od = hypot(*ao) * cos(theta / 2)
    aw = chord / 2 + od * tan(radio * theta - theta / 2)
    ow = (aw * ab[0] / chord - ao[0], aw * ab[1] / chord - ao[1])
    scale = hypot(*ao) / hypot(*ow)
    return ao[0] + scale * ow[0], ao[1] + scale * ow[1]


def test_w3_the_manuals_printed_trace_is_wrong_and_the_corrected_values_are_tested() -> None:
    # The manual's trace (001 L7785-7866) mixes two chords and flips a sign:
    # (a) a 2 rad arc of radius 5 has chord 10 sin 1 = 8.4147, not the printed 8 (its
    #     AO(X) = 4.2095 = 5 sin 1 belongs to 8.4147, its |AD| = 4 to 8);
    assert CHORD[0] == pytest.approx(8.4147, abs=5e-5)
    # (b) it takes OW(Y) = 0 + 2.698, i.e. AO(Y) = -2.698 (centre below), then adds +2.698 to
    #     get AP(Y) = 2.698 + 4.732 = 7.430: a point 7.43 from the chord of a radius-5 circle
    #     whose centre is 2.7 below it cannot be on the circle. Its own steps give 2.034.
    printed_ap = (5.8455, 7.430)
    centre = (4.2095, -2.698)
    assert hypot(printed_ap[0] - centre[0], printed_ap[1] - centre[1]) > R + 2
    # its own steps, with its own rounding: OW = (0.9327, 0 - AO(Y)), |OW| = 2.85
    op = (5 * 0.9327 / 2.85, 5 * 2.698 / 2.85)
    assert op == pytest.approx((1.636, 4.732), abs=2e-3)  # it printed 4.732 for 4.7333
    ap = (centre[0] + op[0], centre[1] + op[1])
    assert ap == pytest.approx((5.8455, 2.034), abs=2e-3)  # AP(Y) 2.034, not 7.430
    # the formula unrounded on the same (inconsistent) inputs, chord 8, lands near there
    assert _manual_cirseg((8.0, 0.0), centre, 0.7, 2.0) == pytest.approx((5.8430, 2.0275), abs=1e-4)
    # and on consistent inputs it agrees with the rotation that the code uses
    _near(
        _manual_cirseg((CHORD[0], 0.0), (CENTRE[0], CENTRE[1]), 0.7, 2.0), (6.15445, 1.90379), 5e-6
    )


def test_w3_mirrored_the_centre_above_makes_the_arc_counterclockwise() -> None:
    pieces = split_arc(CHORD, (CENTRE[0], -CENTRE[1], 0.0), Plane.XY, False, 0.7)
    _close(pieces.first_departures, (6.15445, -1.90379, 0.0), 5)


def test_cirseg_splits_a_full_circle_and_an_arc_beyond_pi() -> None:
    # the tangent form is infinite at RADIO*theta - theta/2 = pi/2; the rotation is not
    full = Move.circle((0.0, 0.0, 0.0), (-2.0, 0.0, 0.0), Plane.XY, False, 10.0)
    assert full.arc is not None and full.arc.sweep == pytest.approx(tau)
    half, rest = split_move(full, 0.5)
    _near(half.departures, (-4.0, 0.0, 0.0))  # counterclockwise from the circle's +X point
    _near(rest.departures, (4.0, 0.0, 0.0))
    assert half.time + rest.time == pytest.approx(full.time)
    quarter = split_arc((0.0, 0.0, 0.0), (-2.0, 0.0, 0.0), Plane.XY, True, 0.25)
    _near(quarter.first_departures, (-2.0, -2.0, 0.0))  # clockwise: down first


def test_cirseg_in_the_zx_and_yz_planes_turns_about_y_and_x() -> None:
    # ZX: counterclockwise seen from +Y turns Z into X; YZ: seen from +X turns Y into Z
    zx = split_arc((0.0, 0.0, 0.0), (0.0, 0.0, -1.0), Plane.ZX, False, 0.25).first_departures
    _near(zx, (1.0, 0.0, -1.0))
    yz = split_arc((0.0, 0.0, 0.0), (0.0, -1.0, 0.0), Plane.YZ, False, 0.25).first_departures
    _near(yz, (0.0, -1.0, 1.0))


def test_a_helix_rises_in_proportion() -> None:
    helix = Move.circle((0.0, 0.0, 3.0), (-2.0, 0.0, 0.0), Plane.XY, False, 10.0)
    assert helix.length == pytest.approx(hypot(2.0 * tau, 3.0))
    first, rest = split_move(helix, 1 / 3)
    _near(first.departures[2:], (1.0,))
    _near(rest.departures[2:], (2.0,))


def test_a_dwell_splits_its_time() -> None:
    first, rest = split_move(Move.dwell(0.5), 0.2)
    assert (first.time, rest.time) == pytest.approx((0.1, 0.4))


# --- §5.3: the whole worked sequence (Diagrams 3.4.8.2.1B/C) ----------------------------


def test_the_worked_sequence_of_section_5_3() -> None:
    head_1 = [
        Move.line((10.0, 0.0, 0.0), 20.0, source="La1"),
        Move.circle(CHORD, CENTRE, Plane.XY, True, 10.0, source="Ca1"),
    ]
    head_2 = [
        Move.line((12.0, 0.0, 0.0), 10.0, source="Lb1"),
        Move.line((8.0, 3.0, 0.0), 10.0, source="Lb2"),
    ]
    pairs = list(equal_time_merge(iter(head_1), iter(head_2), TMAX, 0.0))
    assert [(p.head_1 and p.head_1.source, p.head_2 and p.head_2.source) for p in pairs] == [
        ("La1", "Lb1"),
        ("Ca1", "Lb1"),
        ("Ca1", "Lb2"),
        (None, "Lb2"),
    ]
    la1_lb11, s1_lb12, s2_lb21, lb22 = pairs
    assert la1_lb11.head_1 == head_1[0]  # La1 as it is
    assert la1_lb11.head_2 is not None and la1_lb11.head_2.departures == pytest.approx((5, 0, 0))
    assert s1_lb12.head_1 is not None and s1_lb12.head_2 is not None
    _close(s1_lb12.head_1.departures, (6.15445, 1.90379, 0.0), 5)  # s1: AP, offsets AO
    assert s1_lb12.head_1.arc is not None
    _close(s1_lb12.head_1.arc.offsets, (4.20735, -2.70151, 0.0), 5)
    assert s1_lb12.head_2.departures == pytest.approx((7, 0, 0))  # Lb12
    assert s2_lb21.head_1 is not None and s2_lb21.head_2 is not None
    _close(s2_lb21.head_1.departures, (2.26026, -1.90379, 0.0), 5)  # s2: PB, offsets PO
    assert s2_lb21.head_1.arc is not None
    _close(s2_lb21.head_1.arc.offsets, (-1.94709, -4.60530, 0.0), 5)
    assert s2_lb21.head_1.time == pytest.approx(0.3)  # the 3 in left of the arc
    _close(s2_lb21.head_2.departures, (2.8090, 1.0534, 0.0), 4)  # Lb21
    assert lb22.step is None and lb22.head_2 is not None
    _close(lb22.head_2.departures, (5.1910, 1.9466, 0.0), 4)  # Lb22 alone: head 1 is done
    for pair in pairs[:3]:
        assert pair.head_1 is not None and pair.head_2 is not None
        assert pair.step is not None and pair.step.rule is MergeRule.SPLIT
        assert isclose(pair.head_1.time, pair.head_2.time, rel_tol=1e-12)
        assert pair.head_1.feed in (20.0, 10.0) and pair.head_2.feed == 10.0  # feeds kept


def test_rule_2_in_the_merge_slows_the_quicker_head_and_a_dwell_waits_longer() -> None:
    pairs = list(
        equal_time_merge(
            [Move.line((10.0, 0.0, 0.0), 10.0), Move.dwell(0.5)],
            [Move.line((9.95, 0.0, 0.0), 10.0), Move.line((5.02, 0.0, 0.0), 10.0)],
            TMAX,
            0.0,
        )
    )
    assert [p.step.rule if p.step else None for p in pairs] == [MergeRule.RULE_2] * 2
    first, second = pairs
    assert first.head_2 is not None and first.head_2.feed == pytest.approx(9.95)
    assert second.head_1 is not None and second.head_1.dwell_minutes == pytest.approx(0.502)
    for pair in pairs:
        assert pair.head_1 is not None and pair.head_2 is not None
        assert isclose(pair.head_1.time, pair.head_2.time, rel_tol=1e-12)


def test_a_move_that_takes_no_time_goes_out_alone() -> None:
    pairs = list(
        equal_time_merge(
            [Move.line((0.0, 0.0, 0.0), 10.0), Move.line((1.0, 0.0, 0.0), 10.0)],
            [Move.line((1.0, 0.0, 0.0), 10.0)],
            TMAX,
            0.0,
        )
    )
    assert [(p.head_1 is not None, p.head_2 is not None) for p in pairs] == [
        (True, False),
        (True, True),
    ]


def test_the_merge_streams_endless_heads() -> None:
    pulled = [0, 0]

    def endless(head: int, length: float) -> Iterator[Move]:
        while True:
            pulled[head - 1] += 1
            yield Move.line((length, 0.0, 0.0), 10.0)

    pairs = list(itertools.islice(equal_time_merge(endless(1, 3.0), endless(2, 5.0), 0.0, 0.0), 6))
    assert len(pairs) == 6
    assert pulled[0] <= 7 and pulled[1] <= 7
    for pair in pairs:
        assert pair.head_1 is not None and pair.head_2 is not None
        assert isclose(pair.head_1.time, pair.head_2.time, rel_tol=1e-12)


# --- W19: the linear head's arc centre offsets ---------------------------------------------


def test_w19_linear_head_offsets_divide_by_the_half_angle() -> None:
    # S = 8.4147, R = 5: B1 = 0.84147, theta = atan(B1 / sqrt(1 - B1^2)) = 1.0 rad
    # (001 L8752-8777); IL = 2 / 1.0, JL = 1 / 1.0
    offsets = linear_head_offsets((8.4147, 0.0, 0.0), CENTRE, (2.0, 1.0, 0.0))
    _close(offsets, (2.0, 1.0, 0.0), 4)
    b1 = 8.4147 / (2 * R)
    assert atan(b1 / sqrt(1 - b1 * b1)) == pytest.approx(1.0, abs=1e-4)


def test_linear_head_offsets_at_a_half_circle_and_a_full_circle() -> None:
    # a chord rounded a little past the diameter is a half circle: theta = pi/2
    _near(linear_head_offsets((10.0001, 0, 0), (5.0, 0, 0), (pi, 0, 0)), (2.0, 0.0, 0.0))
    with pytest.raises(ValueError):
        linear_head_offsets((0.0, 0.0, 0.0), (5.0, 0.0, 0.0), (1.0, 0.0, 0.0))


# --- W6: common axis (FXMULT, SEG, FXTOL) -----------------------------------------------------


def test_w6_pair_1_same_origin_same_end_no_segmentation() -> None:
    assert common_axis_step(0.0, 10.0, 0.0, 10.0) == CommonAxisStep(AxisRule.COMBINE)


def test_w6_pair_2_head_2_goes_further_and_is_segmented_at_20() -> None:
    step = common_axis_step(10.0, 20.0, 10.0, 25.0)
    assert (step.rule, step.head, step.at) == (AxisRule.SEGMENT, 2, 20.0)
    first, rest = split_line((15.0, 4.5, 0.0), step.fraction)  # SEG: rest 20 -> 25
    _near(first, (10.0, 3.0, 0.0))
    _near(rest, (5.0, 1.5, 0.0))


def test_common_axis_head_1_longer_and_the_minus_direction() -> None:
    assert common_axis_step(0.0, 15.0, 0.0, 10.0) == CommonAxisStep(
        AxisRule.SEGMENT, 1, 10.0, pytest.approx(2 / 3)
    )
    assert common_axis_step(20.0, 5.0, 20.0, 10.0) == CommonAxisStep(
        AxisRule.SEGMENT, 1, 10.0, pytest.approx(2 / 3)
    )


def test_common_axis_cases_the_manual_leaves_to_its_write_ups() -> None:
    # different origins: the head behind cuts alone up to the other's origin
    assert common_axis_step(0.0, 10.0, 5.0, 15.0) == CommonAxisStep(AxisRule.CATCH_UP, 1, 5.0, 0.5)
    assert common_axis_step(10.0, 0.0, 4.0, -6.0) == CommonAxisStep(AxisRule.CATCH_UP, 1, 4.0, 0.6)
    assert common_axis_step(8.0, 12.0, 0.0, 6.0) == CommonAxisStep(AxisRule.CATCH_UP, 2)
    # one head still on the axis: it cuts alone, the mover waits
    assert common_axis_step(5.0, 5.0, 5.0, 9.0) == CommonAxisStep(AxisRule.CATCH_UP, 1)
    # opposite ways, or both still at different places: each head alone
    assert common_axis_step(0.0, 10.0, 0.0, -10.0) == CommonAxisStep(AxisRule.SEPARATE)
    assert common_axis_step(1.0, 1.0, 2.0, 2.0) == CommonAxisStep(AxisRule.SEPARATE)
    assert common_axis_step(1.0, 1.0, 1.0, 1.0) == CommonAxisStep(AxisRule.COMBINE)


def test_fxtol_component_feeds() -> None:
    # Fx = dX * F / s (001 L8284-8292): 3-4-5 at 10 ipm -> 6 ipm along X
    assert component_feed(3.0, 5.0, 10.0) == pytest.approx(6.0)
    assert component_feed(0.0, 0.0, 10.0) == 0.0
    # 6 against 5.5 ipm differ by 8.3 % of the faster
    assert component_feeds_agree(3.0, 5.0, 10.0, 5.5, 10.0, 10.0, 9.0)
    assert not component_feeds_agree(3.0, 5.0, 10.0, 5.5, 10.0, 10.0, 8.0)
    assert component_feeds_agree(3.0, 5.0, 10.0, 5.5, 10.0, 10.0, 0.0)  # 157 = 0: no check
    assert component_feeds_agree(0.0, 5.0, 10.0, 0.0, 3.0, 20.0, 1.0)  # no axis motion
    assert not component_feeds_agree(3.0, 5.0, 10.0, -3.0, 5.0, 10.0, 50.0)  # opposite ways
    # with one feed register equal dX gives equal Fx whatever the paths (001 L8292-8299)
    time = 0.5
    assert component_feeds_agree(4.0, 5.0, 5.0 / time, 4.0, 13.0, 13.0 / time, 1e-9)


# --- properties ------------------------------------------------------------------------------

finite = st.floats(-50.0, 50.0, allow_nan=False)
vectors = st.tuples(finite, finite, finite)
fractions = st.floats(0.0, 1.0)
planes = st.sampled_from(list(Plane))


@st.composite
def arcs(draw: st.DrawFn) -> tuple[tuple[float, float, float], Arc]:
    """An arc of any sweep (full circles included) in any plane and direction."""
    plane, clockwise = draw(planes), draw(st.booleans())
    radius = draw(st.floats(0.01, 50.0))
    start_angle = draw(st.floats(0.0, tau))
    sweep = draw(st.one_of(st.floats(0.01, tau - 0.01), st.just(tau)))
    rise = draw(st.one_of(st.just(0.0), finite))
    end_angle = start_angle - sweep if clockwise else start_angle + sweep
    u, v, w = plane.axes
    centre_to_start = (radius * cos(start_angle), radius * sin(start_angle))
    centre_to_end = (radius * cos(end_angle), radius * sin(end_angle))
    offsets, departures = [0.0] * 3, [0.0] * 3
    offsets[u], offsets[v] = -centre_to_start[0], -centre_to_start[1]
    departures[u] = centre_to_end[0] - centre_to_start[0]
    departures[v] = centre_to_end[1] - centre_to_start[1]
    departures[w] = rise
    if sweep == tau:
        departures[u] = departures[v] = 0.0
    arc = Arc((offsets[0], offsets[1], offsets[2]), plane, clockwise, sweep)
    return (departures[0], departures[1], departures[2]), arc


@given(vectors, fractions)
def test_a_line_splits_into_pieces_that_add_up(departures: tuple[float, ...], f: float) -> None:
    first, rest = split_line(departures, f)
    _near(tuple(a + b for a, b in zip(first, rest, strict=True)), departures, 1e-12)
    _near(first, tuple(d * f for d in departures), 1e-12)


@settings(max_examples=300)
@given(arcs(), st.floats(0.01, 0.99))
def test_an_arc_splits_into_pieces_that_add_up(
    drawn: tuple[tuple[float, float, float], Arc], f: float
) -> None:
    departures, arc = drawn
    assert arc_sweep(departures, arc.offsets, arc.plane, arc.clockwise) == pytest.approx(
        arc.sweep, abs=1e-7
    )
    move = Move(departures, 10.0, arc)
    first, rest = split_move(move, f)
    assert first.arc is not None and rest.arc is not None
    # departures and times add up; P lies on the circle; each piece turns its share
    total = tuple(a + b for a, b in zip(first.departures, rest.departures, strict=True))
    _near(total, departures, 1e-9)
    assert first.time + rest.time == pytest.approx(move.time, rel=1e-12)
    assert first.time == pytest.approx(f * move.time, rel=1e-12)
    assert first.arc.offsets == arc.offsets
    assert rest.arc.radius == pytest.approx(arc.radius, rel=1e-12)
    for piece in (first, rest):
        assert piece.arc is not None
        derived = arc_sweep(piece.departures, piece.arc.offsets, arc.plane, arc.clockwise)
        assert derived == pytest.approx(piece.arc.sweep, abs=1e-7)
    # the rest's centre is the whole arc's centre (in the plane: a helix rises off it)
    u, v, _ = arc.plane.axes
    centre = [first.departures[a] + rest.arc.offsets[a] for a in (u, v)]
    _near(tuple(centre), (arc.offsets[u], arc.offsets[v]), 1e-9)


@settings(max_examples=200)
@given(arcs(), st.floats(0.0, 1.0))
def test_the_manuals_tangent_form_agrees_with_the_rotation_under_pi(
    drawn: tuple[tuple[float, float, float], Arc], f: float
) -> None:
    departures, arc = drawn
    if arc.sweep > pi - 0.1 or arc.plane is not Plane.XY or hypot(*departures[:2]) < 1e-3:
        return
    pieces = split_arc(departures, arc.offsets, arc.plane, arc.clockwise, f)
    manual = _manual_cirseg(departures[:2], arc.offsets[:2], f, arc.sweep)
    _near(pieces.first_departures[:2], manual, 1e-6 * max(1.0, arc.radius))


def _moves(draw: st.DrawFn) -> list[Move]:
    kinds = draw(st.lists(st.sampled_from(["line", "arc", "dwell"]), min_size=0, max_size=6))
    moves: list[Move] = []
    for kind in kinds:
        if kind == "dwell":
            moves.append(Move.dwell(draw(st.floats(0.001, 2.0))))
        elif kind == "line":
            departures = draw(vectors.filter(lambda d: hypot(*d) > 1e-3))
            moves.append(Move.line(departures, draw(st.floats(0.5, 200.0))))
        else:
            departures, arc = draw(arcs())
            moves.append(Move(departures, draw(st.floats(0.5, 200.0)), arc))
    return moves


@st.composite
def programs(draw: st.DrawFn) -> tuple[list[Move], list[Move], float, float]:
    tmax = draw(st.sampled_from([0.0, TMAX, 0.1]))
    band = draw(st.sampled_from([0.0, 5.0, 50.0]))
    return _moves(draw), _moves(draw), tmax, band


@settings(max_examples=300)
@given(programs())
def test_every_merged_pair_takes_one_time_and_nothing_is_lost(
    program: tuple[list[Move], list[Move], float, float],
) -> None:
    head_1, head_2, tmax, band = program
    pairs: list[MergedPair] = list(equal_time_merge(head_1, head_2, tmax, band))
    for pair in pairs:
        if pair.head_1 is None or pair.head_2 is None:
            assert pair.step is None
            continue
        assert pair.step is not None
        assert isclose(pair.head_1.time, pair.head_2.time, rel_tol=1e-12)
        assert pair.step.time == pytest.approx(pair.head_1.time, rel=1e-12)
        if pair.step.rule is MergeRule.SPLIT:
            assert pair.step.difference >= tmax  # the rest is never reader limited
    # each head's pieces add back to its moves: departures, and times where nothing slowed
    for head, moves in ((1, head_1), (2, head_2)):
        pieces = [p.head_1 if head == 1 else p.head_2 for p in pairs]
        mine = [p for p in pieces if p is not None]
        total = tuple(sum(p.departures[a] for p in mine) for a in range(3))
        _near(total, tuple(sum(m.departures[a] for m in moves) for a in range(3)), 1e-8)
        slowed = any(
            p.step is not None and p.step.rule is not MergeRule.SPLIT and p.step.head == head
            for p in pairs
        )
        if not slowed:
            assert sum(p.time for p in mine) == pytest.approx(sum(m.time for m in moves), rel=1e-9)


@given(st.floats(0.01, 10.0), st.floats(0.01, 10.0), st.floats(0.5, 100.0))
def test_rule_2_gives_equal_times_by_feed_reduction(
    time_1: float, time_2: float, feed: float
) -> None:
    step = equal_time_step(time_1, time_2, tmax=abs(time_1 - time_2) + 1.0, band_percent=0.0)
    if step.rule is MergeRule.EQUAL:
        return
    assert step.rule is MergeRule.RULE_2
    quicker_time = min(time_1, time_2)
    quicker = Move.line((quicker_time * feed, 0.0, 0.0), feed).slowed(step.feed_factor)
    assert quicker.time == pytest.approx(max(time_1, time_2), rel=1e-12)
    assert quicker.feed <= feed


def test_w5_gfdlim_divides_below_fcomax() -> None:
    """Spec 08 W-5 (GFDLIM, 001 L32886-32903): f = 500, FCOMAX = 500, departures (3, 4):
    FRN = 10 x 500 / 5 = 1000; the divisor is 3, not 2 (1000 / 2 = 500 is not below 500):
    FRN 333.3, I = 9, J = 12. The merge pass's GMOTIN divides so; the first pass's CONTUR
    stops at the maximum "or below" (001 L12470-12480) and takes 2."""
    from gecent.core.feed.contour import FeedCommand
    from gecent.core.machine import standard_machine

    machine = standard_machine().with_options({24: 500.0, 10: 0.0, 26: 0.0})
    feed = FeedCommand(machine)
    assert feed.multiplier(500.0, 10.0, 5.0, 2) is not None
    assert feed.multiplier(500.0, 10.0, 5.0, 2)[0] == 2  # type: ignore[index]
    feed.strictly_below = True
    found = feed.multiplier(500.0, 10.0, 5.0, 2)
    assert found is not None
    constant, command, _ = found
    assert constant == 3
    # 1000 / 3 = 333.3, rounded to the Standard Machine's F format (no decimals)
    assert command == 333.0
    # I, J, K carry the departures times the divisor (FeedOptimiser.multiplied)
    assert (3 * constant, 4 * constant) == (9, 12)


@pytest.mark.parametrize(
    ("metric", "bands"),
    [
        # English: 0-.0999, .1-.9999, 1.0-9.9999, 10.0-99.9999, 100.0-999.9999
        (False, [(0.0999, 13), (0.1, 12), (0.9999, 12), (1.0, 2), (9.9999, 2), (10.0, 11),
                 (99.9999, 11), (100.0, 14), (999.9999, 14)]),
        # metric: 0-.999, 1.0-9.999, 10.0-99.999, 100.0-999.999
        (True, [(0.999, 13), (1.0, 12), (9.999, 12), (10.0, 2), (99.999, 2), (100.0, 11),
                (999.999, 11)]),
    ],
)  # fmt: skip
def test_w12_selgcd_length_bands(metric: bool, bands: list[tuple[float, int]]) -> None:
    """Spec 08 W-12 (SELGCD, 001 L37008-37031): the bands of the dimension G codes the
    merge pass gives the pieces of a split move; they are SELG's (core/motion/gcode.py),
    a piece's G chosen as every block's is (docs/decisions.md)."""
    from dataclasses import replace

    from gecent.core.machine import standard_machine
    from gecent.core.motion.gcode import LinearCodes

    machine = standard_machine().with_options({138: 1.0 if metric else 0.0, 4: 999.9999})
    tableg = list(machine.tableg)
    for location, code in ((13, 10), (12, 11), (2, 1), (11, 12), (14, 13)):
        tableg[location] = code
    machine = replace(machine, tableg=tuple(tableg))
    step = 0.001 if metric else 0.0001
    codes = LinearCodes(machine, step)
    for length, location in bands:
        assert codes.select(round(length / step)).location == location, length
