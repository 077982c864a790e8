"""Where the event macros fire in the post (spec 09 §5), each with its $P.

The run installs these as its hooks only when a macro engine runs (a machine with macros):
without macros the post's path is untouched. Each hook is a bound method of
:class:`EventHooks`, or a statement handler taking the run (core/macros/statement_hooks.py),
so a snapshot of the run for a look-ahead carries hooks that act on the snapshot alone. The
register and tape macros' work is in core/macros/block_events.py.

=====================  ======================================================
kind                   fires around
=====================  ======================================================
tool change (first)    TOOLNO, LOADTL, TURRET (§5.4-5.5)
motion                 each FROM, GOTO, GODLTA; an arc's GOTO with $P1 = 1 (§5.7)
cycle                  each hole of a canned cycle the control runs (§5.6)
LCS                    TRANS, gecent's immediate LCS change (§5.8)
break                  BREAK (§5.3)
register               each register of a block (§5.10)
tape                   each punched block (§5.11)
diagnostic             each warning (§5.12)
operation event        OPTYPE, after its look-ahead (§5.9)
=====================  ======================================================
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from gecent.core.cl.records import Motion, MotionSubtype
from gecent.core.errors import Diagnostic
from gecent.core.families import HookPoint
from gecent.core.macros.block_events import register_event, tape_event
from gecent.core.macros.context import Frame
from gecent.core.macros.cycle_switches import cycle_switches, feed_alone
from gecent.core.macros.diagnostics import WARNING, comment_number, deliver
from gecent.core.macros.helix import NORMAL_AXIS, helical_changed
from gecent.core.macros.host import MacroHost
from gecent.core.macros.macfun import MacfunContext, handled
from gecent.core.macros.model import NOT_DONE, Kind, MacroError, MacroFailure, Phase
from gecent.core.macros.params import (
    CycleParams,
    DiagnosticParams,
    MotionParams,
)
from gecent.core.macros.searches import next_motion
from gecent.core.motion.positioning import refuse_cycle_by_moves
from gecent.core.output.block import Block

if TYPE_CHECKING:
    from gecent.core.macros.engine import MacroEngine
    from gecent.core.motion.cycles import Cycle
    from gecent.core.motion.positioning import PositioningMotion
    from gecent.core.output.element import OutputElement
    from gecent.core.output.words import Word as RegisterWord

_SUBCLASS = {MotionSubtype.FROM: 3.0, MotionSubtype.GODLTA: 5.0, MotionSubtype.GOTO: 5.0,
             MotionSubtype.CONTINUATION: 6.0}  # fmt: skip


class EventHooks:
    def __init__(self, engine: MacroEngine) -> None:
        self.engine = engine

    def output_element(self, output: OutputElement) -> None:
        """The tape and register macros sit in the output element's path."""
        table = self.engine.table
        if table.has(Kind.TAPE):
            output.emit = self.tape
        if table.has(Kind.REGISTER):
            output.register_hook = self.register
        if HookPoint.SLIDE_LIMITS in self.engine.macfuns:
            output.slide_limits.hook = self.slide_limits

    def positioning_element(self, positioning: PositioningMotion) -> None:
        """The cycle macros sit around each hole a positioning control drills (CYCLGP)."""
        if self.engine.table.has(Kind.CYCLE):
            positioning.hole_event = self.positioning_cycle

    def macfun(self, hook: HookPoint, **fields: Any) -> bool:
        """The machine's MACFUN at a hook point: True when it did the special sequence
        (RETURN = 1), so the caller skips the rest."""
        handler = self.engine.macfuns.get(hook)
        if handler is None:
            return False
        run = self.run
        fields.setdefault("record", run.current_record)
        fields.setdefault("data", self.engine.macfun_data)
        return handled(handler(MacfunContext(hook, run, **fields)))

    def has_macfun(self, hook: HookPoint) -> bool:
        """Whether the machine's MACFUN answers at ``hook``."""
        return hook in self.engine.macfuns

    def slide_limits(self, position: tuple[int, ...]) -> bool:
        """MCHCON 2: the machine tests its slide limits itself (TSTLIM's MACSRT call)."""
        step = self.run.machine.number_option(14)
        machine_point = tuple(p * step for p in position)
        return self.macfun(
            HookPoint.SLIDE_LIMITS, position=tuple(position), machine_point=machine_point
        )

    def fast_path_allowed(self) -> bool:
        """The fast path makes GOTO blocks itself: only when no macro would see them."""
        table = self.engine.table
        if any(table.has(kind) for kind in (Kind.MOTION, Kind.TAPE, Kind.REGISTER)):
            return False
        return not table.covers((5000, int(MotionSubtype.GOTO)))

    @property
    def run(self) -> MacroHost:
        return self.engine.run

    # -- motion (§5.7) -------------------------------------------------------------------

    def motion(self, record: Motion) -> None:
        engine = self.engine
        run = self.run
        if engine.search is not None:
            engine.search.motion(run, record)
        if (
            not engine.table.has(Kind.MOTION)
            or Kind.MOTION in engine._running  # a motion macro's own move (§4.2 rule 3)
            or not engine.enabled(Kind.MOTION)
        ):
            self._motion_builtin(record)
            return
        params = self._motion_params(record)
        circle = run._circle
        pending = circle.centre if params.subclass == 1.0 and circle is not None else None
        start = tuple(run.state.position.present_part[:3])
        if circle is not None and pending is not None:
            circle.centre = None  # the startup macro's own moves are not this arc

        def goes(p: Any) -> bool:
            subclass = p.subclass
            if subclass in (9.0, 10.0):
                raise MacroError("a motion's $P1 cannot become a spline (9) or a pattern (10)")
            if circle is not None and pending is not None:
                # the arc stays an arc unless suppressed, made simple, or moved away from
                # by the startup macro's own motions (§5.7)
                moved = tuple(run.state.position.present_part[:3]) != start
                circle.centre = pending if subclass == 1.0 and not moved else None
            return bool(subclass != 0)

        travel = params[19]

        def builtin() -> None:
            if 19 in params.changed and params.helical != travel:
                try:
                    helical_changed(self, record, params.helical, travel)
                except MacroError as error:
                    raise self._failure(Kind.MOTION, error, record) from None
                return
            self._motion_builtin(record)

        engine.event(Kind.MOTION, params, record, builtin, proceed=goes)

    def _failure(self, kind: Kind, error: MacroError, record: Any) -> MacroFailure:
        """A value a macro left that the post cannot take: the macro's error, named."""
        table = self.engine.table
        macro = table.event(kind, Phase.STARTUP) or table.event(kind, Phase.EVENT)
        name = macro.key if macro is not None else kind.value
        return MacroFailure(f"macro {name}: {error}", getattr(record, "where", None))

    def _motion_builtin(self, record: Motion) -> None:
        """The post's motion, after the MACFUN FROM test (MCHCON 8) or thread sequence
        (MCHCON 12) where the machine has them."""
        run = self.run
        cycle_own_move = Kind.CYCLE in self.engine._running
        if run.cycle is not None and record.subtype is not MotionSubtype.FROM and cycle_own_move:
            self._plain_move(record)  # a cycle macro's own move is no hole (§5.6)
            return
        macfuns = self.engine.macfuns
        if macfuns:
            hook = None
            if record.subtype is MotionSubtype.FROM:
                hook = HookPoint.FROM
            elif run.state.threading.armed:
                hook = HookPoint.THREAD
            if hook is not None and hook in macfuns:
                cl = tuple(float(v) for v in record.points[-1][:3])
                translation = run.state.position.translation
                machine_point = tuple(cl[a] + translation[a] for a in range(3))
                if self.macfun(hook, record=record, point=cl, machine_point=machine_point):
                    return
        run.motion_builtin(record)

    def _plain_move(self, record: Motion) -> None:
        run = self.run
        control = run.control_cycles
        if control is not None and control.active:
            control.off(record.number)  # G80 first: the control would drill at the point
        cycle, run.cycle = run.cycle, None
        try:
            run.motion_builtin(record)
        finally:
            run.cycle = cycle

    def _motion_params(self, record: Motion) -> MotionParams:
        run = self.run
        position = run.state.position
        translation = position.translation
        end = next_motion(run, record)  # where the move ends, CL and machine values
        cl = (end.xc, end.yc, end.zc)
        machine = (end.xm, end.ym, end.zm, 0.0, 0.0, 0.0)
        params = MotionParams()
        circle = run._circle
        arc = (
            circle is not None
            and circle.centre is not None
            and record.subtype is MotionSubtype.GOTO
        )
        params.set(1, 1.0 if arc else _SUBCLASS[record.subtype])
        params.set(2, (*cl, 0.0, 0.0, 1.0))
        params.set(3, machine)
        params.set(4, record.number)
        params.set(5, record.number)
        params.set(6, 0)
        if arc and circle is not None:
            centre = circle.exact_centre
            start = position.previous_part
            u, v = {0: (0, 1), 1: (2, 0), 2: (1, 2)}[circle.plane]
            moved = tuple(centre[a] + translation[a] for a in range(3))
            params.set(8, len(record.points))
            params.set(9, 1.0 if circle.axis_sense < 0 else 2.0)
            params.set(10, float(circle.plane + 1))
            params.set(11, params[2])
            params.set(12, machine)
            params.set(13, centre)
            params.set(14, moved)
            params.set(18, ((start[u] - moved[u]) ** 2 + (start[v] - moved[v]) ** 2) ** 0.5)
            # the helical component: the arc's travel along its axis (machine units)
            params.set(19, machine[NORMAL_AXIS[circle.plane]] - start[NORMAL_AXIS[circle.plane]])
            params.set(23, 0.0)
        return params

    # -- cycle (§5.6) ---------------------------------------------------------------------

    def cycle(
        self,
        record: Motion,
        at: tuple[float, float, float],
        hole: tuple[float, float, float],
        first_z: float,
    ) -> None:
        """A hole of a canned cycle the control runs: the cycle macros around its block.
        $P1 left 0 skips the hole; -1 makes it by moves (no shutdown macro then); $P11,
        $P13 and $P15 changed move the R plane, the bottom and the return level."""
        run = self.run
        cycle = run.cycle
        control = run.control_cycles
        assert cycle is not None and control is not None
        translation = run.state.position.translation
        plane, bottom, back = control.levels(cycle, hole, first_z)
        params = CycleParams()
        values: tuple[tuple[int, Any], ...] = (
            (1, 1.0), (2, hole), (3, (*(hole[a] + translation[a] for a in range(3)), 0.0, 0.0,
            0.0)), (4, cycle_type(cycle.kind, bool(cycle.dwell))), (5, not control.active), (6, 0),
            (8, True), (9, run.state.feed.ipm), (10, True), (11, plane), (12, True),
            (13, bottom), (14, True), (15, back), (16, 1 if cycle.step else 0),
            (17, (cycle.step,) if cycle.step else ()), (18, 0), (19, 3.0), (20, False),
        )  # fmt: skip
        for number, value in values:
            params.set(number, value)

        activating = bool(params.activating)

        def builtin() -> object:
            if params.control == -2:
                feed_alone(run, record, params)
                return NOT_DONE  # the cycle at the next OUTPUT, or none at the exit
            if params.control == -1:
                run.simulated_hole(record, at, hole)
                return None
            try:
                switches = cycle_switches(params, activating)
            except MacroError as error:
                raise self._failure(Kind.CYCLE, error, record) from None
            levels = (float(params.clearance), float(params.depth), float(params.retract))
            moved = params.changed & {11, 13, 15}
            control.hole(cycle, record.number, hole, first_z, levels if moved else None,
                         switches)  # fmt: skip
            return None

        self.engine.event(
            Kind.CYCLE, params, record, builtin, proceed=_cycle_goes, then=_cycle_output
        )

    def positioning_cycle(
        self,
        record: Motion,
        point: tuple[float, ...],
        cycle: Cycle,
        positioning: PositioningMotion,
    ) -> None:
        """A hole of a positioning control's cycle (CYCLGP, 001 L30095-30204): the cycle
        macros around its blocks, with the same $P as on a contouring control, in the
        machine frame the cycle block is measured in. $P1 left 0 skips the hole; -1 drills
        it by positioning moves; $P11 and $P13 changed move the R plane and the bottom
        (the block's R and Z); the output switches $P5, $P8, $P10, $P12 work on the cycle
        block and the hole's F as on a contouring control; $P1 = -2 is the feed alone. The
        control returns to the level the tool stands at ($P15): CYCLGP's block has no
        register for another, nor for $P14 to force (docs/decisions.md, "Cycles: the last
        forms")."""
        run = self.run
        translation = run.state.position.translation
        plane, bottom, height = positioning.levels(point, cycle)
        hole = (point[0], point[1], point[2])
        machine_point = (*(hole[a] + translation[a] for a in range(3)), 0.0, 0.0, 0.0)
        params = CycleParams()
        values: tuple[tuple[int, Any], ...] = (
            (1, 1.0), (2, hole), (3, machine_point), (4, cycle_type(cycle.kind,
            bool(cycle.dwell))), (5, positioning.restates(point, cycle)), (6, 0), (8, True),
            (9, run.state.feed.ipm), (10, True), (11, plane), (12, True), (13, bottom),
            (14, True), (15, height), (16, 0), (17, ()), (18, 0), (19, 3.0), (20, False),
        )  # fmt: skip
        for number, value in values:
            params.set(number, value)

        activating = bool(params.activating)

        def builtin() -> object:
            if params.control == -2:
                feed_alone(run, record, params)
                return NOT_DONE  # the cycle at the next OUTPUT, or none at the exit
            if params.control == -1:
                refuse_cycle_by_moves(run.machine, cycle, record.where)
                positioning.hole_by_moves(record, point, cycle)
                return None
            try:
                switches = cycle_switches(params, activating)
                if 15 in params.changed or switches.get("retract"):
                    raise MacroError(
                        "$P14/$P15 (retract plane) on a positioning machine: its control "
                        "returns to the level the tool stands at, and CYCLGP's block holds "
                        "G, Z and R only (001 L30164-30178)"
                    )
            except MacroError as error:
                raise self._failure(Kind.CYCLE, error, record) from None
            levels = (float(params.clearance), float(params.depth))
            moved = params.changed & {11, 13}
            positioning.hole(record, point, cycle, levels if moved else None, switches)
            return None

        self.engine.event(
            Kind.CYCLE, params, record, builtin, proceed=_cycle_goes, then=_cycle_output
        )

    # -- diagnostic, tape, register (§5.10-§5.12) ----------------------------------------

    def diagnostic(self, diagnostic: Diagnostic) -> None:
        """§5.12: the macro may drop, change or add diagnostics before they count."""
        engine = self.engine
        run = self.run
        count = engine._occurrences.get(diagnostic.text, 0) + 1
        engine._occurrences[diagnostic.text] = count
        params = DiagnosticParams()
        entry_number = comment_number(diagnostic.text)
        for number, value in ((1, 1.0), (2, entry_number), (3, WARNING), (4, count),
                              (5, diagnostic.text)):  # fmt: skip
            params.set(number, value)

        def emit(frame: Frame) -> None:
            deliver(run, params, entry_number, diagnostic.where)
            params.changed.clear()

        frame = engine.single(Kind.DIAGNOSTIC, params, run.current_record, emit)
        if frame is None:
            run.warn_builtin(diagnostic)
            return
        if params.flag != 0 and (frame.outputs == 0 or params.changed):
            try:
                deliver(run, params, entry_number, diagnostic.where)
            except MacroError as error:
                raise self._failure(Kind.DIAGNOSTIC, error, run.current_record) from None

    def tape(self, block: Block) -> None:
        """§5.11: each punched block goes through the tape macro (core/macros/block_events.py)."""
        tape_event(self.engine, self.run, block)

    def register(self, block: Block, words: list[RegisterWord]) -> list[RegisterWord]:
        """§5.10: each register of a block, before it is placed (core/macros/block_events.py)."""
        return register_event(self.engine, self.run, block, words)


def _cycle_goes(params: Any) -> bool:
    return bool(params.control != 0)


def _cycle_output(params: Any) -> bool:
    """The cycle shutdown macro follows a cycle block, not holes made by moves (§5.6)."""
    return bool(params.control in (1, 2))


# the cycle types of $P4 (§5.6) for gecent's cycle words, without and with a dwell
CYCLE_TYPES = {"DRILL": (1.0, 2.0), "FACE": (2.0, 2.0), "TAP": (3.0, 3.0), "BORE": (5.0, 6.0),
               "DEEP": (11.0, 11.0), "THRU": (13.0, 13.0), "MILL": (1.0, 2.0)}  # fmt: skip


def cycle_type(kind: str, dwell: bool) -> float:
    """$P4: DRILL 1 (with a dwell 2, as FACE), TAP 3, BORE 5 (6 with a dwell), DEEP 11,
    THRU 13; gecent's stand-ins (CSINK, REAM, BRKCHP) arrive as DRILL, BORE, DEEP."""
    plain, dwelling = CYCLE_TYPES.get(kind, (1.0, 2.0))
    return dwelling if dwell else plain
