"""What a review of the macro layer found, each a test: look-ahead state never leaks into
the run, a macro's errors are named, no accepted write is silently without effect, and the
motions a macro makes keep to §5.6-§5.8."""

from __future__ import annotations

import pytest
from gecent.core.errors import InputError, RunStopped
from gecent.core.macros import Kind, Macros, Phase
from gecent.core.macros.lookahead import snapshot
from gecent.core.plugins import get_plugins
from gecent.core.run import Run

from .macros_helpers import post, records, warnings

HEAD = "PARTNO T\nUNITS/MM\nFROM/0,0,10\nFEDRAT/100\n"
ARC = HEAD + "GOTO/10,0,0\nCIRCLE/0,0,0,0,0,1,10\nGOTO/0,10,0\nGOTO/5,5,0\nFINI\n"


def test_a_machin_read_in_a_look_ahead_leaves_the_runs_macfun_alone() -> None:
    macros = Macros(machine="mach40")

    @macros.event(Kind.TOOL_CHANGE, Phase.SHUTDOWN)
    def look(ctx):  # type: ignore[no-untyped-def]
        _ = ctx.next.tool

    program = (
        "PARTNO T\nFROM/-19,48,31.75\nFEDRAT/10\nLOADTL/1\nCYCLE/TAP,4,IPM,5.4\n"
        "GOTO/-18,48,31\nCYCLE/OFF,2\nMACHIN/GECENT,40,OPTAB,133,0\nLOADTL/2\nFINI\n"
    )
    tape, _ = post(program, macros, "mach40")
    assert "G52" in tape  # MACF40 still handled CYCLE/OFF,2 (it is off only from record 8)


def test_an_illegal_motion_subclass_is_the_macros_error() -> None:
    macros = Macros()

    @macros.event(Kind.MOTION, Phase.STARTUP)
    def spline(ctx):  # type: ignore[no-untyped-def]
        ctx.p.subclass = 9

    with pytest.raises(InputError, match=r"macro \*:spline: a motion's \$P1 cannot become"):
        post(HEAD + "GOTO/1,0,0\nFINI\n", macros)


def test_a_cycle_macros_own_move_is_no_hole() -> None:
    macros = Macros()

    @macros.event(Kind.CYCLE, Phase.SHUTDOWN)
    def clear(ctx):  # type: ignore[no-untyped-def]
        ctx.goto(ctx.p.cl[0], ctx.p.cl[1], 20)  # up and out of the way after each hole

    program = HEAD + (
        "CYCLE/DRILL,DEPTH,5,CLEAR,2,MMPM,50\nGOTO/10,0,0\nGOTO/20,0,0\nCYCLE/OFF\nFINI\n"
    )
    tape, _ = post(program, macros)
    lines = tape.splitlines()
    assert sum("G81" in line for line in lines) == 2  # the holes, each after a G80
    assert "Z20." in tape and not any("G81" in line and "Z15." in line for line in lines)
    up = next(i for i, line in enumerate(lines) if "Z20." in line)
    assert "G80" in lines[up - 1] or "G80" in lines[up]


@pytest.mark.parametrize("command", ["LOADTL/5", "GOTO/5,5,5", "CYCLE/DRILL,DEPTH,5", "FINI"])
def test_an_lcs_macro_may_not_issue_what_section_5_8_lists(command: str) -> None:
    macros = Macros()

    @macros.event(Kind.LCS, Phase.STARTUP)
    def lcs(ctx, command: str = command) -> None:  # type: ignore[no-untyped-def]
        ctx.cmd(command)

    with pytest.raises(InputError, match="an LCS macro may not issue"):
        post(HEAD + "TRANS/1,2,3\nFINI\n", macros)


def test_a_suppressed_arc_is_gone_and_the_next_move_is_plain() -> None:
    subclasses: list[float] = []
    macros = Macros()

    @macros.event(Kind.MOTION, Phase.STARTUP)
    def drop_arcs(ctx):  # type: ignore[no-untyped-def]
        subclasses.append(ctx.p.subclass)
        if ctx.p.subclass == 1:
            ctx.p.subclass = 0

    tape, result = post(ARC, macros)
    assert subclasses == [3.0, 5.0, 1.0, 5.0] and "G03" not in tape and "X5. Y5." in tape
    assert warnings(result) == []


def test_extra_motions_before_an_arc_make_it_linear_unless_the_position_is_back() -> None:
    for back in (False, True):
        macros = Macros()

        @macros.event(Kind.MOTION, Phase.STARTUP)
        def lift(ctx, back: bool = back) -> None:  # type: ignore[no-untyped-def]
            if ctx.p.subclass == 1:
                ctx.goto(10, 0, 5)  # an extra motion (§5.7)
                if back:
                    ctx.goto(10, 0, 0)  # ... and back where the arc starts

        tape, _ = post(ARC, macros)
        assert ("G03" in tape) is back


def test_writes_once_refused_now_have_their_effect() -> None:
    """LCS $P21, cycle $P5 and diagnostic $P3 (tests/test_macros_wave9.py has them all)."""
    outcomes: list[object] = []
    for kind, phase, field, program in (
        (Kind.LCS, Phase.STARTUP, "motion", HEAD + "TRANS/1,2,3\nFINI\n"),
        (Kind.CYCLE, Phase.STARTUP, "activating",
         HEAD + "CYCLE/DRILL,DEPTH,5,CLEAR,2,MMPM,50\nGOTO/10,0,0\nCYCLE/OFF\nFINI\n"),
        (Kind.DIAGNOSTIC, Phase.EVENT, "severity", HEAD + "PENUP\nFINI\n"),
    ):  # fmt: skip
        macros = Macros()

        def change(ctx, field: str = field) -> None:  # type: ignore[no-untyped-def]
            setattr(ctx.p, field, 2)

        macros.event(kind, phase, name="change")(change)
        try:
            tape, result = post(program, macros)
            outcomes.append((tape == post(program, None)[0], len(result.diagnostics)))
        except RunStopped as stopped:
            outcomes.append(stopped.message)
    # LCS: no motion to make, warned (the tape unchanged); cycle: $TRUE at its activation,
    # as GENER set it; diagnostic: severity 2 stops the run
    assert outcomes == [
        (True, 1),
        (True, 0),
        "PENUP IS NOT A GECENT III POSTPROCESSOR WORD; STATEMENT DISREGARDED",
    ]


def test_a_macro_error_met_only_in_a_look_ahead_is_reported() -> None:
    macros = Macros()

    @macros.event(Kind.TOOL_CHANGE, Phase.SHUTDOWN)
    def look(ctx):  # type: ignore[no-untyped-def]
        _ = ctx.next.tool

    @macros.event(Kind.MACHINE, Phase.SHUTDOWN)
    def at_fini(ctx):  # type: ignore[no-untyped-def]
        if ctx.la.tool:
            return undefined_name  # type: ignore[name-defined]  # noqa: F821

    with pytest.raises(InputError, match="macro \\*:at_fini failed: NameError"):
        post(HEAD + "LOADTL/1\nGOTO/1,0,0\nFINI\n", macros)


def test_the_next_incremental_move_counts_from_the_current_moves_end() -> None:
    found: list[tuple[float, ...]] = []
    macros = Macros()

    @macros.event(Kind.MOTION, Phase.STARTUP)
    def ahead(ctx):  # type: ignore[no-untyped-def]
        if ctx.p.subclass == 5 and ctx.p.cl[0] == 10:
            following = ctx.next.motion
            found.append((following.xm, following.ym, following.zm))

    post(HEAD + "GOTO/10,0,0\nGODLTA/1,0,0\nFINI\n", macros)
    assert found == [(11.0, 0.0, 0.0)]


def test_the_operation_table_records_a_diagnostic() -> None:
    severities: list[object] = []
    macros = Macros()

    @macros.event(Kind.MACHINE, Phase.SHUTDOWN)
    def end(ctx):  # type: ignore[no-untyped-def]
        severities.append(ctx.ops.tab[10, ctx.ops.oi])

    post(HEAD + "LOADTL/1\nFOO/1\nGOTO/1,0,0\nFINI\n", macros)
    assert severities == [1.0]


def test_a_snapshot_copies_no_diagnostics_and_shares_open_files(tmp_path) -> None:  # type: ignore[no-untyped-def]
    macros = Macros()
    clones: list[object] = []

    @macros.event(Kind.MACHINE, Phase.STARTUP)
    def start(ctx):  # type: ignore[no-untyped-def]
        ctx.globals["log"] = open(tmp_path / "log.txt", "w")  # noqa: SIM115 (X1's file)

    @macros.syntax("STOP")
    def stop(ctx):  # type: ignore[no-untyped-def]
        clone = snapshot(ctx._engine.run)
        clones.append((clone.result.diagnostics, clone.macros.globals["log"] is ctx.globals["log"]))
        ctx.globals["log"].close()

    from gecent.core.macros.table import with_macros

    plugins = with_macros(get_plugins(), macros.macros)
    pack = plugins.machine("linuxcnc-mill")
    assert pack is not None
    Run(pack.load(), plugins).process(iter(records(HEAD + "PENUP\nSTOP\nFINI\n")))
    assert clones == [([], True)]


def test_a_macros_except_exception_cannot_swallow_terminate_or_a_look_ahead() -> None:
    macros = Macros()
    seen: list[object] = []

    @macros.event(Kind.TOOL_CHANGE, Phase.SHUTDOWN)
    def careless(ctx):  # type: ignore[no-untyped-def]
        try:
            seen.append(ctx.next.tool)
            ctx.terminate()
        except Exception:
            seen.append("swallowed")
        seen.append("after")

    post(HEAD + "LOADTL/1\nLOADTL/2\nFINI\n", macros)
    assert seen == [2.0, None]


def test_tool_change_params_from_the_statements_words() -> None:
    """$P7-$P17 come from words gecent's own LOADTL does not take (a vendor's form a user
    macro passes on, say); the params read them all."""
    from gecent.core.macros.statement_hooks import _tool_params

    from .macros_helpers import record

    statement = record("LOADTL/3,LARGE,DIAMET,12,TIMES,2,SETOOL,1,2,3,ATANGL,45")
    params = _tool_params(statement)  # type: ignore[arg-type]
    assert {n: params[n] for n in (7, 8, 9, 11, 12, 13, 14, 15, 16)} == {
        7: 2.0, 8: None, 9: 3.0, 11: 12.0, 12: 2.0, 13: 1.0, 14: 2.0, 15: 3.0, 16: 45.0
    }  # fmt: skip


def test_a_cycle_with_a_dwell_has_its_own_type() -> None:
    types: list[float] = []
    macros = Macros()

    @macros.event(Kind.CYCLE, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        types.append(ctx.p.cycle_type)

    tape, _ = post(
        HEAD + "CYCLE/DRILL,DEPTH,5,CLEAR,2,DWELL,1,MMPM,50\nGOTO/10,0,0\nCYCLE/OFF\nFINI\n",
        macros,
    )
    assert types == [2.0] and "G82" in tape  # DRILL with a dwell: the control's G82


def test_ilook_false_ends_finfo_where_the_macro_is() -> None:
    found: list[float] = []
    macros = Macros()

    @macros.event(Kind.MACHINE, Phase.STARTUP)
    def start(ctx):  # type: ignore[no-untyped-def]
        found.append(ctx.finfo(0, 0))

    @macros.syntax("STOP")
    def stop(ctx):  # type: ignore[no-untyped-def]
        if ctx.la.active:
            ctx.sv.ILOOK = False
        ctx.output()

    post(HEAD + "GOTO/1,0,0\nSTOP\nGOTO/2,0,0\nFINI\n", macros)
    assert found == [6.0]  # the STOP's record, not FINI's -2


def test_look_ahead_values_reset_when_another_macro_runs() -> None:
    searches: list[int] = []
    macros = Macros()

    @macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        _ = ctx.next.tool
        ctx.cmd("STOP")  # a user macro runs: the value is gone (§7.3)
        _ = ctx.next.tool

    @macros.syntax("GOTO")
    def move(ctx):  # type: ignore[no-untyped-def]
        if ctx.la.active:
            searches.append(1)
        ctx.output()

    @macros.syntax("STOP")
    def stop(ctx):  # type: ignore[no-untyped-def]
        ctx.output()

    post(HEAD + "LOADTL/1\nGOTO/1,0,0\nLOADTL/2\nFINI\n", macros)
    assert len(searches) == 2  # two searches at tool 1 (each met the GOTO), none after


def test_ppfun_23_resets_a_rows_travel() -> None:
    rows: list[object] = []
    macros = Macros()

    @macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        if ctx.p.tool_id == 2:
            ctx.ops.reset_travel(1)
            rows.append((ctx.ops.max[1, 1], ctx.ops.min[3, 1]))

    post(HEAD + "LOADTL/1\nGOTO/5,0,0\nLOADTL/2\nFINI\n", macros)
    assert rows == [(None, None)]
