"""Worked examples of spec 06 (manual §4.4-§4.12) that had no golden test yet (issue 22):
RS-1, RS-2 and RS-3 (the STATE vector and reinstatement, §4.7), DW-2 (preset timers,
§4.10), DW-5 (option 56 = 0.01 on a format-44 control) and TH-2's 6-digit registers
(§4.6). A/D (AD-1..AD-10) is in tests/test_ad_testing.py.

TH-5 (the 7582's "450-1000 RPM: lead under .50000 in", table 3, 001 L15902-15904) is not
tested: no option selects the 7582's capability table, and gecent does not build it
(docs/decisions.md, threading capability tables).
"""

from __future__ import annotations

from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.output.block import Code
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins
from gecent.core.run import Run
from gecent.core.state import (
    COOLANT,
    FEED_M,
    SFM,
    SPINDLE_COMMAND,
    SPINDLE_M,
    SPINDLE_RANGE,
    T_CODE,
)

from tests.test_post_linear import post
from tests.test_threading import START, threads
from tests.test_threading import lathe as mach04


def run_of(lines: list[str], machine: MachineDefinition) -> Run:
    run = Run(machine)
    run.process(AptSourceReader("part.apt").read_lines([*lines, "FINI"]))
    return run


def punched(lines: list[str], machine: MachineDefinition) -> list[str]:
    return [b.punch for b in post(lines, machine).blocks if b.punch]


def type3_example() -> MachineDefinition:
    """The §4.5.4 type 3 machine (three ranges, range-only M codes M41-M43, M03/M04 for the
    direction): a spindle with a range 2 that turns CLW with M03, as RS-1 needs."""
    plugin = get_plugins().get("spindles", 3)
    assert plugin is not None
    return load_machine_text(plugin.manual_example, "type03.toml")


# -- §4.7, the STATE vector (001 L16046-16095) ---------------------------------------------


def test_rs1_sfm_statement_stores_direction_range_and_surface_speed() -> None:
    """RS-1 (001 L16071-16081): SPINDL/20, SFM, RANGE, 2, CLW stores STATE(3) = 3 (for M03),
    STATE(4) = 2 and STATE(5) = 20; a non-DMBITS STATE(5) is the SFM mode. At radius 0.1
    the speed is 12 x 20 / (2 pi 0.1) = 382 RPM, bracketed by 300 and 400 in range 2; the
    start lies on 400's side of the shift radius (0.111): S3 (option 47 = 2, row 1), after
    the range code M42."""
    run = run_of(["FROM/0.1,2,0", "SPINDL/20, SFM, RANGE, 2, CLW"], type3_example())
    state = run.state.conditions.values
    assert (state[SPINDLE_M], state[SPINDLE_RANGE], state[SFM]) == (3.0, 2.0, 20.0)
    assert run.state.sfm.active
    assert tape_lines(run.result.blocks) == ["N002M42", "N002S3M03"]


def test_rs2_rpm_statement_stores_540_and_ends_the_sfm_value() -> None:
    """RS-2 (001 L16083-16093): SPINDL/40, RPM stores STATE(2) = 540 (40 RPM is command 540
    on the Standard Machine's type 1, magic-three spindle) and STATE(5) = DMBITS (absent
    here), also when it follows an SFM statement. (The direction comes from option 34.)"""
    machine = standard_machine()
    fresh = run_of(["SPINDL/40, RPM"], machine).state.conditions.values
    assert fresh[SPINDLE_COMMAND] == 540.0 and SFM not in fresh
    assert fresh[SPINDLE_M] == 3.0  # no direction given: option 34 = +1, CLW (M03)
    run = run_of(["FROM/2,0,0", "SPINDL/20,SFM,CLW", "SPINDL/40, RPM"], machine)
    values = run.state.conditions.values
    assert values[SPINDLE_COMMAND] == 540.0 and SFM not in values
    assert not run.state.sfm.active
    assert tape_lines(run.result.blocks)[-1] == "N003S540"


def test_rs3_conditions_given_after_a_stop_are_output_once_in_order() -> None:
    """RS-3 (001 L16106-16141): STOP, SPINDL/40,RPM, COOLNT/MIST, FEDRAT/RANGE,2, GOTO on
    MACH04 with option 145 = 1. The three conditions go out when given and in that order
    (S540 with range 1's CLW M60; the coolant; M41, range 2's feed gear, with the next
    block); RESTAT then reinstates only the tool, not them again. Without them RESTAT
    brings back all four: T, S630 M62, the feed gear M42 and the coolant."""
    machine = mach04().with_options({145: 1.0})
    before = ["FROM/0,0,0", "TOOLNO/3", "SPINDL/300,CLW", "COOLNT/FLOOD"]
    before += ["FEDRAT/1,RANGE,1", "GOTO/1,-1,0", "STOP"]
    head = [
        "N002G04Z+02T00003M06",
        "N003G04S630M62",
        "N005G04M08",
        "N006G01X+1Z+1F00707M42",
        "N007G04M00",
    ]
    assert tape_lines(post([*before, "GOTO/2,-1,0"], machine).blocks) == [
        *head,
        "N008G04T00003",
        "N008G04S630M62",
        "N008G04M42",
        "N008G01Z+1F010M08",
    ]
    again = ["SPINDL/40,RPM", "COOLNT/MIST", "FEDRAT/RANGE,2", "GOTO/2,-1,0"]
    run = run_of([*before, *again], machine)
    assert tape_lines(run.result.blocks) == [
        *head,
        "N008G04S540M60",
        "N010G04M08",
        "N011G04T00003M41",
        "N011G01Z+1F010",
    ]
    conditions = run.state.conditions
    assert conditions.respecified == set()  # RESTAT has run: the marks are cleared
    assert conditions.values[SPINDLE_COMMAND] == 540.0
    assert conditions.values[SPINDLE_M] == 60.0
    assert conditions.values[FEED_M] == 41.0
    assert conditions.values[COOLANT] == 8.0
    assert conditions.values[T_CODE] == 3.0


# -- §4.10, dwell blocks --------------------------------------------------------------------

PRESET_TIMERS = """
[machine]
name = "preset-timers"
title = "PRESET TIMERS"
[tableg]
5 = "absent"
[tablem]
18 = 31
# timer 2: the machine function routine's interrogation of DELAY (001 L30344-30346)
[[macros]]
name = "timer-2"
sdl = "DELAY/$P1"
body = ["{% if p[1] == 3 %}AUXFUN/32{% else %}OUTPUT{% endif %}"]
"""


def test_dw2_preset_timers_m31_one_second_m32_three_seconds() -> None:
    """DW-2 (001 L16334-16339): M31 selects preset timer 1 (a 1 s dwell), M32 timer 2 (3 s).
    With no dwell G code (TABLEG(5) absent) DELAY outputs TABLEM(18), timer 1, in a block
    by itself (001 L30311-30342); GECENT has one such slot, so timer 2 is the machine's
    own DELAY routine, here a machine-file macro."""
    machine = load_machine_text(PRESET_TIMERS, "timers.toml")
    assert punched(["DELAY/1", "DELAY/3"], machine) == ["N001M31", "N002M32"]
    assert punched(["DELAY/1"], standard_machine()) == ["N001G04X+01"]  # a G04 machine is untouched


def test_dw5_option_56_of_a_hundredth_on_a_format_44_control() -> None:
    """DW-5 (option 56, 001 L25110-25128): a 7500 control with motion in format 44 reads
    its dwell in a fixed format 24, so option 56 = 0.01 makes a 15 s dwell X1500, not
    X0015; the dwell time counted is the real 15 s. Motion keeps its format 44."""
    text = '[machine]\nname = "f44"\ntitle = "FORMAT 44"\n[optab]\n56 = 0.01\n[regfor]\n3 = 44.0\n'
    machine = load_machine_text(text, "f44.toml", base=standard_machine())
    result = post(["DELAY/15", "FROM/0,0,0", "FEDRAT/10", "GOTO/4.2,0,0"], machine)
    assert [b.punch for b in result.blocks if b.punch] == ["N001G04X1500", "N004G01X00042F024"]
    (dwell,) = [b for b in result.blocks if b.code is Code.DWELL]
    assert dwell.dwell_minutes == 15 / 60


# -- §4.6, threading ------------------------------------------------------------------------


def test_th2_six_digit_registers_take_a_seven_digit_lead() -> None:
    """TH-2 (001 L15680-15693): a fine lead (more than 10 threads per inch) is a six-digit
    lead with its leading zero passed over in a 5-digit register; a 6-digit register
    (format 15) takes a seven-digit lead. PITCH/13: lead .0769231 -> K76923 on MACH04's
    format 14, K769231 in format 15; a coarse lead (PITCH/4, .25) is K25 in both."""
    six = load_machine_text(
        '[machine]\nname = "l6"\ntitle = "L6"\n[regfor]\n8 = 15.0\n10 = 15.0\n',
        "l6.toml",
        base=mach04(),
    )
    for machine, fine in ((mach04(), "N006G33Z-2K76923"), (six, "N006G33Z-2K769231")):
        blocks, _ = threads([*START, "PITCH/13", "THREAD/TURN", "GOTO/8,0,0"], machine)
        assert [b.punch for b in blocks] == [fine]
        assert blocks[0].code is Code.THREAD_6
        blocks, _ = threads([*START, "PITCH/4", "THREAD/TURN", "GOTO/8,0,0"], machine)
        assert [b.punch for b in blocks] == ["N006G33Z-2K25"]
        assert blocks[0].code is Code.THREAD_5
