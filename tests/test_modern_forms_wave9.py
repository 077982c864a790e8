"""The last not-yet-supported forms of issue 22 on the modern packs (wave 9; options 251-265,
docs/modern-controls.md), each posted and, where LinuxCNC's rs274 is here and the verifier
models the form, read back by ``gecent verify``:

* SFM on a whole arc (option 253): whole arcs between SFM's shift points, each with its S
  (SFMCIR's shift points, manual §3.4.4 and §4.4, 001 L5152-5163, L14230-14549);
* SFM on an arc cut into chords (option 262, a helix the control has no G02/G03 for): each
  chord cut at the shift radii as a line is;
* a multiaxis circle on a control with modern arc words (options 252, 253);
* ROTATE on a multiaxis machine with absolute output (option 251);
* a turn of the tool alone on a machine without its radius (options 112, 128): F read as
  degrees per minute;
* a circle about an axis along none of X, Y, Z: chords in its own plane.

The SFM golden tests put the manual's worked examples SFM-1 to SFM-5 (spec 06 §11.2,
001 L14267-14364) on the quarter circle of tests/test_spindle_wave3.py (the table 15 ... 80
RPM, SFM = 20, the radius from 1 at A to 2 at D): B at R = 1.11408 (40 -> 30), C at
R = 1.59155 (30 -> 20), with the exact constants (the manual rounds them to 1.9 and 0.95).
"""

from __future__ import annotations

import re
import shutil
from math import acos, atan2, ceil, hypot, pi, sqrt
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.motion.sfm import shift_radius
from gecent.core.output.block import Code
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import PluginSet, get_plugins
from gecent.core.verify.check import verify

from tests.test_post_circle import post_apt
from tests.test_post_linear import post as post_lines
from tests.test_sfm import discrete_lathe, overlay
from tests.test_spindle_wave3 import ARC, QUARTER, x_on_quarter

needs_rs274 = pytest.mark.skipif(
    shutil.which("rs274") is None,
    reason="rs274 (LinuxCNC's interpreter, Debian package linuxcnc-uspace) is not installed",
)


def post(tmp_path: Path, text: str, machine: str | None = None) -> tuple[int, Path, Path, str]:
    source = tmp_path / "part.apt"
    source.write_text(text)
    tape = tmp_path / "part.ngc"
    command = ["post", str(source), "-o", str(tape)]
    if machine is not None:
        command += ["--machine", machine]
    result = CliRunner().invoke(main, command)
    text_out = tape.read_text() if tape.exists() else ""
    return result.exit_code, source, tape, text_out + result.output


def posted(tmp_path: Path, text: str, machine: str | None = None) -> tuple[Path, Path, str]:
    status, source, tape, output = post(tmp_path, text, machine)
    assert status == 0, output
    return source, tape, tape.read_text()


def verified(plugins: PluginSet, tape: Path, source: Path, machine: str | None) -> None:
    result = verify(str(tape), str(source), plugins, machine, 0.001)
    assert result.passed, "\n".join(result.report())


def program(*body: str, head: str = "") -> str:
    lines = ["PARTNO WAVE9", *([head] if head else []), "UNITS/MM", "LOADTL/1"]
    return "\n".join([*lines, "SPINDL/RPM,500,CLW", *body, "FINI", ""])


# -- SFM on whole arcs (option 253) -----------------------------------------------------------

WHOLE = "252 = 1.0\n253 = 1.0"  # signed I, J, K from each block's start; whole arcs


def arcs_of(lines: list[str], options: str) -> list:
    result = post_lines(lines, overlay(options, discrete_lathe()))
    return [b for b in result.blocks if abs(int(b.code)) == 10]


def test_sfm_1_to_5_on_whole_arcs() -> None:
    """SFM-1 .. SFM-5 on a control taking whole arcs: three arcs A-B, B-C, C-D ending at
    the shift points on the arc, B = (9.5362, 1.1141), C = (9.0872, 1.5915), D = (9, 2); the
    signed centre offsets of (10, 2) from each arc's start, (0, 1), (0.4638, 0.8859),
    (0.9128, 0.4085); F = F_IPR x S = 0.4, 0.3, 0.2 IPM (SFM-5); S530 and S520 (30 and
    20 RPM, type 5's magic three) ride in B-C and C-D; the three sweeps make the quarter."""
    assert round(x_on_quarter(shift_radius(20.0, 40.0, 30.0)) * 10000) == 95362
    assert round(x_on_quarter(shift_radius(20.0, 30.0, 20.0)) * 10000) == 90872
    result = post_lines([*QUARTER, *ARC], overlay(WHOLE, discrete_lathe()))
    arcs = [b for b in result.blocks if abs(int(b.code)) == 10]
    assert [b.position for b in arcs] == [(95362, 11141, 0), (90872, 15915, 0), (90000, 20000, 0)]
    assert [b.cells[8] for b in arcs] == pytest.approx([1.0, 0.8859, 0.4085])
    assert [b.cells[10] for b in arcs] == pytest.approx([0.0, 0.4638, 0.9128])
    assert [b.cells[19] for b in arcs] == pytest.approx([0.4, 0.3, 0.2])
    assert sum(b.sweep for b in arcs) == pytest.approx(pi / 2)
    assert tape_lines(result.blocks) == [
        "N002G04S540M03",
        "N005G02X-01141Z-04638I1F004",
        "N005G02X-04774Z-0449I08859K04638F003S530",
        "N005G02X-04085Z-00872I04085K09128F002S520",
    ]


def test_a_whole_arc_is_cut_only_where_the_speed_changes() -> None:
    """The half circle from A (10, 1) clockwise about (10, 2) to (10, 3): the radius runs
    1 -> 3, so the speed steps 40, 30, 20 and, at the 20 -> 15 shift radius 2.22817 (E),
    15; the quadrant point (9, 2) inside C-E cuts a Mark Century arc (five quadrant
    blocks) but not a whole arc (four)."""
    half = ["CIRCLE/10,2,0,0,0,-1,1", "GOTO/10,3,0"]
    e = shift_radius(20.0, 20.0, 15.0)
    assert round(e, 5) == 2.22817
    whole = arcs_of([*QUARTER, *half], WHOLE)
    assert [b.position for b in whole] == [
        (95362, 11141, 0),
        (90872, 15915, 0),
        (round(x_on_quarter(e) * 10000), round(e * 10000), 0),
        (100000, 30000, 0),
    ]
    assert [b.cells[19] for b in whole] == pytest.approx([0.4, 0.3, 0.2, 0.15])
    assert sum(b.sweep for b in whole) == pytest.approx(pi)
    quadrants = arcs_of([*QUARTER, *half], "253 = 0.0")
    assert (90000, 20000, 0) in [b.position for b in quadrants] and len(quadrants) == 5


LATHE_ARC = (
    "FROM/100,60,0",
    "RAPID",
    "GOTO/50,20,0",
    "SPINDL/100,SFM,MAXRPM,3000",
    "FEDRAT/0.2,MMPR",
    "GOTO/50,40,0",
    "CIRCLE/30,40,0,0,0,1,20",
    "GOTO/30,60,0",
    "GOTO/0,60,0",
)


def test_sfm_whole_arcs_on_the_fanuc_lathe(tmp_path: Path) -> None:
    """The lathe pack (diameter X, G18, G95): the arc from R 40 to R 60 (mm) in four G03
    blocks, each with its S and K, I signed from its own start."""
    _, _, tape = posted(tmp_path, program(*LATHE_ARC), "fanuc-lathe")
    assert [line for line in tape.splitlines() if " G03 " in line or "I-" in line] == [
        "N12 G03 X84.444 Z49.876 K-20. S121",
        "N13 X93.828 Z48.767 I-2.222 K-19.876 S109",
        "N14 X104.252 Z45.905 I-6.914 K-18.767 S98",
        "N15 X120. Z30. I-12.126 K-15.905 S88",
    ]


@needs_rs274
@pytest.mark.parametrize("chords", [None, "OPTAB,262,0.05"])
def test_sfm_arcs_on_the_lathe_verify(
    plugins: PluginSet, tmp_path: Path, chords: str | None
) -> None:
    """rs274 reads the pieces back (whole arcs, or chords under option 262) onto the CL's
    arc, every CL point in order."""
    head = f"MACHIN/GECENT,83,{chords}" if chords else ""
    source, tape, text = posted(tmp_path, program(*LATHE_ARC, head=head), "fanuc-lathe")
    assert ("G03" in text) == (chords is None), text
    verified(plugins, tape, source, "fanuc-lathe")


# -- SFM on chords (option 262) -------------------------------------------------------------


def test_sfm_chords_are_cut_at_the_shift_radii() -> None:
    """Option 262 = 0.001 in: the quarter as chords, each a line to SFMO: the speed changes
    where a chord crosses the shift radius, on the chord (y = 1.1141 and 1.5915 exactly),
    S530 and S520 riding in the pieces that follow; every other chord ends on the arc."""
    result = post_lines([*QUARTER, *ARC], overlay("262 = 0.001", discrete_lathe()))
    assert not [b for b in result.blocks if abs(int(b.code)) == 10]  # no arc block
    moves = [b for b in result.blocks if b.position is not None and b.code is Code.LINEAR]
    ys = [b.position[1] for b in moves]
    assert 11141 in ys and 15915 in ys
    lines = tape_lines(result.blocks)
    shifted = [line for line in lines if re.search(r"S5\d\d$", line)]
    assert [line[-4:] for line in shifted] == ["S530", "S520"]
    for block in moves:
        x, y, _ = block.position
        if y not in (11141, 15915):
            assert abs(hypot(x - 100000, y - 20000) - 10000) <= 1.0  # on the arc (steps)
    assert moves[-1].position == (90000, 20000, 0)


# -- a multiaxis circle on a control with modern arc words (options 252, 253) ------------

FIVE_CIRCLE = (
    "FROM/0,0,100",
    "RAPID",
    "GOTO/40,0,-5",
    "FEDRAT/300,MMPM",
    "CIRCLE/0,0,-5,0,0,1,40",
    "GOTO/0,40,-5",
    "CIRCLE/0,0,-5,0,0,1,40",
    "GOTO/0,-40,-5",
    "GOTO/0,-40,50",
)


@pytest.mark.parametrize(
    ("machine", "words", "lines"),
    [
        ("86", "", ["G03 X0. Y40. I-40. F300.", "X0. Y-40. J-40."]),
        ("86", ",OPTAB,252,2", ["G03 X0. Y40. I0. J0. F300.", "X0. Y-40. I0. J0."]),
        ("87", "", ["G03 X0. Y40. I-40. F300.", "X0. Y-40. J-40."]),
    ],
    ids=["linuxcnc-signed", "linuxcnc-absolute-centre", "fanuc-tcp"],
)
def test_a_multiaxis_circle_is_one_whole_arc(
    plugins: PluginSet, tmp_path: Path, machine: str, words: str, lines: list[str]
) -> None:
    """CIRCLE records on the five-axis packs (option 9 = 1): with the tool along Z the
    class maps the arc to a circle of the slides, one G03 per record, the centre words by
    option 252, the rotary axes (not moving) left out under G90."""
    head = f"MACHIN/GECENT,{machine},OPTAB,9,1{words}"
    source, tape, text = posted(tmp_path, program(*FIVE_CIRCLE, head=head))
    body = [re.sub(r"^N\d+ ", "", line) for line in text.splitlines()]
    start = body.index(lines[0])
    assert body[start : start + 2] == lines
    if shutil.which("rs274"):
        verified(plugins, tape, source, None)


def test_a_multiaxis_circle_whose_tool_turns_goes_out_as_chords(tmp_path: Path) -> None:
    """The tool axis leans 30 degrees toward the centre line and turns with the arc: the
    class makes the arc no circle of the slides, so it goes out as multiaxis straight moves
    (G93 on the five-axis pack), ending on the CL's point with the CL's axis (C -180)."""
    body = (
        "MULTAX/ON",
        "FROM/0,0,100,0,0,1",
        "RAPID",
        "GOTO/40,0,-5,0.5,0,0.8660254",
        "FEDRAT/300,MMPM",
        "CIRCLE/0,0,-5,0,0,1,40",
        "GOTO/0,40,-5,0,0.5,0.8660254",
    )
    _, _, text = posted(tmp_path, program(*body, head="MACHIN/GECENT,86,OPTAB,9,1"))
    assert "G02" not in text and "G03" not in text
    moves = [line for line in text.splitlines() if "F534.765" in line]
    assert len(moves) > 50
    assert moves[-1].endswith("X0. Y-12.141 Z8.971 A-30. C-180. F534.765")


# -- ROTATE on a multiaxis machine with absolute output (option 251) -----------------------

ROTATE = (
    "MULTAX/ON",
    "FROM/0,0,100,0,0,1",
    "RAPID",
    "GOTO/40,0,10,0,0,1",
    "FEDRAT/300,MMPM",
    "GOTO/40,0,-5,0,0,1",
    "ROTATE/TABLE,INCR,90,CLW",
    "GOTO/40,10,-5,0,0,1",
    "GOTO/40,10,50,0,0,1",
)


@pytest.mark.parametrize(
    ("head", "feed"),
    [("", "F1.91"), ("MACHIN/GECENT,87,OPTAB,112,0,OPTAB,128,0", "F3.333")],
    ids=["table-radius-100", "no-radius"],
)
def test_rotate_under_g90_is_the_angle_reached(
    plugins: PluginSet, tmp_path: Path, head: str, feed: str
) -> None:
    """ROTATE/TABLE,INCR,90 on the Fanuc five-axis pack: one move of C alone to C90. (the
    slides left out, the control is at them), timed as a turn of the tool alone under G93:
    the 90-degree arc at option 112's 100 mm is 157.08 mm, 0.5236 min at 300 mm/min, F1.91;
    with options 112 and 128 at 0 the feed is read as degrees per minute, 0.3 min, F3.333."""
    head = head or "MACHIN/GECENT,87"
    source, tape, text = posted(tmp_path, program(*ROTATE, head=head))
    body = [re.sub(r"^N\d+ ", "", line) for line in text.splitlines()]
    turn = body.index(f"G01 C90. {feed}")
    assert body[turn - 1] == "G93" and body[turn + 1] == "G94"
    if shutil.which("rs274") and not head.endswith("0"):
        verified(plugins, tape, source, None)


def test_rotate_with_the_part_frame_turned_on_a_trunnion(tmp_path: Path) -> None:
    """LinuxCNC's A-C trunnion (slides computed by gecent): the part turns with C, the
    slides stand; the next point in the turned part is where the class puts it."""
    _, _, text = posted(tmp_path, program(*ROTATE, head="MACHIN/GECENT,86"))
    body = [re.sub(r"^N\d+ ", "", line) for line in text.splitlines()]
    turn = body.index("G01 C90. F1.91")
    assert body[turn + 2] == "G01 X-10. Y40. F300."


def test_a_turn_of_the_tool_alone_without_a_radius_is_degrees_per_minute(tmp_path: Path) -> None:
    """The Fanuc pack under its tool centre point (the tip stands) with options 112 and 128
    at 0: the tool turns 30 degrees about B alone; F is read as degrees per minute, so the
    move takes 30 / 300 min: G93 F10."""
    body = (
        "MULTAX/ON",
        "FROM/0,0,100,0,0,1",
        "GOTO/10,0,0,0,0,1",
        "FEDRAT/300,MMPM",
        "GOTO/10,0,0,0.5,0,0.8660254",
    )
    head = "MACHIN/GECENT,87,OPTAB,112,0,OPTAB,128,0"
    _, _, text = posted(tmp_path, program(*body, head=head))
    assert re.search(r"G01 B-?30\. F10\.\n", text), text


# -- a circle about a tilted axis --------------------------------------------------------------

ROOT_HALF = sqrt(0.5)
TILTED = (
    "FROM/0,0,100",
    "RAPID",
    "GOTO/14.142136,0,-14.142136",
    "FEDRAT/300,MMPM",
    f"CIRCLE/0,0,0,{ROOT_HALF:.7f},0,{ROOT_HALF:.7f},20",
    "GOTO/0,20,0",
    f"CIRCLE/0,0,0,{ROOT_HALF:.7f},0,{ROOT_HALF:.7f},20",
    "GOTO/-14.142136,0,14.142136",
    "GOTO/-14.142136,0,50",
)


def points_of(text: str) -> list[tuple[float, float, float]]:
    at = [0.0, 0.0, 0.0]
    out = []
    for line in text.splitlines():
        words = dict(re.findall(r"([XYZ])(-?[\d.]+)", line))
        if not words:
            continue
        for axis, name in enumerate("XYZ"):
            if name in words:
                at[axis] = float(words[name])
        out.append((at[0], at[1], at[2]))
    return out


@pytest.mark.parametrize(("tolerance", "count"), [(0.0, 158), (0.05, 24)])
def test_a_tilted_circle_is_chords_in_its_own_plane(
    tmp_path: Path, tolerance: float, count: int
) -> None:
    """A half circle of radius 20 about (1, 0, 1): chords, each end on the circle (20 from
    the axis, in the plane x + z = 0) to the step, each chord within option 262's tolerance
    (one step, 0.001 mm, when 0: 2 acos(1 - 0.001/20) = 0.02 rad, 79 a quarter), turning
    counterclockwise about the axis, through the record ends (0, 20, 0) and
    (-14.142, 0, 14.142). With 262 = 0.05: 2 acos(1 - 0.05/20) = 0.1414 rad, 12 a
    quarter."""
    head = f"MACHIN/GECENT,80,OPTAB,262,{tolerance}" if tolerance else ""
    _, _, text = posted(tmp_path, program(*TILTED, head=head), "linuxcnc-mill")
    assert "G02" not in text and "G03" not in text
    points = points_of(text)
    start = points.index((14.142, 0.0, -14.142))
    along = points[start + 1 : -1]
    sag = tolerance or 0.001
    widest = 2 * acos(1 - sag / 20)
    assert len(along) == count == 2 * ceil((pi / 2) / widest - 1e-9)
    assert (0.0, 20.0, 0.0) in along and along[-1] == (-14.142, 0.0, 14.142)
    before = points[start]
    last_angle = 0.0
    for x, y, z in along:
        assert abs(x + z) <= 0.002  # in the plane through the centre across the axis
        assert abs(sqrt(((x - z) ** 2) / 2 + y * y) - 20.0) <= 0.002  # on the circle
        middle = [(a + b) / 2 for a, b in zip(before, (x, y, z), strict=True)]
        assert 20.0 - sqrt((middle[0] - middle[2]) ** 2 / 2 + middle[1] ** 2) <= sag + 0.002
        angle = atan2(y, (x - z) / sqrt(2))  # counterclockwise about (1, 0, 1)
        assert angle >= last_angle - 1e-9
        last_angle, before = angle, (x, y, z)


def test_a_tilted_circle_of_several_points_goes_through_them() -> None:
    """APT writes points along the arc: they are its chords already, within the part
    program's tolerance, and go out linear as a circle in no plane (CHKAX) does."""
    lines = [
        "FROM/14.142136,0,-14.142136",
        "FEDRAT/300",
        f"CIRCLE/0,0,0,{ROOT_HALF:.7f},0,{ROOT_HALF:.7f},20",
        "POINTS/10,14.142136,-10,0,20,0",
    ]
    result = post_apt(lines, get_plugins().machine("linuxcnc-mill").load())
    moves = [b for b in result.blocks if b.position is not None and b.code is Code.LINEAR]
    assert [b.position for b in moves] == [(10000, 14142, -10000), (0, 20000, 0)]


def test_a_tilted_circle_whose_end_is_off_it_is_bad_input(tmp_path: Path) -> None:
    body = (
        "FROM/0,0,100",
        "RAPID",
        "GOTO/20,0,0",
        "FEDRAT/300,MMPM",
        f"CIRCLE/0,0,0,{ROOT_HALF:.7f},0,{ROOT_HALF:.7f},20",
        "GOTO/0,20,0",
    )
    status, _, _, output = post(tmp_path, program(*body), "linuxcnc-mill")
    assert status == 2 and "part.apt:10" in output and "off its circle" in output, output


@pytest.mark.parametrize("machine", ["23", "86"])
def test_a_tilted_circle_posts_on_the_manuals_mill_and_a_five_axis_pack(
    tmp_path: Path, machine: str
) -> None:
    """The same chords on MACH23 (inch steps; the CL in mm) and, through the class, as
    straight multiaxis moves on the A-C pack (option 9 = 1), the tool along Z throughout."""
    head = f"MACHIN/GECENT,{machine}" + (",OPTAB,9,1" if machine == "86" else "")
    status, _, _, output = post(tmp_path, program(*TILTED, head=head))
    assert status == 0, output
    assert "not yet supported" not in output


def test_sfm_on_a_helix_rises_with_the_angle(plugins: PluginSet, tmp_path: Path) -> None:
    """A half turn down 5 mm on the LinuxCNC mill under SFM about X (RADIUS,XCOORD): whole
    arcs between the shift points, each piece's Z in proportion to the angle it reaches,
    the last at the CL's (-20, 0, -5); rs274 reads them back onto the helix."""
    body = (
        "FROM/0,0,50",
        "RAPID",
        "GOTO/20,0,0",
        "SPINDL/100,SFM,RADIUS,XCOORD,MAXRPM,5000",
        "FEDRAT/300,MMPM",
        "CIRCLE/0,0,-5,0,0,1,20",
        "GOTO/-20,0,-5",
        "GOTO/-20,0,50",
    )
    source, tape, text = posted(tmp_path, program(*body), "linuxcnc-mill")
    pieces = points_of(text)[1:-1]
    assert len(pieces) > 10 and pieces[-1] == (-20.0, 0.0, -5.0)
    for x, y, z in pieces:
        assert abs(hypot(x, y) - 20.0) <= 0.002
        assert abs(z - (-5.0 * atan2(y, x) / pi)) <= 0.002
    if shutil.which("rs274"):
        verified(plugins, tape, source, "linuxcnc-mill")


@needs_rs274
@pytest.mark.parametrize("machine", ["linuxcnc-mill", "fanuc-mill", "linuxcnc-mill-inch"])
@pytest.mark.parametrize("lead_in", ["GOTO/14.142136,0,-14.142136", "GOTO/14.849243,0,-13.435029"])
def test_a_tilted_circle_verifies(
    plugins: PluginSet, tmp_path: Path, machine: str, lead_in: str
) -> None:
    """rs274 reads the chords back: each ends on the CL's circle, in its plane (or on the
    helix's rise: the second start is 1 mm up the axis), counterclockwise about the axis,
    within the chord tolerance; both CL points reached."""
    body = tuple(lead_in if line.startswith("GOTO/14.") else line for line in TILTED)
    source, tape, _ = posted(tmp_path, program(*body), machine)
    result = verify(str(tape), str(source), plugins, machine, 0.001)
    assert result.passed, "\n".join(result.report())
    assert result.comparison is not None and result.comparison.arcs == 2


@needs_rs274
@pytest.mark.parametrize(
    ("old", "new", "problem"),
    [
        ("Y13.422 Z-10.485", "Y13.522 Z-10.485", "ends 0.0678 off it"),
        ("X10.485 Y13.422 Z-10.485", "X10.495 Y13.422 Z-10.475", "leaves its plane by 0.0141"),
    ],
    ids=["off the circle", "off the plane"],
)
def test_the_verifier_finds_a_chord_off_the_tilted_circle(
    plugins: PluginSet, tmp_path: Path, old: str, new: str, problem: str
) -> None:
    source, tape, text = posted(tmp_path, program(*TILTED), "linuxcnc-mill")
    assert old in text
    tape.write_text(text.replace(old, new, 1))
    result = verify(str(tape), str(source), plugins, "linuxcnc-mill", 0.001)
    assert not result.passed and problem in "\n".join(result.report())
