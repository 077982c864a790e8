"""Multihead programs (manual §3.4.8): the first pass per head into scratch tapes, the
merge pass GEMULT's sequencing by OP/n (the manual's example, 001 L2214-2300) and GMOUT's
combined blocks."""

from __future__ import annotations

import glob
import os
import tempfile
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.absent import ABSENT
from gecent.core.cl.records import Comment
from gecent.core.cli import main
from gecent.core.dispatch.post import post
from gecent.core.errors import FatalError, InputError
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


EXAMPLE = ROOT / "examples" / "twohead_mach51.apt"


def _one_feed_register(tmp_path: Path, source: Path) -> Path:
    """The program with MACH51's second feedrate register turned off (option 139 = 0):
    the equal-time method."""
    program = tmp_path / source.name
    program.write_text(
        source.read_text().replace("MACHIN/GECENT,51", "MACHIN/GECENT,51,OPTAB,139,0")
    )
    return program


def _head_blocks(blocks: list[Block]) -> dict[int, list[Block]]:
    heads: dict[int, list[Block]] = {1: [], 2: []}
    for block in blocks:
        for part in block.halves or (block,):
            if part.steps is not None and part.code is not Code.FROM:
                heads[part.head].append(part)
    return heads


@pytest.mark.parametrize("one_register", [False, True])
def test_every_head_reaches_its_points(
    plugins: PluginSet, tmp_path: Path, one_register: bool
) -> None:
    """Split or not, each head's departures add up, block after block, to the points its
    CL records reach: no step is lost or doubled by a split."""
    program = _one_feed_register(tmp_path, EXAMPLE) if one_register else EXAMPLE
    result = post(str(program), plugins)
    starts = {1: (60000, 40000), 2: (70000, 50000)}  # the FROMs in steps of 0.0001 in
    for head, blocks in _head_blocks(result.blocks).items():
        at = list(starts[head])
        for block in blocks:
            assert block.steps is not None and block.position is not None
            steps = block.steps[:2]  # (a circle's block carries the third, zero)
            at = [a + s for a, s in zip(at, steps, strict=True)]
            assert tuple(at) == block.position[:2]
    assert any(b.halves for b in result.blocks)


def test_one_feed_register_gives_both_heads_one_time(plugins: PluginSet, tmp_path: Path) -> None:
    """With one F register every combined block takes one time on both heads (001
    L7390-7530): the longer move is split, lines (SPLIT) and the circle (CIRSEG)."""
    result = post(str(_one_feed_register(tmp_path, EXAMPLE)), plugins)
    combined = [b for b in result.blocks if b.halves is not None]
    assert len(combined) >= 5
    circles = [b for b in combined if b.halves and b.halves[0].code is Code.CIRCLE_XY_CCLW]
    assert len(circles) == 2  # the quarter circle cut in two against head 2's lines
    for block in combined:
        assert block.halves is not None
        first, second = block.halves
        feed = [float(h.cells[19]) for h in block.halves]  # type: ignore[arg-type]
        times = []
        for half, ipm in zip((first, second), feed, strict=True):
            assert half.steps is not None
            if half.code is Code.CIRCLE_XY_CCLW:
                assert half.radius is not None
                chord = sum((s * 0.0001) ** 2 for s in half.steps) ** 0.5
                from math import asin

                length = 2 * half.radius * asin(min(1.0, chord / (2 * half.radius)))
            else:
                length = sum((s * 0.0001) ** 2 for s in half.steps) ** 0.5
            times.append(length / ipm)
        # equal to the rounding of the pieces to whole steps
        assert times[0] == pytest.approx(times[1], rel=2e-3, abs=2e-5)


def test_prephd_enables_the_circle_on_its_head(plugins: PluginSet, tmp_path: Path) -> None:
    """PREPHD (001 L34994-35040): TABLEG(16) = G18 on MACH51, in a block by itself before
    head 1's circle, once while it is in effect."""
    result = post(str(_one_feed_register(tmp_path, EXAMPLE)), plugins)
    lines = [tape_line(b) for b in result.blocks]
    g18 = [i for i, line in enumerate(lines) if line is not None and line.endswith("G18")]
    assert len(g18) == 1
    after = result.blocks[g18[0] + 1]
    assert after.halves is not None and after.halves[0].code is Code.CIRCLE_XY_CCLW


GANTRY = DATA / "multihead" / "gantry.apt"


def test_w6_common_axis_segments_at_the_other_heads_end(plugins: PluginSet) -> None:
    """Spec 04 W6 (Diagram 3.4.8.2.1.3.2A, 001 L8185-8402): X common to both heads, one
    feedrate register. Pair 1 (0->10 and 0->10) combines as it is; pair 2 (10->20 and
    10->25): head 2 goes further and is segmented at 20, the pieces combine; head 1 then
    reads its STOP, is parked (head 2 withdrawn with it and brought back), and head 2's
    remnant 20->25 goes out alone."""
    result = post(str(GANTRY), plugins)
    lines = [tape_line(b) for b in result.blocks if b.code is not Code.PARTNO]
    lines = [line for line in lines if line is not None]
    assert lines[:2] == ["N014G10X+010F0100U+010", "N015G10X+010F0100U+010"]
    assert lines[-1] == "G01U+005E0020"  # the remnant, 5 in at 10 IPM
    texts = [b.text for b in result.blocks if b.code is Code.COMMENT]
    assert texts == ["HEAD 1 PARKED"]
    heads = _head_blocks(result.blocks)
    assert heads[2][-1].position is not None and heads[2][-1].position[0] == 250000
    _gantry_holds(result.blocks, {1: [0, 10000], 2: [0, 20000]})


def test_a_head_the_common_axis_moved_returns_to_its_point(
    plugins: PluginSet, tmp_path: Path
) -> None:
    """Head 1 cuts along X alone (unequal operation numbers) while head 2 is parked; the
    axis takes head 2 along, so before head 2 cuts it returns to its own point: the X of
    its own last CL point (001 L7986-7990)."""
    program = tmp_path / "p.apt"
    program.write_text(
        GANTRY.read_text()
        .replace("OP/1\nGOTO/10,1,0", "OP/1\nGOTO/5,1,0\nOP/2\nGOTO/10,1,0", 1)
        .replace("OP/1\nGOTO/10,2,0", "OP/3\nGOTO/10,2,0", 1)
    )
    result = post(str(program), plugins)
    texts = [b.text for b in result.blocks if b.code is Code.COMMENT]
    # head 2 parked while head 1 cuts alone; head 1 parked before head 2 comes back
    assert texts == ["HEAD 2 PARKED", "HEAD 1 PARKED", "HEAD 2 RETURNED TO THE WORK"]
    returned = [tape_line(b) for b in result.blocks if b.head == 2 and b.rapid]
    # along X at the parked level (001 L7980-7990), then into the work by its SAFETY
    assert returned[-2:] == ["G10U-020E0500", "G11W-0005E0304"]
    _gantry_holds(result.blocks, {1: [0, 10000], 2: [0, 20000]})


def _gantry_holds(blocks: list[Block], at: dict[int, list[int]]) -> None:
    """Each block's departures take its head from where it stands to the point the block
    says, where a head stands moving with the other's moves along X (the common axis),
    and a combined block moves both heads alike along it: on the tape's grid (MACH51
    prints X to 0.001 in, 10 steps), finer CL values being rounded away."""
    grid = 10
    for block in blocks:
        parts = [p for p in block.halves or (block,) if p.steps and p.code is not Code.FROM]
        if block.halves is not None and len(parts) == 2:
            assert parts[0].steps is not None and parts[1].steps is not None
            assert abs(parts[0].steps[0] - parts[1].steps[0]) < grid
        for part in parts:
            assert part.steps is not None and part.position is not None
            mine = at[part.head]
            mine[:] = [a + s for a, s in zip(mine, part.steps[:2], strict=True)]
            assert all(abs(m - p) < grid for m, p in zip(mine, part.position[:2], strict=True))
            mine[:] = list(part.position[:2])
            if block.halves is None:  # (a combined block moves both heads itself)
                at[3 - part.head][0] = mine[0]


def test_safety_along_the_common_axis_is_refused(plugins: PluginSet, tmp_path: Path) -> None:
    program = tmp_path / "p.apt"
    program.write_text(GANTRY.read_text().replace("SAFETY/0,0.5,0", "SAFETY/0.5,0,0", 1))
    with pytest.raises(InputError, match="along the heads' common axis"):
        post(str(program), plugins)


PARKING = DATA / "multihead" / "parking.apt"


def test_a_broken_restriction_parks_the_other_head(plugins: PluginSet) -> None:
    """Feeds of 10 and 5 IPM under OP/1,RPM,10,10 break the 10 % band (001 L7626-7645):
    head 2 is withdrawn by its SAFETY (head 1 withdrawn with it and brought back), head 1
    finishes its part, head 2 returns and finishes its own; a comment at each park."""
    result = post(str(PARKING), plugins)
    texts = [b.text for b in result.blocks if b.code is Code.COMMENT]
    assert texts == ["HEAD 2 PARKED", "HEAD 2 RETURNED TO THE WORK"]
    moves = [
        tape_line(b)
        for b in result.blocks
        if b.halves is not None or (b.steps is not None and b.code is not Code.FROM)
    ]
    assert moves == [
        "N014G11X+0005F0304U+0005E0304",  # both withdrawn at once
        "N014G11X-0005",  # head 1 back to the work
        "N014G01X-001F0100",
        "N015G01Z-001",
        "G11U-0005",  # head 2 returns
        "G01U-001E0050",
        "G01W-001",
    ]
    assert any("FEEDRATES DIFFER" in d.text for d in result.diagnostics)


def test_without_safety_a_head_cannot_be_parked(plugins: PluginSet, tmp_path: Path) -> None:
    program = tmp_path / "p.apt"
    program.write_text(PARKING.read_text().replace("SAFETY/0.5,0,0\nFEDRAT/5", "FEDRAT/5"))
    result = post(str(program), plugins)
    assert "HEAD 2 NOT PARKED: NO SAFETY WAS GIVEN FOR IT" in [d.text for d in result.diagnostics]


def test_op_none_lifts_the_restrictions(plugins: PluginSet, tmp_path: Path) -> None:
    program = tmp_path / "p.apt"
    program.write_text(PARKING.read_text().replace("OP/1,RPM,10,10\nGOTO/6", "OP/1,NONE\nGOTO/6"))
    result = post(str(program), plugins)
    assert not [b for b in result.blocks if b.code is Code.COMMENT]
    assert any(b.halves for b in result.blocks)


def test_safety_on_a_single_head_program_is_not_built(plugins: PluginSet, tmp_path: Path) -> None:
    program = tmp_path / "p.apt"
    """MACH23 is a single-head mill: SAFETY there is only SAFEGM's multihead record, so it
    is bad input pointing to COMBIN/2 (it was NotYetSupported until issue 22 wave 4)."""
    program.write_text("PARTNO P\nMACHIN/GECENT,23\nSAFETY/0.5,0,0\nFINI\n")
    with pytest.raises(InputError, match="COMBIN/2 must come first"):
        post(str(program), plugins)


W18 = DATA / "multihead" / "w18.apt"


def test_w18_code_signs_follow_the_primary_head(plugins: PluginSet, tmp_path: Path) -> None:
    """Spec 04 W18 (001 L8413-8424, L8726-8733, L8781-8790): one F register; head 2 has
    priority (PRFSEQ/ON on head 2), so a line-line pair is CODE -17 with head 2's feed
    command in the block's F; a linear head 1 with a circular head 2 is -17 too (the sign
    points at the circular head), after PREPHD's TABLEG(17) = G15, and head 1 carries the
    "arc-centre offsets" under the one G register, the circle's G31."""
    program = tmp_path / "w18.apt"
    program.write_text(W18.read_text().replace("OPTAB,139,0", "OPTAB,139,0,OPTAB,156,3"))
    result = post(str(program), plugins)
    combined = [b for b in result.blocks if b.halves is not None]
    assert [int(b.code) for b in combined] == [-17, -17, -17, -17]
    assert tape_line(combined[0]) == "N012G01X-001F0100U-001"
    lines = [tape_line(b) for b in result.blocks]
    g15 = lines.index("N021G15")
    circle = result.blocks[g15 + 1]
    assert circle.halves is not None and circle.halves[1].code is Code.CIRCLE_XY_CCLW
    words = dict(circle.halves[0].words)
    assert 10 in words  # head 1's K
    # the one G register's code sits in head 1's cell (GMHBUF(2)), head 2's is empty
    assert circle.halves[0].cells[2] == 31.0 and circle.halves[1].cells[2] is ABSENT
    assert tape_line(circle).startswith("N021G31Z-0005K")


def test_w18_a_pair_the_control_cannot_cut_together_is_not_split(plugins: PluginSet) -> None:
    """Option 156 = 1 (MACH51): circle on head 1 with a line on head 2 only; head 2's
    circle goes out alone, whole, after PREPHD's G15, while head 1's lines wait their turn."""
    result = post(str(W18), plugins)
    circles = [b for b in result.blocks if b.code is Code.CIRCLE_XY_CCLW]
    assert len(circles) == 1 and circles[0].head == 2
    assert tape_line(circles[0]) == "G31U+0005W-0005H0005E0020"
    assert result.cut_minutes == pytest.approx(0.1 + 0.05 + 0.05 + 0.25 * 3.14159265 / 10 + 0.05)


def test_the_manuals_multihead_fatal_errors(plugins: PluginSet, tmp_path: Path) -> None:
    """1020 (OP numbers of a head may not go down, 001 L29000-29010 catalogue), 7003 (only
    one head selected) and 3000 (a printout other than GEOUT3 given a multihead block)."""
    program = tmp_path / "p.apt"
    program.write_text(SEQUENCING.read_text().replace("OP/4\n", "OP/2\n", 1))
    with pytest.raises(FatalError) as raised:
        post(str(program), plugins)
    assert raised.value.number == 1020
    text = SEQUENCING.read_text()
    head_2 = text[text.index("SELECT/HEAD,2\nOP/2") : text.index("FINI")]
    program.write_text(text.replace(head_2, "").replace("SELECT/HEAD,2\nFROM/20,10,0\n", ""))
    with pytest.raises(FatalError) as raised:
        post(str(program), plugins)
    assert raised.value.number == 7003
    machine = tmp_path / "m51.toml"
    machine.write_text(
        (ROOT / "plugins" / "machines" / "mach51.toml")
        .read_text()
        .replace("164 = 3.0", "164 = 1.0")
    )
    tape, listing = tmp_path / "p.tape", tmp_path / "p.lis"
    result = CliRunner().invoke(
        main,
        ["post", str(SEQUENCING), "--machine", str(machine), "-o", str(tape),
         "--listing", str(listing)],
    )  # fmt: skip
    assert result.exit_code == 1
    assert "fatal error 3000" in result.output
    assert (not tape.exists() and "GEDUMP" in listing.read_text().upper()) or listing.exists()


HEADER = """PARTNO R
MACHIN/GECENT,51{options}
COMBIN/2
SELECT/HEAD,1
FROM/10,10,0
FEDRAT/10
SELECT/HEAD,2
FROM/20,10,0
FEDRAT/{feed}
"""


def _program(tmp_path: Path, body: str, options: str = "", feed: float = 10) -> str:
    program = tmp_path / "p.apt"
    program.write_text(HEADER.format(options=options, feed=f"{feed:g}") + body + "FINI\n")
    return str(program)


def _tape(blocks: list[Block]) -> list[str]:
    return [
        line for b in blocks if b.code is not Code.PARTNO and (line := tape_line(b)) is not None
    ]


def test_a_dwell_beside_a_move_is_a_zero_move(plugins: PluginSet, tmp_path: Path) -> None:
    """001 L8707-8710: a delay in a combined block has feed command 0 and no words; the
    other head's move is the block (no G04 shared with it, no dwell word in U)."""
    body = "SELECT/HEAD,1\nOP/1\nGOTO/10,9,0\nSELECT/HEAD,2\nOP/1\nDELAY/6\nGOTO/20,9,0\n"
    result = post(_program(tmp_path, body, ",OPTAB,139,0"), plugins)
    assert _tape(result.blocks) == ["N012G01Z-001F0100", "G01W-001E0100"]
    assert result.cut_minutes == pytest.approx(0.2)


def test_two_feed_registers_count_the_longer_head(plugins: PluginSet, tmp_path: Path) -> None:
    """Head 2 at 2 IPM takes 0.5 min for its inch while head 1 takes 0.1: the combined
    block takes 0.5."""
    body = "SELECT/HEAD,1\nOP/1\nGOTO/9,10,0\nSELECT/HEAD,2\nOP/1\nGOTO/19,10,0\n"
    result = post(_program(tmp_path, body, feed=2), plugins)
    assert result.cut_minutes == pytest.approx(0.5)


def test_split_pieces_add_up_on_the_tape(plugins: PluginSet, tmp_path: Path) -> None:
    """MACH51's X prints three decimals (REGFOR -33) while its step is 0.0001 in: the pieces
    are cut on 0.001 so that their words add up to the 0.3 in head 1 moves."""
    body = (
        "SELECT/HEAD,1\nFEDRAT/1\nOP/1\nGOTO/9.7,10,0\n"
        "SELECT/HEAD,2\nFEDRAT/7\nOP/1\nGOTO/19.9,10,0\nGOTO/19.8,10,0\nGOTO/19.7,10,0\n"
    )
    result = post(_program(tmp_path, body, ",OPTAB,139,0"), plugins)
    words = [w for line in _tape(result.blocks) for w in line.split("G") if "X" in w]
    total = sum(int(w.split("X")[1].split("F")[0].split("U")[0]) for w in words)
    assert total == -300  # thousandths of an inch


def test_an_end_waits_for_the_other_head(plugins: PluginSet, tmp_path: Path) -> None:
    """The ENDs close the program (001 L2263-2300): head 2's moves come before head 1's
    M02, though head 1's END comes first on its tape."""
    body = "SELECT/HEAD,1\nOP/1\nGOTO/11,10,0\nEND\nSELECT/HEAD,2\nOP/1\nGOTO/20,9,0\nGOTO/20,8,0\n"
    lines = _tape(post(_program(tmp_path, body), plugins).blocks)
    end = next(i for i, line in enumerate(lines) if "M02" in line)
    assert all("W" not in line for line in lines[end:])


def test_two_circles_need_two_g_registers(plugins: PluginSet, tmp_path: Path) -> None:
    """Option 156 = 2 allows circle-circle, but MACH51 has one G register (option 152 = 0,
    001 L8786-8788): the circles are cut one head after the other, none split."""
    body = (
        "SELECT/HEAD,1\nOP/1\nCIRCLE/11,10,0,0,0,1,1\nGOTO/11,9,0\n"
        "SELECT/HEAD,2\nOP/1\nCIRCLE/21,10,0,0,0,1,1\nGOTO/21,9,0\n"
    )
    result = post(_program(tmp_path, body, ",OPTAB,156,2"), plugins)
    circles = [b for b in result.blocks if b.code is Code.CIRCLE_XY_CCLW]
    assert len(circles) == 2 and not any(b.halves for b in result.blocks)
    with pytest.raises(InputError, match="a preparatory \\(G\\) register per head"):
        post(_program(tmp_path, body, ",OPTAB,156,2,OPTAB,152,1"), plugins)


GANTRY_HEADER = """PARTNO G
MACHIN/GECENT,51,OPTAB,139,0,OPTAB,155,1
COMBIN/2
SELECT/HEAD,1
FROM/0,1,0
SAFETY/0,0.5,0
FEDRAT/10
SELECT/HEAD,2
FROM/0,5,0
SAFETY/0,0.5,0
FEDRAT/10
"""


def _gantry(tmp_path: Path, plugins: PluginSet, body: str) -> list[Block]:
    program = tmp_path / "g.apt"
    program.write_text(GANTRY_HEADER + body + "FINI\n")
    blocks = post(str(program), plugins).blocks
    _gantry_holds(blocks, {1: [0, 10000], 2: [0, 50000]})
    return blocks


def _cuts(blocks: list[Block], head: int) -> list[tuple[int, ...]]:
    """The points a head's own moves reach (its program's, not parking's), in order."""
    return [
        part.position[:2]
        for block in blocks
        for part in block.halves or (block,)
        if part.head == head and part.position is not None and not part.rapid
        and part.code is not Code.FROM
    ]  # fmt: skip


@pytest.mark.parametrize(
    ("body", "cuts"),
    [
        # CL finer than the tape's 0.001: no cut lost, no endless pairing (review finding)
        (
            "SELECT/HEAD,1\nOP/1\nGOTO/3.14159,1,0\nGOTO/10,1,0\n"
            "SELECT/HEAD,2\nOP/1\nGOTO/10,5,0\n",
            {1: [(31416, 10000), (100000, 10000)], 2: [(31420, 50000), (100000, 50000)]},
        ),
        # moves before the other head's FROM was read: both FROMs first
        (
            "SELECT/HEAD,1\nGOTO/5,1,0\nOP/1\nGOTO/10,1,0\n"
            "SELECT/HEAD,2\nGOTO/5,5,0\nOP/1\nGOTO/10,5,0\n",
            {1: [(50000, 10000), (100000, 10000)], 2: [(50000, 50000), (100000, 50000)]},
        ),
        # a broken restriction: head 2 comes back by the axis, parked, after head 1
        (
            "SELECT/HEAD,1\nOP/1,RPM,10,10\nGOTO/10,1,0\nGOTO/20,1,0\n"
            "SELECT/HEAD,2\nOP/1,RPM,10,10\nGOTO/5,5,0\nFEDRAT/5\nGOTO/20,5,0\n",
            {1: [(50000, 10000), (100000, 10000), (200000, 10000)],
             2: [(50000, 50000), (200000, 50000)]},
        ),
        # a dwell is made at the head's own point, not where it stands parked
        (
            "SELECT/HEAD,1\nOP/1\nGOTO/10,1,0\nDELAY/5\nGOTO/10,2,0\n"
            "SELECT/HEAD,2\nOP/1\nGOTO/-10,5,0\n",
            {1: [(100000, 10000), (100000, 20000)], 2: [(-100000, 50000)]},
        ),
    ],
)  # fmt: skip
def test_gantry_review_cases(
    plugins: PluginSet, tmp_path: Path, body: str, cuts: dict[int, list[tuple[int, int]]]
) -> None:
    """Each head cuts its own CL points, the axis moving both heads alike."""
    blocks = _gantry(tmp_path, plugins, body)
    for head, points in cuts.items():
        assert _cuts(blocks, head) == points


def test_a_gantry_pair_on_one_feed_register_takes_the_longer_time(
    plugins: PluginSet, tmp_path: Path
) -> None:
    """Neither head moves along X: 1 in at 10 IPM beside 2 in at 10 IPM. The block takes
    the longer 0.2 min, the F of head 2 (the quicker head slowed, as Rule 2 slows it), never
    head 1's F that would drive head 2 at 20 IPM."""
    body = "SELECT/HEAD,1\nOP/1\nGOTO/0,2,0\nSELECT/HEAD,2\nOP/1\nGOTO/0,7,0\n"
    blocks = _gantry(tmp_path, plugins, body)
    combined = [b for b in blocks if b.halves is not None]
    assert [tape_line(b) for b in combined] == ["N014G01Z+001F0050W+002"]
    assert int(combined[0].code) == -17


def test_option_155_names_an_axis_the_machine_has(plugins: PluginSet, tmp_path: Path) -> None:
    program = tmp_path / "g.apt"
    program.write_text(GANTRY_HEADER.replace("155,1", "155,3") + "FINI\n")
    with pytest.raises(InputError, match="the machine has two axes"):
        post(str(program), plugins)


def test_a_safety_that_does_not_withdraw_is_refused(plugins: PluginSet, tmp_path: Path) -> None:
    program = tmp_path / "p.apt"
    program.write_text(PARKING.read_text().replace("SAFETY/0.5,0,0", "SAFETY/0.00001,0,0", 1))
    with pytest.raises(InputError, match="SAFETY does not withdraw the head"):
        post(str(program), plugins)
