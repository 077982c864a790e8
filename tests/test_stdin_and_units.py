"""`gecent post -` reads the CL file from standard input; a modern pack warns when the CL
file states no UNITS before its first move (issue 16)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).parents[1]
HELLO = ROOT / "examples" / "hello.apt"


def gecent(*arguments: str, cwd: Path, stdin: bytes = b"") -> subprocess.CompletedProcess[bytes]:
    return subprocess.run(
        [sys.executable, "-m", "gecent.core.cli", *arguments],
        input=stdin,
        capture_output=True,
        cwd=cwd,
        env={**os.environ, "PYTHONPATH": os.environ.get("PYTHONPATH", "")},
        check=False,
    )


def test_post_reads_standard_input_like_a_file(tmp_path: Path) -> None:
    named = gecent("post", str(HELLO), "--machine", "linuxcnc-mill", "-o", "a.ngc", cwd=tmp_path)
    piped = gecent(
        "post", "-", "--machine", "linuxcnc-mill", "-o", "b.ngc",
        cwd=tmp_path, stdin=HELLO.read_bytes(),
    )  # fmt: skip
    assert named.returncode == piped.returncode == 0, piped.stderr
    assert (tmp_path / "a.ngc").read_bytes() == (tmp_path / "b.ngc").read_bytes()
    # its warnings name it "-", and nothing of the spool is left
    assert piped.stderr.decode().startswith("-:4 (record 4): warning: MACHIN/GECENT,23")


def test_standard_input_without_o_is_stdin_tape_and_errors_name_it(tmp_path: Path) -> None:
    done = gecent("post", "-", cwd=tmp_path, stdin=HELLO.read_bytes())
    assert done.returncode == 0, done.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["stdin.lis", "stdin.tape"]
    bad = gecent(
        "post", "-", "--machine", "23", "-o", "x.tape",
        cwd=tmp_path, stdin=b"PARTNO X\nGOTO/1,2\nFINI\n",
    )  # fmt: skip
    assert bad.returncode == 2
    assert bad.stderr.decode().startswith("-:2:1: error: GOTO takes 3 or 6 values, found 2")
    assert not (tmp_path / "x.tape").exists()


def test_a_modern_pack_warns_of_a_cl_file_without_units(tmp_path: Path) -> None:
    source = tmp_path / "p.apt"
    source.write_text("PARTNO P\nFROM/0,0,1\nFEDRAT/10\nGOTO/1,2,0\nGOTO/1,3,0\nFINI\n")
    done = gecent(
        "post", str(source), "--machine", "linuxcnc-mill-inch", "-o", "p.ngc", cwd=tmp_path
    )
    assert done.returncode == 0
    lines = done.stderr.decode().splitlines()
    assert lines == [
        f"{source}:2 (record 2): warning: NO UNITS STATEMENT BEFORE THE FIRST MOVE: THE CL "
        "FILE IS TAKEN IN INCHES, THE MACHINE'S UNIT"
    ]
    source.write_text("PARTNO P\nUNITS/INCHES\nFROM/0,0,1\nFEDRAT/10\nGOTO/1,2,0\nFINI\n")
    done = gecent(
        "post", str(source), "--machine", "linuxcnc-mill-inch", "-o", "p.ngc", cwd=tmp_path
    )
    assert done.returncode == 0 and done.stderr == b""
    # the manual's machines take the CL in their unit, as in 1970, without a word
    source.write_text("PARTNO P\nFROM/0,0,1\nFEDRAT/10\nGOTO/1,2,0\nFINI\n")
    done = gecent("post", str(source), "--machine", "23", cwd=tmp_path)
    assert done.returncode == 0 and b"NO UNITS" not in done.stderr
