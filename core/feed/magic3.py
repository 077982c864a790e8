"""EIA "magic three" feedrate code (manual appendix 7.1, 001 L40132-40174; EIACOM
L30854-30904).

Digits 2-3: the value rounded to two significant digits. Digit 1: 3 + the number of digits
left of the decimal point, or, with none, 3 - the number of zeros right after the point.
Valid for 0.0001 to 9999.
"""

from __future__ import annotations

from decimal import ROUND_HALF_UP, Decimal

SMALLEST = Decimal("0.0001")
LARGEST = Decimal("9999")


def magic3(value: float) -> int | None:
    """The code as a number (540 for 40 IPM, 46 for 0.000462, shown "046"); None when the
    value is outside 0.0001..9999 (the manual's comment case)."""
    number = Decimal(repr(abs(value)))
    if number == 0:
        return 0
    if not SMALLEST <= number <= LARGEST:
        return None
    exponent = number.adjusted()
    two = int(number.scaleb(1 - exponent).quantize(Decimal(1), ROUND_HALF_UP))
    if two == 100:  # 9.96 rounds to 10: the next decade
        two, exponent = 10, exponent + 1
    return (exponent + 4) * 100 + two


def decode(code: int) -> float:
    """The feed a magic-3 code stands for (540 -> 40.0, 46 -> 0.00046)."""
    return (code % 100) * 10.0 ** (code // 100 - 5)
