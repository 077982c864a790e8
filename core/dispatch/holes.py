"""A motion record's points under CYCLE, the canned cycle in force (CYCFLG, ICYTYP; manual
§3.4, the cycle routines CYCLEL, CYCLGP and CYCLGX, 001 L30038-30246): each point is a hole,
drilled by the control's own cycle (core/motion/control_cycles.py), by rapid and feed moves
(core/motion/cycles.py), or on a multiaxis machine along its tool axis (CYCLGX,
core/motion/multiaxis_cycles.py). Mixed into the run (core/run.py)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from typing import TYPE_CHECKING

from gecent.core.cl.records import Motion, MotionSubtype
from gecent.core.errors import Diagnostic
from gecent.core.feed.rapid import RapidTraverse
from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.circle import CircularMotion
from gecent.core.motion.control_cycles import ControlCycles
from gecent.core.motion.cycles import Cycle, cycle_legs
from gecent.core.motion.guard import check_segments
from gecent.core.motion.linear import LinearMotion, godlta_delta, path_length
from gecent.core.output.element import OutputElement
from gecent.core.state import PostState

if TYPE_CHECKING:
    from gecent.core.macros.engine import MacroEngine
    from gecent.core.motion.multiaxis import MultiaxisMotion


class CycleHoles:
    """Mixed into the run: what it needs of it is declared here."""

    state: PostState
    warn: Callable[[Diagnostic], None]
    cycle: Cycle | None
    cycle_first_z: float | None
    control_cycles: ControlCycles | None
    macros: MacroEngine | None
    machine: MachineDefinition
    output: OutputElement
    rapid: RapidTraverse
    circle: CircularMotion
    motion: LinearMotion
    multiaxis: MultiaxisMotion

    def _multiaxis_holes(self, record: Motion) -> None:
        """CYCLGX: each point a hole drilled along its tool axis, through the transform
        (core/motion/multiaxis_cycles.py)."""
        from gecent.core.motion.multiaxis_cycles import MultiaxisHoles

        assert self.cycle is not None
        holes = MultiaxisHoles(self.state, self.output, self.rapid, self.multiaxis)
        self.cycle_first_z = holes.record(record, self.cycle, self.cycle_first_z)

    def _cycle_points(self, record: Motion) -> None:
        """Each point of a record under CYCLE is a hole: its moves go through the rapid and
        linear elements as ordinary one-point records with the record's number."""
        assert self.cycle is not None
        position = self.state.position
        tx, ty, tz = position.translation
        for point in record.points:
            previous = position.previous_part
            at = (previous[0] - tx, previous[1] - ty, previous[2] - tz)
            if record.subtype is MotionSubtype.GODLTA:
                delta = godlta_delta(point)
                hole = (at[0] + delta[0], at[1] + delta[1], at[2] + delta[2])
            else:
                hole = (point[0], point[1], point[2])
            if self.cycle_first_z is None:
                self.cycle_first_z = at[2]
            control = self.control_cycles
            turned = None if control is None else control.turned(self.cycle)
            if control is not None and turned is not None:
                # a left-hand tap since the CYCLE statement: G80, then the tap by moves
                if control.first_turn(self.cycle):
                    self.warn(Diagnostic(f"CYCLE/TAP IS DRILLED BY MOVES: {turned}", record.where))
                control.off(record.number)
                self.simulated_hole(record, at, hole)
                continue
            if self.control_cycles is not None:
                self.circle.select_plane(0, record.number)  # the control drills along Z
                feed = self.state.feed
                feed.rapid_requested = False  # the control positions at rapid itself
                if feed.rapid_mode:
                    self.rapid.leave()
                if self.macros is not None:
                    self.macros.hooks.cycle(record, at, hole, self.cycle_first_z)
                else:
                    self.control_cycles.hole(self.cycle, record.number, hole, self.cycle_first_z)
                continue
            self.simulated_hole(record, at, hole)

    def simulated_hole(
        self,
        record: Motion,
        at: tuple[float, float, float],
        hole: tuple[float, float, float],
    ) -> None:
        """A hole by rapid and feed moves (core/motion/cycles.py); the spindle turned again
        after TAP, DRAG or MANUAL is the spindle's direction at the hole."""
        assert self.cycle is not None and self.cycle_first_z is not None
        cycle = replace(self.cycle, restart_cell=5 if self.state.spindle.direction < 0 else 4)
        if cycle.kind == "DEEP" and cycle.step:
            pecks = int(min(abs(cycle.depth / cycle.step), 1e18))
            check_segments(pecks, self.state.max_segments, record.where, "deep-hole cycle")
        for leg in cycle_legs(cycle, at, hole, self.cycle_first_z):
            if leg.dwell:
                block = self.output.dwell(leg.dwell)
                block.record = record.number
                self.output.output(block)
            code = None if leg.m_code_cell is None else self.machine.m_code(leg.m_code_cell)
            if code is not None:
                self.output.store_m(code)
            self._leg(record, leg.point, leg.rapid)

    def _leg(self, record: Motion, point: tuple[float, float, float], rapid: bool) -> None:
        leg = Motion(record.file, record.line, record.number, MotionSubtype.GOTO, (point,))
        feed = self.state.feed
        if rapid:
            self.rapid.request()
        if feed.rapid_requested or feed.rapid_mode:
            self.rapid.motion(path_length(self.state.position, leg))
        self.motion.record(leg)
