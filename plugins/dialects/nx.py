"""Siemens NX CLSF (shared/corpus/dialects.md): its words mapped onto the post's.

=========================================  ================================================
NX writes                                  the post reads
=========================================  ================================================
``TOOL PATH/operation,TOOL,name``          ``PPRINT/operation name`` (the listing)
``TLDATA/MILL,d,r,length,...``             ``CUTTER/d,r`` (the tool list, verify's tools)
``MSYS/x0,y0,z0,xi,xj,xk,yi,yj,yk``        nothing: the motion is in that system already
``LOAD/TOOL,n[,ADJUST,h]``                 ``LOADTL/n[,ADJUST,h]``
``SELECT/TOOL,n``                          nothing (the next tool)
``CUTCOM/LEFT|RIGHT,XYPLAN``               ``CUTCOM/LEFT|RIGHT``
``CYCLE/DRILL[,DEEP],RAPTO,r,FEDTO,d,...``  ``CYCLE/DRILL|DEEP,DEPTH,|d|,CLEAR,r,...``
``NURBS/ KNOT/ CNTRL/``                    straight moves within INTOL (core/cl/nurbs.py)
``PAINT/...``, ``END-OF-PATH``             nothing (display; the path's end)
=========================================  ================================================

The first GOTO of a path carries the tool axis; along the spindle it is three-axis motion.
A file may end without FINI (the post warns and ends the program).
"""

from __future__ import annotations

from typing import Any

from gecent.core.errors import InputError
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.macros import Macros
from gecent.core.macros.dialect import Dialect, ignore_noted
from gecent.plugins.dialects.cycle_words import cycle_words, split_cycle

NAME = "nx"
TITLE = "Siemens NX CLSF"
macros = Macros()


@macros.syntax("TOOL_PATH/$P1(),TOOL,$P2()")
def tool_path(ctx: Any) -> None:
    ctx.pprint(f"{ctx.p[1].name} {ctx.p[2].name}")


@macros.syntax("TLDATA/MILL,$P1,$P2,*")
def tool_data(ctx: Any) -> None:
    ctx.cmd("CUTTER", ctx.p[1], ctx.p[2])


@macros.syntax("TLDATA/$P1(DRILL,TAP,BORE,REAM),$P2,*")
def hole_tool_data(ctx: Any) -> None:
    """A hole-making tool's first value is its diameter."""
    ctx.cmd("CUTTER", ctx.p[2])


ignore_noted(macros, "PAINT", "NX DISPLAY ONLY")
macros.ignore("END-OF-PATH")  # the path's end: nothing to say
ignore_noted(macros, "SELECT/TOOL,?", "THE NEXT TOOL, FOR A CHANGER THAT STAGES IT")


@macros.syntax("MSYS")
def machine_system(ctx: Any) -> None:
    """The motion is in this system already; its origin is the work offset's business."""
    noted = ctx.globals.setdefault("msys", set())
    values = tuple(ctx.record.numbers())
    if values not in noted:
        noted.add(values)
        origin = ", ".join(f"{v:g}" for v in values[:3])
        turned = len(values) >= 9 and values[3:9] != (1.0, 0.0, 0.0, 0.0, 1.0, 0.0)
        turn = " (ITS AXES TURNED FROM THE PART'S)" if turned else ""
        ctx.warn(
            f"MSYS: THE MOTION IS IN THE MACHINE SYSTEM AT {origin}{turn}; "
            "SET THE WORK OFFSET THERE"
        )


@macros.syntax("LOAD/TOOL,$P1,[ADJUST,$P2]")
def load_tool(ctx: Any) -> None:
    if ctx.p[2] is None:
        ctx.cmd("LOADTL", ctx.p[1])
    else:
        ctx.cmd("LOADTL", ctx.p[1], "ADJUST", ctx.p[2])


@macros.syntax("CUTCOM/$P1(LEFT,RIGHT),XYPLAN")
def cutcom_plane(ctx: Any) -> None:
    ctx.cmd("CUTCOM", ctx.p[1].name)


@macros.syntax("CYCLE/$P1(DRILL,TAP,BORE,REAM,FACE),$P2*")
def cycle(ctx: Any) -> None:
    items = list(ctx.p[2])
    kind = ctx.p[1].name
    if items and getattr(items[0], "name", None) in ("DEEP", "BRKCHP"):
        kind = items.pop(0).name
    where = ctx.record.where
    numbers, pairs = split_cycle(items, where)
    if numbers or "FEDTO" not in pairs:
        raise InputError("CYCLE: FEDTO (the depth) and word, value pairs expected", where)
    back = pairs.get("RTRCTO", 0.0) > pairs.get("RAPTO", 0.0)  # above R: the start level
    step = pairs.get("STEP", pairs.get("INCR"))  # the peck, by either name
    ctx.cmd("CYCLE", *cycle_words(kind, abs(pairs["FEDTO"]), pairs.get("RAPTO", 0.0), pairs,
                                  step, back))  # fmt: skip


def sniff(head: str) -> bool:
    """NX writes TOOL PATH, TLDATA, MSYS, PAINT and END-OF-PATH."""
    starts = ("TOOL PATH/", "TLDATA/", "MSYS/", "END-OF-PATH")
    return any(line.lstrip().upper().startswith(starts) for line in head.splitlines())


DIALECT = Dialect(NAME, TITLE, "shared/corpus/dialects.md: Siemens NX CLSF", sniff,
                  tuple(macros.macros), priority=10, nurbs=True,
                  tool_lines=("LOAD/", "TLDATA/"))  # fmt: skip


@hookimpl
def register_dialects(register: Register) -> None:
    register(DIALECT)
