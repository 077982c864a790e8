"""Variable look-ahead (spec 09 §7.2-§7.6): the next tool, the next motion, FINI, the
worked examples X2 and X3, and that a look-ahead never writes to the real outputs."""

from __future__ import annotations

from gecent.core.macros import Kind, Macros, Phase

from .macros_helpers import post, warnings

HEAD = "PARTNO T\nUNITS/MM\nFROM/0,0,10\nFEDRAT/100\n"
THREE_TOOLS = HEAD + ("LOADTL/1\nGOTO/1,0,0\nLOADTL/2\nGOTO/2,0,0\nLOADTL/3\nGOTO/3,0,0\nFINI\n")


def staged_tools() -> tuple[Macros, list[object]]:
    seen: list[object] = []
    macros = Macros()

    @macros.event(Kind.TOOL_CHANGE, Phase.SHUTDOWN)
    def stage_next(ctx):  # type: ignore[no-untyped-def]
        following = ctx.next.tool
        if not ctx.la.active:  # (X1: a side effect of our own, kept out of look-aheads)
            seen.append((ctx.p.tool_id, following))
        if following is not None:
            ctx.insert(f"T{following:g}")  # the next tool staged in the magazine

    return macros, seen


def test_next_tool_at_each_change_and_none_at_the_last() -> None:
    macros, seen = staged_tools()
    tape, _ = post(THREE_TOOLS, macros)
    assert seen == [(1.0, 2.0), (2.0, 3.0), (3.0, None)]
    lines = tape.splitlines()
    first = next(i for i, line in enumerate(lines) if "T01 M06" in line)
    assert lines[first + 1] == "T2"
    assert sum(line.startswith("T") for line in lines) == 2  # no staging after the last


def test_the_look_ahead_writes_nothing_and_changes_nothing() -> None:
    macros, _ = staged_tools()
    tape, result = post(THREE_TOOLS, macros)
    plain, plain_result = post(THREE_TOOLS, None)
    assert [line for line in tape.splitlines() if line not in ("T2", "T3")] == plain.splitlines()
    assert warnings(result) == warnings(plain_result)
    assert result.records == plain_result.records


def test_the_look_ahead_sees_records_a_macro_translates() -> None:
    """The search runs the user-defined macros: a vendor's LOAD/TOOL,n translated into
    LOADTL is the next tool (§7.2: the record may come from a macro)."""
    macros, seen = staged_tools()

    @macros.syntax("LOAD/TOOL,$P1")
    def load_tool(ctx):  # type: ignore[no-untyped-def]
        ctx.cmd("LOADTL", ctx.p[1])

    post(HEAD + "LOAD/TOOL,4\nGOTO/1,0,0\nLOAD/TOOL,9\nGOTO/2,0,0\nFINI\n", macros)
    assert seen == [(4.0, 9.0), (9.0, None)]


def test_x2_the_machine_shutdown_forces_the_results_at_fini() -> None:
    macros, seen = staged_tools()
    motions: list[object] = []

    @macros.event(Kind.MACHINE, Phase.SHUTDOWN)
    def at_fini(ctx):  # type: ignore[no-untyped-def]
        if ctx.la.tool:
            ctx.cmd("LOADTL/99")
        if ctx.la.motion:
            ctx.goto(99, 99, 99)

    @macros.event(Kind.MOTION, Phase.STARTUP)
    def next_move(ctx):  # type: ignore[no-untyped-def]
        following = ctx.next.motion
        if not ctx.la.active:
            motions.append((ctx.p.cl[0], following.xm, following.ym, following.zm))

    tape, _ = post(THREE_TOOLS, macros)
    assert seen == [(1.0, 2.0), (2.0, 3.0), (3.0, 99.0)]
    assert motions[-1] == (3.0, 99.0, 99.0, 99.0)
    assert "99" not in tape.replace("T99", "")  # none of it reached the real output
    assert "T99" in tape  # (the staging macro's INSERT of the forced result did)


def test_x3_next_motion_across_a_tool_change_in_machine_coordinates() -> None:
    motions: list[tuple[float, ...]] = []
    macros = Macros()

    @macros.event(Kind.MOTION, Phase.STARTUP)
    def next_move(ctx):  # type: ignore[no-untyped-def]
        following = ctx.next.motion
        if following is None:  # inside another look-ahead (§7.3 step 2)
            ctx.terminate()
        motions.append((ctx.sv.XM, ctx.p.cl[0], following.xm, following.zm, following.zc))

    post(HEAD + "TRANS/0,0,5\nGOTO/1,0,0\nLOADTL/2\nGOTO/2,0,0\nFINI\n", macros)
    assert motions == [
        (0.0, 0.0, 1.0, 5.0, 0.0),  # FROM: next is GOTO/1,0,0, machine Z = 0 + 5
        (0.0, 1.0, 2.0, 5.0, 0.0),  # across the LOADTL
        (1.0, 2.0, 1.0, 5.0, 0.0),  # the last: no next motion, the current position
    ]


def test_a_look_ahead_inside_a_look_ahead_is_none() -> None:
    inner: list[object] = []
    macros = Macros()

    @macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        _ = ctx.next.tool

    @macros.syntax("SPINDL/$P1")
    def speed(ctx):  # type: ignore[no-untyped-def]
        if ctx.la.active:
            inner.append(ctx.next.motion)  # a motion search during a tool search: none
        ctx.output()

    post(HEAD + "LOADTL/1\nSPINDL/500\nGOTO/1,0,0\nLOADTL/2\nFINI\n", macros)
    assert inner == [None]


def test_results_are_cached_within_one_activation() -> None:
    searched: list[int] = []
    macros = Macros()

    @macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        assert ctx.next.tool == ctx.next.tool  # one search for both reads

    @macros.syntax("GOTO")
    def move(ctx):  # type: ignore[no-untyped-def]
        if ctx.la.active:
            searched.append(1)
        ctx.output()

    post(THREE_TOOLS, macros)
    assert len(searched) == 3  # each search met one GOTO before the next tool or FINI
