"""Putting a macro engine into a run: the hooks of core/macros/events.py take the places
of the run's own handlers, only for what the machine's macros need."""

from __future__ import annotations

from typing import cast

from gecent.core.macros.engine import MacroEngine
from gecent.core.macros.events import EventHooks
from gecent.core.macros.host import MacroHost
from gecent.core.macros.model import Kind
from gecent.core.macros.operations import OperationSink
from gecent.core.macros.statement_hooks import STATEMENT_HOOKS
from gecent.core.macros.table import MacroTable
from gecent.core.statements import Handler

# statements only the macro layer gives a meaning (the post alone warns and disregards them)
NEW_STATEMENTS = frozenset({"OPTYPE", "OPNAME"})


def install_macros(run: MacroHost, table: MacroTable) -> MacroEngine:
    engine = MacroEngine(table, run)
    hooks = engine.hooks = EventHooks(engine)
    for major, hook in STATEMENT_HOOKS.items():
        if major in run._statements or major in NEW_STATEMENTS:
            run._statements[major] = cast(Handler, hook)  # it takes the run, a Post
    run.sinks.add(OperationSink(engine.operations, run.state))
    run._motion_record = hooks.motion  # motion macros, and the next-motion look-ahead
    if table.has(Kind.DIAGNOSTIC):
        run.warn = hooks.diagnostic  # type: ignore[method-assign]
    return engine
