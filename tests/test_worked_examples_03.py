"""Golden tests: spec 03's worked examples that had none (the motion element, manual §3.4).

W2 (a two-point record), W4's absolute half, W11's diagrams A and B, W21 through a whole
post and W29 (the standard option values the examples assume). The others are golden
tests elsewhere: W1, W6-W9, W14, W21's selector (test_motion_linear.py), W3, W4's
incremental half (test_post_linear.py), W5 (test_multiaxis_motion.py), W10-W12, W23
(test_post_circle.py), W13-W20, W22, W25, W27 (test_rotary.py, test_rotary_positioning.py),
W22, W24, W25 (test_multiaxis_selgro.py, test_multiaxis_circle.py), W26, W27
(test_multiaxis_rotref.py). W28 is advice to the part programmer (r about (INTOL + OUTTOL)
/ 2): gecent computes nothing from it. The last section tests spec 03 checklist items that
had no test of their own (the issue 22 review).
"""

from __future__ import annotations

import io
import re
from dataclasses import replace
from pathlib import Path

import pytest
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.cl.binary_layout import parse_layout
from gecent.core.cl.binary_reader import read_binary
from gecent.core.cl.binary_writer import write_binary
from gecent.core.cl.records import Fini, Motion, MotionSubtype, Multiax, Other, Record
from gecent.core.dispatch.post import post as dispatch_post
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.motion.linear import LinearMotion
from gecent.core.motion.quadrants import _quadrant, quadrant_crossings
from gecent.core.output.block import Code
from gecent.core.output.tape import tape_line
from gecent.core.plugins import get_plugins
from gecent.core.run import Run
from gecent.core.state import PostState, RunResult

from .test_post_circle import post_apt, punched
from .test_post_linear import post

# -- W2: point extraction from a two-point GOTO record ----------------------------------


def _binary_program(tmp_path: Path, multiax: bool) -> list[Record]:
    """FROM/0,0,0, TRANS/1,2,3, FEDRAT/10, then one GOTO record whose data words 6-11 are
    1.5, 2.25, 0, 4, -1, 0.5 (NWPR = 11), an INDIRP record (subtype 1) before it and a
    subtype-7 record after it, written as an APT IV binary CL file and read back."""
    head = list(AptSourceReader("w2.apt").read_lines(["FROM/0,0,0", "TRANS/1,2,3", "FEDRAT/10"]))
    words = (1.5, 2.25, 0.0, 4.0, -1.0, 0.5)
    records: list[Record] = [
        *head,
        *([Multiax("w2.apt", 4, 4, True)] if multiax else []),
        Other("w2.apt", 5, 5, 5000, 1, (0.0, 1.0, 0.0)),
        Motion("w2.apt", 6, 6, MotionSubtype.GOTO, (words,)),
        Other("w2.apt", 7, 7, 5000, 7, (1.0,)),
        Fini("w2.apt", 8, 8),
    ]
    buffer = io.BytesIO()
    write_binary(records, buffer, parse_layout("apt4"))
    path = tmp_path / "w2.cl"
    path.write_bytes(buffer.getvalue())
    return list(read_binary(str(path)))


def test_w2_a_two_point_record_gives_two_points_each_with_trans(tmp_path: Path) -> None:
    """W2 (001 L3901-3937): NCOM = 3, NWPR = 11: point 1 is CLDATA(6..8) + TRANSL, point
    2 CLDATA(9..11) + TRANSL, then the record is spent (INDPTS 5 -> 8 -> 11). TRANS/1,2,3
    makes them (2.5, 4.25, 3) and (5, 1, 3.5): two CODE 0 blocks of the record from the
    FROM block (CODE +3) at the origin. Subtypes 1 (INDIRP) and 7 are not motion to
    GECENT III (001 L4061-4154): they post nothing."""
    records = _binary_program(tmp_path, multiax=False)
    (goto,) = [r for r in records if isinstance(r, Motion) and r.subtype is MotionSubtype.GOTO]
    assert goto.points == ((1.5, 2.25, 0.0), (4.0, -1.0, 0.5))
    ignored = [(r.record_type, r.subtype) for r in records if isinstance(r, Other)]
    assert ignored == [(5000, 1), (5000, 7)]
    result = Run(standard_machine()).process(iter(records))
    blocks = [b for b in result.blocks if b.code is not Code.FINI]
    assert [b.code for b in blocks] == [Code.FROM, Code.LINEAR, Code.LINEAR]
    assert [b.position for b in blocks] == [(0, 0, 0), (25000, 42500, 30000), (50000, 10000, 35000)]
    assert [b.record for b in blocks[1:]] == [goto.number] * 2
    assert [b.punch for b in blocks[1:]] == ["N006G01X+25Y+425Z+3F017", "N006X+25Y-325Z+05F024"]


def test_w2_under_multax_the_same_words_are_one_point(tmp_path: Path) -> None:
    """W2's record under MULTAX (NCOM = 6, 001 L3700-3945): words 6-11 are one point,
    x, y, z, i, j, k."""
    records = _binary_program(tmp_path, multiax=True)
    (goto,) = [r for r in records if isinstance(r, Motion) and r.subtype is MotionSubtype.GOTO]
    assert goto.points == ((1.5, 2.25, 0.0, 4.0, -1.0, 0.5),)


# -- W4: absolute output ---------------------------------------------------------------


def test_w4_absolute_output_on_a_positioning_machine() -> None:
    """W4 (001 L4204-4232), absolute half: X of A, B, C = 2.4, 5.6, 8.6 go out as the
    positions X2.4, X5.6, X8.6 on a positioning machine (MACH24, format -24: X+024000;
    the decimal point is not punched). The incremental half (X3.2, X3.0) is
    tests/test_post_linear.py::test_w4_incremental_output."""
    pack = get_plugins().machine("mach24")
    assert pack is not None
    mach24 = pack.load()
    result = post(
        ["FROM/0,0,5", "FEDRAT/10", "GOTO/2.4,0,5", "GOTO/5.6,0,5", "GOTO/8.6,0,5"], mach24
    )
    moves = [b for b in result.blocks if b.punch]
    assert [round(float(b.cells[3]), 4) for b in moves] == [2.4, 5.6, 8.6]  # type: ignore[arg-type]
    assert [b.punch for b in moves] == [
        "N003G80X+024000Y+000000F20",
        "N004X+056000",
        "N005X+086000",
    ]


# -- W11: points on the axes (QUADNT) -----------------------------------------------------


@pytest.mark.parametrize(("ccw", "quadrant"), [(True, 2), (False, 1)])
def test_w11_diagram_a_a_first_point_on_an_axis(ccw: bool, quadrant: int) -> None:
    """W11 diagram A (001 L4917-4948): first point PX = 0, PY > 0: CCLW -> QA = 2 (the
    quadrant the circle passes through first), CLW -> QA = 1."""
    assert _quadrant((0.0, 2.0), ccw, first_point=True) == quadrant


def test_w11_diagram_a_on_tape() -> None:
    """Diagram A as arcs of radius 2 from (0, 2): CCLW to (-1.2, -1.6) has QA = 2, QB = 3,
    one crossing, at (-2, 0); CLW to (1.2, -1.6) has QA = 1, QB = 4, one crossing, at
    (2, 0). Were QA the other quadrant, each would cross again at its own start."""
    assert quadrant_crossings((0.0, 2.0), (-1.2, -1.6), clockwise=False) == [(-1, 0)]
    assert quadrant_crossings((0.0, 2.0), (1.2, -1.6), clockwise=True) == [(1, 0)]
    circle = ["FROM/0,2,0", "FEDRAT/10", "CIRCLE/0,0,0,0,0,1,2"]
    ccw = punched(post_apt([*circle, "POINTS/-1.4142136,1.4142136,0,-1.2,-1.6,0"]))
    cw = punched(post_apt([*circle, "POINTS/1.4142136,1.4142136,0,1.2,-1.6,0"]))
    assert ccw == ["N004G03X-2Y-2J2F050", "N004X+08Y-16I2"]
    assert cw == ["N004G02X+2Y-2J2F050", "N004X-08Y-16I2"]


@pytest.mark.parametrize(("end", "ccw"), [((0.0, -2.0), True), ((-2.0, 0.0), False)])
def test_w11_diagram_b_a_last_point_on_an_axis(end: tuple[float, float], ccw: bool) -> None:
    """W11 diagram B (001 L4930-4933): a last point on an axis lies in the quadrant the
    circle last passed through, III: a CCLW arc ending at (0, -r), a CLW one at (-r, 0)."""
    assert _quadrant(end, ccw, first_point=False) == 3


def test_w11_diagram_b_on_tape() -> None:
    """Diagram B as an arc of radius 2, CCLW from (-1.2, 1.6) in II to (0, -2): QB = 3, so
    one crossing, at (-2, 0), and no zero-length block at the end point."""
    assert quadrant_crossings((-1.2, 1.6), (0.0, -2.0), clockwise=False) == [(-1, 0)]
    lines = punched(
        post_apt(["FROM/-1.2,1.6,0", "FEDRAT/10", "CIRCLE/0,0,0,0,0,1,2", "POINTS/-2,0,0,0,-2,0"])
    )
    assert lines == ["N004G03X-08Y-16I12J16F050", "N004X+2Y-2I2"]


# -- W21: linear G-code selection through a post -------------------------------------------


def _every_linear_code() -> MachineDefinition:
    """Every dimension code present (the manual's examples assume so, 001 L6127-6128):
    TABLEG 13, 12, 2, 11, 14, 15 = G12, G11, G01, G10, G13, G14; option 4 = 99.9999 so
    that a departure of 80 is one block; X, Y, Z in format -24 to hold it."""
    text = (
        '[machine]\nnumber = 88\nname = "w21"\ntitle = "W21 TEST"\n'
        "[tableg]\n11 = 10\n12 = 11\n13 = 12\n14 = 13\n15 = 14\n"
        "[optab]\n4 = 99.9999\n[regfor]\n3 = -24.0\n4 = -24.0\n5 = -24.0\n"
    )
    return load_machine_text(text, "w21.toml")


def _first_move(goto: str) -> tuple[float, str]:
    result: RunResult = post(["FROM/0,0,0", "FEDRAT/10", goto], _every_linear_code())
    (block,) = [b for b in result.blocks if b.punch]
    assert block.punch is not None
    return float(block.cells[2]), block.punch  # type: ignore[arg-type]


def test_w21_the_largest_departure_chooses_the_code() -> None:
    """W21 (001 L5907-5918): a departure of 8 takes the 1-9.9999 code (the text's "G01",
    TABLEG(2)); 80 the 10-99.9999 code ("G10", TABLEG(11)); dX 8 with dY 80 the code
    that covers both, G10. F = GDIMUL x FIPM / S (GDIMUL 10 for G01, 100 for G10): 10 x
    10 / 8 = 12.5 -> 013; 100 x 10 / 80 = 12.5 -> 013; 100 x 10 / 80.399 = 12.4 -> 012."""
    assert _first_move("GOTO/8,0,0") == (1.0, "N003G01X+08F013")
    assert _first_move("GOTO/80,0,0") == (10.0, "N003G10X+80F013")
    assert _first_move("GOTO/8,80,0") == (10.0, "N003G10X+08Y+80F012")


def test_w21_examples_1_and_2_on_tape() -> None:
    """W21 ex. 1 (001 L6021-6028): dX 0.2, dY 2, dZ 20: 10 < 20 < 100, TABLEG(11) = G10,
    GDIMUL 100: F = 100 x 10 / 20.1 = 49.8 -> 050. Ex. 2 (L6029-6036): dX -0.001: under
    RNGDEP(1), TABLEG(13) = G12, GDIMUL 0.1: 0.1 x 10 / 0.001 = 1000 is over option 24
    (500), so the feedrate multiplier c = 2 puts F500 and I 0.002 (option 26 = 0)."""
    assert _first_move("GOTO/0.2,2,20") == (10.0, "N003G10X+002Y+02Z+20F050")
    assert _first_move("GOTO/-0.001,0,0") == (12.0, "N003G12X-00001I0002F500")


def test_w21_no_leading_digit_is_lost() -> None:
    """W21 (001 L5942-5944): 23.2468 under the 1-9.9999 code would move 3.2468; SELG gives
    it the 10-99.9999 code, and all six digits go out."""
    assert _first_move("GOTO/23.2468,0,0") == (10.0, "N003G10X+232468F043")


# -- W29: the standard values the examples assume ----------------------------------------


def test_w29_the_standard_machine_has_the_examples_values() -> None:
    """W29 (option table xref): DEPMAX 9.9999 (option 4), STEP 0.0001 (14), ROTMAX
    35.99964 degrees (111) = 0.099999 revolution in option 118 = 0's output units, rotary
    step 0.0001 (119), option 117 = +1, 28 = 1, 29 = 1, 198 = 0. DEPMAX is 99999 whole
    steps: gecent keeps positions in steps, so HSTEP's test (a departure under
    0.499999 STEP is none) is "no whole step" (tests/test_motion_linear.py W6)."""
    machine = standard_machine()
    options = {n: machine.number_option(n) for n in (4, 14, 111, 117, 118, 119, 28, 29, 198)}
    assert options == {
        4: 9.9999,
        14: 0.0001,
        111: 35.99964,
        117: 1.0,
        118: 0.0,
        119: 0.0001,
        28: 1.0,
        29: 1.0,
        198: 0.0,
    }
    assert machine.number_option(111) / 360 == pytest.approx(0.099999, abs=1e-12)
    assert LinearMotion(PostState(machine), lambda block: None).depmax == 99999


# -- checklist evidence: spec 03 features that had no test of their own -------------------


def test_a_continuation_off_the_plane_is_warned_and_the_circle_goes_on() -> None:
    """Spec 03 §8.3 (001 L4749-4781): a continuation record is too late to fall back to
    linear: a point off the plane is warned about and the circle is output as one."""
    reader = AptSourceReader("c.apt")
    lines = ["FROM/2,0,0", "FEDRAT/10", "CIRCLE/0,0,0,0,0,1,2"]
    head = [replace(r, number=n, line=n) for n, r in enumerate(reader.read_lines(lines), 1)]
    first = Motion("c.apt", 4, 4, MotionSubtype.GOTO, ((1.4142136, 1.4142136, 0.0), (0, 2, 0)))
    rest = ((-1.4142136, 1.4142136, 0.01), (-2.0, 0.0, 0.0))
    more = Motion("c.apt", 5, 5, MotionSubtype.CONTINUATION, rest)
    result = Run(standard_machine()).process(iter([*head, first, more, Fini("c.apt", 6, 6)]))
    assert [d.text for d in result.diagnostics] == ["WARNING - CIRCLE DOES NOT LIE IN A PLANE"]
    assert punched(result) == ["N004G03X-2Y+2I2F050", "N004X-2Y-2J2"]


def test_an_end_point_that_reverses_the_arc_goes_linear() -> None:
    """Spec 03 §9.2 (001 L5355-5383): a CLW arc's last segment from the crossing Q = (2, 0)
    to an end E with |E_x| >= |Q_x| looks counterclockwise: it goes out linear (CODE 0,
    no arc offsets; the I, J are option 26's feedrate multiplier); an end inside is an arc."""
    circle = ["FROM/-1.2,1.6,0", "FEDRAT/10", "CIRCLE/0,0,0,0,0,1,2"]
    outside = post_apt([*circle, "POINTS/0,2,0,2.0001,-0.0005,0"])
    inside = post_apt([*circle, "POINTS/0,2,0,1.9999,-0.03,0"])
    assert [int(b.code) for b in outside.blocks if b.punch] == [10, 10, 0]
    assert punched(outside)[-1] == "N004G01X+00001Y-00005I00393J01965F499"
    assert [int(b.code) for b in inside.blocks if b.punch] == [10, 10, 10]
    assert punched(inside)[-1] == "N004X-00001Y-003I2"


def _lintol_pieces(tmp_path: Path, lintol: str) -> int:
    from .test_multiaxis_motion import mach40_g10

    program = tmp_path / "cone.apt"
    program.write_text(
        "PARTNO CONE\nMACHIN/GECENT,40\nFROM/0,0,10,0,0.6,0.8\nFEDRAT/10\n"
        f"{lintol}\nGOTO/2,0,10,0.6,0,0.8\nFINI\n"
    )
    result = dispatch_post(str(program), get_plugins(), machine_override=mach40_g10())
    return len([b for b in result.blocks if b.code is Code.LINEAR])


def test_the_cone_alone_cuts_a_move(tmp_path: Path) -> None:
    """Spec 03 §15.2-15.3 (001 L6900-6946): with a sphere too wide to fail (r = 100) the
    move is ROTMAX's three segments; a cone half-angle of 0.5 degrees cuts it, 0.1 degree
    finer still, and LINTOL/r,0 cancels the cone."""
    plain = _lintol_pieces(tmp_path, "LINTOL/100")
    assert plain == 3
    coarse = _lintol_pieces(tmp_path, "LINTOL/100,0.5")
    assert plain < coarse < _lintol_pieces(tmp_path, "LINTOL/100,0.1")
    assert _lintol_pieces(tmp_path, "LINTOL/100,0.5\nLINTOL/100,0") == plain


def test_each_head_shifts_to_rapid_with_its_own_m_codes(tmp_path: Path) -> None:
    """Spec 03 §16.4 (001 L7270-7278): RAPID in a multihead program outputs the M codes
    of the head selected: MACH51's head 1 TABLEM 42/43 (M40, M41), head 2 TABLEM 142/143
    (M44, M45). Moves of 40 in pass option 37 (35 in), so both heads shift."""
    program = tmp_path / "heads.apt"
    program.write_text(
        "PARTNO HEADS\nMACHIN/GECENT,51\nCOMBIN/2\nSELECT/HEAD,1\nFROM/10,10,0\nFEDRAT/10\n"
        "SELECT/HEAD,2\nFROM/20,10,0\nFEDRAT/10\nSELECT/HEAD,1\nOP/1\nRAPID\nGOTO/-30,10,0\n"
        "GOTO/-31,10,0\nOP/2\nEND\nSELECT/HEAD,2\nOP/1\nGOTO/19,10,0\nOP/2\nRAPID\n"
        "GOTO/60,10,0\nGOTO/61,10,0\nEND\nFINI\n"
    )
    result = dispatch_post(str(program), get_plugins())
    codes: dict[int, set[str]] = {1: set(), 2: set()}
    for block in result.blocks:
        for half in block.halves or (block,):
            line = tape_line(half) or ""
            codes[half.head] |= set(re.findall(r"M(4\d)", line))
    assert codes == {1: {"40", "41"}, 2: {"44", "45"}}
