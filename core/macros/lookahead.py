"""Look-ahead by snapshot (spec 09 §7, §13.4).

A look-ahead copies the run (outputs excluded: the copy writes to no file, reports nothing
and keeps no blocks), gives the copy's engine a search (core/macros/searches.py) and feeds
it the records after the one being processed, peeked from the stream without consuming
them. The copy's hooks tell the search what happens; the search ends the look-ahead with
its result. At the end of the file the copy runs FINI and its machine shutdown macro (§7.6:
a macro can force the result there, X2). Nothing of the copy survives but the result (and
the variables a ``$FLOOK`` keeps): the real run goes on from where it was.

Python frames cannot be resumed, so the copy starts after the current record, as if the
current macro and the rest of the record's processing had ended (§7.3 step 4); what they
would still issue is not searched, and ``$FLOOK`` and ``$FINFO`` return their end value
at once instead of 0 first (docs/decisions.md). An error in a later record ends the search
with its FINI result: the real run meets the error in its turn.
"""

from __future__ import annotations

import copy
from collections.abc import Iterator
from typing import Any

from gecent.core.cl.records import MotionSubtype, Record
from gecent.core.errors import GecentError
from gecent.core.macros.context import LookaheadFlags
from gecent.core.macros.host import MacroHost
from gecent.core.macros.model import Found, Kind, MacroFailure
from gecent.core.macros.operations import OperationSink
from gecent.core.macros.searches import Search
from gecent.core.output.sinks import Sinks

LOOKAHEAD_LIMIT = 1_000_000  # records a search reads at most (they are held while it runs)


def snapshot(run: MacroHost) -> MacroHost:
    """A copy of the run sharing what never changes (machine, plugins, macro table, the
    record stream) and writing nowhere."""
    engine = run.macros
    assert engine is not None
    memo: dict[int, Any] = {
        id(run.sinks): Sinks([]),
        id(run.result.blocks): [],
        id(run.result.diagnostics): [],  # (the copy's warnings go nowhere)
        id(run.plugins): run.plugins,
        id(run.machine): run.machine,
        id(engine.table): engine.table,
        id(engine.records): engine.records,
        id(run.report): None,
    }
    for value in engine.globals.values():  # a file a macro keeps open is shared, not copied
        try:
            copy.deepcopy(value, {})
        except Exception:  # (deepcopy of an open file, a module, a lock... fails)
            memo[id(value)] = value
    clone = copy.deepcopy(run, memo)
    clone.report = _silent
    clone._fast = None  # type: ignore[attr-defined]
    return clone


def _silent(diagnostic: Any) -> None:
    return None


def _counted(engine: Any, records: Iterator[Record]) -> Iterator[Record]:
    """The records a snapshot reads, counted: a look-ahead started inside it goes on from
    its place in the stream, not the real run's."""
    for record in records:
        engine.offset += 1
        yield record


def look_ahead(run: MacroHost, search: Search, start: int = 0) -> tuple[Any, Any]:
    """Run a copy of the run forward with ``search``: its result, and the copy's engine
    (for the variables a ``$FLOOK`` keeps). ``start`` skips, uninterpreted, the records
    before that CL record number (``$FINFO``'s start, §7.8)."""
    engine = run.macros
    assert engine is not None and engine.records is not None
    clone = snapshot(run)
    look = clone.macros
    assert look is not None
    look.search = search
    look.looking = search.kind
    look.flags = LookaheadFlags(
        active=True, tool=search.kind == "tool", motion=search.kind == "motion",
        finfo=search.kind == "finfo", oe=search.kind == "oe",
    )  # fmt: skip
    if search.context:
        look.flook_stack = (*engine.flook_stack, search.context)
    operations = getattr(search, "operations", None)
    if operations is not None:  # the span's extents and times ($INFO.TLMAX, ...)
        clone.sinks.add(OperationSink(operations, clone.state))
    look.frames = []
    look._running = set()
    if search.kind == "tool":
        look._running.add(Kind.MOTION)  # a tool search runs no motion macros (§7.4)
    # a tool search may send GOTOs by the fast path unless a user macro could see them;
    # every other search must see every motion
    fast = search.kind == "tool" and not engine.table.covers((5000, int(MotionSubtype.GOTO)))
    clone.use_fast_path = fast and clone.fast_allowed  # type: ignore[attr-defined]
    look.offset = engine.offset
    records = _counted(look, engine.records.ahead(LOOKAHEAD_LIMIT, engine.offset))
    if start:
        records = (r for r in records if r.number >= start)
    try:
        clone.feed(records, fast, look.dispatch)
        clone.end_of_input()
    except Found as found:
        return found.value, look
    except MacroFailure:
        raise  # a macro's own error, even one only a look-ahead runs into, is reported
    except GecentError:
        pass  # bad input further on: the real run meets it in its turn
    return search.fini(clone), look
