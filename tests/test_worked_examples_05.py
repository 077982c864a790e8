"""Golden tests: spec 05's worked example E16, the rapid traverse sequence of manual §4.1.4
(001 L11809-11910), the one example of digest 05 without a test of its own (issue 22).

The others are tested where their feature lives: E1, E3, E4, E17, E20, E21, E22 in
tests/test_feed_forms.py; E2 in tests/test_multiaxis_motion.py; E5-E14 and E15's table in
tests/test_feed_types.py (E15 posted in tests/test_rotary_positioning.py); E18, E19 in
tests/test_feed_limits.py; E23's hand-checkable cases in tests/test_class1.py, _class2,
_class4, _class5, its round trip in tests/contract/test_classes.py.

The manual's program is

    (1) RAPID          RAPID sets RAPFLG = 1
    (2) GOTO/x,y,z     TSTFLG -> RAPIDO: RAPFLG = 0, FLRPON on, the gear-shift M codes,
                       FRAPID = -option 42: the block's F is negative, a rapid traverse
    (3) GOTO/x,y,z     TSTFLG -> RAPIDX: FRAPID = FLRPON = 0, the shift-back M codes;
                       the block's F is FEDIPM again

with three variants: RAPID again before (3) makes no new gear shift (FLRPON is on); a move
shorter than option 37 does not shift but goes at option 39, the feed range's highest; a
move the tape reader cannot keep up with sets FRAPID positive, to the reader's highest feed,
and the block is still marked rapid. gecent marks a rapid block by ``Block.rapid`` and keeps
its feed in IPM in cell 19; FRAPID is ``Feed.rapid_ipm``, FLRPON ``Feed.rapid_mode``.

At the end, tests for two checklist items of digest 05 that no test exercised: the
feedrate-number command raised to option 49, and the table feed held to options 113/114.
"""

from __future__ import annotations

from math import pi

import pytest
from gecent.core.feed.rapid import ONE_SHOT, RapidTraverse
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.output.block import Block, Code
from gecent.core.plugins import get_plugins
from gecent.core.state import PostState

from .test_post_linear import post

# A mill that shifts gears for rapid: option 46 = -1, one M code for all axes, TABLEM(42) =
# M40 into rapid and TABLEM(43) = M41 back (as MACH04, 001 L27712-27713), with no dwells so
# each code rides in its motion block; option 42 = 200 IPM (standard), option 13 = 0: no
# tape-reader limit unless a test sets one.
GEAR_SHIFT = {46: -1.0, 16: 0.0, 81: 0.0, 82: 0.0, 13: 0.0}


def _machine(optab: dict[int, float]) -> MachineDefinition:
    text = '[machine]\nnumber = 87\nname = "rapid"\ntitle = "RAPID TEST"\n'
    text += "[tablem]\n42 = 40\n43 = 41\n"
    text += "[optab]\n" + "".join(f"{k} = {v}\n" for k, v in optab.items())
    return load_machine_text(text, "rapid.toml")


def _motion(program: list[str], optab: dict[int, float]) -> list[Block]:
    result = post(["FROM/0,0,0", "FEDRAT/10", *program], _machine(optab))
    assert result.diagnostics == []
    return [b for b in result.blocks if b.code is Code.LINEAR]


def test_e16_the_flags_of_rapid_rapido_and_rapidx() -> None:
    """E16 statement by statement, on the flags the manual names (001 L11839-11870):
    RAPID sets RAPFLG; the first motion clears it, sets FLRPON and FRAPID = -option 42 and
    stores the gear-shift code; the second clears FRAPID and FLRPON and stores the code
    back."""
    machine = _machine({**GEAR_SHIFT, 42: 180.0})
    state = PostState(machine)
    stored: list[float] = []
    emitted: list[Block] = []

    def no_dwell(seconds: float) -> Block:
        pytest.fail(f"a {seconds} s dwell with options 16, 81, 82 = 0")

    rapid = RapidTraverse(state, emitted.append, stored.append, no_dwell)
    feed = state.feed

    rapid.request()  # (1) RAPID
    assert (feed.rapid_requested, feed.rapid_mode, feed.rapid_ipm) == (True, 0, 0.0)

    rapid.motion(5.0)  # (2) GOTO: RAPIDO
    assert (feed.rapid_requested, feed.rapid_mode, feed.rapid_ipm) == (False, ONE_SHOT, -180.0)
    assert stored == [40.0]

    rapid.motion(1.0)  # (3) GOTO: RAPIDX
    assert (feed.rapid_requested, feed.rapid_mode, feed.rapid_ipm) == (False, 0, 0.0)
    assert stored == [40.0, 41.0]
    assert emitted == []


def test_e16_rapid_then_the_feed_returns() -> None:
    """E16: (2) goes at rapid, option 42 = 200 IPM, with the shift code M40: on a single
    axis the vector optimisation (option 36 = 0) keeps 200 IPM, command 10 x 200 / 5 = 400;
    (3) is back at FEDIPM = 10 IPM, F = 10 x 10 / 1 = 100, with the shift-back code M41."""
    blocks = _motion(["RAPID", "GOTO/5,0,0", "GOTO/6,0,0"], GEAR_SHIFT)
    assert [b.punch for b in blocks] == ["N004G01X+5F400M40", "N005X+1F100M41"]
    assert [b.rapid for b in blocks] == [True, False]
    assert [b.cells[19] for b in blocks] == [200.0, 10.0]


def test_e16_rapid_again_makes_no_second_gear_shift() -> None:
    """E16 variant (001 L11871-11876): RAPID before (3) finds FLRPON on, so (3) is rapid
    again without M40; the move after it shifts back once. (3) is 5 in, command 400 again,
    which the F register does not repeat."""
    blocks = _motion(["RAPID", "GOTO/5,0,0", "RAPID", "GOTO/10,0,0", "GOTO/11,0,0"], GEAR_SHIFT)
    assert [b.punch for b in blocks] == ["N004G01X+5F400M40", "N006X+5", "N007X+1F100M41"]
    assert [b.rapid for b in blocks] == [True, True, False]
    assert [b.cells[19] for b in blocks] == [200.0, 200.0, 10.0]


def test_e16_a_move_shorter_than_option_37_stays_in_the_feed_range() -> None:
    """E16 variant (001 L11878-11884): option 37 = 2 in, a 1 in move: no gear shift either
    way; the move goes at option 39 (standard 50 IPM), the feed range's highest. It is still
    a rapid block for the optimisation, with option 39 for every axis (001 L12630-12631):
    10 x 50 / 1 = 500."""
    blocks = _motion(["RAPID", "GOTO/1,0,0", "GOTO/2,0,0"], {**GEAR_SHIFT, 37: 2.0})
    assert [b.punch for b in blocks] == ["N004G01X+1F500", "N005X+1F100"]
    assert [b.cells[19] for b in blocks] == [50.0, 10.0]


def test_e16_the_tape_reader_holds_the_rapid_down() -> None:
    """E16 variant (001 L11886-11897): option 13 = 0.05 min to read a block, so a 5 in move
    can go at 5 / 0.05 = 100 IPM at most, under option 42's 200: FRAPID is set positive
    (+100) and the block is still marked rapid, at 100 IPM: command 10 x 100 / 5 = 200."""
    machine = _machine({**GEAR_SHIFT, 13: 0.05})
    state = PostState(machine)
    emitted: list[Block] = []
    stored: list[float] = []
    rapid = RapidTraverse(state, emitted.append, stored.append, lambda s: pytest.fail("dwell"))
    rapid.request()
    rapid.motion(5.0)
    assert state.feed.rapid_ipm == pytest.approx(100.0)
    assert (stored, emitted) == ([40.0], [])  # the gears still shift into rapid

    blocks = _motion(["RAPID", "GOTO/5,0,0", "GOTO/6,0,0"], {**GEAR_SHIFT, 13: 0.05})
    assert [b.punch for b in blocks] == ["N004G01X+5F200M40", "N005X+1F100M41"]
    assert [b.rapid for b in blocks] == [True, False]
    assert blocks[0].cells[19] == pytest.approx(100.0)


# --- checklist items of digest 05 that no test exercised (issue 22's review) -------------


def test_a_feedrate_number_below_option_49_is_raised_to_it() -> None:
    """Spec 05 §3 bound rule (001 L10799-10815): 1 IPM along (9, 9, 9), S = 15.588, in
    G01 (D = 10): Fc = 10 / 15.588 = 0.64 < option 49 (1): the command is 1 and the feed it
    gives is FIPM = Fc S / D = 1.5588 IPM."""
    result = post(["FROM/0,0,0", "FEDRAT/1", "GOTO/9,9,9"])
    (block,) = [b for b in result.blocks if b.punch]
    assert block.punch == "N003G01X+9Y+9Z+9F001"
    assert block.cells[19] == pytest.approx(15.588457 / 10)


@pytest.mark.parametrize(
    ("options", "feed", "punch", "ipm"),
    [
        ({114: 0.25}, 30, "N002G10A+0833F300", 2 * pi * 6 * 0.25),  # held to the maximum
        ({113: 0.2}, 1, "N002G10A+0833F240", 2 * pi * 6 * 0.2),  # raised to the minimum
    ],
)
def test_the_table_feed_is_held_to_options_113_and_114_at_the_part_radius(
    options: dict[int, float], feed: float, punch: str, ipm: float
) -> None:
    """Spec 05 §3.1.3 (001 L10936-10984): the rotary table's minimum and maximum, options
    113 and 114 in RPM, are 2 pi R RPM in IPM at option 112's part radius (MACH23: 6 in).
    A 30 degree turn is S = pi / 6 x 6 = 3.1416 in, in G10 (D = 100): 0.25 RPM is 9.425
    IPM, F = 100 x 9.425 / 3.1416 = 300; 0.2 RPM is 7.540 IPM, F = 240."""
    machine = get_plugins().machine("mach23").load().with_options(options)
    result = post([f"FEDRAT/{feed}", "ROTATE/TABLE,INCR,30,CLW"], machine)
    (block,) = [b for b in result.blocks if b.punch]
    assert block.punch == punch
    assert block.cells[19] == pytest.approx(ipm)
