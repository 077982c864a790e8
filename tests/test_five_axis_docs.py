"""docs/five-axis.md's complete program is what `gecent post` writes today, and it passes
`gecent verify` (issue 21): the page is posted again block for block."""

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
PAGE = (ROOT / "docs" / "five-axis.md").read_text()
PROGRAMS = re.findall(r"<!-- program: (\S+) on (\S+) -->\n```\n(.*?)```", PAGE, flags=re.S)


def posted(tmp_path: Path, example: str, machine: str) -> Path:
    tape = tmp_path / "p.ngc"
    result = CliRunner().invoke(
        main, ["post", str(ROOT / example), "--machine", machine, "-o", str(tape)]
    )
    assert result.exit_code == 0, result.output
    return tape


def test_the_page_shows_a_program() -> None:
    assert [(example, machine) for example, machine, _ in PROGRAMS] == [
        ("examples/fiveaxis.apt", "fanuc-5axis-bc")
    ]


@pytest.mark.parametrize(("example", "machine", "text"), PROGRAMS)
def test_the_program_on_the_page_is_posted_as_shown(
    tmp_path: Path, example: str, machine: str, text: str
) -> None:
    assert posted(tmp_path, example, machine).read_text() == text


@pytest.mark.skipif(shutil.which("rs274") is None, reason="rs274 is not installed")
@pytest.mark.parametrize(("example", "machine", "text"), PROGRAMS)
def test_the_program_on_the_page_verifies(
    plugins: PluginSet, tmp_path: Path, example: str, machine: str, text: str
) -> None:
    tape = posted(tmp_path, example, machine)
    checked = verify(str(tape), str(ROOT / example), plugins, machine, 0.001)
    assert checked.passed, "\n".join(checked.report())
