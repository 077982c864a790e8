"""The Mark Century 7500's mixed control, option 1 = 3: "machine has both positioning
(absolute) and contouring (incremental) capability" (manual §5.6.5, option 1, 001
L24352-24356; option 132 = 8, "positioning machine with contouring option (7500 series)",
L25958). The manual names the control but never says which motion goes out which way;
gecent's reading (docs/decisions.md, "issue 22 wave 8"):

* a motion at rapid traverse (RAPID, or a modal rapid in force) and every hole of a canned
  cycle go out as the positioning control makes them (GEPOS's POSMOV and CYCLGP,
  core/motion/positioning.py): absolute X, Y, Z by option 130, the cycle-off or cycle G
  code, the positioning feed type of option 78 and option 45's rapid command;
* a motion at feed goes out as the contouring control makes it (GETERP: GOLINE, GOCIRC,
  threading, SFM, core/run.py's contouring path): incremental departures, the
  interpolation G codes and the contouring feedrate command of option 10;
* FROM and the present point are one: both paths keep the same step-grid point (the
  position state), so each departure after a positioning move counts from the position
  it reached, and each position after contouring is where the departures led;
* the block's G code tells the control which way it reads the block (a positioning or
  cycle G against an interpolation G), so a control switching ways is never left in the
  other's G: the G word is output whenever it changes, as every G is.

Option 140's Z inversion and option 86 < 0's tool length move the positioning control's
Z frame only (enter_way): the departures are increments of the same slide.

The positioning control's held words (option 40's repeated X and Y, the cycle block's Z
and R) mean nothing once contouring has moved the slides, so they are forgotten then.
"""

from __future__ import annotations

from gecent.core.cl.records import Motion, MotionSubtype
from gecent.core.feed.rapid import MODAL
from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.positioning import PositioningMotion
from gecent.core.motion.rounding import to_steps
from gecent.core.state import PostState

MIXED_CONTROL = 3.0  # option 1
Z = 2


def is_mixed(machine: MachineDefinition) -> bool:
    return machine.number_option(1) == MIXED_CONTROL


def enter_way(state: PostState, positioning: PositioningMotion, way: bool) -> None:
    """The present point put in the Z frame of the way the next move goes (``way`` True:
    the positioning control's). Its Z is the contouring control's (the CL point plus
    TRANS, as every departure counts) or the positioning control's, moved by option 140's
    inversion and, with option 86 < 0, by the tool length (POSMOV, 001 L19870-19876,
    L34956-34961, L26049-26062, L25406-25434).

    The 7500 has one Z slide: a departure is an increment of it and carries no frame, so
    the shift belongs to the absolute positions only. When the control switches ways, the
    present point is re-expressed in the other way's frame by the shift in force then:
    the positioning way's Z is the tip plus the shift (the spindle nose above the tip, the
    inversion's datum), the contouring way's the tip of the tool now in the spindle, so
    a tool changed under positioning leaves the next departure counted from that tool's
    tip (docs/decisions.md, issue 22 wave 9)."""
    if way == positioning.in_own_frame:
        return
    positioning.in_own_frame = way
    shift = positioning_z_shift(state)
    if shift:
        _move_frame(state, shift if way else -shift)


def positioning_z_shift(state: PostState) -> float:
    """POSMOV's Z adjustment (as core/motion/positioning.py makes it): less option 140's
    inversion, plus the tool length under option 86 < 0."""
    machine = state.machine
    length = state.tool.length if machine.number_option(86) < 0 else None
    return -machine.number_option(140) + (length or 0.0)


def _move_frame(state: PostState, shift: float) -> None:
    """The present and previous point, part and steps, moved along Z by ``shift``; the
    steps by the grid's own rounding of the new Z, so the positions stay on the grid."""
    step = state.machine.number_option(14)
    position = state.position
    for part, steps in (
        (position.present_part, position.present),
        (position.previous_part, position.previous),
    ):
        moved = part[Z] + shift
        steps[Z] += to_steps(moved, step) - to_steps(part[Z], step)
        part[Z] = moved


def goes_positioning(state: PostState, record: Motion, cycle_in_force: bool) -> bool:
    """True when the record goes out by the positioning control: a hole under a canned
    cycle, or a move at rapid traverse (a thread is cut at feed by the contouring way,
    which warns of the rapid). FROM is the contouring way's (no block moves)."""
    if record.subtype is MotionSubtype.FROM:
        return False
    if cycle_in_force:
        return True
    if state.threading.armed:
        return False
    feed = state.feed
    return feed.rapid_requested or feed.rapid_mode == MODAL


def contouring_moved(positioning: PositioningMotion | None) -> None:
    """Contouring moves the slides: the positioning control's held X, Y, Z and its cycle
    block are no longer what the control has."""
    if positioning is None:
        return
    positioning.held = [None, None, None]
    positioning.cycle_block = None
