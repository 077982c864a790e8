"""Golden tests: register formatting (CONBCD) with the manual's own examples."""

from __future__ import annotations

import pytest
from gecent.core.machine.regformat import decode_regfor
from gecent.core.motion.rounding import half_up
from gecent.core.output.format import FormatOverflow, RegisterFormatter, _units
from hypothesis import given, settings
from hypothesis import strategies as st


def formatter(location: int, letter: str, regfor: float, drop: bool = True) -> RegisterFormatter:
    fmt = decode_regfor(regfor)
    assert fmt is not None
    return RegisterFormatter(location, letter, fmt, drop_trailing=drop)


@pytest.mark.parametrize(
    ("location", "letter", "regfor", "drop", "value", "printed", "punched"),
    [
        # 001 L8838-8841: X -3.2468 in format -24 prints -03.2468, punches X-032468
        (3, "X", -24, False, -3.2468, "-03.2468", "-032468"),
        # 001 L16325-16329: a 0.4 s dwell in format 14 punches G04X04
        (3, "X", 14, True, 0.4, "0.4   ", "04"),
        # 001 L16347-16353: F 1.5 in format 31 punches F0015
        (11, "F", 31, True, 1.5, "001.5", "0015"),
        # 001 L11166-11171: F 8.76 in format 32 punches F00876
        (11, "F", 32, True, 8.76, "008.76", "00876"),
        # 001 L25122-25128: 15 / 0.01 = 1500 in format 44 punches X1500
        (3, "X", 44, True, 1500.0, "1500.    ", "1500"),
        # 4.2 in format 14 punches 42
        (3, "X", 14, True, 4.2, "4.2   ", "42"),
        # sequence number 240 in format 30 (001 L886)
        (1, "N", 30, True, 240, "240", "240"),
        (1, "N", 30, True, 40, "040", "040"),
        (2, "G", 20, True, 1, "01", "01"),
    ],
)
def test_manual_format_examples(
    location: int,
    letter: str,
    regfor: float,
    drop: bool,
    value: float,
    printed: str,
    punched: str,
) -> None:
    result = formatter(location, letter, regfor, drop).format(value)
    assert (result.printed, result.punched) == (printed, punched)


def test_signed_registers_show_plus_and_drop_trailing_zeros_on_contouring() -> None:
    x = formatter(3, "X", -14)
    assert x.format(3.3334).punched == "+33334"
    assert x.format(8.0).printed == "+8.    " and x.format(8.0).punched == "+8"
    assert x.format(-0.0001).punched == "-00001"
    assert x.format(3.3333000000000004).punched == "+33333"  # a step count times STEP
    assert x.format(-0.00001).punched == "+0"  # rounds to zero: no minus sign


def test_positioning_keeps_trailing_zeros() -> None:
    assert formatter(3, "X", -24, drop=False).format(8.0).punched == "+080000"


def test_overflow_is_refused() -> None:
    with pytest.raises(FormatOverflow, match=r"does not fit register format -14"):
        formatter(3, "X", -14).format(10.0)


@settings(max_examples=500, deadline=None)
@given(
    st.one_of(
        st.integers(min_value=0, max_value=10**7).map(lambda n: n * 0.0001),
        st.floats(min_value=0, max_value=9999, allow_nan=False),
        st.integers(min_value=0, max_value=10**6).map(lambda n: n / 1000 + 0.0005),
    ),
    st.integers(min_value=0, max_value=5),
)
def test_fast_rounding_agrees_with_exact_half_up(value: float, decimals: int) -> None:
    """Values on the step grid take a float path; it must give what Decimal half-up gives."""
    assert _units(value, decimals) == int(half_up(value, decimals).scaleb(decimals))
