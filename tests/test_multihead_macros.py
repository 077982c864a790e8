"""Macros in a multihead program (manual §3.4.8.1, 001 L7170-7206: the first pass
processes the CL file "for both heads separately"; macros, spec 09): each head's run reads
its own records through its own macro engine, and a macro's look-ahead runs along that
head's records, not the other head's."""

from __future__ import annotations

from pathlib import Path

from gecent.core.dispatch.post import post
from gecent.core.macros import Kind, Macros, Phase
from gecent.core.macros.table import with_macros
from gecent.core.output.block import Code
from gecent.core.output.tape import tape_line
from gecent.core.plugins import PluginSet

PROGRAM = """PARTNO MACROS
MACHIN/GECENT,51
COMBIN/2
SELECT/HEAD,1
FROM/10,10,0
FEDRAT/10
SELECT/HEAD,2
FROM/20,10,0
FEDRAT/10
SELECT/HEAD,1
OP/1
STOP
GOTO/10,9,0
SELECT/HEAD,2
OP/1
GOTO/20,8,0
FINI
"""


def test_a_statement_macro_runs_on_the_head_that_meets_it(
    plugins: PluginSet, tmp_path: Path
) -> None:
    """STOP on head 1 is made COOLNT/ON by the macro: head 1's M08 rides its move in the
    combined block (one M register, MACH51); head 2 has none of its own."""
    macros = Macros()

    @macros.syntax("STOP")
    def stop(ctx):  # type: ignore[no-untyped-def]
        ctx.cmd("COOLNT/ON")

    program = tmp_path / "p.apt"
    program.write_text(PROGRAM)
    result = post(str(program), with_macros(plugins, macros.macros))
    lines = [tape_line(b) for b in result.blocks if b.code is not Code.PARTNO]
    assert [line for line in lines if line] == ["N013G01Z-001F0100M08W-002E0050"]


def test_a_look_ahead_runs_along_the_heads_own_records(plugins: PluginSet, tmp_path: Path) -> None:
    """Each head's FROM looks ahead to its next motion: head 1's is (10, 9), head 2's
    (20, 8), though head 1's GOTO comes between them in the file; each head's engine
    starts the machine once and shuts it down at FINI."""
    seen: list[tuple[float, float]] = []
    events: list[str] = []
    macros = Macros()

    @macros.event(Kind.MACHINE, Phase.STARTUP)
    def start(ctx):  # type: ignore[no-untyped-def]
        events.append("startup")

    @macros.event(Kind.MACHINE, Phase.SHUTDOWN)
    def stop(ctx):  # type: ignore[no-untyped-def]
        if not ctx.la.active:  # (a look-ahead that reaches FINI shuts its copy down)
            events.append("shutdown")

    @macros.event(Kind.MOTION, Phase.STARTUP)
    def next_move(ctx):  # type: ignore[no-untyped-def]
        following = ctx.next.motion
        if not ctx.la.active and ctx.p.cl[1] == 10.0:  # (each head's FROM)
            seen.append((following.xm, following.ym))

    program = tmp_path / "p.apt"
    program.write_text(PROGRAM)
    post(str(program), with_macros(plugins, macros.macros))
    assert seen == [(10.0, 9.0), (20.0, 8.0)]
    assert events == ["startup", "shutdown", "startup", "shutdown"]
