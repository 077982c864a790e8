"""SPINDL (spindle type 1), LOADTL/TOOLNO on a mill, and feeds per revolution, on the
Standard Machine (S format 30, T format 20) and the sample mill MACH23 (no S, no T
register); readings in docs/research/spindle-tool.md, decisions in docs/decisions.md."""

from __future__ import annotations

import pytest
from gecent.core.errors import InputError
from gecent.core.feed.magic3 import magic3
from gecent.core.machine.definition import MachineDefinition
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post


def punched(lines: list[str], machine: MachineDefinition | None = None) -> list[str | None]:
    return [b.punch for b in post(lines, machine).blocks if b.punch]


def comments(lines: list[str], machine: MachineDefinition | None = None) -> list[str]:
    return [d.text for d in post(lines, machine).diagnostics]


def mach23() -> MachineDefinition:
    return get_plugins().machine("mach23").load()


def test_type_1_codes_are_magic_three_of_the_speed() -> None:
    """§4.5.2 (001 L14642-14643): 137.2 RPM -> 614, 0.0123 -> 212; 40 RPM -> 540 (L16086)."""
    assert (magic3(137.2), magic3(0.0123), magic3(40)) == (614, 212, 540)
    assert punched(["SPINDL/137.2,CLW"]) == ["N001S614M03"]


def test_spindle_block_starts_changes_and_reverses() -> None:
    """The direction M goes out when the spindle starts or reverses; a new speed alone is
    an S block; OFF is TABLEM(6) in a block of its own; ON restarts at the last speed."""
    lines = ["SPINDL/250,CLW", "SPINDL/300", "SPINDL/300,CCLW", "SPINDL/OFF", "SPINDL/ON"]
    assert punched(lines) == ["N001S625M03", "N002S630", "N003S630M04", "N004M05", "N005S630M04"]
    assert comments(lines) == ["WARNING--SPINDLE DIRECTION HAS CHANGED"]


def test_speeds_outside_the_table_take_the_nearest_listed_speed() -> None:
    """The Standard Machine's table is 1..300 RPM (001 L26914-26916, L14588-14590)."""
    lines = ["SPINDL/RPM,15915.507752,CLW", "SPINDL/.5", "SPINDL/10,RPM,RANGE,2"]
    assert punched(lines) == ["N001S630M03", "N002S410", "N003S510"]
    assert comments(lines) == [
        "SPINDLE SPEED COULD NOT BE FOUND.",
        "LOWEST SPEED IN RANGE IS OUTPUT.",
        "RANGE REQUESTED IS NOT AVAILABLE, USE HIGHEST",
    ]


def test_no_speed_ever_given_assumes_option_27() -> None:
    assert punched(["SPINDL/CLW"]) == ["N001S580M03"]  # 80 RPM
    assert comments(["SPINDL/CLW"]) == ["OPTION VALUE IS ASSUMED FOR THE SPINDLE SPEED"]


def test_mach23_has_no_s_register_so_only_the_m_codes_go_out() -> None:
    """MACH23 (REGFOR(12) = REGFOR(13) = 0, option 38 = 1): Creo's LOADTL/1 outputs
    nothing, SPINDL/RPM,15915.5,CLW is G04 M03 and SPINDL/OFF G04 M05, without comments."""
    lines = ["LOADTL/1", "SPINDL/RPM,15915.5,CLW", "SPINDL/OFF"]
    assert punched(lines, mach23()) == ["N002G04M03", "N003G04M05"]
    assert comments(lines, mach23()) == []


def test_tool_change_on_a_mill_with_a_t_register_is_a_dwell_block() -> None:
    """TOOLGM: option 83 (5 s) in the option-57 register (X) over option 56 (10)."""
    assert punched(["TOOLNO/1", "LOADTL/12"]) == ["N001G04X+05T01", "N002G04X+05T12"]


@pytest.mark.parametrize(
    ("statement", "error"),
    [
        ("LOADTL/1.5", InputError),
        ("SPINDL/100,200", InputError),
        ("SPINDL/OFF,100", InputError),
        ("SPINDL/100,RANGE", InputError),
    ],
)
def test_unbuilt_and_malformed_forms(statement: str, error: type[Exception]) -> None:
    with pytest.raises(error):
        post([statement])


def test_feed_per_revolution_follows_the_spindle_speed() -> None:
    """FEDIPM = FEDIPR x RPM (001 L31113-31212): 0.01 IPR at 100 RPM is 1 IPM (F = 10 x 1 /
    1 in), at 200 RPM 2 IPM; a bare FEDRAT keeps the per-revolution mode."""
    lines = [
        "SPINDL/100,CLW",
        "FROM/0,0,0",
        "FEDRAT/0.01,IPR",
        "GOTO/1,0,0",
        "SPINDL/200",
        "GOTO/2,0,0",
        "FEDRAT/0.02",
        "GOTO/3,0,0",
        "FEDRAT/30,IPM",
        "GOTO/4,0,0",
    ]
    assert punched(lines) == [
        "N001S610M03",
        "N004G01X+1F010",
        "N005S620",
        "N006X+1F020",
        "N008X+1F040",
        "N010X+1F300",
    ]


def test_feed_per_revolution_without_a_speed_assumes_option_27() -> None:
    lines = ["FEDRAT/0.1,IPR", "FROM/0,0,0", "GOTO/1,0,0"]
    assert punched(lines) == ["N003G01X+1F080"]  # 0.1 x 80 RPM
    assert comments(lines) == ["NO SPINDLE SPEED GIVEN FOR IPR MODE."]
