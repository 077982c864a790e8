"""Tool statements on positioning machines (issue 22, wave 3): option 1 = 2's S and T
merged into the following motion block (001 L24332-24358, TOOLGP L38648-38692), GOHOME
by POSMOV (options 184-186, L26455-26500; POSMOV L34934-34992) and LOAD/TOOL as the
positioning machine's tool change (options 86 and 96, L25406-25434, L25526-25530).

MACH24 (the sample positioning machine): X, Y, Z formats -24, option 59 +X -Y +Z, G80 cycle
off, T format 20, option 40 = 1 (a repeated X or Y is left out); with the variable spindle
of tests/test_positioning.py 1200 RPM is S712 (001 L1165-1166).
"""

from __future__ import annotations

import pytest
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.output.block import Code
from gecent.core.output.element import NO_MOVE_FOR_S_T
from gecent.core.output.tape import tape_lines

from tests.test_positioning import VARIABLE_SPINDLE, mach24
from tests.test_post_linear import post


def merging(extra: str = "") -> MachineDefinition:
    """MACH24 with option 1 = 2 and the variable spindle (S712 = 1200 RPM)."""
    return mach24(VARIABLE_SPINDLE.replace("[optab]", f"[optab]\n1 = 2.0\n{extra}"))


# -- option 1 = 2 --------------------------------------------------------------------------


def test_option_1_2_merges_s_and_t_into_the_following_move() -> None:
    """SPINDL and LOADTL immediately before the move (001 L24346-24349): no block of their
    own; the move carries S712 and T04, and its X, which option 40 would leave out as a
    repeat, goes with the T ("except values that appear with a T code", L24919-24927)."""
    lines = ["FROM/0,0,5", "FEDRAT/10", "GOTO/1,1,5", "SPINDL/1200,CLW", "LOADTL/4"]
    result = post([*lines, "GOTO/1,2,5"], merging())
    assert tape_lines(result.blocks) == [
        "N003G80X+010000Y-010000F20",
        "N006X+010000Y-020000S712T04",
    ]
    move = result.blocks[-2]
    assert move.code is Code.POSITION_XY
    assert move.cells[20] == 1200.0  # the listing's S-RPM


def test_option_1_2_a_later_tool_takes_the_speed_in_force_and_an_m_block_no_s() -> None:
    """As with option 1 = 1, the spindle command in force rides with every T; a block that
    comes between (AUXFUN/8, an M08 block, is not a move) does not take the waiting S."""
    lines = ["FROM/0,0,5", "FEDRAT/10", "SPINDL/1200,CLW", "LOADTL/4", "GOTO/1,1,5"]
    lines += ["SPINDL/1500", "LOADTL/5", "GOTO/2,1,5"]
    assert tape_lines(post(lines, merging()).blocks) == [
        "N005G80X+010000Y-010000F20S712T04",
        "N008X+020000Y-010000S715T05",
    ]
    lines = ["FROM/0,0,5", "FEDRAT/10", "SPINDL/1200,CLW", "AUXFUN/8", "GOTO/1,1,5"]
    assert tape_lines(post(lines, merging()).blocks) == [
        "N004M08",
        "N005G80X+010000Y-010000F20S712",
    ]


def test_option_1_2_a_tool_with_no_move_after_it_is_named() -> None:
    """The programmer must give the move: a T still waiting at FINI is not output, with a
    warning; option 1 = 1 puts the same T out at once (TOOLGP's CODE -1 block)."""
    lines = ["FROM/0,0,5", "FEDRAT/10", "GOTO/1,1,5", "LOADTL/4"]
    result = post(lines, merging())
    assert tape_lines(result.blocks) == ["N003G80X+010000Y-010000F20"]
    assert NO_MOVE_FOR_S_T in [d.text for d in result.diagnostics]
    at_once = post(lines, mach24())
    assert tape_lines(at_once.blocks)[-1] == "N004G80T04"
    assert NO_MOVE_FOR_S_T not in [d.text for d in at_once.diagnostics]


# -- GOHOME on a positioning machine -----------------------------------------------------

HOME = "184 = 2.0\n185 = 3.0\n186 = 4.0\n130 = 1.0\n"


def test_gohome_on_a_positioning_machine_punches_the_home_positions() -> None:
    """Home X 2, Y 3, Z 4 are machine positions: TRANS does not move them, and neither
    does option 140's inversion (Z 4 is punched although POSMOV takes 2 off each CL Z).
    Z goes in a block of its own (option 130 = +1); RAPID takes the move at rapid (F99)."""
    machine = mach24(f"[optab]\n{HOME}140 = 2.0\n")
    lines = ["FROM/0,0,5", "FEDRAT/10", "GOTO/1,1,5", "TRANS/1,0,0", "RAPID", "GOHOME"]
    assert tape_lines(post([*lines, "GOTO/0,0,5"], machine).blocks) == [
        "N003G80X+010000Y-010000F20",
        "N006X+020000Y-030000F99",
        "N006Z+040000",
        "N007X+010000Y+000000F20",
        "N007Z+030000",
    ]


def test_gohome_under_a_control_cycle_drills_no_hole_at_home() -> None:
    """The move home is a plain positioning move (G80); the next hole states its cycle
    block again, measured from the home height (CL Z 4: plunge 4.6, R 3.9)."""
    lines = ["FROM/0,0,5", "CYCLE/DRILL,DEPTH,0.6,IPM,6,CLEAR,0.1", "GOTO/1,1,0", "GOHOME"]
    assert tape_lines(post([*lines, "GOTO/3,1,0"], mach24(f"[optab]\n{HOME}")).blocks) == [
        "N003G81Z+056000F12R+049",
        "N003X+010000Y-010000",
        "N004G80X+020000Y-030000",
        "N004Z+040000",
        "N005G81Z+046000R+039",
        "N005X+030000Y-010000",
    ]


def test_gohome_of_a_rotary_axis_without_a_rotary_register_is_bad_input() -> None:
    """(GOHOME of a rotary axis on a machine with one: tests/test_statements_wave9.py)"""
    with pytest.raises(InputError, match="no rotary register"):
        post(["FROM/0,0,5", "GOHOME"], mach24("[optab]\n188 = 90.0\n"))


# -- LOAD/TOOL on a positioning machine ----------------------------------------------------


def test_load_tool_on_a_positioning_machine_is_toolnos_tool_change() -> None:
    """LOAD/TOOL, n is TOOLGP's T block; option 86 = +1 corrects Z by the change of length
    "with a LOAD/TOOL or TOOLNO statement" (L25412): 3 - 2 = 1 raises the next Z by 1."""
    machine = mach24("[optab]\n86 = 1.0\n130 = -1.0\n")
    expected = [
        "N003G80T03",
        "N004G80X+010000Y-010000Z+010000F20",
        "N005G80T04",
        "N006G80Z+020000",
    ]
    for load in ("LOAD/TOOL,{n},LENGTH,{l}", "TOOLNO/{n},LENGTH,{l}"):
        lines = ["FROM/0,0,0", "FEDRAT/10", load.format(n=3, l=2), "GOTO/1,1,1"]
        lines += [load.format(n=4, l=3), "GOTO/1,1,1"]
        assert tape_lines(post(lines, machine).blocks) == expected


def test_load_tool_on_a_positioning_machine_under_option_1_2_waits_for_the_move() -> None:
    lines = ["FROM/0,0,5", "FEDRAT/10", "LOAD/TOOL,7", "GOTO/1,1,5"]
    assert tape_lines(post(lines, merging()).blocks) == ["N004G80X+010000Y-010000F20T07"]


@pytest.mark.parametrize(
    ("line", "message"),
    [
        ("LOAD/7", "LOAD/TOOL, n"),
        ("LOAD/TOOL,7,LARGE", "does not take LARGE"),
        ("LOAD/TOOL,2.5", "whole numbers"),
    ],
)
def test_bad_load_tool_on_a_positioning_machine(line: str, message: str) -> None:
    with pytest.raises(InputError, match=message):
        post(["FROM/0,0,5", line], mach24())
