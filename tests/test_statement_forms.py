"""Issue 22: statement forms that stopped with "not yet supported": POSITN's modes and SET12
(core/statements/handling.py, core/motion/positioning.py), SELECT/HED,SADDLE
(core/statements/select.py), TMARK/1, RAPID and FEDRAT words, option 93 < 0, MODE and
PIVOTZ. The readings are in docs/decisions.md, "Statement forms (issue 22)"."""

from __future__ import annotations

import pytest
from gecent.core.errors import InputError, MachineDefinitionError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post

# TABLEG 52-62 of a machine with the positioning modes: each location holds its own number
MODE_CODES = "".join(f"{n} = {n}\n" for n in (52, 53, 54, 58, 60, 61, 62, 63))
RANGE_ASSUMED = "OPTION FEED RATE RANGE ASSUMED."
FEED_MODE_ASSUMED = "OPTION FEEDRATE MODE ASSUMED."
TWO_RANGES = "[optab]\n18 = 2.0\n174 = 4.0\n[feed_ranges]\nranges = [[0.1, 50.0], [0.1, 50.0]]\n"


def overlaid(name: str, overlay: str) -> MachineDefinition:
    base = get_plugins().machine(name).load()
    text = f'[machine]\nname = "{name}-forms"\n{overlay}'
    return load_machine_text(text, "forms.toml", base=base)


def positioning(extra: str = "") -> MachineDefinition:
    """MACH24 (G80 cycle off, Y negated by option 59, F = 2 x IPM) with the mode codes."""
    return overlaid("mach24", f"[tableg]\n{MODE_CODES}{extra}")


def tape(lines: list[str], machine: MachineDefinition) -> list[str]:
    return tape_lines(post(lines, machine).blocks)


# -- POSITN and SET12 ----------------------------------------------------------------------


def test_each_mode_puts_its_g_code_in_the_moves_after_it() -> None:
    """FINE TABLEG(52), COARSE 54, TRAV of COARSE 58, CORMIL 61 (feed range 1), NOBACK 53;
    OFF outputs TABLEG(60) alone (CODE -4) and the moves go back to G80 (TABLEG(1))."""
    program = [
        "FROM/0,0,5",
        "FEDRAT/10",
        "POSITN/FINE",
        "GOTO/1,1,5",
        "GOTO/2,1,5",
        "POSITN/COARSE",
        "GOTO/3,1,5",
        "POSITN/TRAV",
        "GOTO/4,1,5",
        "POSITN/CORMIL",
        "GOTO/4,2,5",
        "POSITN/NOBACK",
        "GOTO/5,2,5",
        "POSITN/OFF",
        "GOTO/6,2,5",
    ]
    assert tape(program, positioning()) == [
        "N004G52X+010000Y-010000F20",
        "N005X+020000",
        "N007G54X+030000",
        "N009G58X+040000",
        "N011G61Y-020000",
        "N013G53X+050000",
        "N014G60",
        "N015G80X+060000",
    ]


def test_a_cycle_keeps_its_own_g_and_the_mode_comes_back_after_it() -> None:
    """SET12 only fills a block with no G (POSMOV step 2): a hole under CYCLE/DRILL has
    G81; after CYCLE/OFF the next move takes the mode's G, not G80."""
    program = [
        "FROM/0,0,5",
        "FEDRAT/10",
        "POSITN/FINE",
        "CYCLE/DRILL,1,IPM,10",
        "GOTO/1,1,5",
        "CYCLE/OFF",
        "GOTO/2,2,5",
    ]
    lines = tape(program, positioning())
    assert lines[-1] == "N007G52X+020000Y-020000"
    assert all("G52" not in line for line in lines[:-1])
    assert any("G81" in line for line in lines)


def test_cormil_takes_the_code_of_the_feed_range() -> None:
    """CORMIL: TABLEG(61) in feed range 1, 62 in range 2 (FEDRAT/...,RANGE,2 on a machine
    with two feed ranges, option 18)."""
    machine = positioning(TWO_RANGES)
    program = [
        "FROM/0,0,5",
        "FEDRAT/10,RANGE,1",
        "POSITN/CORMIL",
        "GOTO/1,1,5",
        "FEDRAT/10,RANGE,2",
        "GOTO/2,1,5",
    ]
    # (MACH24 has no range M codes TABLEM 113-114: comment 22 for each, no block)
    assert tape(program, machine) == ["N004G61X+010000Y-010000F20", "N006G62X+020000"]


def test_trav_in_ipr_mode_is_tableg_63() -> None:
    """TRAV: traverse to feed without a stop, IPM mode TABLEG(58), IPR mode 63."""
    program = ["FROM/0,0,5", "SPINDL/100", "FEDRAT/0.1,IPR", "POSITN/FINE", "POSITN/TRAV"]
    lines = tape([*program, "GOTO/1,1,5"], positioning())
    assert "G63X+010000Y-010000" in lines[-1]


def test_a_mode_the_machine_lacks_is_bad_input_naming_the_code() -> None:
    with pytest.raises(InputError, match=r"POSITN/COARSE: .*TABLEG\(54\)"):
        post(["POSITN/COARSE"], overlaid("mach24", "[tableg]\n52 = 52\n"))
    # CORMIL on a machine with two feed ranges needs the range-2 code too
    two_ranges = overlaid("mach24", f"[tableg]\n61 = 61\n{TWO_RANGES}")
    with pytest.raises(InputError, match="TABLEG\\(62\\)"):
        post(["POSITN/CORMIL"], two_ranges)
    with pytest.raises(InputError, match=r"POSITN/TRAV: .*TABLEG\(58\)"):
        post(["POSITN/FINE", "POSITN/TRAV"], overlaid("mach24", "[tableg]\n52 = 52\n"))


# -- SELECT/HED,SADDLE ---------------------------------------------------------------------


def lathe_with_saddle(optab: str = "") -> MachineDefinition:
    """MACH04 (the sample lathe: G04 in non-motion blocks by option 38, dwell in Z) with a
    signed saddle register R (REGFOR(16) = -32), TABLEM(25) = M25 and option 87 = 1.5 s."""
    return overlaid(
        "mach04", f"[regfor]\n16 = -32.0\n[tablem]\n25 = 25\n[optab]\n87 = 1.5\n{optab}"
    )


def test_a_saddle_move_at_a_feed_in_ipm() -> None:
    """The move in register 16, the feed left in IPM in F (not a feed command)."""
    assert tape(["SELECT/HED,SADDLE,2.5,5,IPM"], lathe_with_saddle()) == ["N001G04F005R+0025"]


def test_a_saddle_move_with_no_feed_takes_options_84_and_85_with_the_comment() -> None:
    """Option 84 = 5 IPM (the standard), option 85 = +1 (IPM) with its comment."""
    result = post(["SELECT/HED,SADDLE,1"], lathe_with_saddle())
    assert tape_lines(result.blocks) == ["N001G04F005R+001"]
    assert [d.text for d in result.diagnostics] == [FEED_MODE_ASSUMED]


def test_a_saddle_rapid_longer_than_the_maximum_departure_is_segmented() -> None:
    """TRAV: option 87's dwell into rapid, M25 with the first block, the -25 move cut in
    three (option 4 = 9.9999: -8.3333, -8.3333, -8.3334, printed to R's two decimals), the
    dwell back to feed."""
    assert tape(["SELECT/HED,SADDLE,-25,TRAV"], lathe_with_saddle()) == [
        "N001G04Z+015",
        "N001G04M25R-00833",
        "N001G04R-00833",
        "N001G04R-00833",
        "N001G04Z+015",
    ]


def test_saddle_errors_name_what_is_wrong() -> None:
    with pytest.raises(InputError, match="no saddle register"):
        post(["SELECT/HED,SADDLE,1,5,IPM"], get_plugins().machine("mach04").load())
    with pytest.raises(InputError, match="SELECT/HED,SADDLE expects"):
        post(["SELECT/HED,SADDLE,1,TRAV,IPM"], lathe_with_saddle())
    with pytest.raises(InputError, match="SELECT/HED,SADDLE expects"):
        post(["SELECT/HED,SADDLE,TRAV"], lathe_with_saddle())
    with pytest.raises(MachineDefinitionError, match="option 85 = 0"):
        post(["SELECT/HED,SADDLE,1,5"], lathe_with_saddle("85 = 0.0\n"))
    with pytest.raises(InputError, match="SELECT/SADDLE: SELECT takes one of"):
        post(["SELECT/SADDLE,1"], lathe_with_saddle())


def test_a_saddle_move_under_sfm_goes_out_at_the_speed_in_force() -> None:
    """SADSFM (001 L36474-36478): not yet supported until wave 7 (tests/test_last_forms_wave7.py):
    the saddle changes no SFM radius, so SFMO leaves the speed as it is."""
    program = ["FROM/1,0,0", "SPINDL/100,SFM", "SELECT/HED,SADDLE,1,5,IPM"]
    assert tape(program, lathe_with_saddle())[-1] == "N003G04F005R+001"


# -- TMARK, RAPID, FEDRAT ------------------------------------------------------------------


def test_tmark_1_is_tmark() -> None:
    """The GEOUT4 example's TMARK/1 (001 L10122) prints one TMARK line."""
    machine = get_plugins().machine("mach04").load()
    assert tape(["TMARK/1"], machine) == tape(["TMARK"], machine)
    assert len(tape(["TMARK/1"], machine)) == 1


@pytest.mark.parametrize(
    ("statement", "message"),
    [
        ("TMARK/2", "TMARK/2: the manual defines TMARK and TMARK/1"),
        ("TMARK/ON", "TMARK/ON: the manual defines"),
        ("RAPID/ON", "RAPID/ON: RAPID takes no values"),
        ("RAPID/1", "RAPID/1: RAPID takes no values"),
        ("FEDRAT/10,INVERS", "FEDRAT/INVERS: FEDRAT takes"),
    ],
)
def test_forms_the_manual_does_not_define_are_bad_input(statement: str, message: str) -> None:
    with pytest.raises(InputError, match=message):
        post([statement], get_plugins().machine("mach04").load())


# -- option 93 < 0 -------------------------------------------------------------------------


def test_option_93_below_zero_needs_the_machines_macfun() -> None:
    """The dwell is the MACFUN's (001 L25507-25511): without one (option 133 = 0) the
    machine file is wrong, and so it is when the machine's MACFUN has no feed range hook
    (the hook itself: tests/test_statements_wave9.py)."""
    with pytest.raises(MachineDefinitionError, match="option 133 = 0"):
        post(["FEDRAT/1,RANGE,2"], overlaid("mach04", "[optab]\n93 = -2.0\n"))
    with pytest.raises(MachineDefinitionError, match="has no feed range hook"):
        post(["FEDRAT/1,RANGE,2"], overlaid("mach04", "[optab]\n93 = -2.0\n133 = 1.0\n"))
