"""CLRSRF, RETRCT, XOFSET, OVRCNT (core/statements/surfaces.py) and DRESS, WELD,
FLAME, DRAFT and the words without a routine (core/statements/control.py).

The digests have no worked example of these statements, so each test checks what the
routine's METHOD text says (001 L29442-29470, L35647-35692, L40092-40130, L34364-34400,
L30580-30610, L40047-40090, L31217-31290, L30529-30578) on the sample positioning machine
(MACH24) and on machines given the option-132 category.
"""

from __future__ import annotations

import pytest
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.output.block import Code
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins
from gecent.core.run import Run
from gecent.core.state import PostState

from tests.test_post_linear import post

NOT_AVAILABLE = "REQUESTED MISCELLANEOUS FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE"
# MACH24 with Z programmable in a block of its own (option 130 = +1) and weld codes
POSITIONING_Z = "[optab]\n130 = 1.0\n"
WELD_CODES = "[tablem]\n28 = 71.0\n66 = 66.0\n67 = 67.0\n83 = 83.0\n84 = 84.0\n85 = 85.0\n"
WELD_CODES += "86 = 86.0\n87 = 87.0\n88 = 88.0\n91 = 91.0\n92 = 92.0\n"
FLAME_CODES = "".join(f"{cell} = {cell - 35}.0\n" for cell in range(85, 97))  # M50..M61


def overlay(name: str, text: str) -> MachineDefinition:
    base = get_plugins().machine(name).load() if name != "standard" else standard_machine()
    return load_machine_text(f'[machine]\nname = "{name}-test"\n{text}', "test.toml", base=base)


def tape(lines: list[str], machine: MachineDefinition) -> list[str]:
    return tape_lines(post(lines, machine).blocks)


def comments(lines: list[str], machine: MachineDefinition) -> list[str]:
    return [d.text for d in post(lines, machine).diagnostics]


# -- CLRSRF and RETRCT ---------------------------------------------------------------------


def test_retrct_rises_to_the_clearance_plane_at_rapid_in_a_z_block() -> None:
    """RETRCT: Z = CLRSRF in a CODE -16 block at rapid (option 45's F99 on MACH24); the
    next move goes back down with its Z, since the control now holds the clearance Z."""
    machine = overlay("mach24", POSITIONING_Z)
    program = ["CLRSRF/5", "FROM/0,0,5", "FEDRAT/10", "GOTO/1,1,0", "RETRCT", "GOTO/2,2,0"]
    result = post(program, machine)
    assert tape_lines(result.blocks) == [
        "N004G80X+010000Y-010000F20",
        "N004Z+000000",
        "N005Z+050000F99",
        "N006X+020000Y-020000F20",
        "N006Z+000000",
    ]
    retract = [b for b in result.blocks if b.record == 5]
    assert [b.code for b in retract] == [Code.POSITION_Z]


def test_retrct_adds_trans_and_clrsrf_takes_a_z_plane() -> None:
    """Z = CLRSRF height + TRANSL(3); CLRSRF/0,0,1,3 is the plane z = 3."""
    machine = overlay("mach24", POSITIONING_Z)
    program = ["CLRSRF/0,0,2,6", "TRANS/0,0,1", "FROM/0,0,0", "RETRCT"]
    assert tape(program, machine) == ["N004Z+040000F99"]


def test_a_short_retract_stays_in_the_feed_range() -> None:
    """RAPIDO: a move shorter than option 37 is not worth a rapid (option 39's feed);
    MACH24 marks it as its other positioning rapid moves."""
    machine = overlay("mach24", POSITIONING_Z + "37 = 2.0\n39 = 30.0\n")
    result = post(["CLRSRF/1", "FROM/0,0,0", "RETRCT"], machine)
    block = result.blocks[1]
    assert block.code is Code.POSITION_Z and tape_lines([block]) == ["N003Z+010000F99"]
    assert block.cells[19] == 30.0  # the feed in IPM: option 39


def test_retrct_needs_clrsrf_a_z_and_a_positioning_machine() -> None:
    machine = overlay("mach24", POSITIONING_Z)
    with pytest.raises(InputError, match="CLRSRF statement before it"):
        post(["FROM/0,0,0", "RETRCT"], machine)
    with pytest.raises(InputError, match="programmable Z"):
        post(["CLRSRF/2", "FROM/0,0,0", "RETRCT"], overlay("mach24", ""))  # option 130 = 0
    with pytest.raises(InputError, match="positioning-machine statement"):
        post(["CLRSRF/2", "FROM/0,0,0", "RETRCT"], standard_machine())
    with pytest.raises(InputError, match="CLRSRF expects"):
        post(["CLRSRF/ON"], machine)
    with pytest.raises(InputError, match="normal to Z"):
        post(["CLRSRF/1,0,0,4"], machine)


def test_clrsrf_alone_outputs_nothing() -> None:
    assert tape(["CLRSRF/3"], standard_machine()) == []


# -- XOFSET --------------------------------------------------------------------------------


def test_xofset_is_a_cycle_off_block_with_the_offset_number() -> None:
    """XOFSET/n: G = TABLEG(1) (G80) and n in DBFSEG(17), a CODE +1 block."""
    machine = overlay("mach24", '[regstr]\n17 = "H"\n[regfor]\n17 = 20.0\n')
    result = post(["XOFSET/12"], machine)
    assert tape_lines(result.blocks) == ["N001G80H12"]
    assert result.blocks[0].code is Code.NONMOTION


def test_xofset_needs_its_register_and_a_positioning_machine() -> None:
    with pytest.raises(InputError, match="REGSTR 17"):
        post(["XOFSET/3"], overlay("mach24", ""))
    with pytest.raises(InputError, match="positioning-machine statement"):
        post(["XOFSET/3"], standard_machine())
    with pytest.raises(InputError, match="whole offset number"):
        post(["XOFSET/2.5"], overlay("mach24", ""))


# -- OVRCNT ---------------------------------------------------------------------


def run_state(lines: list[str], machine: MachineDefinition) -> PostState:
    run = Run(machine)
    run.process(AptSourceReader("part.apt").read_lines([*lines, "FINI"]))
    return run.state


def test_ovrcnt_keeps_the_value_off_clears_it_on_puts_it_back() -> None:
    machine = standard_machine()
    assert run_state(["OVRCNT/0.25"], machine).overcenter == 0.25
    assert run_state(["OVRCNT/0.25", "OVRCNT/OFF"], machine).overcenter == 0.0
    assert run_state(["OVRCNT/0.25", "OVRCNT/OFF", "OVRCNT/ON"], machine).overcenter == 0.25
    assert tape(["OVRCNT/0.25"], machine) == []
    with pytest.raises(InputError, match="OVRCNT expects"):
        post(["OVRCNT/CLW"], machine)


# -- DRESS and WELD ------------------------------------------------------------------------


def test_dress_is_tablem_28_by_itself_or_comment_22() -> None:
    machine = overlay("mach24", WELD_CODES)
    assert tape(["COOLNT/ON", "DRESS"], machine) == ["N002M08", "N002M71"]
    assert comments(["DRESS"], overlay("mach24", "")) == [NOT_AVAILABLE]


def test_weld_codes_by_modifier() -> None:
    """TILT -> TABLEM(83)/(84), SCHEDL -> (85)/(86), FIXTUR -> (66)/(67), SHIFT,n ->
    weld shift n = TABLEM(87 + n), SHIFT,0 -> BEAM 0 = TABLEM(92); each by itself."""
    machine = overlay("mach24", WELD_CODES)
    program = ["WELD/TILT,2", "WELD/SCHEDL,1", "WELD/FIXTUR,2", "WELD/SHIFT,4", "WELD/SHIFT,0"]
    assert tape(program, machine) == ["N001M84", "N002M85", "N003M67", "N004M91", "N005M92"]


def test_weld_off_rides_with_the_next_move_and_on_withdraws_it() -> None:
    """WELD/OFF (IGEFLG = 1): the weld-cycle-off TABLEM(87) goes with the next positioning
    block; WELD/ON before any block withdraws it."""
    machine = overlay("mach24", WELD_CODES)
    moves = ["FROM/0,0,0", "FEDRAT/10"]
    assert tape([*moves, "WELD/OFF", "GOTO/1,0,0"], machine) == ["N004G80X+010000Y+000000F20M87"]
    assert tape([*moves, "WELD/OFF", "WELD/ON", "GOTO/1,0,0"], machine) == [
        "N005G80X+010000Y+000000F20"
    ]


def test_weld_unknown_modifier_is_comment_22_and_bad_numbers_are_input_errors() -> None:
    machine = overlay("mach24", WELD_CODES)
    assert comments(["WELD/ROCK,1"], machine) == [NOT_AVAILABLE]
    assert comments(["WELD/SHIFT,2"], machine) == [NOT_AVAILABLE]  # TABLEM(89) absent
    with pytest.raises(InputError, match="WELD/TILT expects one of 1, 2"):
        post(["WELD/TILT,3"], machine)
    with pytest.raises(InputError, match="positioning-machine statement"):
        post(["WELD/ON"], standard_machine())


# -- FLAME ---------------------------------------------------------------------------------


def flame_cutter(extra: str = "") -> MachineDefinition:
    return overlay("standard", f"[optab]\n132 = 4.0\n{extra}[tablem]\n{FLAME_CODES}")


def test_flame_codes_by_head() -> None:
    """PREHET ON/OFF -> 85/86 and 87/88, OXYGEN ON/OFF -> 89/90 and 91/92, DOWN -> 93/94,
    UP -> 95/96 (master/slave); BOTH gives the master's then the slave's, each by itself;
    the head holds from one FLAME to the next."""
    program = [
        "FLAME/PREHET,ON",
        "FLAME/SLAVE,OXYGEN,ON",
        "FLAME/DOWN",
        "FLAME/BOTH,UP",
        "FLAME/MASTER,OXYGEN,OFF,PREHET,OFF",
    ]
    assert tape(program, flame_cutter()) == [
        "N001M50",
        "N002M55",
        "N003M59",
        "N004M60",
        "N004M61",
        "N005M56",
        "N005M52",
    ]


def test_flame_leaves_rapid_first() -> None:
    """RAPIDX before the scan: a modal rapid (option 109 = -1) ends at FLAME."""
    program = ["FROM/0,0,0", "RAPID", "GOTO/1,0,0", "FLAME/UP", "FEDRAT/10", "GOTO/2,0,0"]
    result = post(program, flame_cutter("109 = -1.0\n"))
    assert tape_lines(result.blocks)[1] == "N004M60"
    assert not result.blocks[-1].rapid


def test_flame_vocabulary_is_comment_42_and_other_machines_refuse_it() -> None:
    text = "THE VOCABULARY IS NOT ACCEPTABLE IN THE FLAME STATEMENT."
    assert comments(["FLAME/ON"], flame_cutter()) == [text]
    assert comments(["FLAME/OXYGEN"], flame_cutter()) == [text]
    assert tape(["FLAME/PREHET,ON,TILT"], flame_cutter()) == []  # nothing of a bad statement
    with pytest.raises(InputError, match="option 132 = 4"):
        post(["FLAME/UP"], standard_machine())


# -- DRAFT ---------------------------------------------------------------------------------


def plotter() -> MachineDefinition:
    return overlay("standard", '[optab]\n132 = 3.0\n[regstr]\n16 = "D"\n[regfor]\n16 = 10.0\n')


def test_draft_d_codes() -> None:
    """ON D1; ON,DASH D4 (D1 first when the pen is up); OFF,DASH D5; OFF D2."""
    program = ["DRAFT/ON", "DRAFT/ON,DASH", "DRAFT/OFF,DASH", "DRAFT/OFF", "DRAFT/DASH,ON"]
    assert tape(program, plotter()) == ["N001D1", "N002D4", "N003D5", "N004D2", "N005D1", "N005D4"]
    assert tape(["DRAFT/ON,SOLID"], plotter()) == ["N001D1"]


def test_draft_needs_a_drafting_machine_and_its_words() -> None:
    with pytest.raises(InputError, match="option 132 = 3"):
        post(["DRAFT/ON"], standard_machine())
    with pytest.raises(InputError, match="DRAFT expects"):
        post(["DRAFT/ON,OFF"], plotter())
    with pytest.raises(InputError, match="OFF goes with DASH"):
        post(["DRAFT/OFF,SOLID"], plotter())
    with pytest.raises(InputError, match="REGSTR 16"):
        post(["DRAFT/ON"], overlay("standard", "[optab]\n132 = 3.0\n[regfor]\n16 = 0.0\n"))


# -- words without a routine ---------------------------------------------------------------


@pytest.mark.parametrize("word", ["SWITCH", "PPUNCH/1", "SET/1", "MODE/1", "PIVOTZ/2"])
def test_words_without_a_routine_are_disregarded_with_a_warning(word: str) -> None:
    major = word.split("/")[0]
    text = f"{major}: GECENT III DESCRIBES NO PROCESSING FOR THIS WORD; STATEMENT DISREGARDED"
    result = post(["FROM/0,0,0", word], standard_machine())
    assert [d.text for d in result.diagnostics] == [text]
    assert tape_lines(result.blocks) == []


def test_mode_on_a_macfun_machine_and_pivotz_on_a_multiaxis_machine_are_disregarded() -> None:
    """Issue 22: the manual describes neither (GEMAXS's MODE and PIVPLN have no write-up,
    001 L19040-19067; the sample MACFUN answers no MODE hook), so they are disregarded with
    the warning the other words get, no longer "not yet supported"."""
    for word, machine in (
        ("MODE/1", overlay("standard", "[optab]\n133 = 1.0\n")),
        ("PIVOTZ/2", get_plugins().machine("mach40").load()),
    ):
        major = word.split("/")[0]
        result = post([word], machine)
        assert [d.text for d in result.diagnostics] == [
            f"{major}: GECENT III DESCRIBES NO PROCESSING FOR THIS WORD; STATEMENT DISREGARDED"
        ]
        assert tape_lines(result.blocks) == []
