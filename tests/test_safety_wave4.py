"""The last SAFETY forms (core/statements/safety.py): the lathe's one-shot SAFETY (option 21
= 0, "applies only to first motion statement after a safety statement", 001 L24633-24644;
TSTFLG's SAFETO/SAFETX before each motion, L38926-38959) and SAFETY on a single-head
machine that is neither a lathe nor multiaxis (only SAFEGM's multihead record there,
L36514-36545)."""

from __future__ import annotations

import pytest
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins
from gecent.core.run import Run

from tests.test_post_linear import post

NOT_AVAILABLE = "REQUESTED MISCELLANEOUS FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE"
START = ["FROM/0,0,0", "FEDRAT/10"]


def lathe(tablem: str) -> MachineDefinition:
    """The Standard Machine as a lathe (option 132 = 0; its option 21 is 0, one-shot) with
    only the SAFETY codes ``tablem`` gives."""
    text = f'[machine]\nname = "lathe"\ntitle = "LATHE"\n[tablem]\n{tablem}[optab]\n132 = 0.0\n'
    return load_machine_text(text, "lathe.toml")


def one_shot_mach04(tablem: str = "") -> MachineDefinition:
    """MACH04 (TABLEM(37) = 36 turn, (38) = 38 face, (39) = 37 bore, (40) = 39 off,
    001 L27708-27711) with option 21 = 0, the Standard Machine's one-shot SAFETY."""
    base = get_plugins().machine("mach04").load()
    text = (
        '[machine]\nname = "mach04s"\ntitle = "MACH04 ONE-SHOT SAFETY"\n'
        f"[tablem]\n{tablem}[optab]\n21 = 0.0\n"
    )
    return load_machine_text(text, "mach04s.toml", base)


def punched(lines: list[str], machine: MachineDefinition, fast: bool = True) -> list[str]:
    run = Run(machine, fast=fast)
    result = run.process(AptSourceReader("part.apt").read_lines([*lines, "FINI"]))
    return tape_lines(result.blocks)


# ---------------------------------------------------------------- one-shot (option 21 = 0)


def test_one_shot_safety_is_off_again_at_the_second_motion() -> None:
    """The mode's code rides the first motion (SAFETO), the off code M39 the second
    (SAFETX), nothing the third; the modal MACH04 gives M36 once and no M39 (see
    tests/test_safety_single_head.py)."""
    lines = [*START, "SAFETY/TURN", "GOTO/1,0,1", "GOTO/2,0,2", "GOTO/3,0,3"]
    assert punched(lines, one_shot_mach04()) == [
        "N004G01Z+1F100M36",
        "N005G01Z+1M39",
        "N006G01Z+1",
    ]


@pytest.mark.parametrize(("mode", "m"), [("FACE", "M38"), ("BORE", "M37")])
def test_each_mode_is_one_shot(mode: str, m: str) -> None:
    lines = [*START, f"SAFETY/{mode}", "GOTO/1,0,1", "GOTO/2,0,2"]
    assert punched(lines, one_shot_mach04()) == [f"N004G01Z+1F100{m}", "N005G01Z+1M39"]


def test_the_fast_path_stays_off_while_the_off_code_waits() -> None:
    """MACH23 made a one-shot lathe: its GOTOs go by the fast path (core/motion/fastpath.py),
    which has no SAFETX; the second motion must take the general path for its M71."""
    base = get_plugins().machine("mach23").load()
    text = (
        '[machine]\nname = "lathe23"\ntitle = "LATHE 23"\n'
        "[tablem]\n37 = 70\n40 = 71\n[optab]\n132 = 0.0\n21 = 0.0\n"
    )
    machine = load_machine_text(text, "lathe23.toml", base)
    lines = ["UNITS/INCHES", *START, "GOTO/1,0,1", "SAFETY/TURN"]
    lines += [f"GOTO/{n},0,{n}" for n in range(2, 6)]
    run = Run(machine)
    tape = tape_lines(run.process(AptSourceReader("part.apt").read_lines([*lines, "FINI"])).blocks)
    assert run._fast is not None and run._fast.possible  # the fast path was in use
    assert tape == punched(lines, machine, fast=False)
    assert tape == [
        "N004G01X+01Z+01F071",
        "N006G01X+01Z+01M70",
        "N007G01X+01Z+01M71",
        "N008G01X+01Z+01",
        "N009G01X+01Z+01",
    ]


def test_one_shot_safety_on_the_standard_machine_as_a_lathe() -> None:
    """The Standard Machine's own option 21 (0) and no SAFETY codes of its own: given
    TABLEM(37) and (40), the one-shot off code comes at the second motion there too."""
    machine = lathe("37 = 70\n40 = 71\n")
    lines = [*START, "SAFETY/TURN", "GOTO/1,0,1", "GOTO/2,0,2", "GOTO/3,0,3"]
    tape = punched(lines, machine)
    assert [line[-3:] for line in tape] == ["M70", "M71", tape[2][-3:]]
    assert "M" not in tape[2]


def test_a_from_is_not_the_motion_safety_counts() -> None:
    """As for a one-shot rapid, a FROM makes no move: one between the first and second
    motions leaves the off code for the GOTO after it."""
    lines = [*START, "SAFETY/TURN", "GOTO/1,0,1", "FROM/1,0,1", "GOTO/2,0,2", "GOTO/3,0,3"]
    assert punched(lines, one_shot_mach04()) == [
        "N004G01Z+1F100M36",
        "N006G01Z+1M39",
        "N007G01Z+1",
    ]


def test_safety_off_before_the_second_motion_ends_it() -> None:
    """SAFETY/OFF outputs the off code itself: SAFETX has nothing left to turn off."""
    lines = [*START, "SAFETY/TURN", "GOTO/1,0,1", "SAFETY/OFF", "GOTO/2,0,2", "GOTO/3,0,3"]
    assert punched(lines, one_shot_mach04()) == [
        "N004G01Z+1F100M36",
        "N006G01Z+1M39",
        "N007G01Z+1",
    ]


def test_a_new_mode_starts_the_count_again() -> None:
    """A second SAFETY after the first motion: its code rides the next motion and its off
    code the one after (the new mode replaces the old, no off code between)."""
    lines = [*START, "SAFETY/TURN", "GOTO/1,0,1", "SAFETY/FACE", "GOTO/2,0,2", "GOTO/3,0,3"]
    assert punched(lines, one_shot_mach04()) == [
        "N004G01Z+1F100M36",
        "N006G01Z+1M38",
        "N007G01Z+1M39",
    ]


def test_a_mode_the_machine_lacks_is_never_turned_off() -> None:
    """Comment 22 for the missing mode code, and no off code after it: the mode was never
    on."""
    machine = lathe("40 = 71\n")
    run = Run(machine)
    lines = [*START, "SAFETY/TURN", "GOTO/1,0,1", "GOTO/2,0,2"]
    result = run.process(AptSourceReader("part.apt").read_lines([*lines, "FINI"]))
    assert [d.text for d in result.diagnostics] == [NOT_AVAILABLE]
    assert not any("M" in line for line in tape_lines(result.blocks))


def test_a_missing_off_code_is_comment_22_at_the_second_motion() -> None:
    machine = lathe("38 = 70\n")
    result = post([*START, "SAFETY/FACE", "GOTO/1,0,1", "GOTO/2,0,2", "GOTO/3,0,3"], machine)
    assert [d.text for d in result.diagnostics] == [NOT_AVAILABLE]
    assert [d.where.line for d in result.diagnostics if d.where] == [5]  # the second GOTO
    tape = tape_lines(result.blocks)
    assert tape[0].endswith("M70")
    assert not any("M" in line for line in tape[1:])


# ---------------------------------------------------------------- neither lathe nor multiaxis


@pytest.mark.parametrize("statement", ["SAFETY/0.1,0,0", "SAFETY/TURN", "SAFETY/OFF"])
def test_a_single_head_mill_refuses_safety_naming_why(statement: str) -> None:
    """The Standard Machine (option 132 = 1, GEMILL): its SAFEGM is "the SAFETY statement
    for multihead milling machines" (001 L36521-36523), whose CODE 17 record only the merge
    pass reads (L7336-7346): bad input pointing to COMBIN/2, never NotYetSupported."""
    with pytest.raises(InputError, match=r"neither a lathe \(option 132 = 0\) nor multiaxis"):
        post([statement], standard_machine())


def test_a_positioning_machine_refuses_safety() -> None:
    machine = get_plugins().machine("mach23").load()
    assert machine.number_option(132) != 0 and not machine.multiaxis
    with pytest.raises(InputError, match="COMBIN/2 must come first"):
        post(["SAFETY/0.1,0,0"], machine)
