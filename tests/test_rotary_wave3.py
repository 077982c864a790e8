"""Issue 22, rotary gaps: ROTATE/TORCH (ROTORC, 001 L36260-36302), the rotary table's speed
control ROTATE/TABLE,OFF|CLW|CCLW,RPM,s,RANGE,n (TABSPD, 001 L38089-38171; options
179-183; table speeds in SRTAB 141 up), SET12 in ROTABA's block, the table rapid of an
incremental rotary block (option 115, chart 8, 001 L19839-19842) and option 120 = -1.
The readings are docs/decisions.md, "Rotary: TORCH, table speeds, option 115 (issue 22)".
"""

from __future__ import annotations

import math
from dataclasses import replace

import pytest
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import MachineFileInvalid, load_machine_text
from gecent.core.motion.rotary import TORCH_PAST_360, TORCH_SEGMENTED
from gecent.core.motion.rotary_devices import TABLE_RANGE, TABLE_REVERSES
from gecent.core.output.block import Block, Code
from gecent.core.plugins import get_plugins
from gecent.core.run import RunResult

from tests.test_post_linear import post
from tests.test_rotary_positioning import machine as positioning_table

# -- ROTATE/TORCH ----------------------------------------------------------------------------

# a contouring flame cutter (option 132 = 4) whose torch register A holds degrees to 3
# decimals (option 118 = +1, option 14 = 0.001)
FLAME = """
[machine]
name = "flame"
title = "FLAME CUTTER WITH A TORCH"
[regfor]
6 = -33.0
[optab]
14 = 0.001
118 = 1.0
132 = 4.0
"""


def flame(**options: float) -> MachineDefinition:
    loaded = load_machine_text(FLAME, "flame.toml")
    return loaded.with_options({int(k[1:]): v for k, v in options.items()})


def torch_values(result: RunResult) -> list[float]:
    return [float(b.cells[6]) for b in result.blocks if b.code is Code.ROTARY_ABSOLUTE]  # type: ignore[arg-type]


def comments(result: RunResult) -> list[str]:
    return [b.text or "" for b in result.blocks if b.code is Code.COMMENT]


def test_torch_turn_is_a_departure_in_its_register() -> None:
    """INCR 30 outputs +30; ATANGL 0 then takes the shorter way back, -30; CCLW is
    negative. Each block is CODE +2 with the A register alone (ROTORC calls no G or feed
    routine)."""
    lines = ["ROTATE/TORCH,INCR,30", "ROTATE/TORCH,ATANGL,0", "ROTATE/TORCH,INCR,45.5,CCLW"]
    result = post(lines, flame())
    assert torch_values(result) == pytest.approx([30.0, -30.0, -45.5])
    punched = [b.punch for b in result.blocks if b.code is Code.ROTARY_ABSOLUTE]
    # format -33 with the trailing zeros dropped: 30.000 -> +030, 45.500 -> -0455
    assert punched == ["N001A+030", "N002A-030", "N003A-0455"]
    assert not comments(result)


def test_torch_warns_once_it_has_turned_past_360_degrees() -> None:
    """200 + 200 degrees CLW: 400 from the start, the hoses' warning; turning back below
    360 ends it."""
    result = post(
        ["ROTATE/TORCH,INCR,200", "ROTATE/TORCH,INCR,200", "ROTATE/TORCH,INCR,100,CCLW"],
        flame(),
    )
    assert torch_values(result) == pytest.approx([200.0, 200.0, -100.0])
    assert comments(result) == [TORCH_PAST_360]


def test_torch_turn_too_large_for_the_register_is_segmented() -> None:
    """A register of format -22 holds 99.99: 250 degrees go in three equal parts at the
    0.01 step, the rounding carried (83.33, 83.34, 83.33 = 250.00), with ROTORC's
    comment."""
    machine = load_machine_text(FLAME.replace("6 = -33.0", "6 = -22.0"), "flame.toml")
    result = post(["ROTATE/TORCH,INCR,250"], machine.with_options({14: 0.01}))
    assert torch_values(result) == pytest.approx([83.33, 83.34, 83.33])
    assert sum(torch_values(result)) == pytest.approx(250.0)
    assert comments(result) == [TORCH_SEGMENTED]


def test_torch_rounds_to_the_linear_step_and_carries_the_difference() -> None:
    """SRAREC (the linear rounding, option 14), in option 118's units: revolutions at
    0.001, three turns of 10 degrees are .028, .028, .027 (0.083 rev = 29.88 degrees, the
    nearest the step allows to 30)."""
    result = post(["ROTATE/TORCH,INCR,10"] * 3, flame(o118=0.0))
    assert torch_values(result) == pytest.approx([0.028, 0.028, 0.027])


def test_torch_on_a_positioning_flame_cutter() -> None:
    """ROTORC is one routine for both systems: a positioning flame cutter outputs the
    same departure."""
    result = post(["ROTATE/TORCH,INCR,15,CLW"], flame(o1=1.0))
    assert torch_values(result) == pytest.approx([15.0])


def test_torch_needs_a_flame_cutter_and_its_form() -> None:
    with pytest.raises(InputError, match="flame-cutter statement"):
        post(["ROTATE/TORCH,INCR,10"], flame(o132=1.0))
    with pytest.raises(InputError, match="ROTATE/TORCH expects INCR or ATANGL"):
        post(["ROTATE/TORCH,10"], flame())
    with pytest.raises(InputError, match="ROTATE/TORCH expects INCR or ATANGL"):
        post(["ROTATE/TORCH,INCR,10,RPM"], flame())
    without_register = load_machine_text(FLAME.replace("6 = -33.0", "6 = 0.0"), "flame.toml")
    with pytest.raises(InputError, match="no rotary register"):
        post(["ROTATE/TORCH,INCR,10"], without_register)


# -- ROTATE/TABLE speed control (TABSPD) ------------------------------------------------------

# MACH23 with a spinning table: two ranges of two speeds (0.5, 1.0 | 2.0, 4.0 RPM) in SRTAB
# 141-144, the speed register E in DBFSEG(17), table M codes, a 2 s reversal dwell and a
# 1.5 s start-up dwell
SPINNING = """
[machine]
name = "spinning"
title = "MILL WITH A SPINNING TABLE"
[tablem]
1 = 0
50 = 55
83 = 53
84 = 54
[regstr]
17 = "E"
[regfor]
17 = 21.0
[optab]
179 = 2.0
180 = 2.0
181 = 0.75
182 = 2.0
183 = 1.5
[spindle_table.cells]
141 = 0.5
142 = 1.0
143 = 2.0
144 = 4.0
"""


def spinning(**options: float) -> MachineDefinition:
    base = get_plugins().machine("mach23").load()
    loaded = load_machine_text(SPINNING, "spinning.toml", base)
    return loaded.with_options({int(k[1:]): v for k, v in options.items()})


def speed_blocks(result: RunResult) -> list[Block]:
    return [b for b in result.blocks if b.code is not Code.COMMENT and b.punch]


def test_table_speed_start_reverse_and_range_change() -> None:
    """Start CLW at the speed nearest 0.9 (1.0): TABLEM(83) and E in a dwell block of
    option 183's 1.5 s. Reverse at 0.5: the comment, then TABLEM(84), E and option
    182's 2 s. 3.5 RPM is nearest 4.0, in range 2: a stop block (TABLEM 1), the
    operator's comment, then the direction code and speed with no dwell. OFF: TABLEM(50)
    by itself."""
    lines = [
        "ROTATE/TABLE,CLW,RPM,0.9",
        "ROTATE/TABLE,CCLW,RPM,0.5",
        "ROTATE/TABLE,CCLW,RPM,3.5",
        "ROTATE/TABLE,OFF",
    ]
    machine = spinning()
    result = post(lines, machine)
    blocks = speed_blocks(result)
    assert [b.code for b in blocks] == [
        Code.DWELL,
        Code.DWELL,
        Code.AUX_ONLY,
        Code.NONMOTION,
        Code.AUX_ONLY,
    ]
    assert [b.cells[14] for b in blocks] == [53.0, 54.0, 0.0, 54.0, 55.0]
    assert [b.cells[17] for b in blocks if b.code is not Code.AUX_ONLY] == [1.0, 0.5, 4.0]
    assert [b.dwell_minutes for b in blocks[:2]] == pytest.approx([1.5 / 60, 2.0 / 60])
    assert blocks[2].stop
    assert comments(result) == [TABLE_REVERSES, TABLE_RANGE.format(2)]
    # option 57's dwell word X in seconds, the M code, E = 1.0 RPM in format 21
    assert blocks[0].punch == "N001G04X+0015M53E01"


def test_table_speed_without_rpm_is_option_181s_and_range_picks_within_it() -> None:
    """No RPM: option 181's 0.75, nearest 0.5 and 1.0 alike, the lower wins (0.5). RANGE, 2
    with 1.2 RPM takes range 2's nearest, 2.0 (after the stop for the change)."""
    result = post(["ROTATE/TABLE,CLW", "ROTATE/TABLE,CLW,RPM,1.2,RANGE,2"], spinning())
    speeds = [b.cells[17] for b in speed_blocks(result) if b.code is not Code.AUX_ONLY]
    assert speeds == [0.5, 2.0]
    assert comments(result) == [TABLE_RANGE.format(2)]


def test_same_direction_new_speed_has_no_dwell() -> None:
    result = post(["ROTATE/TABLE,CLW,RPM,1", "ROTATE/TABLE,RPM,0.5"], spinning())
    blocks = speed_blocks(result)
    assert [b.code for b in blocks] == [Code.DWELL, Code.NONMOTION]
    assert blocks[1].cells[14] == 53.0  # the table keeps turning CLW
    assert blocks[1].cells[17] == 0.5


def test_option_206_reverses_the_table_direction_code() -> None:
    result = post(["ROTATE/TABLE,CLW,RPM,1"], spinning(o206=-1.0))
    assert speed_blocks(result)[0].cells[14] == 54.0


def test_table_speed_refusals() -> None:
    with pytest.raises(InputError, match="contouring-machine statement"):
        post(["ROTATE/TABLE,CLW,RPM,1"], positioning_table())
    with pytest.raises(InputError, match=r"SRTAB\(141..146\)"):
        post(["ROTATE/TABLE,CLW,RPM,1"], spinning(o180=3.0))
    with pytest.raises(InputError, match="speed range"):
        post(["ROTATE/TABLE,CLW,RPM,1,RANGE,3"], spinning())
    with pytest.raises(InputError, match="OFF takes no speed"):
        post(["ROTATE/TABLE,OFF,RPM,1"], spinning())
    with pytest.raises(InputError, match="ROTATE/TABLE expects OFF"):
        post(["ROTATE/TABLE,CLW,RPM"], spinning())
    plain = get_plugins().machine("mach23").load()
    with pytest.raises(InputError, match="table speed register"):
        post(["ROTATE/TABLE,CLW,RPM,1"], plain)


def test_table_speeds_are_not_spindle_speeds() -> None:
    """SRTAB 141 up is the table's: it does not count against option 7 x option 8, it is
    kept when a derived machine gives new spindle speeds, and it may not meet FRTAB."""
    machine = spinning()
    assert machine.srtab_top < 141
    derived = load_machine_text(
        '[machine]\nname = "derived"\n[spindle_table]\nspeeds = [10.0, 500.0]\n',
        "derived.toml",
        machine,
    )
    assert [derived.srtab(i) for i in range(141, 145)] == [0.5, 1.0, 2.0, 4.0]
    with pytest.raises(MachineFileInvalid, match="overlap"):
        load_machine_text(
            '[machine]\nname = "crowded"\n[optab]\n174 = 158.0\n', "crowded.toml", machine
        )


# -- SET12, option 115, option 120 -------------------------------------------------------------


def test_rotaba_block_takes_the_positioning_mode_g_code() -> None:
    """SET12 in ROTABA (001 L35892-35937, L5612-5614): under POSITN/FINE the table block
    carries TABLEG(52), not the cycle-off TABLEG(1) = G80."""
    text_machine = positioning_table()
    tableg = list(text_machine.tableg)
    tableg[52] = 52
    machine = replace(text_machine, tableg=tuple(tableg))
    result = post(["FEDRAT/7", "POSITN/FINE", "ROTATE/TABLE,ATANGL,23,CLW"], machine)
    (block,) = [b for b in result.blocks if b.code is Code.ROTARY_ABSOLUTE]
    assert block.cells[2] == 52.0
    plain = post(["FEDRAT/7", "ROTATE/TABLE,ATANGL,23,CLW"], text_machine)
    assert [b.cells[2] for b in plain.blocks if b.code is Code.ROTARY_ABSOLUTE] == [80.0]


def mach23(**options: float) -> MachineDefinition:
    loaded = get_plugins().machine("mach23").load()
    return loaded.with_options({int(k[1:]): v for k, v in options.items()})


def rotary_punches(result: RunResult) -> list[str]:
    return [b.punch or "" for b in result.blocks if b.code is Code.ROTARY_INCREMENTAL]


def test_table_rapid_on_a_contouring_machine() -> None:
    """RAPID, then 30 degrees (0.0833 rev = 29.988 degrees after rounding): ROTRAP = 0.5
    RPM (option 115) x 2 pi x 6 in = 18.85 IPM over an arc of 3.1403 in; under G10
    (GDIMUL 100) the feedrate number is 100 x 18.85 / 3.1403 = 600.2 -> F600. MACH23's
    option 45 = 500 holds it to F500; option 45 < 0 outputs none. The rapid is one shot:
    the next turn is at feed (F318, as test_rotary's MACH23 example)."""
    lines = ["FEDRAT/10", "RAPID", "ROTATE/TABLE,INCR,30", "ROTATE/TABLE,INCR,30"]
    result = post(lines, mach23(o45=999.0, o115=0.5))
    assert rotary_punches(result) == ["N003G10A+0833F600", "N004G10A+0834F318"]
    rapid = next(b for b in result.blocks if b.code is Code.ROTARY_INCREMENTAL)
    assert rapid.rapid
    assert float(rapid.cells[19]) == pytest.approx(0.5 * 2 * math.pi * 6)  # type: ignore[arg-type]
    arc = math.radians(0.0833 * 360) * 6
    assert rapid.cut_minutes == pytest.approx(arc / (6 * math.pi))
    held = post(lines, mach23(o115=0.5))
    assert rotary_punches(held)[0] == "N003G10A+0833F500"
    silent = post(lines, mach23(o45=-1.0, o115=0.5))
    assert rotary_punches(silent)[0] == "N003G10A+0833"


def test_rapid_covers_every_segment_of_the_turn_and_ends_there() -> None:
    """90 degrees are three blocks on MACH23: all at the table's rapid; the GOTO after is
    at feed."""
    lines = ["FROM/0,0,0", "FEDRAT/10", "RAPID", "ROTATE/TABLE,INCR,90", "GOTO/1,0,0"]
    result = post(lines, mach23(o45=999.0, o115=0.5))
    turns = [b for b in result.blocks if b.code is Code.ROTARY_INCREMENTAL]
    assert [b.rapid for b in turns] == [True, True, True]
    (move,) = [b for b in result.blocks if b.code is Code.LINEAR]
    assert not move.rapid


def test_option_120_minus_1_a_positive_command_turns_ccw() -> None:
    """Option 120 = -1 (001 L25815-25842): the table turns CCLW for a positive command, so
    30 degrees CLW go out negative and 30 CCLW positive (the carried difference cancels
    on the way back: 0.0833 each way)."""
    lines = ["FEDRAT/10", "ROTATE/TABLE,INCR,30,CLW", "ROTATE/TABLE,INCR,30,CCLW"]
    result = post(lines, mach23(o120=-1.0))
    assert rotary_punches(result) == ["N002G10A-0833F318", "N003G10A+0833"]
    standard = post(lines, mach23())
    assert rotary_punches(standard) == ["N002G10A+0833F318", "N003G10A-0833"]
