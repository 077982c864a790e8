"""FEDRAT's feed ranges and MAXIPM (FEDRGB steps 4, 7, 8, 9; 001 L31113-31212) on MACH04, the
manual's two-range lathe (001 L27681-27799): option 18 = 2, TABLEM(113) = 42 (range 1),
TABLEM(114) = 41 (range 2), FRTAB ranges 0.01-2 and 0.1-20 IPM; option 91 (assumed range)
stays at its standard 2, option 93 (range-change dwell) at 0.

How MACH04 writes a block (every expected line below): CL x goes to Z (option 59 = +Z-X),
so GOTO/1,0,0 from the origin is Z+1; a 1-inch departure takes G01 (TABLEG(2) = 1, GDIMUL
10), so the feedrate number is F = 10 x IPM / 1 in format 3.2 with trailing zeros dropped
(1 IPM -> F010, 0.05 IPM -> F0005); option 38 = 1 repeats G01 in every block and fills
G04 (TABLEG(5)) into blocks without a G; option 107 = 1 drops a repeated F.
"""

from __future__ import annotations

import pytest
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.errors import InputError, MachineDefinitionError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import standard_machine
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins
from gecent.core.run import Run

from tests.test_post_linear import post

ASSUMED = "OPTION FEED RATE RANGE ASSUMED."


def mach04(options: dict[int, float] | None = None) -> MachineDefinition:
    return get_plugins().machine("mach04").load().with_options(options or {})


def tape(lines: list[str], machine: MachineDefinition | None = None) -> list[str]:
    return tape_lines(post(lines, machine or mach04()).blocks)


def comments(lines: list[str], machine: MachineDefinition | None = None) -> list[str]:
    return [d.text for d in post(lines, machine or mach04()).diagnostics]


def test_a_range_change_stores_its_m_code_for_the_next_block() -> None:
    """RANGE,1 then RANGE,2: each new range STOREs TABLEM(112 + r), M42 then M41; option
    93 = 0 "no dwell block is issued, and the feedrate range M code is merged into a program
    block" (001 L25507-25508), the next motion (records 3, 5). Record 6 repeats range 2: no
    code (step 7, "a range was given and is different from the previous range").
    F: 1 IPM -> 10, 10 IPM -> 100, 5 IPM -> 050."""
    program = ["FROM/0,0,0", "FEDRAT/1,RANGE,1", "GOTO/1,0,0", "FEDRAT/10,RANGE,2"]
    program += ["GOTO/2,0,0", "FEDRAT/5,RANGE,2", "GOTO/3,0,0"]
    assert tape(program) == ["N003G01Z+1F010M42", "N005G01Z+1F100M41", "N007G01Z+1F050"]
    assert comments(program) == []


def test_the_range_limits_the_feed_instead_of_options_48_and_25() -> None:
    """Step 8: FRMIN/FRMAX from the range. 0.05 IPM is inside range 1 (0.01-2): F = 10 x
    0.05 = 0.5 -> F0005; in range 2 (0.1-20) it is raised to 0.1: F = 1 -> F001, with the
    TSTEXT comment. Options 48/25 (0.01/20) would have let 0.05 pass."""
    program = ["FROM/0,0,0", "FEDRAT/0.05,RANGE,1", "GOTO/1,0,0", "FEDRAT/0.05,RANGE,2"]
    program += ["GOTO/2,0,0"]
    assert tape(program) == ["N003G01Z+1F0005M42", "N005G01Z+1F001M41"]
    assert comments(program) == [
        "FEEDRATE 0.05 IPM IS OUTSIDE THE MACHINE RANGE 0.1-20; 0.1 IPM USED"
    ]


def test_low_and_high_and_a_range_beyond_option_18() -> None:
    """RANGE,LOW is range 1 (M42, 5 IPM held to its 2: F020); HIGH is range 3, beyond
    option 18 = 2: SPINDL's "RANGE REQUESTED IS NOT AVAILABLE, USE HIGHEST" (001 L37617),
    range 2 (M41, F = 10 x 1 = 010)."""
    assert tape(["FROM/0,0,0", "FEDRAT/5,RANGE,LOW", "GOTO/1,0,0"]) == ["N003G01Z+1F020M42"]
    high = ["FROM/0,0,0", "FEDRAT/1,RANGE,HIGH", "GOTO/1,0,0"]
    assert tape(high) == ["N003G01Z+1F010M41"]
    assert comments(high) == ["RANGE REQUESTED IS NOT AVAILABLE, USE HIGHEST"]
    assert tape(["FROM/0,0,0", "FEDRAT/1,RANGE,MEDIUM", "GOTO/1,0,0"]) == ["N003G01Z+1F010M41"]


def test_no_range_ever_given_assumes_option_91_once() -> None:
    """Step 7: "OPTION FEED RATE RANGE ASSUMED." (001 L31199-31200) at the first FEDRAT,
    once; the range is option 91's (standard 2, L25477-25484), whose code TABLEM(43) = 41 =
    TABLEM(114) says the machine is already in it, so no M code. 0.05 IPM is raised to range
    2's 0.1 (F001). A later RANGE,2 is no change: no M41."""
    program = ["FROM/0,0,0", "FEDRAT/0.05", "GOTO/1,0,0", "FEDRAT/1", "FEDRAT/1,RANGE,2"]
    program += ["GOTO/2,0,0"]
    assert tape(program) == ["N003G01Z+1F001", "N006G01Z+1F010"]
    assert comments(program) == [
        ASSUMED,
        "FEEDRATE 0.05 IPM IS OUTSIDE THE MACHINE RANGE 0.1-20; 0.1 IPM USED",
    ]


def test_fedrat_range_without_a_feed_keeps_the_held_feed_within_the_new_range() -> None:
    """FEDRAT/RANGE,1 (record 4) keeps FDHOLD = 10 IPM (step 5) and holds it to range 1's
    2 IPM (F = 20): M42 and F020 at record 5."""
    program = ["FROM/0,0,0", "FEDRAT/10", "GOTO/1,0,0", "FEDRAT/RANGE,1", "GOTO/2,0,0"]
    assert tape(program) == ["N003G01Z+1F100", "N005G01Z+1F020M42"]
    assert comments(program) == [
        ASSUMED,
        "FEEDRATE 10 IPM IS OUTSIDE THE MACHINE RANGE 0.01-2; 2 IPM USED",
    ]


def test_option_93_dwell_carries_the_range_code() -> None:
    """Option 93 = 2 s: a dwell block after the STOREM (step 7), so M42 rides in it: G04
    (TABLEG(5)) and 2 s in the option-57 register Z over option 56 = 10, Z+0.2 -> Z+02
    (format 1.4 signed, trailing zeros dropped), at the FEDRAT's record 2."""
    program = ["FROM/0,0,0", "FEDRAT/1,RANGE,1", "GOTO/1,0,0"]
    assert tape(program, mach04({93: 2.0})) == ["N002G04Z+02M42", "N003G01Z+1F010"]


def test_option_219_puts_the_range_code_in_a_block_before_the_dwell() -> None:
    """Option 219 (printed "OPTION 129", 001 L26688-26697) = 1: the M code in its own block
    first (G04 filled by option 38), then the dwell."""
    program = ["FROM/0,0,0", "FEDRAT/1,RANGE,1", "GOTO/1,0,0"]
    assert tape(program, mach04({93: 2.0, 219: 1.0})) == [
        "N002G04M42",
        "N002G04Z+02",
        "N003G01Z+1F010",
    ]


def test_a_negative_option_93_is_output_by_macfun() -> None:
    """ "A negative value means ... Dwell is output by a special machine function subroutine"
    (001 L25508-25511): MACH04 has no MACFUN (option 133 = 0), so its machine file is wrong
    (issue 22: no longer "not yet supported"; with a MACFUN, tests/test_statement_forms.py)."""
    with pytest.raises(MachineDefinitionError, match="option 133 = 0"):
        post(["FEDRAT/1,RANGE,1"], mach04({93: -2.0}))


def test_the_range_is_reinstated_after_a_stop() -> None:
    """Option 145 = 1 (001 L16024-16143): the range code is STATE(6); at the first motion
    after STOP, RESTAT stores it again and it rides in the motion block (record 5; the F
    is redundant). STOP is M00 with option 38's G04."""
    program = ["FROM/0,0,0", "FEDRAT/1,RANGE,1", "GOTO/1,0,0", "STOP", "GOTO/2,0,0"]
    assert tape(program, mach04({145: 1.0})) == [
        "N003G01Z+1F010M42",
        "N004G04M00",
        "N005G01Z+1M42",
    ]


def test_a_range_given_after_the_stop_is_not_reinstated_again() -> None:
    """The manual's own case (001 L16106-16141): STOP, then FEDRAT/RANGE,2 (the held 1 IPM,
    F redundant); STATE(6) is stored negative while STOPON = 1 (step 7), so the range given
    after the stop is output when given (M41 in record 6) and RESTAT leaves it."""
    program = ["FROM/0,0,0", "FEDRAT/1,RANGE,1", "GOTO/1,0,0", "STOP", "FEDRAT/RANGE,2"]
    program += ["GOTO/2,0,0"]
    assert tape(program, mach04({145: 1.0})) == [
        "N003G01Z+1F010M42",
        "N004G04M00",
        "N006G01Z+1M41",
    ]


def test_a_one_range_machine_ignores_range() -> None:
    """Step 7 reads option 18 first; on the Standard Machine (option 18 = 0, one range)
    RANGE selects nothing: the tape of FEDRAT/10 (F = 10 x 10 / 1 = 100), no comment."""
    machine = standard_machine()
    program = ["FROM/0,0,0", "FEDRAT/10,RANGE,2", "GOTO/1,0,0"]
    assert tape(program, machine) == ["N003G01X+1F100"]
    assert comments(program, machine) == []


def _feed_after(lines: list[str], machine: MachineDefinition) -> float | None:
    run = Run(machine)
    run.process(AptSourceReader("part.apt").read_lines([*lines, "FINI"]))
    return run.state.feed.maximum_ipm


def test_maxipm_is_held_to_the_range_maximum() -> None:
    """Step 9: MAXIPM, v sets SFMAXI = v, then SFMAXI = FRMAX if above it: 10 in range 1
    (FRMAX 2) is 2, 10 in range 2 (FRMAX 20) stays 10; on the Standard Machine FRMAX is
    option 25 = 200."""
    assert _feed_after(["FEDRAT/1,RANGE,1,MAXIPM,10"], mach04()) == 2.0
    assert _feed_after(["FEDRAT/1,RANGE,2,MAXIPM,10"], mach04()) == 10.0
    assert _feed_after(["FEDRAT/10,MAXIPM,500"], standard_machine()) == 200.0
    assert _feed_after(["FEDRAT/10,MAXIPM,50"], standard_machine()) == 50.0


@pytest.mark.parametrize(
    ("statement", "message"),
    [
        ("FEDRAT/1,RANGE", "FEDRAT RANGE needs a value after it"),
        ("FEDRAT/1,RANGE,0", "FEDRAT RANGE expects a range number 1, 2, ..., found 0"),
        ("FEDRAT/1,RANGE,1.5", "found 1.5"),
        ("FEDRAT/1,RANGE,FAST", "FEDRAT RANGE expects LOW, MEDIUM, HIGH or a range number"),
        ("FEDRAT/1,MAXIPM,HIGH", "FEDRAT MAXIPM expects a feedrate value"),
        ("FEDRAT/1,MAXIPM,0", "FEDRAT MAXIPM needs a positive feedrate"),
        ("FEDRAT/1,2", "FEDRAT expects one feedrate value, found 2"),
        ("FEDRAT/IPM", "FEDRAT expects one feedrate value, found 0"),
    ],
)
def test_bad_forms_name_what_is_expected(statement: str, message: str) -> None:
    with pytest.raises(InputError, match=message):
        post([statement], mach04())


def test_other_fedrat_words_are_bad_input() -> None:
    # issue 22: FEDRAT's scan knows IPM, IPR, RANGE and MAXIPM (001 L31139-31164); a second
    # unit word is bad input, no longer "not yet supported"
    with pytest.raises(InputError, match="FEDRAT/IPR"):
        post(["FEDRAT/1,IPM,IPR"], mach04())
