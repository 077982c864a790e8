"""Rounding CL values to the machine step (SRAREC/SROREC, manual §3.4.1, 001 L3946-4006).

Machine positions are kept as whole numbers of steps, so that the manual's values (22.2469
at a 0.0001 step) are exact and departures never drift: a departure is the difference of two
integers, and the half-step zero test of GOLINE (001 L4268-4290) is "the difference is 0".
"""

from __future__ import annotations

from decimal import ROUND_HALF_UP, Decimal

ROUND_UP_FROM = 0.5001  # printed "0.50010" (L4000) and "0.5001" (L5505): 0.4999 step rounds up
ROUND_UP_NUMERATOR, ROUND_UP_DENOMINATOR = 5001, 10000  # the same, for exact arithmetic


def to_steps(value: float, step: float) -> int:
    """``value`` as a signed whole number of steps: sign(v) * int(|v| / step + 0.5001)."""
    count = int(abs(value) / step + ROUND_UP_FROM)
    return -count if value < 0 else count


def round_to_step(value: float, step: float) -> float:
    """SRAREC: ``value`` rounded to the step, as a number of the machine's units."""
    return to_steps(value, step) * step


def half_up(value: float, decimals: int) -> Decimal:
    """``value`` rounded half-up to ``decimals`` places, exactly (Python's round() is
    half-even): register formats and feed commands round so."""
    return Decimal(repr(value)).quantize(Decimal(1).scaleb(-decimals), ROUND_HALF_UP)


# a scaled value within this of a half is left to Decimal; elsewhere float decides alike
_TIE_MARGIN = 1e-4
_FLOAT_EXACT = 1e11  # below this, x * 10**d errs by far less than the margin


def half_up_float(value: float, decimals: int) -> float:
    """``float(half_up(value, decimals))``, without Decimal where float arithmetic decides
    the same (away from a half, for values whose scaled size float holds exactly enough);
    ``tests/test_rounding.py`` checks the two agree."""
    if value >= 0.0:
        power: int = 10**decimals
        scaled = value * power
        if scaled < _FLOAT_EXACT:
            whole = int(scaled)
            fraction = scaled - whole
            if abs(fraction - 0.5) > _TIE_MARGIN:
                return (whole + (1 if fraction > 0.5 else 0)) / power
    return float(half_up(value, decimals))
