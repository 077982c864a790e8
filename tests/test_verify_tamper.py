"""`gecent verify` cannot be fooled (issue 16 review): a correct tape of the documented job
passes, and each hand edit that makes it not do what the CL file says fails, naming why."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.plugins import PluginSet
from gecent.core.verify.check import verify

pytestmark = pytest.mark.skipif(shutil.which("rs274") is None, reason="rs274 is not installed")
ROOT = Path(__file__).parents[1]
POCKET = ROOT / "examples" / "pocket_mill.apt"


@pytest.fixture(scope="module")
def tape(tmp_path_factory: pytest.TempPathFactory) -> str:
    out = tmp_path_factory.mktemp("pocket") / "p.ngc"
    command = ["post", str(POCKET), "--machine", "linuxcnc-mill", "-o", str(out)]
    result = CliRunner().invoke(main, command)
    assert result.exit_code == 0, result.output
    return out.read_text()


def checked(plugins: PluginSet, tmp_path: Path, text: str) -> str:
    edited = tmp_path / "edited.ngc"
    edited.write_text(text)
    result = verify(str(edited), str(POCKET), plugins, "linuxcnc-mill", 0.001)
    report = "\n".join(result.report())
    assert result.passed == ("verify: passed" in report)
    return report


def test_the_tape_as_posted_passes(plugins: PluginSet, tmp_path: Path, tape: str) -> None:
    assert "verify: passed" in checked(plugins, tmp_path, tape)


@pytest.mark.parametrize(
    ("old", "new", "reason"),
    [
        ("N21 T02 M06", "N21 T01 M06", "tool T1 cuts where the CL has loaded T2"),
        ("Z5. H1\n", "Z5. H2\n", "H2 where the tool's offset number is 1"),
        ("G00 G43 X-20. Y-20. Z5. H1", "G00 X-20. Y-20. Z5.", "compensation (G43) is off"),
        ("N6 G41 D1", "N6 G41 D2", "D2 where the CL's compensation is D1"),
        ("N6 G41 D1", "N6 G42 D1", "cutter compensation right where the CL has left"),
        ("N22 S1200 M03", "N22 S1200", "the spindle is stopped where the CL cuts"),
        ("N2 S3000 M03", "N2 S3000 M04", "the spindle turns the other way"),
        ("G17 G21 G90", "G17 G20 G90", "the tape is in inches (G20)"),
        (
            "N14 G00 Z10.",
            "N14 G00 Z-50.\nN14 G00 Z10.",
            "a rapid move to Z -50.0000, outside the way",
        ),
        ("N19 X70. Y20. I-10.", "N19 X70. Y20. I-10. P3", "the arc turns 3 times"),
        ("N9 G03 X100. Y0. J20.", "N9 G02 X100. Y0. J20.", "the arc turns the wrong way"),
        ("N9 G03 X100. Y0. J20.", "N9 G03 X100. Y0. J20.003", "arc centre"),
        ("N26 X90. Y10.\n", "", "the tape ends before this point"),
    ],
    ids=[
        "tool",
        "H",
        "no G43",
        "D",
        "G42",
        "spindle stopped",
        "M04",
        "G20",
        "rapid dip",
        "P turns",
        "G02",
        "centre",
        "hole dropped",
    ],
)
def test_an_edit_fails(
    plugins: PluginSet, tmp_path: Path, tape: str, old: str, new: str, reason: str
) -> None:
    assert old in tape
    report = checked(plugins, tmp_path, tape.replace(old, new, 1))
    assert "FAILED" in report and reason in report, report


def test_chords_must_stay_within_their_tolerance(plugins: PluginSet, tmp_path: Path) -> None:
    """Option 262 = 0.01: the chords pass; one straight cut for the whole arc fails."""
    source = tmp_path / "c.apt"
    source.write_text(
        "PARTNO C\nMACHIN/GECENT,80,OPTAB,262,0.01\nUNITS/MM\nLOADTL/1\n"
        "SPINDL/RPM,1000,CLW\nFROM/0,0,50\nRAPID\nGOTO/100,0,-1\nFEDRAT/300,MMPM\n"
        "CIRCLE/0,0,-1,0,0,1,100\nGOTO/0,100,-1\nFINI\n"
    )
    tape = tmp_path / "c.ngc"
    command = ["post", str(source), "--machine", "linuxcnc-mill", "-o", str(tape)]
    assert CliRunner().invoke(main, command).exit_code == 0
    result = verify(str(tape), str(source), plugins, "linuxcnc-mill", 0.001)
    assert result.passed, "\n".join(result.report())
    lines = tape.read_text().splitlines()
    first = next(i for i, line in enumerate(lines) if " G01 " in line)
    last = next(i for i, line in enumerate(lines) if "X0. Y100." in line)
    tape.write_text("\n".join([*lines[:first], "N5 G01 X0. Y100. F300.", *lines[last + 1 :]]))
    result = verify(str(tape), str(source), plugins, "linuxcnc-mill", 0.001)
    assert not result.passed
    assert "falls 29.2893 inside it" in "\n".join(result.report())
