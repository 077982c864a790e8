"""The servo analysis of A/D testing (manual §4.3.1-4.3.2, 001 L13404-14229): the errors a
servo of velocity gain Kv makes on a slope, at a corner (overshoot (2), undershoot (1), (9))
and on a circle (3), and the closed-loop terms (11)-(16) that give the circle error constant,
as functions (feeds in IPM, times in seconds, lengths in machine units). The A/D sequence
that uses them on the command blocks is core/feed/accel.py.
"""

from __future__ import annotations

from math import atan, degrees, pi, radians, sin, sqrt

PER_SECOND = 60.0  # the analysis works in inches per second (001 L13609-13619)
FLAT = 1e-9  # a turn smaller than this (radians) is no corner


def velocity_gain(ipm_per_thousandth: float) -> float:
    """Kv (in/s per inch) of a servo of so many IPM per .001" of error (001 L13609-13613)."""
    return ipm_per_thousandth / PER_SECOND / 0.001


def steady_lag(feed: float, gain: float) -> float:
    """The position lag of a servo of gain Kv at ``feed`` IPM: F/Kv (001 L13529-13534)."""
    return feed / PER_SECOND / gain


def slope_error(feed: float, gain: float, mismatch: float, slope: float) -> float:
    """The error on a slope (degrees) when one gain is off by ``mismatch``: (1/2) m (F/Kv)
    sin 2a, "1/2 of 1% of the normal velocity lag" at 45 degrees (001 L13570-13579)."""
    return 0.5 * mismatch * steady_lag(feed, gain) * abs(sin(2 * radians(slope)))


def undershoot_error(feed: float, turn: float, undershoot: float) -> float:
    """(1): E_u = 2 K_B (F/60) sin(theta/2), ``turn`` theta in radians (001 L13706-13720)."""
    return 2 * undershoot * feed / PER_SECOND * sin(turn / 2)


def overshoot_error(feed: float, turn: float, overshoot: float) -> float:
    """(2): E_o = K_o (F/60) sin theta; past 90 degrees the whole overshoot (the tool runs
    on beyond the corner, away from both lines; docs/decisions.md)."""
    return overshoot * feed / PER_SECOND * sin(min(turn, pi / 2))


def overshoot_feed(tolerance: float, turn: float, overshoot: float) -> float:
    """(2) solved for the approach feed F1 (IPM); no limit on a straight run."""
    error = overshoot_error(1.0, turn, overshoot)
    return tolerance / error if error > 0 else float("inf")


def bisector_slope(ratio: float) -> float:
    """(8): the line f(t) = (r t - 1/Kv)/(r - 1) has the slope r/(r - 1) (001 L13886-13893)."""
    return ratio / (ratio - 1)


def bisector_time(ratio: float, gain: float, undershoot: float) -> float:
    """t_B, when the tool crosses the bisector: (8) against f(t) = t - C t^2, C = K_B Kv^2,
    the parabola through (1/Kv, 1/Kv - K_B); 1/Kv when the feed does not change."""
    c = undershoot * gain * gain
    a = (ratio - 1) * c
    if abs(a) < 1e-12:
        return 1 / gain
    return (-1 + sqrt(max(0.0, 1 + 4 * a / gain))) / (2 * a)


def undershoot_constant(ratio: float, gain: float, undershoot: float) -> float:
    """K2B(r) = 1/Kv - f(t_B) of (9), rising from 0 (a stop, r = 0) through K_B (r = 1)."""
    t = bisector_time(ratio, gain, undershoot)
    return 1 / gain - t + undershoot * gain * gain * t * t


def departing_feed(
    approach: float, turn: float, tolerance: float, gain: float, undershoot: float
) -> float:
    """F2 (IPM) from F1 and the allowed undershoot, E_u = 2 K2B(F2/F1) F1 sin(theta/2) (9),
    by bisection on r (K2B rises with r; the closed form is lost in the scan)."""
    half = sin(turn / 2)
    if approach <= 0 or half <= FLAT:
        return float("inf")
    wanted = tolerance / (2 * approach / PER_SECOND * half)
    if wanted >= 1 / gain:
        return float("inf")
    low, high = 0.0, 1.0
    while undershoot_constant(high, gain, undershoot) < wanted:
        low, high = high, 2 * high  # (K2B tends to 1/Kv: a ratio is found)
    for _ in range(60):
        middle = (low + high) / 2
        low, high = (
            (middle, high)
            if undershoot_constant(middle, gain, undershoot) < wanted
            else (low, middle)
        )
    return low * approach


def arc_feed_limit(tolerance: float, radius: float, circle: float) -> float:
    """(3): F = 60 Kc sqrt(E r), the feed at which the circle is oversize by E."""
    return PER_SECOND * circle * sqrt(tolerance * radius)


def slowdown_distance(
    approach: float, initial: float, settling: float, extra: float, overshoot: float
) -> float:
    """DO = max(Ts F1, k_ao K_o Fi) (001 L13748-13775)."""
    return max(settling * approach, extra * overshoot * initial) / PER_SECOND


def closed_loop_terms(crossover: float, breaks: tuple[float, ...]) -> tuple[float, ...]:
    """(11), (12): |C/R|^-2 = 1 + c2 x^2 + c4 x^4 + ... for x = w/wc, of the naked-system
    servo with its crossover wc and the higher breaks wi (001 L13961-14152): (c2, c4, ...).
    With s = p/wc the closed loop is 1 / P(s), P(s) = 1 + s prod(1 + s wc/wi)."""
    poly = [0.0, 1.0]
    for corner in breaks:
        ratio = crossover / corner
        poly = [a + ratio * b for a, b in zip([*poly, 0.0], [0.0, *poly], strict=True)]
    poly[0] = 1.0
    # P(jx): the even powers are the real part, the odd ones the imaginary part
    real = [p * (-1) ** (k // 2) if k % 2 == 0 else 0.0 for k, p in enumerate(poly)]
    imaginary = [p * (-1) ** (k // 2) if k % 2 else 0.0 for k, p in enumerate(poly)]
    squared = [0.0] * (2 * len(poly) - 1)
    for part in (real, imaginary):
        for i, a in enumerate(part):
            for j, b in enumerate(part):
                squared[i + j] += a * b
    return tuple(squared[2::2])


def crossover_phase_lag(crossover: float, breaks: tuple[float, ...]) -> float:
    """The phase lag (degrees) the higher breaks add at crossover; c2 = 0 makes it about
    1/2 radian, 28.6 degrees (001 L14120-14127)."""
    return degrees(sum(atan(crossover / corner) for corner in breaks))


def circle_error_constant(crossover: float, breaks: tuple[float, ...]) -> float:
    """(16): Kc = wc / sqrt(sum wc/wi - 1/2), for a servo with some overshoot (c2 < 0)."""
    excess = sum(crossover / corner for corner in breaks) - 0.5
    if excess <= 0:
        raise ValueError("c2 >= 0: the servo has no resonant peak, (16) does not apply")
    return crossover / sqrt(excess)
