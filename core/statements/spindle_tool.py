"""SPINDL, TOOLNO/LOADTL and ROTATE, through their elements (core/spindle.py,
core/tool.py, core/motion/rotary.py)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol, runtime_checkable

from gecent.core.cl.records import Statement
from gecent.core.errors import NotYetSupported
from gecent.core.statements.feed import feed_per_revolution

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post
    from gecent.core.motion.multiaxis import MultiaxisMotion


def spindl(run: Post, statement: Statement) -> None:
    run.spindle.statement(statement)
    if run.state.feed.per_revolution:
        feed_per_revolution(run, statement)


def tool(run: Post, statement: Statement) -> None:
    run.tool.statement(statement)


def turret(run: Post, statement: Statement) -> None:
    run.tool.turret(statement)


def rotate(run: Post, statement: Statement) -> None:
    """ROTATE/TABLE|HEAD: an incremental rotary system on a contouring machine (ROTABI;
    on a multiaxis machine core/motion/multiaxis_rotate.py); absolute systems belong to
    positioning machines (ROTABA)."""
    if run.machine.number_option(1) != 0:
        raise NotYetSupported("ROTATE on a positioning machine (ROTABA)", statement.where)
    if run.machine.multiaxis:
        # ROTABI's multiaxis branch (manual §3.4.7.2): the transform class's rotary axis
        # turns, and the part frame with it or not (ROTREF, option 198)
        from gecent.core.motion.multiaxis_rotate import rotate as rotate_multiaxis

        if not isinstance(run, _Multiaxis):
            raise NotYetSupported("ROTATE on a multiaxis machine in this context", statement.where)
        rotate_multiaxis(run.multiaxis, statement)
        return
    run.rotary.statement(statement)


@runtime_checkable
class _Multiaxis(Protocol):
    """A run with a multiaxis element (core/run.py's)."""

    @property
    def multiaxis(self) -> MultiaxisMotion: ...


HANDLERS = {
    "SPINDL": spindl,
    "TOOLNO": tool,
    "LOADTL": tool,
    "TURRET": turret,
    "ROTATE": rotate,
}
