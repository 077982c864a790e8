"""SAFETY on a single-head machine (core/statements/safety.py) and SELECT/HED's heads
(core/statements/select.py): the lathe's SAFETY modes (SAFEGL, TABLEM(37)-(40),
001 L23200-23206, option 21 L24633-24644), the R-register code (SAFEGX,
001 L36554-36611, spec 08 W-4) and SELHED's heads (001 L36846-36893)."""

from __future__ import annotations

import pytest
from gecent.core.errors import InputError, MachineDefinitionError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.output.block import Code
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post

NOT_AVAILABLE = "REQUESTED MISCELLANEOUS FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE"


def mach04() -> MachineDefinition:
    """The sample lathe: TABLEM(37) = 36 turn, (38) = 38 face, (39) = 37 bore, (40) = 39
    off (001 L27708-27711), option 21 = 1, modal SAFETY (L27745)."""
    return get_plugins().machine("mach04").load()


def lathe(options: str, tablem: str = "") -> MachineDefinition:
    """The Standard Machine as a lathe (option 132 = 0), without safety codes unless
    ``tablem`` gives them."""
    text = (
        '[machine]\nname = "lathe"\ntitle = "LATHE"\n'
        f"[tablem]\n{tablem}[optab]\n132 = 0.0\n{options}"
    )
    return load_machine_text(text, "lathe.toml")


def r_machine() -> MachineDefinition:
    """MACH40, the sample multiaxis mill (option 116 ≠ 0: GEMAXS), given an R register
    REGFOR(16) = 30 for SAFEGX's three digits (MACH40 itself has none). Its option 98 =
    200 puts F200 in every non-motion block (001 L25585-25602)."""
    base = get_plugins().machine("mach40").load()
    text = '[machine]\nname = "mach40r"\ntitle = "MACH40 WITH R"\n[regfor]\n16 = 30.0\n'
    return load_machine_text(text, "mach40r.toml", base)


LATHE_MOVES = ["FROM/0,0,0", "FEDRAT/10"]


# ---------------------------------------------------------------- SAFEGL (lathe)


def test_lathe_safety_codes_ride_the_next_motion_on_mach04() -> None:
    """SAFEGL's STOREM: each mode's code waits for the next block, the motion's; modal
    (option 21 = 1), so the code is given once and stays until SAFETY/OFF's M39."""
    lines = [
        *LATHE_MOVES,
        "SAFETY/TURN",
        "GOTO/1,0,1",
        "GOTO/2,0,2",
        "SAFETY/OFF",
        "GOTO/3,0,3",
        "SAFETY/FACE",
        "GOTO/2,0,2",
        "SAFETY/BORE",
        "GOTO/1,0,1",
    ]
    punched = [line for line in tape_lines(post(lines, mach04()).blocks)]
    assert punched == [
        "N004G01Z+1F100M36",
        "N005G01Z+1",
        "N007G01Z+1M39",
        "N009G01Z-1M38",
        "N011G01Z-1M37",
    ]


def test_a_waiting_safety_code_is_pushed_out_by_the_next() -> None:
    """STOREM (001 L38041-38087): two SAFETY statements before a motion: the first code
    goes out in a block of its own (MACH04's non-motion blocks carry G04), the second
    rides the motion."""
    blocks = post([*LATHE_MOVES, "SAFETY/BORE", "SAFETY/FACE", "GOTO/1,0,1"], mach04()).blocks
    assert tape_lines(blocks) == ["N004G04M37", "N005G01Z+1F100M38"]


def test_a_lathe_without_the_code_gets_comment_22() -> None:
    result = post([*LATHE_MOVES, "SAFETY/TURN", "GOTO/1,0,1"], lathe("21 = 1.0\n"))
    assert [d.text for d in result.diagnostics][-1] == NOT_AVAILABLE
    assert not any("M" in line for line in tape_lines(result.blocks))


def test_one_shot_safety_is_named_not_built() -> None:
    """Option 21 = 0 was NotYetSupported until the run gained its hook before each motion
    record (wave 4, core/run.py's safety_motion call): the statement is taken now, and
    tests/test_safety_wave4.py tests the codes it gives. (The name stays: checklist item
    02-37 names this test.)"""
    assert tape_lines(post(["SAFETY/FACE"], lathe("21 = 0.0\n", "38 = 38\n")).blocks) == []


def test_safety_off_under_one_shot_outputs_the_off_code() -> None:
    machine = lathe("21 = 0.0\n", "40 = 39\n")
    lines = tape_lines(post([*LATHE_MOVES, "SAFETY/OFF", "GOTO/1,0,1"], machine).blocks)
    assert lines[-1].endswith("M39")


def test_option_21_must_be_zero_or_one() -> None:
    with pytest.raises(MachineDefinitionError, match="option 21 = 2"):
        post(["SAFETY/TURN"], lathe("21 = 2.0\n"))


@pytest.mark.parametrize("statement", ["SAFETY/0.1,0,0", "SAFETY", "SAFETY/TURN,FACE", "SAFETY/UP"])
def test_lathe_safety_forms(statement: str) -> None:
    with pytest.raises(InputError, match="TURN, FACE, BORE or OFF"):
        post([statement], mach04())


# ---------------------------------------------------------------- SAFEGX (R code)


def test_w4_r304_is_x_plus_point_1_and_z_minus_point_1() -> None:
    """Spec 08 W-4 (001 L36577-36592): "address R304 would indicate that the X axis is to
    move .1 inch in the plus direction and the z is to move .1 inch in the minus
    direction": SAFETY/.1,0,-.1 -> R304 in a block of its own."""
    blocks = post(["SAFETY/0.1,0,-0.1"], r_machine()).blocks
    assert [b.cells[16] for b in blocks if b.code is Code.NONMOTION] == [304.0]
    assert tape_lines(blocks) == ["N001F200R304"]


@pytest.mark.parametrize(
    ("move", "code"),
    [(0.01, "R111"), (-0.01, "R222"), (0.1, "R333"), (-0.1, "R444"), (1.0, "R555"), (-1.0, "R666")],
)
def test_safegx_table(move: float, code: str) -> None:
    """The manual's table R111 ... R666: the same move on X, Y and Z."""
    lines = tape_lines(post([f"SAFETY/{move},{move},{move}"], r_machine()).blocks)
    assert lines == [f"N001F200{code}"]


def test_metric_moves_are_read_in_inches() -> None:
    """The table is in inches: 2.54 mm is .1 inch."""
    lines = tape_lines(post(["UNITS/MM", "SAFETY/0,-2.54,0"], r_machine()).blocks)
    assert lines == ["N002F200R040"]


def test_safety_off_sets_the_code_to_zero_and_outputs_nothing() -> None:
    assert tape_lines(post(["SAFETY/OFF"], r_machine()).blocks) == []


@pytest.mark.parametrize(
    ("statement", "message"),
    [
        ("SAFETY/0.1,0,-0.01", "one size in a statement"),  # "only one of the three values"
        ("SAFETY/0.2,0,0", "one size in a statement"),
        ("SAFETY/0.1,0", "expects OFF or the moves"),
        ("SAFETY/TURN", "expects OFF or the moves"),
        ("SAFETY/0,0,0", "moves no axis"),
    ],
)
def test_safegx_forms(statement: str, message: str) -> None:
    with pytest.raises(InputError, match=message):
        post([statement], r_machine())


def test_a_multiaxis_machine_without_an_r_register() -> None:
    with pytest.raises(InputError, match=r"no R register \(REGFOR\(16\)\)"):
        post(["SAFETY/0.1,0,0"], get_plugins().machine("mach40").load())


def test_a_single_head_mill_has_no_safety() -> None:
    """The Standard Machine is a three-axis mill: neither SAFEGL nor SAFEGX is its. It was
    NotYetSupported; wave 4 made it bad input (the manual defines only the multihead
    SAFEGM there), tested further in tests/test_safety_wave4.py."""
    with pytest.raises(InputError, match="COMBIN/2 must come first"):
        post(["SAFETY/0.1,0,0"], standard_machine())


# ---------------------------------------------------------------- SELECT/HED (SELHED)


def heads(extra: str = "") -> MachineDefinition:
    """Head 1 - On = M61, Head 2 - On = M62, Engage Bar = M57 (TABLEM 125, 126, 57); no
    head 3 code; rapid by option 42 with gear shifts (option 46 = -1, TABLEM(42)/(43))."""
    text = (
        '[machine]\nname = "heads"\ntitle = "HEADS"\n'
        f"[tablem]\n125 = 61\n126 = 62\n57 = 57\n42 = 40\n43 = 41\n{extra}"
        "[optab]\n46 = -1.0\n42 = 100.0\n"
    )
    return load_machine_text(text, "heads.toml")


def test_select_hed_outputs_the_head_code_in_a_block_by_itself() -> None:
    lines = tape_lines(post(["SELECT/HED,1", "SELECT/HEAD,2", "SELECT/HED,BAR"], heads()).blocks)
    assert lines == ["N001M61", "N002M62", "N003M57"]


def test_select_hed_leaves_rapid() -> None:
    """SELHED's rapid flags (RAPFLG, FLRPON, FRAPID, ...): the new head starts in the
    feed range, the gears shifted back (RAPIDX: the Standard Machine's catch-up and shift
    dwells, M41) before the head code, and its move is at feed."""
    lines = tape_lines(
        post(
            ["FROM/0,0,0", "FEDRAT/10", "RAPID", "GOTO/1,1,0", "SELECT/HED,2", "GOTO/2,2,0"],
            heads(),
        ).blocks
    )
    assert lines == [
        "N004G04X+005",
        "N004G04X+02M40",
        "N004G01X+1Y+1F500",
        "N005G04X+005",
        "N005G04X+01M41",
        "N005M62",
        "N006G01X+1Y+1F071",
    ]


def test_a_head_code_the_machine_lacks_is_comment_22() -> None:
    result = post(["SELECT/HED,3"], heads())
    assert tape_lines(result.blocks) == []
    assert [d.text for d in result.diagnostics] == [NOT_AVAILABLE]


@pytest.mark.parametrize(
    "statement", ["SELECT/HED", "SELECT/HED,4", "SELECT/HED,1,2", "SELECT/HED,UP"]
)
def test_select_hed_forms(statement: str) -> None:
    with pytest.raises(InputError, match="SELECT/HED expects 1, 2, 3, BAR"):
        post([statement], heads())


def test_a_machine_without_head_codes_points_to_combin() -> None:
    with pytest.raises(InputError, match=r"no head codes .*COMBIN/2 must come first"):
        post(["SELECT/HED,1"], standard_machine())
