"""The ACME VMC-1's macros: spindle and coolant off and the head up before a tool change
(the changer works at machine Z0); after it a header for the tool's work and the next tool
staged in the magazine (T without M06, found by look-ahead); a header for each operation
a CAM system marks with OPTYPE."""

from gecent.core.hookspecs import hookimpl
from gecent.core.macros import Kind, Macros, Phase

macros = Macros(machine="acme-vmc1")


@macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
def tool_change(ctx):
    ctx.cmd("SPINDL/OFF")
    ctx.cmd("COOLNT/OFF")
    ctx.insert("G53 Z0")


@macros.event(Kind.TOOL_CHANGE, Phase.SHUTDOWN)
def stage_next_tool(ctx):
    following = ctx.next.tool
    staged = "LAST TOOL" if following is None else f"NEXT T{following:g}"
    ctx.pprint(f"TOOL {ctx.p.tool_id:g} - {staged}")
    if following is not None:
        ctx.insert(f"T{following:g}")


@macros.event(Kind.OPERATION_EVENT)
def operation_header(ctx):
    oe = ctx.oe
    kind = {1: "TOOL", 2: "MILL", 3: "TURN", 4: "CYCLE"}.get(int(ctx.p[1]), "NO CUT")
    name = " ".join(str(word) for word in ctx.p[2][1:])
    speed = f" S{oe.S:g}" if oe.S else ""
    feed = f" F{oe.F:g}" if oe.F else ""
    ctx.pprint(f"{kind} {name}".strip() + speed + feed)


@hookimpl
def register_macros(register):
    macros.register_all(register)
