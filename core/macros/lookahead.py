"""Variable look-ahead by snapshot (spec 09 §7.2-§7.6, §13.4).

A look-ahead copies the run (outputs excluded: the copy writes to no file, reports nothing
and keeps no blocks), puts the copy's engine in look-ahead mode and feeds it the records
after the one being processed, peeked from the stream without consuming them. The copy's
hooks end the search with :class:`Found` when the wanted record comes; at the end of the
file the copy runs FINI and its machine shutdown macro (§7.6: a macro can force the result
there, X2). Nothing of the copy survives: the real run goes on from where it was.

Python frames cannot be resumed, so the copy starts after the current record, as if the
current macro and the rest of the record's processing had ended (§7.3 step 4); what they
would still issue is not searched (docs/decisions.md). An error in a later record ends the
search empty-handed: the real run meets it in its turn.
"""

from __future__ import annotations

import copy
from typing import Any

from gecent.core.cl.records import Motion, MotionSubtype
from gecent.core.errors import GecentError
from gecent.core.macros.context import LookaheadFlags, NextMotion
from gecent.core.macros.host import MacroHost
from gecent.core.macros.model import Found, Kind
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
        id(run.plugins): run.plugins,
        id(run.machine): run.machine,
        id(engine.table): engine.table,
        id(engine.records): engine.records,
        id(run.report): None,
    }
    clone = copy.deepcopy(run, memo)
    clone.report = _silent
    clone._fast = None  # type: ignore[attr-defined]
    return clone


def _silent(diagnostic: Any) -> None:
    return None


def look_ahead(run: MacroHost, kind: str) -> Any:
    """The value the search for ``kind`` ("tool" or "motion") finds, or its default."""
    engine = run.macros
    assert engine is not None and engine.records is not None
    clone = snapshot(run)
    look = clone.macros
    assert look is not None
    look.looking = kind
    look.flags = LookaheadFlags(active=True, tool=kind == "tool", motion=kind == "motion")
    look.frames = []
    look._running = set()
    if kind == "tool":
        look._running.add(Kind.MOTION)  # a tool search runs no motion macros (§7.4)
    # a tool search runs no motion macros: GOTOs may take the fast path, unless a user
    # macro could make a tool change of one; a motion search must see every motion
    fast = kind == "tool" and not engine.table.covers((5000, int(MotionSubtype.GOTO)))
    clone.use_fast_path = fast and clone.fast_allowed  # type: ignore[attr-defined]
    try:
        clone.feed(engine.records.ahead(LOOKAHEAD_LIMIT), fast)
        clone.end_of_input()
    except Found as found:
        return found.value
    except GecentError:
        pass
    if kind == "motion":
        return current_motion(run)
    return None


def next_motion(run: MacroHost, record: Motion) -> NextMotion:
    """Where a motion record ends (its last point), machine and CL values (§7.2)."""
    position = run.state.position
    translation = position.translation
    last = record.points[-1]
    if record.subtype is MotionSubtype.GODLTA:
        delta = last if len(last) == 3 else (0.0, 0.0, last[0])
        machine = tuple(position.previous_part[a] + delta[a] for a in range(3))
    else:
        machine = tuple(last[a] + translation[a] for a in range(3))
    cl = tuple(machine[a] - translation[a] for a in range(3))
    return NextMotion(machine[0], machine[1], machine[2], cl[0], cl[1], cl[2], record.number)


def current_motion(run: MacroHost) -> NextMotion:
    """§7.3: no next motion: the current position."""
    position = run.state.position
    machine = tuple(position.present_part[a] for a in range(3))
    cl = tuple(machine[a] - position.translation[a] for a in range(3))
    return NextMotion(machine[0], machine[1], machine[2], cl[0], cl[1], cl[2], None)
