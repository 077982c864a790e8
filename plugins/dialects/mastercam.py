"""Mastercam through NCData Services' NCI-to-APT converter (the only Mastercam APT found:
EfrainRodriguez/step-nc-adapters samples; issue 19 research): its words mapped onto the
post's.

============================================  ============================================
the converter writes                          the post reads
============================================  ============================================
``$$ TOOL PLANE VIEW / MATRIX`` rows ...       comments
``TPRINT/name``                               ``PPRINT/name``
``LOAD/ TOOL,n,LENGTH,l,ADJUST,h``            ``LOADTL/n,LENGTH,l,ADJUST,h``
``MODE/ XYPLAN``, ``AUTOPS``                  nothing
``INDIRV`` + ``TLON,GOFWD/(CIRCLE/...),ON,    ``CIRCLE`` and the ``GOTO`` to the arc's end
(LINE/...)``                                  (plugins/dialects/gofwd.py)
============================================  ============================================

Its header and MACHIN may disagree on units (MM in one, INCHES in the other): the file's
UNITS, if any, decides, else the machine's unit, as for any file.
"""

from __future__ import annotations

from typing import Any

from gecent.core.hookspecs import Register, hookimpl
from gecent.core.macros import Macros
from gecent.core.macros.dialect import Dialect, ignore_noted
from gecent.plugins.dialects.gofwd import circle_move, indirv

macros = Macros()
ignore_noted(macros, "MODE", "ARCS ARE READ IN XY")
macros.ignore("AUTOPS")  # (part of the GOFWD circle form)
macros.syntax("INDIRV/$P1,$P2,$P3", name="indirv")(indirv)
macros.syntax("GOFWD/TLON,*", name="circle")(circle_move)


@macros.syntax("TPRINT/$P1''")
def tprint(ctx: Any) -> None:
    ctx.pprint(ctx.p[1])


@macros.syntax("LOAD/TOOL,$P1,$P2*")
def load_tool(ctx: Any) -> None:
    """LENGTH,0 is the converter's "not known": left out."""
    items = [getattr(a, "name", a) for a in ctx.p[2]]
    kept: list[Any] = []
    for index in range(0, len(items) - 1, 2):
        word, value = items[index], items[index + 1]
        if not (word == "LENGTH" and value == 0):
            kept += [word, value]
    ctx.cmd("LOADTL", ctx.p[1], *kept)


def sniff(head: str) -> bool:
    return "MasterCAM NCI to APT" in head or "MASTERCAM NCI TO APT" in head.upper()


DIALECT = Dialect("mastercam", "Mastercam (NCI to APT)", "NCData Services NCI2APT output",
                  sniff, tuple(macros.macros), priority=15, track_position=True,
                  tool_lines=("LOAD/",))  # fmt: skip


@hookimpl
def register_dialects(register: Register) -> None:
    register(DIALECT)
