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

from .conftest import MODERN_PACKS

ROOT = Path(__file__).parents[1]
PAGE = (ROOT / "docs" / "modern-controls.md").read_text()
PROGRAMS = re.findall(r"<!-- program: (\S+) on (\S+) -->\n```\n(.*?)```", PAGE, flags=re.S)


def test_the_page_shows_every_pack() -> None:
    assert {machine for _, machine, _ in PROGRAMS} == set(MODERN_PACKS)


@pytest.mark.parametrize(("example", "machine", "text"), PROGRAMS, ids=[p[1] for p in PROGRAMS])
def test_a_program_on_the_page_is_posted_as_shown(
    tmp_path: Path, example: str, machine: str, text: str
) -> None:
    assert posted(tmp_path, example, machine).read_text() == text
    if "mill" in machine or "840d" in machine:  # the mill job: contour, helix, holes
        words = set(re.findall(r"\b(G4[139]|G5[4]|G8[01]|G0?[23]|[HD]\d)\b", text))
        assert {"G43", "G41", "G49", "G54", "G81", "G80", "H1", "D1"} <= words


@pytest.mark.skipif(shutil.which("rs274") is None, reason="rs274 is not installed")
@pytest.mark.parametrize(("example", "machine", "text"), PROGRAMS, ids=[p[1] for p in PROGRAMS])
def test_a_program_on_the_page_verifies(
    plugins: PluginSet, tmp_path: Path, example: str, machine: str, text: str
) -> None:
    tape = posted(tmp_path, example, machine)
    checked = verify(str(tape), str(ROOT / example), plugins, machine, 0.001)
    assert checked.passed, "\n".join(checked.report())


def posted(tmp_path: Path, example: str, machine: str) -> Path:
    tape = tmp_path / "p.ngc"
    result = CliRunner().invoke(
        main, ["post", str(ROOT / example), "--machine", machine, "-o", str(tape)]
    )
    assert result.exit_code == 0, result.output
    return tape
