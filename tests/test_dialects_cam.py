"""CAM dialects, continued (tests/test_dialects.py has SolidWorks CAM's real files and the
dialects.md examples): CATIA V5, Mastercam (NCI to APT) and Fusion files in the forms their
vendors document, and the later NX and SolidWorks word forms."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.cl.records import Circle, Motion, Statement
from gecent.core.cli import main
from gecent.core.dispatch.post import post
from gecent.core.errors import InputError
from gecent.core.macros.dialect import DialectStage, choose_dialect
from gecent.core.output.tape import tape_image
from gecent.core.plugins import get_plugins

from .test_dialects import needs_rs274, nx, statements, translated

# -- CATIA V5, Mastercam (NCI to APT), Fusion: files in their documented forms -----------------
# (tests/data/dialect_*: written for these tests from the vendors' documented output, issue 19
# research: CATIA's sequence tags past column 72 and TLON,GOFWD circle, Mastercam's LOAD/TOOL
# and unit-first SPINDL, Fusion's quoted PARTNO, LOADTL with four values and its cycles)

DATA = Path(__file__).resolve().parent / "data"


@pytest.mark.parametrize(
    ("name", "dialect"),
    [
        ("dialect_catia.aptsource", "catia"),
        ("dialect_mastercam.apt", "mastercam"),
        ("dialect_fusion.apt", "fusion"),
    ],
)
def test_vendor_files_are_detected(name: str, dialect: str) -> None:
    found = choose_dialect(str(DATA / name), get_plugins())
    assert found is not None and found.name == dialect


@needs_rs274
@pytest.mark.parametrize(
    ("name", "expected"),
    [
        ("dialect_catia.aptsource", ["N1 T01 M06", "N5 G03 X0. Y50. I-50."]),
        ("dialect_mastercam.apt", ["N1 T01 M06", "N5 G03 X66.625 Y70. J-2.625"]),
        ("dialect_fusion.apt", ["N1 T01 M06", "N9 G81 X5. Y5. Z-5. F100. R5."]),
    ],
)
def test_vendor_files_post_and_verify(name: str, expected: list[str], tmp_path: Path) -> None:
    tape = tmp_path / "part.ngc"
    runner = CliRunner()
    posted = runner.invoke(
        main, ["post", str(DATA / name), "--machine", "linuxcnc-mill", "-o", str(tape)]
    )
    assert posted.exit_code == 0, posted.output
    lines = tape.read_text().splitlines()
    assert all(line in lines for line in expected), lines
    checked = runner.invoke(
        main, ["verify", str(tape), "--cl", str(DATA / name), "--machine", "linuxcnc-mill"]
    )
    assert checked.exit_code == 0, checked.output


def test_a_gofwd_circle_without_indirv_names_its_line(tmp_path: Path) -> None:
    source = tmp_path / "m.apt"
    source.write_text(
        "$$MasterCAM NCI to APT Source CLFile Converter\nUNITS/MM\nFROM/0,0,0\n"
        "TLON,GOFWD/ (CIRCLE/ 0,0,0,5),ON,(LINE/ 0,0,0,5,0,0)\nFINI\n"
    )
    with pytest.raises(InputError, match=r"m\.apt:4.*needs INDIRV"):
        post(str(source), get_plugins(), "linuxcnc-mill")


def test_catia_lines_are_read_to_column_72() -> None:
    from gecent.core.cl.apt_source import read_apt_source

    records = list(read_apt_source(str(DATA / "dialect_catia.aptsource"), 72))
    gotos = [r for r in records if isinstance(r, Motion)]
    assert gotos[0].points == ((50.0, 0.0, 10.0),)  # "PT 1" past column 72 is not read
    with pytest.raises(InputError, match="expected ',' between values"):
        list(read_apt_source(str(DATA / "dialect_catia.aptsource")))


def test_fusion_words() -> None:
    from gecent.plugins.dialects.fusion import DIALECT as FUSION

    text = (
        "PARTNO/'BRACKET'\nPPRINT/'ROUGH'\nLOADTL/1,0,50,1\nLOADTL/2,0,50,0\n"
        "MOVARC/0,0,0,0,0,-1,5,ANGLE,90\nCUTCOM/ON\nMODE/MILL\n"
        "CYCLE/DEEP, 12, INCR, 2, MMPM, 100, 8, RAPTO, 3\nGOTO/1,2,-12\nGOTO/3,4,-12\n"
        "GOTO/5,6,-20\nCYCLE/OFF\n"
        "CYCLE/BORE, 8, MMPM, 50, 2, 0.1, ORIENT, 0\nCYCLE/OFF\n"
    )
    records = AptSourceReader("f.apt").read_lines(text.splitlines(keepends=True))
    made = list(DialectStage(FUSION).translate(records))
    # the points are the holes' bottoms, the clearance an absolute height and RAPTO below
    # it (the R plane at 8 - 3 = 5): the post's cycle from each hole's top; a new top
    # restates the cycle; a cycle with no point makes nothing
    assert statements(made) == [
        "PARTNO BRACKET", "PPRINT ROUGH", "LOADTL/1,ADJUST,1", "LOADTL/2",
        "CYCLE/DEEP,DEPTH,12,CLEAR,5,STEP,2,RETURN,0,MMPM,100",
        "CYCLE/DEEP,DEPTH,12,CLEAR,13,STEP,2,RETURN,0,MMPM,100",
        "CYCLE/OFF",
    ]  # fmt: skip
    holes = [r.points[0] for r in made if isinstance(r, Motion)]
    assert holes == [(1.0, 2.0, 0.0), (3.0, 4.0, 0.0), (5.0, 6.0, -8.0)]
    circles = [r for r in made if isinstance(r, Circle)]
    assert circles[0].values == (0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 5.0)


# -- what the review found ----------------------------------------------------------------


def test_two_gofwd_arcs_in_a_row_each_turn_their_own_way(tmp_path: Path) -> None:
    source = tmp_path / "two.apt"
    source.write_text(
        "$$MasterCAM NCI to APT Source CLFile Converter\nUNITS/MM\nFROM/50,0,-2\nFEDRAT/100\n"
        "INDIRV/0,1,0\nTLON,GOFWD/ (CIRCLE/ 0,0,-2,50),ON,2,INTOF,(LINE/ 0,0,-2,-50,0,-2)\n"
        "INDIRV/0,-1,0\nTLON,GOFWD/ (CIRCLE/ 0,0,-2,50),ON,2,INTOF,(LINE/ 0,0,-2,50,0,-2)\nFINI\n"
    )
    tape = tape_image(post(str(source), get_plugins(), "linuxcnc-mill").blocks)
    assert tape.count("G03") == 1 and "X-50." in tape and "G02" not in tape  # a full circle


def test_nx_rtrcto() -> None:
    made = nx(
        "CYCLE/DRILL,RAPTO,3,FEDTO,-10,RTRCTO,20,MMPM,100\n"
        "CYCLE/DRILL,RAPTO,3,FEDTO,-10,RTRCTO,AUTO,MMPM,100\n"
    )
    assert statements(made) == [
        "CYCLE/DRILL,DEPTH,10,CLEAR,3,RETURN,0,MMPM,100",
        "CYCLE/DRILL,DEPTH,10,CLEAR,3,MMPM,100",
    ]


def test_nx_is_not_detected_from_a_comment(tmp_path: Path) -> None:
    plain = tmp_path / "plain.apt"
    plain.write_text("$$ OPERATION 1: SEE TOOL PATH/SHEET 2\nCYCLE/DRILL,DEPTH,10,CLEAR,3\n")
    assert choose_dialect(str(plain), get_plugins()) is None


def test_gecent_cl_reads_catia_to_column_72() -> None:
    shown = CliRunner().invoke(main, ["cl", str(DATA / "dialect_catia.aptsource")])
    assert shown.exit_code == 0 and shown.output.startswith("DIALECT catia")


def test_a_statement_without_its_slash_is_still_an_error() -> None:
    with pytest.raises(InputError, match="expected '/' after COOLNT"):
        list(AptSourceReader("x").read_lines(["COOLNT OFF\n"]))


def test_nurbs_knots_all_the_same_are_refused() -> None:
    with pytest.raises(InputError, match="no span"):
        nx("NURBS/\nKNOT/0,0,0,0,0,0\nCNTRL/0,0,0\nCNTRL/1,1,1\nCNTRL/2,0,0\n")


def test_a_control_drill_with_a_dwell_is_g82_and_a_bore_with_one_is_refused(
    tmp_path: Path,
) -> None:
    head = "PARTNO T\nUNITS/MM\nFROM/0,0,10\nFEDRAT/100\n"
    source = tmp_path / "dwell.apt"
    source.write_text(head + "CYCLE/DRILL,DEPTH,5,CLEAR,2,DWELL,1.5,MMPM,50\nGOTO/1,1,0\n"
                      "CYCLE/OFF\nFINI\n")  # fmt: skip
    tape = tape_image(post(str(source), get_plugins(), "linuxcnc-mill").blocks)
    assert "G82" in tape and "P1.5" in tape and "G81" not in tape
    source.write_text(head + "CYCLE/BORE,DEPTH,5,CLEAR,2,DWELL,1.5,MMPM,50\nGOTO/1,1,0\nFINI\n")
    # the pack has no G89: the bore is drilled by moves (issue 22, tests/test_cycles_wave3.py)
    bored = tape_image(post(str(source), get_plugins(), "linuxcnc-mill").blocks)
    assert "G04 P1.5" in bored and "G89" not in bored


def test_solidworks_unit_inch() -> None:
    assert statements(translated("UNIT/INCH\n")) == ["UNITS/INCHES"]


def test_a_value_past_catias_column_72_is_an_error() -> None:
    from gecent.core.cl.apt_source import AptSourceReader

    line = "GOTO / 1.0, 2.0, " + "3" * 60 + ".5\n"  # the number crosses column 72
    with pytest.raises(InputError, match=r"x:1:73.*runs past column 72"):
        list(AptSourceReader("x", 72).read_lines([line]))


def test_gofwd_errors_are_named(tmp_path: Path) -> None:
    head = "$$MasterCAM NCI to APT Source CLFile Converter\nUNITS/MM\nFROM/50,0,0\n"
    source = tmp_path / "g.apt"
    source.write_text(
        head + "INDIRV/1,0,0\nTLON,GOFWD/ (CIRCLE/ 0,0,0,50),ON,(LINE/ 0,0,0,0,50,0)\n"
    )
    with pytest.raises(InputError, match="along the radius"):
        post(str(source), get_plugins(), "linuxcnc-mill")
    source.write_text(head + "INDIRV/0,1,0\nTLON,GOFWD/ (CIRCLE/ 0,0,0,50,ON,(LINE/ 0,0,0)\n")
    with pytest.raises(InputError, match="GOFWD: "):
        post(str(source), get_plugins(), "linuxcnc-mill")


def test_a_nurbs_cut_too_fine_is_refused() -> None:
    with pytest.raises(InputError, match="is INTOL meant so fine"):
        nx("INTOL/1e-9\nNURBS/\nKNOT/0,0,0,1,1,1\nCNTRL/0,0,0\nCNTRL/500,500,0\nCNTRL/1000,0,0\n")


def test_nx_hole_tool_data_and_a_turned_msys() -> None:
    made = nx("TLDATA/DRILL,8.5,118,60\nMSYS/0,0,0,0,1,0,-1,0,0\n")
    cutters = [r for r in made if not isinstance(r, Statement)]
    assert [type(r).__name__ for r in cutters] == ["Arelem"]  # CUTTER/8.5
