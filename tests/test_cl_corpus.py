"""Real CL files nobody here wrote: the Creo text CL and the APT IV binary CL files.

Each apt4 ``.cl3`` must decode to exactly what the APT processor's own CL print (CLPRNT,
in the ``.lis`` beside it) shows: record number, ISN, major word, words, numbers, text,
surface names and every point, at the printed precision.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass, field, replace
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cl.apt_source import read_apt_source
from gecent.core.cl.binary_reader import read_binary
from gecent.core.cl.clprint import ARELEM_NAMES
from gecent.core.cl.records import (
    Arelem,
    Circle,
    Fini,
    Motion,
    MotionSubtype,
    Record,
    Statement,
    Word,
)
from gecent.core.cli import main

from .conftest import SHARED

CREO = SHARED / "corpus" / "creo"
APT4 = SHARED / "corpus" / "apt4"
WITH_CLPRNT = ["test2_contour_tlrgt", "test2d_finetol", "test3_ppwords"]

needs_corpus = pytest.mark.skipif(not APT4.is_dir(), reason="shared corpus not present")


@dataclass
class Entry:
    tapeno: int
    isn: int
    header: str = ""
    points: list[list[str]] = field(default_factory=list)


_NUMBERS = re.compile(r"^\s*-?\d+\.\d+(\s+-?\d+\.\d+)*\s*$")
_TAPENO = re.compile(r"^[0 ]\s*(\d+)/\s*(\d+)(.*)$")


def clprint_entries(lis: Path) -> dict[int, Entry]:
    """The CL print section of an APT IV listing, keyed by TAPENO (the CL record number)."""
    lines = lis.read_text().splitlines()
    start = next(i for i, line in enumerate(lines) if "START CLEDITOR" in line)
    end = next(i for i, line in enumerate(lines) if "END   CLEDITOR" in line)
    entries: dict[int, Entry] = {}
    current: Entry | None = None
    for line in lines[start + 1 : end]:
        match = _TAPENO.match(line)
        if match:
            tapeno, isn, rest = int(match[1]), int(match[2]), match[3]
            if rest.split() == ["X", "Y", "Z"]:
                continue
            current = entries.setdefault(tapeno, Entry(tapeno, isn))
            if _NUMBERS.match(rest):
                current.points.append(rest.split())
            else:
                current.header = rest.strip()
        elif _NUMBERS.match(line):
            assert current is not None
            current.points.append(line.split())
    return entries


def _number(text: str) -> str:
    return text.strip()


def _check_statement(record: Statement, header: str) -> None:
    if record.text is not None:
        major, _, text = header.partition(" ")
        assert major == record.major
        assert text.strip() == record.text
        return
    major, slash, rest = header.partition("/")
    assert major.strip() == record.major
    shown = [item.strip() for item in rest.split(",")] if slash else []
    ours = [a.name if isinstance(a, Word) else f"{a:.4f}" for a in record.args]
    assert shown == ours


def _check_arelem(record: Arelem, header: str) -> None:
    major, _, rest = header.partition("/")
    assert major.strip() == ARELEM_NAMES[record.subtype]
    assert [v.strip() for v in rest.split(",")] == [f"{v:.4f}" for v in record.values]


def _check_points(record: Motion, entry: Entry) -> None:
    ours = [[f"{v:.7f}" for v in point] for point in record.points]
    assert entry.points == ours, f"record {record.number}"


@needs_corpus
@pytest.mark.parametrize("stem", WITH_CLPRNT)
def test_apt4_binary_matches_its_cl_print(stem: str) -> None:
    records = {r.number: r for r in read_binary(str(APT4 / f"{stem}.cl3"))}
    entries = clprint_entries(APT4 / f"{stem}.lis")
    assert sorted(records) == sorted(entries)
    circles = 0
    for number, entry in entries.items():
        record = records[number]
        assert record.line == entry.isn, f"record {number}"
        if isinstance(record, Statement):
            _check_statement(record, entry.header)
        elif isinstance(record, Arelem):
            _check_arelem(record, entry.header)
        elif isinstance(record, Circle):
            circles += 1
            name, _, circle = entry.header.partition("=")
            motion_name = name.partition("/")[2]
            assert motion_name.split("(")[0].strip() == record.name
            assert int(motion_name.split("(")[1].rstrip(") ")) == record.subscript
            values = circle.partition("/")[2].split()
            assert values == [f"{v:.4f}" for v in record.values]
            follower = records[number + 1]
            assert isinstance(follower, Motion) and follower.name == record.name
        elif isinstance(record, Motion):
            _check_points(record, entry)
            if record.subtype is MotionSubtype.CONTINUATION:
                assert entry.header == "CONT."
            elif entry.header:
                assert entry.header.partition("/")[2].split("(")[0].strip() == record.name
        elif isinstance(record, Fini):
            assert entry.header == "FINI"
        else:
            pytest.fail(f"record {number} {record!r} has no CL print check")
    assert circles == (1 if stem.startswith("test2") else 0)


@needs_corpus
def test_apt4_test1_matches_its_part_program() -> None:
    """test1 has no CL print (no CLPRNT): its part program is plain CL statements, so the
    binary records equal what the APT source reader makes of test1.apt, ISN = line."""
    binary = list(read_binary(str(APT4 / "test1.cl3")))
    source = list(read_apt_source(str(APT4 / "test1.apt")))

    def content(records: list[Record]) -> list[Record]:
        out = []
        for record in records:
            if isinstance(record, Motion):
                record = replace(record, name="", subscript=0)
            out.append(replace(record, number=0))
        return out

    assert content(binary) == content(source)
    assert [r.line for r in binary] == [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]


@needs_corpus
def test_apt4_long_motion_continues_in_subtype_6_records() -> None:
    records = list(read_binary(str(APT4 / "test2d_finetol.cl3")))
    arc = [r for r in records if isinstance(r, Motion) and r.name == "C1"]
    assert [r.subtype for r in arc] == [MotionSubtype.GOTO] + [MotionSubtype.CONTINUATION] * 5
    assert [len(r.points) for r in arc] == [63, 63, 63, 63, 63, 59]
    assert {r.line for r in arc} == {17}


def _cl_json(path: Path) -> list[dict[str, object]]:
    result = CliRunner().invoke(main, ["cl", str(path), "--json"])
    assert result.exit_code == 0, result.stderr
    return [json.loads(line) for line in result.stdout.splitlines()]


@needs_corpus
def test_creo_roughing_counts() -> None:
    """The counts of corpus/README.md, with continuation lines joined."""
    rows = _cl_json(CREO / "schruppen_1.ncl.1")
    goto_points = sum(len(r["points"]) for r in rows if r.get("major") == "GOTO")  # type: ignore[arg-type]
    majors = [r.get("major") for r in rows]
    assert goto_points == 5590
    assert sum(1 for r in rows if r["type"] == 3000) == 419
    assert majors.count("RAPID") == 619
    assert majors.count("FEDRAT") == 432
    assert [r for r in rows if r["type"] == 14000] == [
        {"line": 7495, "record": rows[-1]["record"], "type": 14000, "major": "FINI"}
    ]
    first_goto = next(r for r in rows if r.get("major") == "GOTO")
    assert first_goto["type"] == 5000 and first_goto["subtype"] == 5
    circle = next(r for r in rows if r["type"] == 3000)
    assert len(circle["values"]) == 7  # type: ignore[arg-type]


@needs_corpus
def test_creo_continuation_lines_are_joined() -> None:
    rows = _cl_json(CREO / "schruppen_1.ncl.1")
    texts = Path(CREO / "schruppen_1.ncl.1").read_text().splitlines()
    continued = [i for i, line in enumerate(texts, start=1) if line.rstrip().endswith("$")]
    assert continued, "the roughing file has $ continuations"
    for line in continued:
        row = next((r for r in rows if r["line"] == line), None)
        if row is None or row["type"] == 1000:
            continue
        # a continued statement is one record starting on its first line
        assert not any(r["line"] == line + 1 and r["type"] == row["type"] for r in rows)


@needs_corpus
def test_creo_drilling_cycle_words() -> None:
    rows = _cl_json(CREO / "bohren_1.ncl.8")
    cycle = next(r for r in rows if r.get("major") == "CYCLE")
    assert cycle["args"] == ["DEEP", "DEPTH", 3.5, "STEP", 1.0, "MMPM", 50.0, "CLEAR", 1.0]
    spindle = next(r for r in rows if r.get("major") == "SPINDL")
    assert spindle == {
        "line": 13,
        "record": spindle["record"],
        "type": 2000,
        "subtype": 1031,
        "major": "SPINDL",
        "code": 1031,
        "args": ["RPM", 9000.0, "CLW"],
    }


@needs_corpus
def test_post_reads_binary_cl(tmp_path: Path) -> None:
    """The APT IV binary file posts on the Standard Machine (MACHIN/MILL names another
    postprocessor): FROM, then four feed moves; the tape equals the one its part program
    gives, but for the N words, which are CL record numbers (2, 4, ... in APT IV files)."""
    tapes = []
    for source in (APT4 / "test1.cl3", APT4 / "test1.apt"):
        tape = tmp_path / f"{source.suffix[1:]}.tape"
        listing = tmp_path / f"{source.suffix[1:]}.lis"
        result = CliRunner().invoke(
            main, ["post", str(source), "-o", str(tape), "--listing", str(listing)]
        )
        assert result.exit_code == 0, result.stderr
        assert "MACHIN/MILL names another postprocessor; ignored" in result.stderr
        tapes.append(tape.read_text())
    assert tapes[0] == "TEST1\nN012G01X+1Z-1F071\nN014Y+1F100\nN016X-1\nN018Y-1\n"
    assert tapes[1] == "TEST1\nN006G01X+1Z-1F071\nN007Y+1F100\nN008X-1\nN009Y-1\n"
