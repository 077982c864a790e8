"""REGFOR decoding (WE-2) and the option 59/60 axis shuffle (WE-8)."""

from __future__ import annotations

import pytest
from gecent.core.machine.regformat import RegisterFormat, decode_regfor
from gecent.core.machine.shuffle import decode_shuffle, describe_shuffle


@pytest.mark.parametrize(
    ("regfor", "signed", "left", "right"),
    [
        (-14.0, True, 1, 4),
        (20.0, False, 2, 0),
        (30.0, False, 3, 0),
        (-24.0, True, 2, 4),
        (-23.0, True, 2, 3),
        (40.0, False, 4, 0),
    ],
)
def test_regfor_we2(regfor: float, signed: bool, left: int, right: int) -> None:
    fmt = decode_regfor(regfor)
    assert fmt == RegisterFormat(signed, left, right)
    assert fmt.regfor == regfor and fmt.digits == left + right


def test_regfor_zero_is_no_register_and_fractions_are_rejected() -> None:
    assert decode_regfor(0.0) is None
    with pytest.raises(ValueError):
        decode_regfor(-14.5)


@pytest.mark.parametrize(
    ("value", "axes", "expected"),
    [
        (131415, "XYZ", "+X+Y+Z"),
        (132415, "XYZ", "+X-Y+Z"),
        (152300, "XYZ", "+Z-X"),
        (131500, "XYZ", "+X+Z"),
        (161718, "IJK", "+I+J+K"),
        (181600, "IJK", "+K+I"),
        (161800, "IJK", "+I+K"),
        (141500, "XYZ", "+Y+Z"),
    ],
)
def test_shuffle_we8(value: int, axes: str, expected: str) -> None:
    assert describe_shuffle(decode_shuffle(value, axes)) == expected


def test_shuffle_drops_blank_groups() -> None:
    targets = decode_shuffle(152300, "XYZ")
    assert targets[2] is None and targets[1] is not None and targets[1].sign == -1


@pytest.mark.parametrize("value", [191415, 131313, 331415, 1314150, 13141.5])
def test_bad_shuffle_is_rejected(value: float) -> None:
    with pytest.raises(ValueError):
        decode_shuffle(value, "XYZ")
