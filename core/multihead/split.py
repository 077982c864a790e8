"""Equal-time merging of two heads' moves under one feedrate register: the arithmetic of
GEMULT's GMLINE, GMCIRL, SPLIT and CIRSEG (manual §3.4.8.2.1.1, 001 L7390-7890; write-ups
CIRSEG 001 L29244-29370, GMCIRL and GMLINE L32965-33208, SPLIT L37639-37730) and of GMOUT's
linear-head arc-centre offsets (§3.4.8.2.2.2, 001 L8737-8785).

With one F register every combined block must take the same time on both heads. The head
whose move takes longer is split so that its first piece takes the other head's time; the
rest waits for the other head's next move. A split that would leave a rest shorter than the
tape-reader limit TMAX is not made (Rule 2), nor one whose time difference lies within the
option-151 band: the quicker head is slowed instead.

Moves are incremental: departures from the start in inches, an arc's centre offsets signed
from the start to the centre, feeds in IPM, times in minutes. A dwell is a move of no length
and no feed whose time is the dwell time (001 L7629-7633, L7676-7677).

The feed command of a merged block (GMOTIN) and the rescaling of I, J, K for an over-range
command (GFDLIM, spec 08 W-5) are not here: ``FeedCommand.command`` and
``FeedCommand.multiplier`` in core/feed/contour.py compute them for one head's block.
"""

from __future__ import annotations

from collections.abc import Callable, Generator, Iterable, Sequence
from dataclasses import dataclass, replace
from enum import Enum, IntEnum
from functools import cached_property
from math import asin, atan2, cos, hypot, isclose, sin, tau

Vector = tuple[float, float, float]
ZERO: Vector = (0.0, 0.0, 0.0)

# Times this close are one time: what is left is the float noise of an earlier split.
SAME_TIME = 1e-12
# An in-plane departure this small beside the radius ends where the arc began.
FULL_CIRCLE = 1e-9


class Plane(IntEnum):
    """An arc's plane, numbered as IPLANE: CODE +-10 XY, +-11 ZX, +-12 YZ."""

    XY = 0
    ZX = 1
    YZ = 2

    @property
    def axes(self) -> tuple[int, int, int]:
        """(u, v, normal) as indices of X, Y, Z; u turns into v counterclockwise seen from
        the normal's + end, which is how clockwise is judged (G02 in G17, G18, G19)."""
        return ((0, 1, 2), (2, 0, 1), (1, 2, 0))[self]


def _place(axes: tuple[int, int, int], u: float, v: float, w: float) -> Vector:
    values = [0.0, 0.0, 0.0]
    values[axes[0]], values[axes[1]], values[axes[2]] = u, v, w
    return (values[0], values[1], values[2])


def _check_fraction(fraction: float) -> None:
    if not 0.0 <= fraction <= 1.0:
        raise ValueError(f"a split fraction lies in 0..1, not {fraction}")


def move_time(length: float, ipm: float) -> float:
    """Minutes to cut ``length`` inches at ``ipm``: T = L / F (001 L7404-7410)."""
    if length < 0.0:
        raise ValueError(f"a move's length is not negative: {length}")
    if length == 0.0:
        return 0.0
    if ipm <= 0.0:
        raise ValueError(f"a move of {length} in needs a feed, not {ipm} ipm")
    return length / ipm


def tape_reader_limit(option13_minutes: float, option69_seconds: float) -> float:
    """TMAX in minutes: the larger of the tape reading time (option 13, in minutes by the
    option table) and the servo settling time (option 69, in seconds); the theory text
    calls both seconds (001 L7553-7557, L24515-24540, L25243-25246)."""
    return max(option13_minutes, option69_seconds / 60.0)


def split_line(departures: Sequence[float], fraction: float) -> tuple[Vector, Vector]:
    """SPLIT for a line (001 L37639-37730): the first piece is ``fraction`` of each
    departure, the rest is what remains, so the two always add up to the move."""
    _check_fraction(fraction)
    x, y, z = departures
    first = (x * fraction, y * fraction, z * fraction)
    return first, (x - first[0], y - first[1], z - first[2])


def arc_sweep(
    departures: Sequence[float], offsets: Sequence[float], plane: Plane, clockwise: bool
) -> float:
    """The angle an arc turns through, in radians in (0, 2*pi]: from the centre-to-start
    vector to the centre-to-end one, in the arc's direction; an arc ending where it began
    is a full circle. Any departure along the plane's normal (a helix) is left aside."""
    u, v, _ = plane.axes
    start_u, start_v = -offsets[u], -offsets[v]
    end_u, end_v = departures[u] - offsets[u], departures[v] - offsets[v]
    radius = hypot(start_u, start_v)
    if radius == 0.0:
        raise ValueError("an arc's centre must lie away from its start")
    if hypot(departures[u], departures[v]) <= FULL_CIRCLE * radius:
        return tau
    counterclockwise = atan2(start_u * end_v - start_v * end_u, start_u * end_u + start_v * end_v)
    counterclockwise %= tau
    if counterclockwise == 0.0:
        raise ValueError("an arc's end lies on the ray from its centre through its start")
    return tau - counterclockwise if clockwise else counterclockwise


@dataclass(frozen=True)
class ArcSplit:
    """CIRSEG's answer in the manual's names (Diagram 3.4.8.2.1C, 001 L7785-7866)."""

    first_departures: Vector  # AP: start A to split point P
    first_offsets: Vector  # AO: the whole arc's offsets, unchanged
    rest_departures: Vector  # PB: split point P to end B
    rest_offsets: Vector  # PO: split point P to centre O


def split_arc(
    departures: Sequence[float],
    offsets: Sequence[float],
    plane: Plane,
    clockwise: bool,
    fraction: float,
    sweep: float | None = None,
) -> ArcSplit:
    """CIRSEG (001 L29244-29370, L7785-7866): split an arc at ``fraction`` of its length.

    The manual finds P where the ray OP crosses the chord, with a tangent of the angle
    between OP and the chord's perpendicular; that tangent is infinite for arcs of pi or
    more. Rotating OA about the centre by ``fraction * sweep`` in the arc's direction finds
    the same P for any arc, full circles included. ``sweep`` (radians) is derived from the
    departures when not given; a helix rises along the normal in proportion.
    """
    _check_fraction(fraction)
    u, v, w = plane.axes
    angle = arc_sweep(departures, offsets, plane, clockwise) if sweep is None else sweep
    turn = -fraction * angle if clockwise else fraction * angle
    centre_to_start_u, centre_to_start_v = -offsets[u], -offsets[v]
    c, s = cos(turn), sin(turn)
    op_u = centre_to_start_u * c - centre_to_start_v * s
    op_v = centre_to_start_u * s + centre_to_start_v * c
    first = _place(plane.axes, offsets[u] + op_u, offsets[v] + op_v, departures[w] * fraction)
    rest = (departures[0] - first[0], departures[1] - first[1], departures[2] - first[2])
    # the offsets' normal component is 0 for every arc the post makes; it is carried as is
    rest_offsets = _place(plane.axes, -op_u, -op_v, offsets[w])
    return ArcSplit(first, (offsets[0], offsets[1], offsets[2]), rest, rest_offsets)


@dataclass(frozen=True)
class Arc:
    """An arc move's circle: its signed centre offsets from the start, plane, direction and
    the angle it turns through (radians; use ``Move.circle`` to derive it)."""

    offsets: Vector
    plane: Plane
    clockwise: bool
    sweep: float

    def __post_init__(self) -> None:
        if not 0.0 <= self.sweep <= tau:
            raise ValueError(f"an arc turns through 0..2*pi, not {self.sweep}")

    @property
    def radius(self) -> float:
        u, v, _ = self.plane.axes
        return hypot(self.offsets[u], self.offsets[v])


@dataclass(frozen=True)
class Move:
    """One head's pending move: a line, an arc (``arc`` set) or a dwell (``dwell_minutes``
    set, no departures, no feed). ``source`` is the caller's own record, carried unchanged
    into both pieces of a split."""

    departures: Vector = ZERO
    feed: float = 0.0
    arc: Arc | None = None
    dwell_minutes: float = 0.0
    source: object = None

    def __post_init__(self) -> None:
        if self.feed < 0.0 or self.dwell_minutes < 0.0:
            raise ValueError("feeds and dwell times are not negative")
        if self.dwell_minutes > 0.0 and (any(self.departures) or self.arc is not None or self.feed):
            raise ValueError("a dwell neither moves nor feeds")
        move_time(self.length, self.feed)  # a move needs a feed

    @classmethod
    def line(cls, departures: Sequence[float], feed: float, source: object = None) -> Move:
        x, y, z = departures
        return cls((x, y, z), feed, source=source)

    @classmethod
    def circle(
        cls,
        departures: Sequence[float],
        offsets: Sequence[float],
        plane: Plane,
        clockwise: bool,
        feed: float,
        sweep: float | None = None,
        source: object = None,
    ) -> Move:
        """An arc; its sweep is derived from the departures unless given (a zero in-plane
        departure is a full circle)."""
        if sweep is None:
            sweep = arc_sweep(departures, offsets, plane, clockwise)
        x, y, z = departures
        i, j, k = offsets
        return cls((x, y, z), feed, Arc((i, j, k), plane, clockwise, sweep), source=source)

    @classmethod
    def dwell(cls, minutes: float, source: object = None) -> Move:
        return cls(dwell_minutes=minutes, source=source)

    @cached_property
    def length(self) -> float:
        """The path length: along the arc (along the helix, if it rises) or the line."""
        if self.arc is None:
            return hypot(*self.departures)
        rise = self.departures[self.arc.plane.axes[2]]
        return hypot(self.arc.radius * self.arc.sweep, rise)

    @cached_property
    def time(self) -> float:
        """Minutes: the dwell time, or the length at the feed."""
        if self.dwell_minutes > 0.0:
            return self.dwell_minutes
        return move_time(self.length, self.feed)

    def slowed(self, factor: float) -> Move:
        """The move taking 1/``factor`` times as long: a lower feed, or a longer dwell (the
        dwell's "feed" cannot drop, so its time grows to the other head's)."""
        if not 0.0 < factor <= 1.0:
            raise ValueError(f"a feed is slowed by a factor in (0, 1], not {factor}")
        if self.dwell_minutes > 0.0:
            return replace(self, dwell_minutes=self.dwell_minutes / factor)
        return replace(self, feed=self.feed * factor)


def split_move(move: Move, fraction: float) -> tuple[Move, Move]:
    """SPLIT (001 L37639-37730): a dwell's time, a line's departures or an arc (CIRSEG)
    divided at ``fraction``; feed and source go to both pieces. An arc's pieces keep their
    exact sweeps, so their times add up to the whole arc's."""
    _check_fraction(fraction)
    if move.dwell_minutes > 0.0:
        first_minutes = move.dwell_minutes * fraction
        return (
            replace(move, dwell_minutes=first_minutes),
            replace(move, dwell_minutes=move.dwell_minutes - first_minutes),
        )
    arc = move.arc
    if arc is None:
        first, rest = split_line(move.departures, fraction)
        return replace(move, departures=first), replace(move, departures=rest)
    pieces = split_arc(move.departures, arc.offsets, arc.plane, arc.clockwise, fraction, arc.sweep)
    first_sweep = arc.sweep * fraction
    return (
        replace(move, departures=pieces.first_departures, arc=replace(arc, sweep=first_sweep)),
        replace(
            move,
            departures=pieces.rest_departures,
            arc=Arc(pieces.rest_offsets, arc.plane, arc.clockwise, arc.sweep - first_sweep),
        ),
    )


class MergeRule(Enum):
    """How a pair of moves is made to take one time (001 L7685-7700)."""

    EQUAL = "equal times"  # both as they are
    SPLIT = "split"  # the longer move is split (SPLIT, CIRSEG)
    RULE_2 = "rule 2"  # the rest would be tape-reader limited: the quicker head is slowed
    TOLERANCE_BAND = "option 151"  # the difference is within the band: the quicker is slowed


@dataclass(frozen=True)
class EqualTimeStep:
    """One GMLINE/GMCIRL decision. ``head`` (1 or 2) is the head split (SPLIT) or slowed
    (RULE_2, TOLERANCE_BAND); None when the times are equal."""

    rule: MergeRule
    head: int | None
    time: float  # minutes the combined block takes
    difference: float  # delta T: the longer time less the shorter
    fraction: float = 1.0  # SPLIT: the part of the split head's move in this block
    feed_factor: float = 1.0  # RULE_2, TOLERANCE_BAND: the slowed head's feed multiplier


def equal_time_step(
    time_1: float, time_2: float, tmax: float, band_percent: float
) -> EqualTimeStep:
    """GMLINE/GMCIRL's choice for moves taking ``time_1`` and ``time_2`` minutes (001
    L7390-7645; GMLINE L33176-33181, GMCIRL L33017-33023).

    The longer move is split at t_short / t_long unless the difference is below ``tmax``
    (Rule 2; a difference of exactly TMAX leaves a rest that meets the reader limit, so it
    splits) or below ``band_percent`` (option 151) of the time of the head that would not
    be split; then that quicker head's feed is multiplied by t_short / t_long instead.
    """
    if not (time_1 > 0.0 and time_2 > 0.0):
        raise ValueError(f"only moves that take time are merged: {time_1}, {time_2}")
    if tmax < 0.0 or not 0.0 <= band_percent <= 100.0:
        raise ValueError(f"TMAX {tmax} or option 151 {band_percent} out of range")
    longer = 1 if time_1 > time_2 else 2
    long_time, short_time = max(time_1, time_2), min(time_1, time_2)
    difference = long_time - short_time
    if isclose(time_1, time_2, rel_tol=SAME_TIME, abs_tol=0.0):
        return EqualTimeStep(MergeRule.EQUAL, None, long_time, difference)
    ratio = short_time / long_time
    quicker = 3 - longer
    if difference < tmax:
        return EqualTimeStep(MergeRule.RULE_2, quicker, long_time, difference, feed_factor=ratio)
    if difference / short_time < band_percent / 100.0:
        return EqualTimeStep(
            MergeRule.TOLERANCE_BAND, quicker, long_time, difference, feed_factor=ratio
        )
    return EqualTimeStep(MergeRule.SPLIT, longer, short_time, difference, fraction=ratio)


@dataclass(frozen=True)
class MergedPair:
    """One output block of a combined cut: each head's piece (None for a head that sits it
    out) and the decision that made their times equal (None when one head is alone)."""

    head_1: Move | None
    head_2: Move | None
    step: EqualTimeStep | None


def equal_time_merge(
    moves_1: Iterable[Move],
    moves_2: Iterable[Move],
    tmax: float,
    band_percent: float,
    together: Callable[[Move, Move], bool] | None = None,
    stop: Callable[[Move, Move], bool] | None = None,
) -> Generator[MergedPair, None, tuple[Move | None, Move | None]]:
    """The GMLINE/GMCIRL loop (001 L7390-7530, L7700-7890): pair the heads' moves in order,
    splitting or slowing each pair to one time; a split's rest is paired with the other
    head's next move. When one head has no moves left, the other's go out alone (Rule 1:
    the finished head waits). A move that takes no time has no ratio and goes out alone.

    ``together`` says whether the control can cut a pair at once (option 156): when it
    cannot, nothing is split and the head behind in time goes on alone. ``stop`` ends the
    loop before a pair (an OP restriction broken): the generator then returns the two
    moves not yet output (a split's rest among them). Both inputs are read one move at a
    time, so either may be an endless stream.
    """
    one, two = iter(moves_1), iter(moves_2)
    move_1, move_2 = next(one, None), next(two, None)
    behind = [0.0, 0.0]  # each head's time so far
    while move_1 is not None and move_2 is not None:
        if stop is not None and stop(move_1, move_2):
            return move_1, move_2
        alone = None
        if move_1.time == 0.0 or move_2.time == 0.0:
            alone = 1 if move_1.time == 0.0 else 2
        elif together is not None and not together(move_1, move_2):
            alone = 1 if behind[0] <= behind[1] else 2
        if alone == 1:
            behind[0] += move_1.time
            yield MergedPair(move_1, None, None)
            move_1 = next(one, None)
            continue
        if alone == 2:
            behind[1] += move_2.time
            yield MergedPair(None, move_2, None)
            move_2 = next(two, None)
            continue
        step = equal_time_step(move_1.time, move_2.time, tmax, band_percent)
        behind[0] += step.time
        behind[1] += step.time
        if step.rule is MergeRule.SPLIT and step.head == 1:
            piece, move_1 = split_move(move_1, step.fraction)
            yield MergedPair(piece, move_2, step)
            move_2 = next(two, None)
            continue
        if step.rule is MergeRule.SPLIT:
            piece, move_2 = split_move(move_2, step.fraction)
            yield MergedPair(move_1, piece, step)
            move_1 = next(one, None)
            continue
        if step.head == 1:
            move_1 = move_1.slowed(step.feed_factor)
        elif step.head == 2:
            move_2 = move_2.slowed(step.feed_factor)
        yield MergedPair(move_1, move_2, step)
        move_1, move_2 = next(one, None), next(two, None)
    while move_1 is not None:
        yield MergedPair(move_1, None, None)
        move_1 = next(one, None)
    while move_2 is not None:
        yield MergedPair(None, move_2, None)
        move_2 = next(two, None)
    return None, None


def linear_head_offsets(
    circular_departures: Sequence[float],
    circular_offsets: Sequence[float],
    linear_departures: Sequence[float],
) -> Vector:
    """The linear head's "arc centre offsets" when both heads share one G register (GMOUT,
    §3.4.8.2.2.2 steps 1-8, 001 L8752-8777): its departures divided by
    theta = atan(B1 / sqrt(1 - B1^2)) = asin(S / 2R), S the circular head's chord and R its
    radius. That theta is half the arc's angle; the manual divides by it, and so does this.
    From the chord alone an arc beyond pi looks like its complement.
    """
    chord = hypot(*circular_departures)
    radius = hypot(*circular_offsets)
    if chord == 0.0 or radius == 0.0:
        raise ValueError("a full circle (or no circle) has no chord to give the angle")
    # a rounded chord of a half circle can come out a step longer than the diameter
    theta = asin(min(chord / (2.0 * radius), 1.0))
    x, y, z = linear_departures
    return (x / theta, y / theta, z / theta)
