"""Cycles on positioning and multiaxis machines (issue 22): CYCLE/IN on a positioning
machine (TABLEG(90) in a block by itself, CYCLGP 001 L30164-30182), what a modern control's
cycle cannot drill drilled by moves (core/motion/control_cycles.py ``unfit``), a machine
with no Z axis (option 59), and CYCLGX (001 L30206-30246): holes along the tool axis through
the transform class (MACH40, class 1) and the five-axis packs by data
(core/motion/multiaxis_cycles.py)."""

from __future__ import annotations

import re
from math import isclose, sqrt
from pathlib import Path

import pytest
from gecent.core.dispatch.post import post as post_file
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.machine.selection import resolve_machine
from gecent.core.motion.cycles import Cycle, cycle_legs
from gecent.core.motion.multiaxis_cycles import hole_frame, tool_axis_legs
from gecent.core.output.tape import tape_line, tape_lines
from gecent.core.plugins import get_plugins

from .test_post_linear import post


def overlay(base: str, text: str) -> MachineDefinition:
    machine = resolve_machine(get_plugins(), base, None)
    return load_machine_text(f'[machine]\nname = "t"\ntitle = "T"\n{text}', base=machine)


def pack_tape(tmp_path: Path, text: str, machine: object) -> tuple[list[str], list[str]]:
    """The tape's lines and the warnings of ``text`` posted on ``machine``."""
    source = tmp_path / "part.apt"
    source.write_text(text)
    result = post_file(str(source), get_plugins(), machine)  # type: ignore[arg-type]
    return tape_lines(result.blocks), [note.text for note in result.diagnostics]


# -- positioning: CYCLE/IN -----------------------------------------------------------------


def test_in_on_a_positioning_machine_is_its_withdrawal_code_by_itself() -> None:
    """MACH24 given MACH40's OUT and IN codes (TABLEG(89) = 50, (90) = 59, 001 L27904-27905):
    OUT is the control's cycle block (Z the plunge from the tool's 2 to the bottom -1 = 3,
    R the rapid distance to top + CLEAR = 1.9) and the hole's XY runs it; IN is G59 alone
    in a CODE -16 block at the statement (no plunge, no R); the points after it are plain
    positions with the cycle-off G80 (TABLEG(1))."""
    mach24 = overlay("mach24", "[tableg]\n89 = 50\n90 = 59\n")
    result = post(
        [
            "SPINDL/100,CLW",
            "FROM/0,0,2",
            "FEDRAT/10",
            "CYCLE/OUT,DEPTH,1,CLEAR,0.1",
            "GOTO/1,1,0",
            "CYCLE/IN",
            "GOTO/3,1,0",
            "CYCLE/OFF",
            "GOTO/4,4,2",
        ],
        mach24,
    )
    assert tape_lines(result.blocks)[1:] == [
        "N005G50Z+030000F20R+019",
        "N005X+010000Y-010000",
        "N006G59",
        "N007G80X+030000",
        "N009X+040000Y-040000",
    ]


def test_in_on_a_positioning_machine_without_its_code_is_named() -> None:
    mach24 = resolve_machine(get_plugins(), "mach24", None)
    with pytest.raises(InputError, match=r"CYCLE/IN on a positioning machine .*TABLEG\(90\)"):
        post(["CYCLE/IN"], mach24)


# -- a modern control: what its cycle cannot drill is drilled by moves ---------------------

HOLE = (
    "PARTNO T\nUNITS/MM\nFROM/0,0,10\nFEDRAT/100\nSPINDL/500,{direction}\n{cycle}\n"
    "GOTO/1,1,0\nCYCLE/OFF\nFINI\n"
)


def test_a_left_hand_tap_is_drilled_by_moves_with_the_spindle_reversed(tmp_path: Path) -> None:
    """G84 taps right-handed; with the spindle CCLW the tap goes in at M04 and comes out at
    M03, then the spindle turns CCLW again (TABLEM(4) = M03, (5) = M04)."""
    text = HOLE.format(direction="CCLW", cycle="CYCLE/TAP,DEPTH,5,CLEAR,2,MMPM,50")
    lines, notes = pack_tape(tmp_path, text, "linuxcnc-mill")
    assert lines[3:9] == [
        "N1 S500 M04",
        "N2 G00 X1. Y1. Z10.",
        "N3 Z2.",
        "N4 G01 Z-5. F50.",
        "N5 Z2. M03",
        "N6 M04",
    ]
    assert notes == [
        "CYCLE/TAP IS DRILLED BY MOVES: A LEFT-HAND TAP (SPINDLE CCLW) HAS NO TABLEG CODE"
    ]
    right, _ = pack_tape(tmp_path, text.replace("CCLW", "CLW"), "linuxcnc-mill")
    assert "N3 G84 X1. Y1. Z-5. F50. R2." in right


@pytest.mark.parametrize(
    ("cycle", "machine", "reason"),
    [
        ("CYCLE/OUT,DEPTH,5,CLEAR,2", "[tableg]\n89 = 89\n", "CYCLE/OUT HAS NO G-CODE"),
        ("CYCLE/DRILL,DEPTH,5,CLEAR,2,RETURN,4", "", "TO R OR TO THE START LEVEL ONLY"),
        ("CYCLE/DRILL,DEPTH,5,CLEAR,2", "[regfor]\n16 = 0\n", "NO R REGISTER"),
        ("CYCLE/DEEP,DEPTH,5,STEP,2,CLEAR,2", "[regfor]\n21 = 0\n", "NO PECK REGISTER Q"),
        (
            "CYCLE/DRILL,DEPTH,5,CLEAR,2",
            '[tableg]\n126 = "absent"\n',
            r"NO RETURN CODE TABLEG\(126\)",
        ),
        ("CYCLE/BORE,DWELL,1,DEPTH,5,CLEAR,2", "", r"NO G CODE TABLEG\(94\) FOR BORE,DWELL"),
        ("CYCLE/TAP,DEPTH,5,CLEAR,2,DWELL,1", "", "TAP TAKES NO DWELL"),
    ],
)
def test_each_form_the_control_cannot_drill_is_named_and_drilled_by_moves(
    tmp_path: Path, cycle: str, machine: str, reason: str
) -> None:
    """No cycle G code on the tape: the hole is R at rapid, the bottom at feed (Z-5.)."""
    text = HOLE.format(direction="CLW", cycle=cycle)
    lines, notes = pack_tape(tmp_path, text, overlay("linuxcnc-mill", machine))
    assert not any(f" G8{n}" in line for line in lines[3:] for n in range(1, 10))
    assert "N3 Z2." in lines and any("Z-5." in line for line in lines)
    assert len(notes) == 1 and " IS DRILLED BY MOVES: " in notes[0]
    assert re.search(reason, notes[0])


def test_return_to_another_level_goes_back_there_by_moves(tmp_path: Path) -> None:
    text = HOLE.format(direction="CLW", cycle="CYCLE/DRILL,DEPTH,5,CLEAR,2,RETURN,4")
    lines, _ = pack_tape(tmp_path, text, "linuxcnc-mill")
    assert lines[lines.index("N4 G01 Z-5. F100.") + 1] == "N5 G00 Z4."


# -- no Z axis ------------------------------------------------------------------------------


def test_a_machine_without_z_has_no_axis_to_drill_along() -> None:
    flat = load_machine_text('[machine]\nname = "xy"\ntitle = "XY"\n[optab]\n59 = 131400\n')
    with pytest.raises(InputError, match=r"CYCLE/DRILL .*option 59 = 131400.* no spindle axis"):
        post(["FROM/0,0,1", "CYCLE/DRILL,1,IPM,2,0.1", "GOTO/0,0,0"], flat)


# -- CYCLGX: holes along the tool axis --------------------------------------------------------


def test_the_hole_frame_is_orthonormal_and_the_part_s_axes_for_a_vertical_tool() -> None:
    assert hole_frame((0.0, 0.0, 1.0)) == ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
    for axis in ((1.0, 0.0, 0.0), (0.0, 0.6, 0.8), (1 / sqrt(3),) * 3, (0.0, 0.0, -1.0)):
        e1, e2, e3 = hole_frame(axis)  # type: ignore[arg-type]
        vectors = (e1, e2, e3)
        for a in range(3):
            for b in range(3):
                dot = sum(vectors[a][n] * vectors[b][n] for n in range(3))
                assert isclose(dot, 1.0 if a == b else 0.0, abs_tol=1e-12)
        cross = (
            e1[1] * e2[2] - e1[2] * e2[1],
            e1[2] * e2[0] - e1[0] * e2[2],
            e1[0] * e2[1] - e1[1] * e2[0],
        )
        assert all(isclose(c, t, abs_tol=1e-12) for c, t in zip(cross, e3, strict=True))


def test_tool_axis_legs_along_z_are_the_three_axis_legs() -> None:
    cycle = Cycle("DEEP", 3.5, 1.0, step=1.0, axis=2)
    at, hole = (0.0, 0.0, 5.0), (2.0, 1.0, 0.5)
    three = cycle_legs(cycle, at, hole, 5.0)
    tilted = tool_axis_legs(cycle, at, hole, (0.0, 0.0, 1.0), 5.0)
    assert [point[:3] for point, _ in tilted] == [leg.point for leg in three]
    assert all(point[3:] == (0.0, 0.0, 1.0) for point, _ in tilted)


MACH40_HOLES = [
    "MACHIN/GECENT,40",
    "FROM/0,0,10,0,0,1",
    "FEDRAT/10",
    "GOTO/1,0,10,0,0.6,0.8",
    "CYCLE/DRILL,1,IPM,10,0.1",
    "GOTO/1,0,0,0,0.6,0.8",
    "GOTO/2,0,0",
]


def mach40() -> MachineDefinition:
    """MACH40 with TABLEG(11) = G10 (as tests/test_multiaxis_motion.py gives it: the manual's
    examples assume every code, 001 L6127-6128)."""
    pack = get_plugins().machine("mach40")
    assert pack is not None
    return load_machine_text(
        '[machine]\nname = "m40"\ntitle = "M40"\n[tableg]\n11 = 10\n', "m40.toml", pack.load()
    )


def test_mach40_drills_along_the_tilted_tool_axis_through_class_1() -> None:
    """MACH40, class 1, R + TL = 4, the tool along u = (0, .6, .8): C = 90 and A stay, and
    the machine point is (x, y + 2.4, z + 3.2) (tests/test_multiaxis_motion.py), so each leg
    of the hole moves the machine as it moves the tip along u. By hand, from the tip at
    (1, 0, 10), level 10 x .8 = 8 along u, to the hole top (1, 0, 0), level 0:

    * across at level 8 to (1, 0, 0) + 8u = (1, 4.8, 6.4): Y+4.8 Z-3.6 (the first move
      after the turn: G01);
    * rapid to R, level .1: -7.9u = Y-4.74 Z-6.32;
    * feed to the bottom, level -1: -1.1u = Y-.66 Z-.88; rapid back to R: Y+.66 Z+.88;
    * the next hole (2, 0, 0) is on the same face (level 0): across at R, X+1 only, then in
      to the bottom and back to R. A and C never turn inside the cycle."""
    lines = [line for line in (tape_line(b) for b in post(MACH40_HOLES, mach40()).blocks) if line]
    holes = [line for line in lines if line.startswith(("N006", "N007"))]
    assert holes == [
        "N006G01Y+48Z-36F4167",
        "N006Y-474Z-632F3165",
        "N006G11Y-066Z-088F0091",
        "N006Y+066Z+088F2273",
        "N007G01X+1F9999",  # (already at R: the next leg feeds in)
        "N007G11Y-066Z-088F0091",
        "N007Y+066Z+088F2273",
    ]


def test_mach40_a_hole_along_another_axis_than_the_tool_s_is_named() -> None:
    # (OUT: DRILL's five-axis hole pattern is built, tests/test_five_axis_hole_pattern.py)
    program = [*MACH40_HOLES[:-1], "GOTO/2,0,0,0,0,1"]
    program[4] = "CYCLE/OUT,DEPTH,1,CLEAR,0.1"
    # (not yet supported until wave 7: the tool CYCLE/OUT left in the hole cannot turn there)
    with pytest.raises(InputError, match=r"tool axis \(0, 0, 1\) is not the one.*CYCLE/IN"):
        post(program, mach40())


FIVE_AXIS_HOLES = """PARTNO HOLES
UNITS/MM
MULTAX
LOADTL/1,LENGTH,100
SPINDL/1000,CLW
FROM/0,0,100,0,0,1
RAPID
GOTO/10,0,50,0,0,1
CYCLE/DRILL,DEPTH,5,CLEAR,2,MMPM,100
GOTO/10,0,0,0,0,1
GOTO/20,0,0
CYCLE/OFF
RAPID
GOTO/20,0,50,0.7071068,0,0.7071068
CYCLE/DEEP,DEPTH,6,STEP,2,CLEAR,2,MMPM,100,RETURN,0
GOTO/20,0,0,0.7071068,0,0.7071068
GOTO/20,10,0,0.7071068,0,0.7071068
CYCLE/OFF
FINI
"""


def test_fanuc_5axis_bc_drills_vertical_and_tilted_holes_by_hand(tmp_path: Path) -> None:
    """The control's tool centre point (G43.4): X, Y, Z are the tip in the part.

    * vertical DRILL: the three-axis legs, R = 2, bottom -5, back to R; the next hole at R;
    * DEEP along u = (.7071, 0, .7071) (B45) from the tip at (20, 0, 50), level 49.497,
      hole top (20, 0, 0): across at that level to (20, 0, 0) + 35.355u = (45, 0, 25); R
      = top + 2u = (21.414, 0, 1.414); pecks of 2 from the top: -2u (18.586, -1.414), -4u
      (17.172, -2.828), each back to R; the bottom -6u (15.757, -4.243); RETURN,0 back to
      the start level (45, 0, 25); the next hole 10 along Y, on the same face."""
    lines, _ = pack_tape(tmp_path, FIVE_AXIS_HOLES, "fanuc-5axis-bc")
    start = lines.index("N3 G00 X10. Y0. Z50. B0. C0.")
    assert lines[start + 1 : start + 24] == [
        "N4 Z2.",
        "N5 G01 Z-5. F100.",
        "N6 G00 Z2.",
        "N7 X20.",
        "N8 G01 Z-5.",
        "N9 G00 Z2.",
        "N10 Z50. B45.",
        "N11 X45. Z25.",
        "N12 X21.414 Z1.414",
        "N13 G01 X18.586 Z-1.414",
        "N14 G00 X21.414 Z1.414",
        "N15 G01 X17.172 Z-2.828",
        "N16 G00 X21.414 Z1.414",
        "N17 G01 X15.757 Z-4.243",
        "N18 G00 X45. Z25.",
        "N19 Y10.",
        "N20 X21.414 Z1.414",
        "N21 G01 X18.586 Z-1.414",
        "N22 G00 X21.414 Z1.414",
        "N23 G01 X17.172 Z-2.828",
        "N24 G00 X21.414 Z1.414",
        "N25 G01 X15.757 Z-4.243",
        "N26 G00 X45. Z25.",
    ]


def test_linuxcnc_5axis_ac_tilts_the_part_so_the_hole_is_drilled_along_z(tmp_path: Path) -> None:
    """Slides computed (option 265 = 0): the trunnion turns the tilted hole's axis onto the
    machine's Z, so inside the hole only Z moves, by the pecks' own lengths: R to the first
    peck 4 (CLEAR 2 + STEP 2), then 6 and 8 to the bottom; no rotary axis turns in it."""
    lines, _ = pack_tape(tmp_path, FIVE_AXIS_HOLES, "linuxcnc-5axis-ac")
    first = lines.index(next(line for line in lines if "A-45." in line))
    hole = lines[first + 2 : first + 9]
    assert all(" X" not in line and " Y" not in line and " A" not in line for line in hole)
    depths = [float(line.rsplit("Z", 1)[1]) for line in hole]
    plane = depths[0]
    assert [round(plane - d, 3) for d in depths[1::2]] == [4.0, 6.0, 8.0]
    assert depths[2:6:2] == [plane, plane]  # back to R after each peck
