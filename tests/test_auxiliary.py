"""COOLNT, STOP, OPSTOP, END, REWIND, AUXFUN, PREFUN, CLAMP, SEQNO, TRANS, ORIGIN and words
the manual does not know (worked examples of docs/research/statements-misc.md §17)."""

from __future__ import annotations

import pytest
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.output.block import Code
from gecent.core.output.punch import punch, unpunch
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post

NOT_AVAILABLE = "REQUESTED MISCELLANEOUS FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE"


def tape(lines: list[str], machine: MachineDefinition | None = None) -> list[str]:
    return tape_lines(post(lines, machine).blocks)


def comments(lines: list[str], machine: MachineDefinition | None = None) -> list[str]:
    return [d.text for d in post(lines, machine).diagnostics]


def machine(name: str) -> MachineDefinition:
    return get_plugins().machine(name).load()


def test_stop_is_m00_in_a_block_by_itself() -> None:
    assert tape(["STOP"]) == ["N001M00"]


def test_a_waiting_coolant_code_goes_out_before_the_stop() -> None:
    """STOREM: COOLNT/OFF's M09 waits; STOP's M00 pushes it out in a block of its own."""
    assert tape(["COOLNT/OFF", "STOP"]) == ["N002M09", "N002M00"]


def test_mach23_opstop_gets_the_dwell_g_of_option_38() -> None:
    assert tape(["OPSTOP"], machine("mach23")) == ["N001G04M01"]


def test_auxfun_is_its_own_block_or_rides_along_under_option_75() -> None:
    assert tape(["AUXFUN/13"]) == ["N001M13"]
    merged = standard_machine().with_options({75: 1.0})
    program = ["AUXFUN/13", "FROM/0,0,0", "FEDRAT/10", "GOTO/1,0,0"]
    assert tape(program, merged) == ["N002M13", "N004G01X+1F100"]  # FROM forces it out


def test_prefun_is_a_g_code_by_itself() -> None:
    assert tape(["PREFUN/90"]) == ["N001G90"]


def test_coolant_rides_in_the_next_block() -> None:
    assert tape(["COOLNT/ON", "FROM/0,0,0", "FEDRAT/10", "GOTO/1,0,0"]) == [
        "N002M08",  # FROM never reaches the tape: the waiting M08 is forced out there
        "N004G01X+1F100",
    ]
    assert tape(["FROM/0,0,0", "FEDRAT/10", "COOLNT/ON", "GOTO/1,0,0"]) == ["N004G01X+1F100M08"]


def test_a_coolant_mode_without_its_code_falls_back_to_m08() -> None:
    assert tape(["COOLNT/FLOOD", "STOP"]) == ["N002M08", "N002M00"]


def test_end_on_the_standard_machine_and_its_filler_card() -> None:
    """M02 in a CODE +5 block, then option 11 = +1: one card (72 frames) of the space code."""
    lines = tape(["END"])
    assert lines == ["N001M02", "(" * 72]
    assert punch(lines, "eia")[-72:] == b"\x10" * 72


def test_mach23_end_has_no_code_and_a_blank_filler_card() -> None:
    """MACH23: TABLEM(3) absent (comment 22), option 11 = 0: a blank card, 72 frames of
    blank tape, shown as an empty line of the tape image."""
    lines = tape(["END"], machine("mach23"))
    assert lines == [""]
    assert punch(lines, "eia") == b"\x00" * 72
    assert unpunch(punch(lines, "eia"), "eia") == lines
    assert comments(["END"], machine("mach23")) == [NOT_AVAILABLE]


def test_mach04_end_dwells_with_t0_first() -> None:
    """Option 97 = 2 s: a dwell (Z, over option 56) with a zero T code before M02."""
    assert tape(["END"], machine("mach04")) == ["N001G04Z+02T00000", "N001G04M02", "(" * 72]


def test_motion_after_end_without_from_is_commented() -> None:
    assert comments(["FROM/0,0,0", "FEDRAT/10", "END", "GOTO/1,1,0"])[0] == (
        "END OR RESET HAS NOT BEEN FOLLOWED BY A FROM POINT."
    )


def test_rewind_and_clamp() -> None:
    assert tape(["REWIND/1"]) == ["N001M30"]
    assert comments(["CLAMP/XAXIS,ON"]) == [NOT_AVAILABLE]
    mach40 = machine("mach40")
    assert tape(["CLAMP/ON", "STOP"], mach40)[0].endswith("M10")


def test_seqno_numbers_the_blocks_that_follow() -> None:
    """SEQNO/10,INCR,5: 10, 15, ...; OFF drops N; ON resumes the series."""
    program = [
        "SEQNO/10,INCR,5",
        "FROM/0,0,0",
        "FEDRAT/10",
        "GOTO/1,0,0",
        "GOTO/2,0,0",
        "SEQNO/OFF",
        "GOTO/3,0,0",
        "SEQNO/ON",
        "GOTO/4,0,0",
    ]
    assert tape(program) == ["N010G01X+1F100", "N015X+1", "X+1", "N020X+1"]


def test_trans_replaces_the_translation() -> None:
    assert tape(["FROM/0,0,0", "FEDRAT/10", "TRANS/1,0,0", "GOTO/1,0,0"]) == ["N004G01X+2F050"]


def test_origin_shifts_the_operator_columns_only() -> None:
    result = post(["ORIGIN/10,5,0", "FROM/0,0,0", "FEDRAT/10", "GOTO/1,0,0"])
    assert tape_lines(result.blocks) == ["N004G01X+1F100"]
    assert result.blocks[0].code.name == "INFORMATION"


def test_a_word_the_manual_does_not_know_is_disregarded_with_a_warning() -> None:
    assert tape(["SELCTL/3"]) == []
    assert comments(["SELCTL/3"]) == [
        "SELCTL IS NOT A GECENT III POSTPROCESSOR WORD; STATEMENT DISREGARDED"
    ]


@pytest.mark.parametrize(
    "statement", ["COOLNT/5", "AUXFUN/1.5", "PREFUN", "SEQNO/A", "TRANS/1,2,3,4", "STOP/1"]
)
def test_malformed_statements(statement: str) -> None:
    with pytest.raises(InputError):
        post([statement])


def test_origin_in_the_operator_printout() -> None:
    """MACH04 prints OPR columns (option 172 = 1): ABS less the ORIGIN, shuffled like the
    axes (CL x -> Z, CL y -> -X): from (5, 2), ORIGIN/1,0.5 gives OPR-Z 4, OPR-X -1.5."""
    lathe = machine("mach04")
    plain = post(["FROM/5,2,0"], lathe)
    shifted = post(["ORIGIN/1,0.5,0", "FROM/5,2,0"], lathe)
    printout = get_plugins().get("printouts", 1)
    assert "+0005.0000" in printout.render(lathe, plain.blocks, "")  # W9's leading zeros
    text = printout.render(lathe, shifted.blocks, "")
    line = next(row for row in text.splitlines() if row.startswith("FROM"))
    assert "-0001.5000" in line and "+0004.0000" in line


def test_air_codes_by_themselves() -> None:
    """AIR/ON -> TABLEM(123), AIR/OFF -> TABLEM(124), each in a block by itself (001
    L28677-28716); a machine without them warns."""
    text = '[machine]\nname = "air"\n[tablem]\n123 = 51\n124 = 52\n'
    machine = load_machine_text(text, "air.toml")
    result = post(["AIR/ON", "AIR/OFF"], machine)
    assert [b.punch for b in result.blocks if b.punch] == ["N001M51", "N002M52"]
    plain = post(["AIR/ON"])
    assert [d.text for d in plain.diagnostics] == [
        "REQUESTED MISCELLANEOUS FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE"
    ]


def test_reset_is_end_without_its_code() -> None:
    """RESET (END's entry, CODE -5, neither printed nor punched): TRANS and the stop are
    reset and the next motion must be a FROM (comment 47)."""
    result = post(["FROM/0,0,0", "TRANS/1,0,0", "RESET", "GOTO/1,0,0"])
    assert [b.code for b in result.blocks if b.code == Code.RESET] == [Code.RESET]
    assert [b.punch for b in result.blocks if b.punch] == [
        "N004G01X+1F050"
    ]  # option 23's assumed feed
    assert [d.text for d in result.diagnostics][:1] == [
        "END OR RESET HAS NOT BEEN FOLLOWED BY A FROM POINT."
    ]
