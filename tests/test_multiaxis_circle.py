"""Multiaxis circular interpolation (manual §3.4.7.1, 001 L6447-6542; spec 03 §13, W24):
GOCIRC's circle through the transform class, as circular blocks of the machine when the
class makes it one, else straight moves along the arc."""

from __future__ import annotations

from math import cos, radians, sin
from pathlib import Path

import pytest
from gecent.core.dispatch.post import post
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.motion.gcode import CircularCodes, RotaryCodes, circle_code
from gecent.core.motion.multiaxis_circle import slerp
from gecent.core.output.block import Code
from gecent.core.plugins import get_plugins
from gecent.core.state import RunResult

# MACH40 reads no CIRCLE (option 9 = 0), is LINEAR (option 28 = 0) and has no I, J, K
# registers: given here, with the G codes of the manual's examples
CIRCLES = "[optab]\n9 = 1.0\n28 = 1.0\n[regfor]\n8 = 14.0\n9 = 14.0\n10 = 14.0\n"
ALL_CODES = "[tableg]\n11 = 10\n21 = 20\n31 = 30\n"


def mach40(overlay: str) -> MachineDefinition:
    pack = get_plugins().machine("mach40")
    assert pack is not None
    text = f'[machine]\nname = "mach40x"\ntitle = "MACH40 TEST"\n{overlay}'
    return load_machine_text(text, "mach40x.toml", pack.load())


def run(tmp_path: Path, lines: list[str], machine: MachineDefinition) -> RunResult:
    program = tmp_path / "c.apt"
    program.write_text("\n".join(["PARTNO CIRCLE", *lines, "FINI", ""]))
    return post(str(program), get_plugins(), machine_override=machine)


def punched(result: RunResult) -> list[tuple[int, str]]:
    return [(int(b.code), b.punch) for b in result.blocks if b.punch]


def test_w24_selgro_overrides_the_circular_code() -> None:
    """W24 (001 L6150-6170): CIRRAD 8.67, dA 40 degrees, rotary maximum 359.9999 (all
    codes available, L6127-6128): SELGCR takes the 1-9.9999 code (TABLEG(3) CLW, (4)
    CCLW), whose rotary range reaches 35.9999 degrees only; SELGRO needs the 36-359.9999
    range (TABLEG(11)), so the arc takes the circular code one band up: TABLEG(21) CLW,
    TABLEG(31) CCLW, GDIMUL 100 (the sentence naming it is lost in the manual; open
    question 11: a circular code, not the linear TABLEG(11))."""
    machine = mach40(ALL_CODES + "[optab]\n111 = 360.0\n118 = 1.0\n")
    circular = CircularCodes(machine)
    rotary = RotaryCodes(machine, 360.0)
    assert circular.select(8.67, True).location == 3
    clw = circle_code(circular, rotary, 8.67, True, 40.0)
    ccw = circle_code(circular, rotary, 8.67, False, 40.0)
    assert (clw.location, clw.code, clw.gdimul) == (21, 20, 100.0)
    assert (ccw.location, ccw.code, ccw.gdimul) == (31, 30, 100.0)
    # within the code's rotary range SELGRO accepts SELGCR's code
    assert circle_code(circular, rotary, 8.67, True, 35.0).location == 3
    assert circle_code(circular, rotary, 8.67, True, 0.0).location == 3


def test_w24_arc_takes_selgro_circular_code(tmp_path: Path) -> None:
    """W24 as an arc on class 1: radius 8.67 about the table's axis, the tool level
    (k = 0, A = 0) turning from azimuth 0 to 40 degrees while the tip sweeps 80: C = the
    azimuth, X = -8.67 sin C, Y = 8.67 cos C + 4, a machine circle of radius 8.67 with
    C turning 40 degrees in proportion, counterclockwise. OUTPUT's SELGRO puts its block
    under TABLEG(31) = G30 (GDIMUL 100), not SELGCR's TABLEG(4) = G03 (the manual's rule;
    this test stopped with "not yet supported" before OUTPUT applied it). C's register is
    given a 2.4 format: 40 degrees do not fit MACH40's -14."""
    overlay = CIRCLES.replace("28 = 1.0\n", "28 = 1.0\n111 = 360.0\n118 = 1.0\n")
    machine = mach40(overlay.replace("8 = 14.0\n", "7 = -24.0\n8 = 14.0\n") + ALL_CODES)
    end = (8.67 * cos(radians(80)), 8.67 * sin(radians(80)))
    lines = [
        "FROM/8.67,0,1,1,0,0",
        "FEDRAT/10",
        "CIRCLE/0,0,1,0,0,1,8.67",
        f"GOTO/{end[0]:.8f},{end[1]:.8f},1,{cos(radians(40)):.8f},{sin(radians(40)):.8f},0",
    ]
    result = run(tmp_path, lines, machine)
    arcs = [b for b in result.blocks if b.code is Code.CIRCLE_XY_CCLW]
    assert len(arcs) == 1
    assert (arcs[0].cells[2], arcs[0].cells[7]) == (30.0, 40.0)
    # X = -8.67 sin 40, Y = 8.67 (cos 40 - 1), J 8.67; F = 10 / 8.67 in the TABLEG(11) size
    # class's inverse time row (format 33)
    assert arcs[0].punch == "N005G30X-5573Y-20284C+40J867F001153"


def test_a_circle_with_the_tool_along_z(tmp_path: Path) -> None:
    """Class 1 with the tool along Z keeps C = 0: X = -y, Y = x, Z = z + 4, a quarter turn
    of the plane. The half circle about (1, 1) from (5, 1) to (-3, 1), counterclockwise,
    is the machine's from (-1, 5) to (-1, -3) about (-1, 1): its quadrant point (-5, 1),
    two G03 blocks (TABLEG(4) = 3) with J 4, then I 4, from each block's start."""
    lines = [
        "FROM/5,1,10,0,0,1",
        "FEDRAT/10",
        "CIRCLE/1,1,10,0,0,1,4",
        "GOTO/-3,1,10,0,0,1",
    ]
    result = run(tmp_path, lines, mach40(CIRCLES))
    assert punched(result) == [
        (-10, "N005G03X-4Y-4J4F00250"),
        (-10, "N005X+4Y-4I4"),
    ]


def test_the_machine_plane_and_sense_are_the_machines(tmp_path: Path) -> None:
    """A ZX circle of the part (y = 0 constant) is a YZ circle of the machine (X = -y,
    Y = x, Z = z + 4): the quarter about -Y from (5, 0, 0) to (0, 0, 5), clockwise in the
    part's (z, x), is counterclockwise in the machine's (Y, Z) (the map mirrors the plane):
    G19 (MACH40's option 98 puts F200 in the non-motion block), then one G03 block, CODE
    -12, Y-5 Z+5, J 5 (|Yc - Y| from the block's start (5, 4), K = 0)."""
    lines = [
        "FROM/5,0,0,0,0,1",
        "FEDRAT/10",
        "CIRCLE/0,0,0,0,-1,0,5",
        "GOTO/0,0,5,0,0,1",
    ]
    result = run(tmp_path, lines, mach40(CIRCLES))
    assert punched(result) == [(-4, "N005G19F200"), (-12, "N005G03Y-5Z+5J5F00200")]


def test_a_full_circle_is_four_quadrants(tmp_path: Path) -> None:
    """An arc that ends where it starts is a full circle (the three-axis rule): four G03
    blocks in the machine's quadrants, each offset from its own start."""
    lines = ["FROM/5,1,10,0,0,1", "FEDRAT/10", "CIRCLE/1,1,10,0,0,1,4", "GOTO/5,1,10,0,0,1"]
    result = run(tmp_path, lines, mach40(CIRCLES))
    assert punched(result) == [
        (-10, "N005G03X-4Y-4J4F00250"),
        (-10, "N005X+4Y-4I4"),
        (-10, "N005X+4Y+4J4"),
        (-10, "N005X-4Y+4I4"),
    ]


def test_a_fixed_tilted_tool_moves_the_circle(tmp_path: Path) -> None:
    """The tool along (0, .6, .8): C = 90, A = 53.13 for the whole arc; X = x, Y = y + 2.4,
    Z = z + 3.2. The quarter about (1, 1) from (1, -3) to (5, 1) is one G03 block."""
    lines = [
        "FROM/1,-3,10,0,0.6,0.8",
        "FEDRAT/10",
        "CIRCLE/1,1,10,0,0,1,4",
        "GOTO/5,1,10,0,0.6,0.8",
    ]
    result = run(tmp_path, lines, mach40(CIRCLES))
    assert punched(result) == [(-10, "N005G03X+4Y+4J4F00250")]


def test_an_arc_that_turns_the_table_is_one_circle(tmp_path: Path) -> None:
    """The W24 geometry small enough for MACH40's codes: radius 5 about the table's axis,
    the level tool turning 3 degrees while the tip sweeps 6: X = -5 sin C, Y = 5 cos C + 4
    (the machine circle about (0, 4)), C turns 3 degrees = .8333 hundredths, within the
    1-9.9999 code's rotary range (ROTMAX / 10 = .99999). One G03 block with J 5 and the C
    departure; MACH40 has no D, E registers (its 17 is H), so no supplementary constant
    goes out (tests/test_last_forms_wave7.py has them; until issue 22 wave 7 a warning said so)."""
    end = (5 * cos(radians(6)), 5 * sin(radians(6)))
    lines = [
        "FROM/5,0,1,1,0,0",
        "FEDRAT/10",
        "CIRCLE/0,0,1,0,0,1,5",
        f"GOTO/{end[0]:.8f},{end[1]:.8f},1,{cos(radians(3)):.8f},{sin(radians(3)):.8f},0",
    ]
    result = run(tmp_path, lines, mach40(CIRCLES))
    assert punched(result) == [(-10, "N005G03X-02617Y-00069C+08333J5F00200")]
    assert not any("SUPPLEMENTARY" in d.text for d in result.diagnostics)


def test_an_arc_the_class_bends_goes_as_straight_moves(tmp_path: Path) -> None:
    """The tool turning from (.6, 0, .8) to (0, .6, .8) over a quarter about the table's
    axis: the slerped axis tilts on the way (A changes), so the machine path is no circle.
    The arc goes out as CODE 0 moves through its quadrant points, each chord within the
    tolerance (LINTOL's r here), ending at the record's point with its tool axis."""
    lines = [
        "FROM/5,0,0,0.6,0,0.8",
        "FEDRAT/10",
        "LINTOL/0.01",
        "CIRCLE/0,0,0,0,0,1,5",
        "GOTO/0,5,0,0,0.6,0.8",
    ]
    # (its chords turn C up to 1.48 units, past ROTMAX / 10: SELGRO needs a TABLEG(11),
    # which MACH40 as transcribed lacks)
    result = run(tmp_path, lines, mach40(CIRCLES + ALL_CODES))
    moves = [b for b in result.blocks if b.code is Code.LINEAR]
    assert len(moves) > 10
    assert all(b.radius is None for b in moves)
    # the end: C = 90, A = 53.13: X = 0, Y = 5 + 2.4, Z = 3.2
    assert moves[-1].position == (0, 74000, 32000)


def test_slerp_follows_the_great_circle() -> None:
    """Spec 03 §13 step 4: the axis a fraction of the way along the sphere, parallel
    axes keeping the start's (open question 15's reading)."""
    half = slerp((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), 0.5)
    assert half == pytest.approx((2**-0.5, 2**-0.5, 0.0))
    third = slerp((1.0, 0.0, 0.0), (0.0, 0.0, 1.0), 1 / 3)
    assert third == pytest.approx((cos(radians(30)), 0.0, sin(radians(30))))
    assert slerp((0.0, 0.0, 1.0), (0.0, 0.0, 1.0), 0.7) == (0.0, 0.0, 1.0)
