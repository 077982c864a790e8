"""Segment points in whole numbers (issue 17): a long move's segments all fit option 4 and
add up to the departure exactly; a float sum of the shares drifted until one did not
(FROM/0,0,0 then GOTO/23675874,0,0 on MACH23 stopped with fatal 139)."""

from __future__ import annotations

from gecent.core.motion.segments import segment_count, segments
from hypothesis import given, settings
from hypothesis import strategies as st


def test_the_reported_move_fits_every_segment() -> None:
    departure = 236_758_740_000  # 23675874 in at 0.0001 in a step
    limit = 999_999  # MACH23's option 4, 99.9999 in
    count = segment_count([departure, 0, 0], [limit] * 3)
    total = 0
    largest = 0
    for x, y, z in segments([departure, 0, 0], count):
        total += x
        largest = max(largest, abs(x))
        assert y == z == 0
    assert total == departure and largest <= limit


@settings(max_examples=300, deadline=None)
@given(
    st.lists(st.integers(-(10**9), 10**9), min_size=2, max_size=3),
    st.integers(10**5, 10**6),
)
def test_segments_fit_and_add_up(departures: list[int], limit: int) -> None:
    count = segment_count(departures, [limit] * len(departures))
    sums = [0] * len(departures)
    for step in segments(departures, count):
        for axis, value in enumerate(step):
            assert abs(value) <= limit
            sums[axis] += value
    assert sums == departures
