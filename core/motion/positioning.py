"""Motion on a positioning machine (option 1 = 1 or 2; overlay GEPOS): POSMOV and the
control's own canned cycles, CYCLGP (manual §2.4.1, 001 L1043-1178; flow chart 9,
001 L19849-19935; POSMOV 001 L34934-34992; CYCLGP 001 L30095-30204; RAPIDP L35274-35313).

Everything a positioning machine outputs is absolute:

* each CL point plus TRANS (Z first moved by option 140, and by the tool length under
  option 86 < 0) is rounded to whole steps and
  output as a position, not a departure;
* CODE +16 carries X and Y; Z follows option 130: 0 ignored, +1 a CODE -16 block of its own
  after the XY block, -1 in the XY block; a coordinate that did not change is not output,
  and under option 40 a repeated X or Y is left out of a block that moves the other;
* with no cycle in force the block gets the cycle-off G code TABLEG(1); under a cycle, the
  cycle's G code (TABLEG 82-88), so each XY position runs the control's cycle;
* the F command is made at output by the positioning feed type (POSFED, option 78);
* SET12 gives a move with no cycle the G code of the positioning mode POSITN set (MODPOS,
  001 L34913, L34952-34955): FINE TABLEG(52), NOBACK 53, COARSE 54, CORMIL 61 or 62 by the
  feed range, TRAV (MODPOS < 0) 58, or 63 in IPR mode; with no mode, TABLEG(1) (POSMOV's
  step 7). The manual does not describe SET12: docs/decisions.md ("Statement forms").

A cycle is set up by one CODE -16 block: the cycle's G code, Z = the plunge and R = the
distance at rapid, both measured down from the tool's height (CURNTZ). CL files give each
hole's top and the cycle's DEPTH and CLEAR from it, so the block is made at the first hole
and made again whenever a hole's top moves the plunge or the rapid distance. Without an R
register (REGFOR(16) = 0) RAPIDP simulates it: the R distance is a rapid Z move in a block
of its own, and the cycle block's Z is the rest of the plunge. A cycle whose G code the
control lacks is simulated the same way, whole: positioning moves across, down at rapid to
R, at feed to the bottom and back (docs/decisions.md, "Options 80, 222 and positioning
cycles"), with the expansion's dwell blocks and spindle M codes on the way: TAP out with the
spindle reversed, DRAG and MANUAL with the spindle (and program) stopped at the bottom
(TABLEG 85, 91-95, 001 L22875-22977; core/motion/cycles.py).

Under the machine's cycle macros (spec 09 §5.6) each hole the control drills goes through
:attr:`PositioningMotion.hole_event` (core/macros/events.py), which may skip it, drill it by
moves or move its R plane and bottom (:meth:`PositioningMotion.hole`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

from gecent.core.absent import ABSENT, Absent
from gecent.core.cl.records import Motion, MotionSubtype
from gecent.core.errors import Diagnostic, InputError, SourcePosition
from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.cycles import CYCLE_TYPES, Cycle, cycle_legs
from gecent.core.motion.guard import check_segments
from gecent.core.motion.linear import godlta_point
from gecent.core.motion.rounding import to_steps
from gecent.core.output.block import Block, Code
from gecent.core.state import PostState

# a hole under the cycle macros: (record, point, cycle, this element)
HoleEvent = Callable[[Motion, tuple[float, ...], Cycle, "PositioningMotion"], None]
NEGATIVE_Z = "Z IS BELOW ZERO AFTER THE OPTION 140 ADJUSTMENT"  # comment 66 (text lost)
X, Y, Z = 0, 1, 2
# SET12: MODPOS -> TABLEG location (chart L22710-22714, L22805-22854; decisions.md)
MODE_G = {1: 52, 2: 53, 3: 54}  # FINE (backlash takeup), NOBACK (none), COARSE
CORNER_MILLING_G = {1: 61, 2: 62}  # CORMIL, by the feed range IFDRNG
TRAVERSE_G, TRAVERSE_IPR_G = 58, 63  # TRAV: traverse to feed without a stop, IPM or IPR
MODE_NAMES = {1: "FINE", 2: "NOBACK", 3: "COARSE", 4: "CORMIL"}


def mode_g_location(state: PostState) -> int | None:
    """SET12's TABLEG location for the positioning mode in force (MODPOS); None for
    POSITN/OFF (or none given), where a move takes the cycle-off code TABLEG(1)."""
    mode = state.modes.positioning
    if mode == 0:
        return None
    if mode < 0:
        return TRAVERSE_IPR_G if state.feed.per_revolution else TRAVERSE_G
    if mode == 4:
        return CORNER_MILLING_G[2 if state.feed.range == 2 else 1]
    return MODE_G[mode]


def set12(state: PostState, where: SourcePosition | None = None) -> float | None:
    """SET12 (001 L34952-34955, L5612-5614): the positioning mode's G code, or None when
    no mode is in force. A machine without the mode's code is bad input naming it."""
    location = mode_g_location(state)
    if location is None:
        return None
    code = state.machine.g_code(location)
    if code is None:
        mode = state.modes.positioning
        name = "TRAV" if mode < 0 else MODE_NAMES[mode]
        raise InputError(
            f"POSITN/{name}: machine {state.machine.label} has no positioning-mode code "
            f"TABLEG({location}) (POSITN needs TABLEG 52-62)",
            where,
        )
    return code


def refuse_cycle_by_moves(
    machine: MachineDefinition, cycle: Cycle, where: SourcePosition | None
) -> None:
    """CYCLE on a positioning machine whose control lacks the cycle's G code (TABLEG
    82-90), or a hole a cycle macro has made by moves ($P1 = -1): the hole is drilled by
    positioning moves, which needs Z on tape (option 130 = +1 or -1)."""
    cell = CYCLE_TYPES[cycle.kind][1]
    if machine.number_option(130) == 0:
        lacking = (
            f"without its G code TABLEG({cell})"
            if machine.g_code(cell) is None
            else "by moves (a cycle macro's $P1 = -1)"
        )
        raise InputError(
            f"CYCLE/{cycle.kind} on a positioning machine {lacking}: machine "
            f"{machine.label} puts no Z on tape (option 130 = 0), so the hole cannot be "
            "drilled by moves",
            where,
        )


class PositioningMotion:
    """POSMOV for a single-head positioning machine."""

    def __init__(
        self,
        state: PostState,
        emit: Callable[[Block], None],
        warn: Callable[[Diagnostic], None],
        rapid_motion: Callable[[float], None],
        store_m: Callable[[float], None],
        dwell: Callable[[float], Block],
    ) -> None:
        machine = state.machine
        self.state = state
        self.emit = emit
        self.warn = warn
        self.rapid_motion = rapid_motion
        self.store_m = store_m  # STOREM: a cycle's M code waits for its move (TAP, DRAG)
        self.dwell = dwell  # a dwell block (CODE +4) at a hole's bottom
        # the cycle macros' hook around each hole the control drills (core/macros/events.py)
        self.hole_event: HoleEvent | None = None
        self.switched: dict[int, bool] | None = None  # a cycle macro's F switch for a hole
        self.step = machine.number_option(14)
        self.z_mode = machine.number_option(130)
        self.suppress_repeats = machine.number_option(40) == 1
        self.inversion = machine.number_option(140)  # 0: no adjustment
        # option 86 < 0: POSMOV adjusts Z by the tool length TOOLEN (001 L34956-34961)
        self.length_adjusted = machine.number_option(86) < 0
        cycle_off = machine.g_code(1)
        self.cycle_off: float | Absent = ABSENT if cycle_off is None else float(cycle_off)
        self.has_r_register = machine.registers.formats[16] is not None
        # what the control holds: the last X and Y output, and the last cycle block
        self.held: list[int | None] = [None, None, None]
        self.cycle_block: tuple[float, int, int] | None = None
        # a cycle the control lacks, drilled by moves: it and the level it started from
        self.expanding: Cycle | None = None
        self.first_z = 0.0
        # option 1 = 3: the present point is in this control's Z frame (core/motion/mixed.py)
        self.in_own_frame = False

    # -- records ---------------------------------------------------------------------------

    def record(self, record: Motion, cycle: Cycle | None) -> None:
        if record.subtype is MotionSubtype.FROM:
            self._from(record)
            return
        if cycle is None:
            self.cycle_block = None
        for point in self._points(record):
            if len(point) != 3:
                raise InputError(
                    "a multiaxis (6-value) point on a 3-axis positioning machine", record.where
                )
            if cycle is None:
                self._move(record, point)
            elif self.state.machine.g_code(CYCLE_TYPES[cycle.kind][1]) is None:
                self.hole_by_moves(record, point, cycle)
            elif self.hole_event is not None:
                self.hole_event(record, point, cycle, self)
            else:
                self.hole(record, point, cycle)

    def _points(self, record: Motion) -> list[tuple[float, ...]]:
        if record.subtype is not MotionSubtype.GODLTA:
            return list(record.points)
        return [godlta_point(self.state.position, record)]

    def _machine_point(self, point: tuple[float, ...]) -> tuple[list[float], list[int]]:
        tx, ty, tz = self.state.position.translation
        part = [point[X] + tx, point[Y] + ty, point[Z] + tz]
        z_shift = self._z_shift()
        if z_shift:
            part[Z] += z_shift  # "DATACL = DATACL - OPTAB(140)" (001 L19870-19876)
            if self.inversion and part[Z] < 0:
                self.warn(Diagnostic(NEGATIVE_Z, None))
        return part, [to_steps(value, self.step) for value in part]

    def _z_shift(self) -> float:
        """Z's adjustment: less option 140's inversion; with option 86 < 0 plus the tool
        length, the spindle nose standing that far above the tip (001 L25406-25434)."""
        length = self.state.tool.length if self.length_adjusted else None
        return -self.inversion + (length or 0.0)

    def _from(self, record: Motion) -> None:
        position = self.state.position
        part, steps = self._machine_point(record.points[0])
        block = Block(Code.FROM, record.number)
        for axis in range(3):
            block.cells[3 + axis] = steps[axis] * self.step
        block.position = tuple(steps)
        self._arrive(part, steps)
        position.from_given = True
        self.emit(block)

    def _arrive(self, part: list[float], steps: list[int]) -> None:
        position = self.state.position
        position.present_part[:3] = part
        position.present[:3] = steps
        position.previous_part[:] = position.present_part
        position.previous[:] = position.present

    # -- POSMOV ----------------------------------------------------------------------------

    def _move(
        self,
        record: Motion,
        point: tuple[float, ...],
        g_code: float | Absent = ABSENT,
        hole: bool = False,
    ) -> None:
        """One positioning move, as option 130 splits it. A hole at the present XY still
        gets its block, with X and Y again: the control runs its cycle on a block."""
        part, steps = self._machine_point(point)
        previous = self.state.position.previous
        moved = [steps[a] != previous[a] for a in range(3)]
        if hole and not (moved[X] or moved[Y]):
            self.held[X] = self.held[Y] = None
            moved[X] = moved[Y] = True
        self._rapid_test([steps[a] - previous[a] for a in range(3)])
        if g_code is ABSENT:
            g_code = self._set12(record)
        if self.z_mode < 0:
            if any(moved):
                self._block(record, Code.POSITION_XY, steps, (X, Y, Z), g_code)
        else:
            if moved[X] or moved[Y]:
                self._block(record, Code.POSITION_XY, steps, (X, Y), g_code)
            if self.z_mode > 0 and moved[Z]:
                self._block(record, Code.POSITION_Z, steps, (Z,), g_code)
        self._arrive(part, steps)

    def _set12(self, record: Motion) -> float | Absent:
        """The G of a positioning block with no cycle G: the positioning mode's (SET12),
        else the cycle-off code TABLEG(1)."""
        code = set12(self.state, record.where)
        return self.cycle_off if code is None else code

    def _block(
        self,
        record: Motion,
        code: Code,
        target: list[int],
        axes: tuple[int, ...],
        g_code: float | Absent,
    ) -> None:
        previous = list(self.state.position.previous[:3])
        reached = list(previous)
        block = Block(code, record.number)
        for axis in axes:
            reached[axis] = target[axis]
            repeated = self.held[axis] == target[axis]
            if axis != Z and repeated and self.suppress_repeats:
                continue  # POSIT, option 40 (001 L34842-34846)
            if axis == Z and repeated:
                continue
            block.cells[3 + axis] = target[axis] * self.step
            self.held[axis] = target[axis]
        block.cells[2] = g_code
        block.position = tuple(reached)
        block.steps = tuple(reached[a] - previous[a] for a in range(3))
        block.rapid = bool(self.state.feed.rapid_ipm)
        block.switched, self.switched = self.switched, None  # a macro's F switch, once
        self.state.position.previous[:3] = reached
        self.emit(block)

    def _rapid_test(self, departures: list[int]) -> None:
        """TSTFLG: RAPIDO or RAPIDX once per CL point, over the whole move."""
        feed = self.state.feed
        if feed.rapid_requested or feed.rapid_mode:
            self.rapid_motion(sum((d * self.step) ** 2 for d in departures) ** 0.5)

    # -- CYCLGP ----------------------------------------------------------------------------

    def levels(self, point: tuple[float, ...], cycle: Cycle) -> tuple[float, float, float]:
        """A hole's R plane, bottom and the tool's height (the level the control returns
        to), in the machine frame the cycle block is measured in (TRANS, option 140 and
        option 86's tool length applied)."""
        tz = self.state.position.translation[Z]
        top = point[Z] + tz + self._z_shift()
        height = self.state.position.previous_part[Z]
        return top + cycle.clearance - cycle.rapto, top - cycle.depth, height

    def restates(self, point: tuple[float, ...], cycle: Cycle) -> bool:
        """The hole's cycle block goes out again (first hole, or a changed plunge or R)."""
        rapid_level, bottom, height = self.levels(point, cycle)
        plunge = to_steps(height - bottom, self.step)
        rapid = to_steps(height - rapid_level, self.step)
        if not self.has_r_register and rapid > 0:  # RAPIDP's Z move, then the rest
            plunge, rapid = plunge - rapid, 0
        return (self._cycle_g(cycle), plunge, rapid) != self.cycle_block

    def hole(
        self,
        record: Motion,
        point: tuple[float, ...],
        cycle: Cycle,
        levels: tuple[float, float] | None = None,
        switches: dict[str, bool] | None = None,
    ) -> None:
        """One hole under the control's cycle: the cycle block when the plunge or the rapid
        distance changes, then the XY position that runs it. The tool stays at its height.
        ``levels`` (R plane, bottom; machine frame) replace the cycle's (a cycle macro's
        $P11 and $P13). ``switches`` (a cycle macro's, spec 09 §5.6; core/macros/
        cycle_switches.py): ``activate``, ``depth`` or ``clearance`` True state the cycle
        block again, its G (activate), Z or R forced; ``depth`` or ``clearance`` False leave
        Z or R out of it (the next hole states it again); ``feed`` True forces the F of the
        hole's first block, False leaves F out of its blocks."""
        switches = switches or {}
        if any(switches.get(name) for name in ("activate", "depth", "clearance")):
            self.cycle_block = None
        rapid_level, bottom, height = self.levels(point, cycle)
        if levels is not None:
            rapid_level, bottom = levels
        plunge = to_steps(height - bottom, self.step) * self.step
        rapid_distance = to_steps(height - rapid_level, self.step) * self.step
        if plunge <= 0 or rapid_distance < 0 or rapid_distance > plunge:
            raise InputError(
                f"CYCLE/{cycle.kind}: the tool at Z {height:g} is not above the hole's "
                f"clearance level {rapid_level:g} and bottom {bottom:g}",
                record.where,
            )
        g_code = self._cycle_g(cycle)
        if not self.has_r_register and rapid_distance > 0:
            # RAPIDP: R as a rapid Z move in a block of its own; the cycle plunges the rest
            self.state.feed.rapid_requested = True
            tx, ty, tz = self.state.position.translation
            at = self.state.position.previous_part
            lowered = (at[X] - tx, at[Y] - ty, at[Z] - rapid_distance - tz - self._z_shift())
            part, steps = self._machine_point(lowered)
            previous = self.state.position.previous
            self._rapid_test([steps[a] - previous[a] for a in range(3)])
            self._block(record, Code.POSITION_Z, steps, (Z,), self._set12(record))
            self._arrive(part, steps)
            height, plunge, rapid_distance = part[Z], plunge - rapid_distance, 0.0
        wanted = (g_code, to_steps(plunge, self.step), to_steps(rapid_distance, self.step))
        switched = {
            cell: switches[name]
            for cell, name in ((2, "activate"), (11, "feed"), (5, "depth"), (16, "clearance"))
            if name in switches
        }
        if wanted != self.cycle_block:
            self.cycle_block = wanted
            if False in (switches.get("depth"), switches.get("clearance")):
                self.cycle_block = None  # the control keeps an old level: stated next time
            block = Block(Code.POSITION_Z, record.number)
            block.cells[2] = g_code
            block.cells[5] = wanted[1] * self.step
            if self.has_r_register:
                block.cells[16] = wanted[2] * self.step
            block.position = tuple(self.state.position.previous[:3])
            block.steps = (0, 0, 0)
            block.switched = switched or None
            self.emit(block)
            if switched.get(11):
                del switched[11]  # F forced once, in the hole's first block
        # F left out of each block of the hole (POSFED would put it in the next)
        self.switched = {11: switched[11]} if 11 in switched else None
        tz = self.state.position.translation[Z]
        self._move(record, (point[X], point[Y], height - tz - self._z_shift()), g_code, hole=True)
        self.switched = None

    def _cycle_g(self, cycle: Cycle) -> float:
        cell = CYCLE_TYPES[cycle.kind][1]
        code = self.state.machine.g_code(cell)
        assert code is not None  # (record() drills a cycle the control lacks by moves)
        return float(code)

    def hole_by_moves(self, record: Motion, point: tuple[float, ...], cycle: Cycle) -> None:
        """A hole whose cycle the control lacks (no TABLEG 82-90 code): drilled by
        positioning moves, as RAPIDP makes the rapid distance a control has no R register
        for (001 L30164-30182, L35274-35313) and as a contouring machine's cycle is
        expanded (core/motion/cycles.py): across at the tool's height, rapid down to R, feed
        to the bottom (DEEP in pecks), out to the return level; each block takes the
        positioning mode's G or TABLEG(1). A dwell is a dwell block (CODE +4) where the
        expansion puts it; an M code (TAP's reversal, DRAG's and MANUAL's stops, the
        spindle again) waits for the next block as STOREM makes it (001 L38041-38087), a
        code the machine lacks having been named at the CYCLE statement (comment 22).
        CYCLE refuses this where option 130 = 0 (no Z on tape)."""
        position = self.state.position
        tx, ty, tz = position.translation
        shift = self._z_shift()
        previous = position.previous_part
        at = (previous[X] - tx, previous[Y] - ty, previous[Z] - tz - shift)
        if cycle is not self.expanding:
            self.expanding, self.first_z = cycle, at[Z]
        self.cycle_block = None  # the cycle-off G of these moves cancels a control cycle
        if cycle.kind == "DEEP" and cycle.step:
            pecks = int(min(abs(cycle.depth / cycle.step), 1e18))
            check_segments(pecks, self.state.max_segments, record.where, "deep-hole cycle")
        hole = (point[X], point[Y], point[Z])
        feed = self.state.feed
        machine = self.state.machine
        # the spindle turned again after TAP, DRAG or MANUAL: as it turns at this hole
        turning = replace(cycle, restart_cell=5 if self.state.spindle.direction < 0 else 4)
        for leg in cycle_legs(turning, at, hole, self.first_z):
            if leg.dwell:
                block = self.dwell(leg.dwell)
                block.record = record.number
                self.emit(block)
            code = None if leg.m_code_cell is None else machine.m_code(leg.m_code_cell)
            if code is not None:
                self.store_m(code)
            feed.rapid_requested = leg.rapid
            self._move(record, leg.point)
        feed.rapid_requested = False
