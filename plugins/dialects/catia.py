"""CATIA V5 APT output (Dassault's "Generated APT Output" and "APT Import" pages; issue 19
research): its words mapped onto the post's.

==========================================  ==============================================
CATIA writes                                the post reads
==========================================  ==============================================
sequence tags past column 72 (PT n)         nothing: lines are read to column 72
``$$*CATIA0`` and three ``$$`` matrix rows   comments (the motion is in that axis system)
``CHANNEL,1``, ``AUTOPS``, ``SWITCH/n``      nothing
``TPRINT/name``                             ``PPRINT/name``
``TOOLNO/n,MILL|TURN,...``                  ``LOADTL/n`` (a later ``LOADTL/n`` of the
                                            same tool is the same change)
``INDIRV/i,j,k`` + ``TLON,GOFWD/(CIRCLE/   ``CIRCLE`` and the ``GOTO`` to the arc's end
...),ON,(LINE/...)``                        (plugins/dialects/gofwd.py)
==========================================  ==============================================

CYCLE statements come from each site's PP table and have no fixed form: they are read as
the post's own CYCLE.
"""

from __future__ import annotations

from typing import Any

from gecent.core.hookspecs import Register, hookimpl
from gecent.core.macros import Macros
from gecent.core.macros.dialect import Dialect, ignore_noted
from gecent.plugins.dialects.gofwd import circle_move, indirv

macros = Macros()
ignore_noted(macros, "CHANNEL", "ONE CHANNEL HERE")
macros.ignore("AUTOPS")  # (part of the GOFWD circle form)
ignore_noted(macros, "MODE", "THE MACHINE'S MODE IS ITS OWN")
macros.syntax("INDIRV/$P1,$P2,$P3", name="indirv")(indirv)
macros.syntax("GOFWD/TLON,*", name="circle")(circle_move)


ignore_noted(macros, "SWITCH/*", "A CATIA PP-TABLE WORD")


@macros.syntax("TPRINT/$P1''")
def tprint(ctx: Any) -> None:
    ctx.pprint(ctx.p[1])


@macros.syntax("TOOLNO/$P1,$P2(MILL,TURN),*")
def toolno(ctx: Any) -> None:
    ctx.cmd("LOADTL", ctx.p[1])
    ctx.globals["tool"] = ctx.p[1]


@macros.syntax("LOADTL/$P1,*")
def loadtl(ctx: Any) -> None:
    if ctx.globals.get("tool") == ctx.p[1]:
        return  # TOOLNO has loaded it
    ctx.globals["tool"] = ctx.p[1]
    ctx.output()


def sniff(head: str) -> bool:
    return "CATIA APT VERSION" in head or "$$*CATIA0" in head


DIALECT = Dialect("catia", "CATIA V5 APT", "Dassault CATIA V5 Generated APT Output", sniff,
                  tuple(macros.macros), priority=15, columns=72, track_position=True,
                  tool_lines=("TOOLNO/",))  # fmt: skip


@hookimpl
def register_dialects(register: Register) -> None:
    register(DIALECT)
