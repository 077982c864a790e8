"""The five-axis packs (docs/five-axis.md): linuxcnc-5axis-ac (A/C trunnion, slides computed
by gecent, G93 on rotary moves) and fanuc-5axis-bc (B head, C table, the control's tool
centre point G43.4): their tapes worked out by hand, the pole, the wrap, the modes, the
bad input, and `gecent verify` and `gecent plot` reading the tapes back."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.plugins import PluginSet
from gecent.core.verify.check import verify

ROOT = Path(__file__).parents[1]
FIVEAXIS = ROOT / "examples" / "fiveaxis.apt"
needs_rs274 = pytest.mark.skipif(shutil.which("rs274") is None, reason="rs274 is not installed")

SMALL = """PARTNO SMALL
UNITS/MM
MULTAX/ON
LOADTL/1,LENGTH,100
SPINDL/RPM,6000,CLW
FROM/0,0,150,0,0,1
RAPID
GOTO/-40,-30,20,0,0,1
FEDRAT/300,MMPM
GOTO/-40,-30,2,0,0,1
FEDRAT/800,MMPM
GOTO/-20,-30,2,-0.5,0,0.8660254
GOTO/0,-30,2,-0.5,0,0.8660254
GOTO/20,-30,2,0.5,0,0.8660254
RAPID
GOTO/20,-30,50,0,0,1
END
FINI
"""

# By hand, the trunnion's A about X through (0, 0, -50), C about Z through the origin:
# N6  leaving the pole, C turns to 90 first with the tip held: (-40, -30) turned 90 degrees
#     is (30, -40); G93 F = 800 / (90 degrees at option 112's 100 mm = 157.08) = 5.093
# N7  (-20, -30, 2) leaning 30 towards -X: C 90 takes it to (30, -20, 52 above A), A -30 to
#     Y = -20 cos 30 + 52 sin 30 = 8.679, Z = 20 sin 30 + 52 cos 30 - 50 = 5.033; the move
#     is timed by the tip's 20 mm in the part (E2): G93 F = 800 / 20 = 40
# N9  no turn: G94, F800, (0, -30, 2) to Y = 26, Z = -4.967
# N11 A over to +30 (the nearest way: C stays), the tip's 20 mm again: F = 40
AC_TAPE = """%
(SMALL)
(T1, LENGTH 100 MM)
G17 G21 G90 G94 G40 G49 G80 G54
N1 T01 M06
N2 S6000 M03
N3 G00 G43 X-40. Y-30. Z20. A0. C0. H1
N4 G01 Z2. F300.
N5 G93
N6 G01 X30. Y-40. C90. F5.093
N7 Y8.679 Z5.033 A-30. F40.
N8 G94
N9 G01 Y26. Z-4.967 F800.
N10 G93
N11 G01 Y-8.679 Z5.033 A30. F40.
N12 G00 Y20. Z50. A0.
N13 M02
%
"""

# The control's tool centre point: X, Y, Z are the tip; B leans the tool (sin B, 0, cos B),
# so -30 then +30 through the pole with C kept; G49 ends G43.4 before M30.
BC_TAPE = """%
O1000
(SMALL)
(T1, LENGTH 100 MM)
G17 G21 G90 G94 G40 G49 G80 G54
N1 T01 M06
N2 S6000 M03
G43.4 H1
N3 G00 X-40. Y-30. Z20. B0. C0.
N4 G01 Z2. F300.
N5 X-20. B-30. F800.
N6 X0.
N7 X20. B30.
N8 G00 Z50. B0.
G49
N9 M30
%
"""


def post(
    tmp_path: Path, source: str | Path, machine: str | None, *extra: str
) -> tuple[int, str, Path]:
    if isinstance(source, str):
        path = tmp_path / "job.apt"
        path.write_text(source)
    else:
        path = source
    tape = tmp_path / "job.ngc"
    command = ["post", str(path), "-o", str(tape), *extra]
    if machine is not None:
        command += ["--machine", machine]
    result = CliRunner().invoke(main, command)
    return result.exit_code, result.output, tape


@pytest.mark.parametrize(
    ("machine", "expected"), [("linuxcnc-5axis-ac", AC_TAPE), ("fanuc-5axis-bc", BC_TAPE)]
)
def test_the_small_job_by_hand(tmp_path: Path, machine: str, expected: str) -> None:
    code, output, tape = post(tmp_path, SMALL, machine)
    assert code == 0, output
    assert tape.read_text() == expected


def test_leaving_the_pole_is_named(tmp_path: Path) -> None:
    code, output, _ = post(tmp_path, SMALL, "linuxcnc-5axis-ac")
    assert code == 0
    assert "TOOL AXIS WITHIN 0.000 DEGREES OF THE POLE OF C: C TURNS 90.000 DEGREES" in output


def test_the_continuous_c_counts_past_a_turn_and_the_rollover_c_stays_within_one(
    tmp_path: Path,
) -> None:
    code, output, tape = post(tmp_path, FIVEAXIS, "linuxcnc-5axis-ac")
    assert code == 0, output
    words = [w for line in tape.read_text().splitlines() for w in line.split() if w[0] == "C"]
    assert min(float(w[1:]) for w in words) <= -450.0  # one and a half turns round the part
    code, output, tape = post(tmp_path, FIVEAXIS, "fanuc-5axis-bc")
    assert code == 0, output
    words = [w for line in tape.read_text().splitlines() for w in line.split() if w[0] == "C"]
    values = [float(w[1:]) for w in words]
    assert all(0.0 <= v < 360.0 for v in values) and 330.0 in values and 0.0 in values


def test_the_control_s_tcp_mode_on_the_trunnion_and_computed_slides_on_the_head(
    tmp_path: Path,
) -> None:
    ac = "MACHIN/GECENT,86,OPTAB,265,1\n" + SMALL
    code, output, tape = post(tmp_path, ac, None)
    assert code == 0, output
    text = tape.read_text()
    assert "N5 X-20. A-30. C90. F800." in text  # the tip itself, G94 at the tip's feed
    assert "G93" not in text
    bc = "MACHIN/GECENT,87,OPTAB,265,0\n" + SMALL
    code, output, tape = post(tmp_path, bc, None)
    assert code == 0, output
    text = tape.read_text()
    # the gauge point: the tip + (100 + 150) up the tool axis, less the pivot's 150
    assert "N3 G00 X-40. Y-30. Z120. B0. C0." in text
    assert "G43" not in text.split("G17", 1)[1]  # no length offset along Z: it is in the slides


def test_computed_slides_on_a_head_need_the_tool_length(tmp_path: Path) -> None:
    job = "MACHIN/GECENT,87,OPTAB,265,0\n" + SMALL.replace("LOADTL/1,LENGTH,100", "LOADTL/1")
    code, output, _ = post(tmp_path, job, None)
    assert code == 2
    assert "give the tool's length, LOADTL/n,LENGTH,l" in output
    assert "Traceback" not in output


def test_a_tool_axis_beyond_travel_is_bad_input(tmp_path: Path) -> None:
    job = SMALL.replace("GOTO/0,-30,2,-0.5,0,0.8660254", "GOTO/0,-30,2,0,0,-1")
    code, output, tape = post(tmp_path, job, "fanuc-5axis-bc")
    assert code == 2
    assert "job.apt:13" in output and "beyond the rotary axes' travel (B -110 to 110)" in output
    assert not tape.exists()


@pytest.mark.parametrize(
    ("kinematics", "message"),
    [
        (
            'direction = [1.0, 0.0, 0.0]\npivot = [0.0, 0.0, 0.0]\nwrap = "limited"',
            'wrap = "limited" needs limits',
        ),
        ("direction = [0.0, 0.0, 1.0]\nlimits = [0.0, 90.0]", "limits are for wrap"),
        ("direction = [0.0, 0.0, 0.0]", "direction must not be 0, 0, 0"),
        ("direction = [0.0, 0.0, 2.0]", "the two rotary axes are parallel"),
    ],
)
def test_a_bad_kinematics_table_names_the_entry(
    tmp_path: Path, kinematics: str, message: str
) -> None:
    pack = (ROOT / "plugins" / "machines" / "linuxcnc-5axis-ac.toml").read_text()
    head, _, _ = pack.partition("[[kinematics.axis]]")
    first = 'letter = "A"\ncarrier = "table"\ndirection = [0.0, 0.0, 1.0]\n'
    second = f'letter = "C"\ncarrier = "table"\n{kinematics}\n'
    machine = tmp_path / "bad.toml"
    machine.write_text(
        head.replace('name = "linuxcnc-5axis-ac"', 'name = "bad"')
        + "[[kinematics.axis]]\n"
        + first
        + "[[kinematics.axis]]\n"
        + second
    )
    code, output, _ = post(tmp_path, SMALL, str(machine))
    assert code == 2, output
    assert "[kinematics]" in output and message in output


def test_a_kinematics_axis_needs_its_register_letter(tmp_path: Path) -> None:
    pack = (ROOT / "plugins" / "machines" / "linuxcnc-5axis-ac.toml").read_text()
    machine = tmp_path / "bad.toml"
    machine.write_text(pack.replace('6 = "A"', '6 = "B"'))
    code, output, _ = post(tmp_path, SMALL, str(machine))
    assert code == 2
    assert "register 6, which must have the letter 'A'" in output


@needs_rs274
@pytest.mark.parametrize(
    ("machine", "tcp"),
    [
        ("linuxcnc-5axis-ac", 0),
        ("linuxcnc-5axis-ac", 1),
        ("fanuc-5axis-bc", 1),
        ("fanuc-5axis-bc", 0),
    ],
)
def test_the_five_axis_job_passes_verify_at_a_micrometre_and_a_thousandth_of_a_degree(
    plugins: PluginSet, tmp_path: Path, machine: str, tcp: int
) -> None:
    number = 86 if machine == "linuxcnc-5axis-ac" else 87
    job = tmp_path / "fiveaxis.apt"
    job.write_text(f"MACHIN/GECENT,{number},OPTAB,265,{tcp}\n" + FIVEAXIS.read_text())
    code, output, tape = post(tmp_path, job, None)
    assert code == 0, output
    result = verify(str(tape), str(job), plugins, None, 0.001)
    report = "\n".join(result.report())
    assert result.passed, report
    assert "tolerance 0.001 mm, 0.001 degrees" in report
    assert "verify: passed: every CL point and tool axis reached in order" in report


@needs_rs274
@pytest.mark.parametrize(
    ("edit", "reason"),
    [
        (("N7 Y8.679 Z5.033 A-30. F40.", "N7 Y8.679 Z5.033 A-30.01 F15.279"), "off the CL"),
        (("N9 G01 Y26. Z-4.967 F800.", "N9 G01 Y26. Z-4.967 F900."), "F is 900.0000"),
        (("N11 G01 Y-8.679 Z5.033 A30. F40.", "N11 G01 Y-8.679 Z5.033 A30. F9."), "G93's F"),
        (("N6 G01 X30. Y-40. C90. F5.093\n", ""), "off the CL line"),
        (("N12 G00 Y20. Z50. A0.\n", ""), "the tape ends before this CL point"),
    ],
)
def test_verify_is_not_fooled(
    plugins: PluginSet, tmp_path: Path, edit: tuple[str, str], reason: str
) -> None:
    job = tmp_path / "job.apt"
    job.write_text(SMALL)
    tape = tmp_path / "edited.ngc"
    assert edit[0] in AC_TAPE
    tape.write_text(AC_TAPE.replace(edit[0], edit[1]))
    result = verify(str(tape), str(job), plugins, "linuxcnc-5axis-ac", 0.001)
    report = "\n".join(result.report())
    assert not result.passed
    assert reason in report, report


@needs_rs274
def test_plot_draws_the_tool_tip_and_axis_in_3d(tmp_path: Path) -> None:
    code, output, tape = post(tmp_path, FIVEAXIS, "fanuc-5axis-bc")
    assert code == 0, output
    picture = tmp_path / "plot.png"
    command = ["plot", str(tape), "--cl", str(FIVEAXIS), "--machine", "fanuc-5axis-bc"]
    result = CliRunner().invoke(main, [*command, "-o", str(picture), "--axis-every", "3"])
    assert result.exit_code == 0, result.output
    assert "points drawn in 3-D" in result.output
    assert picture.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
