"""ROTATE on a positioning machine: the absolute rotary system ROTABA (manual §3.4.5.1,
spec 03 W16, W17), its own feed register (options 139, 141: rotary feed type 1, spec 05
E15), table rapid (TABLEM 42, 43, option 115), options 120 = -2, 206, 220 and 221, and the
M-code devices ROTATE/INDEXER and ROTATE/MAGAZINE (ROTIND, ROTMAG)."""

from __future__ import annotations

import math

import pytest
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.motion.rotary import long_way_targets
from gecent.core.output.block import Code
from gecent.core.run import RunResult

from tests.test_post_linear import post

# MACH24's layout with a table register B (format 33, degrees), the manual's E register
# for rotary feed type 1 in DBFSEG(17) (the example's 16 is MACH24's R), the table rapid
# M codes and M-code devices
MACHINE = """
[machine]
name = "rotaba"
title = "POSITIONING WITH A TABLE"
[tableg]
1 = 80
82 = 81
[tablem]
42 = 40
43 = 41
48 = 21
49 = 22
83 = 23
84 = 24
[regstr]
16 = "R"
17 = "E"
[regfor]
3 = -24.0
4 = -24.0
5 = -24.0
7 = 33.0
8 = 0.0
9 = 0.0
10 = 0.0
11 = 20.0
12 = 20.0
13 = 20.0
16 = -22.0
17 = 10.0
[optab]
1 = 1.0
4 = 98.0
23 = 5.0
24 = 99.0
25 = 49.5
88 = -12.0
112 = 6.0
114 = 0.5
118 = 1.0
119 = 0.001
139 = 17.0
141 = 1.0
"""


def machine(**options: float) -> MachineDefinition:
    loaded = load_machine_text(MACHINE, "rotaba.toml")
    return loaded.with_options({int(k[1:]): v for k, v in options.items()})


def table_blocks(result: RunResult) -> list[str]:
    return [b.punch or "" for b in result.blocks if b.code is Code.ROTARY_ABSOLUTE]


def test_w16_the_register_holds_the_position() -> None:
    """W16 (001 L5561-5568): ATANGL 23 CLW outputs 23; INCR 10 CLW then outputs 33."""
    result = post(["FEDRAT/7", "ROTATE/TABLE,ATANGL,23,CLW", "ROTATE/TABLE,INCR,10,CLW"], machine())
    assert table_blocks(result) == ["N002G80B023E6", "N003G80B033E6"]


def test_w17_the_long_way_round_in_two_moves() -> None:
    """W17 (001 L5570-5592): from 90 on a scale that reads lower clockwise (option 117 =
    -1), ATANGL 180 CLW goes to 271, then to 180."""
    lines = ["FEDRAT/7", "ROTATE/TABLE,ATANGL,90", "ROTATE/TABLE,ATANGL,180,CLW"]
    result = post(lines, machine(o117=-1.0))
    assert table_blocks(result)[1:] == ["N003G80B271E6", "N003G80B180E6"]


def test_long_way_rule_carried_on_past_one_half_turn() -> None:
    """Open question 9: each move under 180 degrees, whatever the travel (a half turn is
    two moves, a whole turn three)."""
    assert long_way_targets(0.0, 180.0) == [179.0, 180.0]
    assert long_way_targets(0.0, 360.0) == [179.0, 358.0, 0.0]
    assert long_way_targets(10.0, -200.0) == [191.0, 170.0]
    assert long_way_targets(10.0, 179.0) == [189.0]


def test_e15_rotary_feed_type_1_command_in_its_own_register() -> None:
    """E15 (001 L11738-11808): 7 IPM is not in the table; the next lowest, 6.4460 IPM by
    the formula (the manual prints 6.4476 from rounded RPM values), is row 6: E6. The
    linear F register is not used by a table block."""
    result = post(["FEDRAT/7", "ROTATE/TABLE,ATANGL,90"], machine())
    (block,) = [b for b in result.blocks if b.code is Code.ROTARY_ABSOLUTE]
    assert block.punch == "N002G80B090E6"
    assert float(block.cells[19]) == pytest.approx(6.4460, abs=1e-4)  # type: ignore[arg-type]
    # 90 degrees at 6 in radius at 6.4460 IPM
    assert block.cut_minutes == pytest.approx(math.radians(90) * 6 / 6.44604, rel=1e-5)
    assert result.cut_minutes == pytest.approx(block.cut_minutes)


def test_no_rotary_feed_type_leaves_the_table_block_without_feed() -> None:
    """Option 141 = 0: no separate feed command (RFTYPE does nothing)."""
    result = post(["FEDRAT/7", "ROTATE/TABLE,ATANGL,45"], machine(o141=0.0))
    assert table_blocks(result) == ["N002G80B045"]


def test_rotary_feed_type_needs_its_register() -> None:
    with pytest.raises(Exception, match="option 139"):
        post(["FEDRAT/7", "ROTATE/TABLE,ATANGL,45"], machine(o139=0.0))


def test_no_feedrate_assumes_option_23_with_rotates_comment() -> None:
    """ROTATE's comment OPTION FEEDRATE IS ASSUMED. (001 L36080-36082): 5 IPM -> E5."""
    result = post(["ROTATE/TABLE,ATANGL,45"], machine())
    texts = [b.text for b in result.blocks if b.code is Code.COMMENT]
    assert "OPTION FEEDRATE IS ASSUMED." in texts
    assert table_blocks(result) == ["N001G80B045E5"]


def test_table_rapid_is_one_shot_between_its_m_codes() -> None:
    """RAPID: TABLEM(42) with the table block, TABLEM(43) with the next; no feed command;
    the table moves at option 115's RPM (2.0) at the part radius (001 L5619-5626)."""
    lines = ["FEDRAT/7", "RAPID", "ROTATE/TABLE,ATANGL,90", "ROTATE/TABLE,ATANGL,100"]
    result = post(lines, machine())
    punches = [b.punch for b in result.blocks if b.punch]
    assert punches == ["N003G80B090M40", "N004G80B100M41E6"]
    rapid = next(b for b in result.blocks if b.code is Code.ROTARY_ABSOLUTE)
    assert float(rapid.cells[19]) == pytest.approx(2 * math.pi * 6 * 2.0)  # type: ignore[arg-type]


def test_option_120_minus_2_signs_the_direction() -> None:
    """Option 120 = -2: + for CLW, - for CCLW, even to a lower position (001 L25815-25842)."""
    lines = ["FEDRAT/7", "ROTATE/TABLE,ATANGL,90,CLW", "ROTATE/TABLE,ATANGL,30,CCLW"]
    signed = load_machine_text(MACHINE.replace("7 = 33.0", "7 = -33.0"), "signed.toml")
    result = post(lines, signed.with_options({120: -2.0}))
    assert table_blocks(result) == ["N002G80B+090E6", "N003G80B-030E6"]


def test_option_206_reverses_the_tables_clw() -> None:
    """Option 206 = -1: ROTATE/TABLE,...,CLW turns the table CCLW (001 L26616-26626): from
    90, ATANGL 180 CLW is then the short way; INCR 10 (CLW by default) goes down to 170."""
    lines = ["FEDRAT/7", "ROTATE/TABLE,ATANGL,90", "ROTATE/TABLE,ATANGL,180,CLW"]
    lines.append("ROTATE/TABLE,INCR,10")
    blocks = table_blocks(post(lines, machine(o117=-1.0, o206=-1.0)))
    assert blocks[1:] == ["N003G80B180E6", "N004G80B190E6"]


def test_table_limits_are_warned_about() -> None:
    """Options 220, 221: a move passing outside 0-270 degrees is warned about and made."""
    lines = ["FEDRAT/7", "ROTATE/TABLE,ATANGL,200,CLW", "ROTATE/TABLE,INCR,100,CLW"]
    result = post(lines, machine(o220=0.0, o221=270.0))
    warnings = [d.text for d in result.diagnostics]
    assert len(warnings) == 1 and "TABLE ROTATION LIMIT" in warnings[0]
    assert table_blocks(result)[-1] == "N003G80B300E6"


def test_table_block_ends_a_control_cycle() -> None:
    """The table block's G80 cancels the control's cycle, so the next hole states the
    cycle block (G81, Z, R) again."""
    lines = [
        "FROM/0,0,5",
        "CYCLE/DRILL,DEPTH,0.6,IPM,6,CLEAR,0.1",
        "GOTO/1,1,0",
        "ROTATE/TABLE,ATANGL,90",
        "GOTO/2,1,0",
    ]
    result = post(lines, machine())
    punches = [b.punch for b in result.blocks if b.punch]
    assert punches == [
        "N003G81Z+056000F12R+049",
        "N003X+010000Y+010000",
        "N004G80B090E5",
        "N005G81Z+056000R+049",
        "N005X+020000",
    ]


def test_indexer_steps_are_m_code_blocks() -> None:
    """ROTIND (001 L36126-36160): n blocks of TABLEM(48) right (the default) or 49 left."""
    result = post(["ROTATE/INDEXER,2", "ROTATE/INDEXR,1,LEFT"], machine())
    assert [b.punch for b in result.blocks if b.punch] == ["N001M21", "N001M21", "N002M22"]


def test_indexer_needs_a_whole_count() -> None:
    with pytest.raises(InputError, match="whole number"):
        post(["ROTATE/INDEXER,1.5"], machine())


def test_magazine_turns_the_shorter_way_and_states_the_pocket() -> None:
    """ROTMAG (001 L36176-36217): TABLEM(83) CLW or 84 CCLW, as given or by MINMOV over
    |option 88| = 12 pockets; the pocket in T, CODE -1; no pocket: the one up."""
    lines = ["ROTATE/MAGAZINE,3", "ROTATE/MAGAZINE,11", "ROTATE/MAGZIN,CLW", "ROTATE/MAGAZINE,2"]
    punches = [b.punch for b in post(lines, machine()).blocks if b.punch]
    assert punches == ["N001T03", "N002T11M24", "N003T11M23", "N004T02M23"]


def test_devices_are_positioning_statements() -> None:
    contouring = machine(o1=0.0)
    with pytest.raises(InputError, match="positioning-machine"):
        post(["ROTATE/INDEXER,1"], contouring)


def test_torch_needs_a_flame_cutter() -> None:
    """ROTATE/TORCH is a flame cutter's (option 132 = 4; tests/test_rotary_wave3.py): on
    this positioning machine it is bad input."""
    with pytest.raises(InputError, match="TORCH"):
        post(["ROTATE/TORCH,INCR,10"], machine())
