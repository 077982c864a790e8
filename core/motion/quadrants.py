"""The geometry of an arc split at its quadrants (manual §3.4.4, QUADNT and QUADET, 001
L4850-5100; spec 03 §8.7-8.8, §9): the axis crossings of an arc, the angle it turns, and
the special cases that make its end linear. Shared by circular and multiaxis motion."""

from __future__ import annotations

from math import atan2, hypot, tau

# an arc whose end is within this many steps of its start is a full circle; a longer one
# whose end rounds onto the start is a short arc, no move (docs/decisions.md)
FULL_CIRCLE = 0.01
# the axis crossing leaving each quadrant, as (du, dv) on the unit circle
LEAVE_CCLW = {1: (0, 1), 2: (-1, 0), 3: (0, -1), 4: (1, 0)}
LEAVE_CLW = {1: (1, 0), 2: (0, 1), 3: (-1, 0), 4: (0, -1)}


def arc_sweep(
    first: tuple[float, float], last: tuple[float, float], clockwise: bool, step: float
) -> float:
    """The angle an arc turns from ``first`` to ``last`` (offsets from the centre) in its
    sense; an arc that ends where it began (within FULL_CIRCLE steps) is a full circle."""
    if hypot(last[0] - first[0], last[1] - first[1]) <= FULL_CIRCLE * step:
        return tau  # back where it started: a full circle (no CL arc has no length)
    turn = atan2(last[1], last[0]) - atan2(first[1], first[0])
    return (-turn if clockwise else turn) % tau


def quadrant_crossings(
    first: tuple[float, float], last: tuple[float, float], clockwise: bool
) -> list[tuple[int, int]]:
    """QUADNT and QUADET (001 L4850-5100): the axis crossings, as (du, dv) on the unit
    circle, of an arc from ``first`` to ``last`` (offsets from its centre) in path order;
    an arc that starts and ends in one quadrant with the end behind the start goes round."""
    ccw = not clockwise
    entered = _quadrant(first, ccw, first_point=True)
    left = _quadrant(last, ccw, first_point=False)
    crossings = (left - entered) % 4 if ccw else (entered - left) % 4
    if crossings == 0 and _long_way(first, last, ccw):
        crossings = 4
    leave = LEAVE_CCLW if ccw else LEAVE_CLW
    out: list[tuple[int, int]] = []
    quadrant = entered
    for _ in range(crossings):
        out.append(leave[quadrant])
        quadrant = quadrant % 4 + 1 if ccw else (quadrant + 2) % 4 + 1
    return out


def goes_linear(
    index: int,
    count: int,
    departures: tuple[int, int],
    before: tuple[float, float],
    end: tuple[float, float],
) -> bool:
    """PROCQD's special cases (001 L5214-5383): the first or last of ``count`` quadrant
    segments with a zero in-plane departure (steps), or a last segment whose end looks
    behind its start (``before`` and ``end``: offsets from the centre), goes out linear."""
    if index in (0, count - 1) and (departures[0] == 0 or departures[1] == 0):
        return True  # zero departure at the start or end (001 L5284-5293)
    if index == count - 1 and count >= 2:
        axis = 0 if abs(before[0]) > abs(before[1]) else 1
        if abs(end[axis]) >= abs(before[axis]):
            return True  # apparent reversal at the end point (001 L5355-5383)
    return False


def _quadrant(point: tuple[float, float], ccw: bool, *, first_point: bool) -> int:
    """QUADNT (001 L4883-4930): a point on an axis belongs to the quadrant the arc enters
    next (first point) or last passed through (last point)."""
    pu, pv = point
    if pu and pv:
        if pu > 0:
            return 1 if pv > 0 else 4
        return 2 if pv > 0 else 3
    turn = 0 if pu > 0 else 1 if pv > 0 else 2 if pu < 0 else 3
    if first_point:
        return turn % 4 + 1 if ccw else (turn - 1) % 4 + 1
    return (turn - 1) % 4 + 1 if ccw else turn % 4 + 1


def _long_way(first: tuple[float, float], last: tuple[float, float], ccw: bool) -> bool:
    """Start and end in one quadrant with the end behind the start: nearly a full circle."""
    cross = first[0] * last[1] - last[0] * first[1]
    return cross <= 0 if ccw else cross >= 0
