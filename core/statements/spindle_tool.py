"""SPINDL, TOOLNO/LOADTL and ROTATE, through their elements (core/spindle.py,
core/tool.py, core/motion/rotary.py)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol, runtime_checkable

from gecent.core.cl.records import Statement, Word
from gecent.core.motion.rotary_absolute import AbsoluteRotary, rotary_feed
from gecent.core.motion.rotary_devices import (
    INDEXER_WORDS,
    MAGAZINE_WORDS,
    rotate_indexer,
    rotate_magazine,
)
from gecent.core.motion.rotary_turret import (
    index_drafting_turret,
    turn_spindle_turret,
    turret_routine,
)
from gecent.core.plugins import PluginSet, get_plugins
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
    """ROTATE/TABLE|HEAD: an incremental rotary system on a contouring machine (ROTABI;
    on a multiaxis machine core/motion/multiaxis_rotate.py), the absolute system of a
    positioning machine (ROTABA); ROTATE/INDEXER and ROTATE/MAGAZINE turn devices by M
    codes (core/motion/rotary_devices.py)."""
    device = next((a.name for a in statement.args if isinstance(a, Word)), "")
    if device in INDEXER_WORDS:
        rotate_indexer(statement, run.machine, run.output)
        return
    if device in MAGAZINE_WORDS:
        run.tool.position = rotate_magazine(statement, run.machine, run.output, run.tool.position)
        return
    if device == "TURRET" and turret_routine(run.machine) == "ROTDRF":
        index_drafting_turret(statement, run.machine, run.output, run.state.pen_down, run.warn)
        return
    if device == "TURRET" and turret_routine(run.machine) == "ROTUR":
        turn_spindle_turret(statement, run.tool)
        return
    if run.machine.number_option(1) != 0:
        _rotate_absolute(run, statement)
        return
    if run.machine.multiaxis:
        # ROTABI's multiaxis branch (manual §3.4.7.2): the transform class's rotary axis
        # turns, and the part frame with it or not (ROTREF, option 198)
        from gecent.core.motion.multiaxis_rotate import rotate as rotate_multiaxis

        rotate_multiaxis(run.multiaxis, statement)
        return
    run.rotary.statement(statement)


def _rotate_absolute(run: Post, statement: Statement) -> None:
    """ROTABA: the positioning machine's absolute table (core/motion/rotary_absolute.py),
    made on first use with the table's own feed type (options 139, 141). Its moves count
    in the run's cutting time; a control cycle in force is cancelled by the table block's
    TABLEG(1), so the next hole states its cycle again."""
    rotary = run.rotary
    if rotary.absolute_system is None:
        plugins = run.plugins if isinstance(run, _WithPlugins) else None
        family = plugins or get_plugins()
        feed = rotary_feed(run.machine, lambda number: family.get("rotaryfeeds", number))
        rotary.absolute_system = AbsoluteRotary(
            run.state, run.output.output, run.output.store_m, run.warn, feed, rotary.positions
        )
    element = rotary.absolute_system
    before = element.cut_minutes
    element.statement(statement)
    run.output.cut_minutes += element.cut_minutes - before
    if run.cycle is not None:
        run.positioning.cycle_block = None


@runtime_checkable
class _WithPlugins(Protocol):
    """A run that knows its plugin set (core/run.py's)."""

    plugins: PluginSet | None


HANDLERS = {
    "SPINDL": spindl,
    "TOOLNO": tool,
    "LOADTL": tool,
    "TURRET": turret,
    "ROTATE": rotate,
}
