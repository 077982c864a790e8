"""A third-party machine pack, installed with pip into a fresh virtual environment, shows
up in ``gecent --list-plugins`` and ``gecent machines`` with no change to gecent."""

from __future__ import annotations

import json
import os
import subprocess
import venv
from pathlib import Path

import pytest

from .conftest import ROOT

PACK = ROOT / "examples" / "packs" / "acme-mill"


@pytest.mark.slow
def test_acme_pack_in_a_fresh_virtual_environment(tmp_path: Path) -> None:
    env_dir = tmp_path / "venv"
    venv.EnvBuilder(with_pip=True).create(env_dir)
    bindir = env_dir / ("Scripts" if os.name == "nt" else "bin")
    python = bindir / "python"
    environment = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}
    subprocess.run(
        [
            str(python),
            "-m",
            "pip",
            "install",
            "--quiet",
            "--disable-pip-version-check",
            str(ROOT),
            str(PACK),
        ],
        check=True,
        env=environment,
        cwd=tmp_path,
    )
    gecent = [str(bindir / "gecent")]
    listed = subprocess.run(
        [*gecent, "--list-plugins", "--json"],
        capture_output=True,
        text=True,
        check=True,
        env=environment,
        cwd=tmp_path,
    )
    data = json.loads(listed.stdout)
    acme = {(r["family"], r["id"]): r for r in data["plugins"] if r["distribution"] == "acme-mill"}
    assert set(acme) == {
        ("machines", "acme-vmc1"),
        ("macfuns", "acme-vmc1"),
        ("macros", "acme-vmc1:tool_change"),
        ("macros", "acme-vmc1:stage_next_tool"),
        ("macros", "acme-vmc1:operation_header"),
    }
    assert acme[("machines", "acme-vmc1")]["module"] == "acme_mill.machine"
    assert data["failures"] == []
    machines = subprocess.run(
        [*gecent, "machines"],
        capture_output=True,
        text=True,
        check=True,
        env=environment,
        cwd=tmp_path,
    )
    assert any(line.split()[:2] == ["77", "acme-vmc1"] for line in machines.stdout.splitlines())
    shown = subprocess.run(
        [*gecent, "machine", "show", "77"],
        capture_output=True,
        text=True,
        check=True,
        env=environment,
        cwd=tmp_path,
    )
    assert "ACME VMC-1 MILL" in shown.stdout
    program = tmp_path / "two_tools.apt"
    program.write_text(
        "PARTNO ACME\nFROM/0,0,10\nLOADTL/1\nSPINDL/1350,CLW\nFEDRAT/10\nGOTO/1,0,0\n"
        "LOADTL/2\nSPINDL/900,CLW\nGOTO/2,0,0\nFINI\n"
    )
    subprocess.run(
        [*gecent, "post", str(program), "--machine", "acme-vmc1", "-o", str(tmp_path / "t.tape")],
        check=True,
        env=environment,
        cwd=tmp_path,
    )
    tape = (tmp_path / "t.tape").read_text().splitlines()
    assert tape.count("G53Z0") == 2 and tape.count("T2") == 1  # the pack's macros ran
