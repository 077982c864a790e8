"""CYCLE, CYCLE/OFF and CYCLE/INHIBT. On a contouring machine the cycle is remembered and
every later CL point is drilled by the expansion of core/motion/cycles.py
(docs/research/cycles.md), along the machine's spindle axis. On a positioning machine
(option 1 = 1, 2) the control runs the cycle: core/motion/positioning.py (CYCLGP); on a
modern contouring control with absolute dimensions (gecent option 251 = 1) too:
core/motion/control_cycles.py (G81-G89). On a lathe (option 132 = 0) whose control has the
cycle's G code, CYCLEL puts that G code in a block by itself and the points that follow are
ordinary moves for the control's cycle (001 L30038-30093).

On a multiaxis machine (CYCLGX, 001 L30206-30246) the hole is drilled by moves along the
tool axis, each through the machine's transform (core/motion/multiaxis_cycles.py); a
control's cycle (G81-G89) drills along the machine's Z and is not used there. A form the
control's cycle cannot drill is drilled by moves (ControlCycles.unfit names why). CYCLE/IN on
a positioning machine is the withdrawal code TABLEG(90) in a block by itself, where the tool
stands; the points that follow are plain positioning moves."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement
from gecent.core.errors import Diagnostic, InputError
from gecent.core.motion.cycles import (
    CYCLE_TYPES,
    PROGRAM_STOP,
    SPINDLE_CCLW,
    SPINDLE_CLW,
    SPINDLE_OFF,
    Cycle,
    in_machine_units,
    parse_cycle,
    spindle_axis,
)
from gecent.core.motion.positioning import refuse_cycle_by_moves
from gecent.core.output.block import Block, Code
from gecent.core.output.element import NOT_AVAILABLE
from gecent.core.statements.feed import program_feed

# the control's own cycle block holds G, Z and R only (CYCLGP, 001 L30164-30178)
CONTROL_CYCLE_KEEPS = "CYCLE {} NOT OUTPUT: THE CONTROL'S OWN CYCLE DOES IT"
# CYCLEL's block holds the G code alone (001 L30049-30056)
LATHE_CYCLE_KEEPS = "CYCLE {} NOT OUTPUT: THE LATHE'S CYCLE G CODE GOES OUT BY ITSELF"
NO_DWELL_TIME = "CYCLE/{} NAMES NO DWELL TIME: IT DWELLS 0 SECONDS"
BY_MOVES = "CYCLE/{} IS DRILLED BY MOVES: {}"  # the control's cycle cannot (unfit)
LATHE = 0  # option 132, the machine type

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post


def cycle(run: Post, statement: Statement) -> None:
    machine = run.machine
    positioning = machine.number_option(1) != 0
    lathe = not positioning and machine.number_option(132) == LATHE
    parsed = parse_cycle(statement, run.warn, needs_depth=not lathe)
    feed = run.state.feed
    if feed.rapid_mode:
        run.rapid.leave()  # RAPIDX: a cycle ends rapid traverse (001 L30195-30197)
    feed.rapid_requested = False
    if positioning:
        run.output.milling = parsed is not None and parsed.kind == "MILL"
    if parsed is None:
        if lathe:
            run.control_cycle_element().off(statement.number)  # the lathe's cycle G ends
        run.cycle = None
        if run.control_cycles is not None:
            run.control_cycles.off(statement.number)
            run.control_cycles = None
        return
    cell = CYCLE_TYPES[parsed.kind][1]
    if lathe and machine.g_code(cell) is not None:
        _lathe_block(run, parsed, statement, float(machine.g_code(cell) or 0))
        return
    if lathe:
        run.control_cycle_element().off(statement.number)
    if not parsed.depth and parsed.kind != "IN":
        raise InputError(f"CYCLE/{parsed.kind} needs a depth", statement.where)
    by_moves = positioning and machine.g_code(cell) is None
    if by_moves:  # the control lacks the cycle: drilled by positioning moves
        refuse_cycle_by_moves(machine, parsed, statement.where)
    elif positioning:
        _unsent(run, parsed, statement, CONTROL_CYCLE_KEEPS)
    if positioning and parsed.kind == "IN" and not by_moves:
        _positioning_withdrawal(run, parsed, statement, float(machine.g_code(cell) or 0))
        return
    # a control that bores also makes BORE's forms: control_cycles names a missing cell
    bore_form = parsed.kind.startswith("BORE,") and machine.g_code(CYCLE_TYPES["BORE"][1])
    multiaxis = machine.multiaxis and not positioning
    # (with incremental dimensions, option 251 = 0 or 2, the control's block is G91's)
    control = (
        not positioning and not multiaxis and (machine.g_code(cell) is not None or bool(bore_form))
    )
    unfit = None
    if control:
        unfit = run.control_cycle_element().unfit(parsed, run.state.spindle.direction)
        control = unfit is None
    units = run.units
    run.cycle = in_machine_units(parsed, units.length)
    run.cycle_first_z = None
    if by_moves:
        _codes_on_the_way(run, run.cycle, statement)
    if not positioning and not control:
        run.cycle = _expanded(run, run.cycle, statement, multiaxis)
        if unfit is not None:
            run.warn(Diagnostic(BY_MOVES.format(parsed.kind, unfit), statement.where))
    if control:
        run.control_cycles = run.control_cycle_element()
    elif run.control_cycles is not None:  # a cycle the control lacks follows one it has
        run.control_cycles.off(statement.number)
        run.control_cycles = None
    if (by_moves or not positioning) and "DWELL" in parsed.kind and not parsed.dwell:
        run.warn(Diagnostic(NO_DWELL_TIME.format(parsed.kind), statement.where))
    _program_cycle_feed(run, parsed, statement)


def _expanded(run: Post, cycle: Cycle, statement: Statement, multiaxis: bool) -> Cycle:
    """The cycle gecent makes by moves: along the spindle axis (a multiaxis machine's tool
    axis), with the machine's spindle stop (and program stop) for DRAG and MANUAL."""
    machine = run.machine
    axis = 2 if multiaxis else spindle_axis(machine)  # (the tool axis's frame: its third)
    if axis is None:
        # the plunge would go out on no register: the tape would drill nothing
        raise InputError(
            f"CYCLE/{cycle.kind} on a machine that outputs no Z axis (option 59 = "
            f"{machine.number_option(59):.0f}): there is no spindle axis to drill along",
            statement.where,
        )
    _codes_on_the_way(run, cycle, statement)
    restart = 5 if run.state.spindle.direction < 0 else 4  # the spindle turns as it did
    if axis != 2 and not multiaxis:
        # the level the cycle starts from, along the spindle axis (Post takes CL z itself)
        position = run.state.position
        run.cycle_first_z = position.previous_part[axis] - position.translation[axis]
    return replace(cycle, axis=axis, restart_cell=restart)


def _codes_on_the_way(run: Post, cycle: Cycle, statement: Statement) -> None:
    """A cycle drilled by moves stores M codes on the way: TAP the reversed spindle and the
    spindle again, DRAG the spindle stop (TABLEM(6)), MANUAL the spindle and program stops
    (TABLEM 6, 1). A code the machine lacks is STOREM's comment 22, given here once for
    the statement, and the hole is drilled without it (001 L38041-38087; CLAMP does the
    same, 001 L29337-29358; docs/decisions.md, "Cycles: the last forms")."""
    machine = run.machine
    way_out = CYCLE_TYPES[cycle.kind][0]
    restart = SPINDLE_CCLW if run.state.spindle.direction < 0 else SPINDLE_CLW
    needed = {
        "tap": (SPINDLE_CLW + SPINDLE_CCLW - restart, restart),
        "drag": (SPINDLE_OFF, restart),
        "manual": (SPINDLE_OFF, PROGRAM_STOP, restart),
    }.get(way_out, ())
    if any(machine.m_code(cell) is None for cell in needed):
        run.warn(Diagnostic(NOT_AVAILABLE, statement.where))


def _positioning_withdrawal(run: Post, parsed: Cycle, statement: Statement, code: float) -> None:
    """CYCLE/IN on a positioning machine: the withdrawal code TABLEG(90) in a CODE -16 block
    by itself, made at the statement as CYCLGP makes its block (001 L30164-30182); a
    withdrawal has no plunge and no rapid distance, so no Z and no R. The control takes the
    spindle out where the tool stands; the points that follow are plain positioning moves
    (the expansion's IN too withdraws, then moves across)."""
    run.cycle = None
    position = run.state.position
    block = Block(Code.POSITION_Z, statement.number)
    block.cells[2] = code
    block.position = tuple(position.previous[:3])
    block.steps = (0, 0, 0)
    run.output.output(block)
    _program_cycle_feed(run, parsed, statement)


def _lathe_block(run: Post, parsed: Cycle, statement: Statement, code: float) -> None:
    """CYCLEL: the G code in a block by itself; the later points are plain moves."""
    if run.control_cycles is not None:
        run.control_cycles.off(statement.number)
        run.control_cycles = None
    run.cycle = None
    _unsent(run, parsed, statement, LATHE_CYCLE_KEEPS)
    run.control_cycle_element().lathe_block(code, statement.number)
    _program_cycle_feed(run, parsed, statement)


def _unsent(run: Post, parsed: Cycle, statement: Statement, text: str) -> None:
    """A warning naming what the control's block does not carry."""
    unsent = [
        name
        for name, given in (
            ("DEPTH", text is LATHE_CYCLE_KEEPS and parsed.depth > 0),
            ("CLEAR", text is LATHE_CYCLE_KEEPS and parsed.clearance > 0),
            ("STEP", parsed.step is not None),
            ("DWELL", parsed.dwell > 0),
            ("RETURN", parsed.return_level is not None),
        )
        if given
    ]
    if unsent:
        run.warn(Diagnostic(text.format(", ".join(unsent)), statement.where))


def _program_cycle_feed(run: Post, parsed: Cycle, statement: Statement) -> None:
    if parsed.feed is not None:
        value, unit = parsed.feed
        program_feed(run, run.units.per_minute(value, unit), unit, statement)


HANDLERS = {"CYCLE": cycle}
