"""Spindle types 7 and 11-19 (manual §4.5.8, §4.5.12-§4.5.20, 001 L14980-15647): the
manual's worked examples at the type's ``select`` and on tape through the whole kernel.
Decisions on the open questions are in docs/decisions.md (spindle types 7, 11-19)."""

from __future__ import annotations

from pathlib import Path

import pytest
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.dispatch.post import post as post_file
from gecent.core.errors import MachineDefinitionError
from gecent.core.families import HookPoint, HookResult, Macfun
from gecent.core.feed.magic3 import magic3
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.output.block import Code
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins, load_module_plugins
from gecent.core.run import Run
from gecent.core.spindle_macfun import SpindleCodeContext
from gecent.core.spindle_types import (
    CCLW,
    CLW,
    LOWEST_OUTPUT,
    NOT_FOUND,
    Running,
    SpindleRequest,
    SpindleSelection,
    SpindleType,
)
from gecent.plugins.spindles.type12 import speed_command

from tests.test_post_linear import post


def spindle(number: int) -> SpindleType:
    found = get_plugins().get("spindles", number)
    assert found is not None, f"spindle type {number} is not registered"
    return found  # type: ignore[no-any-return]


def manual_text(number: int) -> str:
    """The type's ``manual_example`` machine overlay (not part of the SpindleType protocol)."""
    text: str = spindle(number).manual_example
    return text


def example(number: int) -> MachineDefinition:
    return load_machine_text(manual_text(number), f"type{number:02d}-example.toml")


def select(
    number: int,
    machine: MachineDefinition,
    speed: float,
    range_number: int | None = None,
    direction: int = CLW,
    running: Running | None = None,
    head: int = 1,
) -> SpindleSelection:
    request = SpindleRequest(speed, range_number, direction, running, head=head)
    return spindle(number).select(machine, request)


def tape(lines: list[str], machine: MachineDefinition) -> list[str]:
    return tape_lines(post(lines, machine).blocks)


def tape_and_comments(lines: list[str], machine: MachineDefinition) -> list[str]:
    """The punched blocks with the postprocessor's comments where they fall."""
    return [
        block.punch if block.punch else str(block.text)
        for block in post(lines, machine).blocks
        if block.punch or block.code is Code.COMMENT
    ]


# --- type 7: the machine's own MACFUN computes S (§4.5.8) ------------------------------

TYPE7_MACHINE = """
[machine]
name = "type07-local"
title = "TYPE 7 SPINDLE"
[optab]
7 = 2.0
8 = 3.0
19 = 7.0
133 = 1.0
[spindle_table]
speeds = [10.0, 25.0, 50.0, 50.0, 100.0, 150.0]
"""


def range_and_row_code(context: SpindleCodeContext) -> HookResult:
    """A machine's own S code: 100 x range + row, from the table choice SPTYPE made."""
    choice = context.table_choice()
    context.selection = SpindleSelection(
        choice.speed, 100.0 * choice.range + choice.row, choice.range, choice.comments
    )
    return HookResult.HANDLED


def declines(context: SpindleCodeContext) -> HookResult:
    return HookResult.CONTINUE


@hookimpl
def register_macfuns(register: Register) -> None:
    register(
        Macfun(
            "type07-local",
            "type07-local",
            "§4.5.8",
            {HookPoint.SPINDLE_CODE: range_and_row_code},
        )
    )
    register(
        Macfun("type07-declines", "type07-declines", "§4.5.8", {HookPoint.SPINDLE_CODE: declines})
    )


def type7_run(lines: list[str], name: str = "type07-local") -> list[str]:
    machine = load_machine_text(TYPE7_MACHINE.replace("type07-local", name), f"{name}.toml")
    plugins = load_module_plugins(__name__)  # type 7 is the kernel's: no spindle plugin
    run = Run(machine, plugins)
    result = run.process(AptSourceReader("part.apt").read_lines([*lines, "FINI"]))
    return tape_lines(result.blocks)


def test_type7_machine_macfun_computes_the_s_code() -> None:
    """SPTYPE branches to the machine's own code for a type-7 spindle (001 L37748-37752):
    the local MACFUN's S is 100 x range + row of the table speed DSRROW chose (option 90 =
    -1: 30 RPM is 25, row 1 of range 1; 100 RPM is row 1 of range 2)."""
    assert type7_run(["SPINDL/20,CLW", "SPINDL/30", "SPINDL/100"]) == [
        "N001S100M03",
        "N002S101",
        "N003S201",
    ]


def test_type7_without_its_macfun_is_a_machine_error() -> None:
    """Option 19 = 7 needs option 133 = 1 and the machine's MACFUN (001 L24608-24616)."""
    with pytest.raises(MachineDefinitionError, match="spindle-type-7"):
        type7_run(["SPINDL/20,CLW"], "type07-nobody")
    with pytest.raises(MachineDefinitionError, match="HANDLED"):
        type7_run(["SPINDL/20,CLW"], "type07-declines")


# --- type 11: table lookup (§4.5.12) ---------------------------------------------------


def test_type11_command_is_the_paired_table_entry() -> None:
    """SPNCOM = SRTAB(N + row) (TYPE11, 001 L39550-39555). The manual's command column is
    unreadable (001 L15125-15166), so the example pairs its speeds 5..35 with commands of
    our own, 12 3 27 8 40 19 33: 20 RPM is the fourth speed, S8; 22 RPM is 20 under
    option 90 = -1 and 25 (S40) under +1; below and above the table the ends, with
    comments 80 and 63."""
    machine = example(11)
    assert select(11, machine, 20).command == 8.0
    assert select(11, machine, 35).command == 33.0
    assert (select(11, machine, 22).speed, select(11, machine, 22).command) == (20.0, 8.0)
    higher = machine.with_options({90: 1.0})
    assert (select(11, higher, 22).speed, select(11, higher, 22).command) == (25.0, 40.0)
    assert select(11, machine, 1).comments == (LOWEST_OUTPUT,)
    assert select(11, machine, 99).comments == (NOT_FOUND,)


def test_type11_on_tape_never_uses_range_2() -> None:
    """The table is one range: RANGE,2 falls back to it (001 L15121-15123)."""
    machine = example(11)
    assert tape_and_comments(["SPINDL/20,CLW", "SPINDL/35,RANGE,2"], machine) == [
        "N001S008M03",
        "RANGE REQUESTED IS NOT AVAILABLE, USE HIGHEST",
        "N002S033",
    ]


def test_type11_rejects_a_table_without_its_commands() -> None:
    text = manual_text(11).replace(", 12.0, 3.0, 27.0, 8.0, 40.0, 19.0, 33.0", ", 12.0, 3.0")
    machine = load_machine_text(text, "type11-short.toml")
    with pytest.raises(MachineDefinitionError, match=r"SRTAB\(10\)"):
        select(11, machine, 20)


# --- type 12: command equal to the selected speed (§4.5.13) --------------------------


def test_type12_truncates_to_whole_rpm_and_to_tens_from_200() -> None:
    """SP-12 (001 L15172-15179): 28.4 -> S28, 28.7 -> S28, 418 -> S410, 422 -> S420."""
    machine = example(12)
    assert [select(12, machine, s).command for s in (28.4, 28.7, 418, 422)] == [
        28.0,
        28.0,
        410.0,
        420.0,
    ]
    assert select(12, machine, 418).speed == 410.0  # the spindle turns the command
    assert speed_command(199.9) == 199.0 and speed_command(200.0) == 200.0


def test_type12_dwell_when_a_change_crosses_199() -> None:
    """SP-12d (001 L15181-15187): 70 -> 200 RPM and 300 -> 180 RPM cross 199 RPM, so the S
    code goes out in an option-54 dwell block (2 s in the example machine); 200 -> 418 and
    the first speed do not cross."""
    machine = example(12)
    program = ["SPINDL/70,CLW", "SPINDL/200", "SPINDL/418", "SPINDL/300", "SPINDL/180"]
    assert tape(program, machine) == [
        "N001S070M03",
        "N002G04X+02S200",
        "N003S410",
        "N004S300",
        "N005G04X+02S180",
    ]
    crossing = select(12, machine, 200, running=Running(70.0, 1))
    assert crossing.dwell_after == 2.0


def test_type12_without_option_54_the_s_is_a_block_by_itself() -> None:
    """Option 54 = 0: "the S code is output in a block by itself" (001 L15187)."""
    machine = example(12).with_options({54: 0.0})
    assert tape(["SPINDL/70,CLW", "SPINDL/200"], machine) == ["N001S070M03", "N002S200"]


def test_type12_option_196_moves_the_cross_over() -> None:
    """Option 196, the type-12 cross-over speed (001 L26540-26545): at 250 RPM, 70 -> 200
    stays below it and 200 -> 300 crosses it."""
    machine = example(12).with_options({196: 250.0})
    assert tape(["SPINDL/70,CLW", "SPINDL/200", "SPINDL/300"], machine) == [
        "N001S070M03",
        "N002S200",
        "N003G04X+02S300",
    ]


def test_type12_holds_speeds_to_the_srtab_limits() -> None:
    machine = example(12)
    low = select(12, machine, 10)
    assert (low.command, low.comments) == (25.0, (LOWEST_OUTPUT,))
    assert select(12, machine, 900).command == 600.0
    speeds = spindle(12).table_speeds(machine, 1)
    assert speeds is not None and speeds[:2] == (25.0, 26.0) and speeds[-2:] == (590.0, 600.0)
    assert len(speeds) == 175 + 41  # 25..199 whole, 200..600 by tens


def test_type12_rejects_limits_it_cannot_command() -> None:
    broken = manual_text(12).replace("speeds = [25.0, 600.0]", "speeds = [25.5, 600.0]")
    with pytest.raises(MachineDefinitionError, match="whole RPM below 200"):
        select(12, load_machine_text(broken, "type12-broken.toml"), 100)


# --- type 13: expanded quasi-EIA, two heads (§4.5.14) ---------------------------------


def test_type13_code_is_the_range_1_speed_of_the_row() -> None:
    """SP-13a (001 L15197-15211): 100 RPM in range 2 is S512, the EIA code of range 1's
    second row (12 RPM). The manual's range-2 column (88, 100, 200, 300, 450) is no single
    multiple of range 1, so the example machine's range 2 is 100/12 x range 1."""
    machine = example(13)
    chosen = select(13, machine, 100, 2)
    assert (chosen.speed, chosen.command, chosen.range, chosen.row) == (100.0, 512.0, 2, 1)
    assert chosen.direction_cells == {CLW: 74, CCLW: 73}
    assert select(13, machine, 100).range == 2  # range 1 is 10..77 RPM
    assert select(13, machine, 12).command == 512.0


def test_type13_manual_multiple_corrected() -> None:
    """SP-13b (001 L15297-15312): "198 is in range 2. The corresponding speed in range 1 is
    94 ... the multiple is 2.2 since 94 x 2.2 = 198 ... S594." 94 x 2.2 is 206.8, not 198:
    the manual's slip is the factor. With the factor 198/94 the range-2 speed of 94's row is
    198 RPM and gives S594; with the printed 2.2 the same row is 206.8 RPM, also S594."""
    layout = """
[machine]
name = "type13-sp13b"
[optab]
7 = 2.0
8 = 2.0
19 = 13.0
[spindle_table]
speeds = [90.0, 98.0, {low}, {high}, 5.0, 1.0, {factor}, 90.0, 92.0, 94.0, 96.0, 98.0]
cells = {{ 180 = 5.0 }}
"""
    factor = 198 / 94
    corrected = load_machine_text(
        layout.format(low=90 * factor, high=98 * factor, factor=factor), "type13-sp13b.toml"
    )
    chosen = select(13, corrected, 198, 2)
    assert (round(chosen.speed, 9), chosen.command, chosen.row) == (198.0, 594.0, 2)
    printed = load_machine_text(
        layout.format(low=198.0, high=215.6, factor=2.2), "type13-printed.toml"
    )
    chosen = select(13, printed, 206.8, 2)
    assert (round(chosen.speed, 9), chosen.command) == (206.8, 594.0)


def test_type13_second_head_uses_its_own_limits_and_factors() -> None:
    """Head 2's ranges are its own multiples (SRTAB(12), (13)) of the range-1 speeds; its
    code is the EIA code of its own range-1 RPM (24 RPM = 2 x 12: S524)."""
    machine = example(13)
    chosen = select(13, machine, 24, head=2)
    assert (chosen.speed, chosen.command, chosen.range) == (24.0, 524.0, 1)
    assert select(13, machine, 200, head=2).range == 2
    with pytest.raises(MachineDefinitionError, match="head 3"):
        select(13, machine, 24, head=3)


def test_type13_on_tape_range_and_direction_codes() -> None:
    """The M code names range and direction as type 4 (TABLEM(70 + 2n) CLW, (69 + 2n)
    CCLW): M40/M41 range 1, M42/M43 range 2 in the example machine."""
    machine = example(13)
    program = ["SPINDL/100,CLW", "SPINDL/12", "SPINDL/20", "SPINDL/20,CCLW"]
    assert tape(program, machine) == ["N001S512M42", "N002S512M40", "N003S520", "N004S520M41"]


def test_type13_rejects_a_layout_without_strtpt() -> None:
    text = manual_text(13).replace("cells = { 180 = 9.0 }", "cells = { 180 = 8.0 }")
    with pytest.raises(MachineDefinitionError, match=r"SRTAB\(180\)"):
        select(13, load_machine_text(text, "type13-broken.toml"), 100)


MACH40_PROGRAM = """PARTNO SPINDLE ON MACH40
MACHIN / GECENT, 40
SPINDL / 100, CLW
SPINDL / 350
SPINDL / 20, CCLW
SPINDL / OFF
FINI
"""


def test_mach40_type13_spindle_posts(tmp_path: Path) -> None:
    """MACH40 (001 L27867-27979): option 7 = 2, SRTAB(180) = 9: two heads; N = SRTAB(9) = 101
    range-1 speeds 10..350 RPM from SRTAB(14); range codes TABLEM 72 = M03 / 71 = M04
    (range 1) and 74 = M17 / 73 = M18 (range 2); option 98's F200 on non-motion blocks.
    The CL file selects the machine by MACHIN/GECENT,40, as `gecent post` does."""
    source = tmp_path / "m40.apt"
    source.write_text(MACH40_PROGRAM)
    result = post_file(str(source), get_plugins())
    assert tape_lines(result.blocks) == [
        "SPINDLEONMACH40",
        "N003F200S610M03",
        "N004F200S635",
        "N005F200S520M04",
        "N006M05",
    ]
    assert (magic3(100), magic3(350), magic3(20)) == (610, 635, 520)


def test_mach40_range_2_with_taba_11_read_as_2_8333333() -> None:
    """MACH40's range-2 factor SRTAB(11) prints as "12.8333333" (001 L27883), but range 2's
    limits SRTAB(3), (4) are 28.3 and 991 RPM = 2.8333 x 10 and 2.8333 x 350 (head 2's
    factors, 4.0 and 11.333333, match their limits the same way); the machine file holds
    2.8333333 (docs/decisions.md). 500 RPM (option 90 = 0: closest) is 176 x 2.8333333 =
    498.67 RPM in range 2: S618, the code of 176 RPM, with M17."""
    corrected = get_plugins().machine("mach40").load()
    assert corrected.store[11] == 2.8333333
    chosen = select(13, corrected, 500)
    assert (chosen.range, round(chosen.speed, 2), chosen.command) == (2, 498.67, 618.0)
    assert tape(["SPINDL/100,CLW", "SPINDL/500"], corrected) == [
        "N001F200S610M03",
        "N002F200S618M17",
    ]


# --- type 14: speed changes by mode (§4.5.15) -----------------------------------------


def test_type14_same_range_in_two_modes() -> None:
    """SP-14 (001 L15352-15356), option 47 = 10, option 31 = 3: in mode 1, 40 RPM in range 3
    is S35; the same speed in range 3 of mode 2 (RANGE,13: TYPE14's ranges 11-20 are mode
    2, 001 L39705-39710) is S30, 40 RPM being below that range's minimum, 120."""
    machine = example(14)
    mode1 = select(14, machine, 40, 3)
    assert (mode1.command, mode1.range_cell, mode1.speed) == (35.0, 72, 40.0)
    mode2 = select(14, machine, 40, 13)
    assert (mode2.command, mode2.range_cell, mode2.speed) == (30.0, 74, 120.0)
    assert mode2.comments == (LOWEST_OUTPUT,)


def test_type14_mode_code_only_on_a_mode_change() -> None:
    """TABLEM(72) = M26 for mode 1 and TABLEM(74) = M27 for mode 2 go out when the mode
    changes, not within a mode, before the spindle's direction code (001 L15318-15322,
    L39705-39712)."""
    machine = example(14)
    program = ["SPINDL/40,CLW,RANGE,3", "SPINDL/40,RANGE,13", "SPINDL/128,RANGE,13", "SPINDL/10"]
    assert tape(program, machine) == [
        "N001M26",
        "N001S035M03",
        "N002S030M27",
        "N003S031",
        "N004S013M26",
    ]


def test_type14_unused_range_uses_the_highest_of_its_mode() -> None:
    machine = example(14)
    chosen = select(14, machine, 40, 5)
    assert (chosen.range, chosen.command) == (3, 35.0)
    assert chosen.comments == ("RANGE REQUESTED IS NOT AVAILABLE, USE HIGHEST",)


def test_type14_needs_the_mode_codes() -> None:
    text = manual_text(14).replace("74 = 27\n", "")
    with pytest.raises(MachineDefinitionError, match=r"TABLEM\(74\)"):
        select(14, load_machine_text(text, "type14-broken.toml"), 40)


# --- type 15: ratio between ranges (§4.5.16) ------------------------------------------


def test_type15_manual_example_every_case() -> None:
    """SP-15 (001 L15394-15431), ratios 5, 7.5, 20, speed 35 RPM. Range 1: 35/5 = 7 (the
    OCR's "1" is 7), speed 35. Range 2: 35/7.5 = 4.67: option 90 = 0 or +1 gives command 5,
    37.5 RPM; -1 gives 4, 30 RPM. Range 3: raised to its minimum, 100 RPM: 100/20 = 5."""
    machine = example(15)
    one = select(15, machine, 35)
    assert (one.range, one.command, one.speed) == (1, 7.0, 35.0)
    for rule, command, speed in ((0.0, 5.0, 37.5), (1.0, 5.0, 37.5), (-1.0, 4.0, 30.0)):
        chosen = select(15, machine.with_options({90: rule}), 35, 2)
        assert (chosen.command, chosen.speed) == (command, speed), rule
    three = select(15, machine, 35, 3)
    assert (three.command, three.speed, three.comments) == (5.0, 100.0, (LOWEST_OUTPUT,))
    assert spindle(15).table_speeds(machine, 2) == (30.0, 37.5, 45.0, 52.5, 60.0)


def test_type15_on_tape_with_range_and_direction_codes() -> None:
    """TABLEM 71-76 "may also be used for range and direction changes" (001 L15374-15375):
    with them, the range pair replaces M03/M04 and a repeated code is not output again."""
    machine = load_machine_text(
        manual_text(15).replace(
            "[spindle_table]",
            '[tablem]\n4 = "absent"\n5 = "absent"\n71 = 61\n72 = 60\n73 = 63\n74 = 62\n'
            "75 = 65\n76 = 64\n[spindle_table]",
        ),
        "type15-codes.toml",
    )
    program = ["SPINDL/35,CLW", "SPINDL/20", "SPINDL/35,RANGE,2", "SPINDL/120"]
    assert tape(program, machine) == ["N001S007M60", "N002S004", "N003S004M62", "N004S006M64"]
    assert tape(["SPINDL/35,CLW", "SPINDL/20"], example(15)) == ["N001S007M03", "N002S004"]


def test_type15_rejects_a_missing_ratio() -> None:
    text = manual_text(15).replace(", 5.0, 7.5, 20.0]", ", 5.0, 7.5]")
    with pytest.raises(MachineDefinitionError, match=r"SRTAB\(9\)"):
        select(15, load_machine_text(text, "type15-broken.toml"), 35)


# --- type 16: stored, non-unit-increasing codes (§4.5.17) -----------------------------


def test_type16_code_from_the_stored_list() -> None:
    """SP-16 (001 L15468-15476, derived): codes 00 02 05 15 20 30 after the two ranges; 750
    RPM is range 2's third speed: S05 with range 2's code; 150 RPM is S05 in range 1."""
    machine = example(16)
    chosen = select(16, machine, 750)
    assert (chosen.range, chosen.command, chosen.range_cell) == (2, 5.0, 74)
    assert select(16, machine, 150).command == 5.0
    assert select(16, machine, 1000, direction=CCLW).range_cell == 73


def test_type16_on_tape_range_only_and_combined_codes() -> None:
    """As type 3 (§4.5.4): with M03/M04 the range code (M41 range 1, M42 range 2) goes out
    when it changes; with TABLEM 4 and 5 empty the range pair is the direction code."""
    machine = example(16)
    assert tape(["SPINDL/750,CLW", "SPINDL/150", "SPINDL/1000"], machine) == [
        "N001M42",
        "N001S005M03",
        "N002S005M41",
        "N003S015M42",
    ]
    combined = load_machine_text(
        manual_text(16).replace(
            "71 = 41\n72 = 41\n73 = 42\n74 = 42\n",
            '4 = "absent"\n5 = "absent"\n71 = 61\n72 = 60\n73 = 63\n74 = 62\n',
        ),
        "type16-combined.toml",
    )
    assert tape(["SPINDL/750,CLW", "SPINDL/1000", "SPINDL/150,CCLW"], combined) == [
        "N001S005M62",
        "N002S015",
        "N003S005M61",
    ]


def test_type16_rejects_missing_codes() -> None:
    text = manual_text(16).replace("  0.0, 2.0, 5.0, 15.0, 20.0, 30.0,\n", "")
    with pytest.raises(MachineDefinitionError, match=r"SRTAB\(13\)"):
        select(16, load_machine_text(text, "type16-broken.toml"), 750)


# --- type 17: proportional code 000-999 (§4.5.18) -------------------------------------


def test_type17_proportional_code() -> None:
    """SN = (SD - SMIN) / (SMAX - SMIN) x 1000 (001 L15522-15530): 300 RPM in 50..550 is
    S500; the maximum is S999 (549.5 RPM); 300.3 RPM is 500.6: S500 under option 90 = -1,
    S501 (300.5 RPM) under 0 and +1; 1400 RPM is range 2 (400..2400): S500."""
    machine = example(17)
    assert (select(17, machine, 300).command, select(17, machine, 300).speed) == (500.0, 300.0)
    top = select(17, machine, 550)
    assert (top.command, top.speed, top.comments) == (999.0, 549.5, ())
    assert select(17, machine, 300.3).command == 500.0
    for rule in (0.0, 1.0):
        chosen = select(17, machine.with_options({90: rule}), 300.3)
        assert (chosen.command, chosen.speed) == (501.0, 300.5)
    assert (select(17, machine, 1400).range, select(17, machine, 1400).command) == (2, 500.0)
    assert select(17, machine, 10).comments == (LOWEST_OUTPUT,)


def test_type17_stop_before_a_range_change_by_option_216_or_194() -> None:
    """ "If it is required that the spindle be stopped before changing ranges, set option
    216 = 1" (001 L15553-15555); option 194 is the option table's stop before a range
    change (001 L26523-26530). Either gives M05, then the new speed with M03."""
    program = ["SPINDL/300,CLW", "SPINDL/400", "SPINDL/1400", "SPINDL/2000"]
    expected = ["N001S500M03", "N002S700", "N003M05", "N003S500M03", "N004S800"]
    assert tape(program, example(17).with_options({216: 1.0})) == expected
    assert tape(program, example(17).with_options({194: 1.0})) == expected
    assert tape(program, example(17))[2:] == ["N003S500", "N004S800"]


def test_type17_rejects_a_range_without_span() -> None:
    text = manual_text(17).replace("400.0, 2400.0", "400.0, 400.0")
    with pytest.raises(MachineDefinitionError, match="minimum < SRTAB"):
        select(17, load_machine_text(text, "type17-broken.toml"), 300)


# --- type 18: generated table, type 2 codes (§4.5.19) ---------------------------------


def type18_example() -> MachineDefinition:
    """The manual's example (SRTAB = 340, .01, 1500, .01; options 7 = 2, 8 = 98, 31 = 103,
    47 = 203): SRTAB holds 2 x option 7 generation words, which the loader's checklist
    accepts for type 18."""
    return load_machine_text(manual_text(18), "type18-example.toml")


def test_type18_generated_table_and_codes() -> None:
    """SP-18 (001 L15578-15626): S300 = 340, S299 = 337, S298 = 333 ... S203 = 10 RPM;
    S500 = 1500, S499 = 1485, S498 = 1470 ... S403 = 45 RPM. The generated speeds are held
    in whole RPM as printed (340 x .99 = 336.6 -> 337, 340 x .03 = 10.2 -> 10)."""
    machine = type18_example()
    pairs = {
        340: 300.0,
        337: 299.0,
        333: 298.0,
        10: 203.0,
        1500: 500.0,
        1485: 499.0,
        1470: 498.0,
    }
    for speed, code in pairs.items():
        chosen = select(18, machine, speed)
        assert (chosen.speed, chosen.command) == (float(speed), code), speed
    assert select(18, machine, 45, 2).command == 403.0
    assert select(18, machine, 336.9).command == 298.0  # option 90 = -1: 333 RPM
    limits = [spindle(18).speed_limits(machine, r) for r in (1, 2)]
    assert limits == [(10.0, 340.0), (45.0, 1500.0)]
    assert spindle(18).table_speeds(machine, 1) is None  # variable in SFM


def test_type18_on_tape() -> None:
    machine = type18_example()
    program = ["SPINDL/340,CLW", "SPINDL/337", "SPINDL/10", "SPINDL/1500", "SPINDL/45,RANGE,2"]
    assert tape(program, machine) == [
        "N001S300M03",
        "N002S299",
        "N003S203",
        "N004S500",
        "N005S403",
    ]


def test_type18_rejects_a_change_that_runs_below_zero() -> None:
    machine = type18_example().with_options({8: 101.0})
    with pytest.raises(MachineDefinitionError, match=r"SRTAB\(1\)"):
        select(18, machine, 100)


def test_type18_shifts_as_type_2_under_option_137() -> None:
    """ "If option 137 is set, special shifting will be done as for the Type 2 spindle"
    (001 L39885-39886). Shift row 5 is 24 RPM (S207) in range 1 and 105 RPM (S407) in
    range 2: from 340 RPM to 1500 RPM, both above it, the spindle goes down to row 5,
    across to row 5 of range 2, then up; from 14 RPM (row 2) to 90 RPM (row 4 of range 2),
    both at or below it, the change is direct."""
    machine = type18_example().with_options({137: 5.0})
    assert tape(["SPINDL/340,CLW", "SPINDL/1500"], machine) == [
        "N001S300M03",
        "N002S207",
        "N002S407",
        "N002S500",
    ]
    assert tape(["SPINDL/14,CLW", "SPINDL/90,RANGE,2"], machine) == ["N001S204M03", "N002S406"]


# --- type 19: stop, comment and new speed on a range change (§4.5.20) ----------------


def test_type19_range_change_block_shape() -> None:
    """SP-19 (001 L15636-15645): N123G04M00 / A SPINDLE SPEED CHANGE OCCURS AT THIS POINT /
    N125G04S45. The example machine (option 38 = 1, option 47 = 40, option 31 = 1) makes
    160 RPM S45; from 400 RPM in range 2 it is a range change: the stop block, the comment
    and the speed block. Within a range, the speed alone."""
    machine = example(19)
    program = ["SPINDL/400,CLW", "SPINDL/160", "SPINDL/125"]
    assert tape_and_comments(program, machine) == [
        "N001G04S049M03",
        "N002G04M00",
        "A SPINDLE SPEED CHANGE OCCURS AT THIS POINT",
        "N002G04S045",
        "N003G04S044",
    ]


def test_type19_select_sets_the_stop_only_on_a_range_change() -> None:
    machine = example(19)
    change = select(19, machine, 160, running=Running(400.0, 2))
    assert (change.command, change.stop_cell, change.stop_comment) == (
        45.0,
        1,
        "A SPINDLE SPEED CHANGE OCCURS AT THIS POINT",
    )
    same = select(19, machine, 125, running=Running(160.0, 1))
    assert (same.command, same.stop_cell, same.stop_comment) == (44.0, None, None)
    assert select(19, machine, 400).command == 49.0  # 40 + 3 + (2 - 1) x (6 - 1 + 1)


def test_type19_needs_a_program_stop_code() -> None:
    text = manual_text(19).replace("[spindle_table]", '[tablem]\n1 = "absent"\n[spindle_table]')
    with pytest.raises(MachineDefinitionError, match=r"TABLEM\(1\)"):
        select(19, load_machine_text(text, "type19-broken.toml"), 160)
