"""Autodesk Fusion / HSM "Common ISO 4343 APT" post output (its post source, revision
43569; docs/research, issue 19): its words mapped onto the post's.

===========================================  ===========================================
Fusion writes                                the post reads
===========================================  ===========================================
``PARTNO/'name'``, ``PPRINT/'text'``         the text without its quotes
``LOADTL/t,0,body length,length offset``     ``LOADTL/t[,ADJUST,offset]``
``MOVARC/cx,cy,cz,nx,ny,nz,r,ANGLE,a``       ``CIRCLE/cx,cy,cz,nx,ny,nz,r`` (the GOTO after
                                             it ends the arc)
``CUTCOM/ON``, ``MODE/MILL|TURN``            nothing
``CYCLE/type,d,[INCR,s,]MMPM,f,c[,RAPTO,r]``  ``CYCLE/type,DEPTH,d,CLEAR,R-top[,STEP,s]...``
and its points (each the hole's bottom)       the points at the holes' tops; R = c - r
``CYCLE/BORE,...,ORIENT,0``                  ORIENT dropped (the spindle is not oriented)
===========================================  ===========================================

The post's SPINDL/ON and SPINDL/OFF for stopping and starting are read as written (the
Fusion post had them swapped in the revision read; a file says what the control gets).
"""

from __future__ import annotations

from typing import Any

from gecent.core.errors import InputError
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.macros import Macros
from gecent.core.macros.dialect import Dialect, ignore_noted
from gecent.plugins.dialects.cycle_words import cycle_words, split_cycle

NAME = "fusion"
TITLE = "Autodesk Fusion ISO 4343 APT"
macros = Macros()


def _unquoted(text: str) -> str:
    text = text.strip()
    if len(text) >= 2 and text[0] == text[-1] == "'":
        return text[1:-1]
    return text


@macros.syntax("PARTNO/$P1''")
def partno(ctx: Any) -> None:
    ctx.cmd(f"PARTNO/{_unquoted(ctx.p[1])}")


@macros.syntax("PPRINT/$P1''")
def pprint(ctx: Any) -> None:
    ctx.pprint(_unquoted(ctx.p[1]))


@macros.syntax("LOADTL/$P1,$P2,$P3,$P4")
def loadtl(ctx: Any) -> None:
    if ctx.p[4]:
        ctx.cmd("LOADTL", ctx.p[1], "ADJUST", ctx.p[4])
    else:
        ctx.cmd("LOADTL", ctx.p[1])


@macros.syntax("MOVARC/$P1,$P2,$P3,$P4,$P5,$P6,$P7,[ANGLE,$P8]")
def movarc(ctx: Any) -> None:
    ctx.cmd("CIRCLE", *(ctx.p[n] for n in range(1, 8)))


macros.ignore("CUTCOM/ON")  # (CUTCOM/LEFT or RIGHT follows)
ignore_noted(macros, "MODE/()", "THE MACHINE'S MODE IS ITS OWN")


@macros.syntax("CYCLE/$P1(DRILL,DEEP,BRKCHP,TAP,BORE,REAM,FACE),$P2*")
def cycle(ctx: Any) -> None:
    """Held until its first point: Fusion's cycle point is the hole's bottom and its
    clearance an absolute height, so the post's cycle (from the hole's top) is made there."""
    numbers, pairs = split_cycle(ctx.p[2], ctx.record.where)
    if len(numbers) == 3 and ctx.p[1].name == "BORE":
        numbers = numbers[:2]  # the bore's shift goes with ORIENT, which is not kept
    if len(numbers) != 2:
        raise InputError(
            "CYCLE: expected the depth and the clearance, and word, value pairs",
            ctx.record.where,
        )
    if "ORIENT" in pairs or "ORIANT" in pairs:
        ctx.warn("CYCLE/BORE: ORIENT AND ITS SHIFT NOT KEPT: A PLAIN BORE, FED OUT")
    depth, clearance = numbers
    ctx.globals["cycle"] = {
        "kind": ctx.p[1].name,
        "depth": abs(depth),
        "plane": clearance - pairs.get("RAPTO", 0.0),  # the R plane, absolute
        "pairs": pairs,
        "made": None,
    }


@macros.syntax("CYCLE/OFF")
def cycle_off(ctx: Any) -> None:
    held = ctx.globals.pop("cycle", None)
    if held is None or held["made"] is not None:
        ctx.output()  # (a cycle with no point made nothing to end)


@macros.syntax("GOTO/$P1,$P2,$P3,*")
def cycle_point(ctx: Any) -> None:
    held = ctx.globals.get("cycle")
    if held is None:
        ctx.output()
        return
    ctx.match(False)  # what this makes is the post's own CYCLE and GOTO
    top = ctx.p[3] + held["depth"]  # the point is the hole's bottom
    clear = held["plane"] - top
    if held["made"] != (top, clear):
        pairs = held["pairs"]
        # back to where the cycle began (the clearance height)
        words = cycle_words(held["kind"], held["depth"], clear, pairs, pairs.get("INCR"), True)
        ctx.cmd("CYCLE", *words)
        held["made"] = (top, clear)
    ctx.goto(ctx.p[1], ctx.p[2], top)


def sniff(head: str) -> bool:
    """Fusion quotes PARTNO's text and writes MOVARC; it writes no $$ header."""
    return "PARTNO/'" in head or "\nMOVARC/" in head


DIALECT = Dialect(NAME, TITLE, "Autodesk Fusion's Common ISO 4343 APT post", sniff,
                  tuple(macros.macros), priority=40, tool_lines=("LOADTL/",))  # fmt: skip


@hookimpl
def register_dialects(register: Register) -> None:
    register(DIALECT)
