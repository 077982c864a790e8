"""`gecent verify` and `gecent plot`: the corpus posted on the modern packs and read back by
LinuxCNC's rs274 within 0.001 mm; a lathe program in G18; a corrupted tape named by its
block. These need rs274 (Debian package linuxcnc-uspace); without it they skip."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.plugins import PluginSet
from gecent.core.verify.check import verify
from gecent.core.verify.rs274 import numbered_copy, parse_canon

from .conftest import ROOT, SHARED

CORPUS = SHARED / "corpus"
CL_FILES = [
    "creo/schruppen_1.ncl.1",
    "creo/bohren_1.ncl.8",
    "apt4/test1.cl3",
    "apt4/test2_contour_tlrgt.cl3",
    "apt4/test2d_finetol.cl3",
    "apt4/test3_ppwords.cl3",
]
needs_rs274 = pytest.mark.skipif(
    shutil.which("rs274") is None,
    reason="rs274 (LinuxCNC's interpreter, Debian package linuxcnc-uspace) is not installed",
)
needs_corpus = pytest.mark.skipif(not CORPUS.is_dir(), reason="shared corpus not present")


def post_file(source: Path, machine: str, tape: Path) -> None:
    result = CliRunner().invoke(
        main,
        [
            "post",
            str(source),
            "--machine",
            machine,
            "-o",
            str(tape),
            "--listing",
            str(tape.with_suffix(".lis")),
        ],
    )
    assert result.exit_code == 0, result.output


def test_numbered_copy_names_blocks_by_tape_line() -> None:
    tape = "%\n(COMMENT)\nN10 G00 X1.\n/N20 G01 X2.\nG01 X3.\n%\n"
    assert numbered_copy(tape, diameter=False) == (
        "%\n(COMMENT)\nN3 G00 X1.\n/N4 G01 X2.\nN5 G01 X3.\n%\n"
    )
    assert numbered_copy(tape, diameter=True).splitlines()[1] == "G07"


def test_parse_canon_reads_moves_in_their_plane() -> None:
    output = """\
    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)
    2 N3     SELECT_PLANE(CANON_PLANE_XZ)
    3 N3     SET_FEED_MODE(0, 1)
    4 N3     SET_FEED_RATE(0.1500)
    5 N4     STRAIGHT_FEED(10.0000, 0.0000, -20.0000, 0.0000, 0.0000, 0.0000)
    6 N5     ARC_FEED(-25.0000, 15.0000, -25.0000, 10.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)
"""
    reading = parse_canon(output)
    feed, arc = reading.moves
    assert feed.end == (10.0, 0.0, -20.0) and feed.per_revolution and feed.feed == 0.15
    assert arc.end == (15.0, 0.0, -25.0) and arc.centre == (10.0, 0.0, -25.0)
    assert arc.plane == "XZ" and arc.rotation == 1 and arc.line == 5


@needs_rs274
@needs_corpus
@pytest.mark.parametrize(
    "machine", ["linuxcnc-mill", "fanuc-mill", "haas-mill", "sinumerik-840d-iso"]
)
@pytest.mark.parametrize("name", CL_FILES)
def test_corpus_verifies(plugins: PluginSet, tmp_path: Path, name: str, machine: str) -> None:
    source = CORPUS / name
    tape = tmp_path / "part.ngc"
    post_file(source, machine, tape)
    result = verify(str(tape), str(source), plugins, machine, 0.001)
    assert result.passed, "\n".join(result.report())
    assert result.comparison is not None
    assert max(result.comparison.deviation) <= 0.001
    assert result.comparison.targets > 0


@needs_rs274
def test_lathe_verifies_in_g18(plugins: PluginSet, tmp_path: Path) -> None:
    source = ROOT / "examples" / "lathe_fanuc.apt"
    tape = tmp_path / "lathe.ngc"
    post_file(source, "fanuc-lathe", tape)
    result = verify(str(tape), str(source), plugins, None, 0.001)
    assert result.passed, "\n".join(result.report())
    assert result.comparison is not None and result.comparison.arcs == 2
    assert {move.plane for move in result.interpretation.moves} == {"XZ"}


@needs_rs274
def test_corrupted_tape_fails_and_names_the_block(plugins: PluginSet, tmp_path: Path) -> None:
    """One coordinate changed by 0.01 mm: verify exits 1 naming the tape line and block."""
    source = ROOT / "examples" / "lathe_fanuc.apt"
    tape = tmp_path / "lathe.ngc"
    post_file(source, "fanuc-lathe", tape)
    text = tape.read_text()
    assert "N8 G01 Z-40.\n" in text
    tape.write_text(text.replace("N8 G01 Z-40.\n", "N8 G01 Z-40.01\n"))
    result = CliRunner().invoke(main, ["verify", str(tape), "--cl", str(source)])
    assert result.exit_code == 1, result.output
    assert "FAILED: first mismatch at CL" in result.output
    assert "lathe_fanuc.apt:18" in result.output  # the GOTO / -40, 15, 0
    line = text.splitlines().index("N8 G01 Z-40.") + 1
    assert f"tape line {line}: N8 G01 Z-40.01" in result.output


@needs_rs274
def test_a_tape_rs274_refuses_fails(plugins: PluginSet, tmp_path: Path) -> None:
    source = ROOT / "examples" / "lathe_fanuc.apt"
    tape = tmp_path / "lathe.ngc"
    post_file(source, "fanuc-lathe", tape)
    tape.write_text(tape.read_text().replace("G02 X60. Z-50. I10.", "G02 X60. Z-50. I12."))
    result = CliRunner().invoke(main, ["verify", str(tape), "--cl", str(source)])
    assert result.exit_code == 1
    assert "rs274 stopped reading the tape at tape line" in result.output
    assert "G02 X60. Z-50. I12." in result.output


def test_verify_without_rs274_says_what_to_install(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr("gecent.core.verify.rs274.rs274_path", lambda: None)
    source = ROOT / "examples" / "lathe_fanuc.apt"
    tape = tmp_path / "lathe.ngc"
    post_file(source, "fanuc-lathe", tape)
    result = CliRunner().invoke(main, ["verify", str(tape), "--cl", str(source)])
    assert result.exit_code == 3
    assert "linuxcnc-uspace" in result.output


@pytest.mark.parametrize("suffix", [".png", ".svg"])
def test_plot_a_cl_file(tmp_path: Path, suffix: str) -> None:
    picture = tmp_path / f"lathe{suffix}"
    source = ROOT / "examples" / "lathe_fanuc.apt"
    result = CliRunner().invoke(main, ["plot", str(source), "-o", str(picture), "--plane", "XZ"])
    assert result.exit_code == 0, result.output
    data = picture.read_bytes()
    assert data.startswith(b"\x89PNG") if suffix == ".png" else b"<svg" in data
    if suffix == ".svg":
        assert data.count(b"<path") >= 9  # 7 lines and 2 arcs at least


@needs_rs274
def test_plot_a_tape_with_the_cl_under_it(tmp_path: Path) -> None:
    source = ROOT / "examples" / "lathe_fanuc.apt"
    tape = tmp_path / "lathe.ngc"
    post_file(source, "fanuc-lathe", tape)
    picture = tmp_path / "lathe.png"
    result = CliRunner().invoke(
        main, ["plot", str(tape), "--cl", str(source), "-o", str(picture), "--plane", "XZ"]
    )
    assert result.exit_code == 0, result.output
    assert "9 moves drawn" in result.output


def test_plot_refuses_other_formats(tmp_path: Path) -> None:
    source = ROOT / "examples" / "lathe_fanuc.apt"
    result = CliRunner().invoke(main, ["plot", str(source), "-o", str(tmp_path / "x.jpg")])
    assert result.exit_code == 2
    assert ".png or .svg" in result.output
    assert not (tmp_path / "x.jpg").exists()
