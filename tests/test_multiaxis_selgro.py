"""SELGRO in OUTPUT for multiaxis blocks (manual §3.4.6.1-3.4.6.3, 001 L6052-6069,
L6150-6170, L6171-6282; spec 03 §11.3-11.5, §12.4, §13 step 7; W22, W24, W25): a CODE 0
move or a circle that also turns a rotary axis keeps SELG's (SELGCR's) code when that
code's rotary range covers the largest rotary departure (DBFSEG 6, 7, 18, output units),
else takes one that covers both; the feed command's GDIMUL is the chosen code's."""

from __future__ import annotations

from math import cos, radians, sin
from pathlib import Path

import pytest
from gecent.core.dispatch.post import post
from gecent.core.errors import FatalError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.motion.gcode import CircularCodes, LinearCodes, RotaryCodes, circle_code
from gecent.core.output.block import Block, Code
from gecent.core.output.element import OutputElement
from gecent.core.output.tape import tape_line
from gecent.core.plugins import get_plugins
from gecent.core.state import PostState

STEP = 0.0001
# every dimension code of the manual's tables (its examples assume them all, L6127-6128,
# L6247-6248): G numbers = location - 1, as TABLEG(2) = G01 and TABLEG(3) = G02
ALL_CODES = (
    "[tableg]\n11 = 10\n12 = 11\n13 = 12\n14 = 13\n15 = 14\n"
    "21 = 20\n22 = 21\n23 = 22\n31 = 30\n32 = 31\n33 = 32\n"
)


def machine(options: str = "", tableg: str = ALL_CODES) -> MachineDefinition:
    """The Standard Machine with every code, rotary output in degrees (option 118 = +1),
    option 4 = 99.9999 and the feedrate number (option 10 = 0: F = GDIMUL x IPM / L)."""
    text = '[machine]\nname = "selgro"\ntitle = "SELGRO"\n' + tableg
    text += f"[optab]\n4 = 99.9999\n118 = 1.0\n{options}"
    return load_machine_text(text, "selgro.toml")


def element(definition: MachineDefinition, ipm: float = 1.0) -> OutputElement:
    out = OutputElement(PostState(definition))
    out.state.feed.ipm = ipm
    out.state.feed.programmed = ipm
    return out


def linear(
    departures: tuple[float, float, float], rotary: dict[int, float], length: float = 0.0
) -> Block:
    """A CODE 0 multiaxis block: linear departures (inches), rotary ones by cell."""
    steps = tuple(round(d / STEP) for d in departures)
    block = Block.motion(Code.LINEAR, 1, steps, steps, STEP)
    for cell, value in rotary.items():
        block.cells[cell] = value
    block.feed_length = length
    return block


def arc(code: Code, radius: float, turn: float) -> Block:
    """A multiaxis quadrant block of ``radius`` (XY) turning the table (cell 7)."""
    steps = (round(radius / STEP), round(radius / STEP), 0)
    block = Block.motion(code, 1, steps, steps, STEP)
    block.radius = radius
    block.cells[8] = radius
    block.cells[9] = 0.0
    block.cells[7] = turn
    return block


# -- W22: linear + rotary ------------------------------------------------------------------


def test_w22_selgro_overrides_the_linear_code() -> None:
    """W22 (001 L6059-6068, L6271-6282): dX 0.2, dY 0.1, dZ 0.09 take the 0.1-0.9999 code
    (TABLEG(12)), whose rotary range reaches 3.5999 degrees only (ROTMAX 359.9999); dA =
    40 degrees moves the block up two ranges to the 36-359.9999 code, TABLEG(11) = G10,
    GDIMUL 100, which also covers the linear moves: F = 100 x 1 IPM / 0.24104."""
    out = element(machine("111 = 359.9999\n"))
    block = linear((0.2, 0.1, 0.09), {6: 40.0})
    out.motion(block)
    assert block.cells[2] == 10.0
    length = (0.2**2 + 0.1**2 + 0.09**2) ** 0.5
    assert block.cells[11] == round(100.0 * 1.0 / length)  # (F format 40: whole numbers)
    # without the rotary departure SELG's own code, GDIMUL 1
    plain = linear((0.2, 0.1, 0.09), {})
    out.motion(plain)
    assert plain.cells[2] == 11.0
    assert plain.cells[11] == round(1.0 * 1.0 / length)


def test_w22_selgro_accepts_a_code_that_covers_the_turn() -> None:
    """SELGRO keeps SELG's code when its rotary range covers the turn: 3 degrees is within
    TABLEG(12)'s 0.36-3.5999 (W22's "extends only to 3.5999"); a 20 in departure's
    TABLEG(11) covers 40 degrees; a negative departure counts by its size."""
    out = element(machine("111 = 359.9999\n"))
    small = linear((0.2, 0.1, 0.09), {6: -3.0})
    out.motion(small)
    assert small.cells[2] == 11.0
    long = linear((20.0, 2.0, 0.2), {7: 40.0})
    out.motion(long)
    assert long.cells[2] == 10.0
    over = linear((0.2, 0.1, 0.09), {6: -3.6})
    out.motion(over)
    assert over.cells[2] == 1.0  # 3.6-35.9999: TABLEG(2) = G01, GDIMUL 10


def test_an_absent_code_is_skipped_upward() -> None:
    """SELGRO, as SELG, uses only the codes the machine has (001 L5959-5962): without a
    TABLEG(2), a 10-degree turn under G11 goes to TABLEG(11)."""
    codes = ALL_CODES.replace("[tableg]\n", '[tableg]\n2 = "absent"\n')
    out = element(machine("111 = 359.9999\n", codes))
    block = linear((0.2, 0.1, 0.09), {6: 10.0})
    out.motion(block)
    assert block.cells[2] == 10.0


# -- W25: rotary departures in cells 6, 7, 18 ---------------------------------------------


def test_w25_example_1_the_largest_of_a_b_c() -> None:
    """W25 ex. 1 (001 L6240-6252): dA 40, dB 1, dC 0.1 degrees, option 111 = 360: dA is
    the largest, 360/10 < 40 < 360/1: TABLEG(11), GDIMUL 100. A CODE 0 block without
    linear departures (spec 03 §12.4) whose feed path is 2 in: F = 100 x 1 / 2 = 50."""
    out = element(machine("111 = 360.0\n"))
    block = linear((0.0, 0.0, 0.0), {6: 40.0, 7: 1.0, 18: 0.1}, length=2.0)
    out.motion(block)
    assert block.cells[2] == 10.0
    assert block.cells[11] == pytest.approx(50.0)


def test_w25_example_2_a_smaller_rotary_maximum() -> None:
    """W25 ex. 2 (001 L6253-6260): dA 0.0001, dB 0.1, option 111 = 36 degrees: |dB| is
    the largest, 36/1000 < 0.1 < 36/100: TABLEG(12), GDIMUL 1: F = 1 x 1 / 0.5 = 2."""
    out = element(machine("111 = 36.0\n"))
    block = linear((0.0, 0.0, 0.0), {6: 0.0001, 7: -0.1}, length=0.5)
    out.motion(block)
    assert block.cells[2] == 11.0
    assert block.cells[11] == pytest.approx(2.0)


def test_rotary_codes_rank_and_cover() -> None:
    """W25's ranges as SELGRO's ranks (13, 12, 2, 11) and the acceptance of a code."""
    definition = machine()
    rotary = RotaryCodes(definition, 360.0)
    assert [rotary.needed(t) for t in (0.3, 0.36, 3.6, 40.0, 359.0)] == [0, 1, 2, 3, 3]
    codes = LinearCodes(definition, STEP)
    g11 = codes.select(2000)  # 0.2 in: TABLEG(12)
    assert rotary.covers(g11, 3.5999) and not rotary.covers(g11, 3.6)
    assert rotary.with_linear(g11, 40.0).location == 11
    assert rotary.with_linear(g11, 0.0) is g11


# -- W24: circle + rotary -----------------------------------------------------------------


def test_w24_output_takes_the_circular_code_selgro_needs() -> None:
    """W24 (001 L6150-6170): CIRRAD 8.67 gives the 1-9.9999 code (TABLEG(3) CLW, (4)
    CCLW), whose rotary range reaches 35.9999 degrees only; dA 40 needs the 36-359.9999
    range: OUTPUT puts the arc under the circular code of that range, TABLEG(21) = G20
    CLW, TABLEG(31) = G30 CCLW, GDIMUL 100 (open question 11: a circle keeps a circular
    code). F = GDIMUL x IPM / R."""
    out = element(machine("111 = 359.9999\n"))
    clw = arc(Code.CIRCLE_XY_CLW, 8.67, 40.0)
    ccw = arc(Code.CIRCLE_XY_CCLW, 8.67, -40.0)
    within = arc(Code.CIRCLE_XY_CLW, 8.67, 35.0)
    for block in (clw, ccw, within):
        out.motion(block)
    assert (clw.cells[2], ccw.cells[2], within.cells[2]) == (20.0, 30.0, 2.0)
    assert clw.cells[11] == round(100.0 / 8.67)
    assert within.cells[11] == round(10.0 / 8.67)


def test_circle_code_without_the_band_is_fatal_144() -> None:
    """No circular code covers the turn (no TABLEG(21) or (31)): fatal 144, SELGCR's
    "no G code is available" (001 L28458-28475)."""
    definition = machine("111 = 359.9999\n", "[tableg]\n11 = 10\n")
    circular = CircularCodes(definition)
    rotary = RotaryCodes(definition, 359.9999)
    assert circle_code(circular, rotary, 8.67, True, 35.0).location == 3
    with pytest.raises(FatalError, match="fatal error 144"):
        circle_code(circular, rotary, 8.67, True, 40.0)


# -- machines -----------------------------------------------------------------------------


def mach40(overlay: str = "") -> MachineDefinition:
    pack = get_plugins().machine("mach40")
    assert pack is not None
    text = f'[machine]\nname = "mach40x"\ntitle = "MACH40 TEST"\n{overlay}'
    return load_machine_text(text, "mach40x.toml", pack.load())


def run(tmp_path: Path, lines: list[str], definition: MachineDefinition) -> list[str]:
    program = tmp_path / "s.apt"
    program.write_text("\n".join(["PARTNO SELGRO", *lines, "FINI", ""]))
    result = post(str(program), get_plugins(), machine_override=definition)
    return [line for b in result.blocks if b.code is not Code.PARTNO and (line := tape_line(b))]


def turn_in_place(degrees: float) -> list[str]:
    """The level tool at (5, 0, 1) turned ``degrees`` about Z with its tip kept: class 1's
    C turns by as much (A = 0), and the slides move X 5 sin C, Y 5 (cos C - 1)."""
    c = radians(degrees)
    return ["FROM/5,0,1,1,0,0", "FEDRAT/10", f"GOTO/5,0,1,{cos(c):.8f},{sin(c):.8f},0"]


def test_mach40_a_small_turn_lifts_g11_to_g01(tmp_path: Path) -> None:
    """MACH40 (rotary output in hundredths, ROTMAX 35.99964 degrees = 9.9999 units): the
    tool turning 3 degrees about its tip moves X .2617 (SELG: G11, TABLEG(12)) and C
    .8333 units, past G11's rotary range (ROTMAX / 100 = .099999): SELGRO's G01 (TABLEG(2),
    up to .99999), and the inverse time command of G01's row (format 32, 001 L24465):
    F011.94 = 10 IPM over the tip's swing, .8378 in (G11's row, format 31, gave F0119)."""
    lines = run(tmp_path, turn_in_place(3.0), mach40())
    assert lines[-1] == "N004G01X+02617Y-00069C+08333F01194"


def test_mach40_as_transcribed_cuts_its_turns_at_a_tenth_of_rotmax(tmp_path: Path) -> None:
    """MACH40's Machine Subroutine gives TABLEG(12) = 11 and keeps the Standard Machine's
    TABLEG(2) = 01, no TABLEG(11) (001 L27896-27905, L22448-22471): a turn of 4 degrees
    (1.1111 units > ROTMAX / 10) has no code in one block, so SEGMNT cuts it at ROTMAX / 10,
    the largest range MACH40 has a code for: two G01 blocks of .5556 and .5555 units
    (docs/decisions.md); with a G10 it goes out in one block under it (the manual's
    examples assume every code, L6127-6128)."""
    assert run(tmp_path, turn_in_place(4.0), mach40()) == [
        "N004G01X+01744Y-00061C+05556F01790",
        "N004X+01744Y-00061C+05555F01791",
    ]
    lines = run(tmp_path, turn_in_place(4.0), mach40("[tableg]\n11 = 10\n"))
    # X = 5 sin 4, Y = 5 (cos 4 - 1); F in G10's row (format 33, 001 L24453)
    assert lines[-1] == "N004G10X+03488Y-00122C+11111F008953"


@pytest.mark.parametrize("name", ["linuxcnc-5axis-ac", "fanuc-5axis-bc", "fanuc-mill"])
def test_modern_machines_keep_their_g01(name: str) -> None:
    """A five-axis machine by data (machine.kinematics) or absolute output (option
    251 = 1) has G01/G02/G03 without ranges: SELGRO does not apply. Given a rotary
    maximum of 36 and no TABLEG(11), SELGRO would stop a 40-unit turn with fatal 138."""
    pack = get_plugins().machine(name)
    assert pack is not None
    overlay = '[machine]\nname = "modern"\ntitle = "MODERN"\n[tableg]\n11 = "absent"\n'
    definition = load_machine_text(overlay + "[optab]\n111 = 36.0\n", "m.toml", pack.load())
    assert (definition.kinematics is not None) == (name != "fanuc-mill")
    out = element(definition, ipm=10.0)
    block = linear((0.2, 0.1, 0.0), {6: 40.0, 7: 200.0})
    block.feed_length = 0.25
    out.motion(block)
    assert block.cells[2] == 1.0
