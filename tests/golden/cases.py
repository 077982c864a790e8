"""The posts whose outputs must not change unless a documented fix changes them: every
corpus file and example program on the manual's machines and every modern pack, each with
tape, listing, punch and JSON lines. Shared by the test and by ``make_outputs.py``, which
records the outputs of a given commit."""

from __future__ import annotations

import hashlib
import os
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SHARED = ROOT.parent / "shared"
MANUAL = ["23", "4", "24", "standard"]
MODERN = ["linuxcnc-mill", "linuxcnc-mill-inch", "fanuc-mill", "fanuc-lathe"]


def inputs() -> list[str]:
    """Project-relative paths of the inputs (the corpus may be absent: the test skips)."""
    corpus = SHARED / "corpus"
    found = [
        *sorted(corpus.glob("creo/*.ncl.[0-9]")),
        *sorted(corpus.glob("apt4/*.apt")),
        *sorted(corpus.glob("apt4/*.cl3")),
        *sorted(corpus.glob("solidworks-cam/*.apt")),
        *sorted((ROOT / "examples").glob("*.apt")),
    ]
    return [str(Path("..") / p.relative_to(ROOT.parent)) if SHARED in p.parents
            else str(p.relative_to(ROOT)) for p in found]  # fmt: skip


def cases() -> list[tuple[str, str | None]]:
    """(input, machine) pairs; None: the machine the file's MACHIN names (examples)."""
    pairs: list[tuple[str, str | None]] = []
    for source in inputs():
        for machine in MANUAL + MODERN:
            pairs.append((source, machine))
        if source.startswith("examples/"):
            pairs.append((source, None))
    return pairs


def case_id(source: str, machine: str | None) -> str:
    return f"{Path(source).name}@{machine or 'MACHIN'}"


def _digest(data: bytes | None) -> str | None:
    return None if data is None else hashlib.sha256(data).hexdigest()


def run_case(source: str, machine: str | None) -> dict[str, object]:
    """Post one case through the command line in-process; what it wrote, as hashes."""
    from click.testing import CliRunner
    from gecent.core.cli import main

    code = "ascii" if machine in MODERN else "eia"
    with tempfile.TemporaryDirectory() as folder, _in(ROOT):
        out = Path(folder)
        # the input by its project-relative path: a GEDUMP names it, wherever the clone is
        arguments = ["post", source, "-o", str(out / "t.tape")]
        arguments += ["--listing", str(out / "t.lis"), "--punch", code, str(out / "t.pun")]
        arguments += ["--json"]
        if machine is not None:
            arguments += ["--machine", machine]
        result = CliRunner().invoke(main, arguments)
        stderr = result.stderr.replace(str(ROOT) + "/", "").replace(folder, "<out>")
        outputs: dict[str, object] = {
            "exit": result.exit_code,
            "stdout": _digest(result.stdout.encode("utf-8")),
            "stderr": stderr.splitlines(),
        }
        for name in ("t.tape", "t.lis", "t.pun"):
            path = out / name
            outputs[name] = _digest(path.read_bytes() if path.exists() else None)
    return outputs


@contextmanager
def _in(folder: Path) -> Iterator[None]:
    before = os.getcwd()
    os.chdir(folder)
    try:
        yield
    finally:
        os.chdir(before)
