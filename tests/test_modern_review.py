"""Issue 16's review: ordinary jobs a CNC programmer runs on the modern packs, each posted
and (where rs274 is here) verified: planes around cycles and compensation, compensation
sequencing, centres of split arcs, comment text, block numbers past N's digits, and CIRCLE
records that are not arcs."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.plugins import PluginSet
from gecent.core.verify.check import verify

needs_rs274 = pytest.mark.skipif(shutil.which("rs274") is None, reason="rs274 is not installed")
HEAD = "PARTNO JOB\n{machin}UNITS/MM\nLOADTL/1\nSPINDL/RPM,2000,CLW\nFROM/0,0,50\n"


def post(tmp_path: Path, body: str, machine: str | None = "linuxcnc-mill", machin: str = ""):
    source = tmp_path / "job.apt"
    source.write_text(HEAD.format(machin=machin + "\n" if machin else "") + body + "FINI\n")
    tape = tmp_path / "job.ngc"
    command = ["post", str(source), "-o", str(tape)]
    if machine is not None:
        command += ["--machine", machine]
    result = CliRunner().invoke(main, command)
    text = tape.read_text() if tape.exists() else ""
    return result.exit_code, text, result.output, source, tape


def verified(plugins: PluginSet, source: Path, tape: Path, machine: str | None) -> None:
    if shutil.which("rs274") is None:
        return
    result = verify(str(tape), str(source), plugins, machine, 0.001)
    assert result.passed, "\n".join(result.report())


def test_the_plane_is_xy_again_before_a_cycle_and_compensation(
    plugins: PluginSet, tmp_path: Path
) -> None:
    body = (
        "RAPID\nGOTO/10,0,5\nFEDRAT/300,MMPM\nCIRCLE/0,0,5,0,1,0,10\nGOTO/0,0,-5\n"
        "RAPID\nGOTO/30,30,5\nCYCLE/DRILL,DEPTH,10,MMPM,100,CLEAR,2\nGOTO/30,30,0\n"
        "CYCLE/OFF\nRAPID\nGOTO/0,-10,5\nGOTO/0,-10,-1\nCUTCOM/LEFT,XYPLAN\nGOTO/20,-10,-1\n"
        "CUTCOM/OFF\nRAPID\nGOTO/20,-10,50\n"
    )
    status, text, output, source, tape = post(tmp_path, body)
    assert status == 0, output
    lines = text.splitlines()
    g18 = next(i for i, line in enumerate(lines) if " G18" in line)
    g81 = next(i for i, line in enumerate(lines) if " G81 " in line)
    assert any(" G17" in line for line in lines[g18:g81])
    verified(plugins, source, tape, "linuxcnc-mill")


@needs_rs274
def test_compensation_sequencing_the_controls_accept(plugins: PluginSet, tmp_path: Path) -> None:
    """CUTCOM before the tool's first move (G43 H first), RIGHT while LEFT is on (G40
    between), a tool change under compensation (G40 first): rs274 takes the tape."""
    body = (
        "CUTCOM/RIGHT,5\nRAPID\nGOTO/0,0,5\nFEDRAT/300,MMPM\nGOTO/0,0,-1\nGOTO/20,0,-1\n"
        "CUTCOM/LEFT\nGOTO/20,20,-1\nLOADTL/2\nRAPID\nGOTO/20,20,50\nCUTCOM/OFF\n"
    )
    status, text, output, source, tape = post(tmp_path, body)
    assert status == 0, output
    assert "CUTCOM/LEFT WHILE RIGHT IS ON: G40 FIRST" in output
    assert "TOOL CHANGE WITH CUTCOM/LEFT ON: G40 FIRST" in output
    lines = text.splitlines()
    assert lines.index("N3 G43 H1") < lines.index("N4 G42 D5")
    verified(plugins, source, tape, "linuxcnc-mill")


@pytest.mark.parametrize("centres", ["252,1,253,0", "252,2", "252,2,253,0"])
def test_centres_of_split_and_absolute_arcs(
    plugins: PluginSet, tmp_path: Path, centres: str
) -> None:
    body = "RAPID\nGOTO/0.5,0,0\nFEDRAT/300,MMPM\nCIRCLE/0,0,0,0,0,1,0.5\nGOTO/-0.5,0,0\n"
    body += "CIRCLE/20,0,0,0,0,1,20.5\nGOTO/20,20.5,0\n"  # three quarters about (20, 0)
    status, text, output, source, tape = post(
        tmp_path, body, None, machin=f"MACHIN/GECENT,80,OPTAB,{centres}"
    )
    assert status == 0, output
    if centres.startswith("252,2"):
        assert "G90.1" in text
    verified(plugins, source, tape, None)


def test_a_percent_in_a_comment_is_not_punched(tmp_path: Path) -> None:
    status, text, _, _, _ = post(tmp_path, "PPRINT FEED 50% ON THE FINISH\n")
    assert status == 0 and "(FEED 50  ON THE FINISH)" in text
    assert text.count("%") == 2


def test_block_numbers_stop_rather_than_repeat(tmp_path: Path) -> None:
    """A pack whose N holds two digits: past N99 the blocks go on without N, warned."""
    pack = Path(__file__).parents[1] / "plugins" / "machines" / "linuxcnc-mill.toml"
    text = pack.read_text().replace('name = "linuxcnc-mill"', 'name = "short-n"')
    text = text.replace("number = 80 ", "number = 96 ").replace("1 = 50.0 ", "1 = 20.0 ")
    machine = tmp_path / "short-n.toml"
    machine.write_text(text)
    body = "FEDRAT/300,MMPM\n" + "".join(f"GOTO/{i},{i % 7},0\n" for i in range(150))
    status, tape, output, _, _ = post(tmp_path, body, str(machine))
    assert status == 0, output
    numbers = [int(n) for n in re.findall(r"^N(\d+) ", tape, flags=re.M)]
    assert numbers == list(range(1, 100))
    assert "BLOCK NUMBERS PASS N99: THE REST OF THE PROGRAM HAS NO N WORDS" in output
    assert len(tape.splitlines()) > 150


def test_chords_are_bounded_like_segments(tmp_path: Path) -> None:
    body = "RAPID\nGOTO/100,0,0\nFEDRAT/300,MMPM\nCIRCLE/0,0,0,0,0,1,100\nGOTO/100,0,0\n"
    status, _, output, _, _ = post(tmp_path, body, None, "MACHIN/GECENT,80,OPTAB,262,0.00000001")
    assert status == 2 and "--max-segments" in output and "job.apt:" in output


@pytest.mark.parametrize(
    ("circle", "end", "status", "message"),
    [
        ("CIRCLE/0,0,0,0,0,1,5", "GOTO/0,3,0", 2, "the arc ends 2 off its circle"),
        ("CIRCLE/0,0,0,0,0,0,5", "GOTO/0,5,0", 2, "CIRCLE has no axis"),
        ("CIRCLE/0,0,0,0,0,1,-5", "GOTO/0,5,0", 2, "CIRCLE radius must be more than 0"),
    ],
    ids=["end off", "no axis", "negative radius"],  # (tilted: built, test_modern_forms_wave9)
)
def test_a_circle_record_that_is_no_arc_is_refused(
    tmp_path: Path, circle: str, end: str, status: int, message: str
) -> None:
    body = f"RAPID\nGOTO/5,0,0\nFEDRAT/300,MMPM\n{circle}\n{end}\n"
    found, _, output, _, _ = post(tmp_path, body)
    assert found == status and message in output and "job.apt:" in output, output


def test_the_lathe_tool_list_names_t_codes(tmp_path: Path) -> None:
    body = "FEDRAT/0.1,MMPR\nGOTO/0,10,0\nLOADTL/101\nGOTO/0,12,0\nTURRET/4,6\nGOTO/0,14,0\n"
    status, text, output, _, _ = post(tmp_path, body, "fanuc-lathe")
    assert status == 0, output
    assert [line for line in text.splitlines() if line.startswith("(T")] == ["(T0101)", "(T0604)"]
