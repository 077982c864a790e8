"""Operations (spec 09 §5.9, §7.7-§7.9, §8, §9): OPTYPE and the operation-event macro with
$OE.*, $FINFO with $INFO.*, $FLOOK and $LOOK (X5-X8), and the operation tables (X19)."""

from __future__ import annotations

import pytest
from gecent.core.macros import Kind, Macros, Phase

from .macros_helpers import post, warnings

HEAD = "PARTNO T\nUNITS/MM\nFROM/0,0,50\n"
OPERATION = "RAPID\nGOTO/10,0,5\nFEDRAT/200\nGOTO/10,0,-2\nGOTO/20,0,-2\nRAPID\nGOTO/20,0,5\n"


def oe_macros(seen: list[tuple[object, ...]]) -> Macros:
    macros = Macros()

    @macros.event(Kind.OPERATION_EVENT)
    def operation(ctx):  # type: ignore[no-untyped-def]
        oe = ctx.oe
        start = oe.P2.C[:3] if oe.P2.C else None
        seen.append((ctx.p[1], ctx.p[3], ctx.p[4], ctx.sv.OPTYPE, oe.P1.CLN, start,
                     oe.T, oe.S, oe.F))  # fmt: skip
        ctx.pprint(f"OPERATION {ctx.p[2][0]}")

    return macros


def test_optype_auto_is_resolved_and_the_oe_macro_sees_the_coming_operation() -> None:
    seen: list[tuple[object, ...]] = []
    program = HEAD + "LOADTL/1\nSPINDL/1000\nOPTYPE/AUTO\n" + OPERATION + "FINI\n"
    _, result = post(program, oe_macros(seen))
    # $P1 MILL (a feed motion first); $P3 the OPTYPE's record; $P4 the first cut's record;
    # $OPTYPE still the previous value (-3: none yet); $OE.P1 the first move (the rapid),
    # $OE.P2 where the cut starts; the status there: tool 1, S 1000, F 200
    assert seen == [(2.0, 6, 10, -3.0, 8, (10.0, 0.0, 5.0), 1.0, 1000.0, 200.0)]
    assert warnings(result) == []


@pytest.mark.parametrize(
    ("after", "expected"),
    [
        ("LOADTL/2\nGOTO/1,1,1\nFINI\n", 1.0),  # a tool change first: TOOL
        ("OPTYPE/MILL\n" + OPERATION + "FINI\n", -1.0),  # another OPTYPE before a cut
        ("FINI\n", -2.0),  # FINI before a cut
        ("CYCLE/DRILL,DEPTH,5,CLEAR,2,MMPM,50\nGOTO/10,0,0\nCYCLE/OFF\nFINI\n", 4.0),  # AXIAL
    ],
)
def test_what_ends_the_optype_look_ahead(after: str, expected: float) -> None:
    seen: list[tuple[object, ...]] = []
    post(HEAD + "LOADTL/1\nFEDRAT/100\nOPTYPE/AUTO\n" + after, oe_macros(seen))
    assert seen[0][0] == expected


def test_an_explicit_optype_keeps_its_type() -> None:
    seen: list[tuple[object, ...]] = []
    post(HEAD + "LOADTL/1\nOPTYPE/TURN,ROUGH\n" + OPERATION + "FINI\n", oe_macros(seen))
    assert seen[0][0] == 3.0


def test_optype_without_macros_is_warned_and_disregarded() -> None:
    _, result = post(HEAD + "OPTYPE/MILL\nFINI\n", None)
    assert any("OPTYPE" in w and "DISREGARDED" in w for w in warnings(result))


def test_a_bad_optype_is_bad_input() -> None:
    with pytest.raises(Exception, match="OPTYPE expects TOOL, MILL, TURN, AXIAL or AUTO"):
        post(HEAD + "OPTYPE/DRILLING\nFINI\n", oe_macros([]))


def test_the_oe_redundancy_guard_off_leaves_the_operation_as_it_was() -> None:
    """$P4 = 0 disables the guard (tests/test_macros_wave9.py has the guard)."""
    macros = Macros()

    @macros.event(Kind.OPERATION_EVENT)
    def operation(ctx):  # type: ignore[no-untyped-def]
        ctx.p[4] = 0

    program = HEAD + "OPTYPE/MILL\n" + OPERATION + "FINI\n"
    assert post(program, macros)[0] == post(program, None)[0]


# -- $FINFO and $INFO.* ----------------------------------------------------------------------


def test_finfo_gathers_the_operation_ahead() -> None:
    found: list[object] = []
    macros = Macros()

    @macros.event(Kind.TOOL_CHANGE, Phase.SHUTDOWN)
    def after(ctx):  # type: ignore[no-untyped-def]
        last = ctx.finfo()
        info = ctx.info
        found.append((last, info.P1.CLN, info.P2.C[:3], info.P3.C[:3], info.P4.CLN,
                      info.OPCNT, info.ISIL, info.ISIP, info.ISIC, info.V[7]))  # fmt: skip
        found.append((info.TLMAX, info.TLMIN, info.TLSUM[4], info.TLSUM[0] > 0))
        info.V[7] = "late"  # ignored: the look-ahead is over (§7.8)
        info.OPCNT = 99
        assert ctx.info.V[7] == "marked" and ctx.info.OPCNT == 1

    @macros.syntax("PPRINT/$P1''")
    def mark(ctx):  # type: ignore[no-untyped-def]
        if ctx.la.active:
            ctx.info.V[7] = "marked"  # macros may set $INFO.V* during $FINFO

    program = HEAD + "LOADTL/1\n" + OPERATION + "PPRINT/NOT REACHED\nGOTO/0,0,50\nFINI\n"
    post(program.replace("GOTO/20,0,-2\n", "GOTO/20,0,-2\nPPRINT/HERE\n"), macros)
    # stopped at the rapid after the cut (record 12); P1 the first move, P2 the cut's
    # start, P3 the last cut's end, P4 the last rapid; V7 set by a macro during the search
    assert found[0] == (12.0, 6, (10.0, 0.0, 5.0), (20.0, 0.0, -2.0), 12, 1, True, True, False,
                        "marked")  # fmt: skip
    # the operation's extents (X, Y, Z) and its highest feed, and time at feed
    assert found[1] == ((20.0, 0.0, 5.0), (10.0, 0.0, -2.0), 200.0, True)  # points reached


def test_finfo_with_an_end_spans_operations_and_fini_gives_minus_two() -> None:
    found: list[float] = []
    macros = Macros()

    @macros.event(Kind.MACHINE, Phase.STARTUP)
    def start(ctx):  # type: ignore[no-untyped-def]
        found.append(ctx.finfo())
        found.append(ctx.info.OPCNT)
        found.append(ctx.finfo(0, 12))
        found.append(ctx.finfo(0, 0))
        found.append(ctx.info.OPCNT)

    post(HEAD + "LOADTL/1\n" + OPERATION + OPERATION + "FINI\n", macros)
    # from the start, with no end: it stops at the tool change (record 4), no cut seen;
    # with end 12 it reads past the operation boundary up to record 12 (the second
    # operation's first move), then the first record beyond ends it
    assert found[0] == 4.0 and found[1] == 0
    assert found[2] == 12.0
    assert found[3:] == [-2.0, 2]  # to FINI: -2, and both operations counted


# -- $FLOOK and $LOOK (X5-X8) ----------------------------------------------------------------


def cutting_time_macros(times: list[float], rows: list[float]) -> Macros:
    """X7: the cutting time of each coming operation."""
    macros = Macros()

    @macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        ctx.look[1] = ctx.sv.FEDTIM  # ends look-ahead 1 at the next tool change
        times.append(ctx.flook(1) - ctx.sv.FEDTIM)

    @macros.event(Kind.MACHINE, Phase.SHUTDOWN)
    def end(ctx):  # type: ignore[no-untyped-def]
        ctx.look[1] = ctx.sv.FEDTIM  # so the last operation's call does not return -2
        if not ctx.la.active:  # the operation tables' feed and positioning seconds
            ops = ctx.ops
            rows.extend(ops.sum[1, row] + ops.sum[2, row] for row in range(2, ops.size + 1))

    return macros


def test_x7_cutting_time_of_each_operation() -> None:
    times: list[float] = []
    rows: list[float] = []
    program = HEAD + "LOADTL/1\n" + OPERATION + "LOADTL/2\n" + OPERATION * 2 + "FINI\n"
    _, result = post(program, cutting_time_macros(times, rows))
    assert len(times) == 2 and sum(times) == pytest.approx(result.cut_minutes)
    # the look-ahead's times are what the operation table gathered as the blocks went out
    assert [60 * t for t in times] == pytest.approx(rows)
    # the second operation is the first one twice less the first one's long approach
    assert times[1] < 2 * times[0]


def test_x8_break_the_tape_before_a_tool_change() -> None:
    macros = Macros()

    @macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
    def before(ctx):  # type: ignore[no-untyped-def]
        if ctx.sv.FT != 0 and ctx.flook(1) == 1:  # was the break macro activated?
            ctx.cmd("BREAK")

    @macros.event(Kind.BREAK, Phase.SHUTDOWN)
    def broken(ctx):  # type: ignore[no-untyped-def]
        ctx.look[1] = 1  # signal that a tape break is needed

    program = HEAD + "LOADTL/1\n" + OPERATION + "LOADTL/2\n" + OPERATION + "BREAK\nFINI\n"
    tape, _ = post(program, macros)
    lines = tape.splitlines()
    tool2 = next(i for i, line in enumerate(lines) if "T2 M06" in line or "T02 M06" in line)
    assert lines[tool2 - 1].endswith("M01")  # the BREAK issued before the tool change
    assert sum(line.endswith("M01") for line in lines) == 2


def test_x5_x6_flook_zero_and_look_active() -> None:
    seen: list[object] = []
    macros = Macros()

    @macros.event(Kind.MACHINE, Phase.STARTUP)
    def start(ctx):  # type: ignore[no-untyped-def]
        seen.append(("idle", ctx.flook(0), ctx.look.active(1)))
        seen.append(("ended", ctx.flook(1)))

    @macros.syntax("STOP")
    def stop(ctx):  # type: ignore[no-untyped-def]
        if ctx.look.active(1):
            seen.append(("inside", ctx.flook(0), ctx.flook(2) if ctx.look[1] else None))
            ctx.look[1] = 42  # X5: ends look-ahead 1 with 42
        ctx.output()

    @macros.syntax("OPSTOP")
    def opstop(ctx):  # type: ignore[no-untyped-def]
        if ctx.look.active(2):
            ctx.look[2] = 7
        ctx.output()

    post(HEAD + "STOP\nOPSTOP\nFINI\n", macros)
    # inside context 1, $FLOOK(0) is 1 and a nested $FLOOK(2) runs and returns 7
    assert seen[0] == ("idle", 0.0, 0)
    assert ("inside", 1.0, 7.0) in seen and ("ended", 42.0) in seen


def test_flook_keeps_the_listed_variables() -> None:
    kept: list[object] = []
    macros = Macros()

    @macros.event(Kind.MACHINE, Phase.STARTUP)
    def start(ctx):  # type: ignore[no-untyped-def]
        ctx.globals.update(tools=0, other=0)
        result = ctx.flook(3, keep=("tools",))
        kept.append((result, ctx.globals["tools"], ctx.globals["other"]))

    @macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
    def count(ctx):  # type: ignore[no-untyped-def]
        ctx.globals["tools"] += 1
        ctx.globals["other"] += 1

    post(HEAD + "LOADTL/1\nLOADTL/2\nLOADTL/3\nFINI\n", macros)
    assert kept == [(-2.0, 3, 0)]  # FINI: -2; "tools" came back, "other" did not


# -- the operation tables (§9, X19) ----------------------------------------------------------


def test_x19_operation_table_rows() -> None:
    rows: list[tuple[object, ...]] = []
    macros = Macros()

    @macros.event(Kind.MACHINE, Phase.SHUTDOWN)
    def end(ctx):  # type: ignore[no-untyped-def]
        ops = ctx.ops
        for row in range(1, ops.size + 1):
            rows.append((ops.tab[1, row], ops.tab[3, row], ops.tab[8, row], ops.tab[9, row],
                         ops.max[1, row], ops.min[3, row], round(ops.sum[1, row], 3) > 0,
                         ops.sum[5, row]))  # fmt: skip
        rows.append(("oi", ctx.sv.OI, ops.oi, ctx.sv.OPSIZ))

    @macros.event(Kind.OPERATION_EVENT)
    def operation(ctx):  # type: ignore[no-untyped-def]
        return None

    program = (HEAD + "LOADTL/1\nOPTYPE/MILL\n" + OPERATION + "OPTYPE/MILL\n" + OPERATION
               + "LOADTL/2\n" + OPERATION + "FINI\n")  # fmt: skip
    post(program, macros)
    # row 1 the dummy (and whole-program travel); tool 1's row, then a row for its second
    # OPTYPE, then tool 2's row
    assert [r[0] for r in rows[:4]] == [None, 1.0, 1.0, 2.0]
    # a tool change's row takes the $OPTYPE in force (the first OPTYPE then fills it)
    assert [r[1] for r in rows[:4]] == [-3.0, 2.0, 2.0, 2.0]
    assert rows[0][4] == 20.0 and rows[0][5] == -2.0  # the whole program's X max, Z min
    assert all(r[2] is not None and r[3] >= r[2] for r in rows[1:4])  # N from .. to
    assert rows[1][7] == 200.0  # the highest feed of the operation
    assert rows[-1] == ("oi", 4, 4, 4)


def test_opmerge_and_the_999_operation_limit() -> None:
    sizes: list[int] = []
    macros = Macros()

    @macros.event(Kind.MACHINE, Phase.STARTUP)
    def start(ctx):  # type: ignore[no-untyped-def]
        ctx.sv.OPMERGE = True

    @macros.event(Kind.MACHINE, Phase.SHUTDOWN)
    def end(ctx):  # type: ignore[no-untyped-def]
        sizes.append(ctx.ops.size)

    program = HEAD + "LOADTL/1\nOPTYPE/MILL\nOPTYPE/MILL\n" + "LOADTL/1\n" * 1100 + "FINI\n"
    post(program, macros)
    assert sizes == [999]
