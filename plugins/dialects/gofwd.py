"""APT's circle motion as CATIA V5 and Mastercam's NCI-to-APT converter write it (not a
plugin: the two dialects share it)::

    INDIRV/ i, j, k                                    the start tangent
    TLON,GOFWD/ (CIRCLE/ xc, yc, zc, r),ON,[2,INTOF,](LINE/ x1,y1,z1, x2,y2,z2)

The arc goes from the tool's position round the circle in the tangent's sense and ends at
the LINE's second point. It becomes the post's CIRCLE (centre, axis +Z or -Z, radius) and
the GOTO to the end. Only arcs in the XY plane are read (MODE/XYPLAN); CYLNDR and POINT
forms stop the run naming the line.
"""

from __future__ import annotations

import re
from typing import Any

from gecent.core.errors import InputError, NotYetSupported

_CIRCLE = re.compile(r"\(\s*CIRCLE\s*/([^)]*)\)", re.IGNORECASE)
_LINE = re.compile(r"\(\s*LINE\s*/([^)]*)\)", re.IGNORECASE)


def _numbers(text: str, where: Any, what: str) -> list[float]:
    try:
        return [float(item) for item in text.split(",") if item.strip()]
    except ValueError:
        raise InputError(
            f"GOFWD: the {what} takes numbers, found {text.strip()!r}", where
        ) from None


def circle_move(ctx: Any) -> None:
    """The body of a macro on ``GOFWD/$P1*``: the CIRCLE and the GOTO it stands for."""
    record = ctx.record
    text = record.text or ""
    circle, line = _CIRCLE.search(text), _LINE.search(text)
    if circle is None or line is None:
        raise NotYetSupported(
            f"GOFWD/{text[:30]} (only CIRCLE ... LINE in XY is read)", record.where
        )
    values = _numbers(circle.group(1), record.where, "CIRCLE")
    ends = _numbers(line.group(1), record.where, "LINE")
    if len(values) not in (4, 7) or len(ends) != 6:
        raise InputError("GOFWD: CIRCLE takes 4 (or 7) values and LINE 6", record.where)
    xc, yc, zc, radius = (*values[:3], values[-1])
    tangent = ctx.globals.get("indirv")
    if tangent is None:
        raise InputError(
            "GOFWD along a circle needs INDIRV (its start direction) first", record.where
        )
    x, y, _ = ctx.globals.get("position", (xc + radius, yc, zc))
    turn = (x - xc) * tangent[1] - (y - yc) * tangent[0]
    if abs(turn) < 1e-9:
        raise InputError("GOFWD: INDIRV points along the radius, so the arc has no sense",
                         record.where)  # fmt: skip
    axis = 1.0 if turn > 0 else -1.0  # counterclockwise about +Z, else clockwise
    ctx.cmd("CIRCLE", xc, yc, zc, 0.0, 0.0, axis, radius)
    ctx.goto(*ends[3:6])


def indirv(ctx: Any) -> None:
    """The body of a macro on ``INDIRV/$P1,$P2,$P3``: the next circle's start tangent."""
    ctx.globals["indirv"] = (ctx.p[1], ctx.p[2], ctx.p[3])
