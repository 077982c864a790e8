"""Multihead programs (manual §3.4.8): the first pass per head into scratch tapes, the
merge pass GEMULT's sequencing by OP/n (the manual's example, 001 L2214-2300) and GMOUT's
combined blocks."""

from __future__ import annotations

import glob
import os
import tempfile
from pathlib import Path

import pytest
from gecent.core.cl.records import Comment
from gecent.core.dispatch.post import post
from gecent.core.errors import InputError
from gecent.core.macros.dialect import read_raw
from gecent.core.output.block import Block, Code
from gecent.core.output.tape import tape_line
from gecent.core.plugins import PluginSet

from .conftest import DATA, ROOT

SEQUENCING = DATA / "multihead" / "sequencing.apt"


def _names(path: Path, plugins: PluginSet) -> dict[int, str]:
    """Record number -> the motion's name after its $$ (the manual's letters)."""
    lines = path.read_text().splitlines()
    names = {}
    for record in read_raw(str(path), plugins, None):
        assert record.line is not None
        line = lines[record.line - 1]
        if "$$" in line and not isinstance(record, Comment):
            names[record.number] = line.split("$$")[1].strip()
        elif line.startswith("END"):
            names[record.number] = "END"
    return names


def _sequence(blocks: list[Block], names: dict[int, str]) -> list[str]:
    out = []
    for block in blocks:
        if block.halves is not None:
            first, second = block.halves
            out.append(f"{names[first.record]}+{names[second.record]}")  # type: ignore[index]
        elif block.record in names and block.code in (Code.LINEAR, Code.END):
            out.append(f"{names[block.record]}({block.head})")
    return out


def test_the_manuals_opcode_sequencing(plugins: PluginSet) -> None:
    """A; B, C; D; E1+E2; F1+F2; G; H; I; J1+J2; END(2); END(3) (001 L2263-2300), the
    tapes' heads in brackets. G goes out within the section of OP/3, as head 2's rest."""
    result = post(str(SEQUENCING), plugins)
    sequence = _sequence(result.blocks, _names(SEQUENCING, plugins))
    assert sequence == [
        "A(1)", "B(1)", "C(1)", "D(2)", "E1+E2", "F1+F2", "G(2)", "H(1)", "I(2)",
        "J1+J2", "END(1)", "END(2)",
    ]  # fmt: skip


def test_each_head_posts_with_its_own_registers(plugins: PluginSet) -> None:
    """Head 2 of MACH51 has U, W and the feed register E, no N (001 L28193-28201); a
    combined block is one tape block, head 1's words first; one FINI closes it."""
    result = post(str(SEQUENCING), plugins)
    lines = {b.record: tape_line(b) for b in result.blocks if b.code is Code.LINEAR}
    assert lines[11] == "N011G01X-001F0100"  # A: head 1
    assert lines[33] == "G01U-001E0100"  # D: head 2, no N register
    combined = [b for b in result.blocks if b.halves is not None]
    assert tape_line(combined[0]) == "N019G01X-001U-001"
    assert [b.code for b in result.blocks].count(Code.FINI) == 1
    assert all(abs(int(b.code)) == 17 for b in combined)


def test_the_scratch_tapes_are_removed(plugins: PluginSet, tmp_path: Path) -> None:
    before = set(glob.glob(os.path.join(tempfile.gettempdir(), "gecent-head*")))
    post(str(SEQUENCING), plugins)
    bad = tmp_path / "bad.apt"
    bad.write_text(SEQUENCING.read_text().replace("OP/7", "OP/0"))
    with pytest.raises(InputError, match="OP expects"):
        post(str(bad), plugins)
    after = set(glob.glob(os.path.join(tempfile.gettempdir(), "gecent-head*")))
    assert after <= before


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (("SELECT/HEAD,2", "SELECT/HEAD,3"), "SELECT/HEAD expects a head number 1..2"),
        (("COMBIN/2", "COMBIN/3"), None),  # not a multihead program: COMBIN refused
        (("OP/1", "OP/1,RPM,5"), "OP expects"),
        (("OP/1", "OP/1,FAST"), "OP expects"),
    ],
)
def test_bad_multihead_statements(
    plugins: PluginSet, tmp_path: Path, change: tuple[str, str], message: str | None
) -> None:
    bad = tmp_path / "bad.apt"
    bad.write_text(SEQUENCING.read_text().replace(*change, 1))
    with pytest.raises(InputError, match=message or "COMBIN expects the number of heads, 2"):
        post(str(bad), plugins)


def test_multihead_words_need_combin(plugins: PluginSet, tmp_path: Path) -> None:
    program = tmp_path / "p.apt"
    text = SEQUENCING.read_text().replace("COMBIN/2\n", "")
    program.write_text(text)
    with pytest.raises(InputError, match="COMBIN/2 must come first"):
        post(str(program), plugins)
    program.write_text(text.replace("MACHIN/GECENT,51", "MACHIN/GECENT,23"))
    with pytest.raises(InputError, match="COMBIN/2 must come first"):
        post(str(program), plugins)
    program.write_text(SEQUENCING.read_text().replace("MACHIN/GECENT,51", "MACHIN/GECENT,23"))
    with pytest.raises(InputError, match="which has one head"):
        post(str(program), plugins)


def test_the_example_program_posts(plugins: PluginSet) -> None:
    result = post(str(ROOT / "examples" / "twohead_mach51.apt"), plugins)
    assert result.warnings == 0
    assert any(b.halves is not None for b in result.blocks)
