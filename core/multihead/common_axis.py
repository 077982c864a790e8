"""Heads that share a common axis (option 155): the arithmetic of GEMULT's FXMULT, SEG and
FXTOL (manual §3.4.8.2.1.3, 001 L7897-8402; write-ups FXMULT 001 L31712-31832, FXTOL
L31924-31993, SEG L36653-36699).

On a gantry both heads ride one axis, so every combined block must move both the same way
along it: the path that goes further is cut where the other one ends (SEG), and the two
component feeds along the axis must agree within option 157. Only lines combine on a common
axis (001 L7992-7994). Parking, withdrawing and returning the heads (FXPARK) belong to the
merge pass; these functions only say which head moves and how far.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

# Coordinates this close are one coordinate (inches): positions summed from rounded steps.
SAME_COORDINATE = 1e-9


class AxisRule(Enum):
    """What FXMULT does with two heads' moves along the common axis."""

    COMBINE = "combine"  # the same range: one combined block as the moves are
    SEGMENT = "segment"  # same origin, ``head`` goes further: cut at the other's end
    CATCH_UP = "catch up"  # ``head`` cuts alone first (the other parked), then they re-pair
    SEPARATE = "separate"  # opposite ways or still apart: each head cuts alone, head 1 first


@dataclass(frozen=True)
class CommonAxisStep:
    """FXMULT's decision. For SEGMENT and CATCH_UP, ``head`` moves; ``at`` is the common-axis
    coordinate where its first piece ends (None: its whole move) and ``fraction`` that piece's
    share of its move, for ``split_line``; the rest waits to be paired again."""

    rule: AxisRule
    head: int | None = None
    at: float | None = None
    fraction: float = 1.0


def _cut(head: int, start: float, end: float, at: float) -> CommonAxisStep:
    return CommonAxisStep(AxisRule.SEGMENT, head, at, (at - start) / (end - start))


def common_axis_step(
    start_1: float,
    end_1: float,
    start_2: float,
    end_2: float,
    tolerance: float = SAME_COORDINATE,
) -> CommonAxisStep:
    """FXMULT's tests on the common-axis coordinates of both heads' moves (001 L8185-8402).

    Both move the same way from one origin: equal ends combine; otherwise the longer path
    is segmented at the other's end (the manual's length test DIR * (H1X2 - H2X2)). The
    cases the manual leaves to its write-ups are settled so that the gantry never has to
    come back (FXMULT step 4, "the segment which best allows the system to catch up"):

    * different origins, same way: the head behind cuts alone up to the other's origin
      (its whole move when it ends before that), then the heads pair again;
    * one head still on the axis: that head's move is cut alone, the other waits;
    * opposite ways, or both still at different coordinates: each head cuts alone.
    """
    move_1, move_2 = end_1 - start_1, end_2 - start_2
    still_1, still_2 = abs(move_1) <= tolerance, abs(move_2) <= tolerance
    same_origin = abs(start_1 - start_2) <= tolerance
    if still_1 and still_2:
        return CommonAxisStep(AxisRule.COMBINE if same_origin else AxisRule.SEPARATE)
    if still_1 or still_2:
        return CommonAxisStep(AxisRule.CATCH_UP, 1 if still_1 else 2)
    if (move_1 > 0.0) != (move_2 > 0.0):
        return CommonAxisStep(AxisRule.SEPARATE)
    direction = 1.0 if move_1 > 0.0 else -1.0
    if not same_origin:
        behind = 1 if direction * (start_1 - start_2) < 0.0 else 2
        start, end, other_start = (
            (start_1, end_1, start_2) if behind == 1 else (start_2, end_2, start_1)
        )
        if direction * (end - other_start) <= tolerance:
            return CommonAxisStep(AxisRule.CATCH_UP, behind)
        return CommonAxisStep(
            AxisRule.CATCH_UP, behind, other_start, (other_start - start) / (end - start)
        )
    length_test = direction * (end_1 - end_2)
    if abs(length_test) <= tolerance:
        return CommonAxisStep(AxisRule.COMBINE)
    if length_test < 0.0:
        return _cut(2, start_2, end_2, end_1)
    return _cut(1, start_1, end_1, end_2)


def component_feed(axis_departure: float, length: float, feed: float) -> float:
    """FXTOL's component feed along the common axis, Fx = dX * F / s (001 L8284-8292);
    0 for a move of no length."""
    return axis_departure * feed / length if length > 0.0 else 0.0


def component_feeds_agree(
    axis_departure_1: float,
    length_1: float,
    feed_1: float,
    axis_departure_2: float,
    length_2: float,
    feed_2: float,
    tolerance_percent: float,
) -> bool:
    """FXTOL (001 L31924-31993, L7955-7968): may two moves be cut together, their component
    feeds along the common axis differing by at most ``tolerance_percent`` (option 157)?

    Option 157 = 0 asks for no check. The percent is of the larger component feed: the
    fraction by which the faster head would have to slow to match the slower, as FXTOL
    itself does for a rapid move (step 6). A pair with no motion on the axis agrees.
    """
    if tolerance_percent == 0.0:
        return True
    if tolerance_percent < 0.0:
        raise ValueError(f"option 157 is a percent, not {tolerance_percent}")
    fx_1 = component_feed(axis_departure_1, length_1, feed_1)
    fx_2 = component_feed(axis_departure_2, length_2, feed_2)
    return abs(fx_1 - fx_2) <= tolerance_percent / 100.0 * max(abs(fx_1), abs(fx_2))
