"""Automatic reinstatement after STOP/OPSTOP (option 145; manual §4.7, 001 L16024-16143,
RESTAT L35498-35573, ENTRAP L30953-30990)."""

from __future__ import annotations

from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import standard_machine
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post

BEFORE = [
    "TOOLNO/3",
    "SPINDL/200,CLW",
    "COOLNT/ON",
    "FROM/0,0,0",
    "FEDRAT/10",
    "GOTO/1,0,0",
    "STOP",
]
HEAD = ["N001G04X+05T03", "N002S620M03", "N004M08", "N006G01X+1F100", "N007M00"]


def tape(lines: list[str], machine: MachineDefinition) -> list[str]:
    return tape_lines(post(lines, machine).blocks)


def reinstating() -> MachineDefinition:
    return standard_machine().with_options({145: 1.0})


def test_without_reinstatement_the_programmer_restarts_everything() -> None:
    assert tape([*BEFORE, "GOTO/2,0,0"], standard_machine()) == [*HEAD, "N008X+1"]


def test_tool_spindle_and_coolant_come_back_at_the_next_motion() -> None:
    """Option 145 = +1: T in a block, S with M03 in a block, M08 in the motion block."""
    assert tape([*BEFORE, "GOTO/2,0,0"], reinstating()) == [
        *HEAD,
        "N008T03",
        "N008S620M03",
        "N008X+1M08",
    ]


def test_a_condition_given_again_after_the_stop_is_not_repeated() -> None:
    """SPINDL/100 after the stop was output when given; RESTAT skips the spindle and
    still brings back the tool and the coolant."""
    assert tape([*BEFORE, "SPINDL/100", "GOTO/2,0,0"], reinstating()) == [
        *HEAD,
        "N008S610M03",
        "N009T03",
        "N009X+1M08",
    ]


def test_mach04_waits_in_rapid_gear_after_a_stop() -> None:
    """MACH04, option 145 = -2: ENTRAP puts M40 (rapid gear) after the stop; the first feed
    move shifts back with M41; a RAPID right after the stop goes in that gear."""
    lathe = get_plugins().machine("mach04").load()
    program = ["FROM/0,0,0", "FEDRAT/10", "GOTO/1,-1,0", "STOP"]
    assert tape([*program, "GOTO/2,-1,0"], lathe) == [
        "N003G01X+1Z+1F07071",
        "N004G04M00",
        "N005G04M40",
        "N005G01Z+1F100M41",
    ]
    assert tape([*program, "RAPID", "GOTO/2,-1,0", "GOTO/3,-1,0"], lathe)[2:] == [
        "N006G01Z+1F750M40",
        "N007G01Z+1F100M41",
    ]
