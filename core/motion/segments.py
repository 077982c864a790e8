"""Segmentation of a long linear move (manual §3.4.3.2-3.4.3.2.1, 001 L4317-4673).

When a departure exceeds the largest value its register holds (DEPMAX, option 4) the move
is cut into NSEG = <largest |departure| / DEPMAX> + 1 equal segments. Each segment is the
rounded difference between the exact running point and the actual (rounded) previous
machine point, so no pulse is lost and the path does not drift: the error after any segment
is under half a step (the telescoping proof of §3.4.3.2.1).
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence

from gecent.core.motion.rounding import ROUND_UP_DENOMINATOR, ROUND_UP_NUMERATOR


def segment_count(departures: Sequence[int], limits: Sequence[int]) -> int:
    """NSEG: 1 when every |departure| fits its limit, else <largest ratio> + 1.

    Departures and limits are in steps; ``limits[k]`` is DEPMAX for axis k (the manual uses
    one DEPMAX for the linear axes and ROTMAX for the rotary ones)."""
    worst = 0.0
    for departure, limit in zip(departures, limits, strict=True):
        if abs(departure) > limit:
            worst = max(worst, abs(departure) / limit)
    return int(worst) + 1 if worst else 1


def segment_place(
    index: int, count: int, whole: tuple[bool, bool] | None = None
) -> tuple[bool, bool] | None:
    """Where segment ``index`` (from 0) of ``count`` lies in the departure that was
    segmented: (first, last); ``whole`` is the place of the block it was cut from, when
    that block is a segment itself. None: a departure left whole (``count`` = 1). Option
    17's digit 2 prints only the first and last (001 L24571-24591)."""
    if count == 1:
        return whole
    first, last = whole or (True, True)
    return (first and index == 0, last and index == count - 1)


def segments(departures: Sequence[int], count: int) -> Iterator[tuple[int, ...]]:
    """The per-segment departures, in steps, of a move split into ``count`` segments.

    For each axis: the exact point advances by departure / count; each output is that exact
    point minus the actual point so far, rounded to a whole step (001 L4514-4559). The exact
    point after k segments is the fraction departure * k / count, kept in whole numbers: a
    float sum of the shares drifts on a long move until a segment no longer fits option 4."""
    actual = [0] * len(departures)
    up_num, up_den = ROUND_UP_NUMERATOR, ROUND_UP_DENOMINATOR
    for index in range(1, count + 1):
        out = []
        for axis, departure in enumerate(departures):
            if index == count:
                step = departure - actual[axis]  # exact: the end point is whole steps
            else:
                # rest = departure * index / count - actual, as numerator / count
                rest = departure * index - actual[axis] * count
                magnitude = (abs(rest) * up_den + up_num * count) // (up_den * count)
                step = -magnitude if rest < 0 else magnitude
            actual[axis] += step
            out.append(step)
        yield tuple(out)
