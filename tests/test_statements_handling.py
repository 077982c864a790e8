"""GOHOME, LOAD/TOOL (LOADGM, 001 L33878-33925), PICKUP (L34568-34610), UNLOAD
(L39947-39988) and POSITN (L34880-34932): core/statements/handling.py."""

from __future__ import annotations

import pytest
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.output.block import Block, Code
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post

WRONG_POCKET = "ATTEMPTING TO UNLOAD TOOL IN WRONG MAGAZINE POCKET."


def mach40() -> MachineDefinition:
    return get_plugins().machine("mach40").load()


def overlaid(name: str, overlay: str) -> MachineDefinition:
    """A sample machine with some of its tables changed."""
    base = get_plugins().machine(name).load()
    text = f'[machine]\nname = "{name}-handling"\n{overlay}'
    return load_machine_text(text, "handling.toml", base=base)


def positioning(tableg: str = "", tablem: str = "") -> MachineDefinition:
    """MACH24 (the sample positioning machine: G80 cycle off, a T register) with extra
    codes."""
    return overlaid("mach24", f"[tableg]\n{tableg}[tablem]\n{tablem}")


def blocks_of(blocks: list[Block], record: int, code: Code) -> list[Block]:
    return [b for b in blocks if b.record == record and b.code is code]


# -- GOHOME ------------------------------------------------------------------------------


def test_gohome_moves_to_options_184_to_186() -> None:
    """Home X 10, Y 5, Z 8 (options 184-186, machine coordinates): from (1, 1, 1) the move
    is X+9 Y+4 Z+7 at the feed in force; TRANS moves the part, not home: from the part's
    (0, 0, 0) + TRANS (1, 0, 0) the move home is X+9 Y+5 Z+8."""
    home = load_machine_text(
        '[machine]\nname = "home"\ntitle = "HOME"\n[optab]\n184 = 10.0\n185 = 5.0\n186 = 8.0\n',
        "home.toml",
    )
    lines = ["FEDRAT/10", "FROM/0,0,0", "GOTO/1,1,1", "GOHOME", "TRANS/1,0,0", "GOTO/0,0,0"]
    assert tape_lines(post([*lines, "GOHOME"], home).blocks) == [
        "N003G01X+1Y+1Z+1F058",
        "N004X+9Y+4Z+7F008",
        "N006X-9Y-5Z-8",
        "N007X+9Y+5Z+8",
    ]


def test_gohome_needs_a_from_and_a_contouring_machine() -> None:
    with pytest.raises(InputError, match="before any FROM"):
        post(["GOHOME"], standard_machine())
    # (GOHOME on a positioning machine is built: tests/test_tools_wave3.py)
    with pytest.raises(InputError, match="no values"):
        post(["FROM/0,0,0", "GOHOME/1"], standard_machine())


# -- LOAD --------------------------------------------------------------------------------

MACH40_LOAD = [
    "FEDRAT/20",
    "FROM/0,0,10,0,0,1",
    "LOAD/TOOL,5,LARGE,LENGTH,2",
    "GOTO/0,0,10,0,0,1",
]


def test_we19_macf40_load_returns_the_tool_to_the_change_point() -> None:
    """WE-19 (MACF40 MCHCON 6, 001 L28120-28128): TLHEAD = 0 -> DPRESM = X -19, Y 48,
    Z 48.75, A -25, and the normal LOAD continues: GOHOME moves there. The FROM has the
    tool along +Z: X 0, Y 0, Z = 10 + R (option 104 = 4) = 14, A = 90 degrees = +25 (100
    parts a turn, option 118 = -1); the head turns -50 (half a turn, the tie taken
    negative), segmented by ROTMAX."""
    result = post(MACH40_LOAD, mach40())
    moves = blocks_of(result.blocks, 3, Code.LINEAR)
    step = 0.0001
    assert moves[-1].position is not None
    assert [round(p * step, 4) for p in moves[-1].position] == [-19.0, 48.0, 48.75]
    total = {cell: round(sum(float(b.cells[cell]) for b in moves), 4) for cell in (3, 4, 5, 6)}
    assert total == {3: -19.0, 4: 48.0, 5: 34.75, 6: -50.0}


def test_load_outputs_the_head_and_gripper_load_code_with_t() -> None:
    """Head 1's large gripper is TABLEG(27) = G26 on MACH40 (L27898-27903); T5 with it in
    a CODE -4 block (the F is MACH40's option-98 momentary dwell of non-motion blocks)."""
    lines = tape_lines(post(MACH40_LOAD, mach40()).blocks)
    assert "N003G26F200T00005" in lines
    small = tape_lines(post(["FROM/0,0,10,0,0,1", "LOAD/TOOL,7"], mach40()).blocks)
    assert "N002G25F200T00007" in small


def test_load_sets_r_plus_tl_of_the_loaded_tool() -> None:
    """CLASS1 raises Z by R + TL with the tool along Z: before LOAD R = option 104 = 4
    (Z 14 at z 10); LOAD/TOOL with the large gripper and LENGTH 2 makes it option 105 +
    2 = 9.5 + 2 = 11.5: the same CL point is machine Z 21.5."""
    result = post(MACH40_LOAD, mach40())
    after = blocks_of(result.blocks, 4, Code.LINEAR)
    assert after[-1].position is not None
    assert [round(p * 0.0001, 4) for p in after[-1].position] == [0.0, 0.0, 21.5]
    start = blocks_of(result.blocks, 2, Code.FROM)[0]
    assert start.position is not None and round(start.position[2] * 0.0001, 4) == 14.0


@pytest.mark.parametrize(
    ("lines", "machine", "error", "text"),
    [
        (["FROM/0,0,0", "LOAD/TOOL,1"], "standard", InputError, "OPTAB\\(116\\) must be set"),
        (["LOAD/TOOL,1"], "mach40", InputError, "FROM"),
        (["FROM/0,0,10,0,0,1", "LOAD/1"], "mach40", InputError, "LOAD/TOOL, n"),
        (["FROM/0,0,10,0,0,1", "LOAD/TOOL,1,LENGTH,-1"], "mach40", InputError, "length > 0"),
    ],
)
def test_load_refuses(lines: list[str], machine: str, error: type[Exception], text: str) -> None:
    """GECENT's LOAD is the multiaxis one (OPTAB(116) must be set) and needs a FROM first
    (001 L33921-33925)."""
    with pytest.raises(error, match=text):
        post(lines, standard_machine() if machine == "standard" else mach40())


def test_load_without_the_gripper_code_is_bad_input() -> None:
    """Head 2's codes (TABLEG 28, 29) are MACH40's; a machine without TABLEG(27) cannot load
    with a large gripper."""
    lacking = overlaid("mach40", '[tableg]\n27 = "absent"\n')
    with pytest.raises(InputError, match=r"TABLEG\(27\)"):
        post(["FROM/0,0,10,0,0,1", "LOAD/TOOL,3,LARGE"], lacking)


# -- PICKUP, UNLOAD ----------------------------------------------------------------------


def test_pickup_and_unload_by_m_codes() -> None:
    """TABLEG(24) and (26) absent: PICKUP is the cycle-off G80 with TABLEM(32), UNLOAD G80
    with TABLEM(33) (001 L34590-34600, L39962-39968). Unloading tool 4 with the magazine
    at pocket 5 is comment 40."""
    machine = positioning(tablem="32 = 6\n33 = 7\n")
    lines = ["FROM/0,0,0", "TOOLNO/3", "PICKUP", "UNLOAD", "TOOLNO/4", "PICKUP", "TOOLNO/5"]
    result = post([*lines, "UNLOAD"], machine)
    assert tape_lines(result.blocks) == [
        "N002G80T03",
        "N003G80M06",
        "N004G80M07",
        "N005G80T04",
        "N006G80M06",
        "N007G80T05",
        "N008G80M07",
    ]
    assert [d.text for d in result.diagnostics] == [WRONG_POCKET]


def test_pickup_and_unload_by_g_codes() -> None:
    """TABLEG(24) = G23: PICKUP's G code by itself (CODE -4); TABLEG(26) = G25: UNLOAD's G
    with T of the tool in the spindle."""
    machine = positioning(tableg="24 = 23\n26 = 25\n")
    result = post(["FROM/0,0,0", "TOOLNO/3", "PICKUP", "UNLOAD"], machine)
    assert tape_lines(result.blocks) == ["N002G80T03", "N003G23", "N004G25T03"]
    assert result.diagnostics == []


def test_unload_with_nothing_picked_up_is_comment_40() -> None:
    machine = positioning(tablem="33 = 7\n")
    result = post(["FROM/0,0,0", "TOOLNO/3", "UNLOAD"], machine)
    assert [d.text for d in result.diagnostics] == [WRONG_POCKET]


@pytest.mark.parametrize("word", ["PICKUP", "UNLOAD"])
def test_pickup_and_unload_refuse(word: str) -> None:
    with pytest.raises(InputError, match="positioning machine"):
        post(["FROM/0,0,0", word], standard_machine())
    with pytest.raises(InputError, match="must be set"):
        post(["FROM/0,0,0", word], positioning())


# -- POSITN ------------------------------------------------------------------------------


def test_positn_off_outputs_tableg_60() -> None:
    """POSITN/OFF: TABLEG(60) in a CODE -4 block (L34910-34913); TRAV of OFF is OFF."""
    machine = positioning(tableg="60 = 70\n")
    assert tape_lines(post(["POSITN/OFF", "POSITN/TRAV"], machine).blocks) == ["N001G70"]


def test_positn_refuses() -> None:
    # FINE is built now (tests/test_statement_forms.py): a machine without its code
    # TABLEG(52) is bad input, no longer "not yet supported"
    with pytest.raises(InputError, match="TABLEG\\(52\\)"):
        post(["POSITN/FINE"], positioning(tableg="60 = 70\n"))
    with pytest.raises(InputError, match="TABLEG\\(60\\)"):
        post(["POSITN/OFF"], positioning())
    with pytest.raises(InputError, match="positioning machine"):
        post(["POSITN/OFF"], standard_machine())
    with pytest.raises(InputError, match="one of OFF"):
        post(["POSITN/FAST"], positioning(tableg="60 = 70\n"))
