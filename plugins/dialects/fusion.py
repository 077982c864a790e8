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
``CYCLE/type,d,[INCR,s,]MMPM,f,c[,...]``     ``CYCLE/type,DEPTH,d,CLEAR,c[,STEP,s]...,MMPM,f``
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

NAME = "fusion"
TITLE = "Autodesk Fusion ISO 4343 APT"
macros = Macros()
UNITS = ("MMPM", "IPM", "MMPR", "IPR")


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


@macros.syntax("MOVARC/$P1,$P2,$P3,$P4,$P5,$P6,$P7,ANGLE,$P8")
def movarc(ctx: Any) -> None:
    ctx.cmd("CIRCLE", *(ctx.p[n] for n in range(1, 8)))


macros.ignore("CUTCOM/ON")  # (CUTCOM/LEFT or RIGHT follows)
ignore_noted(macros, "MODE/()", "THE MACHINE'S MODE IS ITS OWN")


@macros.syntax("CYCLE/$P1(DRILL,DEEP,BRKCHP,TAP,BORE,REAM,FACE),$P2*")
def cycle(ctx: Any) -> None:
    items = list(ctx.p[2])
    numbers: list[float] = []
    pairs: dict[str, float] = {}
    index = 0
    while index < len(items):
        item = items[index]
        if hasattr(item, "name"):
            if index + 1 >= len(items) or hasattr(items[index + 1], "name"):
                raise InputError(f"CYCLE: {item.name} expects a value", ctx.record.where)
            pairs[item.name] = float(items[index + 1])
            index += 2
        else:
            numbers.append(float(item))
            index += 1
    if len(numbers) == 3 and ctx.p[1].name == "BORE":
        numbers = numbers[:2]  # the bore's shift goes with ORIENT, which is not kept
    if len(numbers) != 2:
        raise InputError(
            "CYCLE: expected the depth and the clearance, and word, value pairs",
            ctx.record.where,
        )
    depth, clearance = numbers
    words: list[Any] = [ctx.p[1].name, "DEPTH", abs(depth), "CLEAR", clearance]
    if "INCR" in pairs:
        words += ["STEP", pairs["INCR"]]
    for name in ("RAPTO", "DWELL"):
        if pairs.get(name):
            words += [name, pairs[name]]
    for unit in UNITS:
        if unit in pairs:
            words += [unit, pairs[unit]]
    ctx.cmd("CYCLE", *words)


def sniff(head: str) -> bool:
    """Fusion quotes PARTNO's text and writes MOVARC; it writes no $$ header."""
    return "PARTNO/'" in head or "\nMOVARC/" in head


DIALECT = Dialect(NAME, TITLE, "Autodesk Fusion's Common ISO 4343 APT post", sniff,
                  tuple(macros.macros), priority=40, tool_lines=("LOADTL/",))  # fmt: skip


@hookimpl
def register_dialects(register: Register) -> None:
    register(DIALECT)
