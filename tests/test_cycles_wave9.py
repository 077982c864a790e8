"""Wave 9: the last canned-cycle forms that stopped a run, built (issue 22).

* a positioning control's missing cycle drilled by moves now dwells and stores its spindle
  M codes on the way: TAP out with the spindle reversed, BORE,DRAG and BORE,MANUAL with the
  spindle (and program) stopped at the bottom, FACE and the DWELL forms with a dwell block
  (TABLEG 82-95, 001 L22875-22977; CYCLGP 001 L30095-30204; STOREM 001 L38041-38087);
* a machine without the M code a cycle by moves needs: STOREM's comment 22, once, at the
  CYCLE statement (CLAMP's way, 001 L29337-29358);
* a tap whose spindle turned CCLW after the CYCLE statement, on a control with G84: G80 and
  the tap by moves (no TABLEG names G74);
* a control's cycle with incremental dimensions (option 251 = 0 or 2): G91's block;
* cycle macros (spec 09 §5.6) on a positioning machine (CYCLGP).

No worked example of the manual covers these forms (the digests' "Worked examples" have
none for canned cycles): the values below are worked out in each test's docstring.
Decisions: docs/decisions.md, "Cycles: the last forms (issue 22 wave 9)"."""

from __future__ import annotations

from typing import Any

import pytest
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.macros import Kind, Macros, Phase
from gecent.core.macros.table import with_macros
from gecent.core.output.element import NOT_AVAILABLE
from gecent.core.output.tape import tape_image, tape_lines
from gecent.core.plugins import get_plugins
from gecent.core.run import Run
from gecent.core.state import RunResult

from tests.macros_helpers import records
from tests.test_post_linear import post

LEFT_HAND = "CYCLE/TAP IS DRILLED BY MOVES: A LEFT-HAND TAP (SPINDLE CCLW) HAS NO TABLEG CODE"


def overlay(base: str, text: str, name: str = "w9") -> MachineDefinition:
    pack = get_plugins().machine(base).load()
    return load_machine_text(f'[machine]\nname = "{base}-{name}"\n{text}', "w9.toml", base=pack)


def positioning(extra_tableg: str = "", tablem: str = "4 = 3\n5 = 4\n6 = 5\n") -> MachineDefinition:
    """MACH24 (a positioning control, Z on tape by option 130 = +1) without the cycles
    named, and with the spindle codes M03, M04, M05 in TABLEM 4-6 (the sample has TABLEM(4)
    and (6) absent)."""
    return overlay(
        "mach24",
        f"[tableg]\n{extra_tableg}[optab]\n130 = 1.0\n" + (f"[tablem]\n{tablem}" if tablem else ""),
    )


def holes(cycle: str, machine: MachineDefinition) -> tuple[list[str], list[tuple[str, int]]]:
    lines = ["FROM/0,0,5", "SPINDL/300,CLW", "FEDRAT/10", f"CYCLE/{cycle}", "GOTO/4,4,0",
             "GOTO/5,4,0"]  # fmt: skip
    result = post(lines, machine)
    notes = [(d.text, d.where.line if d.where else 0) for d in result.diagnostics]
    return tape_lines(result.blocks), notes


# -- 1. a positioning control's missing cycle, by moves, with its M codes and dwell ----------


def test_a_tap_the_control_lacks_reverses_the_spindle_on_the_way_out() -> None:
    """TAP without G84 (TABLEG(85)): across at the tool's height, rapid to R = .1, feed to
    the bottom -.5 (F = 2 x 6 IPM), out to R at feed with the spindle reversed (M04), and the
    spindle forward again (M03) with the next block, the move to the next hole."""
    tape, notes = holes("TAP,DEPTH,0.5,IPM,6,CLEAR,0.1", positioning('85 = "absent"\n'))
    assert tape == [
        "N002S03M03",
        "N005G80X+040000Y-040000F99",
        "N005Z+001000",
        "N005Z-005000F12",
        "N005Z+001000M04",
        "N006X+050000F99M03",
        "N006Z-005000F12",
        "N006Z+001000M04",
    ]
    assert notes == []


def test_a_left_hand_tap_by_moves_reverses_to_m03_and_back_to_m04() -> None:
    machine = positioning('85 = "absent"\n')
    lines = ["FROM/0,0,5", "SPINDL/300,CCLW", "FEDRAT/10", "CYCLE/TAP,DEPTH,0.5,IPM,6,CLEAR,0.1",
             "GOTO/4,4,0", "GOTO/5,4,0"]  # fmt: skip
    tape = tape_lines(post(lines, machine).blocks)
    assert tape[4:6] == ["N005Z+001000M03", "N006X+050000F99M04"]


def test_bore_dwell_manual_by_moves_dwells_stops_and_restarts() -> None:
    """BORE,DWELL,MANUAL without TABLEG(95): feed to the bottom, the dwell (G04 = TABLEG(5),
    2 s / option 56 = 10 in X, option 57 = 3), the spindle stop M05 and the program stop M00
    each in a block of their own, then out at rapid with the spindle starting again (M03)."""
    tape, notes = holes(
        "BORE,DWELL,MANUAL,DEPTH,0.5,IPM,6,CLEAR,0.1,DWELL,2", positioning('95 = "absent"\n')
    )
    assert tape[1:] == [
        "N005G80X+040000Y-040000F99",
        "N005Z+001000",
        "N005Z-005000F12",
        "N005G04X+002000",
        "N005M05",
        "N005M00",
        "N005G80Z+001000F99M03",
        "N006X+050000",
        "N006Z-005000F12",
        "N006G04X+002000",
        "N006M05",
        "N006M00",
        "N006G80Z+001000F99M03",
    ]
    assert notes == []


def test_bore_drag_by_moves_stops_the_spindle_on_the_way_out() -> None:
    """BORE,DRAG without TABLEG(91): out at rapid with M05, M03 with the next move."""
    tape, _ = holes("BORE,DRAG,DEPTH,0.5,IPM,6,CLEAR,0.1", positioning('91 = "absent"\n'))
    assert tape[3:6] == ["N005Z-005000F12", "N005Z+001000F99M05", "N006X+050000M03"]


@pytest.mark.parametrize(
    ("cycle", "absent", "time"),
    [("FACE,DEPTH,0.5,IPM,6,CLEAR,0.1,DWELL,1.5", 83, "X+001500"),
     ("DRILL,DEPTH,0.5,IPM,6,CLEAR,0.1,DWELL,2", 82, "X+002000")],
)  # fmt: skip
def test_face_and_a_drill_with_a_dwell_dwell_at_the_bottom(
    cycle: str, absent: int, time: str
) -> None:
    tape, _ = holes(cycle, positioning(f'{absent} = "absent"\n'))
    assert tape[3:6] == ["N005Z-005000F12", f"N005G04{time}", "N005G80Z+001000F99"]


def test_bore_dwell_without_a_time_is_warned_by_moves_too() -> None:
    _, notes = holes("BORE,DWELL,DEPTH,0.5,IPM,6,CLEAR,0.1", positioning('94 = "absent"\n'))
    assert ("CYCLE/BORE,DWELL NAMES NO DWELL TIME: IT DWELLS 0 SECONDS", 4) in notes


def test_a_missing_spindle_stop_is_comment_22_once_at_the_statement() -> None:
    """MACH24 as sampled has no spindle-stop code (TABLEM(6)): DRAG by moves is STOREM's
    comment 22 at the CYCLE statement (line 4), and the way out has no M code."""
    machine = positioning('91 = "absent"\n', tablem="")
    tape, notes = holes("BORE,DRAG,DEPTH,0.5,IPM,6,CLEAR,0.1", machine)
    assert (NOT_AVAILABLE, 4) in notes and sum(line == 4 for _, line in notes) == 1
    assert tape[4] == "N005Z+001000F99"


def test_a_contouring_drag_without_a_spindle_stop_is_comment_22() -> None:
    """The expansion on a contouring machine: the same comment 22 (was NotYetSupported)."""
    no_stop = load_machine_text('[machine]\nname = "m"\ntitle = "M"\n[tablem]\n6 = "absent"\n')
    result = post(["FROM/0,0,1", "CYCLE/BORE,DRAG,1,IPM,2,0.1", "GOTO/1,0,0"], no_stop)
    assert [(d.text, d.where.line if d.where else 0) for d in result.diagnostics] == [
        (NOT_AVAILABLE, 2)
    ]
    assert tape_lines(result.blocks)[-1] == "N003Z+11F500"  # out at rapid, no M


# -- 2. a left-hand tap on a control with G84 ---------------------------------------------------


def test_a_tap_turned_cclw_after_the_statement_is_drilled_by_moves() -> None:
    """LinuxCNC: G84 at X1; SPINDL/CCLW; the next two holes G80 then by moves from R = .1
    (across at rapid, feed to -.5, out at feed with M03, M04 with the next move), the reason
    warned once; SPINDL/CLW again: G84 with its Z and R stated again."""
    machine = get_plugins().machine("linuxcnc-mill-inch").load()
    lines = ["UNITS/INCHES", "FROM/0,0,2", "SPINDL/300,CLW", "FEDRAT/10",
             "CYCLE/TAP,DEPTH,0.5,IPM,6,CLEAR,0.1", "GOTO/1,1,0", "SPINDL/300,CCLW",
             "GOTO/2,1,0", "GOTO/3,1,0", "SPINDL/300,CLW", "GOTO/4,1,0", "CYCLE/OFF"]  # fmt: skip
    result = post(lines, machine)
    assert tape_lines(result.blocks)[4:-2] == [
        "N3 G84 X1. Y1. Z-0.5 F6. R0.1",
        "N4 S300 M04",
        "N5 G80",
        "N6 G00 X2.",
        "N7 G01 Z-0.5",
        "N8 Z0.1 M03",
        "N9 G00 X3. M04",
        "N10 G01 Z-0.5",
        "N11 Z0.1 M03",
        "N12 M04",
        "N13 S300 M03",
        "N14 G84 X4. Y1. Z-0.5 R0.1",
        "N15 G80",
    ]
    assert [(d.text, d.where.line) for d in result.diagnostics if d.where and "TAP" in d.text] == [
        (LEFT_HAND, 8)
    ]


# -- 3. a control's cycle with incremental dimensions ------------------------------------------


@pytest.mark.parametrize(("option", "dimension"), [("2.0", " G91"), ("0.0", "")])
def test_a_control_cycle_with_incremental_dimensions_is_g91s_block(
    option: str, dimension: str
) -> None:
    """From Z 2: the first hole (top 0) R = .1 - 2 = -1.9, Z = -.5 - .1 = -.6; G99 leaves
    the tool at R .1; the second (top -.25) X +1, R = -.15 - .1 = -.25, Z = -.6; after G80
    the move home is the departure from (2, 1, -.15)."""
    machine = overlay("linuxcnc-mill-inch", f"[optab]\n251 = {option}\n")
    lines = ["UNITS/INCHES", "FROM/0,0,2", "SPINDL/300,CLW", "FEDRAT/10",
             "CYCLE/DRILL,DEPTH,0.5,IPM,6,CLEAR,0.1", "GOTO/1,1,0", "GOTO/2,1,-0.25",
             "CYCLE/OFF", "GOTO/0,0,2"]  # fmt: skip
    result = post(lines, machine)
    tape = tape_lines(result.blocks)
    assert tape[1] == f"G17 G20{dimension} G94 G40 G49 G80 G54"
    assert tape[3:8] == [
        "N2 G99",
        "N3 G81 X1. Y1. Z-0.6 F6. R-1.9",
        "N4 X1. Y0. Z-0.6 R-0.25",
        "N5 G80",
        "N6 G01 X-2. Y-1. Z2.15",
    ]
    assert result.diagnostics == []


def test_absolute_dimensions_keep_the_positions() -> None:
    machine = get_plugins().machine("linuxcnc-mill-inch").load()
    lines = ["UNITS/INCHES", "FROM/0,0,2", "FEDRAT/10", "CYCLE/DRILL,DEPTH,0.5,IPM,6,CLEAR,0.1",
             "GOTO/1,1,0", "GOTO/2,1,-0.25"]  # fmt: skip
    assert tape_lines(post(lines, machine).blocks)[-4:-2] == [
        "N2 G81 X1. Y1. Z-0.5 F6. R0.1",
        "N3 X2. Y1. Z-0.75 R-0.15",
    ]


# -- 4. cycle macros on a positioning machine (CYCLGP) ------------------------------------------

PROGRAM = (
    "PARTNO T\nFROM/0,0,1\nSPINDL/500\nFEDRAT/10\nCYCLE/DRILL,DEPTH,.5,CLEAR,.1,IPM,5\n"
    "GOTO/1,1,0\nGOTO/2,1,0\nGOTO/3,1,0\nGOTO/4,1,0\nCYCLE/OFF\nFINI\n"
)


def macro_post(macros: Macros, extra: str) -> tuple[str, RunResult]:
    plugins = with_macros(get_plugins(), macros.macros)
    pack = plugins.machine("mach24").load()
    machine = load_machine_text(f'[machine]\nname = "mach24-w9"\n{extra}', "w9.toml", base=pack)
    result = Run(machine, plugins, fast=True).process(iter(records(PROGRAM)))
    return tape_image(result.blocks), result


def test_cycle_macros_run_around_a_positioning_controls_holes() -> None:
    """MACH24's G81 from Z 1: plunge 1 - (0 - .5) = 1.5, R 1 - .1 = .9. $P1 = 0 skips the
    hole at X2 (no shutdown); $P13 = -1 at X3 makes the plunge 2.0 (the block stated again);
    $P1 = -1 at X4 drills it by moves (G80, no shutdown). $P11, $P13, $P15: R plane, bottom
    and the tool's height, the level the control returns to."""
    seen: list[tuple[Any, ...]] = []
    ends: list[float] = []
    macros = Macros(machine="mach24-w9")

    @macros.event(Kind.CYCLE, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        p = ctx.p
        seen.append((p.cl[0], p.cycle_type, p.activating, p.clearance, p.depth, p.retract))
        p.control = {2: 0.0, 4: -1.0}.get(int(p.cl[0]), 1.0)
        if p.cl[0] == 3:
            p.depth = -1.0

    @macros.event(Kind.CYCLE, Phase.SHUTDOWN)
    def after(ctx):  # type: ignore[no-untyped-def]
        ends.append(ctx.p.cl[0])

    tape, _ = macro_post(macros, "[optab]\n130 = 1.0\n")
    assert tape.splitlines()[2:] == [
        "N006G81Z+015000F10R+009",
        "N006X+010000Y-010000",
        "N008Z+020000R+009",
        "N008X+030000",
        "N009G80X+040000F99",
        "N009Z+001000",
        "N009Z-005000F10",
        "N009Z+001000F99",
    ]
    assert seen == [
        (1.0, 1.0, True, 0.1, -0.5, 1.0),
        (2.0, 1.0, False, 0.1, -0.5, 1.0),
        (3.0, 1.0, False, 0.1, -0.5, 1.0),
        (4.0, 1.0, True, 0.1, -0.5, 1.0),
    ]
    assert ends == [1.0, 3.0]


def test_a_positioning_retract_plane_is_bad_input_naming_why() -> None:
    macros = Macros(machine="mach24-w9")

    @macros.event(Kind.CYCLE, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        ctx.p.retract = 2.0

    with pytest.raises(
        InputError, match=r"\$P14/\$P15 \(retract plane\) on a positioning"
    ) as caught:
        macro_post(macros, "")
    assert caught.value.where is not None and caught.value.where.line == 6


def test_by_moves_without_z_on_tape_is_bad_input() -> None:
    """$P1 = -1 on MACH24 as sampled (option 130 = 0): no Z on tape to drill by moves."""
    macros = Macros(machine="mach24-w9")

    @macros.event(Kind.CYCLE, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        ctx.p.control = -1.0

    with pytest.raises(InputError, match=r"by moves \(a cycle macro's \$P1 = -1\).*130 = 0"):
        macro_post(macros, "")


def switching(startup: Any) -> list[str]:
    macros = Macros(machine="mach24-w9")
    macros.event(Kind.CYCLE, Phase.STARTUP)(startup)
    tape, _ = macro_post(macros, "")
    return tape.splitlines()[2:]


def test_positioning_output_switches_restate_force_and_leave_out() -> None:
    """$P5 True at X2 states the cycle block again, its G and F forced; $P10 True at X2
    forces the block out with R (G and F modal); $P8 False at X1 leaves F out of the hole's
    blocks (the control's F comes with the next block), True at X3 forces it."""

    def activate(ctx):  # type: ignore[no-untyped-def]
        if ctx.p.cl[0] == 2:
            ctx.p.activating = True

    def clearance(ctx):  # type: ignore[no-untyped-def]
        if ctx.p.cl[0] == 2:
            ctx.p.clearance_out = True

    def feed(ctx):  # type: ignore[no-untyped-def]
        if ctx.p.cl[0] in (1, 3):
            ctx.p.feed_out = ctx.p.cl[0] == 3

    assert switching(activate)[2] == "N007G81Z+015000F10R+009"
    assert switching(clearance)[2] == "N007Z+015000R+009"
    assert switching(feed) == [
        "N006G81Z+015000R+009",
        "N006X+010000Y-010000",
        "N007X+020000F10",
        "N008X+030000F10",
        "N009X+040000",
    ]


def test_positioning_feed_alone_skips_the_hole_without_output() -> None:
    """$P1 = -2 (the feed alone): MACH24's cycle blocks carry the positioning feed type's
    F, no direct feed (option 254 = 0), so nothing goes out, and with no OUTPUT in the macro
    the hole at X2 is not drilled (core/macros/cycle_switches.py)."""

    def alone(ctx):  # type: ignore[no-untyped-def]
        if ctx.p.cl[0] == 2:
            ctx.p.control = -2.0

    assert switching(alone)[2:] == ["N008X+030000", "N009X+040000"]


def test_a_positioning_retract_switch_is_bad_input() -> None:
    def retract(ctx):  # type: ignore[no-untyped-def]
        ctx.p.retract_out = True

    with pytest.raises(InputError, match=r"\$P14/\$P15 \(retract plane\)"):
        switching(retract)
