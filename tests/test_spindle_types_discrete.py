"""Discrete spindle types 0, 2, 3, 4, 5, 6, 8 and 9 (manual §4.5.1-§4.5.10, 001
L14604-15039): the manual's worked examples SP-0a..SP-9, each at the select level and on
tape through a post, and the machine data each type refuses."""

from __future__ import annotations

from typing import Any

import pytest
from gecent.core.errors import MachineDefinitionError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins
from gecent.core.spindle_types import (
    CCLW,
    CLW,
    Running,
    SpindleRequest,
    SpindleSelection,
    SpindleStep,
)

from tests.test_post_linear import post


def spindle_type(number: int) -> Any:
    plugin = get_plugins().get("spindles", number)
    assert plugin is not None, f"spindle type {number} is registered"
    return plugin


def example(number: int, *, replace: dict[str, str] | None = None) -> MachineDefinition:
    """The type's manual example machine, with some lines of its TOML replaced."""
    text = spindle_type(number).manual_example
    for old, new in (replace or {}).items():
        assert old in text
        text = text.replace(old, new)
    return load_machine_text(text, f"type{number:02d}.toml")


def select(
    number: int, machine: MachineDefinition, speed: float, **request: Any
) -> SpindleSelection:
    return spindle_type(number).select(machine, SpindleRequest(speed, **request))  # type: ignore[no-any-return]


def tape(lines: list[str], machine: MachineDefinition) -> list[str]:
    return tape_lines(post(lines, machine).blocks)


def warnings(lines: list[str], machine: MachineDefinition) -> list[str]:
    return [d.text for d in post(lines, machine).diagnostics]


def table_machine(number: int, ranges: int, rows: int, *, extra: str = "") -> MachineDefinition:
    """Range r holds speeds 100 r + row, so a speed names its own range and row."""
    speeds = ", ".join(f"{100.0 * r + row}" for r in range(1, ranges + 1) for row in range(rows))
    text = f"""
[machine]
name = "type{number:02d}-{ranges}x{rows}"
[optab]
7 = {ranges}.0
8 = {rows}.0
19 = {number}.0
{extra}
[spindle_table]
speeds = [{speeds}]
"""
    return load_machine_text(text, "table.toml")


# Type 0 (§4.5.1) --------------------------------------------------------------------------


def test_sp0a_speed_12_is_range_and_row() -> None:
    """SP-0a, 001 L14625-14627: speed 12, option 47 = 0, is S15 (range 1, row 5) or, with
    RANGE,2, S20 (range 2, row 0); the OCR prints "815" for S15."""
    machine = example(0)
    assert (select(0, machine, 12).command, select(0, machine, 12).range) == (15, 1)
    assert (select(0, machine, 12, range=2).command, select(0, machine, 12, range=2).row) == (20, 0)


def test_sp0b_more_than_ten_rows_take_two_digits() -> None:
    """SP-0b, 001 L14629-14631: with more than ten rows per range the row takes two digits:
    S622 is range 6, row 22 (OCR "8622")."""
    machine = table_machine(0, 6, 23)
    assert select(0, machine, 622).command == 622


def test_sp0c_more_than_ten_ranges_give_four_digits() -> None:
    """SP-0c, 001 L14631-14634: S1204 is range 12, row 4 and S1011 range 10, row 11 (OCR
    "81204"); the table has more than ten rows, as row 11 shows, so rows take two digits
    (TYPE00's K = 100, L39111-39118)."""
    machine = table_machine(0, 12, 12)
    assert select(0, machine, 1204).command == 1204
    assert select(0, machine, 1011).command == 1011


def test_type0_ten_rows_or_fewer_keep_one_digit_for_any_range() -> None:
    """TYPE00 (001 L39111-39118): K = 10 while a range holds at most ten speeds, whatever
    the number of ranges: range 12, row 4 of a ten-row table is S124."""
    machine = table_machine(0, 12, 10)
    assert select(0, machine, 1204).command == 124


def test_type0_on_tape() -> None:
    """SP-0a on tape: the lowest range is used unless RANGE,n; above the table the highest
    speed (range 3, row 9: S39) with comment 63."""
    machine = example(0)
    program = ["SPINDL/12,CLW", "SPINDL/12,RANGE,2", "SPINDL/50"]
    assert tape(program, machine) == ["N001S15M03", "N002S20", "N003S39"]
    assert warnings(program, machine) == ["SPINDLE SPEED COULD NOT BE FOUND."]


def test_type0_row_codes_must_fit_their_digit() -> None:
    """Ten rows with option 47 = 1 would make range 1's last code 10 + 10 = 20, range 2's
    first: the machine file is refused, naming option 47."""
    machine = example(0, replace={"47 = 0.0": "47 = 1.0"})
    with pytest.raises(MachineDefinitionError) as error:
        select(0, machine, 12)
    assert (error.value.table, error.value.entry) == ("optab", 47)


# Type 2 (§4.5.3) --------------------------------------------------------------------------

SHIFTING = """
[machine]
name = "type02-shifting"
[optab]
7 = 2.0
8 = 7.0
19 = 2.0
31 = 1.0
54 = {dwell}
137 = 5.0
[regfor]
12 = 20.0
[spindle_table]
speeds = [2.0, 4.0, 6.0, 8.0, 10.0, 20.0, 30.0, 40.0, 60.0, 80.0, 100.0, 120.0, 140.0, 160.0]
"""


def shifting(dwell: float = 0.0) -> MachineDefinition:
    return load_machine_text(SHIFTING.format(dwell=dwell), "type02-shifting.toml")


def test_sp2_speed_14_is_s15_or_s20() -> None:
    """SP-2, 001 L14745-14749: option 47 = 10, option 31 = 3, eight speeds a range: speed
    14 is S15 (range 1, row 5) or S20 (range 2, row 0: 10 + 0 + 1 x (7 + 3))."""
    machine = example(2)
    assert select(2, machine, 14).command == 15
    assert select(2, machine, 14, range=2).command == 20
    assert select(2, machine, 44).command == 37  # range 3's last code


def test_type2_on_tape() -> None:
    """SP-2 on tape, with the S register two digits wide."""
    machine = example(2)
    assert tape(["SPINDL/14,CLW", "SPINDL/14,RANGE,2"], machine) == ["N001S15M03", "N002S20"]


def test_sp2s_protective_shifting_paths() -> None:
    """SP-2s1..s5, 001 L14752-14800: ranges 2..30 and 40..160 RPM, shift point at row 5
    (option 137 = 5; codes 0-6 and 7-13 with option 31 = 1). Each step is a block of its
    own (record 3 gives three blocks)."""
    machine = shifting()
    program = [
        "SPINDL/2,CLW",
        "SPINDL/30",  # SP-2s3: same range, direct
        "SPINDL/160",  # SP-2s1: 10 (S04), 120 (S11), 160 (S13)
        "SPINDL/30",  # SP-2s2: the similar path back: 120, 10, 30
        "SPINDL/160",
        "SPINDL/4",  # SP-2s4: 60 (S08) in range 2, then 4 (S01) at the same row
        "SPINDL/8",
        "SPINDL/100",  # SP-2s5: both at or below the shift row: direct
    ]
    assert tape(program, machine) == [
        "N001S00M03",
        "N002S06",
        "N003S04",
        "N003S11",
        "N003S13",
        "N004S11",
        "N004S04",
        "N004S06",
        "N005S04",
        "N005S11",
        "N005S13",
        "N006S08",
        "N006S01",
        "N007S03",
        "N008S10",
    ]


def test_type2_shift_from_low_to_high_goes_across_at_the_old_row() -> None:
    """Open question 16 (001 L14752-14800): 2 RPM (range 1, row 1) to 160 RPM (range 2,
    row 7) is not described; decided as the reverse of SP-2s4: across at the old row to 40
    RPM (S07), then up to 160 (S13)."""
    machine = shifting()
    running = select(2, machine, 2)
    selection = select(2, machine, 160, running=Running(running.speed, running.range))
    assert selection.steps == (SpindleStep(7.0, 2),)
    assert selection.command == 13


def test_type2_steps_carry_option_54() -> None:
    """TYPE02 calls DWELL (001 L39188-39211): with option 54 = 3 s each intermediate speed
    rides in a dwell block; a direct range change gets the kernel's option-54 dwell after."""
    machine = shifting(3.0)
    program = ["SPINDL/30,CLW", "SPINDL/160", "SPINDL/100"]
    assert tape(program, machine) == [
        "N001S06M03",
        "N002G04X+03S04",
        "N002G04X+03S11",
        "N002S13",
        "N003S10",
    ]
    assert tape(["SPINDL/8,CLW", "SPINDL/100"], machine) == [
        "N001S03M03",
        "N002S10",
        "N002G04X+03",
    ]


def test_type2_refuses_overlapping_codes_and_a_negative_shift_row() -> None:
    """Option 31 = 0 would give range 1's last speed and range 2's first the same code;
    a negative option 137 is type 10's shift speed, not a row."""
    with pytest.raises(MachineDefinitionError) as error:
        select(2, example(2, replace={"31 = 3.0": "31 = 0.0"}), 14)
    assert (error.value.table, error.value.entry) == ("optab", 31)
    machine = load_machine_text(SHIFTING.format(dwell=0.0).replace("137 = 5.0", "137 = -0.25"))
    with pytest.raises(MachineDefinitionError) as error:
        select(2, machine, 14)
    assert (error.value.table, error.value.entry) == ("optab", 137)


def test_mach51_type2_spindle() -> None:
    """MACH51 (001 L28178-28292): one range of 100 speeds, codes = row (option 47 = 0),
    S two digits: 250 RPM takes the next lower 244 (row 53), 100 takes 96 (row 33), and
    900 is above the table: 795 (S99) with comment 63."""
    machine = get_plugins().machine("mach51").load()  # type: ignore[union-attr]
    program = ["SPINDL/250,CLW", "SPINDL/100", "SPINDL/900"]
    assert tape(program, machine) == ["N001G04S53M03", "N002G04S33", "N003G04S99"]


# Type 3 (§4.5.4) --------------------------------------------------------------------------

COMBINED = {
    "71 = 41\n72 = 41\n73 = 42\n74 = 42\n75 = 43\n76 = 43": (
        '4 = "absent"\n5 = "absent"\n71 = 2\n72 = 1\n73 = 4\n74 = 3\n75 = 6\n76 = 5'
    )
}


def test_sp3a_range_only_codes() -> None:
    """SP-3a, 001 L14857-14861: option 47 = 2, speed 400 is S5 with range 1's code M1 or
    S3 with range 2's M2 (here M41, M42 in TABLEM 71/72 and 73/74); the direction is
    TABLEM 4/5's."""
    machine = example(3)
    low = select(3, machine, 400)
    assert (low.command, low.range_cell, low.direction_cells) == (5, 72, None)
    high = select(3, machine, 400, range=2)
    assert (high.command, machine.m_code(high.range_cell or 0)) == (3, 42)


def test_sp3b_combined_codes() -> None:
    """SP-3b, 001 L14883-14893: combined codes M1..M6 (range 1 CLW/CCLW = M1/M2, ...;
    CLW in TABLEM 70 + 2n): speed 400 clockwise is S5 with M1 or S3 with M3 (OCR "M)")."""
    machine = example(3, replace=COMBINED)
    low = select(3, machine, 400)
    assert (low.command, machine.m_code(low.direction_cells[CLW])) == (5, 1)  # type: ignore[index]
    high = select(3, machine, 400, range=2)
    assert (high.command, machine.m_code(high.direction_cells[CLW])) == (3, 3)  # type: ignore[index]
    assert machine.m_code(high.direction_cells[CCLW]) == 4  # type: ignore[index]


def test_type3_combined_codes_on_tape() -> None:
    """SP-3b on tape: the combined code replaces M03/M04 and goes out when the spindle
    starts, changes range or reverses."""
    machine = example(3, replace=COMBINED)
    program = ["SPINDL/400,CLW", "SPINDL/400,RANGE,2", "SPINDL/450", "SPINDL/900,CCLW"]
    assert tape(program, machine) == ["N001S5M01", "N002S3M03", "N003S5M01", "N004S5M06"]


def test_type3_range_only_codes_on_tape() -> None:
    """SP-3a on tape: the start gives the range code M41 (the gear first, TYPE03 001
    L39227-39290), then S5 with M03; afterwards only a changed range code is output (one M
    code to a block, STOREM)."""
    machine = example(3)
    program = ["SPINDL/400,CLW", "SPINDL/400,RANGE,2", "SPINDL/450", "SPINDL/300"]
    assert tape(program, machine) == [
        "N001M41",
        "N001S5M03",
        "N002S3M42",
        "N003S5M41",
        "N004S4",
    ]


@pytest.mark.parametrize(
    ("change", "entry"),
    [
        ({"72 = 41": "72 = 44"}, 71),  # scheme (a): the two slots of range 1 differ
        ({"75 = 43\n76 = 43": ""}, 75),  # range 3 has no code
        ({"[tablem]": '[tablem]\n5 = "absent"'}, 5),  # M03 without M04
        ({"7 = 3.0": "7 = 7.0", "8 = 5.0": "8 = 2.0"}, 7),  # seven ranges: 71..82 hold six
    ],
)
def test_type3_refuses_unusable_codes(change: dict[str, str], entry: int) -> None:
    text = spindle_type(3).manual_example
    for old, new in change.items():
        text = text.replace(old, new)
    if entry == 7:
        text = text.replace(
            text[text.index("speeds = [") :], f"speeds = [{', '.join(['1.0', '2.0'] * 7)}]\n"
        )
    machine = load_machine_text(text, "type03.toml")
    with pytest.raises(MachineDefinitionError) as error:
        select(3, machine, 400)
    assert error.value.entry == entry


# Type 4 (§4.5.5) --------------------------------------------------------------------------


def test_sp4_speed_600_in_each_range() -> None:
    """SP-4, 001 L14921-14925: speed 600 is S660 with M1 (range 1, row 5), S630 with M2
    (range 2, row 2: range 1's 300) or S610 with M3 (range 3, row 0: range 1's 100); OCR
    "8660", "8610". M1..M3 clockwise are M41..M43 here."""
    machine = example(4)
    expected = {None: (660, 41), 2: (630, 42), 3: (610, 43)}
    for requested, (command, code) in expected.items():
        selection = select(4, machine, 600, range=requested)
        assert selection.command == command
        assert machine.m_code(selection.direction_cells[CLW]) == code  # type: ignore[index]


def test_type4_on_tape() -> None:
    """SP-4 on tape: the range-and-direction code with the S code when the spindle starts,
    changes range or reverses (range 3 CCLW = M46)."""
    machine = example(4)
    program = [
        "SPINDL/600,CLW",
        "SPINDL/600,RANGE,2",
        "SPINDL/650",  # range 2 (400-900), next lower 600: no new code
        "SPINDL/550",  # range 1's 500
        "SPINDL/600,CCLW,RANGE,3",
    ]
    assert tape(program, machine) == [
        "N001S660M41",
        "N002S630M42",
        "N003S630",
        "N004S650M41",
        "N005S610M46",
    ]


def test_type4_shift_rows_are_type_2s() -> None:
    """Type 4's down-shift takes option 137 = -N (tests/test_spindle_wave3.py); +N, the
    shift row, is type 2's (001 L26008-26023): a machine-definition error here."""
    machine = example(4, replace={"19 = 4.0": "19 = 4.0\n137 = 5.0"})
    with pytest.raises(MachineDefinitionError, match="137"):
        select(4, machine, 600)


def test_type4_needs_its_range_codes() -> None:
    machine = example(4, replace={"75 = 46\n": ""})
    with pytest.raises(MachineDefinitionError) as error:
        select(4, machine, 600)
    assert (error.value.table, error.value.entry) == ("tablem", 75)


# Types 5 and 6 (§4.5.6, §4.5.7) -----------------------------------------------------------


@pytest.mark.parametrize("number", [5, 6])
def test_sp5_speed_13_is_s512(number: int) -> None:
    """SP-5, 001 L14941-14963: table 2, 3, 5, 7, 10, 12, 15, 17, ... 193, 197, 200 (its
    middle elided); speed 13 is S512, 12 being selected. Type 6 is treated as type 5
    (001 L14965-14979)."""
    machine = example(number)
    selection = select(number, machine, 13)
    assert (selection.speed, selection.command) == (12, 512)
    assert select(number, machine, 196).command == 619  # next lower: 193
    assert select(number, machine, 199).command == 620  # 197 codes as 200 does


@pytest.mark.parametrize("number", [5, 6])
def test_type5_on_tape(number: int) -> None:
    machine = example(number)
    program = ["SPINDL/13,CLW", "SPINDL/250", "SPINDL/1"]
    assert tape(program, machine) == ["N001S512M03", "N002S620", "N003S420"]
    assert warnings(program, machine) == [
        "SPINDLE SPEED COULD NOT BE FOUND.",
        "LOWEST SPEED IN RANGE IS OUTPUT.",
    ]


@pytest.mark.parametrize(
    ("change", "entry"),
    [({"19 = 5.0": "19 = 5.0\n90 = 0.0"}, 90), ({"7 = 1.0\n8 = 23.0": "7 = 23.0\n8 = 1.0"}, 7)],
)
def test_type5_keeps_next_lower_and_one_range(change: dict[str, str], entry: int) -> None:
    """Open question 21 (001 L14937-14945): next lower is part of type 5, so option 90
    must stay -1; and type 5 has no multiple ranges."""
    with pytest.raises(MachineDefinitionError) as error:
        select(5, example(5, replace=change), 13)
    assert error.value.entry == entry


# Type 8 (§4.5.9) --------------------------------------------------------------------------


def test_sp8_codes_independent_of_range() -> None:
    """SP-8, 001 L15004-15007: option 47 = 1; speed 40 is S04 in range 1 and S01 in range
    2; speed 70 with range 3 in use is S01."""
    machine = example(8)
    assert select(8, machine, 40).command == 4
    assert select(8, machine, 40, range=2).command == 1
    assert select(8, machine, 70, range=3).command == 1


def test_type8_on_tape_has_no_range_code() -> None:
    """SP-8 on tape: range shifting is not tape controlled, so the S code goes alone."""
    machine = example(8)
    program = ["SPINDL/40,CLW", "SPINDL/40,RANGE,2", "SPINDL/70,RANGE,3"]
    assert tape(program, machine) == ["N001S04M03", "N002S01", "N003S01"]


def test_mach24_type8_spindle() -> None:
    """MACH24 (001 L27600-27680): 3 ranges of 8 speeds, option 47 = 0, no M03 (TABLEM(4)
    absent: comment 22). 1200 RPM lies in range 2 (100-1600), next lower 1060: S06; 100
    RPM is range 1's row 1: S01; 140 in range 2 is 100: S00; 3000 is range 3's top: S07."""
    machine = get_plugins().machine("mach24").load()  # type: ignore[union-attr]
    program = ["SPINDL/1200,CLW", "SPINDL/100", "SPINDL/140,RANGE,2", "SPINDL/3000"]
    assert tape(program, machine) == ["N001S06", "N002S01", "N003S00", "N004S07"]
    assert warnings(program, machine) == [
        "REQUESTED MISCELLANEOUS FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE",
        "SPINDLE SPEED COULD NOT BE FOUND.",
    ]


# Type 9 (§4.5.10) -------------------------------------------------------------------------


def test_sp9_range_from_the_tool() -> None:
    """SP-9, 001 L15028-15039: option 47 = 0, speed 50 is S04 with tool 1 (range 1, row 4)
    and S01 with tool 5 (range 2, row 1); OCR "804", "801". Open question 22: the tools
    cycle through the ranges as the example's header says (tools 1 & 4, 2 & 5, 3 & 6)."""
    machine = example(9)
    assert (select(9, machine, 50, tool=1).command, select(9, machine, 50, tool=1).range) == (4, 1)
    assert (select(9, machine, 50, tool=5).command, select(9, machine, 50, tool=5).range) == (1, 2)
    third = select(9, machine, 50, tool=6)  # range 3 starts at 70: its lowest, comment 80
    assert (third.range, third.command, third.comments) == (
        3,
        0,
        ("LOWEST SPEED IN RANGE IS OUTPUT.",),
    )
    assert select(9, machine, 50, tool=7).range == 1


def test_type9_without_a_tool() -> None:
    """No tool in use: RANGE,n if given, else the lowest range holding the speed with the
    SPINDL comment "LOWEST RANGE THAT SPINDLE SPEED FALLS IN IS ASSUMED" (001 L37610-37630)."""
    machine = example(9)
    assumed = select(9, machine, 50)
    assert (assumed.range, assumed.command) == (1, 4)
    assert assumed.comments == ("LOWEST RANGE THAT SPINDLE SPEED FALLS IN IS ASSUMED",)
    programmed = select(9, machine, 50, range=2)
    assert (programmed.range, programmed.command, programmed.comments) == (2, 1, ())


def test_type9_on_tape() -> None:
    """SP-9 on tape: TOOLNO/1 then 50 RPM is S04; TOOLNO/5 then 50 RPM is S01; a RANGE,3
    under tool 5 keeps the tool's range 2, with a comment."""
    machine = example(9)
    program = ["TOOLNO/1", "SPINDL/50,CLW", "TOOLNO/5", "SPINDL/50", "SPINDL/50,RANGE,3"]
    lines = [line for line in tape(program, machine) if "S" in line]
    assert lines == ["N002S04M03", "N004S01", "N005S01"]
    assert warnings(program, machine) == ["RANGE 3 IS NOT USED, TOOL 5 TURNS IN RANGE 2"]
