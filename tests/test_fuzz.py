"""Property-based hardening (issue 17): mutated CL text, binary CL and machine files posted on
the installed machines never crash, hang or run away. For every case:

* the exit status is 0, 1 (a fatal error of the manual), 2 (bad input) or 3 (not yet
  supported), never 70 (a bug) or a traceback;
* every error message begins with the file it is about and, for a CL text file, its line
  (``FILE:LINE``; a binary CL file names its record and byte offset, a machine file its
  table and entry);
* a failed run leaves no tape; a run that succeeds writes the same tape again.

CI runs a bounded number of cases; ``GECENT_FUZZ_EXAMPLES=7000 pytest tests/test_fuzz.py``
runs the long campaign (three kinds of input: 21,000 cases). Each case has 20 seconds.
"""

from __future__ import annotations

import os
import re
import signal
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest
from click.testing import CliRunner, Result
from gecent.core import run as run_module
from gecent.core.cli import main
from gecent.core.plugins import get_plugins
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from .conftest import ROOT, SHARED

EXAMPLES = int(os.environ.get("GECENT_FUZZ_EXAMPLES", "40"))
SECONDS = 20
MACHINES = sorted(pack.name for pack in get_plugins().machines())  # every installed machine
TEXT_SEEDS = [
    *(ROOT / "examples").glob("*.apt"),
    *(SHARED / "corpus" / "creo").glob("*.ncl.*"),
    *(SHARED / "corpus" / "solidworks-cam").glob("*.apt"),
]
BINARY_SEEDS = sorted((SHARED / "corpus" / "apt4").glob("*.cl3"))
MACHINE_SEEDS = [
    ROOT / "plugins" / "machines" / name
    for name in ("linuxcnc-mill.toml", "mach23.toml", "mach04.toml", "fanuc-lathe.toml")
]
EXTREMES = [
    "1e300", "-1e300", "inf", "-inf", "nan", "1e999", "-0", "0", "0.0", "1e-300",
    "123456789012", "-5", "99999999", "1.5", "-2.75", "4e7", "0.00001",
]  # fmt: skip
WORDS = [
    "GOTO", "FROM", "GODLTA", "CIRCLE", "CYCLE", "RAPID", "FEDRAT", "SPINDL", "LOADTL",
    "CUTCOM", "MACHIN", "UNITS", "SEQNO", "TRANS", "INTOL", "OUTTOL", "CUTTER", "END",
    "FINI", "ON", "OFF", "LEFT", "RIGHT", "CLW", "CCLW", "MMPM", "IPM", "MMPR", "RPM",
    "OPTAB", "GECENT", "DEEP", "DRILL", "TAP", "DEPTH", "STEP", "CLEAR", "COOLNT",
    "DELAY", "PPRINT", "INSERT", "PARTNO", "MULTAX", "THREAD", "PITCH", "TURRET",
    "SELECT", "OPSKIP", "STOP", "TMARK", "LEADER", "ROTATE", "XYPLAN", "MM", "INCHES",
]  # fmt: skip
NUMBER = re.compile(rb"-?\d+\.?\d*(?:[eE][-+]?\d+)?")
MACHINE_FILE = re.compile(r"^\S+\.toml(:\d+(:\d+)?)?: error: ")


class CaseTimeout(BaseException):
    """A case ran past its time: a hang (a BaseException, so nothing inside catches it)."""


@contextmanager
def time_limit(seconds: int) -> Iterator[None]:
    def stop(signum: int, frame: object) -> None:
        raise CaseTimeout(f"no result after {seconds} s")

    previous = signal.signal(signal.SIGALRM, stop)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)


def seed_text(path: Path, lines: int = 80) -> bytes:
    """A seed's first lines, with a FINI: long corpus files are cut to keep cases quick."""
    data = path.read_bytes().splitlines(keepends=True)
    head = b"".join(data[:lines])
    return head if len(data) <= lines else head + b"FINI\n"


@st.composite
def mutated_lines(draw: st.DrawFn, seed: bytes) -> bytes:
    lines = seed.splitlines(keepends=True) or [b"\n"]
    for _ in range(draw(st.integers(1, 6))):
        index = draw(st.integers(0, max(0, len(lines) - 1)))
        kind = draw(st.sampled_from(["number", "word", "delete", "copy", "bytes", "new", "cut"]))
        line = lines[index] if lines else b""
        if kind == "number" and NUMBER.search(line):
            found = list(NUMBER.finditer(line))
            target = found[draw(st.integers(0, len(found) - 1))]
            value = draw(st.sampled_from(EXTREMES)).encode()
            lines[index] = line[: target.start()] + value + line[target.end() :]
        elif kind == "word":
            words = re.split(rb"([/,\s])", line)
            spot = draw(st.integers(0, max(0, len(words) - 1)))
            words[spot] = draw(st.sampled_from(WORDS)).encode()
            lines[index] = b"".join(words)
        elif kind == "delete" and len(lines) > 1:
            del lines[index]
        elif kind == "copy":
            lines.insert(index, line * draw(st.integers(1, 3)))
        elif kind == "bytes":
            noise = draw(st.binary(min_size=1, max_size=6))
            at = draw(st.integers(0, len(line)))
            lines[index] = line[:at] + noise + line[at:]
        elif kind == "new":
            major = draw(st.sampled_from(WORDS))
            args = draw(st.lists(st.sampled_from(EXTREMES + WORDS), min_size=0, max_size=8))
            end = b" $\n" if draw(st.booleans()) and len(args) > 2 else b"\n"
            lines.insert(index, (major + "/" + ",".join(args)).encode() + end)
        elif kind == "cut":
            lines = lines[: index + 1]
    return b"".join(lines)


@st.composite
def mutated_bytes(draw: st.DrawFn, seed: bytes) -> bytes:
    data = bytearray(seed)
    for _ in range(draw(st.integers(1, 8))):
        if not data:
            break
        at = draw(st.integers(0, len(data) - 1))
        kind = draw(st.sampled_from(["flip", "double", "cut", "copy", "zero"]))
        if kind == "flip":
            data[at] ^= 1 << draw(st.integers(0, 7))
        elif kind == "double":
            value = draw(
                st.sampled_from([b"\x7f\xf0\x00\x00\x00\x00\x00\x00", b"\x7f\xf8" + bytes(6)])
            )
            data[at : at + 8] = value[::-1] if draw(st.booleans()) else value
        elif kind == "cut":
            del data[at:]
        elif kind == "copy":
            data[at:at] = data[at : at + draw(st.integers(1, 64))]
        else:
            data[at : at + 4] = b"\xff\xff\xff\x7f" if draw(st.booleans()) else bytes(4)
    return bytes(data)


def post(tmp_path: Path, source: Path, machine: str) -> tuple[Result, Path]:
    tape = tmp_path / "out" / "t.tape"
    tape.parent.mkdir(exist_ok=True)
    for old in tape.parent.iterdir():
        old.unlink()
    arguments = ["post", str(source), "--machine", machine, "-o", str(tape)]
    arguments += ["--listing", str(tape.with_suffix(".lis")), "--max-segments", "5000"]
    with time_limit(SECONDS):
        result = CliRunner().invoke(main, arguments)
    return result, tape


def check(tmp_path: Path, source: Path, machine: str, named: Path) -> None:
    """The properties of one case; ``named``: the file whose errors must name it."""
    result, tape = post(tmp_path, source, machine)
    output = result.output + (result.stderr if result.stderr_bytes is not None else "")
    assert not isinstance(result.exception, CaseTimeout), f"hang: {source} on {machine}"
    assert result.exit_code in (0, 1, 2, 3), f"exit {result.exit_code}:\n{output}"
    assert "Traceback" not in output and "internal error" not in output, output
    for line in result.stderr.splitlines():
        if " error: " in f" {line}" and "warning" not in line:
            if MACHINE_FILE.match(line):
                continue  # what the machine itself cannot do names the machine's file
            assert line.startswith(str(named)), f"an error that names no file: {line!r}"
            if named.suffix != ".toml" and line.startswith(f"{named}:") is False:
                raise AssertionError(f"an error that names no line or record: {line!r}")
    if result.exit_code != 0:
        assert not tape.exists(), f"a tape after a failed run (exit {result.exit_code})"
        return
    first = tape.read_bytes()
    again, tape = post(tmp_path, source, machine)
    assert again.exit_code == 0 and tape.read_bytes() == first, "a rerun made another tape"


FUZZ = settings(
    max_examples=EXAMPLES,
    deadline=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
    derandomize=EXAMPLES <= 100,  # CI: the same cases every run
)


@FUZZ
@given(st.data())
def test_mutated_cl_text(tmp_path: Path, data: st.DataObject) -> None:
    seed = data.draw(st.sampled_from(TEXT_SEEDS), label="seed")
    text = data.draw(mutated_lines(seed_text(seed)), label="text")
    machine = data.draw(st.sampled_from(MACHINES), label="machine")
    source = tmp_path / "case.apt"
    source.write_bytes(text)
    check(tmp_path, source, machine, source)


@pytest.mark.skipif(not BINARY_SEEDS, reason="the shared corpus is not here")
@FUZZ
@given(st.data())
def test_mutated_binary_cl(tmp_path: Path, data: st.DataObject) -> None:
    seed = data.draw(st.sampled_from(BINARY_SEEDS), label="seed")
    blob = data.draw(mutated_bytes(seed.read_bytes()), label="bytes")
    machine = data.draw(st.sampled_from(MACHINES), label="machine")
    source = tmp_path / "case.cl3"
    source.write_bytes(blob)
    check(tmp_path, source, machine, source)


@FUZZ
@given(st.data())
def test_mutated_machine_file(tmp_path: Path, data: st.DataObject) -> None:
    seed = data.draw(st.sampled_from(MACHINE_SEEDS), label="seed")
    text = data.draw(mutated_lines(seed.read_bytes()), label="machine")
    machine = tmp_path / "fuzz.toml"
    machine.write_bytes(text)
    example = data.draw(st.sampled_from(sorted((ROOT / "examples").glob("*.apt"))))
    result, tape = post(tmp_path, example, str(machine))
    output = result.output
    assert not isinstance(result.exception, CaseTimeout), "hang"
    assert result.exit_code in (0, 1, 2, 3), f"exit {result.exit_code}:\n{output}"
    assert "Traceback" not in output and "internal error" not in output, output
    for line in result.stderr.splitlines():
        if line.startswith("error") or " error: " in line:
            assert line.startswith((str(machine), str(example))), f"no file named: {line!r}"
    if result.exit_code != 0:
        assert not tape.exists()


def test_an_internal_error_is_exit_70_with_the_record(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A bug (here a handler that divides by zero) is never bad input: exit 70, the record
    being posted, and a request for a report."""

    def broken(run: object, statement: object) -> None:
        raise ZeroDivisionError("division by zero")

    source = ROOT / "examples" / "hello.apt"
    original = run_module.handlers

    def patched() -> dict[str, object]:
        table = dict(original())
        table["FEDRAT"] = broken
        return table

    monkeypatch.setattr(run_module, "handlers", patched)
    result = CliRunner().invoke(main, ["post", str(source), "-o", str(tmp_path / "t.tape")])
    assert result.exit_code == 70
    assert f"{source}:8 (record 8): gecent: internal error: ZeroDivisionError" in result.stderr
    assert "please report it" in result.stderr
    assert not (tmp_path / "t.tape").exists()
