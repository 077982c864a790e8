"""ROTATE on a multiaxis machine (manual §3.4.7.2, 001 L6544-6751; spec 03 §14, W26, W27;
options 29 and 198): the class's rotary axis turns, and the part frame with it or not."""

from __future__ import annotations

from math import cos, radians, sin
from pathlib import Path

import pytest
from gecent.core.absent import ABSENT
from gecent.core.dispatch.post import post
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.output.block import Block, Code
from gecent.core.plugins import get_plugins
from gecent.core.state import RunResult

FROM = "FROM/1,2,3,0,0.6,0.8"


def mach40(overlay: str = "") -> MachineDefinition:
    """MACH40 (class 1, R + TL = 4, rotary output in hundredths of a revolution, ROTMAX
    35.99964 degrees = 9.9999 units), with table entries and options laid over it."""
    pack = get_plugins().machine("mach40")
    assert pack is not None
    base = pack.load()
    if not overlay:
        return base
    text = f'[machine]\nname = "mach40x"\ntitle = "MACH40 TEST"\n{overlay}'
    return load_machine_text(text, "mach40x.toml", base)


# MACH40 has no 36-359.9999 degree code (TABLEG(11)): a ROTATE block of more than 3.6
# degrees has no G code there (fatal 138, as the three-axis ROTATE), nor has a CODE 0
# multiaxis move (ROTREF's) once SELGRO applies to it (W22, 001 L6261-6282); the manual's
# W25/W27 assume every code available
WITH_G10 = "[tableg]\n11 = 10\n"


def run(tmp_path: Path, lines: list[str], machine: MachineDefinition) -> RunResult:
    program = tmp_path / "r.apt"
    program.write_text("\n".join(["PARTNO ROTREF", *lines, "FINI", ""]))
    return post(str(program), get_plugins(), machine_override=machine)


def moves(result: RunResult) -> list[Block]:
    return [b for b in result.blocks if b.code in (Code.LINEAR, Code.ROTARY_INCREMENTAL)]


def cells(block: Block) -> tuple[float, ...]:
    """dX, dY, dZ, dC (0 for a register not in the block)."""
    values = [block.cells[c] for c in (3, 4, 5, 7)]
    return tuple(0.0 if v is ABSENT else round(float(v), 4) for v in values)


def test_w26_rotref_keeps_the_tip_and_turns_the_tool(tmp_path: Path) -> None:
    """W26 (001 L6635-6707), option 198 = 0, ROTATE/TABLE,INCR,40,CLW,ROTREF from the
    tool at (1, 2, 3) along (0, .6, .8): class 1 has C = 90, A = 53.13, X = 1, Y = 2 + 4 x
    .6 = 4.4, Z = 3 + 4 x .8 = 6.2. DPRESM(C) = 130 (CLW increases the reading, option
    117 = +1); the inverse gives (i2, j2, k2) = (.6 cos 130, .6 sin 130, .8); the tip is
    reset to (1, 2, 3); GOLINE's direct transform: X = sin 130 - 2 cos 130 = 2.051619,
    Y = cos 130 + 2 sin 130 + 2.4 = 3.289301, Z = 6.2. The CODE 0 move: dX 1.0516,
    dY -1.1107, dC 40 degrees = 11.1111 hundredths, in two ROTMAX segments."""
    lines = [FROM, "FEDRAT/10", "ROTATE/TABLE,INCR,40,CLW,ROTREF"]
    result = run(tmp_path, lines, mach40(WITH_G10))  # (dC 5.5556 needs TABLEG(11))
    blocks = moves(result)
    assert [b.code for b in blocks] == [Code.LINEAR, Code.LINEAR]
    assert [cells(b) for b in blocks] == [
        (0.5258, -0.5554, 0.0, 5.5556),
        (0.5258, -0.5553, 0.0, 5.5555),
    ]
    assert blocks[1].position == (20516, 32893, 62000)


def test_w26_option_198_reverses_rotref(tmp_path: Path) -> None:
    """Option 198 = 1 (L26559-26563): no ROTREF compensates the frame, ROTREF turns it
    with the part (the decision table of spec 03 §14.1)."""
    machine = mach40("[optab]\n198 = 1.0\n" + WITH_G10)
    without = moves(run(tmp_path, [FROM, "FEDRAT/10", "ROTATE/TABLE,INCR,40,CLW"], machine))
    assert [cells(b) for b in without] == [
        (0.5258, -0.5554, 0.0, 5.5556),
        (0.5258, -0.5553, 0.0, 5.5555),
    ]
    machine = mach40("[optab]\n198 = 1.0\n" + WITH_G10)
    lines = [FROM, "FEDRAT/10", "ROTATE/TABLE,INCR,40,CLW,ROTREF"]
    turned = moves(run(tmp_path, lines, machine))
    assert [b.code for b in turned] == [Code.ROTARY_INCREMENTAL] * 2
    assert [cells(b) for b in turned] == [(0.0, 0.0, 0.0, 5.5556), (0.0, 0.0, 0.0, 5.5555)]


def test_the_frame_turns_with_the_table_without_rotref(tmp_path: Path) -> None:
    """Option 198 = 0 without ROTREF (Diagram 3.4.7.2B): the table alone turns (CODE -2,
    ROTOUT's segments), and DPRESP is the inverse of the turned machine point: the tip at
    (sin 130 ..., ) in the turned part, the tool along (.6 cos 130, .6 sin 130, .8). A
    following GOTO/1,2,3 (the tool axis in force) is then W26's move."""
    lines = [FROM, "FEDRAT/10", "ROTATE/TABLE,INCR,40,CLW", "GOTO/1,2,3"]
    result = run(tmp_path, lines, mach40(WITH_G10))
    blocks = moves(result)
    assert [b.code for b in blocks] == [Code.ROTARY_INCREMENTAL] * 2 + [Code.LINEAR]
    assert [cells(b) for b in blocks] == [
        (0.0, 0.0, 0.0, 5.5556),
        (0.0, 0.0, 0.0, 5.5555),
        (1.0516, -1.1107, 0.0, 0.0),
    ]


def test_w27_a_tracked_table_turns_320_degrees_back_to_zero(tmp_path: Path) -> None:
    """W27 (001 L6714-6728) on MACH40: INCR 10, 20, 10 CLW put the table at 40 degrees;
    ATANGL 0 CLW is a 320 degree turn: 88.8889 hundredths of a revolution in nine ROTMAX
    segments (9.9999), each exact to the step, the table back at 0 (100 units)."""
    lines = [
        "FROM/0,0,10,0,0,1",
        "FEDRAT/10",
        "ROTATE/TABLE,INCR,10,CLW",
        "ROTATE/TABLE,INCR,20,CLW",
        "ROTATE/TABLE,INCR,10,CLW",
        "ROTATE/TABLE,ATANGL,0,CLW",
    ]
    result = run(tmp_path, lines, mach40(WITH_G10))
    blocks = moves(result)
    assert all(b.code is Code.ROTARY_INCREMENTAL for b in blocks)
    outputs = [round(float(b.cells[7]), 4) for b in blocks]  # type: ignore[arg-type]
    assert outputs[:3] == [2.7778, 5.5555, 2.7778]
    assert outputs[3:] == [9.8765, 9.8766] * 4 + [9.8765]
    assert round(sum(outputs[3:]), 4) == 88.8889
    punched = [b.punch for b in blocks]
    assert punched[0] == "N004G10C+27778F003581"


def test_option_29_zero_indexes_without_remembering(tmp_path: Path) -> None:
    """Option 29 = 0 (L6733-6746): the turn is output, the multiaxis state is not moved, so
    a later move is not affected by it: back to the FROM point is no move at all."""
    machine = mach40("[optab]\n29 = 0.0\n" + WITH_G10)
    lines = [FROM, "FEDRAT/10", "ROTATE/TABLE,INCR,40,CLW", "GOTO/1,2,3,0,0.6,0.8"]
    result = run(tmp_path, lines, machine)
    assert [cells(b) for b in moves(result)] == [
        (0.0, 0.0, 0.0, 5.5556),
        (0.0, 0.0, 0.0, 5.5555),
    ]
    assert not result.diagnostics


def test_option_29_zero_with_atangl_warns_and_tracks(tmp_path: Path) -> None:
    """ATANGL or ROTREF with option 29 = 0: the warning comment, then as option 29 = 1
    (L6746-6751): ROTREF compensates as W26."""
    machine = mach40("[optab]\n29 = 0.0\n" + WITH_G10)
    lines = [FROM, "FEDRAT/10", "ROTATE/TABLE,INCR,40,CLW,ROTREF"]
    result = run(tmp_path, lines, machine)
    assert [d.text for d in result.diagnostics][-1] == "ROTREF AND ATANGL CANNOT BE USED"
    assert cells(moves(result)[0]) == (0.5258, -0.5554, 0.0, 5.5556)


def test_rotref_is_linearity_tested_even_under_lintol_off(tmp_path: Path) -> None:
    """A ROTREF move is tested when LINTOL is on (spec 03 §15.4), one-point or not: the
    tip would swing off (1, 2, 3) while C turns, so the move is cut; every piece keeps the
    tip within r of the straight move (here a point)."""
    base = [FROM, "FEDRAT/10", "ROTATE/TABLE,INCR,40,CLW,ROTREF"]
    plain = moves(run(tmp_path, base, mach40(WITH_G10)))
    tested = run(tmp_path, [*base[:2], "LINTOL/0.01", "LINTOL/OFF", base[2]], mach40(WITH_G10))
    pieces = moves(tested)
    assert len(pieces) > len(plain)
    assert sum(round(float(b.cells[7]) / 0.0001) for b in pieces) == 111111  # type: ignore[arg-type]
    assert pieces[-1].position == plain[-1].position


def test_a_long_rotref_turn_keeps_its_direction(tmp_path: Path) -> None:
    """320 degrees CLW with ROTREF: made as two turns of 160 so that the class's angle is
    never taken the shorter way (-40): C advances 88.8889 units in all."""
    lines = [FROM, "FEDRAT/10", "ROTATE/TABLE,INCR,320,CLW,ROTREF"]
    blocks = moves(run(tmp_path, lines, mach40(WITH_G10)))
    turns = [round(float(b.cells[7]) / 0.0001) for b in blocks]  # type: ignore[arg-type]
    assert all(t > 0 for t in turns) and sum(turns) == 888889
    # back where the tip was, the tool turned 320 degrees about Z: C = 90 + 320 = 50
    c = radians(50.0)
    assert blocks[-1].position == (
        round((sin(c) - 2 * cos(c)) / 0.0001),
        round((cos(c) + 2 * sin(c) + 2.4) / 0.0001),
        62000,
    )


def test_rotate_head_turns_the_head(tmp_path: Path) -> None:
    """ROTATE/HEAD on MACH40 turns A (DBFSEG(6)), the head, by convention (L1793-1796):
    A from 53.1301 degrees (147584 steps of .0001 hundredths) to 55.1301 (153139), so 2
    degrees go out as .5555, the positions rounded, not the departure."""
    lines = ["FROM/0,0,10,0,0.6,0.8", "FEDRAT/10", "ROTATE/HEAD,INCR,2,CLW"]
    blocks = moves(run(tmp_path, lines, mach40()))
    assert [b.code for b in blocks] == [Code.ROTARY_INCREMENTAL]
    assert round(float(blocks[0].cells[6]), 4) == 0.5555  # type: ignore[arg-type]


def test_rotref_before_from_is_refused(tmp_path: Path) -> None:
    with pytest.raises(InputError, match="no tool position to keep"):
        run(tmp_path, ["FEDRAT/10", "ROTATE/TABLE,INCR,40,CLW,ROTREF"], mach40())
