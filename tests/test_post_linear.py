"""Posting linear motion on contouring machines: the manual's worked examples through the
whole kernel, and the appendix 7.2 bound on random paths, checked from the tape itself."""

from __future__ import annotations

import re

from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import standard_machine
from gecent.core.motion.rounding import to_steps
from gecent.core.output.tape import tape_lines
from gecent.core.run import Run, RunResult
from hypothesis import given, settings
from hypothesis import strategies as st

STEP = 0.0001
WORD = re.compile(r"([A-Z])([+-]?)(\d*)")


def post(lines: list[str], machine: MachineDefinition | None = None) -> RunResult:
    run = Run(machine or standard_machine())
    return run.process(AptSourceReader("part.apt").read_lines([*lines, "FINI"]))


def tape(lines: list[str], machine: MachineDefinition | None = None) -> list[str]:
    return tape_lines(post(lines, machine).blocks)


def decode(line: str, machine: MachineDefinition) -> dict[str, float]:
    """Read a tape line back: each register has L whole digits (leading zeros kept), then
    the decimals that were not dropped."""
    registers = machine.registers
    formats = {registers.letters[k]: registers.formats[k] for k in registers.present()}
    words: dict[str, float] = {}
    for letter, sign, digits in WORD.findall(line):
        fmt = formats[letter]
        assert fmt is not None
        whole, fraction = digits[: fmt.left] or "0", digits[fmt.left :]
        value = int(whole) + (int(fraction) / 10 ** len(fraction) if fraction else 0.0)
        words[letter] = -value if sign == "-" else value
    return words


def test_w7_even_segmentation_on_tape() -> None:
    """W7 (001 L4385-4420): (0,0) -> (40,30) with DEPMAX 9.9999: five blocks of X8 Y6."""
    assert (
        tape(["FROM/0,0,0", "FEDRAT/20", "GOTO/40,30,0"])
        == ["N003G01X+8Y+6F020"] + ["N003X+8Y+6"] * 4
    )


def test_w9_accurate_segmentation_on_tape() -> None:
    """W9 (001 L4514-4552): DEPMAX 3.9999, X 8 -> 18: 3.3333, 3.3334, 3.3333."""
    machine = standard_machine().with_options({4: 3.9999})
    lines = tape(["FROM/8,0,0", "FEDRAT/10", "GOTO/18,0,0"], machine)
    assert [decode(line, machine)["X"] for line in lines] == [3.3333, 3.3334, 3.3333]
    assert lines == ["N003G01X+33333F030", "N003X+33334", "N003X+33333"]


def test_w3_godlta_is_a_goto_from_the_previous_point() -> None:
    """W3 (001 L4111-4118): at (22, 10, 8), GODLTA/2,-4,6 is GOTO/24,6,14."""
    by_delta = tape(["FROM/0,0,0", "FEDRAT/10", "GOTO/22,10,8", "GODLTA/2,-4,6"])
    by_goto = tape(["FROM/0,0,0", "FEDRAT/10", "GOTO/22,10,8", "GOTO/24,6,14"])
    assert by_delta == by_goto
    assert by_delta[-1].startswith("N004X+2Y-4Z+6")


def test_w4_incremental_output() -> None:
    """W4 (001 L4204-4232): X of A, B, C = 2.4, 5.6, 8.6 gives departures X3.2 and X3.0."""
    machine = standard_machine()
    lines = tape(["FROM/2.4,0,0", "FEDRAT/10", "GOTO/5.6,0,0", "GOTO/8.6,0,0"], machine)
    assert [decode(line, machine)["X"] for line in lines] == [3.2, 3.0]


def test_a_move_of_no_whole_step_outputs_nothing() -> None:
    """001 L4283-4290: every departure under half a step: no block, the previous point stays,
    so two sub-step moves that add up to a step do move."""
    lines = tape(["FROM/0,0,0", "FEDRAT/10", "GOTO/0.00004,0,0", "GOTO/0.00008,0,0"])
    # 10 * 10 IPM / 0.0001 in = 1e6: multiplier c = 2000 (option 26 = 0), I = 0.2
    assert lines == ["N004G01X+00001I02F500"]


def test_feed_command_is_clamped_to_option_24() -> None:
    """Fc = GDIMUL * FIPM / S: 10 * 100 / 0.0001 far above option 24 = 500 -> 500, and the
    absolute printout gets the feed that command really gives (001 L10799-10815). Option
    26 = 1: no feedrate multiplier."""
    result = post(
        ["FROM/0,0,0", "FEDRAT/100", "GOTO/0.0001,0,0"], standard_machine().with_options({26: 1.0})
    )
    motion = next(b for b in result.blocks if b.punch and "X" in b.punch)
    assert motion.punch == "N003G01X+00001F500"
    assert motion.cells[19] == 500 * 0.0001 / 10


def test_feedrate_multiplier_keeps_the_programmed_feed() -> None:
    """Option 26 = 0, the standard (001 L12440-12529): the command 10 * 100 / 0.0001 is
    divided by the smallest whole c that brings it to option 24 (c = 20000) and the
    departure times c goes in I (2.0): the control still feeds at 100 IPM."""
    result = post(["FROM/0,0,0", "FEDRAT/100", "GOTO/0.0001,0,0"])
    motion = next(b for b in result.blocks if b.punch and "X" in b.punch)
    assert motion.punch == "N003G01X+00001I2F500"
    assert motion.cells[19] == 100


def test_missing_feedrate_uses_option_23_with_the_manual_comment() -> None:
    result = post(["FROM/0,0,0", "GOTO/1,0,0"])
    assert [d.text for d in result.diagnostics] == ["OPTION FEEDRATE ASSUMED."]
    assert tape_lines(result.blocks) == ["N002G01X+1F050"]  # 10 * 5 IPM / 1 in


def test_feedrate_outside_the_machine_range_is_clamped_with_a_warning() -> None:
    result = post(["FROM/0,0,0", "FEDRAT/900", "GOTO/10,0,0"])
    assert result.diagnostics[0].text == (
        "FEEDRATE 900 IPM IS OUTSIDE THE MACHINE RANGE 1-200; 200 IPM USED"
    )


_COORD = st.integers(-300000, 300000).map(lambda n: n / 10000 + 0.00003)


@settings(max_examples=60, deadline=None)
@given(points=st.lists(st.tuples(_COORD, _COORD, _COORD), min_size=1, max_size=12))
def test_appendix_7_2_no_pulse_is_lost(points: list[tuple[float, float, float]]) -> None:
    """Appendix 7.2 (001 L40175-40246): re-adding the tape's departures from the FROM point
    lands within one step of every CL point (the rounded point itself), however long the
    path and however many segments."""
    machine = standard_machine()
    lines = ["FROM/1.23456,-2.5,0.75", "FEDRAT/40"]
    lines += [f"GOTO/{x!r},{y!r},{z!r}" for x, y, z in points]
    result = post(lines, machine)
    at = [to_steps(v, STEP) for v in (1.23456, -2.5, 0.75)]
    reached: dict[int, list[int]] = {}
    for line in tape_lines(result.blocks):
        words = decode(line, machine)
        for axis, letter in enumerate("XYZ"):
            at[axis] += to_steps(words.get(letter, 0.0), STEP)
        reached[int(words["N"])] = list(at)
    for number, (x, y, z) in enumerate(points, start=3):
        if number in reached:
            for axis, value in enumerate((x, y, z)):
                assert abs(reached[number][axis] * STEP - value) <= STEP
                assert reached[number][axis] == to_steps(value, STEP)


def test_one_shot_rapid_with_vector_optimisation() -> None:
    """RAPID (001 L11809-11910, L12530-12638): the next record goes at rapid; option 36 = 0
    moves each axis at its own rate (options 42-44 = 200 IPM): rho = 5 / 200, F = D / rho
    = 400; the command is held to option 45 (500); the feed returns on the next record."""
    lines = tape(
        [
            "FROM/0,0,2",
            "RAPID",
            "GOTO/10,5,0.1",
            "FEDRAT/10",
            "GOTO/10,5,0",
            "RAPID",
            "GOTO/12,5,0.1",
            "GOTO/13,5,0.1",
        ]
    )
    assert lines == [
        "N003G01X+5Y+25Z-095F400",
        "N003X+5Y+25Z-095",
        "N005Z-01K02F500",  # 10 * 10 / 0.1 = 1000: multiplier c = 2, K = 0.2
        "N007X+2Z+01",  # 10 / (2 / 200) = 1000 -> 500, the same F as before: not repeated
        "N008X+1F100",
    ]


def test_rapid_never_makes_an_arc() -> None:
    lines = tape(["FROM/2,0,0", "RAPID", "CIRCLE/0,0,0,0,0,1,2", "GOTO/0,2,0"])
    assert lines == ["N004G01X-2Y+2F500"]  # 10 / (2 / 200) = 1000, held to option 45
