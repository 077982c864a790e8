"""TURRET/..., NOW on a multihead machine (manual CODE +-14, 001 L9357-9364; corrective
moves cut as lines in the merge, L7676-7677): each head keeps its own turret distances,
its corrective move (CODE -3) goes to its scratch tape, and in a combined section GMOUT
pairs it with the other head's regular motion in one CODE +14 (head 1 corrects) or -14
(head 2 corrects) block, the correcting half punched but not summed on the Absolute
print. MACH51 with a turret of 8 positions (option 106)."""

from __future__ import annotations

from pathlib import Path

import pytest
from gecent.core.dispatch.post import post
from gecent.core.errors import NotYetSupported
from gecent.core.output.block import Block, Code
from gecent.core.output.tape import tape_line
from gecent.core.plugins import PluginSet

HEADER = """PARTNO TURRET
MACHIN/GECENT,51,OPTAB,106,8{options}
COMBIN/2
SELECT/HEAD,1
FROM/6,4,0
FEDRAT/10
TURRET/1,1,2,3
SELECT/HEAD,2
FROM/7,5,0
FEDRAT/8
TURRET/1,1,4,4
"""


def _post(plugins: PluginSet, tmp_path: Path, body: str, options: str = "") -> list[Block]:
    program = tmp_path / "p.apt"
    program.write_text(HEADER.format(options=options) + body + "FINI\n")
    return post(str(program), plugins).blocks


def _tape(blocks: list[Block]) -> list[str]:
    return [
        line for b in blocks if b.code is not Code.PARTNO and (line := tape_line(b)) is not None
    ]


def test_head_1_correction_beside_head_2_motion_is_code_plus_14(
    plugins: PluginSet, tmp_path: Path
) -> None:
    """Head 1 indexes from A = 2, B = 3 to A = 2.5, B = 1: the turret centre moves Z -0.5
    and X +2 while head 2 cuts (-1, -2): one tape block, CODE +14; the correcting half
    stays at head 1's point (6, 4) for the Absolute print, head 2's is summed (6, 3)."""
    body = (
        "SELECT/HEAD,1\nOP/3\nTURRET/2,2,2.5,1,NOW\nGOTO/4.5,1.5,0\n"
        "SELECT/HEAD,2\nOP/3\nGOTO/6,3,0\nGOTO/5,2,0\n"
    )
    blocks = _post(plugins, tmp_path, body)
    assert _tape(blocks)[-3:] == [
        "N014G01X+002Z-0005F0049U-001W-002E0036",
        "N015G01X-0015Z-0025F0034",
        "G01U-001W-001E0057",
    ]
    (paired,) = [b for b in blocks if b.code in (Code.MULTIHEAD_TURRET_1, Code.MULTIHEAD_TURRET_2)]
    assert paired.code is Code.MULTIHEAD_TURRET_1
    assert paired.cells[15] == 14.0
    assert paired.halves is not None
    correction, motion = paired.halves
    assert correction.code is Code.TURRET_CORRECTION and motion.code is Code.LINEAR
    step = 0.0001
    assert correction.position is not None and motion.position is not None
    assert [round(p * step, 4) for p in correction.position[:2]] == [6.0, 4.0]
    assert [round(p * step, 4) for p in motion.position[:2]] == [6.0, 3.0]


def test_head_2_correction_uses_head_2_distances_code_minus_14(
    plugins: PluginSet, tmp_path: Path
) -> None:
    """Each head has its own distances: head 2 indexes from its A = 4, B = 4 to A = 3,
    B = 4.5 (head 1's 2 and 3 play no part): W +1, U -0.5, beside head 1's line: CODE -14.
    Head 1 indexing to its own distances again needs no corrective move."""
    body = (
        "SELECT/HEAD,1\nOP/2\nTURRET/3,3,2,3,NOW\nGOTO/5,4,0\n"
        "SELECT/HEAD,2\nOP/2\nTURRET/2,2,3,4.5,NOW\nGOTO/7,4,0\n"
    )
    blocks = _post(plugins, tmp_path, body)
    corrections = [b for b in blocks if b.code is Code.TURRET_CORRECTION]
    assert corrections == []
    (paired,) = [b for b in blocks if b.halves is not None and b.code.value in (14, -14)]
    assert paired.code is Code.MULTIHEAD_TURRET_2
    assert paired.halves is not None
    motion, correction = paired.halves
    assert motion.code is Code.LINEAR and correction.code is Code.TURRET_CORRECTION
    assert tape_line(paired) is not None
    assert "U-0005W+001" in (tape_line(paired) or "")


def test_two_corrections_go_out_one_after_the_other(plugins: PluginSet, tmp_path: Path) -> None:
    """CODE +-14 pairs a correction with a regular motion; two corrections are not one
    block: each goes out alone as CODE -3."""
    body = "SELECT/HEAD,1\nOP/2\nTURRET/2,2,2.5,1,NOW\nSELECT/HEAD,2\nOP/2\nTURRET/2,2,3,4.5,NOW\n"
    blocks = _post(plugins, tmp_path, body)
    assert [b.head for b in blocks if b.code is Code.TURRET_CORRECTION] == [1, 2]
    assert not [b for b in blocks if b.halves is not None]


def test_a_correction_outside_a_section_is_code_minus_3(plugins: PluginSet, tmp_path: Path) -> None:
    """Without an OP section the corrective move goes out alone, as on one head."""
    body = "SELECT/HEAD,1\nTURRET/2,2,2.5,1,NOW\nGOTO/4.5,1.5,0\nSELECT/HEAD,2\nGOTO/6,3,0\n"
    blocks = _post(plugins, tmp_path, body)
    (correction,) = [b for b in blocks if b.code is Code.TURRET_CORRECTION]
    assert correction.head == 1
    assert tape_line(correction) == "N013G01X+002Z-0005F0049"


def test_a_correction_on_a_common_axis_is_not_yet_supported(
    plugins: PluginSet, tmp_path: Path
) -> None:
    """Heads on a common axis (option 155): a correction along it would move the other
    head's tool: not built (the split one, option 139 = 0, is: test_multihead_turret_split)."""
    body = "SELECT/HEAD,1\nOP/3\nTURRET/2,2,2.5,1,NOW\nSELECT/HEAD,2\nOP/3\nGOTO/6,3,0\n"
    with pytest.raises(NotYetSupported, match=r"CODE \+-14.*common axis"):
        _post(plugins, tmp_path, body, ",OPTAB,155,1")
