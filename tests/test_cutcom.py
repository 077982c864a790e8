"""CUTCOM (CTCMGB, 001 L30025-30060): the cutter-compensation G code in a block by itself
(CODE -4, L9241-9250), from TABLEG 40 off, 41 left, 42 right (L22628-22691), 46 plus and
47 minus. The Standard Machine has none of them (DMBITS)."""

from __future__ import annotations

import pytest
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.output.tape import tape_lines

from tests.test_post_linear import post

G_NOT_AVAILABLE = "REQUESTED PREPARATORY FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE"


def compensating() -> MachineDefinition:
    """The Standard Machine with a control's usual codes: G40/G41/G42, G45/G46."""
    text = '[machine]\nname = "cutcom"\ntitle = "CUTTER COMPENSATION"\n'
    text += "[tableg]\n40 = 40\n41 = 41\n42 = 42\n46 = 45\n47 = 46\n"
    return load_machine_text(text, "cutcom.toml")


def tape(lines: list[str], machine: MachineDefinition | None = None) -> list[str]:
    return tape_lines(post(lines, machine or compensating()).blocks)


@pytest.mark.parametrize(
    ("word", "line"),
    [("LEFT", "N001G41"), ("RIGHT", "N001G42"), ("OFF", "N001G40"), ("PLUS", "N001G45"),
     ("MINUS", "N001G46")],
)  # fmt: skip
def test_each_modifier_is_its_g_code_in_a_block_by_itself(word: str, line: str) -> None:
    """CUTCOM/word is TABLEG(40, 41, 42, 46 or 47) alone in its block; N is the CL record
    number (option 143 = 0), here record 1; G is two digits (REGFOR(2) = 20)."""
    assert tape([f"CUTCOM/{word}"]) == [line]


def test_a_repeated_cutcom_g_is_never_suppressed() -> None:
    """ "G codes in CODE = -4 blocks are never suppressed regardless of redundancy"
    (001 L9247-9248): CUTCOM/LEFT twice (records 3, 4) punches G41 twice. The motion after
    it repeats its G01 as after any non-motion G (records 2 and 5: X1 at 10 IPM, F = 10 x
    10 / 1 = 100 in format 3.0)."""
    program = ["FROM/0,0,0", "FEDRAT/10", "CUTCOM/LEFT", "CUTCOM/LEFT", "GOTO/1,0,0"]
    program += ["CUTCOM/OFF", "GOTO/2,0,0"]
    assert tape(program) == [
        "N003G41",
        "N004G41",
        "N005G01X+1F100",
        "N006G40",
        "N007G01X+1",  # F100 again is redundant (option 107), the G is not
    ]


def test_a_waiting_m_code_rides_in_the_cutcom_block() -> None:
    """COOLNT/ON's M08 waits for the next block output (STOREM, 001 L38041-38087): the CUTCOM
    block, record 2."""
    assert tape(["COOLNT/ON", "CUTCOM/RIGHT"]) == ["N002G42M08"]


def test_option_98_adds_its_momentary_dwell_f() -> None:
    """A CODE -4 block without an F gets option 98's F (001 L9243-9247): F5 in format 3.0 is
    F005; the G stays the CUTCOM code."""
    machine = compensating().with_options({98: 5.0})
    assert tape(["CUTCOM/LEFT"], machine) == ["N001G41F005"]


def test_a_code_the_machine_lacks_is_reported_and_nothing_is_output() -> None:
    """The Standard Machine has TABLEG(41) = DMBITS: the comment, no block."""
    result = post(["CUTCOM/LEFT"], standard_machine())
    assert tape_lines(result.blocks) == []
    assert [d.text for d in result.diagnostics] == [G_NOT_AVAILABLE]


@pytest.mark.parametrize(
    "statement",
    ["CUTCOM/ON", "CUTCOM/LEFT,RIGHT", "CUTCOM/OFF,1", "CUTCOM/3", "CUTCOM/LEFT,XYPLAN,YZPLAN"],
)
def test_other_forms_name_what_is_expected(statement: str) -> None:
    """The manual names no CUTCOM/ON (APT's "plus"?): it is refused, like any other form."""
    with pytest.raises(InputError, match="CUTCOM expects LEFT or RIGHT"):
        post([statement], compensating())


def test_apt_iv_plane_and_offset_number_are_read() -> None:
    """CUTCOM/LEFT,XYPLAN,1 (APT IV, NX): the plane is the one the arcs name; the offset
    number is a modern control's D (option 263), which this machine has not."""
    result = post(["CUTCOM/LEFT,XYPLAN,1"], compensating())
    assert tape_lines(result.blocks) == tape_lines(post(["CUTCOM/LEFT"], compensating()).blocks)
