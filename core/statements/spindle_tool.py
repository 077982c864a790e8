"""SPINDL, TOOLNO/LOADTL and ROTATE, through their elements (core/spindle.py,
core/tool.py, core/motion/rotary.py)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement
from gecent.core.errors import NotYetSupported
from gecent.core.statements.feed import feed_per_revolution

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post


def spindl(run: Post, statement: Statement) -> None:
    run.spindle.statement(statement)
    if run.state.feed.per_revolution:
        feed_per_revolution(run, statement)


def tool(run: Post, statement: Statement) -> None:
    run.tool.statement(statement)


def turret(run: Post, statement: Statement) -> None:
    run.tool.turret(statement)


def rotate(run: Post, statement: Statement) -> None:
    """ROTATE/TABLE|HEAD: an incremental rotary system on a contouring machine (ROTABI);
    absolute systems belong to positioning machines (ROTABA)."""
    if run.machine.number_option(1) != 0:
        raise NotYetSupported("ROTATE on a positioning machine (ROTABA)", statement.where)
    if run.machine.number_option(116) != 0:
        # the table's turn changes the part frame the transform class works in (ROTREF,
        # option 198, manual §3.4.7.2): posting it as a plain rotary block would leave the
        # next multiaxis point on a stale angle
        raise NotYetSupported(
            "ROTATE on a multiaxis machine (ROTREF and option 198, manual §3.4.7.2)",
            statement.where,
        )
    run.rotary.statement(statement)


HANDLERS = {
    "SPINDL": spindl,
    "TOOLNO": tool,
    "LOADTL": tool,
    "TURRET": turret,
    "ROTATE": rotate,
}
