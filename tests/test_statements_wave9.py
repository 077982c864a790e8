"""The last not-yet-supported statement and control forms (issue 22 wave 9): the 7500's mixed
control with options 140 and 86 < 0, GOHOME of ROTATE's head and table (options 187-190),
LOAD/TOOL without a transform class, SELECT/HED's rapid gear shifts (TABLEM 142-153),
FEDRAT's feed range dwell by the MACFUN (option 93 < 0), spindle off by S0 without an S
register, magic three out of its range (EIACOM), inverse time for a code past the chart
(option 10 < 0) and A/D testing (option 55) with F as the feed itself, on multiaxis and
multihead machines. The readings are in docs/decisions.md ("issue 22 wave 9")."""

from __future__ import annotations

from pathlib import Path

import pytest
from gecent.core.dispatch.post import post as post_file
from gecent.core.errors import InputError, MachineDefinitionError
from gecent.core.families import HookPoint, HookResult, Macfun
from gecent.core.feed.contour import MAGIC_THREE_RANGE, FeedCommand
from gecent.core.machine.definition import MachineDefinition
from gecent.core.macros.macfun import MacfunContext
from gecent.core.motion.positioning import NEGATIVE_Z
from gecent.core.output.block import Code
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import PluginSet, get_plugins
from gecent.core.run import Run, RunResult

from tests.test_macfun_engine import with_macfun
from tests.test_mixed_control import m7500
from tests.test_mixed_control import tape as mixed_tape
from tests.test_multihead import SEQUENCING
from tests.test_post_linear import post
from tests.test_rotary_positioning import machine as rotaba_machine
from tests.test_rotary_positioning import table_blocks
from tests.test_statement_forms import overlaid


def texts(result: RunResult) -> list[str]:
    return [d.text for d in result.diagnostics]


# -- 1. the 7500's mixed control with options 140 and 86 < 0 ---------------------------------

MIXED_PROGRAM = [
    "FROM/0,0,5",
    "FEDRAT/10",
    "RAPID",
    "GOTO/1,1,5",
    "RAPID",
    "GOTO/1,1,1",
    "GOTO/3,1,1",
    "GOTO/3,3,1",
    "RAPID",
    "GOTO/3,3,5",
]


def test_mixed_control_z_inversion_moves_the_positions_not_the_departures() -> None:
    """Option 140 = 10: the positions' Z is 10 less (5 -> Z-5, 1 -> Z-9: the XY block
    first, Z unchanged at -5 is not output); the contouring departures X+2, Y-2 are the
    same as without it (test_mixed_control's first tape), F = 10 x 10 / 2 = 50."""
    assert mixed_tape(MIXED_PROGRAM, m7500("140 = 10.0\n")) == [
        "N004G80X+010000Y-010000F99",
        "N006Z-090000",
        "N007G01X+02F50",
        "N008Y-02",
        "N010G80Z-050000F99",
    ]
    result = post(MIXED_PROGRAM, m7500("140 = 10.0\n"))
    assert NEGATIVE_Z in texts(result)


def test_mixed_control_tool_length_changed_under_positioning_moves_the_next_departure() -> None:
    """Option 86 < 0, LOADTL LENGTH 2: the nose stands 2 above the tip, so Z1 is Z+3. Tool 2
    (LENGTH 3) is loaded there: the nose is still at 3, the new tip at 0, so the contour to
    (3,1,1) departs X+2 Z+1 (F = 10 x 10 / sqrt 5 = 44.7 -> 45); the rapid up to Z5 is the
    nose at 5 + 3 = Z+8."""
    lines = [
        "LOADTL/1,LENGTH,2",
        "FROM/0,0,5",
        "FEDRAT/10",
        "RAPID",
        "GOTO/1,1,5",
        "RAPID",
        "GOTO/1,1,1",
        "LOADTL/2,LENGTH,3",
        "GOTO/3,1,1",
        "GOTO/3,3,1",
        "RAPID",
        "GOTO/3,3,5",
    ]
    moves = [
        line
        for line in mixed_tape(lines, m7500("86 = -1.0\n"))
        if "X" in line or "Y" in line or "Z" in line
    ]
    assert moves == [
        "N005G80X+010000Y-010000F99",
        "N007Z+030000",
        "N009G01X+02Z+01F45",
        "N010Y-02F50",
        "N012G80Z+080000F99",
    ]


def test_mixed_control_gohome_after_contouring_is_a_position_in_the_shifted_frame() -> None:
    """GOHOME on the 7500 is a positioning move: home (0, 0, 0) is the machine's, so with
    option 140 = 10 the Z position is 0 (not -10) after a contour left the point in the
    contouring frame; X, Y go out as positions, Z in its own block (option 130 = +1), at
    feed type 0's F = 2 x 10 IPM = 20."""
    lines = ["FROM/0,0,5", "FEDRAT/10", "GOTO/2,0,5", "GOHOME"]
    assert mixed_tape(lines, m7500("140 = 10.0\n")) == [
        "N003G01X+02F50",
        "N004G80X+000000Y+000000F20",
        "N004Z+000000",
    ]


# -- 2. GOHOME of ROTATE's devices; LOAD/TOOL without a class ------------------------------


def _mach23(**options: float) -> MachineDefinition:
    machine = get_plugins().machine("mach23").load()
    return machine.with_options({int(k[1:]): v for k, v in options.items()})


def test_gohome_turns_a_contouring_machines_table_home_the_shorter_way() -> None:
    """MACH23 (one rotary register, A, in revolutions) with option 188 = 90: GOHOME moves the
    slides home, then the table ATANGL 90 as ROTATE/TABLE,ATANGL,90 makes it: the same
    blocks, a quarter revolution in all."""
    home = post(["FROM/1,1,1", "FEDRAT/10", "GOHOME"], _mach23(o188=90.0))
    by_hand = post(["FROM/1,1,1", "FEDRAT/10", "GOHOME", "ROTATE/TABLE,ATANGL,90"], _mach23())
    assert _unnumbered(home) == _unnumbered(by_hand)
    turns = [b for b in home.blocks if b.code is Code.ROTARY_INCREMENTAL]
    assert sum(float(b.cells[6]) for b in turns) == pytest.approx(0.25)


def _unnumbered(result: RunResult) -> list[str]:
    """The tape without sequence numbers (GOHOME's turn has GOHOME's record number)."""
    return [line[4:] if line.startswith("N") else line for line in tape_lines(result.blocks)]


def test_gohome_turns_a_positioning_machines_table_to_its_home_reading() -> None:
    """The ROTABA machine (table B in degrees, format 33, CODE +2 blocks) with option 188 =
    45: after the POSMOV home, the one table block B045 as ROTATE/TABLE,ATANGL,45 makes
    it (ROTABA's E feed and all)."""
    home = post(["FROM/1,1,1", "FEDRAT/7", "GOHOME"], rotaba_machine(o188=45.0))
    by_hand = post(["FROM/1,1,1", "FEDRAT/7", "GOHOME", "ROTATE/TABLE,ATANGL,45"], rotaba_machine())
    assert _unnumbered(home) == _unnumbered(by_hand)
    assert len(table_blocks(home)) == 1 and "B045" in table_blocks(home)[0]


def test_gohome_of_a_third_rotary_or_secondary_axis_needs_a_transform_class() -> None:
    for number in (189, 190):
        machine = _mach23(**{f"o{number}": 5.0})
        with pytest.raises(InputError, match=f"option {number} = 5"):
            post(["FROM/1,1,1", "GOHOME"], machine)


def test_gohome_of_a_table_without_a_rotary_register_is_bad_input() -> None:
    machine = get_plugins().machine("standard").load().with_options({188: 30.0})
    with pytest.raises(InputError, match="no rotary register") as caught:
        post(["FROM/1,1,1", "GOHOME"], machine)
    assert caught.value.where is not None and caught.value.where.line == 2


def test_load_tool_on_a_contouring_machine_without_a_class_is_bad_input() -> None:
    with pytest.raises(InputError, match=r"OPTAB\(116\) must be set") as caught:
        post(["FROM/0,0,0", "LOAD/TOOL,3"])
    assert "L33922" in str(caught.value) and caught.value.where is not None


# -- 3. SELECT/HED,n: the selected head's rapid gear shifts -----------------------------------

# the Standard Machine (one feed range) with head codes and X's gears of heads 1 and 2
HEADS = """[tablem]
42 = 40
43 = 41
125 = 51
126 = 52
142 = 44
143 = 45
[optab]
46 = -300.0
"""
RAPID_AND_BACK = ["FEDRAT/10", "RAPID", "GOTO/5,0,0", "GOTO/6,0,0"]


def test_select_hed_2_shifts_head_2s_gears_into_rapid_and_back() -> None:
    """Option 46 < 0 shifts X's gears only, each shift between its dwells (options 16, 81,
    82): head 1's TABLEM(42)/(43) = M40/M41; once SELECT/HED,2 (M52) has set TLHEAD, head
    2's (142)/(143) = M44/M45 (001 L7270-7278)."""
    machine = overlaid("standard", HEADS)
    one = tape_lines(post(["FROM/0,0,0", *RAPID_AND_BACK], machine).blocks)
    assert [line[4:] for line in one if "M" in line] == ["G04X+02M40", "G04X+01M41"]
    two = tape_lines(post(["FROM/0,0,0", "SELECT/HED,2", *RAPID_AND_BACK], machine).blocks)
    assert [line[4:] for line in two if "M" in line] == ["M52", "G04X+02M44", "G04X+01M45"]


def test_a_head_without_its_own_gear_codes_shifts_none() -> None:
    """Head 3 has no TABLEM(148)-(153) here: its rapid is made without a gear shift, as
    a head-2 cell left absent leaves head 2 without it in a multihead run."""
    machine = overlaid("standard", HEADS.replace("126 = 52\n", "126 = 52\n127 = 53\n"))
    three = tape_lines(post(["FROM/0,0,0", "SELECT/HED,3", *RAPID_AND_BACK], machine).blocks)
    assert [line[4:] for line in three] == ["M53", "G01X+5F400", "X+1F100"]


def test_a_head_change_in_rapid_shifts_the_old_heads_gears_back() -> None:
    machine = overlaid("standard", HEADS)
    lines = ["FROM/0,0,0", "FEDRAT/10", "RAPID", "GOTO/5,0,0", "SELECT/HED,2", "GOTO/6,0,0"]
    codes = [line[4:] for line in tape_lines(post(lines, machine).blocks) if "M" in line]
    assert codes == ["G04X+02M40", "G04X+01M41", "M52"]


# -- 4. FEDRAT's feed range change dwell by the machine's MACFUN ----------------------------

RANGES = "[optab]\n93 = -2.0\n133 = 1.0\n"


def _ranges_run(plugins: PluginSet) -> Run:
    machine = overlaid("mach04", RANGES)
    run = Run(machine, plugins)
    from gecent.core.cl.apt_source import AptSourceReader

    run.process(AptSourceReader("part.apt").read_lines(["FEDRAT/1,RANGE,2", "FINI"]))
    return run


def test_option_93_below_zero_calls_the_feed_range_hook_which_dwells() -> None:
    """The MACFUN gets the new range and the dwell option 93 asks (2 s) and outputs it."""
    calls: list[tuple[float, ...]] = []

    def dwell(context: MacfunContext) -> HookResult:
        calls.append(context.values)
        context.output(context.run.output.dwell(context.values[1]))
        return HookResult.CONTINUE

    plugins = with_macfun(Macfun("ranges", "mach04-forms", "test", {HookPoint.FEED_RANGE: dwell}))
    run = _ranges_run(plugins)
    assert calls == [(2.0, 2.0)]
    dwells = [b for b in run.result.blocks if b.dwell_minutes]
    assert len(dwells) == 1 and dwells[0].dwell_minutes == pytest.approx(2.0 / 60)


def test_option_93_below_zero_without_the_hook_is_a_machine_file_error() -> None:
    with pytest.raises(MachineDefinitionError, match="no feed range hook"):
        _ranges_run(get_plugins())


# -- 5. spindle off by S0 without an S register ---------------------------------------------


def test_spindle_off_by_s0_without_an_s_register_is_a_machine_file_error() -> None:
    machine = overlaid("standard", "[regfor]\n12 = 0.0\n[optab]\n127 = 1.0\n")
    assert machine.registers.formats[12] is None
    with pytest.raises(MachineDefinitionError, match="option 127 = 1"):
        post(["FROM/0,0,0", "SPINDL/OFF"], machine)


# -- 6. magic three out of range, inverse time past the chart, A/D --------------------------


def test_magic_three_out_of_range_comments_and_takes_the_nearest_code() -> None:
    """EIACOM converts 0.0001 to 9999 (001 L30854-30904, appendix 7.1): .00005 IPM gets the
    comment and code 010 (.0001); 20000 IPM gets 810 (9999 rounds to two digits: 10000)."""
    machine = get_plugins().machine("standard").load().with_options({10: 1.0})
    command = FeedCommand(machine)
    assert command.command(0.00005, 1.0, 1.0, 2)[:2] == (10.0, pytest.approx(0.0001))
    assert command.command(20000.0, 1.0, 1.0, 2)[:2] == (810.0, 10000.0)
    assert [d.text for d in command.diagnostics] == [MAGIC_THREE_RANGE] * 2
    assert command.command(40.0, 1.0, 1.0, 2)[:2] == (540.0, 40.0)  # appendix 7.1's form
    assert len(command.diagnostics) == 2


def test_inverse_time_past_the_chart_takes_its_largest_codes_row() -> None:
    """Option 10 = -1 charts G11, G01, G10 only (001 L11113-11146): a G23 block (TABLEG
    14) takes G10's row, REGFOR 33, 0.01 to 9.999; 150 in. at 30 IPM: 30/150 = 0.2."""
    machine = get_plugins().machine("standard").load().with_options({10: -1.0})
    assert FeedCommand(machine).command(30.0, 1.0, 150.0, 14) == (0.2, 30.0, 33.0)
    assert FeedCommand(machine).command(30.0, 1.0, 150.0, 15) == (0.2, 30.0, 33.0)


def _ad(tmp_path: Path, machin: str) -> list[str]:
    source = tmp_path / "p.apt"
    body = ["PARTNO AD", machin, "FROM/0,0,0", "FEDRAT/60", "GOTO/2,0,0", "GOTO/2,2,0", "FINI"]
    source.write_text("\n".join([*body, ""]))
    return tape_lines(post_file(str(source), get_plugins()).blocks)


def test_ad_with_f_as_the_feed_itself_gives_each_piece_its_feed(tmp_path: Path) -> None:
    """test_ad_testing's corner on MACH23 with option 254 = 1: the same pieces (D .0262
    before the corner, U .0061 after it), each F the piece's feed in MACH23's F format
    (3 whole digits): 60, F1 = 10.4895 -> 010, F2 = 2.4551 -> 002."""
    assert _ad(tmp_path, "MACHIN/GECENT,23,OPTAB,55,1,OPTAB,254,1") == [
        "AD",
        "N005G01X+019738F060",
        "N005G11X+000262F010",
        "N006G11Y+000061F002",
        "N006G01Y+019677F060",
        "N006G11Y+000262F010",
    ]


def test_ad_on_a_multiaxis_machine_is_bad_input() -> None:
    machine = get_plugins().machine("mach40").load()
    machine = machine.with_options({55: 1.0, **{n: 0.1 for n in (3, 32, 69, 70, 71)}})
    machine = machine.with_options({72: 0.001, 73: 28.0, 74: 145.0})
    with pytest.raises(InputError, match="multiaxis machine"):
        post(["FROM/-19,48,31.75", "FEDRAT/10", "GOTO/-18,48,31.75"], machine)


def test_ad_on_a_multihead_program_is_bad_input_not_left_out() -> None:
    """The manual's sequencing example (two heads, MACH51, whose servo constants are set)
    with option 55 = 1: refused, where before the heads' runs silently made no A/D."""
    plugins = get_plugins()
    machine = plugins.machine("mach51").load().with_options({55: 1.0})
    with pytest.raises(InputError, match=r"multihead machine.*L25094-25108"):
        post_file(str(SEQUENCING), plugins, machine_override=machine)


# -- 7. the handlers reach the run's elements through the Post protocol -----------------------


def test_the_post_protocol_gives_handlers_the_motion_elements() -> None:
    """GOHOME, LOAD and ROTATE reach the run's motion, positioning and multiaxis elements
    through the Post contract (core/dispatch/context.py), not by a test of the run."""
    from gecent.core.dispatch.context import Post

    for name in ("motion", "positioning", "multiaxis"):
        assert isinstance(getattr(Post, name), property)
        assert isinstance(getattr(Run, name), property)
