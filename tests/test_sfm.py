"""SFM, constant surface speed (manual §4.4, 001 L14230-14549): the worked examples SFM-1 to
SFM-7 of spec 06 §11.2, the variable spindle's option-15 step, the five end conditions, the
statement, leaving the mode, and whole programs on lathes, block by block.

The manual computes its example with the constants rounded to 1.9 (= 12/(2 pi)) and 0.95
(= 12/(4 pi)); gecent uses the exact constants, so the tests expect 38.197 RPM (manual 38),
shift radii 1.11408 (manual 1.1, i.e. 1.108), 1.59155 (manual: not printed, 1.583) and
2.22817 (manual 2.2, i.e. 2.217), and 2.72837 RPM for Diagram 4.4E (manual "2.86").
"""

from __future__ import annotations

from math import pi

import pytest
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.errors import InputError, MachineDefinitionError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.motion.sfm import (
    EndCondition,
    Piece,
    SpeedLadder,
    plan,
    shift_radius,
    spindle_speed,
    step_fraction,
    surface_cuts,
)
from gecent.core.output.block import Code
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins
from gecent.core.run import Run
from gecent.core.state import SFM

from tests.test_post_linear import post

MANUAL_TABLE = (15.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0)  # Diagram 4.4B
CANNOT_START_TABLE = (10.0, 20.0, 30.0, 40.0, 50.0, 60.0)  # Diagram 4.4E

# MACH04 with the manual's discrete table on a type 5 spindle (one range, magic three S,
# option 90 = -1 as type 5 requires) and M03/M04 for the direction.
DISCRETE_LATHE = """
[machine]
name = "sfm-lathe"
title = "SFM LATHE"
[optab]
7 = 1.0
8 = 8.0
19 = 5.0
90 = -1.0
137 = 0.0
[tablem]
4 = 3
5 = 4
[spindle_table]
speeds = [15.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0]
"""

# The Standard Machine with Diagram 4.4E's table on a type 5 spindle.
CANNOT_START_MILL = """
[machine]
name = "sfm-4-4e"
title = "DIAGRAM 4.4E"
[optab]
7 = 1.0
8 = 6.0
19 = 5.0
90 = -1.0
[spindle_table]
speeds = [10.0, 20.0, 30.0, 40.0, 50.0, 60.0]
"""


def mach04() -> MachineDefinition:
    return get_plugins().machine("mach04").load()


def discrete_lathe() -> MachineDefinition:
    return load_machine_text(DISCRETE_LATHE, "sfm-lathe.toml", base=mach04())


def overlay(options: str, base: MachineDefinition) -> MachineDefinition:
    """``base`` with some options changed (an [optab] body)."""
    text = f'[machine]\nname = "overlay"\ntitle = "OVERLAY"\n[optab]\n{options}\n'
    return load_machine_text(text, "overlay.toml", base=base)


def run_of(lines: list[str], machine: MachineDefinition) -> Run:
    run = Run(machine)
    run.process(AptSourceReader("part.apt").read_lines([*lines, "FINI"]))
    return run


def comments(lines: list[str], machine: MachineDefinition) -> list[str]:
    return [d.text for d in post(lines, machine).diagnostics]


def cuts(lines: list[str], machine: MachineDefinition) -> list[tuple[int, ...] | None]:
    """The points reached by the motion blocks of the last record."""
    blocks = [b for b in post(lines, machine).blocks if b.code is Code.LINEAR]
    last = blocks[-1].record
    return [b.position for b in blocks if b.record == last]


# -- the formulas and the discrete example (SFM-1 .. SFM-5) --------------------------------


def test_sfm_1_start_speed_is_bracketed_by_30_and_40() -> None:
    """SFM-1 (001 L14267-14320): S = 12 x 20 / (2 pi x 1) = 38.197 RPM (the manual's
    1.9 x 20 = 38), between the table speeds 30 and 40."""
    speed = spindle_speed(20.0, 1.0)
    assert speed == pytest.approx(38.197186, abs=1e-6)
    assert speed == pytest.approx(240.0 / (2 * pi))
    assert 30.0 < speed < 40.0


def test_sfm_2_3_shift_radii() -> None:
    """SFM-2 and SFM-3 (001 L14323-14352): 40 -> 30 at 1.11408 (manual 0.95 x 20 x (1/40 +
    1/30) = 1.108, "~ 1.1"), 30 -> 20 at 1.59155 (manual's point C, not printed, 1.583),
    20 -> 15 at 2.22817 (manual "~ 2.2", 2.217)."""
    assert shift_radius(20.0, 40.0, 30.0) == pytest.approx(1.1140846, abs=1e-7)
    assert shift_radius(20.0, 30.0, 20.0) == pytest.approx(1.5915494, abs=1e-7)
    assert shift_radius(20.0, 20.0, 15.0) == pytest.approx(2.2281692, abs=1e-7)


def test_sfm_4_pieces_ab_bc_cd() -> None:
    """SFM-4 (001 L14361-14364): A at R = 1, the part end D at R = 2.0, between the shift
    radii 1.59 and 2.23 as the narrative needs: AB at 40, BC at 30, CD at 20; the 20 -> 15
    shift lies beyond D, which ends the sequence (end condition 2)."""
    ladder = SpeedLadder(15.0, 80.0, MANUAL_TABLE)
    result = plan(20.0, 1.0, 2.0, ladder)
    assert result.pieces == (
        Piece(40.0, shift_radius(20.0, 40.0, 30.0)),
        Piece(30.0, shift_radius(20.0, 30.0, 20.0)),
        Piece(20.0, None),
    )
    assert result.end is EndCondition.SHIFT_BEYOND_END


def test_sfm_4_shift_points_on_the_path() -> None:
    """The path A (0, 1) -> D (-1, 2) at a step of 0.0001 in, radius = |y|: B where y =
    1.1140846 (11141 steps, x -1141), C where y = 1.5915494 (15915, x -5915), then D."""
    ladder = SpeedLadder(15.0, 80.0, MANUAL_TABLE)
    path = surface_cuts((0, 10000, 0), (-10000, 20000, 0), 1, 0.0, 20.0, ladder, 0.0001)
    assert [(c.point, c.speed) for c in path.cuts] == [
        ((-1141, 11141, 0), 40.0),
        ((-5915, 15915, 0), 30.0),
        ((-10000, 20000, 0), 20.0),
    ]
    assert path.ends == (EndCondition.SHIFT_BEYOND_END,)


def test_sfm_1_to_5_on_a_lathe_block_by_block() -> None:
    """The manual's example through SPINDL/20,SFM on a lathe with the table 15 ... 80 (type
    5: S is the speed's magic three): the spindle starts at the bracket speed 40 for R = 1
    (S540 M03); AB goes at 40, BC carries S530, CD S520. SFM-5 (001 L14354-14359): in IPR
    mode each piece's feed is F_IPR x S = 0.4, 0.3, 0.2 IPM."""
    lines = [
        "FROM/10,1,0",
        "SPINDL/20,SFM,CLW",
        "FEDRAT/0.01,IPR",
        "GOTO/9,2,0",
    ]
    result = post(lines, discrete_lathe())
    motion = [b for b in result.blocks if b.code is Code.LINEAR]
    assert [b.position for b in motion] == [
        (98859, 11141, 0),
        (94085, 15915, 0),
        (90000, 20000, 0),
    ]
    assert [b.cells[19] for b in motion] == pytest.approx([0.4, 0.3, 0.2])
    assert tape_lines(result.blocks) == [
        "N002G04S540M03",
        "N004G11X-01141Z-01141F00248",
        "N004G11X-04774Z-04774F00044S530",
        "N004G11X-04085Z-04085F00035S520",
    ]
    assert [d.text for d in result.diagnostics] == [
        "SFM MODE ESTABLISHED",
        "OPTION FEED RATE RANGE ASSUMED.",
    ]


# -- the statement (SFM-6) ------------------------------------------------------------------


def test_sfm_6_the_statement_sets_the_flags() -> None:
    """SFM-6 (001 L14446-14462): SPINDL/40,SFM,CLW,RANGE,2,RADIUS,YCOORD,MAXIPM,10,MAXRPM,100
    sets SFMFLG = 1, SFMDES = 40, SPNDIR = 1, ISRNGE = 2 with SFMLOK, ISFMOD = 2 (Y),
    SFMAXI = 10, SFMAXR = 100, FLONSP = 1; STATE(5) = 40 (001 L16071-16081). On MACH04 the
    spindle starts at the present point (the centre line: MAXRPM 100, S610) in range 2
    (M62, range 2 CLW)."""
    statement = "SPINDL/40,SFM,CLW,RANGE,2,RADIUS,YCOORD,MAXIPM,10,MAXRPM,100"
    run = run_of([statement], mach04())
    state = run.state
    sfm = state.sfm
    assert sfm.active
    assert sfm.surface_feet == 40.0
    assert state.spindle.direction == 1
    assert sfm.locked_range == 2 and state.spindle.range == 2
    assert sfm.radius_axis == 1 and sfm.fixed_radius == 0.0
    assert state.feed.maximum_ipm == 10.0
    assert sfm.maximum_rpm == 100.0
    assert state.spindle.on and state.spindle.speed == 100.0
    assert state.conditions.values[SFM] == 40.0
    assert tape_lines(run.result.blocks) == ["N001G04S610M62"]
    assert [d.text for d in run.result.diagnostics] == ["SFM MODE ESTABLISHED"]


def test_a_turning_spindle_is_left_alone_and_the_radius_defaults_to_the_x_output() -> None:
    """A spindle turning in the asked direction and range gets no block from the statement;
    without RADIUS the radius is the CL axis the machine outputs as X: CL y on MACH04
    (option 59 = +Z-X), CL x on the Standard Machine."""
    run = run_of(["SPINDL/300,CLW", "SPINDL/100,SFM"], mach04())
    assert tape_lines(run.result.blocks) == ["N001G04S630M62"]
    assert run.state.sfm.radius_axis == 1 and run.state.sfm.locked_range == 2
    assert run_of(["SPINDL/100,SFM"], standard_machine()).state.sfm.radius_axis == 0


@pytest.mark.parametrize(
    "statement",
    [
        "SPINDL/SFM",
        "SPINDL/0,SFM",
        "SPINDL/100,SFM,RPM",
        "SPINDL/100,200,SFM",
        "SPINDL/100,SFM,CLW,CCLW",
        "SPINDL/100,SFM,RADIUS,LEFT",
        "SPINDL/100,SFM,MAXRPM,0",
        "SPINDL/100,SFM,MAXIPM",
        "SPINDL/100,SFM,RANGE,1.5",
        "SPINDL/100,SFM,RADIUS,ZCOORD",
    ],
)
def test_malformed_sfm_statements(statement: str) -> None:
    with pytest.raises(InputError):
        post([statement], mach04())


def test_a_variable_spindle_needs_option_15() -> None:
    machine = overlay("15 = 0.0", mach04())
    with pytest.raises(MachineDefinitionError, match="option 15"):
        post(["SPINDL/100,SFM"], machine)


# -- SFM-7: the sequence cannot start ----------------------------------------------------


def test_sfm_7_the_start_speed_is_not_in_the_table() -> None:
    """SFM-7 (001 L14508-14549): SPINDL/100,SFM at R1 = 70 with the table 10 ... 60 and the
    radius decreasing (ISENSE = +1): S = 12 x 100 / (2 pi x 70) = 2.72837 RPM (the manual's
    "2 x 100 / 70 = 2.86" rounds 12/(2 pi) to 2), below the table: no pieces."""
    ladder = SpeedLadder(10.0, 60.0, CANNOT_START_TABLE)
    result = plan(100.0, 70.0, 10.0, ladder)
    assert result.start_speed == pytest.approx(2.7283704, abs=1e-7)
    assert result.pieces == ()
    assert result.end is None


def test_sfm_7_the_path_keeps_the_current_speed() -> None:
    """The path P1 P2 (P2 at R = 12, where 15.9 RPM would be in the table; the diagram's P2
    is lost) goes out with the current spindle speed, 30 RPM: DEPMAX (9.9999) cuts it in six
    segments, each tried by SFMO (SEGMNT calls it, 001 L1310-1330), none starting below
    the table (the last one starts at R = 21.67, 8.81 RPM); no S after the first block."""
    machine = load_machine_text(CANNOT_START_MILL, "4-4e.toml")
    lines = ["SPINDL/30,CLW", "FROM/70,0,0", "SPINDL/100,SFM", "GOTO/12,0,0"]
    run = run_of(lines, machine)
    assert tape_lines(run.result.blocks) == [
        "N001S530M03",
        "N004G01X-96667F005",
        "N004X-96666",
        "N004X-96667",
        "N004X-96667",
        "N004X-96666",
        "N004X-96667",
    ]
    assert run.state.spindle.speed == 30.0
    assert run.state.sfm.last_end == 0


def test_each_depmax_segment_is_tried_on_its_own() -> None:
    """The same to R = 10 is seven DEPMAX segments of 8.5714: the last starts at R = 18.5714
    (10.28 RPM; the bracket 10/20 shifts at 14.3239 and R = 18.57 lies on 10's side), so
    SFM starts there at 10 RPM (S510) for 4.2475 and shifts to 20 (S520) at R = 14.3239."""
    machine = load_machine_text(CANNOT_START_MILL, "4-4e.toml")
    lines = ["SPINDL/30,CLW", "FROM/70,0,0", "SPINDL/100,SFM", "GOTO/10,0,0"]
    run = run_of(lines, machine)
    assert tape_lines(run.result.blocks)[-2:] == ["N004X-42475F012S510", "N004X-43239S520"]
    assert run.state.sfm.last_end == EndCondition.SHIFT_BEYOND_END


# -- variable spindles: the option-15 step ---------------------------------------------------


@pytest.mark.parametrize(
    ("option", "fraction"), [(0.1, 0.1), (10.0, 0.1), (-0.05, 0.05), (1.0, 0.01)]
)
def test_option_15_is_a_fraction_below_1_else_a_percent(option: float, fraction: float) -> None:
    assert step_fraction(option) == pytest.approx(fraction)


def test_variable_spindle_steps_by_option_15() -> None:
    """Type 10 range 2 (18 ... 600 RPM), option 15 = 10 %: SFM 100 from R = 1 to R = 0.5
    starts at S0 = 190.986 and steps S(k+1) = 1.1 S(k); the shift between S(k) and S(k+1)
    lies at R(k) (1 + 1/1.1) / 2 with R(k) = 1/1.1^k. The next speed, 409.4 RPM, is beyond
    the end's 381.97 RPM and its shift radius 0.4899 beyond the end (condition 2)."""
    ladder = SpeedLadder(18.0, 600.0, None, 0.1)
    result = plan(100.0, 1.0, 0.5, ladder)
    start = 1200.0 / (2 * pi)
    assert [p.speed for p in result.pieces] == pytest.approx([start * 1.1**k for k in range(8)])
    assert [p.until for p in result.pieces[:-1]] == pytest.approx(
        [(1 + 1 / 1.1) / 2 / 1.1**k for k in range(7)]
    )
    assert result.pieces[-1].until is None
    assert result.end is EndCondition.SHIFT_BEYOND_END


def test_option_15_in_percent_gives_the_same_pieces() -> None:
    fraction = plan(100.0, 1.0, 0.5, SpeedLadder(18.0, 600.0, None, step_fraction(0.1)))
    percent = plan(100.0, 1.0, 0.5, SpeedLadder(18.0, 600.0, None, step_fraction(10.0)))
    assert fraction == percent


def test_variable_spindle_with_a_growing_radius_steps_down() -> None:
    """R from 1 to 1.5 (the end's speed 127.32 RPM): 190.99, then -10 % steps 171.89 (shift
    at 1.0556), 154.70 (at 1.1728), 139.23 (at 1.3032); the next, 125.31, is below the end's
    speed, which ends the sequence (condition 2, "S falls outside of S_pL")."""
    result = plan(100.0, 1.0, 1.5, SpeedLadder(18.0, 600.0, None, 0.1))
    start = 1200.0 / (2 * pi)
    assert [p.speed for p in result.pieces] == pytest.approx([start * 0.9**k for k in range(4)])
    assert result.pieces[1].until == pytest.approx(shift_radius(100.0, start * 0.9, start * 0.81))
    assert result.end is EndCondition.SHIFT_BEYOND_END


# -- the other end conditions ---------------------------------------------------------------


def test_maxrpm_ends_a_variable_sequence_at_maxrpm() -> None:
    """MAXRPM 250 (condition 3): 190.99, 210.08, 231.09, then the 10 % step is held to 250
    (TSTSAF holds SPNSPD within SFMAXR) and the sequence ends there."""
    result = plan(100.0, 1.0, 0.2, SpeedLadder(18.0, 600.0, None, 0.1, 250.0))
    start = 1200.0 / (2 * pi)
    assert [p.speed for p in result.pieces] == pytest.approx(
        [start, start * 1.1, start * 1.21, 250.0]
    )
    assert result.pieces[2].until == pytest.approx(shift_radius(100.0, start * 1.21, 250.0))
    assert result.end is EndCondition.MAXRPM


def test_maxrpm_ends_a_table_sequence_below_the_next_speed() -> None:
    """The table 15 ... 80 with MAXRPM 55, SFM 20, R 1 -> 0.2: 40 (the bracket 30/40 at
    R = 1), 50 from 0.85944; 60 would exceed 55 (condition 3)."""
    result = plan(20.0, 1.0, 0.2, SpeedLadder(15.0, 80.0, MANUAL_TABLE, maximum=55.0))
    assert result.pieces == (Piece(40.0, shift_radius(20.0, 40.0, 50.0)), Piece(50.0))
    assert result.pieces[0].until == pytest.approx(0.8594367, abs=1e-7)
    assert result.end is EndCondition.MAXRPM


def test_the_range_bound_ends_a_sequence() -> None:
    """Condition 4: the table has nothing below 15 (SFM 20, R 1 -> 4: 40, 30, 20, 15), and a
    variable range 4 ... 130 tops out at 130 (SFM 50, R 1 -> 0.5: 95.49, 105.04, 115.55,
    127.10, then 130, held to the range)."""
    table = plan(20.0, 1.0, 4.0, SpeedLadder(15.0, 80.0, MANUAL_TABLE))
    assert [p.speed for p in table.pieces] == [40.0, 30.0, 20.0, 15.0]
    assert table.end is EndCondition.RANGE_BOUND
    variable = plan(50.0, 1.0, 0.5, SpeedLadder(4.0, 130.0, None, 0.1))
    start = 600.0 / (2 * pi)
    assert [p.speed for p in variable.pieces] == pytest.approx(
        [start, start * 1.1, start * 1.21, start * 1.331, 130.0]
    )
    assert variable.end is EndCondition.RANGE_BOUND


def test_a_constant_radius_is_one_piece() -> None:
    """Condition 5: a cut along Z at R = 1 (the bracket speed 40), and RADIUS,2 (a fixed
    radius: 19.099 RPM between 15 and 20, whose shift radius 2.2282 puts R = 2 on 20's
    side) for any path."""
    ladder = SpeedLadder(15.0, 80.0, MANUAL_TABLE)
    assert plan(20.0, 1.0, 1.0, ladder).pieces == (Piece(40.0),)
    assert plan(20.0, 1.0, 1.0, ladder).end is EndCondition.CONSTANT_RADIUS
    path = surface_cuts((0, 0, 0), (5000, 7000, 0), None, 2.0, 20.0, ladder, 0.0001)
    assert [(c.point, c.speed) for c in path.cuts] == [((5000, 7000, 0), 20.0)]
    assert path.ends == (EndCondition.CONSTANT_RADIUS,)


def test_a_start_above_the_range_starts_at_its_top() -> None:
    """Decision (spec 06 Q14): S = 191 RPM at R = 0.2 is above the table's 80: the path
    starts at 80 and, the radius growing, shifts down at 0.95493 x 20 x (1/80 + 1/70)."""
    result = plan(20.0, 0.2, 1.0, SpeedLadder(15.0, 80.0, MANUAL_TABLE))
    assert result.pieces[0] == Piece(80.0, shift_radius(20.0, 80.0, 70.0))
    assert [p.speed for p in result.pieces] == [80.0, 70.0, 60.0, 50.0, 40.0]


def test_a_path_across_the_centre_line_is_split_there() -> None:
    """|y| falls from 0.2 to 0 at the crossing and grows again to 0.2: the crossing is a
    point of the path. The first stretch starts at the table's top (80; 191 RPM wanted) and
    can climb no further (condition 4); the second starts at the top on the centre line,
    and its first shift down (to 70 at R = 0.5116) lies beyond its end (condition 2)."""
    ladder = SpeedLadder(15.0, 80.0, MANUAL_TABLE)
    path = surface_cuts((0, 2000, 0), (4000, -2000, 0), 1, 0.0, 20.0, ladder, 0.0001)
    assert [(c.point, c.speed) for c in path.cuts] == [
        ((2000, 0, 0), 80.0),
        ((4000, -2000, 0), 80.0),
    ]
    assert path.ends == (EndCondition.RANGE_BOUND, EndCondition.SHIFT_BEYOND_END)


# -- leaving SFM, rapid, MAXIPM -------------------------------------------------------------


def test_spindl_rpm_ends_sfm_and_the_next_cut_keeps_its_speed() -> None:
    lines = ["FROM/10,1,0", "SPINDL/20,SFM,CLW", "SPINDL/50", "GOTO/9,2,0"]
    run = run_of(lines, discrete_lathe())
    assert not run.state.sfm.active and run.state.sfm.locked_range is None
    assert SFM not in run.state.conditions.values
    assert tape_lines(run.result.blocks)[-2:] == ["N003G04S550", "N004G01X-1Z-1F03536"]
    assert [d.text for d in run.result.diagnostics] == [
        "SFM MODE ESTABLISHED",
        "RPM MODE ESTABLISHED",
        "OPTION FEEDRATE ASSUMED.",
    ]


@pytest.mark.parametrize(("option_2", "active"), [(0.0, True), (1.0, False)])
def test_fedrat_ipm_ends_sfm_under_option_2(option_2: float, active: bool) -> None:
    """Option 2 (001 L24361-24374): 0 = SFM is left by SPINDL only, 1 = also by
    FEDRAT/n,IPM (a bare FEDRAT/n or IPR does not)."""
    machine = overlay(f"2 = {option_2}", discrete_lathe())
    run = run_of(["SPINDL/20,SFM,CLW", "FEDRAT/1", "FEDRAT/0.1,IPR"], machine)
    assert run.state.sfm.active
    run = run_of(["SPINDL/20,SFM,CLW", "FEDRAT/1,IPM"], machine)
    assert run.state.sfm.active is active


def test_rapid_moves_are_not_subject_to_sfm() -> None:
    lines = ["FROM/10,1,0", "SPINDL/20,SFM,CLW", "RAPID", "GOTO/9,2,0"]
    assert cuts(lines, discrete_lathe()) == [(90000, 20000, 0)]


def test_maxipm_holds_the_feed_of_each_piece() -> None:
    """MAXIPM 0.35 with 0.01 IPR: the piece at 40 RPM would feed 0.4 IPM, held to 0.35 with
    TSTSAF's comment; 30 and 20 RPM are under it."""
    lines = [
        "FROM/10,1,0",
        "SPINDL/20,SFM,CLW,MAXIPM,0.35",
        "FEDRAT/0.01,IPR",
        "GOTO/9,2,0",
    ]
    result = post(lines, discrete_lathe())
    motion = [b for b in result.blocks if b.code is Code.LINEAR]
    assert [b.cells[19] for b in motion] == pytest.approx([0.35, 0.3, 0.2])
    assert "MAXIPM WAS EXCEEDED" in [d.text for d in result.diagnostics]


def test_the_range_stays_locked() -> None:
    """SFMLOK: on MACH04 with the spindle in range 1 (4 ... 130 RPM) the SFM speeds stop at
    130 although range 2 would turn faster; RANGE,2 moves the lock."""
    lines = ["FROM/10,2,0", "SPINDL/100,CLW", "SPINDL/100,SFM", "GOTO/10,0.5,0"]
    run = run_of(lines, mach04())
    assert run.state.spindle.range == 1 and run.state.spindle.speed == 130.0
    assert run.state.sfm.last_end == EndCondition.RANGE_BOUND
    run = run_of([*lines[:2], "SPINDL/100,SFM,RANGE,2", lines[3]], mach04())
    assert run.state.spindle.range == 2 and run.state.spindle.speed > 130.0


# -- a lathe program, block by block -----------------------------------------------------


def test_facing_and_turning_on_mach04_block_by_block() -> None:
    """MACH04 (type 10, range 2 = 18 ... 600 RPM, option 15 = 10 %; CL x is the lathe's Z,
    CL y the radius, output as -X; feeds are inverse time, F = IPM / length): 0.01 IPR,
    SPINDL/100,SFM,MAXRPM,250 with the spindle turning 200 RPM in range 2.

    * the rapid approach carries no S;
    * facing R 2 -> 1: 95.49 x 1.1^k RPM for k = 0 ... 7 (S595 ... S619), each shift at
      R(k) (1 + 1/1.1) / 2, R(k) = 2 / 1.1^k (1.9091, 1.7355, ...); the next speed, 204.7,
      is beyond the end's 190.99 (condition 2);
    * turning at R = 1: one piece at 190.99 (S619, condition 5);
    * facing R 1 -> 0.2: 190.99 (kept, no S), 210.08 (S621), 231.09 (S623), then MAXRPM 250
      (S625) from R = 0.7952 (condition 3);
    * each piece's feed is 0.01 x S IPM;
    * SPINDL/RPM,200 ends the mode and is an ordinary speed block."""
    lines = [
        "FROM/10,3,0",
        "SPINDL/200,CLW",
        "FEDRAT/0.01,IPR",
        "SPINDL/100,SFM,MAXRPM,250",
        "RAPID",
        "GOTO/8,2,0",
        "GOTO/8,1,0",
        "GOTO/4,1,0",
        "GOTO/4,0.2,0",
        "SPINDL/RPM,200",
        "RAPID",
        "GOTO/10,3,0",
    ]
    result = post(lines, mach04())
    assert tape_lines(result.blocks) == [
        "N002G04S620M62",
        "N006G01X+1Z-2F500M40",
        "N007G11X+00909F01051S595M41",
        "N007G11X+01736F00605S611",
        "N007G11X+01577F00733S612",
        "N007G11X+01435F00886S613",
        "N007G11X+01304F01072S614",
        "N007G11X+01185F01298S615",
        "N007G11X+01078F01569S617",
        "N007G11X+00776F02398S619",
        "N008G01Z-4F00477S619",
        "N009G11X+00455F04197",
        "N009G11X+00867F02423S621",
        "N009G11X+00726F03183S623",
        "N009G11X+05952F0042S625",
        "N010G04S620",
        "N012G01X-28Z+6F16667M40",
    ]
    start = 1200.0 / (2 * pi) / 2  # 95.49 RPM at R = 2
    facing = [start * 1.1**k for k in range(8)]
    down = [2 * start, 2 * start, 2 * start * 1.1, 2 * start * 1.21, 250.0]
    feeds = [b.cells[19] for b in result.blocks if b.code is Code.LINEAR and not b.rapid]
    assert feeds == pytest.approx([0.01 * s for s in facing + down])
    shifts = [b.position[1] for b in result.blocks if b.code is Code.LINEAR and b.record == 7]
    assert shifts[:-1] == [round(20000 * (1 + 1 / 1.1) / 2 / 1.1**k) for k in range(7)]
    assert [d.text for d in result.diagnostics] == [
        "OPTION FEED RATE RANGE ASSUMED.",
        "SFM MODE ESTABLISHED",
        "RPM MODE ESTABLISHED",
    ]


def test_a_stopped_spindle_is_started_by_the_statement_at_the_present_radius() -> None:
    """SPINDL/100,SFM,CLW at R = 3 on MACH04: 63.66 RPM, the lowest range holding it (range
    1, 4 ... 130 RPM: S564 with range 1 CLW, M60), which SFM then keeps (SFMLOK)."""
    run = run_of(["FROM/10,3,0", "SPINDL/100,SFM,CLW"], mach04())
    assert tape_lines(run.result.blocks) == ["N002G04S564M60"]
    assert run.state.sfm.locked_range == 1


def test_threads_are_not_subject_and_maxipm_holds_a_per_minute_feed() -> None:
    """FEDRAT/4,IPM with MAXIPM 3: the SFM pieces feed 3 IPM (F = 3 / length; TSTSAF's
    comment once, as the feed comes to MAXIPM); the thread carries no S; SPINDL/OFF ends the
    mode and the programmed 4 IPM is the feed again (F040 over 1 in)."""
    lines = [
        "FROM/10,3,0",
        "SPINDL/100,CLW",
        "FEDRAT/4,IPM,RANGE,2",
        "SPINDL/100,SFM,MAXIPM,3",
        "GOTO/10,2,0",
        "PITCH/8",
        "THREAD/TURN",
        "GOTO/4,2,0",
        "SPINDL/OFF",
        "GOTO/3,2,0",
    ]
    result = post(lines, mach04())
    assert tape_lines(result.blocks) == [
        "N002G04S610M60",
        "N005G11X+01364F02199S564M41",
        "N005G11X+02603F01153S570",
        "N005G11X+02367F01267S577",
        "N005G11X+02151F01395S585",
        "N005G11X+01515F0198S593",
        "N008G33Z-6K125",
        "N009G04M05",
        "N010G01Z-1F040",
    ]
    assert [d.text for d in result.diagnostics] == [
        "SFM MODE ESTABLISHED",
        "MAXIPM WAS EXCEEDED",
        "THE ENCODER IS NOT COUPLED FOR THREADING.",
        "RPM MODE ESTABLISHED",
    ]


def test_a_metric_machine_takes_its_radii_in_millimetres() -> None:
    """Option 138 = 1 (machine in mm, step 0.001): the SFM-2 shift radius 1.11408 in is
    28.298 mm; 0.01 IPR is 0.254 mm per revolution, 10.16 mm/min at 40 RPM, 7.62 at 30."""
    machine = overlay("138 = 1.0\n14 = 0.001\n110 = 0.0", discrete_lathe())
    lines = ["FROM/254,25.4,0", "SPINDL/20,SFM,CLW", "FEDRAT/0.01,IPR", "GOTO/250,30,0"]
    motion = [b for b in post(lines, machine).blocks if b.code is Code.LINEAR]
    assert [b.position for b in motion] == [(251480, 28298, 0), (250000, 30000, 0)]
    assert [b.cells[19] for b in motion] == pytest.approx([10.16, 7.62])


def test_the_standard_machine_type_1_spindle() -> None:
    """Type 1 (1 ... 300 RPM, option 15 = 10 %), radius = CL x: SFM 100 from R = 1 to 1.2
    starts at 190.99 (S619 M03 from the statement), shifts at 1.0556 to 171.89 (S617); the
    next speed, 154.70, is below the end's 159.15 RPM."""
    lines = ["FROM/1,0,0", "SPINDL/100,SFM,CLW", "FEDRAT/10", "GOTO/1.2,0,0"]
    result = post(lines, standard_machine())
    assert tape_lines(result.blocks) == [
        "N002S619M03",
        "N004G01X+00556I02224F450",  # option 26's feedrate multiplier in I
        "N004X+01444I02888F346S617",
    ]
    assert [b.position for b in result.blocks if b.code is Code.LINEAR] == [
        (10556, 0, 0),
        (12000, 0, 0),
    ]


def test_a_fixed_radius_turns_one_speed_everywhere() -> None:
    """RADIUS,2 (SFMRAD = 2): 19.10 RPM between 15 and 20, on 20's side of their shift
    radius 2.2282: the statement starts the spindle at 20 (S520 M03) and a cut from R = 1 to
    R = 2 needs no other speed (condition 5)."""
    lines = ["FROM/10,1,0", "SPINDL/20,SFM,CLW,RADIUS,2", "FEDRAT/0.01,IPR", "GOTO/9,2,0"]
    run = run_of(lines, discrete_lathe())
    assert tape_lines(run.result.blocks) == ["N002G04S520M03", "N004G01X-1Z-1F00141"]
    assert run.state.sfm.radius_axis is None and run.state.sfm.fixed_radius == 2.0
    assert run.state.sfm.last_end == EndCondition.CONSTANT_RADIUS
