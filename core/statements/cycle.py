"""CYCLE and CYCLE/OFF. On a contouring machine the cycle is remembered and every later CL
point is drilled by the expansion of core/motion/cycles.py (docs/research/cycles.md); a
contouring machine whose control has the cycle's own G code (TABLEG 82-88) would take the
control-cycle path, which is not built for contouring controls yet. On a positioning
machine (option 1 = 1, 2) the control runs the cycle: core/motion/positioning.py (CYCLGP);
on a modern contouring control with absolute dimensions (gecent option 251 = 1) too:
core/motion/control_cycles.py (G81-G85)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement
from gecent.core.errors import Diagnostic, NotYetSupported
from gecent.core.motion.cycles import CYCLE_TYPES, in_machine_units, parse_cycle
from gecent.core.statements.feed import program_feed

# the control's own cycle block holds G, Z and R only (CYCLGP, 001 L30164-30178)
CONTROL_CYCLE_KEEPS = "CYCLE {} NOT OUTPUT: THE CONTROL'S OWN CYCLE DOES IT"

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post


def cycle(run: Post, statement: Statement) -> None:
    parsed = parse_cycle(statement, run.warn)
    feed = run.state.feed
    if feed.rapid_mode:
        run.rapid.leave()  # RAPIDX: a cycle ends rapid traverse (001 L30195-30197)
    feed.rapid_requested = False
    machine = run.machine
    positioning = machine.number_option(1) != 0
    if positioning:
        run.output.milling = parsed is not None and parsed.kind == "MILL"
    if parsed is None:
        run.cycle = None
        if run.control_cycles is not None:
            run.control_cycles.off(statement.number)
            run.control_cycles = None
        return
    cell = CYCLE_TYPES[parsed.kind][1]
    if positioning and machine.g_code(cell) is None:
        raise NotYetSupported(
            f"CYCLE/{parsed.kind} on a positioning machine without its G code TABLEG({cell})",
            statement.where,
        )
    if positioning:
        unsent = [
            name
            for name, given in (
                ("STEP", parsed.step is not None),
                ("DWELL", parsed.dwell > 0),
                ("RETURN", parsed.return_level is not None),
            )
            if given
        ]
        if unsent:
            run.warn(Diagnostic(CONTROL_CYCLE_KEEPS.format(", ".join(unsent)), statement.where))
    control = not positioning and machine.g_code(cell) is not None
    if control and machine.number_option(251) != 1:
        raise NotYetSupported(
            f"CYCLE/{parsed.kind} by the control's own cycle (TABLEG({cell})) with "
            "incremental dimensions (option 251 = 1 takes it in absolute ones)",
            statement.where,
        )
    units = run.units
    run.cycle = in_machine_units(parsed, units.length)
    run.cycle_first_z = None
    if control:
        element = run.control_cycle_element()
        element.check(run.cycle, statement.where)
        run.control_cycles = element
    elif run.control_cycles is not None:  # a cycle the control lacks follows one it has
        run.control_cycles.off(statement.number)
        run.control_cycles = None
    if parsed.feed is not None:
        value, unit = parsed.feed
        program_feed(run, units.per_minute(value, unit), unit, statement)


HANDLERS = {"CYCLE": cycle}
