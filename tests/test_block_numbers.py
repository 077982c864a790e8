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

from .conftest import MODERN_PACKS, SHARED

CORPUS = SHARED / "corpus"
CL_FILES = sorted(
    str(path.relative_to(CORPUS))
    for path in CORPUS.glob("*/*")
    if path.suffix in (".apt", ".cl3", ".1", ".8")
)
# corpus files that do not post, and why: APT part programs (geometry, not CL data); each is
# still posted and must fail as bad input (2), so a file that starts to post joins the check
# (SolidWorks CAM's files post through their dialect since issue 19)
NOT_POSTING = {
    "apt4/test2_contour_tlrgt.apt": 2,
    "apt4/test2d_finetol.apt": 2,
}


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
@pytest.mark.parametrize("machine", MODERN_PACKS)
@pytest.mark.parametrize("name", CL_FILES)
def test_no_two_blocks_share_an_n_on_a_modern_tape(tmp_path: Path, name: str, machine: str) -> None:
    """1, 2, 3, ... unless the CL's own SEQNO/n goes back, which a warning says."""
    tape_path = tmp_path / "part.ngc"
    command = ["post", str(CORPUS / name), "-o", str(tape_path), "--machine", machine]
    result = CliRunner().invoke(main, command)
    if name in NOT_POSTING:
        assert result.exit_code == NOT_POSTING[name], result.output
        return
    assert result.exit_code == 0, result.output
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


@pytest.mark.parametrize(
    ("option_143", "expected"),
    [(1, [5, 1, 2]), (0, [5, 7, 8])],  # counting from 1 after SEQNO/ON; the record number
    ids=["counting", "record numbers"],
)
def test_seqno_on_numbers_by_option_143(
    tmp_path: Path, option_143: int, expected: list[int]
) -> None:
    source = tmp_path / "p.apt"
    source.write_text(program(option_143, "SEQNO/ON"))
    status, tape = post(source, tmp_path / "p.tape")
    assert status == 0
    assert numbers(tape) == expected  # the record number until SEQNO/ON


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
