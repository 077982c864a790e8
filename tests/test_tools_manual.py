"""The manual's tool handling beyond the T word (issue 22, part C): tool-length corrections
(TOOLGM, TOOLL, TOOLGP with option 86, TRANS; 001 L38605-38731, L38801-38835,
L25406-25434, L34934-34992), option 96's offset M code (WE-11, 001 L25564-25568) and T-word
layouts 1 and 7 (L25532-25560), the turret corrective moves TURRET/..., NOW|NEXT (CODE -3,
information block 7, fatal 41; L39054-39091, L9225-9233, L22232-22238, L28419-28421) and
SELECT/TOOL, OFSETL, TABLE (SELTUL, SELOFS, SELTAB; L37146-37335)."""

from __future__ import annotations

import re

import pytest
from gecent.core.errors import FatalError, InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.output.block import Code
from gecent.core.plugins import get_plugins
from gecent.core.run import Run, RunResult

from tests.test_post_linear import post


def lathe(**options: float) -> MachineDefinition:
    """MACH04 (option 59 = +Z-X, T format 50, option 96 = 2) with an 8-position turret."""
    machine = get_plugins().machine("mach04").load()
    return machine.with_options({106: 8.0, **{int(k[1:]): v for k, v in options.items()}})


def positioning(option_86: float) -> MachineDefinition:
    """MACH24 (positioning, T format 20), Z in the XY block (option 130 = -1)."""
    machine = get_plugins().machine("mach24").load()
    return machine.with_options({86: option_86, 130: -1.0})


def punched(lines: list[str], machine: MachineDefinition | None = None) -> list[str]:
    return [b.punch for b in post(lines, machine).blocks if b.punch]


def texts(result: RunResult) -> list[str]:
    return [d.text for d in result.diagnostics]


# -- option 96 -------------------------------------------------------------------------------


def test_we11_negative_option_96_outputs_the_offset_as_an_m_code() -> None:
    """WE-11 (derived in the digest): option 96 = -40 and OFSETL, 3 -> M43; T is the tool
    alone, in TOOLGP's CODE -1 block with the cycle-off G80."""
    machine = get_plugins().machine("mach24").load().with_options({96: -40.0})
    assert punched(["LOADTL/5,OFSETL,3"], machine) == ["N001G80T05M43"]


def test_adjust_without_option_263_is_the_offset_as_ofsetl() -> None:
    assert punched(["LOADTL/3,ADJUST,12"], lathe()) == punched(["TOOLNO/3,OFSETL,12"], lathe())
    with pytest.raises(InputError, match="one of OFSETL and ADJUST"):
        post(["LOADTL/3,ADJUST,1,OFSETL,2"], lathe())


@pytest.mark.parametrize(("layout", "expected"), [(1, "T50703"), (7, "T00503")])
def test_option_96_layouts_1_and_7(layout: int, expected: str) -> None:
    """Tool 7, position 3, offset 5: type 1 is offset (1 digit), tool (2), position (2);
    type 7 offset (1), position (2) (docs/decisions.md)."""
    (line,) = punched(["TURRET/7,3,OFSETL,5"], lathe(o96=float(layout)))
    assert line == f"N001G04Z+02{expected}"


def test_an_unknown_layout_type_is_refused() -> None:
    with pytest.raises(InputError, match="option 96 = 9 is no T-word layout"):
        post(["TURRET/7,3"], lathe(o96=9.0))


# -- tool length on contouring machines ---------------------------------------------------


MILL_LENGTHS = ["FROM/0,0,0", "FEDRAT/10", "LOADTL/1,LENGTH,5", "GOTO/1,0,0"]


def test_a_longer_tool_on_the_mill_raises_the_next_move_by_the_difference() -> None:
    """TOOLGM: the change of length (6.5 - 5) moves the previous Z, so the next move's Z
    departure is +1.5; the point it reaches (the tip, for the Absolute print) is the
    programmed one, and the information block 1 carries the change."""
    result = post([*MILL_LENGTHS, "LOADTL/2,LENGTH,6.5", "GOTO/2,0,0", "GOTO/3,0,0"])
    lines = [b.punch for b in result.blocks if b.punch]
    assert lines == [
        "N003G04X+05T01",
        "N004G01X+1F100",
        "N005G04X+05T02",
        "N006G01X+1Z+15F055",
        "N007X+1F100",
    ]
    (info,) = [b for b in result.blocks if b.code is Code.INFORMATION]
    assert info.cells[2] == 1.0 and info.cells[3] == 1.5
    moves = [b.position for b in result.blocks if b.code is Code.LINEAR]
    assert moves == [(10000, 0, 0), (20000, 0, 0), (30000, 0, 0)]


def test_the_same_length_or_no_length_moves_nothing() -> None:
    for load in ("LOADTL/2,LENGTH,5", "LOADTL/2"):
        lines = punched([*MILL_LENGTHS, load, "GOTO/2,0,0"])
        assert lines[-1] == "N006G01X+1"  # (F is modal; G follows the dwell's G04 again)


def test_a_zero_length_is_comment_19_and_a_negative_one_bad_input() -> None:
    result = post(["LOADTL/1,LENGTH,0"])
    assert texts(result) == ["TOOL LENGTH IS ZERO"]
    with pytest.raises(InputError, match="LENGTH expects a length >= 0"):
        post(["LOADTL/1,LENGTH,-2"])


def test_a_lathe_corrects_the_machine_z_through_option_59() -> None:
    """TOOLL: Z corrected for the length variation; MACH04's Z is CL X (+Z-X)."""
    lines = punched(
        [
            "FROM/0,0,0",
            "FEDRAT/10",
            "TOOLNO/1,LENGTH,2",
            "GOTO/1,0,0",
            "TOOLNO/2,LENGTH,3",
            "GOTO/1,0,0",
        ],
        lathe(),
    )
    assert lines[-1].startswith("N006G01Z+1")


# -- tool length on positioning machines (option 86) and TRANS ------------------------------


LOADS = ["FROM/0,0,10", "FEDRAT/10", "LOADTL/1,LENGTH,5", "GOTO/1,1,1"]
LATER = ["LOADTL/2,LENGTH,6", "GOTO/2,2,1", "TRANS/0,0,1", "GOTO/3,3,1"]


@pytest.mark.parametrize(
    ("option_86", "heights"),
    [
        (0.0, ["Z+010000", None, "Z+020000"]),
        (1.0, ["Z+010000", "Z+020000", "Z+030000"]),  # the change since the first tool
        (2.0, ["Z-040000", "Z-050000", "Z-040000"]),  # less the length
        (-1.0, ["Z+060000", "Z+070000", "Z+080000"]),  # POSMOV adds the length
    ],
)
def test_option_86_on_a_positioning_machine(option_86: float, heights: list[str | None]) -> None:
    """The Z of the three moves after the loads (None: Z did not change, not output)."""
    lines = punched([*LOADS, *LATER], positioning(option_86))
    found = [re.search(r"Z[+-]\d+", line) for line in lines if "X" in line]
    assert [z.group() if z else None for z in found] == heights


# -- TURRET NOW and NEXT ---------------------------------------------------------------------


TURRET_START = ["FROM/0,0,0", "FEDRAT/10", "TURRET/1,1,2,3", "GOTO/1,1,0"]


def test_turret_now_is_a_corrective_move_that_leaves_the_tool_point() -> None:
    """A 2 -> 2.5 along the spindle (machine Z), B 3 -> 1 across (machine X): the turret
    centre moves Z -0.5, X +2 at once, in a CODE -3 block processed as a line; the next
    move's departure is the programmed one."""
    result = post([*TURRET_START, "TURRET/2,2,2.5,1,NOW", "GOTO/2,1,0"], lathe())
    corrective = [b for b in result.blocks if b.code is Code.TURRET_CORRECTION]
    assert [b.punch for b in corrective] == ["N005G01X+2Z-05F04851"]
    assert corrective[0].position == (10000, 10000, 0)
    assert [b.punch for b in result.blocks if b.punch][-1] == "N006G01Z+1F100"


def test_turret_next_rides_in_the_next_move_with_information_block_7() -> None:
    """A 2 -> 1: the next move's Z departure is its own 1 and the correction 1."""
    result = post([*TURRET_START, "TURRET/3,3,1,3,NEXT", "GOTO/2,1,0"], lathe())
    assert [b.punch for b in result.blocks if b.punch][-1] == "N006G01Z+2F050"
    (info,) = [b for b in result.blocks if b.code is Code.INFORMATION]
    assert info.cells[2] == 7.0


def test_a_corrective_move_beyond_option_4_is_segmented_with_the_comment() -> None:
    result = post([*TURRET_START, "TURRET/2,2,2,0,NOW"], lathe(o4=1.0))
    corrective = [b for b in result.blocks if b.code is Code.TURRET_CORRECTION]
    assert len(corrective) == 4
    assert "TURRET CORRECTIVE MOVE EXCEEDED MAXIMUM DEPARTURE AND HAS BEEN SEGMENTED" in texts(
        result
    )


def test_a_corrective_move_too_large_to_segment_is_fatal_41() -> None:
    from gecent.core.cl.apt_source import AptSourceReader

    """The correction would take more segments than gecent's bound (--max-segments)."""
    run = Run(lathe(o4=0.01), max_segments=1000)
    lines = [*TURRET_START, "TURRET/2,2,2,-900,NOW", "FINI"]
    with pytest.raises(FatalError) as raised:
        run.process(AptSourceReader("part.apt").read_lines(lines))
    assert raised.value.number == 41


def test_no_correction_for_the_first_tool_or_without_now_or_next() -> None:
    assert punched(["FROM/0,0,0", "TURRET/1,1,2,3,NOW"], lathe()) == ["N002G04Z+02T00011"]
    lines = punched([*TURRET_START, "TURRET/2,2,9,9", "GOTO/2,1,0"], lathe())
    assert lines[-1] == "N006G01Z+1F100"


@pytest.mark.parametrize(
    ("line", "machine", "error", "message"),
    [
        ("TURRET/2,2,NOW", lathe(), InputError, "needs the tool's distances"),
        ("TURRET/2,2,1,NOW", lathe(), InputError, "as a pair"),
        ("TURRET/2,2,1,1,NOW,NEXT", lathe(), InputError, "one of NOW and NEXT"),
        ("TURRET/2,2,1,1,NOW", lathe(o106=0.0), InputError, "option 106"),
        ("TOOLNO/2,NOW", lathe(), InputError, "does not take NOW"),
        # was NotYetSupported: the manual's TURRET is the contouring lathe's (001 L25532)
        ("TURRET/2,2,1,1,NOW", positioning(0.0), InputError, "ROTATE/TURRET"),
    ],
)
def test_bad_turret_corrections(
    line: str, machine: MachineDefinition, error: type[Exception], message: str
) -> None:
    with pytest.raises(error, match=message):
        post(["FROM/0,0,0", "TURRET/1,1,2,3", line], machine)


# -- SELECT/TOOL, OFSETL, TABLE -----------------------------------------------------------


SELECTING = """
[machine]
name = "selecting"
[regstr]
16 = "R"
17 = "D"
[regfor]
13 = 30.0
16 = 20.0
17 = 20.0
"""


def selecting() -> MachineDefinition:
    return load_machine_text(SELECTING, "selecting.toml")


def test_select_tool_preselects_and_warns_when_a_selection_was_not_loaded() -> None:
    """SELTUL: T in a CODE -4 block; a second selection before a load gives the comment."""
    lines = ["SELECT/TOOL,4", "SELECT/TOOL,5,OFSETL,2", "LOADTL/5", "SELECT/TOOL,6"]
    result = post(lines, selecting())
    assert texts(result) == ["PREVIOUSLY SELECTED TOOL WAS NOT LOADED - PRESENT TOOL IS SELECTED"]
    blocks = [b for b in result.blocks if b.code is Code.G_ONLY]
    assert [b.cells[13] for b in blocks] == [4, 502, 6]


def test_select_ofsetl_and_table_output_their_registers() -> None:
    lines = punched(["SELECT/OFSETL,3", "SELECT/TABLE,2"], selecting())
    assert lines == ["N001D03", "N002R02"]


def test_select_ofsetl_without_its_register_warns() -> None:
    result = post(["SELECT/OFSETL,3"], standard_machine())
    assert texts(result) == ["SELECT/OFSETL: THE MACHINE HAS NO REGISTER 17 FOR IT"]
    with pytest.raises(InputError, match="SELECT/TABLE expects one table number"):
        post(["SELECT/TABLE,1,2"], selecting())
