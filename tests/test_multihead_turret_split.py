"""A turret corrective move in a combined section whose moves are split to equal times
(one feedrate register, option 139 = 0; manual §3.4.8.2.1.1, 001 L7390-7530): the
correction is a line there (001 L7676-7677) and is split as one; every piece keeps the
point the correction leaves the tool at (its moves are not summed, CODE -3, 001
L9225-9233) and goes out as a correction, +14 beside head 2's move, -3 alone."""

from __future__ import annotations

from pathlib import Path

import pytest
from gecent.core.dispatch.post import post
from gecent.core.output.block import Block, Code
from gecent.core.output.tape import tape_line
from gecent.core.plugins import PluginSet

from .test_multihead_turret import HEADER

# head 1's correction beside head 2's two moves, on one feedrate register (option 139 = 0)
PROGRAM = (
    HEADER.format(options=",OPTAB,139,0")
    + "SELECT/HEAD,1\nOP/3\nTURRET/2,2,2.5,1,NOW\nGOTO/4.5,1.5,0\n"
    + "SELECT/HEAD,2\nOP/3\nGOTO/6.8,5,0\nGOTO/6.8,4,0\nFINI\n"
)


def _moves(plugins: PluginSet, tmp_path: Path) -> list[Block]:
    program = tmp_path / "p.apt"
    program.write_text(PROGRAM)
    return [b for b in post(str(program), plugins).blocks if b.steps or b.halves]


def test_a_correction_is_split_to_the_other_heads_times(plugins: PluginSet, tmp_path: Path) -> None:
    """Tool 1 (A = 2, B = 3) to tool 2 (2.5, 1): the turret centre moves X +2, Z -0.5,
    2.06 in at 10 IPM, 0.206 min. Head 2's 0.2 in and 1 in at 8 IPM take 0.025 and
    0.125 min: the correction is cut in three, 0.25 in (0.025 min) beside the first, 1.25
    in (0.125 min) beside the second, and the rest alone; head 1's own move follows."""
    blocks = _moves(plugins, tmp_path)
    assert [int(b.code) for b in blocks] == [14, 14, -3, 0]
    assert [tape_line(b) for b in blocks] == [
        "N014G11X+000243Z-000061F0040U-0002",
        "N014G01X+001213Z-000303F0080W-001",
        "N014G11X+000544Z-000136F0018",
        "N015G01X-0015Z-0025F0034",
    ]
    pieces = [b.halves[0] if b.halves else b for b in blocks[:3]]
    assert all(p.code is Code.TURRET_CORRECTION and p.head == 1 for p in pieces)
    # the pieces add up to the correction, and none moves the tool's point (6, 4)
    assert [sum(p.steps[a] for p in pieces) for a in range(2)] == [20000, -5000]  # type: ignore[index]
    assert {p.position[:2] for p in pieces} == {(60000, 40000)}  # type: ignore[index]
    assert blocks[3].position is not None and blocks[3].position[:2] == (45000, 15000)


def test_the_split_correction_takes_the_heads_times(plugins: PluginSet, tmp_path: Path) -> None:
    """One feedrate register: the combined blocks take head 2's times, the rest of the
    correction and head 1's move their own."""
    program = tmp_path / "p.apt"
    program.write_text(PROGRAM)
    result = post(str(program), plugins)
    correction = (2.0**2 + 0.5**2) ** 0.5 / 10.0
    move = (1.5**2 + 2.5**2) ** 0.5 / 10.0
    assert result.cut_minutes == pytest.approx(correction + move, abs=2e-3)
