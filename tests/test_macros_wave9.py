"""The last macro forms that stopped a run as not built (spec 09 §5.5-§5.12): a tool change
macro's changed values, an LCS macro's motion flag, a motion macro's helical component, a
cycle macro's output switches and feed alone, a diagnostic macro's number and severity, and
the operation-event macro's redundancy guard."""

from __future__ import annotations

import pytest
from gecent.core.errors import WARNING_COMMENTS, InputError, RunStopped
from gecent.core.macros import Kind, Macros, Phase
from gecent.core.output.block import Code

from .macros_helpers import post, warnings

HEAD = "PARTNO T\nUNITS/MM\nFROM/0,0,10\nFEDRAT/100\n"


# -- 1. tool change (§5.5: the startup macro's changes alter the tool change) -----------------


def test_tool_change_macro_changes_go_to_the_posts_tool_change() -> None:
    macros = Macros()

    @macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
    def remap(ctx):  # type: ignore[no-untyped-def]
        ctx.p.tool_id = ctx.p.tool_id + 10  # $P9
        ctx.p.ofsetl = 3  # $P5
        ctx.p.drum = 2  # $P4: CCLW

    plain, _ = post(HEAD + "LOADTL/1,CLW\nGOTO/1,0,0\nFINI\n", None)
    tape, _ = post(HEAD + "LOADTL/1,CLW\nGOTO/1,0,0\nFINI\n", macros)
    assert "T01 M06" in plain and "H1" in plain
    assert "T11 M06" in tape and "H3" in tape
    written, _ = post(HEAD + "LOADTL/11,OFSETL,3,CCLW\nGOTO/1,0,0\nFINI\n", None)
    assert tape == written  # exactly the statement the changed values make


def test_a_turret_macro_changes_now_to_next_and_front_to_rear() -> None:
    """TURRET's $P2 (the correction NOW/NEXT) and $P18 (FRONT/REAR) go to the post's
    TURRET as its words (MACH04, option 106 = 8: the corrective move, core/tool.py)."""
    program = (
        "PARTNO T\nMACHIN/GECENT,4,OPTAB,106,8\nFROM/0,0,0\nFEDRAT/10\nTURRET/1,1,2,3\n"
        "GOTO/1,1,0\nTURRET/2,2,2.5,1,NOW\nGOTO/2,1,0\nFINI\n"
    )
    macros = Macros(machine="mach04")

    @macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
    def later(ctx):  # type: ignore[no-untyped-def]
        if ctx.p.tool_id == 2:
            ctx.p.adjust, ctx.p.head_side = 2, 2  # NEXT, REAR

    tape, _ = post(program, macros, "mach04")
    assert tape == post(program.replace(",NOW\n", ",NEXT,REAR\n"), None, "mach04")[0]
    assert tape != post(program, None, "mach04")[0]  # (NOW: the move comes at once)


def test_a_value_written_back_unchanged_is_no_change() -> None:
    macros = Macros()

    @macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
    def same(ctx):  # type: ignore[no-untyped-def]
        ctx.p.gripper = ctx.p.gripper  # $P7 as it was: nothing for the post to take
        ctx.p.change_type = ctx.p.change_type

    program = HEAD + "LOADTL/1\nGOTO/1,0,0\nFINI\n"
    assert post(program, macros)[0] == post(program, None)[0]


def test_a_value_the_posts_tool_change_cannot_take_is_the_macros_error() -> None:
    for field, value, what in (("gripper", 2, "gripper size"), ("adjust", 2, "NOW/NEXT"),
                               ("times", 3, "TIMES"), ("head_pocket", 1, "head")):  # fmt: skip
        macros = Macros()

        def change(ctx, field: str = field, value: int = value) -> None:  # type: ignore[no-untyped-def]
            setattr(ctx.p, field, value)

        macros.event(Kind.TOOL_CHANGE, Phase.STARTUP, name="change")(change)
        with pytest.raises(InputError, match=f"macro .*change.*{what}"):
            post(HEAD + "LOADTL/1\nGOTO/1,0,0\nFINI\n", macros)


# -- 2. LCS motion (§5.8 $P21, $LCSMTN 004 L512-531) -------------------------------------------


def test_trans_offers_no_lcs_motion_and_a_macro_asking_one_is_warned() -> None:
    seen: list[object] = []
    macros = Macros()

    @macros.event(Kind.LCS, Phase.STARTUP)
    def rotate(ctx):  # type: ignore[no-untyped-def]
        seen.append(ctx.p.motion)
        ctx.p.motion = 2  # RTCP motion: a translation has none to make

    @macros.event(Kind.LCS, Phase.SHUTDOWN)
    def after(ctx):  # type: ignore[no-untyped-def]
        seen.append(ctx.p.motion)

    program = HEAD + "TRANS/1,2,3\nGOTO/1,0,0\nFINI\n"
    tape, result = post(program, macros)
    assert seen == [-1.0, -1.0]  # -1 on entry: "LCS generated motions are not available"
    assert any("LCS MOTION NOT AVAILABLE" in w and "$P21 = 2" in w for w in warnings(result))
    plain, _ = post(program, None)
    # the frame is adjusted as without the macro: the same moves, plus the warning's comment
    assert [line for line in tape.splitlines() if "LCS" not in line] == plain.splitlines()


def test_an_lcs_macro_leaving_p21_at_minus_one_is_silent() -> None:
    macros = Macros()

    @macros.event(Kind.LCS, Phase.STARTUP)
    def keep(ctx):  # type: ignore[no-untyped-def]
        ctx.p.motion = -1

    _, result = post(HEAD + "TRANS/1,2,3\nGOTO/1,0,0\nFINI\n", macros)
    assert not any("LCS" in w for w in warnings(result))


# -- 3. a motion macro's helical component (§5.7 $P19) ----------------------------------------

HELIX = HEAD + "GOTO/20,0,0\nCIRCLE/0,0,0,0,0,1,20\nGOTO/0,20,-5\nGOTO/0,30,-5\nFINI\n"


def _helix_macros(value: float | None, seen: list[float]) -> Macros:
    macros = Macros()

    @macros.event(Kind.MOTION, Phase.STARTUP)
    def flatten(ctx):  # type: ignore[no-untyped-def]
        if ctx.p.subclass == 1:
            seen.append(ctx.p.helical)
            if value is not None:
                ctx.p.helical = value

    return macros


def test_a_helix_made_flat_by_the_motion_macro_then_goes_straight_down() -> None:
    seen: list[float] = []
    plain, _ = post(HELIX, None)
    assert "G03 X0. Y20. Z-5. I-20." in plain  # the helix, one block (option 261)
    tape, _ = post(HELIX, _helix_macros(0.0, seen))
    assert seen == [-5.0]  # the arc's travel along Z, machine units
    lines = tape.splitlines()
    arc = next(i for i, line in enumerate(lines) if "G03" in line)
    assert lines[arc].endswith("G03 X0. Y20. I-20.")  # in the plane of its start
    assert lines[arc + 1].endswith("G01 Z-5.")  # then straight on to the programmed end
    assert lines[arc + 2].endswith("Y30.")


def test_a_changed_helical_component_stops_part_way_and_an_unchanged_one_is_the_helix() -> None:
    tape, _ = post(HELIX, _helix_macros(-2.0, []))
    assert "G03 X0. Y20. Z-2. I-20." in tape and "G01 Z-5." in tape
    same, _ = post(HELIX, _helix_macros(-5.0, []))
    assert same == post(HELIX, None)[0]


def test_a_planar_arcs_helical_component_is_zero() -> None:
    seen: list[float] = []
    post(
        HEAD + "GOTO/20,0,0\nCIRCLE/0,0,0,0,0,1,20\nGOTO/0,20,0\nFINI\n", _helix_macros(None, seen)
    )
    assert seen == [0.0]


# -- 4. a cycle macro's output switches and its feed alone (§5.6) -----------------------------

HOLES = (
    HEAD + "CYCLE/DRILL,DEPTH,5,CLEAR,2,MMPM,50\nGOTO/10,0,0\nGOTO/20,0,0\nGOTO/30,0,0\n"
    "CYCLE/OFF\nFINI\n"
)


def _cycle_tape(startup) -> list[str]:  # type: ignore[no-untyped-def]
    macros = Macros()
    macros.event(Kind.CYCLE, Phase.STARTUP, name="holes")(startup)
    tape, _ = post(HOLES, macros)
    return [line for line in tape.splitlines() if line.startswith("N")]


def test_cycle_switches_set_true_force_modal_words_out() -> None:
    def force(ctx):  # type: ignore[no-untyped-def]
        if ctx.p.cl[0] == 20:  # $P8, $P10, $P12, $P14 $TRUE: out although unchanged
            ctx.p.feed_out = ctx.p.clearance_out = ctx.p.depth_out = ctx.p.retract_out = True

    assert _cycle_tape(force) == [
        "N1 G99", "N2 G81 X10. Y0. Z-5. F50. R2.",
        "N3 G99", "N4 G81 X20. Y0. Z-5. F50. R2.",  # (G81 again: G99 was the last G)
        "N5 X30. Y0.", "N6 G80", "N7 M02",
    ]  # fmt: skip


def test_cycle_switches_set_false_leave_words_out_and_the_next_hole_states_them() -> None:
    def inhibit(ctx):  # type: ignore[no-untyped-def]
        if ctx.p.cl[0] == 10:
            ctx.p.feed_out = ctx.p.depth_out = False  # the control keeps the F and Z it had

    assert _cycle_tape(inhibit) == [
        "N1 G99", "N2 G81 X10. Y0. R2.", "N3 X20. Y0. Z-5. F50. R2.", "N4 X30. Y0.",
        "N5 G80", "N6 M02",
    ]  # fmt: skip


def test_p5_true_restates_the_cycle_and_false_at_its_activation_is_refused() -> None:
    def restate(ctx):  # type: ignore[no-untyped-def]
        if ctx.p.cl[0] == 20:
            assert ctx.p.activating is False  # the cycle is active since the first hole
            ctx.p.activating = True

    assert _cycle_tape(restate)[2] == "N3 G81 X20. Y0. Z-5. F50. R2."

    def deactivate(ctx):  # type: ignore[no-untyped-def]
        ctx.p.activating = False

    with pytest.raises(InputError, match=r"macro .*holes.*\$P5 \(activating\) cannot be"):
        _cycle_tape(deactivate)


def test_a_back_bore_switch_is_refused_gecent_has_no_back_bore() -> None:
    def back(ctx):  # type: ignore[no-untyped-def]
        ctx.p.back_out = True

    with pytest.raises(InputError, match="no BORE-BACK"):
        _cycle_tape(back)


def test_x23_the_feed_alone_in_a_block_of_its_own_then_the_cycle() -> None:
    """X23: $P1 = -2 and OUTPUT put the cycle's feed in a block of its own; $P1 = 1 and
    OUTPUT then output the cycle, which does not repeat it. F is modal: a later hole at
    the same feed has no feed block."""
    ends: list[float] = []

    def feed_first(ctx):  # type: ignore[no-untyped-def]
        ctx.p.control = -2
        ctx.output()
        ctx.p.control = 1
        ctx.output()

    macros = Macros()
    macros.event(Kind.CYCLE, Phase.STARTUP)(feed_first)
    macros.event(Kind.CYCLE, Phase.SHUTDOWN)(lambda ctx: ends.append(ctx.p.cl[0]))
    tape, _ = post(HOLES, macros)
    assert [line for line in tape.splitlines() if line.startswith("N")] == [
        "N1 F50.", "N2 G99", "N3 G81 X10. Y0. Z-5. R2.", "N4 X20. Y0.", "N5 X30. Y0.",
        "N6 G80", "N7 M02",
    ]  # fmt: skip
    assert ends == [10.0, 20.0, 30.0]  # each hole was a cycle block: the shutdown runs


def test_p1_minus_2_at_the_exit_is_the_feed_alone_and_no_hole() -> None:
    def feed_only(ctx):  # type: ignore[no-untyped-def]
        ctx.p.control = -2

    assert _cycle_tape(feed_only) == ["N1 F50.", "N2 M02"]


# -- 5. a diagnostic macro's number and severity (§5.12) --------------------------------------

ENDED = HEAD + "PENUP\nEND\nGOTO/1,0,0\nFINI\n"  # PENUP: unnumbered; a move after END: 47


def _diagnostic_post(change) -> tuple[list[tuple[object, str]], object]:  # type: ignore[no-untyped-def]
    seen: list[tuple[object, str]] = []
    macros = Macros()

    def body(ctx):  # type: ignore[no-untyped-def]
        seen.append((ctx.p.number, ctx.p.message))
        change(ctx)

    macros.event(Kind.DIAGNOSTIC, Phase.EVENT, name="diagnostics")(body)
    _, result = post(ENDED, macros)
    return seen, result


def _comments(result) -> list[str]:  # type: ignore[no-untyped-def]
    return [b.text for b in result.blocks if b.code is Code.COMMENT]


def test_the_manuals_numbered_comments_have_their_number_in_p2() -> None:
    seen, result = _diagnostic_post(lambda ctx: None)
    assert seen == [
        (None, "PENUP IS NOT A GECENT III POSTPROCESSOR WORD; STATEMENT DISREGARDED"),
        (47.0, "END OR RESET HAS NOT BEEN FOLLOWED BY A FROM POINT."),
    ]
    assert result.warnings == 2


def test_a_changed_number_puts_out_that_comment_instead() -> None:
    def renumber(ctx):  # type: ignore[no-untyped-def]
        if ctx.p.number == 47:
            ctx.p.number = 22

    _, result = _diagnostic_post(renumber)
    assert warnings(result)[1] == WARNING_COMMENTS[22]
    _, result = _diagnostic_post(lambda ctx: setattr(ctx.p, "number", 40) or
                                 setattr(ctx.p, "message", "MINE"))  # fmt: skip
    assert warnings(result) == ["MINE", "MINE"]  # $P5 written too: the macro's text


def test_a_number_outside_the_catalogue_is_the_macros_error() -> None:
    with pytest.raises(InputError, match=r"macro .*diagnostics.*\$P2 \(number\) 5 is none"):
        _diagnostic_post(lambda ctx: setattr(ctx.p, "number", 5))


def test_severity_0_lists_a_message_uncounted_and_2_stops_the_run() -> None:
    _, result = _diagnostic_post(lambda ctx: setattr(ctx.p, "severity", 0))
    assert result.warnings == 0 and warnings(result) == []
    assert WARNING_COMMENTS[47] in _comments(result)  # still in the listing
    with pytest.raises(RunStopped, match="PENUP IS NOT A GECENT III POSTPROCESSOR WORD"):
        _diagnostic_post(lambda ctx: setattr(ctx.p, "severity", 2))
    with pytest.raises(InputError, match=r"\$P3 \(severity\) takes 0 a message"):
        _diagnostic_post(lambda ctx: setattr(ctx.p, "severity", 7))


def test_the_comment_catalogue_agrees_with_the_texts_the_post_prints() -> None:
    from gecent.core.motion.positioning import NEGATIVE_Z
    from gecent.core.output.element import NOT_AVAILABLE
    from gecent.core.run import AFTER_END
    from gecent.core.spindle_types import LOWEST_OUTPUT, NOT_FOUND
    from gecent.core.statements.handling import WRONG_POCKET
    from gecent.core.tool import LENGTH_ZERO

    assert WARNING_COMMENTS == {19: LENGTH_ZERO, 22: NOT_AVAILABLE, 40: WRONG_POCKET,
                                47: AFTER_END, 63: NOT_FOUND, 66: NEGATIVE_Z,
                                80: LOWEST_OUTPUT}  # fmt: skip


# -- 6. the operation-event macro's redundancy guard (§5.9 $P3, $P4) ----------------------------

OP_HEAD = "PARTNO T\nUNITS/MM\nFROM/0,0,50\nLOADTL/1\n"
# the operation: its spindle and coolant before the first cut, and again after it
OPERATION = (
    "OPTYPE/MILL\nSPINDL/1000\nCOOLNT/ON\nRAPID\nGOTO/10,0,5\nFEDRAT/200\nGOTO/10,0,-2\n"
    "SPINDL/1000\nGOTO/20,0,-2\nFINI\n"
)


def _oe_tape(change) -> list[str]:  # type: ignore[no-untyped-def]
    """The operation with an OE macro that outputs the spindle and coolant itself."""
    macros = Macros()

    @macros.event(Kind.OPERATION_EVENT, name="operation")
    def operation(ctx):  # type: ignore[no-untyped-def]
        ctx.cmd("SPINDL/1000")
        ctx.cmd("COOLNT/ON")
        change(ctx)

    tape, _ = post(OP_HEAD + OPERATION, macros)
    return [line for line in tape.splitlines() if line.startswith("N")]


def test_the_guard_keeps_what_the_oe_macro_output_from_going_out_twice() -> None:
    lines = _oe_tape(lambda ctx: None)
    # the OE macro's S and M08 once; the program's same SPINDL and COOLNT up to the first
    # cut are redundant; the SPINDL after the cut goes out although redundant
    assert sum("M08" in line for line in lines) == 1
    assert sum("S1000 M03" in line for line in lines[:3]) == 1
    assert any("S1000" in line for line in lines[lines.index(next(
        line for line in lines if "Z-2." in line)) + 1:])  # fmt: skip


def test_p4_0_disables_the_guard_and_a_large_p4_carries_it_into_the_cut() -> None:
    def off(ctx):  # type: ignore[no-untyped-def]
        ctx.p.cut_record = 0

    assert sum("M08" in line for line in _oe_tape(off)) == 2  # output twice: no guard

    def longer(ctx):  # type: ignore[no-untyped-def]
        ctx.p.cut_record = 1000

    plain = _oe_tape(lambda ctx: None)
    guarded = _oe_tape(longer)
    assert len(guarded) == len(plain) - 1  # the SPINDL after the cut is redundant too


def test_p3_moves_the_guards_start() -> None:
    def late(ctx):  # type: ignore[no-untyped-def]
        ctx.p.first_record = ctx.p.first_record + 2  # past the SPINDL: it goes out again

    lines = _oe_tape(late)
    assert sum("M08" in line for line in lines) == 1
    assert sum("S1000" in line for line in lines[:4]) == 2


def test_guard_values_that_are_no_record_numbers_are_the_macros_error() -> None:
    with pytest.raises(InputError, match=r"\$P3 and \$P4 are CL record numbers"):
        _oe_tape(lambda ctx: setattr(ctx.p, "cut_record", "END"))
