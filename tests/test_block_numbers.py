"""Block numbers (issue 16): option 143 for SEQNO/ON (001 L26079-26095) and the modern
packs, whose program frame numbers blocks as after SEQNO/ON with option 143 = 1, so that no
two blocks of a tape share an N."""

from __future__ import annotations

import re
from itertools import pairwise
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main

from .conftest import SHARED

CORPUS = SHARED / "corpus"
CL_FILES = sorted(
    str(path.relative_to(CORPUS))
    for path in CORPUS.glob("*/*")
    if path.suffix in (".apt", ".cl3", ".1", ".8")
)
PACKS = [
    "linuxcnc-mill",
    "linuxcnc-mill-inch",
    "fanuc-mill",
    "fanuc-lathe",
    "haas-mill",
    "sinumerik-840d-iso",
]


def post(source: Path, tape: Path, machine: str | None = None) -> tuple[int, str]:
    command = ["post", str(source), "-o", str(tape)]
    if machine is not None:
        command += ["--machine", machine]
    result = CliRunner().invoke(main, command)
    return result.exit_code, tape.read_text() if tape.exists() else ""


def numbers(tape: str, separator: str = "") -> list[int]:
    """The N of each block (with ``separator``: only N words followed by it, which leaves
    out INSERT text such as ``N999M00`` on a tape with blanks between words)."""
    return [int(found) for found in re.findall(rf"^/?N(\d+){separator}", tape, flags=re.M)]


@pytest.mark.skipif(not CORPUS.is_dir(), reason="shared corpus not present")
@pytest.mark.parametrize("machine", PACKS)
@pytest.mark.parametrize("name", CL_FILES)
def test_no_two_blocks_share_an_n_on_a_modern_tape(tmp_path: Path, name: str, machine: str) -> None:
    """1, 2, 3, ... unless the CL's own SEQNO/n goes back, which a warning says."""
    tape_path = tmp_path / "part.ngc"
    command = ["post", str(CORPUS / name), "-o", str(tape_path), "--machine", machine]
    result = CliRunner().invoke(main, command)
    if result.exit_code != 0:
        pytest.skip(f"{name} does not post on {machine} yet (exit {result.exit_code})")
    found = numbers(tape_path.read_text(), " ")
    if "BLOCK NUMBERS REPEAT" in result.output:  # (test3_ppwords: SEQNO/10 near the end)
        return
    assert all(a < b for a, b in pairwise(found)), found
    if "SEQNO" not in (CORPUS / name).read_text(errors="replace"):
        assert found == list(range(1, len(found) + 1))


def program(option_143: float, *body: str) -> str:
    return "\n".join(
        [
            "PARTNO SEQNO",
            f"MACHIN/GECENT,23,OPTAB,143,{option_143:g}",
            "FROM/0,0,0",
            "FEDRAT/10",
            "GOTO/1,0,0",
            *body,
            "GOTO/1,2,0",
            "GOTO/3,2,0",
            "FINI",
            "",
        ]
    )


def test_seqno_on_counts_blocks_with_option_143_plus_one(tmp_path: Path) -> None:
    source = tmp_path / "p.apt"
    source.write_text(program(1, "SEQNO/ON"))
    status, tape = post(source, tmp_path / "p.tape")
    assert status == 0
    # the record number until SEQNO/ON, then 1, 2, ...
    assert numbers(tape) == [5, 1, 2]


def test_seqno_on_takes_record_numbers_with_option_143_zero(tmp_path: Path) -> None:
    source = tmp_path / "p.apt"
    source.write_text(program(0, "SEQNO/ON"))
    status, tape = post(source, tmp_path / "p.tape")
    assert status == 0
    assert numbers(tape) == [5, 7, 8]


def test_option_143_minus_one_leaves_out_a_repeated_n(tmp_path: Path) -> None:
    """Two blocks of one record: the second has no N (a long move in segments, here)."""
    source = tmp_path / "p.apt"
    source.write_text(program(-1, "SEQNO/ON", "GOTO/1,2,150"))
    status, tape = post(source, tmp_path / "p.tape")
    assert status == 0
    blocks = tape.splitlines()
    numbered = [line for line in blocks if line.startswith("N")]
    assert numbers(tape) == [5, 7, 8, 9]
    assert len(blocks) > len(numbered)  # the move of record 7 went out in several blocks


def test_without_seqno_the_standard_holds(tmp_path: Path) -> None:
    """ "If no SEQNO statement is used, the standard value is assumed" (001 L26094-26095)."""
    source = tmp_path / "p.apt"
    source.write_text(program(1))
    status, tape = post(source, tmp_path / "p.tape")
    assert status == 0
    assert numbers(tape) == [5, 6, 7]
