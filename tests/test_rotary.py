"""Rotary tables and heads (manual §3.4.5, spec 03 worked examples W13-W20, W22, W25, W27):
the kernel functions, and ROTATE/TABLE through the whole post on incremental systems."""

from __future__ import annotations

from dataclasses import replace

import pytest
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.machine.regformat import decode_regfor
from gecent.core.motion.gcode import LinearCodes, RotaryCodes, larger
from gecent.core.motion.rotary import (
    CCLW,
    CLW,
    absolute_targets,
    carried_departures,
    normalise,
    rotary_move,
)
from gecent.core.motion.rounding import to_steps
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post


def rotary_outputs(lines: list[str], machine: MachineDefinition) -> list[float]:
    result = post(lines, machine)
    return [
        float(b.cells[b.rotary[0]])  # type: ignore[arg-type]
        for b in result.blocks
        if b.rotary is not None
    ]


def test_w13_hundredths_of_a_revolution() -> None:
    """W13 (001 L5483-5485): option 118 = -1, 90 deg -> 25, 180 deg -> 50."""
    machine = _all_codes().with_options({118: -1.0, 111: 359.9999, 119: 0.01})
    outputs = rotary_outputs(["ROTATE/HEAD,INCR,90", "ROTATE/HEAD,INCR,180"], _with_a(machine))
    assert outputs == pytest.approx([25.0, 50.0])


def test_w14_srorec_rounds_to_the_rotary_step() -> None:
    """W14 (001 L5508-5509): step 0.001, 10.246890 -> 10.247."""
    assert to_steps(10.246890, 0.001) * 0.001 == pytest.approx(10.247)


def test_w15_ninety_degrees_in_three_parts_keeps_every_pulse() -> None:
    """W15 (001 L5520-5546): output unit one revolution, step 0.00001 (the text's 0.0001
    does not match its five-decimal values): 0.08333, 0.08334, 0.08333 = 0.25000."""
    steps, carry = carried_departures(0.25, 35.99964 / 360, 0.00001, 0.0)
    assert steps == [8333, 8334, 8333]
    assert abs(carry) < 0.000005


def test_w20_six_moves_of_thirty_degrees_carry_the_difference() -> None:
    """W20 (001 L5717-5831): 0.08333333 rev each at step 0.0001: .0833, .0834, .0833,
    .0833, .0834, .0833 = 0.5000 rev = 180 deg exactly, whether one move of 180 deg is
    split in six or six moves of 30 deg are programmed."""
    split, _ = carried_departures(0.5, 35.99964 / 360, 0.0001, 0.0)
    assert split == [833, 834, 833, 833, 834, 833]
    carry, moves = 0.0, []
    for _ in range(6):
        steps, carry = carried_departures(30 / 360, 35.99964 / 360, 0.0001, carry)
        moves += steps
    assert moves == split


def test_w16_absolute_system_outputs_the_position() -> None:
    """W16 (001 L5561-5568): ATANGL 23 CLW -> 23; then INCR 10 CLW -> 33."""
    first = rotary_move(0.0, 23, absolute=True, direction=CLW)
    second = rotary_move(first.position, 10, absolute=False, direction=CLW)
    assert absolute_targets(0.0, first) == [23.0]
    assert absolute_targets(first.position, second) == [33.0]


def test_w17_absolute_system_long_way_round_in_two_moves() -> None:
    """W17 (001 L5570-5592): at 90, the shorter way to 180 is CCLW, so the scale reads
    lower clockwise (option 117 = -1); ATANGL 180 CLW goes to 271 then 180."""
    move = rotary_move(90.0, 180, absolute=True, direction=CLW, clw_increases=False)
    assert move.travel == 270.0
    assert absolute_targets(90.0, move, clw_increases=False) == [271.0, 180.0]


def test_w18_incremental_system_outputs_the_departure() -> None:
    """W18 (001 L5638-5649): at 10, ATANGL 23 CLW -> 13; then INCR 10 CLW -> 10 (at 33)."""
    first = rotary_move(10.0, 23, absolute=True, direction=CLW)
    second = rotary_move(first.position, 10, absolute=False, direction=CLW)
    assert (first.travel, second.travel, second.position) == (13.0, 10.0, 33.0)


@pytest.mark.parametrize(("angle", "expected"), [(-40, 320), (-400, 320), (360, 0), (725, 5)])
def test_w19_angles_are_kept_in_0_to_360(angle: float, expected: float) -> None:
    assert normalise(angle) == expected


def test_atangl_without_a_direction_takes_the_shorter_way() -> None:
    assert rotary_move(90.0, 0, absolute=True, direction=None).travel == -90.0
    assert rotary_move(90.0, 0, absolute=True, direction=CCLW).travel == -90.0
    assert rotary_move(90.0, 0, absolute=True, direction=CLW).travel == 270.0


def test_w25_rotary_g_selection() -> None:
    """W25 (001 L6240-6260), output in degrees: option 111 = 360, largest 40 -> TABLEG(11),
    GDIMUL 100; option 111 = 36, largest 0.1 -> TABLEG(12), GDIMUL 1."""
    machine = _all_codes()
    wide = RotaryCodes(machine, 360.0).select(40.0)
    narrow = RotaryCodes(machine, 36.0).select(0.1)
    assert (wide.location, wide.gdimul) == (11, 100.0)
    assert (narrow.location, narrow.gdimul) == (12, 1.0)


def test_w22_linear_and_rotary_take_the_larger_range() -> None:
    """W22 (001 L6059-6068, L6271-6282): dX 0.2, dY 0.1, dZ 0.09 alone take TABLEG(12);
    dA = 40 deg needs the 36-359.9999 deg code, TABLEG(11), which covers both."""
    machine = _all_codes()
    linear = LinearCodes(machine, 0.0001).select(2000)
    rotary = RotaryCodes(machine, 359.9999).select(40.0)
    assert (linear.location, rotary.location) == (12, 11)
    assert larger(linear, rotary).location == 11


def test_w27_tracked_table_goes_back_to_zero_clockwise() -> None:
    """W27 (001 L6714-6728), degrees: INCR 10, 20, 10 then ATANGL 0 CLW is a 320 deg move,
    output in nine parts under option 111 (35.99964) that add up to 320 exactly."""
    machine = _with_a(_all_codes().with_options({118: 1.0, 119: 0.0001}))
    lines = ["ROTATE/TABLE,INCR,10,CLW", "ROTATE/TABLE,INCR,20,CLW", "ROTATE/TABLE,INCR,10,CLW"]
    outputs = rotary_outputs([*lines, "ROTATE/TABLE,ATANGL,0,CLW"], machine)
    assert outputs[:3] == pytest.approx([10.0, 20.0, 10.0])
    assert len(outputs[3:]) == 9 and sum(outputs[3:]) == pytest.approx(320.0)


def test_mach23_rotary_table_in_revolutions() -> None:
    """MACH23's one rotary register, A (REGFOR(6) = -6: fractions of a revolution), drives
    the table; 90 deg CLW is three blocks of G10 (0.0833 rev is above option 111 / 10) with
    F = 100 x 10 IPM / (30 deg x 6 in part radius) = 318."""
    machine = get_plugins().machine("mach23").load()
    result = post(["FEDRAT/10", "ROTATE/TABLE,INCR,90,CLW", "ROTATE/TABLE,ATANGL,0"], machine)
    assert [b.punch for b in result.blocks if b.punch] == [
        "N002G10A+0833F318",
        "N002G10A+0834",
        "N002G10A+0833",
        "N003G10A-0833",
        "N003G10A-0834",
        "N003G10A-0833",
    ]


def _with_a(machine: MachineDefinition) -> MachineDefinition:
    """A machine without a rotary register given an A of format -33."""
    registers = machine.registers
    formats = list(registers.formats)
    regfor = list(registers.regfor)
    formats[6], regfor[6] = decode_regfor(-33.0), -33.0
    heads = (replace(registers, formats=tuple(formats), regfor=tuple(regfor)),)
    return replace(machine, heads=heads + machine.heads[1:])


def _all_codes() -> MachineDefinition:
    text = '[machine]\nname = "codes"\ntitle = "ALL CODES"\n'
    text += "[tableg]\n11 = 10\n12 = 11\n13 = 12\n14 = 13\n15 = 14\n"
    text += "[regfor]\n3 = -24.0\n4 = -24.0\n5 = -24.0\n[optab]\n4 = 99.9999\n"
    return load_machine_text(text, "codes.toml")
