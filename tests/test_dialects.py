"""CAM dialects (issue 19): SolidWorks CAM's real files post on linuxcnc-mill and pass
`gecent verify`; each of its words is read as the post's; `gecent cl` names the dialect;
a six-value GOTO along the spindle axis is three-axis motion, a tilted one an error."""

from __future__ import annotations

import shutil
from itertools import pairwise
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.cl.records import Circle, Motion, Record, Statement
from gecent.core.cli import main
from gecent.core.dispatch.post import post
from gecent.core.errors import InputError
from gecent.core.macros.dialect import DialectStage, choose_dialect
from gecent.core.output.tape import tape_image
from gecent.core.plugins import get_plugins
from gecent.plugins.dialects.solidworks import DIALECT

from .conftest import SHARED

SOLIDWORKS = SHARED / "corpus" / "solidworks-cam"
FILES = ["Sacrifice-Board.apt", "manufacture3-bottom.apt"]
needs_corpus = pytest.mark.skipif(not SOLIDWORKS.is_dir(), reason="shared corpus not present")
needs_rs274 = pytest.mark.skipif(shutil.which("rs274") is None, reason="rs274 not installed")


def translated(text: str) -> list[Record]:
    records = AptSourceReader("sw.apt").read_lines(text.splitlines(keepends=True))
    notes: list[str] = []
    stage = DialectStage(DIALECT, lambda d: notes.append(d.text))
    made = list(stage.translate(records))
    translated.notes = notes  # type: ignore[attr-defined]
    return made


def statements(records: list[Record]) -> list[str]:
    shown = []
    for record in records:
        if isinstance(record, Statement):
            args = ",".join(f"{a:g}" if isinstance(a, float) else str(a) for a in record.args)
            text = f"{record.major} {record.text}" if record.text else record.major
            shown.append(f"{record.major}/{args}" if args else text)
    return shown


@needs_corpus
@pytest.mark.parametrize("name", FILES)
def test_the_files_dialect_is_detected(name: str) -> None:
    dialect = choose_dialect(str(SOLIDWORKS / name), get_plugins())
    assert dialect is not None and dialect.name == "solidworks-cam"


@needs_corpus
def test_creo_files_are_creos_and_apt_iv_files_have_no_dialect() -> None:
    for name in ("creo/schruppen_1.ncl.1", "creo/bohren_1.ncl.8"):
        dialect = choose_dialect(str(SHARED / "corpus" / name), get_plugins())
        assert dialect is not None and dialect.name == "creo"
    for other in ("apt4/test1.apt", "apt4/test1.cl3", "apt4/test3_ppwords.apt"):
        assert choose_dialect(str(SHARED / "corpus" / other), get_plugins()) is None


@needs_corpus
def test_creos_cutter_comment_gives_the_tool_its_diameter(tmp_path: Path) -> None:
    tape = tmp_path / "rough.ngc"
    source = SHARED / "corpus" / "creo" / "schruppen_1.ncl.1"
    done = CliRunner().invoke(main, ["post", str(source), "--machine", "linuxcnc-mill", "-o",
                                     str(tape)])  # fmt: skip
    assert done.exit_code == 0 and "(T1, DIAMETER 3 MM)" in tape.read_text()


@needs_corpus
@needs_rs274
@pytest.mark.parametrize("name", FILES)
def test_solidworks_files_post_and_verify(name: str, tmp_path: Path) -> None:
    tape = tmp_path / "part.ngc"
    runner = CliRunner()
    posted = runner.invoke(
        main, ["post", str(SOLIDWORKS / name), "--machine", "linuxcnc-mill", "-o", str(tape)]
    )
    assert posted.exit_code == 0, posted.output
    checked = runner.invoke(
        main, ["verify", str(tape), "--cl", str(SOLIDWORKS / name), "--machine", "linuxcnc-mill"]
    )
    assert checked.exit_code == 0, checked.output
    assert "verify: passed" in checked.output


@needs_corpus
def test_without_the_dialect_the_file_stops_at_its_first_vendor_word() -> None:
    runner = CliRunner()
    done = runner.invoke(
        main,
        ["post", str(SOLIDWORKS / FILES[0]), "--machine", "linuxcnc-mill", "--dialect", "none",
         "-o", "/dev/null"],
    )  # fmt: skip
    # LOAD/TOOL,12: the multiaxis tool change, bad input on a machine without a transform
    # class (issue 22 wave 9; it was not yet supported)
    assert done.exit_code == 2 and "Sacrifice-Board.apt:5" in done.output


@needs_corpus
def test_gecent_cl_names_the_dialect() -> None:
    shown = CliRunner().invoke(main, ["cl", str(SOLIDWORKS / FILES[0])])
    assert shown.exit_code == 0
    lines = shown.output.splitlines()
    assert lines[0] == "DIALECT solidworks-cam (SolidWorks CAM), detected"
    assert any("UNITS" in line for line in lines) and not any("UNIT " in line for line in lines)


def test_an_unknown_dialect_is_refused_with_the_list() -> None:
    with pytest.raises(InputError, match=r"no dialect 'lunch'.*solidworks-cam"):
        choose_dialect("x.apt", get_plugins(), "lunch")


# -- each word ------------------------------------------------------------------------------


def test_unit_load_select_insert() -> None:
    made = translated(
        "PARTNO/1\nUNIT/MM\nINSERT/[HOLDER=C40] 10.0mm DRILL\nLOAD/TOOL,18\nSELECT/TOOL,19\n"
    )
    assert statements(made) == ["PARTNO 1", "UNITS/MM", "PPRINT [HOLDER=C40] 10.0mm DRILL",
                                "LOADTL/18"]  # fmt: skip


def test_vendor_notes_are_ignored_and_said_once() -> None:
    made = translated(
        "CSI_SET_FLUTE_LENGTH/4.\nCSI_SET_FLUTE_LENGTH/5.\nTRNTYP/WORLD,0,0,0\nSETUP/START,2\n"
        "COOLNT/FLOOD\nSETUP/END,2\n"
    )
    assert statements(made) == ["COOLNT/FLOOD"]
    assert translated.notes == [  # type: ignore[attr-defined]
        "CSI_SET_FLUTE_LENGTH IS A SOLIDWORKS CAM NOTE; IGNORED",
        "TRNTYP IS A SOLIDWORKS CAM NOTE; IGNORED",
        "SETUP IS A SOLIDWORKS CAM NOTE; IGNORED",
    ]


def test_cycles_as_the_posts() -> None:
    made = translated(
        "CYCLE/INIT\nCYCLE/DRILL,FEDTO,5.4,MMPM,364.49,RAPTO,3.,RTRCTO,27.5,DWELL,0\n"
        "CYCLE/DEEP2,FEDTO,28.6,1STPECK,5.,SUBPECK,2.,MMPM,382.27,RAPTO,3.,RTRCTO,2.\n"
        "CYCLE/OFF\n"
    )
    assert statements(made) == [
        "CYCLE/DRILL,DEPTH,5.4,CLEAR,3,RETURN,0,MMPM,364.49",
        "CYCLE/DEEP,DEPTH,28.6,CLEAR,3,STEP,2,MMPM,382.27",  # RTRCTO below R: back to R
        "CYCLE/OFF",
    ]
    assert translated.notes == ["CYCLE/DEEP2: EVERY PECK IS 2 (FIRST PECK 5 NOT KEPT)"]  # type: ignore[attr-defined]


def test_a_cycle_without_its_depth_names_the_line() -> None:
    with pytest.raises(InputError, match=r"sw.apt:1.*FEDTO \(the depth\) is missing"):
        translated("CYCLE/DRILL,MMPM,100,RAPTO,3\n")


def test_csys_that_turns_the_tool_axis_moves_the_part_into_the_machine() -> None:
    """CSYS/-1,0,0,10,0,1,0,20,0,0,-1,30 (a flipped setup, shifted): points, arc centres and
    the tool axis turn with it; the identity ends it."""
    made = translated(
        "CSYS/-1.,0,0,10.,0,1.,0,20.,0,0,-1.,30.\nGOTO/5.,6.,-7.\n"
        "CIRCLE/1,2,-3,0,0,-1\nGOTO/1,2,3,0,0,-1\nCSYS/1.,0,0,0,0,1.,0,0,0,0,1.,0\n"
        "GOTO/1,2,3\n"
    )
    motions = [r for r in made if isinstance(r, Motion | Circle)]
    assert motions[0].points[0] == pytest.approx((5.0, 26.0, 37.0))  # type: ignore[union-attr]
    assert motions[1].values == pytest.approx((9.0, 22.0, 33.0, 0.0, 0.0, 1.0))  # type: ignore[union-attr]
    assert motions[2].points[0] == pytest.approx((9.0, 22.0, 27.0, 0.0, 0.0, 1.0))  # type: ignore[union-attr]
    assert motions[3].points[0] == (1.0, 2.0, 3.0)  # type: ignore[union-attr]


def test_csys_that_turns_about_z_leaves_the_points() -> None:
    """manufacture3-bottom's setups turned about Z: their points are in the setup's frame
    already (applied, three setups would drill one place three times)."""
    made = translated("CSYS/-1.,0,0,456.35,0,-1.,0,197.03,0,0,1.,0\nGOTO/295.4,106.3,25.\n")
    assert [r.points for r in made if isinstance(r, Motion)] == [((295.4, 106.3, 25.0),)]


@needs_corpus
def test_manufacture3_drills_each_hole_group_once(tmp_path: Path) -> None:
    tape = tmp_path / "m3.ngc"
    source = SOLIDWORKS / "manufacture3-bottom.apt"
    CliRunner().invoke(main, ["post", str(source), "--machine", "linuxcnc-mill", "-o", str(tape)])
    starts = [line.split(" F")[0].split(" ", 2)[2] for line in tape.read_text().splitlines()
              if " G83 " in line or " G81 " in line]  # fmt: skip
    assert len(starts) == len(set(starts)) >= 3  # every cycle starts at a hole of its own


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("CSYS/1,0,0,0,0,2,0,0,0,0,1,0\n", "not a rotation"),
        ("CSYS/1,0,0,0,0,1,0,0,0,0,-1,0\n", "mirrored"),
        ("CSYS/1,0,0,0\n", "12 numbers"),
    ],
)
def test_a_bad_csys_names_its_line(text: str, message: str) -> None:
    with pytest.raises(InputError, match=f"sw.apt:1.*{message}"):
        translated(text)


def test_a_flipped_setup_turns_the_tool_axis_to_the_spindle(tmp_path: Path) -> None:
    """Sacrifice-Board's bottom side: CSYS/-1,0,0,0,0,1,0,0,0,0,-1,0 and GOTOs with the tool
    axis 0,0,-1 in part coordinates post as ordinary three-axis moves."""
    program = (
        "PARTNO/1\nUNIT/MM\nCSI_X/1\nLOAD/TOOL,1\nSPINDL/1000,RPM,CLW\nFEDRAT/100.,MMPM\n"
        "CSYS/-1.,0,0,0,0,1.,0,0,0,0,-1.,0\nGOTO/390.,145.,-55.,0,0,-1.\nGOTO/390.,145.,-27.5,0,0,-1.\n"
        "FINI\n"
    )  # fmt: skip
    path = tmp_path / "flipped.apt"
    path.write_text(program)
    result = post(str(path), get_plugins(), "linuxcnc-mill")
    tape = tape_image(result.blocks)
    assert "X-390. Y145. Z55." in tape and "Z27.5" in tape


def test_a_tilted_tool_axis_on_a_three_axis_machine_names_its_line(tmp_path: Path) -> None:
    path = tmp_path / "tilted.apt"
    path.write_text("PARTNO T\nUNITS/MM\nFROM/0,0,10\nGOTO/1,2,3,0,0.5,0.8660254\nFINI\n")
    with pytest.raises(InputError) as refused:
        post(str(path), get_plugins(), "linuxcnc-mill")
    assert "tilted.apt:4" in str(refused.value)
    assert "no rotary axes; use a multiaxis machine" in str(refused.value)


def test_a_spindle_axis_goto_is_three_axis_motion(tmp_path: Path) -> None:
    path = tmp_path / "axis.apt"
    path.write_text(
        "PARTNO T\nUNITS/MM\nFROM/0,0,10\nFEDRAT/100\nMULTAX/ON\nGOTO/1,2,3,0,0,1\n"
        "MULTAX/OFF\nGOTO/4,5,6,0,0,1\nFINI\n"
    )
    tape = tape_image(post(str(path), get_plugins(), "linuxcnc-mill").blocks)
    assert "X1. Y2. Z3." in tape and "X4. Y5. Z6." in tape


def test_words_may_begin_with_digits_and_circles_may_lack_a_radius() -> None:
    made = list(AptSourceReader("x").read_lines(["CYCLE/DEEP,1STPECK,5\n", "CIRCLE/1,2,3,0,0,1\n"]))
    assert made[0].args[1].name == "1STPECK"  # type: ignore[union-attr]
    assert made[1].values == (1.0, 2.0, 3.0, 0.0, 0.0, 1.0)  # type: ignore[union-attr]


# -- the examples of dialects.md, NX and NCL -------------------------------------------------

DIALECTS_MD = SHARED / "corpus" / "dialects.md"


def dialect_examples() -> list[str]:
    import re

    return re.findall(r"```\n(.*?)```", DIALECTS_MD.read_text(encoding="utf-8"), re.DOTALL)


@needs_corpus
@pytest.mark.parametrize(
    ("index", "name"), [(0, "nx"), (1, "solidworks-cam"), (2, "ncl")], ids=["nx", "sw", "ncl"]
)
def test_each_example_is_detected(index: int, name: str, tmp_path: Path) -> None:
    path = tmp_path / "example.cl"
    path.write_text(dialect_examples()[index])
    dialect = choose_dialect(str(path), get_plugins())
    assert dialect is not None and dialect.name == name


@needs_corpus
@pytest.mark.parametrize("index", [0, 1], ids=["nx", "sw"])
def test_the_nx_and_solidworks_examples_post(index: int, tmp_path: Path) -> None:
    source, tape = tmp_path / "example.cl", tmp_path / "example.ngc"
    source.write_text(dialect_examples()[index])
    posted = CliRunner().invoke(
        main, ["post", str(source), "--machine", "linuxcnc-mill", "-o", str(tape)]
    )
    assert posted.exit_code == 0, posted.output
    assert "NO FINI STATEMENT" in posted.output  # they end without FINI: the program ends
    assert tape.read_text().rstrip().endswith("M02\n%")


@needs_corpus
def test_the_nx_example_plots_through_its_dialect(tmp_path: Path) -> None:
    """plot reads a CL file as the post does: NX's CYCLE/DRILL,DEEP is its peck cycle
    (read as plain APT it is refused)."""
    source, picture = tmp_path / "example.cl", tmp_path / "example.svg"
    source.write_text(dialect_examples()[0])
    arguments = ["plot", str(source), "--machine", "linuxcnc-mill", "-o", str(picture)]
    drawn = CliRunner().invoke(main, arguments)
    assert drawn.exit_code == 0, drawn.output
    assert "44 moves drawn" in drawn.output
    plain = CliRunner().invoke(main, [*arguments, "--dialect", "none"])
    # (bad input since wave 7: DEEP is a cycle of its own, not a DRILL modifier, 001 L30106-30130)
    assert plain.exit_code == 2 and "CYCLE/DRILL does not take DEEP" in plain.output


@needs_corpus
@needs_rs274
def test_the_nx_example_verifies_nurbs_and_all(tmp_path: Path) -> None:
    """The NX example's path (11-value circle, peck cycle, NURBS) read back by rs274. (The
    SolidWorks example is a fragment that drills from an unknown start: it posts, above.)"""
    source, tape = tmp_path / "example.cl", tmp_path / "example.ngc"
    source.write_text(dialect_examples()[0])
    runner = CliRunner()
    assert (
        runner.invoke(
            main, ["post", str(source), "--machine", "linuxcnc-mill", "-o", str(tape)]
        ).exit_code
        == 0
    )
    checked = runner.invoke(
        main, ["verify", str(tape), "--cl", str(source), "--machine", "linuxcnc-mill"]
    )
    assert checked.exit_code == 0, checked.output


@needs_corpus
def test_the_ncl_example_names_its_tilted_tool_axis(tmp_path: Path) -> None:
    """Its second GOTO tilts the tool 5 degrees: on a three-axis machine that is an error
    naming the line (a multiaxis machine posts it, issue 21)."""
    source = tmp_path / "ncl.apt"
    source.write_text(dialect_examples()[2])
    done = CliRunner().invoke(
        main, ["post", str(source), "--machine", "linuxcnc-mill", "-o", str(tmp_path / "t")]
    )
    assert done.exit_code == 2
    assert "ncl.apt:8" in done.output and "use a multiaxis machine" in done.output
    assert "PART 4711" not in done.output  # REMARK lines are comments, read without a word


def nx(text: str) -> list[Record]:
    from gecent.plugins.dialects.nx import DIALECT as NX

    records = AptSourceReader("nx.cls").read_lines(text.splitlines(keepends=True))
    return list(DialectStage(NX, None, metric=True).translate(records))


def test_nx_words() -> None:
    made = nx(
        "TOOL PATH/CONTOUR_OUTER,TOOL,FACE_MILL_D40\nTLDATA/MILL,40.0,1.0,50.0,0.0,0.0\n"
        "PAINT/PATH\nLOAD/TOOL,3,ADJUST,3\nSELECT/TOOL,3\nFEDRAT/MMPM,600\n"
        "CUTCOM/LEFT,XYPLAN\nCYCLE/DRILL,DEEP,RAPTO,3.0,FEDTO,-12.0,MMPM,250.0\nEND-OF-PATH\n"
    )
    assert statements(made) == [
        "PPRINT CONTOUR_OUTER FACE_MILL_D40",
        "LOADTL/3,ADJUST,3",
        "FEDRAT/MMPM,600",
        "CUTCOM/LEFT",
        "CYCLE/DEEP,DEPTH,12,CLEAR,3,MMPM,250",
    ]
    cutter = [r for r in made if not isinstance(r, Statement)]
    assert [type(r).__name__ for r in cutter] == ["Arelem"]  # TLDATA -> CUTTER/40,1


def test_nurbs_become_moves_on_the_curve_within_intol() -> None:
    """A quadratic B-spline (knots 0,0,0,.5,1,1,1): the moves start at the curve's start,
    end at its end, and no chord strays from the curve by more than INTOL."""
    from gecent.core.cl.nurbs import NurbsCurve, _off_chord
    from gecent.core.errors import SourcePosition

    made = nx(
        "INTOL/0.005\nNURBS/\nKNOT/0,0,0,0.5,1,$\n1,1\nCNTRL/0,0,-2\nCNTRL/5,8,-2\n"
        "CNTRL/15,8,-2\nCNTRL/20,0,-2\nGOTO/20,0,-2\n"
    )
    moves = [r for r in made if isinstance(r, Motion)]
    points = moves[0].points
    assert points[0] == pytest.approx((0.0, 0.0, -2.0))
    assert points[-1] == pytest.approx((20.0, 0.0, -2.0))
    control = [(0, 0, -2), (5, 8, -2), (15, 8, -2), (20, 0, -2)]
    curve = NurbsCurve([0, 0, 0, 0.5, 1, 1, 1], control, SourcePosition("t"))
    samples = [curve.at(u / 400) for u in range(401)]
    for a, b in pairwise(points):
        near = [p for p in samples if min(a[0], b[0]) - 1e-9 <= p[0] <= max(a[0], b[0]) + 1e-9]
        assert max(_off_chord(p, a, b) for p in near) <= 0.005 + 1e-9
    assert moves[1].points == ((20.0, 0.0, -2.0),)  # the GOTO after it stays


def test_a_weighted_nurbs_is_a_true_circle() -> None:
    """Weights: a quarter circle of radius 10 as a rational quadratic (w = cos 45 degrees)."""
    from gecent.core.cl.nurbs import NurbsCurve
    from gecent.core.errors import SourcePosition

    w = 0.5**0.5
    curve = NurbsCurve([0, 0, 0, 1, 1, 1], [(10, 0, 0, 1), (10, 10, 0, w), (0, 10, 0, 1)],
                       SourcePosition("t"))  # fmt: skip
    for u in (0.1, 0.3, 0.5, 0.9):
        x, y, _ = curve.at(u)
        assert (x * x + y * y) ** 0.5 == pytest.approx(10.0, abs=1e-9)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("NURBS/\nKNOT/0,1\nCNTRL/0,0,0\nCNTRL/1,1,1\n", "give no degree"),
        ("NURBS/\nKNOT/0,0,1,0.5,1,1\nCNTRL/0,0,0\nCNTRL/1,1,1\nCNTRL/2,0,0\n", "not decrease"),
        ("NURBS/\nKNOT/0,0,0,1,1,1\nCNTRL/0,0,0,0\nCNTRL/1,1,1\nCNTRL/2,0,0\n", "weight above 0"),
    ],
)
def test_a_bad_nurbs_names_its_line(text: str, message: str) -> None:
    with pytest.raises(InputError, match=message) as refused:
        nx(text)
    assert "nx.cls:1" in str(refused.value)
