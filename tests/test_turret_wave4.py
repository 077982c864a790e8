"""TURRET/..., NOW|NEXT on an absolute control (option 251 = 1: fanuc-lathe) and on a
multiaxis machine (issue 22, wave 4; docs/decisions.md "Turret NOW/NEXT, wave 4")."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.plugins import PluginSet
from gecent.core.verify.check import verify

# tool 1 at (a, b) = (2, 3) cuts to the face (Z0, diameter 40), tool 2 (2.5, 1) is indexed
# with NOW there, tool 3 (4, 5) with NEXT
LATHE_PROGRAM = """PARTNO TURRET ABS
MACHIN / GECENT, 83, OPTAB, 106, 8
UNITS / MM
FROM / 50, 60, 0
TURRET / 1, 1, 2, 3
SPINDL / RPM, 1200, CLW
FEDRAT / 0.15, MMPR
GOTO / 0, 20, 0
TURRET / 2, 2, 2.5, 1, NOW
GOTO / -20, 20, 0
TURRET / 3, 3, 4, 5, NEXT
GOTO / -30, 25, 0
FINI
"""


def post(tmp_path: Path, text: str, machine: str) -> tuple[int, str, Path, Path]:
    source = tmp_path / "t.apt"
    source.write_text(text)
    tape, listing = tmp_path / "t.ngc", tmp_path / "t.lis"
    command = ["post", str(source), "--machine", machine, "-o", str(tape)]
    result = CliRunner().invoke(main, [*command, "--listing", str(listing)])
    return result.exit_code, result.output, tape, source


def test_now_on_an_absolute_control_moves_to_the_same_tool_point(tmp_path: Path) -> None:
    """The control's positions are the new tool's point once T0202 has called its offset:
    the corrective move states every axis at the point the tool is at (Z0 kept), and the
    turret centre moves by the correction."""
    code, output, tape, _ = post(tmp_path, LATHE_PROGRAM, "fanuc-lathe")
    assert code == 0, output
    lines = tape.read_text().splitlines()
    change = lines.index("N5 T0202")
    assert lines[change - 1] == "N4 G01 X40. Z0. F0.15"
    assert lines[change + 1] == "N6 G01 X40. Z0."  # the correction: same point, both axes
    assert lines[change + 2] == "N7 Z-20."
    listing = (tmp_path / "t.lis").read_text().splitlines()
    correction = next(line for line in listing if line.startswith("      6 "))
    assert "+00020.000     +00000.000" in correction  # the Absolute print does not move


def test_next_on_an_absolute_control_states_the_tool_point(tmp_path: Path) -> None:
    """NEXT: the next move's departure carries the correction, its absolute words are the
    tool's point (X is a diameter: CL y 25 is X50)."""
    code, output, tape, _ = post(tmp_path, LATHE_PROGRAM, "fanuc-lathe")
    assert code == 0, output
    lines = tape.read_text().splitlines()
    assert lines[lines.index("N8 T0303") + 1] == "N9 G01 X50. Z-30."


@pytest.mark.skipif(shutil.which("rs274") is None, reason="rs274 is not installed")
def test_a_corrected_absolute_tape_verifies(plugins: PluginSet, tmp_path: Path) -> None:
    code, output, tape, source = post(tmp_path, LATHE_PROGRAM, "fanuc-lathe")
    assert code == 0, output
    result = verify(str(tape), str(source), plugins, None, 0.001)
    assert result.passed, "\n".join(result.report())


def test_a_correction_on_a_multiaxis_machine_is_bad_input(tmp_path: Path) -> None:
    """The turret's corrective move is the lathe's (GELATH); a multiaxis machine is a mill
    (GEMAXS), 001 L1244-1250, L1598-1604."""
    text = (
        "PARTNO T\nMACHIN/GECENT,86,OPTAB,106,8\nUNITS/MM\nFROM/0,0,10\nFEDRAT/10\n"
        "TURRET/1,1,2,3\nGOTO/1,1,10\nTURRET/2,2,2.5,1,NOW\nGOTO/2,1,10\nFINI\n"
    )
    code, output, _, _ = post(tmp_path, text, "linuxcnc-5axis-ac")
    assert code == 2
    assert "t.apt:8" in output and "multiaxis machine" in output and "GELATH" in output


def test_without_now_the_absolute_lathe_has_no_correction(tmp_path: Path) -> None:
    """The same program without NOW: no block between T0202 and the next move."""
    code, output, tape, _ = post(tmp_path, LATHE_PROGRAM.replace(", NOW", ""), "fanuc-lathe")
    assert code == 0, output
    lines = tape.read_text().splitlines()
    assert lines[lines.index("N5 T0202") + 1] == "N6 G01 X40. Z-20."
