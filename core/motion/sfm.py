"""Surface feet per minute: constant surface speed on a contouring machine, a lathe above
all (manual §4.4, seed 001 L14230-14549; SFMO, TSTSAF L39008-39040, LOCRNG L33927-33960;
options 2 and 15, L24361-24374 and L24551-24558).

A lathe tool cutting at a constant spindle speed cuts fast at large radii and slowly at
small ones. ``SPINDL/f,SFM`` asks the postprocessor to keep the surface speed at f feet
per minute: each cutting path is split into pieces and each piece gets its own spindle
speed and, in IPR mode, the matching IPM feed.

* the speed that turns radius R (inches) at SFM feet per minute is S = 12 SFM / (2 pi R);
* between two speeds S1 and S2 the spindle shifts at the optimum shift radius
  R_SP = 12/(4 pi) SFM (1/S1 + 1/S2), the mean of the radii at which S1 and S2 turn
  exactly the requested SFM (the manual rounds the constants to 1.9 and 0.95);
* a spindle with a table of discrete speeds starts at the table speed on whose side of the
  shift radius between the two speeds bracketing S the path starts (the manual's 38 RPM
  between 30 and 40 starts at 40), then takes the next table speed, higher as the radius
  falls and lower as it grows;
* a variable spindle (types 1, 10, 18) starts at S itself and steps by option 15, a
  fraction (0.10 = 10 %) when |option 15| < 1, else a percent (10.0 = 10 %);
* the sequence over a path ends (SFMLIM) when (1) the end point is reached, (2) the next
  shift radius lies beyond the end point (on a variable spindle also when the next speed
  is beyond the speed of the end point), (3) the next speed would exceed MAXRPM, (4) the
  locked range has no further speed, (5) the radius is constant;
* a path whose starting speed is below the range's lowest speed cannot start SFM and is
  cut at the current speed (the manual's 2.73 RPM against a table from 10 RPM); above the
  highest speed (or MAXRPM) it starts at that highest speed;
* the radius is the absolute value of the CL coordinate RADIUS names (on the machine's step
  grid, TRANS included), or a fixed radius; a path crossing the centre line is split there.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from enum import IntEnum
from math import atan2, cos, inf, pi, sin

from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.ladder import SpeedLadder
from gecent.core.motion.rounding import to_steps
from gecent.core.state import Feed

Steps = tuple[int, ...]

RPM_PER_SFM_INCH = 12.0 / (2.0 * pi)  # S = 12 SFM / (2 pi R): 1.90986 (the manual's "1.9")
_SPEED_EXACT = 1e-6  # RPM: a speed this close to another is the same speed
_RADIUS_EXACT = 1e-9  # inches: a shift radius this close to the end is the end

ESTABLISHED = "SFM MODE ESTABLISHED"  # 001 L37612
RPM_ESTABLISHED = "RPM MODE ESTABLISHED"  # 001 L37610
MAXIPM_EXCEEDED = "MAXIPM WAS EXCEEDED"  # TSTSAF, 001 L39034


class EndCondition(IntEnum):
    """Why the SFM sequence over a path ended (SFMLIM = 1), numbered as the manual lists
    the cases (001 L14487-14504)."""

    PATH_END = 1
    SHIFT_BEYOND_END = 2
    MAXRPM = 3
    RANGE_BOUND = 4
    CONSTANT_RADIUS = 5


def spindle_speed(surface_feet: float, radius: float) -> float:
    """S = 12 SFM / (2 pi R) (001 L14303-14317): the RPM at which ``radius`` inches turn
    at ``surface_feet`` feet per minute; infinite on the centre line."""
    return RPM_PER_SFM_INCH * surface_feet / radius if radius > 0 else inf


def shift_radius(surface_feet: float, first: float, second: float) -> float:
    """R_SP = 12/(4 pi) SFM (1/S1 + 1/S2) (001 L14318-14340): the optimum radius to shift
    between speeds S1 and S2, where the SFM deviation is smallest."""
    return RPM_PER_SFM_INCH / 2.0 * surface_feet * (1.0 / first + 1.0 / second)


def step_fraction(option_15: float) -> float:
    """Option 15 as a fraction: |value| < 1 is a fraction (the option table's standard
    0.10 = "10 percent"), a larger value a percent (type 18's "10.0 ... 10%")."""
    size = abs(option_15)
    return size if size < 1.0 else size / 100.0


@dataclass(frozen=True, slots=True)
class Piece:
    """One piece of a path: its spindle speed and the radius where it ends (None: at the
    end of the path)."""

    speed: float
    until: float | None = None


@dataclass(frozen=True, slots=True)
class SfmPlan:
    """The pieces of one path, the exact speed for its starting radius, and why the
    sequence ended; no pieces and ``end`` None when SFM cannot start on the path."""

    pieces: tuple[Piece, ...]
    start_speed: float
    end: EndCondition | None


def sense_of(start: float, end: float) -> int:
    """ISENSE (001 L14473-14487): +1 decreasing radius, -1 increasing, 0 constant."""
    if abs(end - start) <= _RADIUS_EXACT:
        return 0
    return 1 if end < start else -1


def plan(surface_feet: float, start: float, end: float, ladder: SpeedLadder) -> SfmPlan:
    """SFMO's speeds and shift radii for a path whose radius runs from ``start`` to ``end``
    (inches): the starting speed, then one speed per shift radius until an end condition."""
    exact = spindle_speed(surface_feet, start)
    sense = sense_of(start, end)
    current = _start_speed(surface_feet, start, sense, ladder)
    if current is None:
        return SfmPlan((), exact, None)
    if sense == 0:
        return SfmPlan((Piece(current),), exact, EndCondition.CONSTANT_RADIUS)
    end_speed = spindle_speed(surface_feet, end)  # S_pL, the limiting speed at the end
    pieces: list[Piece] = []
    reached = start
    while True:
        following, stop = _next_speed(current, sense, ladder)
        if following is None:
            assert stop is not None
            ended = stop
            break
        if ladder.table is None and (following - end_speed) * sense > _SPEED_EXACT:
            ended = EndCondition.SHIFT_BEYOND_END  # "S falls outside of S_pL" (L14423-14426)
            break
        radius = shift_radius(surface_feet, current, following)
        if (end - radius) * sense >= -_RADIUS_EXACT:
            at_end = abs(end - radius) <= _RADIUS_EXACT
            ended = EndCondition.PATH_END if at_end else EndCondition.SHIFT_BEYOND_END
            break
        if (reached - radius) * sense > _RADIUS_EXACT:
            pieces.append(Piece(current, radius))
            reached = radius
        current = following  # a shift at or behind the last one changes the speed at once
    pieces.append(Piece(current))
    return SfmPlan(tuple(pieces), exact, ended)


def _start_speed(
    surface_feet: float, radius: float, sense: int, ladder: SpeedLadder
) -> float | None:
    """The speed of the first piece, or None when SFM cannot start (below the range)."""
    exact = spindle_speed(surface_feet, radius)
    low = ladder.table[0] if ladder.table else ladder.low
    top = ladder.top
    if top is None or exact < low - _SPEED_EXACT:
        return None  # Diagram 4.4E: no such speed, the path keeps the current speed
    if exact >= top - _SPEED_EXACT:
        return top
    if ladder.table is None:
        return exact
    speeds = ladder.table
    for speed in speeds:
        if abs(speed - exact) <= _SPEED_EXACT:
            return speed
    above = next(speed for speed in speeds if speed > exact)
    below = max(speed for speed in speeds if speed < exact)
    middle = shift_radius(surface_feet, below, above)
    if abs(radius - middle) <= _RADIUS_EXACT:
        return above if sense > 0 else below  # on the shift radius: the speed it goes to
    return above if radius < middle else below


def _next_speed(
    current: float, sense: int, ladder: SpeedLadder
) -> tuple[float | None, EndCondition | None]:
    """The next speed in the direction the radius asks for, or the condition that ends
    the sequence: the range bound (4) or MAXRPM (3)."""
    if ladder.table is not None:
        if sense > 0:
            higher = next((s for s in ladder.table if s > current + _SPEED_EXACT), None)
            if higher is None:
                return None, EndCondition.RANGE_BOUND
            if ladder.maximum is not None and higher > ladder.maximum + _SPEED_EXACT:
                return None, EndCondition.MAXRPM
            return higher, None
        lower = [s for s in ladder.table if s < current - _SPEED_EXACT]
        return (lower[-1], None) if lower else (None, EndCondition.RANGE_BOUND)
    if sense > 0:
        top = ladder.top
        assert top is not None  # the start speed exists, so the top does
        if current >= top - _SPEED_EXACT:
            by_maximum = ladder.maximum is not None and ladder.maximum < ladder.high
            return None, EndCondition.MAXRPM if by_maximum else EndCondition.RANGE_BOUND
        return min(current * (1.0 + ladder.step), top), None  # TSTSAF holds S to SFMAXR
    if current <= ladder.low + _SPEED_EXACT:
        return None, EndCondition.RANGE_BOUND
    return max(current * (1.0 - ladder.step), ladder.low), None


@dataclass(frozen=True, slots=True)
class Cut:
    """A piece of a path on the step grid: the point it reaches (steps, CL axis order) and
    its spindle speed (None: SFM could not start, the current speed stays)."""

    point: tuple[int, ...]
    speed: float | None


@dataclass(frozen=True, slots=True)
class SurfacePath:
    """The cuts of one path and the end condition of each stretch of it (a path crossing
    the centre line has two stretches; None where SFM could not start)."""

    cuts: tuple[Cut, ...]
    ends: tuple[EndCondition | None, ...]


def surface_cuts(
    start: Sequence[int],
    end: Sequence[int],
    radius_axis: int | None,
    fixed_radius: float,
    surface_feet: float,
    ladder: SpeedLadder,
    inches_per_step: float,
) -> SurfacePath:
    """SFMO over one path from ``start`` to ``end`` (steps): the radius is |coordinate| of
    ``radius_axis`` times ``inches_per_step``, or ``fixed_radius`` (inches) when the axis
    is None; each shift radius becomes a point on the path, rounded to the step grid."""
    begin, finish = tuple(start), tuple(end)
    if radius_axis is None:
        fixed = plan(surface_feet, fixed_radius, fixed_radius, ladder)
        speed = fixed.pieces[0].speed if fixed.pieces else None
        return SurfacePath((Cut(finish, speed),), (fixed.end,))
    axis = radius_axis

    def along(first: Steps, last: Steps) -> Callable[[float], Steps]:
        c0, c1 = first[axis], last[axis]
        return lambda target: _between(first, last, (target - c0) / (c1 - c0))

    stretches = [(begin, finish, along(begin, finish))]
    a, b = begin[axis], finish[axis]
    if a * b < 0:  # across the centre line: |coordinate| turns there
        crossing = _between(begin, finish, a / (a - b))
        stretches = [
            (begin, crossing, along(begin, crossing)),
            (crossing, finish, along(crossing, finish)),
        ]
    return _planned(stretches, axis, surface_feet, ladder, inches_per_step, begin)


def _planned(
    stretches: list[tuple[Steps, Steps, Callable[[float], Steps]]],
    radius_axis: int,
    surface_feet: float,
    ladder: SpeedLadder,
    inches_per_step: float,
    begin: Steps,
) -> SurfacePath:
    """SFMO's pieces over the stretches of a path (a line, or an arc's quadrant segment),
    each split where |coordinate| of the radius axis changes sense: every shift radius
    becomes the point ``locate`` finds for its coordinate on the stretch, rounded to the
    step grid."""
    cuts: list[Cut] = []
    ends: list[EndCondition | None] = []
    reached = begin
    for first, last, locate in stretches:
        if first == last:
            continue
        c0, c1 = first[radius_axis], last[radius_axis]
        stretch = plan(surface_feet, abs(c0) * inches_per_step, abs(c1) * inches_per_step, ladder)
        ends.append(stretch.end)
        if not stretch.pieces:
            cuts.append(Cut(last, None))
            reached = last
            continue
        side = 1 if c0 + c1 > 0 else -1
        for piece in stretch.pieces:
            until = piece.until
            point = last if until is None else locate(side * until / inches_per_step)
            if point == reached:
                continue  # the shift rounds onto the previous point: no move, no piece
            cuts.append(Cut(point, piece.speed))
            reached = point
    return SurfacePath(tuple(cuts), tuple(ends))


def _between(start: tuple[int, ...], end: tuple[int, ...], fraction: float) -> tuple[int, ...]:
    """The point ``fraction`` of the way from start to end, rounded to whole steps as
    SRAREC rounds a CL point."""
    return tuple(to_steps(a + fraction * (b - a), 1.0) for a, b in zip(start, end, strict=True))


def arc_cuts(
    start: Sequence[int],
    end: Sequence[int],
    centre: Sequence[float],
    radius: float,
    plane: tuple[int, int],
    radius_axis: int | None,
    fixed_radius: float,
    surface_feet: float,
    ladder: SpeedLadder,
    inches_per_step: float,
) -> SurfacePath:
    """SFMO over one quadrant segment of a circle (SFMCIR = 1: PROCQD hands each to SFMO
    after its special tests, 001 L5152-5163, L37415-37475): the arc from ``start`` to
    ``end`` (steps) about ``centre`` (steps) with ``radius`` (steps) in the plane ``(u, v)``,
    within one quadrant so that both plane coordinates run one way along it. The speeds
    are planned as on a line, from the radius coordinate at the two ends; each shift
    radius becomes the point of the arc where the coordinate has that value, rounded to
    the step grid. A radius along the plane's normal (or a fixed radius) is constant over
    the arc: one piece."""
    begin, finish = tuple(start), tuple(end)
    u, v = plane
    if radius_axis is None or radius_axis not in plane:
        if radius_axis is None:
            constant = fixed_radius
        else:
            constant = abs(begin[radius_axis]) * inches_per_step
        fixed = plan(surface_feet, constant, constant, ladder)
        speed = fixed.pieces[0].speed if fixed.pieces else None
        return SurfacePath((Cut(finish, speed),), (fixed.end,))
    first_angle = atan2(begin[v] - centre[v], begin[u] - centre[u])
    turn = (atan2(finish[v] - centre[v], finish[u] - centre[u]) - first_angle + pi) % (2 * pi)
    turn -= pi  # the shorter way round: a quadrant segment turns at most a quarter

    def at(fraction: float) -> tuple[int, ...]:
        angle = first_angle + fraction * turn
        point = list(begin)
        point[u] = to_steps(centre[u] + radius * cos(angle), 1.0)
        point[v] = to_steps(centre[v] + radius * sin(angle), 1.0)
        return tuple(point)

    def coordinate(fraction: float) -> float:
        angle = first_angle + fraction * turn
        if radius_axis == u:
            return centre[u] + radius * cos(angle)
        return centre[v] + radius * sin(angle)

    def between(low: float, high: float) -> Callable[[float], Steps]:
        return lambda target: at(_fraction_where(coordinate, target, low, high))

    stretches = [(begin, finish, between(0.0, 1.0))]
    a, b = begin[radius_axis], finish[radius_axis]
    if a * b < 0:  # across the centre line: |coordinate| turns there
        middle = _fraction_where(coordinate, 0.0, 0.0, 1.0)
        crossing = at(middle)
        stretches = [
            (begin, crossing, between(0.0, middle)),
            (crossing, finish, between(middle, 1.0)),
        ]
    return _planned(stretches, radius_axis, surface_feet, ladder, inches_per_step, begin)


def _fraction_where(
    coordinate: Callable[[float], float], target: float, low: float, high: float
) -> float:
    """Where between ``low`` and ``high`` a coordinate that runs one way along the arc
    takes the value ``target`` (bisection); the nearer end when it never does (a shift
    radius the rounded end points put just outside the arc)."""
    rising = coordinate(high) >= coordinate(low)
    if (target <= coordinate(low)) == rising:
        return low
    if (target >= coordinate(high)) == rising:
        return high
    for _ in range(60):
        middle = (low + high) / 2
        if (coordinate(middle) < target) == rising:
            low = middle
        else:
            high = middle
    return (low + high) / 2


def range_feed_limits(machine: MachineDefinition, feed_range: int) -> tuple[float, float]:
    """FRMIN, FRMAX (FEDRAT step 8, 001 L31180-31190): the present range's FRTAB pair on a
    machine with several feed ranges (option 25 >= 0: FRTAB holds one pair per range), else
    options 48 and 25."""
    ranges = machine.feed_ranges
    if (
        machine.number_option(18) > 1
        and machine.number_option(25) >= 0
        and 1 <= feed_range <= len(ranges)
    ):
        return ranges[feed_range - 1]
    # (option 25 < 0 asks for per-axis limits, FEDLIM: its size is the highest feed)
    return machine.number_option(48), abs(machine.number_option(25))


def piece_feed(machine: MachineDefinition, feed: Feed, speed: float) -> tuple[float | None, bool]:
    """TSTSAF's feed for a piece turning at ``speed`` (001 L39008-39040): F_IPM = F_IPR x S
    in IPR mode (001 L14354-14359), else the programmed feed; held to FRMIN..FRMAX and to
    MAXIPM (SFMAXI). Returns the feed (None: no feed programmed yet) and whether MAXIPM was
    exceeded."""
    if feed.per_revolution:
        wanted = feed.per_revolution_value * speed
    elif feed.programmed is not None:
        wanted = feed.programmed
    else:
        return None, False
    low, high = range_feed_limits(machine, feed.range)
    used = min(max(wanted, low), high)
    if feed.maximum_ipm is not None and used > feed.maximum_ipm:
        return feed.maximum_ipm, True
    return used, False
