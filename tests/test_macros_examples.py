"""The worked examples X1-X23 of spec 09 §11, written as Python macros.

Tested elsewhere, with the example's own inputs:

* X2, X3: tests/test_macros_lookahead.py (forced results at FINI; the next motion);
* X5-X8: tests/test_macros_operations.py ($LOOK, nested $FLOOK, cutting time, tape break);
* X11: tests/test_macros_events.py (the register filter $REGMATCH);
* X12-X16, X22: tests/test_macros_syntax.py (the SDL and its matching; ignore/translate);
* X19: tests/test_macros_operations.py (the operation table).

Here: X1, X4, X9, X10, X17, X18, X20, X21 and X23.
"""

from __future__ import annotations

import math

import pytest
from gecent.core.macros import Kind, Macros, Phase

from .macros_helpers import post

HEAD = "PARTNO T\nUNITS/MM\nFROM/0,0,10\nFEDRAT/100\n"


def test_x1_side_effects_guarded_against_look_ahead() -> None:
    """X1: a write outside the post happens once per event, not once more per look-ahead
    that passes the event."""
    log: list[str] = []
    unguarded: list[str] = []
    macros = Macros()

    @macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
    def write_time(ctx):  # type: ignore[no-untyped-def]
        unguarded.append("x")
        if not ctx.la.active:
            log.append(f"T{ctx.p.tool_id:g} at {ctx.sv.FEDTIM:.4f}")

    @macros.event(Kind.MOTION, Phase.STARTUP)
    def looks(ctx):  # type: ignore[no-untyped-def]
        _ = ctx.next.motion  # a motion look-ahead runs every macro type (§7.4)

    post(HEAD + "LOADTL/1\nGOTO/1,0,0\nLOADTL/2\nGOTO/2,0,0\nFINI\n", macros)
    assert len(log) == 2 and len(unguarded) > 2


def test_x4_flook_keeps_future_values() -> None:
    """X4: $FLOOK(3, myarr(1),THRU,myarr(12)): the kept variables come back with the
    values they had when the look-ahead ended."""
    kept: list[object] = []
    macros = Macros()

    @macros.event(Kind.MACHINE, Phase.STARTUP)
    def start(ctx):  # type: ignore[no-untyped-def]
        ctx.globals["myarr"] = [0.0] * 12
        ctx.flook(3, keep=("myarr",))
        kept.append(list(ctx.globals["myarr"]))

    @macros.event(Kind.MOTION, Phase.SHUTDOWN)
    def record_x(ctx):  # type: ignore[no-untyped-def]
        if ctx.look.active(3):
            ctx.globals["myarr"][int(ctx.p.cl[0])] = ctx.p.cl[1]

    @macros.event(Kind.MACHINE, Phase.SHUTDOWN)
    def end(ctx):  # type: ignore[no-untyped-def]
        ctx.look[3] = 1

    post(HEAD + "GOTO/1,5,0\nGOTO/2,7,0\nFINI\n", macros)
    assert kept == [[0.0, 5.0, 7.0] + [0.0] * 9]


def test_x9_oe_macro_outputs_spindle_and_coolant_early() -> None:
    """X9: the OE macro fetches the operation's SPINDL and COOLNT ($FGET between its $P3
    and $P4) and outputs them now (TAPEWT); reached later, they are not output again."""
    macros = Macros()

    @macros.event(Kind.OPERATION_EVENT)
    def early(ctx):  # type: ignore[no-untyped-def]
        found = ctx.fget(("SPINDL", "COOLNT"), ctx.p[3], ctx.p[4])
        while found > 0:
            ctx.tapewt(found)
            found = ctx.fget(("SPINDL", "COOLNT"), found + 1, ctx.p[4])

    program = HEAD + (
        "OPTYPE/MILL\nRAPID\nGOTO/10,0,5\nCOOLNT/FLOOD\nSPINDL/1000\nGOTO/10,0,-2\n"
        "GOTO/20,0,-2\nFINI\n"
    )
    tape, _ = post(program, macros)
    plain, _ = post(program, None)
    lines = tape.splitlines()
    rapid = next(i for i, line in enumerate(lines) if "G00" in line)
    assert any("S1000" in line for line in lines[:rapid])  # before the first move
    assert any("M08" in line for line in lines[:rapid])
    assert sum("S1000" in line for line in lines) == 1 and sum("M08" in line for line in lines) == 1
    assert plain != tape and sum("S1000" in line for line in plain.splitlines()) == 1


def test_x9_tapewt_of_a_record_not_ahead_is_named() -> None:
    macros = Macros()

    @macros.syntax("STOP")
    def back(ctx):  # type: ignore[no-untyped-def]
        ctx.tapewt(1)

    with pytest.raises(Exception, match="TAPEWT: record 1 is not ahead"):
        post(HEAD + "STOP\nFINI\n", macros)


def test_x10_register_output_as_the_sine() -> None:
    """X10: $P2 = $FSWRIT($FREGFMT($P3), $FSIN($P4)): the X word as the sine of its
    value, in the register's own format."""
    macros = Macros()

    @macros.event(Kind.MACHINE, Phase.STARTUP)
    def start(ctx):  # type: ignore[no-untyped-def]
        ctx.sv.REGMATCH = ["X"]

    @macros.event(Kind.REGISTER)
    def sine(ctx):  # type: ignore[no-untyped-def]
        ctx.p.text = ctx.format_register(ctx.p.index, math.sin(math.radians(ctx.p.value)))

    tape, _ = post(HEAD + "GOTO/30,0,0\nGOTO/90,0,0\nFINI\n", macros)
    assert "N1 G01 X0.5 Y0. Z0. F100.\n" in tape and "N2 X1.\n" in tape


def test_x17_the_b_axis_is_not_in_axes_on_a_three_axis_mill() -> None:
    """X17: $FINDEX($AXES,'b') is 0 when the B axis is not active."""
    found: list[int] = []
    macros = Macros()

    @macros.event(Kind.MOTION, Phase.STARTUP)
    def axis(ctx):  # type: ignore[no-untyped-def]
        found.append(ctx.sv.AXES.lower().find("b") + 1)  # $FINDEX is 1-based, 0 = absent

    post(HEAD + "GOTO/1,0,0\nFINI\n", macros)
    assert set(found) == {0}


def test_x18_an_element_of_a_p_sequence() -> None:
    """X18: $P2(3) is the CL Z of the motion (Python tuples count from 0: p[2][2])."""
    zs: list[float] = []
    macros = Macros()

    @macros.event(Kind.MOTION, Phase.STARTUP)
    def z(ctx):  # type: ignore[no-untyped-def]
        zs.append(ctx.p[2][2])

    post(HEAD + "GOTO/1,2,-3\nFINI\n", macros)
    assert zs == [10.0, -3.0]


def test_x20_tlmode_after_a_motion_code_inserted_by_hand() -> None:
    """X20: after INSERTing G00 by hand, $TLMODE = 0 tells the post, so the next feed
    move states its G01 again."""
    for told in (False, True):
        macros = Macros()

        @macros.syntax("STOP")
        def rapid_by_hand(ctx, told: bool = told) -> None:  # type: ignore[no-untyped-def]
            ctx.insert("G00 Z20")
            if told:
                ctx.sv.TLMODE = 0

        tape, _ = post(HEAD + "GOTO/1,0,0\nSTOP\nGOTO/2,0,0\nFINI\n", macros)
        assert ("N2 G01 X2.\n" in tape) is told and ("N2 X2.\n" in tape) is not told


def test_x21_axes_of_a_three_axis_mill() -> None:
    seen: list[str] = []
    macros = Macros()

    @macros.event(Kind.MACHINE, Phase.STARTUP)
    def start(ctx):  # type: ignore[no-untyped-def]
        seen.append(ctx.sv.AXES)

    post(HEAD + "FINI\n", macros)
    assert seen == ["XYZ***"]


def test_x23_feed_alone_before_a_cycle() -> None:
    """X23: $P1 = -2 then OUTPUT put the cycle's feed in a block of its own; $P1 = 1 and
    OUTPUT then output the cycle (tests/test_macros_wave9.py has more)."""
    macros = Macros()

    @macros.event(Kind.CYCLE, Phase.STARTUP)
    def feed_first(ctx):  # type: ignore[no-untyped-def]
        ctx.p.control = -2
        ctx.output()
        ctx.p.control = 1
        ctx.output()

    program = HEAD + "CYCLE/DRILL,DEPTH,5,CLEAR,2,MMPM,50\nGOTO/10,0,0\nCYCLE/OFF\nFINI\n"
    tape, _ = post(program, macros)
    assert "N1 F50.\nN2 G99\nN3 G81 X10. Y0. Z-5. R2.\n" in tape
