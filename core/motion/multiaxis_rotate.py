"""ROTATE/TABLE and ROTATE/HEAD on a multiaxis machine: ROTABI's multiaxis branch (manual
§3.4.7.2, 001 L6544-6751; ROTABI L35939-36010; options 29 and 198, L24741-24760,
L26559-26563; spec 03 §14, W26, W27).

The rotated axis is one of the transform class's rotary axes: its machine angle changes by
the statement's increment (INCR, or ATANGL from the tracked angle; CLW turns the angle up
when option 117 says CLW increases the scale reading). What the part frame does then is
the decision table of option 198 and ROTREF:

* the part frame turns with the table (198 = 0 without ROTREF, 198 != 0 with it; the
  manual's Diagram 3.4.7.2B): the machine's slides stay, the rotary axis alone turns
  (a CODE -2 block per ROTMAX segment, ROTOUT), and the part point is refreshed by the
  class's inverse: the tool now has other direction cosines in the part;
* the frame is compensated (198 = 0 with ROTREF, 198 != 0 without it; Diagram 3.4.7.2C):
  the turned machine point is carried back to the part (MAFORK = 1), its tip reset to the
  part point before (DPREVP), and GOLINE makes the move: a CODE 0 multiaxis block, tested
  for linearity under LINTOL. A turn of 180 degrees or more is made in equal parts under
  180, so that no angle of the class is taken the shorter way back.

Option 29 = 0 does not keep the table's position: the turn is output but the multiaxis
state stays as it was (a later multiaxis move is not affected by it, L6733-6746); ATANGL
or ROTREF with option 29 = 0 is warned about and taken as option 29 = 1 (L6746-6751).
"""

from __future__ import annotations

from dataclasses import replace
from math import radians

import numpy as np
from gecent.core.cl.records import Motion, MotionSubtype, Statement, Word
from gecent.core.errors import Diagnostic, InputError
from gecent.core.motion.multiaxis import MultiaxisMotion
from gecent.core.motion.rotary import _parse, normalise, rotary_move
from gecent.core.motion.segments import segment_count, segment_place, segments
from gecent.core.output.block import Block, Code

UNTRACKED = "ROTREF AND ATANGL CANNOT BE USED"  # ROTABI's comment (001 L35991)
HALF_TURN = 180.0


def rotate(motion: MultiaxisMotion, statement: Statement) -> None:
    """ROTABL and ROTABI for one ROTATE statement on a multiaxis machine."""
    state = motion.state
    machine = state.machine
    words = [a.name for a in statement.args if isinstance(a, Word)]
    rotref = "ROTREF" in words
    plain = replace(
        statement,
        args=tuple(a for a in statement.args if not (isinstance(a, Word) and a.name == "ROTREF")),
    )
    cell, absolute, value, direction = _parse(plain)  # (ROTATE/TABLE|HEAD, INCR|ATANGL, ...)
    index = _axis(motion, cell, statement)
    tracked = machine.number_option(29) != 0
    if not tracked and (absolute or rotref):
        motion.warn(Diagnostic(UNTRACKED, statement.where))
        tracked = True  # "proceeds as if the option = 1" (001 L24754-24757)
    if motion.modern_absolute:
        # an angle word under G90 (option 251 = 1) is where the table is: an untracked
        # index would be turned back by the next move's angle (docs/decisions.md, issue 22 wave 9)
        tracked = True
    clw_increases = machine.number_option(117) >= 0
    move = rotary_move(
        normalise(motion.angles[index]),
        value,
        absolute=absolute,
        direction=direction,
        clw_increases=clw_increases,
    )
    turn = move.travel if clw_increases else -move.travel  # on the class's angle, degrees
    if turn == 0.0:
        return
    if not tracked:
        _index_only(motion, statement, index, turn)
        return
    compensate = rotref if machine.number_option(198) == 0 else not rotref
    if compensate:
        _compensated(motion, statement, index, turn)
    else:
        _with_the_part(motion, statement, index, turn)


def _axis(motion: MultiaxisMotion, cell: int, statement: Statement) -> int:
    """The class's rotary axis the device names: DBFSEG(6) the head, (7) the table, by
    convention (001 L1793-1796); a class with one rotary axis turns it for either."""
    cells = motion.cells
    if cell in cells:
        return cells.index(cell)
    if len(cells) == 1:
        return 0
    device = "TABLE" if cell == 7 else "HEAD"
    transform = motion.transform
    raise InputError(
        f"ROTATE/{device}: {transform.name} (option 116 = {transform.number}) drives no "
        f"rotary {device.lower()} (register {cell})",
        statement.where,
    )


def _rotary_blocks(
    motion: MultiaxisMotion, statement: Statement, index: int, departure: int
) -> None:
    """ROTOUT: the rotary departure (rotary steps) as CODE -2 blocks, segmented equally
    under ROTMAX (option 111); under absolute output, moves of the rotary axis alone."""
    cell = motion.cells[index]
    count = segment_count([departure], [motion.rotmax])
    pieces = [piece[0] for piece in segments([departure], count)]
    if motion.modern_absolute:
        _absolute_turn(motion, statement, index, pieces)
        return
    for number, steps in enumerate(pieces):
        block = Block(Code.ROTARY_INCREMENTAL, statement.number)
        block.cells[cell] = steps * motion.rotary_step
        block.rotary = (cell, abs(steps * motion.rotary_step) / motion.per_degree)
        block.segment = segment_place(number, count)
        motion.emit(block)


def _absolute_turn(
    motion: MultiaxisMotion, statement: Statement, index: int, pieces: list[int]
) -> None:
    """The turn on a control of absolute words (option 251 = 1): each ROTMAX piece a feed
    move of the rotary axis alone to the angle it reaches (the slides stated only where
    the control is not at them yet), timed as GOLINE times a turn of the tool alone (the
    arc at option 112 or 128, G93 on a five-axis machine by data)."""
    position = motion.state.position
    angles = list(motion.rotary_previous)
    count = len(pieces)
    for number, steps in enumerate(pieces):
        angles[index] += steps
        turns = [0] * len(angles)
        turns[index] = steps
        block = Block.motion(
            Code.LINEAR, statement.number, (0, 0, 0), tuple(position.previous[:3]), motion.step
        )
        block.cells[motion.cells[index]] = steps * motion.rotary_step
        block.angles = tuple(angles)
        block.inverse_time = motion.chain is not None
        block.feed_length = motion._turn_length(turns, [0, 0, 0])
        block.segment = segment_place(number, count)
        motion.emit(block)


def _steps(motion: MultiaxisMotion, degrees: float) -> int:
    return round(degrees * motion.per_degree / motion.rotary_step)


def _index_only(motion: MultiaxisMotion, statement: Statement, index: int, turn: float) -> None:
    """Option 29 = 0: the table is indexed; its position is not remembered."""
    angle = motion.angles[index]
    _rotary_blocks(motion, statement, index, _steps(motion, angle + turn) - _steps(motion, angle))


def _turned(motion: MultiaxisMotion, index: int, angle: float) -> np.ndarray:
    """The machine point with the rotary axis at ``angle`` (degrees), the rest as it is."""
    point = np.array(motion.machine_raw, dtype=float)
    point[motion.columns[index]] = radians(angle)
    return point


def _with_the_part(motion: MultiaxisMotion, statement: Statement, index: int, turn: float) -> None:
    """The part frame turns with the table: the rotary move alone, then DPRESP from the
    inverse of the turned machine point (the tool's place and axis in the turned part)."""
    position = motion.state.position
    angle = motion.angles[index] + turn
    new = _steps(motion, angle)
    _rotary_blocks(motion, statement, index, new - motion.rotary_previous[index])
    motion.angles[index] = angle
    rotary = list(motion.rotary_previous)
    rotary[index] = new
    motion.rotary_previous = rotary
    point = _turned(motion, index, angle)
    motion.machine_raw = point
    motion.machine_previous = point.reshape(1, 6)  # a singular axis keeps the turned angle
    if not position.from_given:
        return  # no tool position yet: only the angle is kept
    part = motion.transform.inverse(point.reshape(1, 6), motion.kinematics)[0]
    refreshed = [float(value) for value in part]
    position.present_part[:] = refreshed
    position.previous_part[:] = refreshed
    motion.tool_axis = (refreshed[3], refreshed[4], refreshed[5])


def _compensated(motion: MultiaxisMotion, statement: Statement, index: int, turn: float) -> None:
    """ROTABI with the frame compensated (001 L6635-6707): DPRESM's rotary cell turned,
    DPRESP from the inverse (MAFORK = 1), its xyz reset to DPREVP's, then GOLINE."""
    position = motion.state.position
    if not position.from_given:
        raise InputError(
            "ROTATE with the part frame compensated (ROTREF, option 198) before any FROM: "
            "there is no tool position to keep",
            statement.where,
        )
    parts = int(abs(turn) / HALF_TURN) + 1
    tx, ty, tz = position.translation
    for _ in range(parts):
        angle = motion.angles[index] + turn / parts
        point = _turned(motion, index, angle)
        part = motion.transform.inverse(point.reshape(1, 6), motion.kinematics)[0]
        previous = position.previous_part
        target = (
            previous[0] - tx,
            previous[1] - ty,
            previous[2] - tz,
            float(part[3]),
            float(part[4]),
            float(part[5]),
        )
        # the class's angle is taken from here the shorter way: the turn asked for; a
        # tool axis along the axis the angle turns about keeps the turned angle
        motion.angles[index] = angle
        motion.machine_previous = point.reshape(1, 6)
        record = Motion(
            statement.file, statement.line, statement.number, MotionSubtype.GOTO, (target,)
        )
        motion.goline(record, target, tested=True)
