"""Tools on a lathe: TOOLNO (TOOLL) and TURRET (COMTAT's option-96 T word, MINMOV's shorter
way) on the sample lathe MACH04 (TABLEM(7) = M06, option 83 = 2 s of dwell in Z, T format
50, option 96 = 2), 001 L38694-38799, L39054-39091, L29715-29760, L34013-34055,
L25520-25569."""

from __future__ import annotations

import pytest
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post


def lathe() -> MachineDefinition:
    return get_plugins().machine("mach04").load()


def punched(lines: list[str], machine: MachineDefinition | None = None) -> list[str]:
    return [b.punch for b in post(lines, machine or lathe()).blocks if b.punch]


def test_toolno_on_the_lathe_is_a_dwell_block_with_t_and_the_tool_change_m() -> None:
    """TOOLL: M06 waits (STOREM) and rides in the option-83 dwell block (2 s / option 56 =
    10 -> Z+02 in MACH04's dwell register) that carries the T word."""
    assert punched(["TOOLNO/3"]) == ["N001G04Z+02T00003M06"]


def test_toolno_ofsetl_appends_the_two_offset_digits() -> None:
    assert punched(["TOOLNO/3,OFSETL,12"]) == ["N001G04Z+02T00312M06"]


def test_turret_packs_offset_tool_and_position_by_option_96_type_2() -> None:
    """Option 96 = 2: offset (2 digits), tool (2), turret position (1): TURRET/4, OFSETL, 3
    -> 03 04 4; TURRET/12, 3 -> 00 12 3. MACH04 has no turret-index M (TABLEM(8)), as the
    manual's sample notes ("NO M-CODE WILL BE AVAILABLE FOR TURRET")."""
    assert punched(["TURRET/4,OFSETL,3", "TURRET/12,3"]) == [
        "N001G04Z+02T03044",
        "N002G04Z+02T00123",
    ]


@pytest.mark.parametrize(
    ("layout", "expected"),
    [(0, "T00007"), (3, "T00073"), (4, "T00075"), (5, "T00057"), (6, "T00573")],
)
def test_option_96_layouts(layout: int, expected: str) -> None:
    """Tool 7, turret position 3, offset 5 in each legible layout (001 L25538-25556)."""
    machine = lathe().with_options({96: float(layout)})
    (line,) = punched(["TURRET/7,3,OFSETL,5"], machine)
    assert line == f"N001G04Z+02{expected}"


INDEXING_TURRET = """
[machine]
name = "turret8"
[optab]
88 = -8.0
[tablem]
8 = 70
29 = 71
30 = 72
83 = 73
84 = 74
"""


def test_turret_turns_the_shorter_way_with_its_m_codes() -> None:
    """Option 88 = -8: eight stations turned by M codes; 1 -> 7 is 2 stations CCLW (M74),
    7 -> 3 is 4 stations, half a turn, CLW (M73, "at most 180 degrees"); the index M
    (TABLEM 8 = M70) goes out first, in its own block, when a second M code follows
    (STOREM); option 38 = 1 puts G04 in every block without a G."""
    machine = load_machine_text(INDEXING_TURRET, base=lathe())
    assert punched(["TURRET/1", "TURRET/7", "TURRET/3,REAR,CLW"], machine) == [
        "N001G04Z+02T00011M70",
        "N002G04M70",
        "N002G04Z+02T00077M74",
        "N003G04M72",
        "N003G04M70",
        "N003G04Z+02T00033M73",
    ]


def test_toolno_with_an_unavailable_direction_code_warns() -> None:
    result = post(["TOOLNO/2,CLW"], lathe())
    assert [d.text for d in result.diagnostics] == [
        "REQUESTED MISCELLANEOUS FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE"
    ]
    assert [b.punch for b in result.blocks if b.punch] == ["N001G04Z+02T00002M06"]


@pytest.mark.parametrize(
    ("line", "error", "message"),
    [
        ("TURRET/4,NOW", InputError, "TURRET"),  # NOW needs the tool's a, b (issue 22)
        ("TURRET/123", InputError, "does not fit the 2 digit"),
        ("TOOLNO/2.5", InputError, "whole numbers"),
        ("TOOLNO/2,OFSETL", InputError, "expects an offset number"),
        ("TOOLNO/2,FRONT", InputError, "does not take FRONT"),
    ],
)
def test_bad_or_unbuilt_tool_statements(line: str, error: type, message: str) -> None:
    with pytest.raises(error, match=message):
        post([line], lathe())
