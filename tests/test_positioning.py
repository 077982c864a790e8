"""Positioning machines (option 1 = 1, overlay GEPOS) on the sample drill MACH24: POSMOV's
absolute blocks, CODE +16/-16 by option 130, option 40's repeated X/Y, POSFED's feed
command, rapid, the control's own cycles (CYCLGP, RAPIDP) and TOOLGP (manual §2.4.1,
001 L1043-1178; flow chart 9, 001 L19849-19935; POSMOV L34934-34992; POSIT/POSFED
L34780-34878; CYCLGP L30095-30204; RAPIDP L35274-35313; TOOLGP L38648-38692).

MACH24: X, Y, Z formats -24 (sign, 2.4 digits), option 59 = 132415 (+X -Y +Z), feed type 0
with K = 2 (option 78 unset), option 45 = 99 (the rapid command), TABLEG(1) = G80 and the
cycles G81..G87 at TABLEG 82..88, R register at location 16 (format -22).
"""

from __future__ import annotations

import pytest
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.output.block import Code
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post


def mach24(overlay: str = "") -> MachineDefinition:
    base = get_plugins().machine("mach24").load()
    if not overlay:
        return base
    return load_machine_text(f'[machine]\nname = "mach24-test"\n{overlay}', "test.toml", base=base)


def tape(lines: list[str], machine: MachineDefinition | None = None) -> list[str]:
    return tape_lines(post(lines, machine or mach24()).blocks)


def test_xy_positions_are_absolute_and_z_is_ignored_under_option_130_0() -> None:
    """POSMOV: CODE +16 with absolute X and Y (Y negated by option 59 = 132415); option 130
    = 0 ignores Z; G80 (TABLEG(1)) with no cycle; F = 2 x 10 IPM (feed type 0, K = 2); a
    repeated Y is left out (option 40 = 1, 001 L24919-24927)."""
    blocks = tape(["FROM/0,0,5", "FEDRAT/10", "GOTO/1,1,5", "GOTO/3,1,2", "GOTO/3,1,0"])
    assert blocks == ["N003G80X+010000Y-010000F20", "N004X+030000"]


def test_a_zero_position_is_punched_although_option_51_deletes_zero_words() -> None:
    """Option 51 = 0 deletes zero departures; a zero position is a target (decision)."""
    blocks = tape(["FROM/1,1,5", "FEDRAT/10", "GOTO/0,2,5", "GOTO/0,0,5"])
    assert blocks == ["N003G80X+000000Y-020000F20", "N004Y+000000"]


def test_option_40_0_repeats_both_coordinates() -> None:
    machine = mach24("[optab]\n40 = 0.0\n")
    blocks = tape(["FROM/0,0,5", "FEDRAT/10", "GOTO/1,1,5", "GOTO/3,1,5"], machine)
    assert blocks == ["N003G80X+010000Y-010000F20", "N004X+030000Y-010000"]


def test_option_130_plus_1_puts_z_in_a_block_of_its_own() -> None:
    """Option 130 = +1: the XY block, then CODE -16 with Z alone; an unchanged coordinate
    is not output (flow chart 9)."""
    machine = mach24("[optab]\n130 = 1.0\n")
    result = post(["FROM/0,0,5", "FEDRAT/10", "GOTO/1,1,5", "GOTO/1,1,2", "GOTO/2,2,0"], machine)
    assert tape_lines(result.blocks) == [
        "N003G80X+010000Y-010000F20",
        "N004Z+020000",
        "N005X+020000Y-020000",
        "N005Z+000000",
    ]
    codes = [b.code for b in result.blocks if b.code not in (Code.FROM, Code.FINI)]
    assert codes == [Code.POSITION_XY, Code.POSITION_Z, Code.POSITION_XY, Code.POSITION_Z]


def test_option_130_minus_1_puts_x_y_and_z_in_one_block() -> None:
    machine = mach24("[optab]\n130 = -1.0\n")
    blocks = tape(["FROM/0,0,5", "FEDRAT/10", "GOTO/1,1,5", "GOTO/1,1,2", "GODLTA/1,1,-2"], machine)
    assert blocks == [
        "N003G80X+010000Y-010000Z+050000F20",
        "N004Z+020000",
        "N005X+020000Y-020000Z+000000",
    ]


def test_rapid_is_the_option_45_command_and_one_shot() -> None:
    """A rapid positioning block carries option 45's command (99 on MACH24); the next move
    is back at the programmed feed (option 109 = 0)."""
    result = post(["FROM/0,0,5", "FEDRAT/10", "RAPID", "GOTO/4,3,5", "GOTO/5,3,5"], mach24())
    assert tape_lines(result.blocks) == ["N004G80X+040000Y-030000F99", "N005X+050000F20"]
    rapid, fed = result.blocks[-3:-1]
    assert rapid.rapid and not fed.rapid
    assert float(fed.cells[19]) == 10.0  # type: ignore[arg-type]


def test_cut_time_is_the_distance_over_the_feed() -> None:
    result = post(["FROM/0,0,5", "FEDRAT/10", "GOTO/3,4,5"], mach24())
    assert result.blocks[-2].cut_minutes == pytest.approx(0.5)


def test_control_cycle_block_then_each_hole_runs_it() -> None:
    """CYCLGP: one CODE -16 block with the cycle G (DRILL: TABLEG(82) = G81), Z = the plunge
    and R = the rapid distance, both down from the tool's height 5: a hole top 0 with DEPTH
    0.6 and CLEAR 0.1 gives Z 5.6, R 4.9; each XY position then runs the cycle. A hole top
    at -0.5 makes a new cycle block; CYCLE/OFF brings back G80 (001 L30164-30178)."""
    result = post(
        [
            "FROM/0,0,5",
            "CYCLE/DRILL,DEPTH,0.6,IPM,6,CLEAR,0.1",
            "GOTO/1,1,0",
            "GOTO/3,1,0",
            "GOTO/3,2,-0.5",
            "CYCLE/OFF",
            "GOTO/0,0,5",
        ],
        mach24(),
    )
    assert tape_lines(result.blocks) == [
        "N003G81Z+056000F12R+049",
        "N003X+010000Y-010000",
        "N004X+030000",
        "N005Z+061000R+054",
        "N005Y-020000",
        "N007G80X+000000Y+000000",
    ]
    assert result.blocks[1].code is Code.POSITION_Z
    assert result.blocks[-2].position == (0, 0, 50000)  # the tool stayed at its height


def test_without_an_r_register_the_rapid_distance_is_a_rapid_z_block() -> None:
    """RAPIDP (001 L35274-35313): no R register, so R goes out as a rapid Z move in a block
    of its own, and the cycle's Z is the rest of the plunge (0.6)."""
    machine = mach24("[regfor]\n16 = 0.0\n")
    blocks = tape(
        ["FROM/0,0,5", "CYCLE/DRILL,DEPTH,0.5,IPM,6,CLEAR,0.1", "GOTO/4,4,0", "GOTO/5,4,0"],
        machine,
    )
    assert blocks == [
        "N003G80Z+001000F99",
        "N003G81Z+006000F12",
        "N003X+040000Y-040000",
        "N004X+050000",
    ]


def test_a_hole_above_the_tool_is_refused() -> None:
    with pytest.raises(InputError, match="not above the hole"):
        tape(["FROM/0,0,1", "CYCLE/DRILL,DEPTH,0.5,IPM,6,CLEAR,2", "GOTO/4,4,0"])


def test_a_cycle_the_control_lacks_is_named() -> None:
    machine = mach24('[tableg]\n82 = "absent"\n')
    with pytest.raises(InputError, match=r"TABLEG\(82\)"):
        tape(["FROM/0,0,5", "CYCLE/DRILL,DEPTH,0.5,IPM,6,CLEAR,0.1", "GOTO/4,4,0"], machine)


VARIABLE_SPINDLE = """
[regfor]
12 = 30.0
[optab]
19 = 1.0
7 = 1.0
8 = 2.0
[spindle_table]
speeds = [10.0, 3000.0]
"""


def test_toolgp_outputs_g80_and_t_and_the_spindle_command_rides_with_it() -> None:
    """TOOLGP (001 L38648-38692): the T goes out at once with G80 in a CODE -1 block; the
    present spindle command rides with every T (001 L1165-1166: S712 = 1200 RPM)."""
    machine = mach24(VARIABLE_SPINDLE)
    result = post(["FROM/0,0,5", "SPINDL/1200,CLW", "LOADTL/2", "FEDRAT/10", "GOTO/1,1,5"], machine)
    assert tape_lines(result.blocks) == [
        "N002S712",
        "N003G80S712T02",
        "N005G80X+010000Y-010000F20",
    ]


def test_option_1_minus_1_does_not_merge_s_with_t() -> None:
    machine = mach24(VARIABLE_SPINDLE.replace("[optab]", "[optab]\n1 = -1.0"))
    assert tape(["FROM/0,0,5", "SPINDL/1200,CLW", "LOADTL/2"], machine)[-1] == "N003G80T02"


def test_option_140_moves_z_by_the_spindle_nose_distance() -> None:
    """Option 140 = N: "DATACL = DATACL - OPTAB(140)" (flow chart 9, 001 L19870-19876)."""
    machine = mach24("[optab]\n130 = 1.0\n140 = 2.0\n")
    blocks = tape(["FROM/0,0,5", "FEDRAT/10", "GOTO/0,0,4"], machine)
    assert blocks == ["N003G80Z+020000F20"]


def test_slide_limits_are_tested_on_positions() -> None:
    """TSTLIM on the absolute X and Y (001 L1153): X 0..2 is exceeded at 3."""
    machine = mach24("[optab]\n110 = 1.0\n121 = 2.0\n122 = 0.0\n123 = 9.0\n124 = -9.0\n")
    result = post(["FROM/0,0,5", "FEDRAT/10", "GOTO/1,1,5", "GOTO/3,1,5"], machine)
    assert [(d.where.record if d.where else None, d.text) for d in result.diagnostics] == [
        (4, "X AXIS SLIDE LIMIT HAS BEEN EXCEEDED *** WARNING")
    ]


def test_feed_type_5_z_and_xy_tables_end_to_end() -> None:
    """E10 (001 L11476-11556) through a post: the manual's type-5 tables on MACH24 with
    option 130 = +1. FEDRAT/40,RANGE,2: the XY block is F32 at 35.9 IPM, the Z block F25
    at 15.1 IPM, each printed as the feed really made."""
    example = get_plugins().get("feedtypes", 5).manual_example
    machine = load_machine_text(example, "type5.toml", base=mach24("[optab]\n130 = 1.0\n"))
    result = post(["FROM/0,0,5", "FEDRAT/40,RANGE,2", "GOTO/1,1,5", "GOTO/1,1,2"], machine)
    assert tape_lines(result.blocks) == ["N003G80X+010000Y-010000F32", "N004Z+020000F25"]
    assert [float(b.cells[19]) for b in result.blocks[1:3]] == [35.9, 15.1]  # type: ignore[arg-type]


def test_a_repeated_hole_position_runs_the_cycle_again() -> None:
    """A hole at the present XY still gets a block, with X and Y (decision): the control
    runs its cycle on a positioning block. A new cycle sets its Z and R again."""
    blocks = tape(
        [
            "FROM/0,0,5",
            "CYCLE/DRILL,DEPTH,0.6,IPM,6,CLEAR,0.1",
            "GOTO/1,1,0",
            "CYCLE/BORE,DEPTH,0.6,IPM,3,CLEAR,0.1",
            "GOTO/1,1,0",
        ]
    )
    assert blocks == [
        "N003G81Z+056000F12R+049",
        "N003X+010000Y-010000",
        "N005G85Z+056000F06R+049",
        "N005X+010000Y-010000",
    ]
