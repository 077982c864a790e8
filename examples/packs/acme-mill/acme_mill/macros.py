"""Macros of the ACME VMC-1 (spec 09; docs/macros.md): the tool-change sequence the
machine's changer needs, the next tool staged in the magazine, and a header comment for
the work each tool does.

The VMC-1 changes tools at machine Z0 only: before each change the spindle and coolant go
off and the head goes up (G53 is machine coordinates, so TRANS does not move it). After the
change the next tool of the program is staged (T without M06: the magazine turns while this
tool cuts), found by look-ahead.
"""

from gecent.core.hookspecs import hookimpl
from gecent.core.macros import Kind, Macros, Phase

macros = Macros(machine="acme-vmc1")


@macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
def tool_change(ctx):
    """Spindle and coolant off, head to the change position."""
    ctx.cmd("SPINDL/OFF")
    ctx.cmd("COOLNT/OFF")
    ctx.insert("G53 Z0")


@macros.event(Kind.TOOL_CHANGE, Phase.SHUTDOWN)
def stage_next_tool(ctx):
    """The header of the tool's work, and the next tool staged."""
    following = ctx.next.tool
    staged = "LAST TOOL" if following is None else f"NEXT T{following:g}"
    ctx.pprint(f"TOOL {ctx.p.tool_id:g} - {staged}")
    if following is not None:
        ctx.insert(f"T{following:g}")


@hookimpl
def register_macros(register):
    macros.register_all(register)
