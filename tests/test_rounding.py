"""half_up_float: the float shortcut of the exact half-up rounding agrees with Decimal."""

from __future__ import annotations

import pytest
from gecent.core.motion.rounding import half_up, half_up_float
from hypothesis import given, settings
from hypothesis import strategies as st


@settings(max_examples=3000, deadline=None)
@given(
    value=st.one_of(
        st.floats(0, 1e7, allow_nan=False),
        st.integers(0, 10**8).map(lambda n: n / 1000 + 0.0005),  # ties at 3 decimals
        st.integers(0, 10**8).map(lambda n: n / 100 + 0.005),
        st.floats(-1e3, 1e13, allow_nan=False),
    ),
    decimals=st.integers(0, 6),
)
def test_half_up_float_is_half_up(value: float, decimals: int) -> None:
    assert half_up_float(value, decimals) == float(half_up(value, decimals))


@pytest.mark.parametrize(
    ("value", "decimals", "expected"),
    [(2.5, 0, 3.0), (0.125, 2, 0.13), (1.0005, 3, 1.001), (2.675, 2, 2.68), (0.0, 3, 0.0)],
)
def test_half_up_float_rounds_halves_up(value: float, decimals: int, expected: float) -> None:
    """2.675 is 2.67499999... in binary, but its decimal form is what the manual rounds."""
    assert half_up_float(value, decimals) == expected
