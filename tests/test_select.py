"""SELECT (SLCTGB, 001 L36895-36925): FEDOVR (L31066-31100), PALLET and READER (SELPAL,
SELRDR, L37184-37248), each an M code in a block by itself; the other minor words are not
built yet."""

from __future__ import annotations

import pytest
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post

NOT_AVAILABLE = "REQUESTED MISCELLANEOUS FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE"


def overriding() -> MachineDefinition:
    """The Standard Machine with feedrate override codes: TABLEM(112) = 48 (the code FEDOVR
    outputs for ON) and TABLEM(111) = 49 (for OFF)."""
    text = '[machine]\nname = "fedovr"\ntitle = "FEED OVERRIDE"\n[tablem]\n111 = 49\n112 = 48\n'
    return load_machine_text(text, "fedovr.toml")


def tape(lines: list[str], machine: MachineDefinition) -> list[str]:
    return tape_lines(post(lines, machine).blocks)


def test_feed_override_on_and_off() -> None:
    """FEDOVR: "If ON is given, TABLEM(112) is output. If OFF is given, TABLEM(111) is
    output", in a block by itself (001 L31086-31096): records 1 and 2 give N001M48 and
    N002M49 (M in format 2.0)."""
    assert tape(["SELECT/FEDOVR,ON", "SELECT/FEDOVR,OFF"], overriding()) == ["N001M48", "N002M49"]


def test_a_waiting_m_code_goes_out_first() -> None:
    """STOREM (001 L38041-38087): COOLNT/ON's M08 waits; FEDOVR's code pushes it out in a
    block of its own, then goes out in its own block (both N002, the SELECT's record)."""
    assert tape(["COOLNT/ON", "SELECT/FEDOVR,ON"], overriding()) == ["N002M08", "N002M48"]


def test_pallet_and_reader_on_mach40() -> None:
    """MACH40 sets TABLEM(13) = 36 (pallet select change) and TABLEM(14) = 37 (switch reader)
    (001 L27919-27920, TABLEM chart L23103-23105): each in a block by itself, N = records
    1 and 2. The number names the pallet or reader; the machine has one code for each."""
    mach40 = get_plugins().machine("mach40").load()
    assert tape(["SELECT/PALLET,2", "SELECT/READER,1"], mach40) == ["N001M36", "N002M37"]
    assert tape(["SELECT/PALLET", "SELECT/READER"], mach40) == ["N001M36", "N002M37"]


@pytest.mark.parametrize("statement", ["SELECT/FEDOVR,ON", "SELECT/PALLET,1", "SELECT/READER,1"])
def test_a_code_the_machine_lacks_is_comment_22(statement: str) -> None:
    """The Standard Machine has TABLEM 13, 14, 111 and 112 = DMBITS: comment 22, no block."""
    result = post([statement], standard_machine())
    assert tape_lines(result.blocks) == []
    assert [d.text for d in result.diagnostics] == [NOT_AVAILABLE]


@pytest.mark.parametrize(
    ("statement", "feature"),
    [
        ("SELECT/SADDLE", "SELECT/SADDLE: SELECT takes one of"),
    ],
)
def test_minors_select_does_not_take_are_bad_input(statement: str, feature: str) -> None:
    # issue 22: SELECT calls the routine its minor word names (001 L36895-36925); SADDLE
    # is reached through SELECT/HED,SADDLE (tests/test_statement_forms.py), so SELECT/SADDLE
    # is bad input, no longer "not yet supported"
    with pytest.raises(InputError, match=feature):
        post([statement], overriding())


@pytest.mark.parametrize(
    ("statement", "message"),
    [
        ("SELECT/FEDOVR", "SELECT/FEDOVR expects ON or OFF"),
        ("SELECT/FEDOVR,LEFT", "SELECT/FEDOVR expects ON or OFF"),
        ("SELECT/PALLET,0", "SELECT/PALLET expects a pallet number"),
        ("SELECT/READER,1.5", "SELECT/READER expects a reader number"),
        ("SELECT/PALLET,1,2", "SELECT/PALLET expects a pallet number"),
        ("SELECT/3", "SELECT expects a minor word first"),
        ("SELECT/HEAD,2", "COMBIN/2 must come first"),
        ("SELECT/HED,2", "COMBIN/2 must come first"),
    ],
)
def test_bad_forms_name_what_is_expected(statement: str, message: str) -> None:
    with pytest.raises(InputError, match=message):
        post([statement], overriding())
