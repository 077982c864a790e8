"""Wave 8: option 80, the pallet height in the clearance (slide-limit) test (001
L25356-25366; MACH40 sets 20.25, L27948; TSTLIM L38955-39010); option 222, read as THREDO's
M (001 L26709-26718, L15985-15988); and a cycle the positioning control lacks, drilled by
positioning moves (CYCLGP, RAPIDP: 001 L30095-30204, L35274-35313). Decisions in
docs/decisions.md, "Options 80, 222 and positioning cycles"."""

from __future__ import annotations

import pytest
from gecent.core.errors import InputError
from gecent.core.machine.catalogue import catalogue
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post

LIMIT = "Z AXIS SLIDE LIMIT HAS BEEN EXCEEDED *** WARNING"
Z_LIMITS = "125 = 60.0\n126 = 25.0\n"  # Z within 25..60 (upper 125, lower 126)
# class 1 with the tool along Z (k = 1): machine Z = z + (R + TL) k = z + 4 (option 104 = 4,
# head 1's small gripper, no tool length; 001 L12749-12870)
DOWN = ["FROM/0,0,10,0,0,1", "FEDRAT/10", "GOTO/0,0,1,0,0,1", "GOTO/0,0,0,0,0,1"]


def overlay(base: str, text: str) -> MachineDefinition:
    pack = get_plugins().machine(base).load()
    return load_machine_text(f'[machine]\nname = "{base}-w8"\n{text}', "w8.toml", base=pack)


def limit_lines(lines: list[str], machine: MachineDefinition) -> list[int | None]:
    result = post(lines, machine)
    return [n.where.line if n.where else None for n in result.diagnostics if n.text == LIMIT]


# -- option 80: the pallet under the part, in the clearance (slide-limit) test ---------------


def test_mach40s_pallet_raises_the_z_the_limits_see() -> None:
    """MACH40 (pallet 20.25, option 110 = 2) with Z limits 25..60: z 1 puts the head's Z at
    1 + 4 = 5, 5 + 20.25 = 25.25 above the table, inside; z 0 at 4 + 20.25 = 24.25, below 25:
    the warning, and option 110 = 2 holds the punch back."""
    machine = overlay("mach40", f"[optab]\n{Z_LIMITS}")
    assert limit_lines(DOWN, machine) == [4]
    assert post(DOWN, machine).punch_suppressed


def test_without_a_pallet_the_same_moves_are_below_the_limit() -> None:
    """Option 80 = 0 (no pallet): Z 5 and 4 are both below 25."""
    machine = overlay("mach40", f"[optab]\n80 = 0.0\n{Z_LIMITS}")
    assert limit_lines(DOWN, machine) == [3, 4]


def test_a_three_axis_machine_does_not_read_option_80() -> None:
    """Option 80 is a multiaxis option (class MA): MACH23 with a pallet of 20.25 tests Z 5 as
    it is (option 110 = 1, warn and go on)."""
    machine = overlay("mach23", f"[optab]\n80 = 20.25\n110 = 1.0\n{Z_LIMITS}")
    assert limit_lines(["FROM/0,0,30", "FEDRAT/10", "GOTO/0,0,5"], machine) == [3]


# -- option 222 ----------------------------------------------------------------------------


def test_option_222_is_explained_as_thredos_m() -> None:
    """Option 222 asks for the accuracy THREDO's M always gives (I and J scaled so leading
    zeros are shifted out): no routine reads it, and the catalogue says why."""
    entry = catalogue().option(222)
    assert entry.effect is not None and entry.effect.startswith("none: ")
    assert "L15985" in entry.effect and "L38405" in entry.effect


# -- a cycle the positioning control lacks ----------------------------------------------------


def drill(extra: str) -> MachineDefinition:
    """MACH24 without G81 (TABLEG(82)) or G83 (TABLEG(84)), and Z on tape by ``extra``."""
    return overlay("mach24", f'[tableg]\n82 = "absent"\n84 = "absent"\n[optab]\n{extra}')


def test_a_drill_cycle_the_control_lacks_is_drilled_by_moves() -> None:
    """MACH24 with option 130 = +1 (Z in a block of its own): at each hole the tool goes
    across at its height (rapid, G80 = TABLEG(1), F99 = option 45), down to R = 0 + .1 at
    rapid, to the bottom 0 - .5 at the cycle's 6 IPM (F = 2 x 6, feed type 0), back to R at
    rapid; Y -4 (option 59 negates Y) is not repeated (option 40)."""
    lines = [
        "FROM/0,0,5",
        "FEDRAT/10",
        "CYCLE/DRILL,DEPTH,0.5,IPM,6,CLEAR,0.1",
        "GOTO/4,4,0",
        "GOTO/5,4,0",
    ]
    assert tape_lines(post(lines, drill("130 = 1.0\n")).blocks) == [
        "N004G80X+040000Y-040000F99",
        "N004Z+001000",
        "N004Z-005000F12",
        "N004Z+001000F99",
        "N005X+050000",
        "N005Z-005000F12",
        "N005Z+001000F99",
    ]


def test_deep_pecks_and_return_by_moves() -> None:
    """DEEP with STEP .4 to depth 1: pecks to -.4 and -.8 from the top, each back to R, then
    the bottom -1; RETURN,0 takes the tool back to the level the cycle began at (5)."""
    lines = [
        "FROM/0,0,5",
        "FEDRAT/10",
        "CYCLE/DEEP,DEPTH,1,STEP,0.4,IPM,6,CLEAR,0.1,RETURN,0",
        "GOTO/4,4,0",
    ]
    assert tape_lines(post(lines, drill("130 = 1.0\n")).blocks) == [
        "N004G80X+040000Y-040000F99",
        "N004Z+001000",
        "N004Z-004000F12",
        "N004Z+001000F99",
        "N004Z-008000F12",
        "N004Z+001000F99",
        "N004Z-010000F12",
        "N004Z+050000F99",
    ]


def test_option_130_minus_1_puts_z_with_x_and_y() -> None:
    """Option 130 = -1: Z goes in the XY block; the first block states Z 5 (nothing held)."""
    lines = ["FROM/0,0,5", "FEDRAT/10", "CYCLE/DRILL,DEPTH,0.5,IPM,6,CLEAR,0.1", "GOTO/4,4,0"]
    assert tape_lines(post(lines, drill("130 = -1.0\n")).blocks) == [
        "N004G80X+040000Y-040000Z+050000F99",
        "N004Z+001000",
        "N004Z-005000F12",
        "N004Z+001000F99",
    ]


def test_a_control_cycle_after_the_moves_states_its_block_again() -> None:
    """The moves' G80 cancels a control cycle: a later DRILL on a control that has G81 but
    not G83 states its CODE -16 block again. The moves left the tool at R = .1: the plunge is
    .1 - (0 - .5) = .6, the rapid distance .1 - .1 = 0 (a zero R is not punched)."""
    machine = overlay("mach24", '[tableg]\n84 = "absent"\n[optab]\n130 = 1.0\n')
    lines = [
        "FROM/0,0,5",
        "FEDRAT/10",
        "CYCLE/DEEP,DEPTH,0.5,IPM,6,CLEAR,0.1",
        "GOTO/4,4,0",
        "CYCLE/DRILL,DEPTH,0.5,IPM,6,CLEAR,0.1",
        "GOTO/5,4,0",
    ]
    tape = tape_lines(post(lines, machine).blocks)
    assert tape[-2:] == ["N006G81Z+006000F12", "N006X+050000"]


def test_without_z_on_tape_the_missing_cycle_is_bad_input() -> None:
    """MACH24 as sampled (option 130 = 0: Z is never on tape) cannot drill by moves: the
    statement is refused, naming the missing TABLEG cell and option 130."""
    with pytest.raises(InputError, match=r"TABLEG\(82\).*option 130 = 0") as caught:
        post(["FROM/0,0,5", "CYCLE/DRILL,DEPTH,0.5,IPM,6,CLEAR,0.1", "GOTO/4,4,0"], drill(""))
    assert caught.value.where is not None and caught.value.where.line == 2


def test_forms_with_a_dwell_or_spindle_codes_are_built_by_moves() -> None:
    # were NotYetSupported; wave 9 builds them: tests/test_cycles_wave9.py
    machine = overlay("mach24", '[tableg]\n82 = "absent"\n85 = "absent"\n[optab]\n130 = 1.0\n')
    post(["FROM/0,0,5", "CYCLE/TAP,DEPTH,0.5,IPM,6,CLEAR,0.1", "GOTO/4,4,0"], machine)
    drilled = post(
        ["FROM/0,0,5", "CYCLE/DRILL,DEPTH,0.5,IPM,6,CLEAR,0.1,DWELL,2", "GOTO/4,4,0"], machine
    )
    assert "N003G04X+002000" in tape_lines(drilled.blocks)


def test_in_the_control_lacks_withdraws_then_moves_across() -> None:
    """CYCLE/IN without TABLEG(90): the expansion's IN, out at rapid to R = 0 + .1 (never
    deeper than the tool stands, .05), then across to the point."""
    lines = ["FROM/0,0,0.05", "FEDRAT/10", "CYCLE/IN,CLEAR,0.1", "GOTO/4,4,0"]
    assert tape_lines(post(lines, drill("130 = 1.0\n")).blocks) == [
        "N004G80Z+001000F99",
        "N004X+040000Y-040000",
    ]
