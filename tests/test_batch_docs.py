"""The batch run over the corpus that README.md and docs/batch.md show is what gecent prints
today: every column but the seconds, and the totals line up to its time."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main

from .conftest import SHARED

ROOT = Path(__file__).resolve().parent.parent
COMMAND = "gecent batch ../shared/corpus --machine linuxcnc-mill --verify"


def shown(document: Path) -> str:
    """The summary block after the batch command in ``document``."""
    text = document.read_text()
    found = re.search(r"<!-- batch-summary -->\n```\n(.*?)```", text, re.S)
    assert found is not None, f"{document.name} has no batch summary block"
    return found.group(1)


def comparable(summary: str) -> list[list[str]]:
    """Each row cut at the header's column starts, without the seconds column; the totals
    line without its time."""
    lines = summary.rstrip("\n").splitlines()
    header, rows, totals = lines[0], lines[1:-1], lines[-1]
    starts = [m.start() for m in re.finditer(r"(?:^|(?<=  ))\S", header)]
    bounds = list(zip(starts, [*starts[1:], None], strict=True))
    names = [header[a:b].strip() for a, b in bounds]
    cut = []
    for line in [header, *rows]:
        cells = [line[a:b].strip() for a, b in bounds]
        cut.append([cell for name, cell in zip(names, cells, strict=True) if name != "s"])
    cut.append([totals.split("; ")[0], totals.split("; ")[1]])
    return cut


@pytest.mark.skipif(not (SHARED / "corpus").is_dir(), reason="shared corpus not present")
@pytest.mark.skipif(shutil.which("rs274") is None, reason="rs274 (linuxcnc-uspace) not installed")
def test_the_documented_batch_summary_is_current(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(ROOT)
    args = [*COMMAND.split()[2:], "--out", str(tmp_path), "--no-progress"]
    result = CliRunner().invoke(main, ["batch", *args])
    assert result.exit_code == 1, result.output  # the corpus's two APT part programs
    today = comparable(result.output)
    for document in (ROOT / "README.md", ROOT / "docs" / "batch.md"):
        assert COMMAND in document.read_text(), document.name
        assert comparable(shown(document)) == today, document.name
