"""The Mark Century 7500's mixed control, option 1 = 3 (positioning with contouring,
option 132 = 8; 001 L24352-24356, L25958), and option 213 (L26636-26649): rapid moves and
holes go out by the positioning control (absolute, GEPOS), feed moves by the contouring
control (departures, GETERP) from the same present point (core/motion/mixed.py;
docs/decisions.md, issue 22 wave 8).

The machine M7500 is the sample drill MACH24 (manual §5.6.8.1) given the 7500's
contouring option: option 1 = 3, option 132 = 8, option 130 = +1 (Z in a block of its
own), circular interpolation (option 9 = 1) with unsigned I and J of format 24 and option
60 = 162718 (I and J follow X and Y's signs, +I -J). What it keeps from MACH24: X, Y, Z
formats -24, option 59 = 132415 (+X -Y +Z), G80 at TABLEG(1) and G81.. at 82.., the
positioning feed type 0 with K = 2, option 45 = 99 (the rapid command), option 24 = 99
(the largest feed command), option 40 = 1, an R register of format -22; from the
Standard Machine: G01 = TABLEG(2), G03 = TABLEG(4), option 10 = 0 (F = IPM x DIMULT / L,
DIMULT 10 for the 0-9.9999 in class, an arc's L its radius), options 38 = 0 and 107 = 1
(a repeated G or F is left out).

Every tape below is worked by hand from those numbers.
"""

from __future__ import annotations

import pytest
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import MachineFileInvalid, load_machine_text
from gecent.core.output.block import Code
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post

M7500 = """
[optab]
1 = 3.0
132 = 8.0
130 = 1.0
9 = 1.0
60 = 162718.0
[regfor]
8 = 24.0
9 = 24.0
"""


def m7500(options: str = "") -> MachineDefinition:
    """M7500, with more ``[optab]`` lines when given."""
    base = get_plugins().machine("mach24").load()
    text = M7500.replace("[optab]\n", f"[optab]\n{options}")
    return load_machine_text(f'[machine]\nname = "m7500"\n{text}', "m7500.toml", base=base)


def tape(lines: list[str], machine: MachineDefinition | None = None) -> list[str]:
    return tape_lines(post(lines, machine or m7500()).blocks)


def test_rapid_moves_are_positions_and_feed_moves_departures() -> None:
    """RAPID to (1,1,5): a positioning block, G80 X1 Y-1 absolute with their trailing
    zeros, F99 the rapid command (option 45); RAPID down to Z1: option 130 = +1's Z block
    (G80 and F99 repeated, so left out). At feed 10 IPM to (3,1,1): a departure X+2 in
    G01, zeros dropped, F = 10 x 10 / 2 = 50; to (3,3,1): Y+2 is Y-02 (option 59), F50
    again, left out. RAPID up to Z5: XY did not move, so the Z block alone, G80 and F99
    again after the contouring G01 F50."""
    assert tape(
        [
            "FROM/0,0,5",
            "FEDRAT/10",
            "RAPID",
            "GOTO/1,1,5",
            "RAPID",
            "GOTO/1,1,1",
            "GOTO/3,1,1",
            "GOTO/3,3,1",
            "RAPID",
            "GOTO/3,3,5",
        ]
    ) == [
        "N004G80X+010000Y-010000F99",
        "N006Z+010000",
        "N007G01X+02F50",
        "N008Y-02",
        "N010G80Z+050000F99",
    ]


def test_block_codes_follow_the_way_each_move_went() -> None:
    result = post(["FROM/0,0,5", "FEDRAT/10", "RAPID", "GOTO/1,1,5", "GOTO/3,1,5"], m7500())
    codes = [b.code for b in result.blocks if b.code not in (Code.FROM, Code.FINI)]
    assert codes == [Code.POSITION_XY, Code.LINEAR]


def test_holes_go_by_the_positioning_controls_cycle_between_contours() -> None:
    """A contour X+2 (F50); CYCLE/DRILL,2,IPM,5,.1 at the top Z0 from the height Z5: the
    cycle block G81, Z = the plunge 5 - (0 - 2) = 7, R = the rapid distance 5 - 0.1 = 4.9,
    F = 2 x 5 = 10 (feed type 0); the first hole is at the present XY (2,0), so both X and
    Y go out (the control needs a block to drill, and contouring has made its held words
    stale); the second moves X only (option 40). After CYCLE/OFF the feed move Y+2 at the
    cycle's 5 IPM is a departure again: G01 Y-02, F = 5 x 10 / 2 = 25."""
    assert tape(
        [
            "FROM/0,0,5",
            "FEDRAT/10",
            "GOTO/2,0,5",
            "CYCLE/DRILL,2,IPM,5,.1",
            "GOTO/2,0,0",
            "GOTO/4,0,0",
            "CYCLE/OFF",
            "GOTO/4,2,5",
        ]
    ) == [
        "N003G01X+02F50",
        "N005G81Z+070000F10R+049",
        "N005X+020000Y+000000",
        "N006X+040000",
        "N008G01Y-02F25",
    ]


def test_arcs_are_the_contouring_controls_and_a_rapid_move_spends_the_circle() -> None:
    """At 5 IPM the line to (4,1,5): X+4 Y-1, L = sqrt(17) = 4.1231, F = 50 / 4.1231 =
    12.13, so F12. The quarter circle about (4,2) to (5,2): G03 (counterclockwise in the
    CL plane), departures X+1 Y-1, I = |4 - 4| = 0 left out, J = |2 - 1| = 1, F = 5 x 10
    / radius 1 = 50. A second CIRCLE then RAPID to (0,0,5): no arc, a positioning block
    G80 X0 Y0 (a zero position is a target, so it is punched) at F99."""
    assert tape(
        [
            "FROM/0,0,5",
            "FEDRAT/5",
            "GOTO/4,1,5",
            "CIRCLE/4,2,5,0,0,1,1",
            "GOTO/5,2,5",
            "CIRCLE/4,2,5,0,0,1,1",
            "RAPID",
            "GOTO/0,0,5",
        ]
    ) == [
        "N003G01X+04Y-01F12",
        "N005G03X+01Y-01J01F50",
        "N008G80X+000000Y+000000F99",
    ]


def test_godlta_goes_the_way_of_its_feed() -> None:
    """GODLTA/2,0,0 at feed: a departure X+2 (F50); RAPID GODLTA/0,0,-3: the absolute Z
    5 - 3 = 2 in a Z block (G80, F99); GODLTA/0,2,0 at feed: Y-02 from there, F50."""
    assert tape(
        ["FROM/0,0,5", "FEDRAT/10", "GODLTA/2,0,0", "RAPID", "GODLTA/0,0,-3", "GODLTA/0,2,0"]
    ) == ["N003G01X+02F50", "N005G80Z+020000F99", "N006G01Y-02F50"]


def test_a_modal_rapid_positions_until_fedrat() -> None:
    """Option 109 = -1: RAPID holds until FEDRAT. Both moves after it are positions (the
    second moves X only: Y is held, option 40); after FEDRAT/10 the move X+1 is a
    departure, F = 10 x 10 / 1 = 100, held to option 24's 99: the rapid's F99 is in the
    register already, so the F is left out (option 107 = 1)."""
    machine = m7500("109 = -1.0\n")
    assert tape(
        ["FROM/0,0,5", "RAPID", "GOTO/1,1,5", "GOTO/2,1,5", "FEDRAT/10", "GOTO/3,1,5"], machine
    ) == ["N003G80X+010000Y-010000F99", "N004X+020000", "N006G01X+01"]


def test_a_position_after_contouring_repeats_the_held_coordinate() -> None:
    """Rapid to X1 Y1 (held); a departure X+2 at feed; rapid back to (1,1,5): X1 again, and
    Y1 too, though the positioning control last had Y1: after departures its held words
    are stale, so option 40 does not leave Y out."""
    assert tape(
        ["FROM/0,0,5", "FEDRAT/10", "RAPID", "GOTO/1,1,5", "GOTO/3,1,5", "RAPID", "GOTO/1,1,5"]
    ) == ["N004G80X+010000Y-010000F99", "N005G01X+02F50", "N007G80X+010000Y-010000F99"]


def test_fedrat_is_not_snapped_to_the_positioning_feeds() -> None:
    """FEDRAT/7.3: the contouring move X+1 makes F = 7.3 x 10 / 1 = 73 at 7.3 IPM; the
    hole's positioning block makes type 0's F = round(2 x 7.3) = 15, the feed 7.5 IPM
    (POSFED at output; a positioning machine would have snapped FEDRAT to 7.5 for both)."""
    result = post(
        [
            "FROM/0,0,5",
            "FEDRAT/7.3",
            "GOTO/1,0,5",
            "CYCLE/DRILL,1,IPM,7.3,.1",
            "GOTO/2,0,0",
            "CYCLE/OFF",
        ],
        m7500(),
    )
    moves = [b for b in result.blocks if b.code in (Code.LINEAR, Code.POSITION_XY)]
    assert [(b.code, b.cells[11], b.cells[19]) for b in moves] == [
        (Code.LINEAR, 73.0, 7.3),
        (Code.POSITION_XY, 15.0, 7.5),
    ]


def _problems(text: str) -> list[str]:
    base = get_plugins().machine("mach24").load()
    with pytest.raises(MachineFileInvalid) as caught:
        load_machine_text(f'[machine]\nname = "bad"\n{text}', "bad.toml", base=base)
    return [f"[{p.table}] {p.entry}: {p.rule}" for p in caught.value.problems]


def test_a_mixed_machine_needs_z_positions_and_both_g_codes() -> None:
    found = _problems('[optab]\n1 = 3.0\n132 = 8.0\n[tableg]\n1 = "absent"\n')
    assert any(p.startswith("[optab] 130: option 1 = 3") for p in found)
    assert any(p.startswith("[tableg] 1: option 1 = 3") for p in found)


def test_option_132_8_needs_the_mixed_control() -> None:
    found = _problems("[optab]\n132 = 8.0\n130 = 1.0\n")
    assert any(p.startswith("[optab] 132: option 132 = 8") for p in found)


def test_option_213_needs_a_positioning_control_that_outputs_z() -> None:
    """Option 213 = 1: a contouring machine driven by a positioning control; on a
    contouring control (option 1 = 0) it is bad input, and so is option 130 = 0 (MACH24's),
    which would drop the Z of a cut; any other value than 0 or 1 is bad input."""
    found = _problems("[optab]\n213 = 1.0\n1 = 0.0\n")
    assert any(p.startswith("[optab] 213: option 213 = 1") for p in found)
    found = _problems("[optab]\n213 = 1.0\n")
    assert any(p.startswith("[optab] 130: option 213 = 1") for p in found)
    found = _problems("[optab]\n213 = 2.0\n130 = 1.0\n")
    assert any(p.startswith("[optab] 213: contouring machine") for p in found)


def test_option_213_machine_posts_its_cuts_as_positions_with_z() -> None:
    """With option 213 = 1 and option 130 = +1 every motion is the positioning control's:
    the cut down to Z2 at 10 IPM is a Z block (F = 2 x 10 = 20), the cut along X an
    absolute X3 with Y1 (no block has given Y yet: FROM outputs nothing)."""
    base = get_plugins().machine("mach24").load()
    machine = load_machine_text(
        '[machine]\nname = "m213"\n[optab]\n213 = 1.0\n130 = 1.0\n132 = 7.0\n', "m.toml", base=base
    )
    assert tape(["FROM/1,1,5", "FEDRAT/10", "GOTO/1,1,2", "GOTO/3,1,2"], machine) == [
        "N003G80Z+020000F20",
        "N004X+030000Y-010000",
    ]


def test_a_thread_is_cut_by_the_contouring_control() -> None:
    """PITCH/16 THREAD/TURN at feed along X: the contouring control's thread block, G33
    (TABLEG(34) given for the test) with the departure X+1 and the six-digit lead .062500
    in I, its leading zero passed over and its trailing zeros dropped (I625); the RAPID
    after it (the thread is spent) is a position again: G80 X0 Y0 F99."""
    base = get_plugins().machine("mach24").load()
    machine = load_machine_text(
        f'[machine]\nname = "m7500"\n{M7500}[tableg]\n34 = 33\n', "m7500.toml", base=base
    )
    thread = ["SPINDL/100,CLW", "PITCH/16", "THREAD/TURN", "FEDRAT/5", "GOTO/1,0,5"]
    blocks = tape(["FROM/0,0,5", *thread, "RAPID", "GOTO/0,0,5"], machine)
    assert blocks[-2:] == ["N006G33X+01I625", "N008G80X+000000Y+000000F99"]


def test_describe_names_the_mixed_control() -> None:
    from gecent.core.machine.describe import describe_machine

    text = describe_machine(m7500())
    assert "type: positioning with contouring (option 132)" in text
    assert "positioning and contouring (7500) control (option 1)" in text
