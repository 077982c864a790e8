"""Event macros (spec 09 §4-§5): one test at least per kind, the $P each gets, the effects
of changed values, the enable switches and the no-re-entry rule."""

from __future__ import annotations

import pytest
from gecent.core.macros import Kind, Macros, Phase

from .macros_helpers import post, warnings

HEAD = "PARTNO T\nUNITS/MM\nFROM/0,0,10\nFEDRAT/100\n"
TWO_TOOLS = HEAD + "LOADTL/1\nGOTO/1,0,0\nLOADTL/2\nGOTO/2,0,0\nFINI\n"


def test_declaration_then_machine_startup_then_shutdown() -> None:
    log: list[str] = []
    macros = Macros()

    @macros.event(Kind.DECLARATION)
    def declare(ctx):  # type: ignore[no-untyped-def]
        ctx.globals["parts"] = 0
        log.append("declaration")

    @macros.event(Kind.MACHINE, Phase.STARTUP)
    def start(ctx):  # type: ignore[no-untyped-def]
        ctx.locals["mine"] = True
        log.append("startup")
        ctx.insert("(MACHINE STARTUP)")

    @macros.event(Kind.MACHINE, Phase.SHUTDOWN)
    def stop(ctx):  # type: ignore[no-untyped-def]
        log.append(f"shutdown locals={dict(ctx.locals)} parts={ctx.globals['parts']}")
        ctx.cmd("COOLNT/OFF")

    tape, _ = post(HEAD + "GOTO/1,0,0\nFINI\n", macros)
    # machine startup and shutdown share no locals (§4.2)
    assert log == ["declaration", "startup", "shutdown locals={} parts=0"]
    lines = tape.splitlines()
    assert lines[:3] == ["%", "(MACHINESTARTUP)", "(T)"]  # at the start, before PARTNO
    assert lines[-3:] == ["N2 M09", "N3 M02", "%"]  # shutdown before the end of program


def test_machine_shutdown_runs_at_the_end_of_a_file_without_fini() -> None:
    macros = Macros()

    @macros.event(Kind.MACHINE, Phase.SHUTDOWN)
    def stop(ctx):  # type: ignore[no-untyped-def]
        ctx.insert("(BYE)")

    tape, result = post(HEAD + "GOTO/1,0,0\n", macros)
    assert "(BYE)" in tape and any("NO FINI" in w for w in warnings(result))


def test_a_declaration_macro_issues_no_commands() -> None:
    macros = Macros()

    @macros.event(Kind.DECLARATION)
    def declare(ctx):  # type: ignore[no-untyped-def]
        ctx.cmd("COOLNT/ON")

    with pytest.raises(Exception, match="the declaration macro issues no commands"):
        post(HEAD + "FINI\n", macros)


def test_first_tool_change_replaces_the_tool_change_pair_once() -> None:
    log: list[str] = []
    macros = Macros()
    for kind in (Kind.FIRST_TOOL_CHANGE, Kind.TOOL_CHANGE):
        for phase in (Phase.STARTUP, Phase.SHUTDOWN):

            def body(ctx, kind: Kind = kind, phase: Phase = phase) -> None:  # type: ignore[no-untyped-def]
                log.append(f"{kind.value} {phase.value} T{ctx.p.tool_id:g} FT={ctx.sv.FT}")

            macros.event(kind, phase, name=f"{kind.value}-{phase.value}")(body)
    post(TWO_TOOLS, macros)
    assert log == [
        "first-tool-change startup T1 FT=0",
        "first-tool-change shutdown T1 FT=1",  # just after the tool is loaded
        "tool-change startup T2 FT=1",
        "tool-change shutdown T2 FT=1",
    ]


def test_ft_zero_rearms_the_first_tool_change_macros() -> None:
    log: list[str] = []
    macros = Macros()

    @macros.event(Kind.FIRST_TOOL_CHANGE, Phase.STARTUP)
    def first(ctx):  # type: ignore[no-untyped-def]
        log.append(f"first T{ctx.p.tool_id:g}")

    @macros.event(Kind.TOOL_CHANGE, Phase.SHUTDOWN)
    def after(ctx):  # type: ignore[no-untyped-def]
        log.append(f"after T{ctx.p.tool_id:g}")
        ctx.sv.FT = 0

    post(HEAD + "LOADTL/1\nLOADTL/2\nLOADTL/3\nFINI\n", macros)
    assert log == ["first T1", "after T2", "first T3"]


def test_tool_change_startup_and_shutdown_wrap_the_tool_change() -> None:
    macros = Macros()

    @macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        ctx.locals["from"] = ctx.sv.T
        ctx.cmd("SPINDL/OFF")
        ctx.cmd("COOLNT/OFF")
        ctx.insert("G53 G00 Z0")

    @macros.event(Kind.TOOL_CHANGE, Phase.SHUTDOWN)
    def after(ctx):  # type: ignore[no-untyped-def]
        ctx.pprint(f"TOOL {ctx.locals['from']} OUT, TOOL {ctx.sv.T:g} IN")

    tape, _ = post(HEAD + "SPINDL/1000\nLOADTL/4\nGOTO/1,0,0\nFINI\n", macros)
    body = tape.splitlines()[3:]
    # COOLNT/OFF's M09 waits for the next block, as the post does it (STOREM)
    assert body[:4] == ["N1 S1000 M03", "N2 M05", "G53G00Z0", "N3 M09"]
    assert body[4].startswith("N4 T04 M06")
    assert "(TOOL None OUT, TOOL 4 IN)" in tape


def test_a_tool_change_macro_can_change_the_tool() -> None:
    macros = Macros()

    @macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
    def renumber(ctx):  # type: ignore[no-untyped-def]
        ctx.p.tool_id = ctx.p.tool_id + 10

    tape, _ = post(HEAD + "LOADTL/5\nGOTO/1,0,0\nFINI\n", macros)
    assert "T15 M06" in tape and "T5 " not in tape


def test_tool_change_params() -> None:
    seen = {}
    macros = Macros(machine="haas-mill")

    @macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
    def look(ctx):  # type: ignore[no-untyped-def]
        seen.update({n: ctx.p[n] for n in (1, 2, 3, 4, 5, 6, 9, 20)})

    post(HEAD + "LOADTL/7,OFSETL,17,LENGTH,120,CCLW\nGOTO/1,0,0\nFINI\n", macros, "haas-mill")
    assert seen == {1: 7.0, 2: 1.0, 3: 2.0, 4: 2.0, 5: 17.0, 6: 120.0, 9: 7.0, 20: None}


def test_motion_startup_can_suppress_a_motion_and_its_shutdown() -> None:
    log: list[str] = []
    macros = Macros()

    @macros.event(Kind.MOTION, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        log.append(f"start {ctx.p.subclass:g} {ctx.p.cl[:3]} {ctx.p.machine[:3]}")
        if ctx.p.cl[0] == 2:
            ctx.p.subclass = 0

    @macros.event(Kind.MOTION, Phase.SHUTDOWN)
    def after(ctx):  # type: ignore[no-untyped-def]
        log.append("end")

    tape, _ = post(HEAD + "TRANS/0,0,5\nGOTO/1,0,0\nGOTO/2,0,0\nGOTO/3,0,0\nFINI\n", macros)
    assert log == [
        "start 3 (0.0, 0.0, 10.0) (0.0, 0.0, 10.0)",
        "end",
        "start 5 (1.0, 0.0, 0.0) (1.0, 0.0, 5.0)",
        "end",
        "start 5 (2.0, 0.0, 0.0) (2.0, 0.0, 5.0)",
        "start 5 (3.0, 0.0, 0.0) (3.0, 0.0, 5.0)",
        "end",
    ]
    assert "X2." not in tape and "X3." in tape


def test_a_goto_inside_a_motion_macro_starts_no_motion_macro() -> None:
    count = []
    macros = Macros()

    @macros.event(Kind.MOTION, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        count.append(1)
        if ctx.p.subclass == 5:
            x, y, _ = ctx.p.cl[:3]
            ctx.goto(x, y, 20)  # a safe approach first: no new motion macro (§4.2 rule 3)

    tape, _ = post(HEAD + "GOTO/1,0,0\nFINI\n", macros)
    assert len(count) == 2  # the FROM and the GOTO, not the approach
    assert "X1. Y0. Z20." in tape and "Z0." in tape


def test_an_arc_is_subclass_1_and_can_become_a_line() -> None:
    arcs: list[tuple[float, ...]] = []
    macros = Macros()

    @macros.event(Kind.MOTION, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        if ctx.p.subclass == 1:
            arcs.append((ctx.p.direction, ctx.p.plane, ctx.p.radius, *ctx.p.cl_centre))
            ctx.p.subclass = 5

    program = HEAD + "GOTO/10,0,0\nCIRCLE/0,0,0,0,0,1,10\nGOTO/0,10,0\nFINI\n"
    plain, _ = post(program, None)
    tape, _ = post(program, macros)
    assert "G03" in plain and "G03" not in tape
    assert arcs == [(2.0, 1.0, 10.0, 0.0, 0.0, 0.0)]
    assert "G01 X0. Y10." in tape or "X0. Y10." in tape


def test_lcs_macros_around_trans() -> None:
    seen: list[object] = []
    macros = Macros()

    @macros.event(Kind.LCS, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        seen.append((ctx.p.action, ctx.p.translation, ctx.sv.XM))
        ctx.output()  # LCS processing here
        seen.append(ctx.state.position.translation)

    @macros.event(Kind.LCS, Phase.SHUTDOWN)
    def after(ctx):  # type: ignore[no-untyped-def]
        seen.append("shutdown")

    post(HEAD + "TRANS/1,2,3\nGOTO/1,0,0\nFINI\n", macros)
    assert seen == [(10.0, (1.0, 2.0, 3.0), 0.0), (1.0, 2.0, 3.0), "shutdown"]


def test_lcs_macros_cannot_look_ahead_or_change_read_only_p() -> None:
    macros = Macros()

    @macros.event(Kind.LCS, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        ctx.p.translation = (0, 0, 0)

    with pytest.raises(Exception, match=r"\$P9 \(translation\) of the LCS macro is read-only"):
        post(HEAD + "TRANS/1,2,3\nFINI\n", macros)
    macros = Macros()

    @macros.event(Kind.LCS, Phase.SHUTDOWN)
    def after(ctx):  # type: ignore[no-untyped-def]
        return ctx.next.tool

    with pytest.raises(Exception, match="the lcs shutdown macro cannot look ahead"):
        post(HEAD + "TRANS/1,2,3\nFINI\n", macros)


def test_break_shutdown_comes_before_break_startup() -> None:
    log: list[str] = []
    macros = Macros(machine="mach23")

    @macros.event(Kind.BREAK, Phase.STARTUP)
    def start(ctx):  # type: ignore[no-untyped-def]
        log.append("startup")

    @macros.event(Kind.BREAK, Phase.SHUTDOWN)
    def stop(ctx):  # type: ignore[no-untyped-def]
        log.append("shutdown")

    post("PARTNO T\nFROM/0,0,0\nBREAK\nFINI\n", macros, "mach23")
    assert log == ["shutdown", "startup"]


CYCLE = HEAD + "CYCLE/DRILL,DEPTH,5,CLEAR,2,MMPM,50\nGOTO/10,0,0\nGOTO/20,0,0\nCYCLE/OFF\nFINI\n"


def test_cycle_macros_see_the_hole_and_can_move_its_levels() -> None:
    seen: list[tuple[object, ...]] = []
    macros = Macros()

    @macros.event(Kind.CYCLE, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        p = ctx.p
        seen.append((p.control, p.cl, p.cycle_type, p.activating, p.clearance, p.depth, p.axis))
        if p.cl[0] == 20:
            p.depth = -8.0

    tape, _ = post(CYCLE, macros)
    assert seen == [
        (1.0, (10.0, 0.0, 0.0), 1.0, True, 2.0, -5.0, 3.0),
        (1.0, (20.0, 0.0, 0.0), 1.0, False, 2.0, -5.0, 3.0),
    ]
    assert "N2 G81 X10. Y0. Z-5. F50. R2.\nN3 X20. Y0. Z-8. R2.\n" in tape


def test_cycle_p1_zero_skips_the_hole_and_minus_one_makes_it_by_moves() -> None:
    ends: list[float] = []
    macros = Macros()

    @macros.event(Kind.CYCLE, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        ctx.p.control = 0.0 if ctx.p.cl[0] == 10 else -1.0

    @macros.event(Kind.CYCLE, Phase.SHUTDOWN)
    def after(ctx):  # type: ignore[no-untyped-def]
        ends.append(ctx.p.cl[0])

    tape, _ = post(CYCLE, macros)
    assert "X10." not in tape and "G81" not in tape
    assert "X20." in tape and "Z-5." in tape  # drilled by G00/G01 moves
    assert ends == []  # no shutdown after a skipped or emulated hole (§5.6)


def test_cycle_output_in_startup_puts_commands_after_the_block() -> None:
    macros = Macros()

    @macros.event(Kind.CYCLE, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        ctx.insert("(BEFORE)")
        ctx.output()
        ctx.insert("(AFTER)")

    tape, _ = post(CYCLE, macros)
    lines = tape.splitlines()
    drill = next(i for i, line in enumerate(lines) if "G81" in line)
    assert lines[drill - 2 : drill] == ["(BEFORE)", "N1 G99"] and lines[drill + 1] == "(AFTER)"
    assert sum("X10." in line for line in lines) == 1  # OUTPUT did it; not again at the exit


def test_a_cycle_output_switch_set_false_leaves_its_word_out() -> None:
    """(tests/test_macros_wave9.py has the switches in full.)"""
    macros = Macros()

    @macros.event(Kind.CYCLE, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        ctx.p.feed_out = False

    tape, _ = post(CYCLE, macros)
    assert "G81" in tape and "F50." not in tape


def test_register_macro_changes_and_drops_registers() -> None:
    macros = Macros()

    @macros.event(Kind.REGISTER)
    def registers(ctx):  # type: ignore[no-untyped-def]
        ctx.sv.REGMATCH = ["[YF]"]  # X11: a regular expression from the first character
        if ctx.p.text.startswith("F"):
            ctx.p.flag = 0  # no F word at all
        elif ctx.p.text.startswith("Y"):
            ctx.p.text = f"Y{-ctx.p.value:.3f}"  # a mirrored Y

    tape, _ = post(HEAD + "GOTO/1,2,0\nGOTO/3,4,0\nFINI\n", macros)
    assert "N1 G01 X1. Y-2.000 Z0.\n" in tape and "N2 X3. Y-4.000\n" in tape


def test_register_macro_output_adds_registers() -> None:
    macros = Macros()

    @macros.event(Kind.MACHINE, Phase.STARTUP)
    def start(ctx):  # type: ignore[no-untyped-def]
        ctx.sv.REGMATCH = [11]  # the feed's register index

    @macros.event(Kind.REGISTER)
    def registers(ctx):  # type: ignore[no-untyped-def]
        ctx.output()
        ctx.p.text = "(FEED)"
        ctx.p.index = 99  # appended

    tape, _ = post(HEAD + "GOTO/1,2,0\nFINI\n", macros)
    assert "N1 G01 X1. Y2. Z0. F100. (FEED)\n" in tape


def test_tape_macro_edits_deletes_and_adds_blocks() -> None:
    macros = Macros()

    @macros.event(Kind.TAPE)
    def tape_block(ctx):  # type: ignore[no-untyped-def]
        if "M02" in ctx.p.block:
            ctx.p.block = "M30"
            return
        if ctx.p.rest.startswith("X2."):
            ctx.p.flag = 0
            return
        if ctx.p.sequence == "N1":
            ctx.p.block = "(FIRST MOVE)"
            ctx.output()  # written; $P3 is an empty block again
            ctx.p.block = "N1 G01 X1. Y0. Z0. F100."

    tape, _ = post(HEAD + "GOTO/1,0,0\nGOTO/2,0,0\nFINI\n", macros)
    assert tape.splitlines()[3:] == ["(FIRST MOVE)", "N1 G01 X1. Y0. Z0. F100.", "M30", "%"]


def test_tape_macro_restart_mode() -> None:
    macros = Macros()

    @macros.event(Kind.TAPE)
    def tape_block(ctx):  # type: ignore[no-untyped-def]
        if "n" not in ctx.locals:  # locals keep their values across restarts
            if ctx.p.sequence != "N1":
                return
            ctx.locals.update(n=0, block=ctx.p.block)
        ctx.locals["n"] += 1
        count = ctx.locals["n"]
        if count < 3:
            ctx.p.block = f"(PASS {count})"
            ctx.p.flag = 2  # out, and the macro begins again with an empty block
        else:
            ctx.p.block = ctx.locals["block"]
            ctx.p.flag = 1

    tape, _ = post(HEAD + "GOTO/1,0,0\nFINI\n", macros)
    assert tape.splitlines()[3:6] == ["(PASS 1)", "(PASS 2)", "N1 G01 X1. Y0. Z0. F100."]


def test_a_tape_macro_that_never_stops_restarting_is_stopped() -> None:
    macros = Macros()

    @macros.event(Kind.TAPE)
    def tape_block(ctx):  # type: ignore[no-untyped-def]
        ctx.p.flag = 2

    with pytest.raises(Exception, match=r"restarted 10000 times"):
        post(HEAD + "GOTO/1,0,0\nFINI\n", macros)


def test_tape_macro_issues_no_commands() -> None:
    macros = Macros()

    @macros.event(Kind.TAPE)
    def tape_block(ctx):  # type: ignore[no-untyped-def]
        ctx.cmd("STOP")

    with pytest.raises(Exception, match="the tape macro issues no commands"):
        post(HEAD + "GOTO/1,0,0\nFINI\n", macros)


def test_diagnostic_macro_drops_rewrites_and_counts() -> None:
    seen: list[tuple[object, ...]] = []
    macros = Macros()

    @macros.event(Kind.DIAGNOSTIC)
    def diagnostic(ctx):  # type: ignore[no-untyped-def]
        seen.append((ctx.p.occurrence, ctx.p.message[:5]))
        if ctx.p.message.startswith("PENUP"):
            ctx.p.message = "PEN WORDS ARE IGNORED HERE"
        elif ctx.p.message.startswith("PENDWN"):
            ctx.p.flag = 0

    _, result = post(HEAD + "PENUP\nPENUP\nPENDWN\nFINI\n", macros)
    assert seen == [(1, "PENUP"), (2, "PENUP"), (1, "PENDW")]
    assert warnings(result) == ["PEN WORDS ARE IGNORED HERE"] * 2
    assert result.warnings == 2  # a dropped diagnostic is not counted


def test_switches_turn_event_macros_off() -> None:
    log: list[str] = []
    macros = Macros()

    @macros.event(Kind.MACHINE, Phase.STARTUP)
    def start(ctx):  # type: ignore[no-untyped-def]
        ctx.sv.MTNMAC = False

    @macros.event(Kind.MOTION, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        log.append("motion")

    post(HEAD + "GOTO/1,0,0\nFINI\n", macros)
    assert log == []


def test_system_variables_are_checked_by_name() -> None:
    macros = Macros()

    @macros.event(Kind.MACHINE, Phase.STARTUP)
    def start(ctx):  # type: ignore[no-untyped-def]
        assert ctx.sv["$AXES"] == "XYZ***"  # X21
        ctx.sv.NOSUCH = 1

    with pytest.raises(Exception, match=r"\$NOSUCH is not a macro system variable"):
        post(HEAD + "FINI\n", macros)


def test_cycle_macros_on_a_positioning_machine_run_around_the_hole() -> None:
    # was NotYetSupported; wave 9 builds them (tests/test_cycles_wave9.py)
    macros = Macros(machine="mach24")
    seen: list[float] = []

    @macros.event(Kind.CYCLE, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        seen.append(ctx.p.cl[0])

    program = (
        "PARTNO T\nFROM/0,0,1\nSPINDL/500\nFEDRAT/10\nCYCLE/DRILL,DEPTH,.5,CLEAR,.1,IPM,5\n"
        "GOTO/1,1,0\nCYCLE/OFF\nFINI\n"
    )
    tape, _ = post(program, macros, "mach24")
    assert seen == [1.0] and "G81" in tape
