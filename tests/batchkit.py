"""What the gecent batch tests share: a batch run, its JSON summary, small CL programs."""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner, Result
from gecent.core.cli import main

from .conftest import SHARED

CORPUS = SHARED / "corpus"
HELLO = Path(__file__).resolve().parent.parent / "examples" / "hello.apt"
MILL = Path(__file__).resolve().parent.parent / "plugins" / "machines" / "linuxcnc-mill.toml"
PROGRAM = """PARTNO BATCH {name}
UNITS/MM
LOADTL/3
FROM/0,0,10
FEDRAT/{feed}
GOTO/10,0,0
GOTO/10,20,0
FINI
"""


def batch(*args: str) -> Result:
    return CliRunner().invoke(main, ["batch", "--no-progress", *args])


def summary(path: Path) -> list[dict[str, object]]:
    jobs: list[dict[str, object]] = json.loads(path.read_text())["jobs"]
    return jobs


def statuses(path: Path) -> list[str]:
    return [str(row["status"]) for row in summary(path)]


def programs(folder: Path, count: int = 3) -> list[Path]:
    folder.mkdir(parents=True, exist_ok=True)
    made = []
    for number in range(count):
        path = folder / f"part{number}.apt"
        path.write_text(PROGRAM.format(name=number, feed=100 + number))
        made.append(path)
    return made
