"""Variable format by G code, option 41 (manual §4.8, 001 L16144-16269), on the Mark
Century 100M set-up the manual gives: TABLEG(11) = G10, REGFOR(X, Y, Z) = -14,
option 4 = 99.999."""

from __future__ import annotations

import pytest
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.output.format import FormatOverflow

from tests.test_post_linear import post

MARK_CENTURY_100M = """
[machine]
name = "mark-century-100m"
title = "100M VARIABLE FORMAT"
[tableg]
11 = 10
[regfor]
3 = -14.0
4 = -14.0
5 = -14.0
[optab]
4 = 99.999
41 = {option_41}
"""


def machine(option_41: str) -> MachineDefinition:
    return load_machine_text(MARK_CENTURY_100M.format(option_41=option_41), "100m.toml")


def punched(lines: list[str], option_41: str) -> list[str | None]:
    return [b.punch for b in post(lines, machine(option_41)).blocks if b.punch]


LONG_MOVES = ["FROM/0,0,0", "FEDRAT/10", "GOTO/40,40,40", "RAPID", "GOTO/100,100,100"]
CARRY = ["FROM/2.6789,0,0", "FEDRAT/10", "RAPID", "GOTO/23.7868,0,0", "GOTO/30.2367,0,0"]


def test_option_41_0_segments_feed_moves_and_sends_rapids_in_g10() -> None:
    """001 L16185-16199: statement 2 is five 8-inch departures in G01; the rapid to
    (100, 100, 100) is one G10 block of 60-inch departures (format 23)."""
    assert punched(LONG_MOVES, "0") == [
        "N003G01X+8Y+8Z+8F007",
        *["N003X+8Y+8Z+8"] * 4,
        "N005G10X+60Y+60Z+60F333",
    ]


def test_option_41_0_truncates_and_carries_the_lost_digit() -> None:
    """001 L16200-16245: A = 2.6789, B = 23.7868, C = 30.2367: the G10 departure 21.1079 is
    truncated to 21.107; the 0.0009 lost is carried, so B to C is 6.4508, not 6.4499, and
    2.6789 + 21.107 + 6.4508 = 30.2367 exactly."""
    assert punched(CARRY, "0") == ["N004G10X+21107F500", "N005G01X+64508F016"]


@pytest.mark.parametrize(
    ("option_41", "expected"),
    [
        ("-1", ["N004G10X+21108F500", "N005G01X+64499F016"]),  # format 23: rounded, lost
        ("-2", ["N004G10X+211079F500", "N005G01X+64499F016"]),  # format 24: exact
    ],
)
def test_option_41_negative_changes_the_format_without_correction(
    option_41: str, expected: list[str]
) -> None:
    """-1: long departures in format 23 for feed and rapid alike, no corrective action;
    -2: format 24 (001 L16255-16262)."""
    assert punched(CARRY, option_41) == expected
    assert punched(LONG_MOVES, option_41)[0] == "N003G10X+40Y+40Z+40F014"


def test_a_format_too_small_for_option_4_is_a_load_warning_and_stops_the_long_move() -> None:
    fixed = machine("1")
    assert any("holds at most 9.9999" in warning for warning in fixed.warnings)
    with pytest.raises(FormatOverflow, match=r"X40 does not fit register format -14"):
        post(LONG_MOVES, fixed)


LEADING_ZEROS = """
[machine]
name = "mark-century-100m-lzs"
title = "100M LEADING ZERO SUPPRESSION"
[tableg]
12 = 11
13 = 12
[regfor]
3 = -14.0
4 = -14.0
5 = -14.0
[optab]
51 = -2.0
"""


def test_option_51_minus_2_suppresses_leading_zeros_in_g11_and_g12() -> None:
    """§4.9 (001 L16270-16295): on the 100M, X/Y/Z in G11 blocks lose the zeros left of the
    point, in G12 one zero right of it too; G01 keeps them. Trailing zeros go as always."""
    machine = load_machine_text(LEADING_ZEROS, "100m-lzs.toml")
    program = [
        "FROM/0,0,0",
        "FEDRAT/1",
        "GOTO/0.5,0.25,0",  # G11
        "GOTO/0.5025,0.3,0",  # G12: 0.0025 and 0.05
        "GOTO/5.5025,0.3,0",  # G01
    ]
    result = post(program, machine)
    motion = [b for b in result.blocks if b.punch]
    assert [b.punch for b in motion] == [
        "N003G11X+5Y+25F002",
        "N004G12X+025Y+5",  # 0.0025 keeps its second zero; the F (002) is not repeated
        "N005G01X+5",
    ]
    assert dict(motion[1].words)[3] == "+0.0025"  # the listing keeps the digits
