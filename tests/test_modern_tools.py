"""Tool data on the modern packs (issue 16; options 263, 264, TABLEG 128-130, REGSTR 22-24):
the tool list in the header, G49 and G54 in the start block, G43 H with the first move after
a tool change, D with CUTCOM, the lathe's T as station and offset."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.plugins import PluginSet
from gecent.core.verify.check import verify

PROGRAM = """PARTNO TOOLS
UNITS/MM
CUTTER/10
LOADTL/4,LENGTH,75
SPINDL/RPM,2000,CLW
RAPID
GOTO/10,0,5
FEDRAT/400,MMPM
CUTCOM/LEFT,XYPLAN
GOTO/10,0,-1
GOTO/20,10,-1
CUTCOM/OFF
RAPID
GOTO/20,10,50
LOADTL/17,ADJUST,27
CUTTER/6.35
SPINDL/RPM,3000,CLW
RAPID
GOTO/0,0,5
CUTCOM/RIGHT,33
GOTO/0,0,-2
CUTCOM/OFF
FINI
"""


def post(tmp_path: Path, text: str, machine: str) -> tuple[int, str, str]:
    source = tmp_path / "p.apt"
    source.write_text(text)
    tape = tmp_path / "p.ngc"
    result = CliRunner().invoke(main, ["post", str(source), "--machine", machine, "-o", str(tape)])
    return result.exit_code, tape.read_text() if tape.exists() else "", result.output


def test_a_mill_program_with_tool_data(tmp_path: Path) -> None:
    status, tape, output = post(tmp_path, PROGRAM, "fanuc-mill")
    assert status == 0, output
    assert tape.splitlines() == [
        "%",
        "O1000",
        "(TOOLS)",
        "(T4, DIAMETER 10 MM, LENGTH 75 MM)",
        "(T17, DIAMETER 6.35 MM)",
        "G17 G21 G90 G94 G40 G49 G80 G54",
        "N1 T04 M06",
        "N2 S2000 M03",
        "N3 G00 G43 X10. Y0. Z5. H4",
        "N4 G41 D4",
        "N5 G01 Z-1. F400.",
        "N6 X20. Y10.",
        "N7 G40",
        "N8 G00 Z50.",
        "N9 T17 M06",
        "N10 S3000 M03",  # the tool change stopped the spindle
        "N11 G00 G43 X0. Y0. Z5. H27",  # ADJUST,27; G00 stated again after the tool change
        "N12 G42 D33",  # CUTCOM/RIGHT,33
        "N13 G01 Z-2.",
        "N14 G40",
        "N15 M30",
        "%",
    ]


@pytest.mark.skipif(shutil.which("rs274") is None, reason="rs274 is not installed")
@pytest.mark.parametrize("machine", ["linuxcnc-mill", "fanuc-mill"])
def test_tool_data_verifies(plugins: PluginSet, tmp_path: Path, machine: str) -> None:
    status, _, output = post(tmp_path, PROGRAM, machine)
    assert status == 0, output
    result = verify(str(tmp_path / "p.ngc"), str(tmp_path / "p.apt"), plugins, machine, 0.001)
    assert result.passed, "\n".join(result.report())
    assert result.interpretation.tools == (4, 17, 27, 33)


@pytest.mark.parametrize(
    ("load", "t_word"),
    [
        ("LOADTL/1", "T0101"),
        ("LOADTL/101", "T0101"),
        ("LOADTL/2,OFSETL,12", "T0212"),
        ("LOADTL/3,ADJUST,13", "T0313"),
        ("TURRET/4", "T0404"),
        ("TURRET/4,6", "T0604"),
    ],
)
def test_the_lathe_t_word_is_station_and_offset(tmp_path: Path, load: str, t_word: str) -> None:
    text = f"PARTNO L\nUNITS/MM\n{load}\nFROM/50,60,0\nFEDRAT/0.1,MMPR\nGOTO/0,10,0\nFINI\n"
    status, tape, output = post(tmp_path, text, "fanuc-lathe")
    assert status == 0, output
    assert f"N1 {t_word}" in tape.splitlines()


def test_an_offset_beyond_two_digits_is_refused(tmp_path: Path) -> None:
    text = "PARTNO L\nLOADTL/3,ADJUST,100\nFINI\n"
    status, _, output = post(tmp_path, text, "fanuc-lathe")
    assert status == 2 and "ADJUST expects an offset number 0-99, found 100" in output


def test_the_manuals_machines_take_tool_lengths(tmp_path: Path) -> None:
    """Without option 263 LENGTH is the manual's tool-length correction (issue 22,
    tests/test_tools_manual.py): the run posts."""
    text = "PARTNO M\nLOADTL/1,LENGTH,5\nFROM/0,0,0\nFINI\n"
    status, _, output = post(tmp_path, text, "23")
    assert status == 0, output
