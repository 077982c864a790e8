"""CYCLE and CYCLE/OFF on a contouring machine: the cycle is remembered and every later CL
point is drilled by the expansion of core/motion/cycles.py (docs/research/cycles.md). A
machine whose control has the cycle's own G code (TABLEG 82-88) would take the manual's
control-cycle path, which is not built yet."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement
from gecent.core.errors import NotYetSupported
from gecent.core.motion.cycles import CYCLE_TYPES, parse_cycle
from gecent.core.statements.feed import program_feed

if TYPE_CHECKING:
    from gecent.core.run import Run


def cycle(run: Run, statement: Statement) -> None:
    parsed = parse_cycle(statement, run.warn)
    feed = run.state.feed
    if feed.rapid_mode:
        run.rapid.leave()  # RAPIDX: a cycle ends rapid traverse (001 L30195-30197)
    feed.rapid_requested = False
    if parsed is None:
        run.cycle = None
        return
    machine = run.machine
    cell = CYCLE_TYPES[parsed.kind][1]
    if machine.number_option(1) != 0 or machine.g_code(cell) is not None:
        raise NotYetSupported(
            f"CYCLE/{parsed.kind} by the control's own cycle (TABLEG({cell}), option 1)",
            statement.where,
        )
    units = run.units
    run.cycle = replace(
        parsed,
        depth=units.length(parsed.depth),
        clearance=units.length(parsed.clearance),
        step=None if parsed.step is None else units.length(parsed.step),
        rapto=units.length(parsed.rapto),
        return_level=None if parsed.return_level is None else units.length(parsed.return_level),
    )
    run.cycle_first_z = None
    if parsed.feed is not None:
        value, unit = parsed.feed
        program_feed(run, units.per_minute(value, unit), unit, statement)


HANDLERS = {"CYCLE": cycle}
