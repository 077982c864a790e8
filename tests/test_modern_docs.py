"""docs/modern-controls.md's complete programs are what `gecent post` writes today, and each
passes `gecent verify` (issue 16): the page is posted again block for block."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.plugins import PluginSet
from gecent.core.verify.check import verify

ROOT = Path(__file__).parents[1]
PAGE = (ROOT / "docs" / "modern-controls.md").read_text()
PROGRAMS = re.findall(r"<!-- program: (\S+) on (\S+) -->\n```\n(.*?)```", PAGE, flags=re.S)


def test_the_page_shows_every_pack() -> None:
    shown = {machine for _, machine, _ in PROGRAMS}
    assert shown == {
        "linuxcnc-mill",
        "linuxcnc-mill-inch",
        "fanuc-mill",
        "fanuc-lathe",
        "haas-mill",
        "sinumerik-840d-iso",
    }


@pytest.mark.parametrize(("example", "machine", "text"), PROGRAMS, ids=[p[1] for p in PROGRAMS])
def test_a_program_on_the_page_is_posted_as_shown(
    plugins: PluginSet, tmp_path: Path, example: str, machine: str, text: str
) -> None:
    tape = tmp_path / "p.ngc"
    result = CliRunner().invoke(
        main, ["post", str(ROOT / example), "--machine", machine, "-o", str(tape)]
    )
    assert result.exit_code == 0, result.output
    assert tape.read_text() == text
    if shutil.which("rs274") is None:
        pytest.skip("rs274 is not installed: the program is not verified")
    checked = verify(str(tape), str(ROOT / example), plugins, machine, 0.001)
    assert checked.passed, "\n".join(checked.report())
    if "mill" in machine or "840d" in machine:  # the mill job: contour, helix, holes
        words = set(re.findall(r"\b(G4[139]|G5[4]|G8[01]|G0?[23]|[HD]\d)\b", text))
        assert {"G43", "G41", "G49", "G54", "G81", "G80", "H1", "D1"} <= words
