"""Golden tests: register formatting (CONBCD) with the manual's own examples."""

from __future__ import annotations

import pytest
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.machine.regformat import decode_regfor
from gecent.core.motion.rounding import half_up
from gecent.core.output.block import Block, Code
from gecent.core.output.element import OutputElement
from gecent.core.output.format import FormatOverflow, RegisterFormatter, _units
from gecent.core.state import PostState
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


def _dwell_punch(seconds: float, optab: dict[int, float], regfor: float) -> str:

    text = '[machine]\nname = "dwell"\ntitle = "DWELL"\n[regfor]\n3 = ' + f"{regfor}\n"
    text += "[optab]\n" + "".join(f"{k} = {v}\n" for k, v in optab.items())
    element = OutputElement(PostState(load_machine_text(text, "dwell.toml")))
    element.emit = [].append
    block = element.dwell(seconds)
    block.record = 7
    element.output(block)
    assert block.punch is not None
    return block.punch


@pytest.mark.parametrize(
    ("seconds", "optab", "regfor", "expected"),
    [
        (4.0, {56: 10.0, 57: 3.0}, 14.0, "N007G04X04"),  # DW-1 (001 L16305-16330)
        (42.0, {56: 10.0, 57: 3.0}, 14.0, "N007G04X42"),  # O56a (001 L25116-25121)
        (15.0, {56: 0.01, 57: 3.0}, 44.0, "N007G04X1500"),  # O56b (001 L25122-25128)
    ],
)
def test_dwell_value_goes_in_the_option_57_register_over_option_56(
    seconds: float, optab: dict[int, float], regfor: float, expected: str
) -> None:
    """A dwell of s seconds is s / option 56 in the option-57 register: 4 s is X04 (not
    X4), 42 s reads X42 like a 4.2 in move, 15 s with option 56 = 0.01 is X1500."""
    assert _dwell_punch(seconds, optab, regfor) == expected


def test_w14_sequence_numbers_wrap_at_seqlim() -> None:
    """W14 (001 L9117-9126): REGFOR(1) = 30 holds 999; N 1000 is 1000 mod 999 = 1."""

    element = OutputElement(PostState(standard_machine()))
    emitted: list[Block] = []
    element.emit = emitted.append
    for record in (999, 1000, 2000):
        element.output(Block(Code.AUX_ONLY, record))
    assert [b.punch for b in emitted] == ["N999", "N001", "N002"]


def _digit_by_digit(
    formatter: RegisterFormatter, units: int, negative: bool, leading: int | None
) -> tuple[str, str]:
    """The register word as the manual builds it, digit string by digit string: the
    oracle for the formatter's arithmetic (001 L24057-24062, L16270-16295)."""
    fmt = formatter.fmt
    if formatter.bare:
        if len(str(units)) > fmt.left and units:
            raise FormatOverflow(formatter.letter, float(units), fmt)
        text = ("-" if negative and units else "") + str(units)
        return text, text
    if formatter.decimal:
        whole_units, fraction_units = divmod(units, 10**fmt.right)
        if len(str(whole_units)) > fmt.left and whole_units:
            raise FormatOverflow(formatter.letter, float(units), fmt)
        shown = str(fraction_units).rjust(fmt.right, "0").rstrip("0")
        text = ("-" if negative and units else "") + f"{whole_units}.{shown}"
        return text, text
    digits = str(units).rjust(fmt.right + 1, "0")
    whole, fraction = digits[: len(digits) - fmt.right], digits[len(digits) - fmt.right :]
    whole = whole.lstrip("0")
    if len(whole) > fmt.left:
        raise FormatOverflow(formatter.letter, float(units), fmt)
    whole = whole.rjust(fmt.left, "0")
    shown = fraction.rstrip("0").ljust(fmt.right) if formatter.drop_trailing else fraction
    sign = ("-" if negative and units else "+") if fmt.signed else ""
    printed = sign + whole + ("." if formatter.point else "") + shown
    punched = (sign + whole + shown).replace(" ", "")
    if leading is not None:
        first, kept = whole.lstrip("0"), shown.replace(" ", "")
        if not first and kept.startswith("0" * leading):
            kept = kept[leading:]
        punched = sign + first + kept
    if punched.strip("+-") == "":
        punched = sign + "0"
    return printed, punched


@settings(max_examples=600, deadline=None)
@given(
    regfor=st.sampled_from([10.0, 20.0, 30.0, -24.0, 24.0, -53.0, 53.0, -44.0, 4.0, -4.0, 43.0]),
    units=st.one_of(st.integers(0, 10**8), st.sampled_from([0, 1, 9, 10, 99, 100, 9999, 10000])),
    negative=st.booleans(),
    drop=st.booleans(),
    decimal=st.booleans(),
    location=st.sampled_from([1, 2, 3, 11]),
    leading=st.sampled_from([None, 0, 1]),
)
def test_register_words_are_the_digit_by_digit_words(
    regfor: float,
    units: int,
    negative: bool,
    drop: bool,
    decimal: bool,
    location: int,
    leading: int | None,
) -> None:
    """Every register format's word, overflow included, as the digit strings give it."""
    fmt = decode_regfor(regfor)
    assert fmt is not None
    formatter = RegisterFormatter(location, "X", fmt, drop_trailing=drop, decimal=decimal)
    if formatter.modern:
        leading = None  # the 100M's rule is for its fixed-digit words
    try:
        expected = _digit_by_digit(formatter, units, negative, leading)
    except FormatOverflow:
        with pytest.raises(FormatOverflow):
            formatter.texts(units, negative, None, leading)
        return
    assert formatter.texts(units, negative, None, leading) == expected
