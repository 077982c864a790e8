"""Canned cycles run by a modern control (G81-G89) on a contouring machine (the cycle's
TABLEG 82-95; docs/modern-controls.md), with absolute or incremental dimensions (gecent
option 251).

The manual's contouring machines had no cycles of their own, so CYCLE was expanded into
moves (core/motion/cycles.py); its positioning machines got one block with incremental Z
and R (CYCLGP). A Fanuc- or LinuxCNC-style control takes, for each hole (x, y, top):

    G99 (or G98)                   once, before the first hole: the return level
    G81 X x Y y Z bottom R plane F feed [P dwell] [Q peck]
    X x Y y                        the next holes, the cycle being modal
    G80                            at CYCLE/OFF

with the hole read as APT and CAM systems write it, exactly as the expansion reads it:
R = top + CLEAR - RAPTO, bottom = top - DEPTH. Without RETURN the tool goes back to R (G99);
RETURN,0 sends it back to the level the cycle started from (G98). Other RETURN levels have
no G code and stop the run. The DWELL goes in the option-57 register as for G04, the DEEP
step in Q (REGSTR 21). Z and R are output again whenever a hole changes them.

With incremental dimensions (option 251 = 0, the manual's departures, or 2, under G91) the
block is the one a G-code control reads in G91: X and Y the departures to the hole, R the
distance from the level the tool stands at to the R plane, Z the distance from the R plane
to the bottom, both signed; R depends on where the tool stands, so every hole states Z and
R (docs/decisions.md, "Cycles: the last forms").

The cycles that dwell are the ones whose TABLEG function dwells: FACE (G82, and DRILL with
a DWELL), BORE,DWELL (TABLEG 94, G89), BORE,DWELL,DRAG (93, LinuxCNC's G86 with P) and
BORE,DWELL,MANUAL (95, LinuxCNC's G88 with P) (001 L22877-22977). OUT and IN, a quill's
forward and back, have no G-code control counterpart.

What the control's cycle cannot drill (:func:`ControlCycles.unfit` names why: OUT and IN, a
RETURN level other than R or the start, a DWELL on a cycle whose G code takes no P, a form
whose G code the machine file leaves out, a left-hand tap, a missing R, Q or G98/G99) is
drilled by moves instead, as on a contouring machine whose control has no cycles
(core/motion/cycles.py), with a warning naming the reason. A tap whose spindle is turned
CCLW after the CYCLE statement is such a left-hand tap: :meth:`ControlCycles.turned` names
it at the hole, and the hole is drilled by moves (core/dispatch/holes.py).
"""

from __future__ import annotations

from collections.abc import Callable

from gecent.core.motion.cycles import CYCLE_TYPES, Cycle
from gecent.core.motion.rounding import to_steps
from gecent.core.output.block import Block, Code
from gecent.core.output.modern import RETURN_INITIAL, RETURN_R_PLANE
from gecent.core.state import PostState

PECK_REGISTER = 21  # Q
LEFT_HAND_TAP = "A LEFT-HAND TAP (SPINDLE CCLW) HAS NO TABLEG CODE"
R_REGISTER = 16


def dwells(kind: str) -> bool:
    """The control's cycle for ``kind`` dwells at the bottom, and its block takes P."""
    return kind == "FACE" or kind.startswith("BORE,DWELL")


def control_kind(cycle: Cycle) -> str:
    """The control's cycle that drills ``cycle``: a DRILL with a DWELL is FACE's G82."""
    return "FACE" if cycle.kind == "DRILL" and cycle.dwell else cycle.kind


class ControlCycles:
    def __init__(self, state: PostState, output: Callable[[Block], None]) -> None:
        machine = state.machine
        self.state = state
        self.output = output
        self.step = machine.number_option(14)
        self.machine = machine
        self.active = False  # a cycle block has been output since the last G80
        self.return_code: float | None = None
        self.words: tuple[float, float] | None = None  # the Z and R in force
        # option 251 = 0 or 2: incremental X, Y, R and Z (G91's reading)
        self.incremental = machine.number_option(251) != 1
        self.turn_warned: Cycle | None = None  # the cycle a left-hand tap was named for

    def unfit(self, cycle: Cycle, spindle_direction: int) -> str | None:
        """Why the control's own cycle cannot drill ``cycle``, or None when it can; the
        cycle is then drilled by moves (cycle.py). ``spindle_direction``: the spindle's at
        the CYCLE statement (-1 CCLW)."""
        machine = self.machine
        if cycle.kind in ("OUT", "IN"):
            return f"CYCLE/{cycle.kind} HAS NO G-CODE CONTROL CYCLE"
        if cycle.return_level not in (None, 0.0):
            return "THE CONTROL RETURNS TO R OR TO THE START LEVEL ONLY (G99, G98)"
        location = RETURN_R_PLANE if cycle.return_level is None else RETURN_INITIAL
        if machine.g_code(location) is None:
            return f"NO RETURN CODE TABLEG({location})"
        if machine.registers.formats[R_REGISTER] is None:
            return f"NO R REGISTER (REGFOR {R_REGISTER})"
        if cycle.kind == "DEEP" and machine.registers.formats[PECK_REGISTER] is None:
            return f"NO PECK REGISTER Q (REGFOR {PECK_REGISTER})"
        if cycle.dwell and not dwells(cycle.kind) and cycle.kind != "DRILL":
            # G82 and the BORE,DWELL forms dwell; G81 and G83-G85 take no P
            return f"THE CONTROL'S CYCLE FOR {cycle.kind} TAKES NO DWELL"
        cell = CYCLE_TYPES[control_kind(cycle)][1]
        if machine.g_code(cell) is None:
            # a control that bores (TABLEG 86) but whose file leaves out this form of it
            return f"NO G CODE TABLEG({cell}) FOR {control_kind(cycle)}"
        if cycle.kind == "TAP" and spindle_direction < 0:
            # G84 taps right-handed (M03): a left-hand tap is G74, which no TABLEG names
            return LEFT_HAND_TAP
        return None

    def turned(self, cycle: Cycle) -> str | None:
        """At a hole: why the control's cycle chosen at the CYCLE statement cannot drill
        it now, None when it can. Only the spindle can change in between: a TAP with the
        spindle turned CCLW since is a left-hand tap, which G84 cannot cut."""
        if cycle.kind != "TAP" or self.state.spindle.direction >= 0:
            return None
        return LEFT_HAND_TAP

    def first_turn(self, cycle: Cycle) -> bool:
        """True the first time :meth:`turned` refuses a hole of ``cycle`` (warn once)."""
        first = self.turn_warned is not cycle
        self.turn_warned = cycle
        return first

    def hole(
        self,
        cycle: Cycle,
        record: int,
        hole: tuple[float, float, float],
        first_z: float,
        levels: tuple[float, float, float] | None = None,
        switches: dict[str, bool] | None = None,
    ) -> None:
        """One hole: the cycle block; the tool ends at (x, y, the return level).
        ``levels`` (R plane, bottom, return level) replace the cycle's own (a cycle macro's
        $P11, $P13, $P15). A hole :meth:`turned` refuses is the caller's, by moves.
        ``switches`` (a cycle macro's, spec 09 §5.6) force (True) or leave out (False) the
        whole definition (``activate``, $P5), F (``feed``, $P8), R (``clearance``, $P10),
        Z (``depth``, $P12) and G98/G99 (``retract``, $P14)."""
        switches = switches or {}
        position = self.state.position
        tx, ty, _ = position.translation
        x, y = hole[0] + tx, hole[1] + ty
        plane, bottom, back = levels or self.levels(cycle, hole, first_z)
        machine = self.machine
        location = RETURN_R_PLANE if cycle.return_level is None else RETURN_INITIAL
        code = machine.g_code(location)
        assert code is not None  # unfit() made sure
        retract = switches.get("retract")
        if retract is not False and (code != self.return_code or retract):
            # G98/G99 is modal: output when it changes (or a cycle macro forces it)
            g_block = Block(Code.G_ONLY, record)
            g_block.cells[2] = code
            self.output(g_block)
            self.return_code = code
        reached = (to_steps(x, self.step), to_steps(y, self.step), to_steps(back, self.step))
        block = Block(Code.CYCLE, record)
        block.steps = tuple(reached[a] - position.previous[a] for a in range(3))
        block.position = reached
        if self.incremental:
            block.cells[3] = block.steps[0] * self.step
            block.cells[4] = block.steps[1] * self.step
        else:
            block.cells[3] = reached[0] * self.step
            block.cells[4] = reached[1] * self.step
        kind = control_kind(cycle)
        cycle_g = machine.g_code(CYCLE_TYPES[kind][1])
        assert cycle_g is not None
        block.cells[2] = cycle_g
        plane_steps, bottom_steps = to_steps(plane, self.step), to_steps(bottom, self.step)
        words = (bottom_steps * self.step, plane_steps * self.step)
        if self.incremental:  # Z from R, R from the tool's level: stated at every hole
            level = position.previous[2]
            words = ((bottom_steps - plane_steps) * self.step, (plane_steps - level) * self.step)
        restated = switches.get("activate") is True
        if words != self.words or not self.active or self.incremental or restated:
            block.cells[5], block.cells[R_REGISTER] = words
            if cycle.kind == "DEEP":
                # no STEP: one pass, and G83 still needs its Q (the whole depth)
                block.cells[PECK_REGISTER] = cycle.step or cycle.depth
            if dwells(kind):
                # P even when 0: LinuxCNC refuses G82, G86, G88 and G89 without one
                register = int(machine.number_option(57))
                block.cells[register] = (cycle.dwell or 0.0) / (machine.number_option(56) or 1.0)
        if switches.get("depth") or switches.get("clearance"):
            block.cells[5], block.cells[R_REGISTER] = words  # forced out, even when modal
        switched = {2: "activate", 11: "feed", R_REGISTER: "clearance", 5: "depth"}
        block.switched = {cell: switches[name] for cell, name in switched.items()
                          if name in switches}  # fmt: skip
        # a level left out stays the control's old one: the next hole states both again
        self.words = None if False in (switches.get("depth"), switches.get("clearance")) else words
        block.feed_length = 2 * (plane - bottom)  # down and (at most) back at feed
        block.dwell_minutes = cycle.dwell / 60.0 if cycle.dwell else 0.0
        self.active = True
        self.output(block)
        position.present_part[:3] = [x, y, back]
        position.present[:3] = list(reached)
        position.previous_part[:] = position.present_part
        position.previous[:] = position.present

    def levels(
        self, cycle: Cycle, hole: tuple[float, float, float], first_z: float
    ) -> tuple[float, float, float]:
        """The R plane, the bottom and the return level of a hole (machine units, with
        TRANS), as :meth:`hole` works them out."""
        tz = self.state.position.translation[2]
        top = hole[2] + tz
        plane = top + cycle.clearance - cycle.rapto
        back = plane if cycle.return_level is None else max(first_z + tz, plane)
        return plane, top - cycle.depth, back

    def lathe_block(self, code: float, record: int) -> None:
        """CYCLEL (001 L30038-30093): a lathe's cycle G code in a block by itself; the
        points that follow are the control's."""
        block = Block(Code.G_ONLY, record)
        block.cells[2] = code
        self.output(block)
        self.active = True

    def off(self, record: int) -> None:
        """CYCLE/OFF: G80 (TABLEG(1)) when a cycle block went out."""
        if not self.active:
            return
        self.active = False
        self.words = None
        code = self.machine.g_code(1)
        if code is not None:
            block = Block(Code.G_ONLY, record)
            block.cells[2] = code
            self.output(block)
