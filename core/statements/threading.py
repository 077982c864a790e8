"""PITCH, THREAD and COUPLE: the three threading statements (manual §4.6, 001
L15648-16023; PITCH L34612-34686, THREAD L38323-38356, COUPLE L29897-29930), read in
docs/research/threading.md. The thread blocks themselves come from core/motion/thread.py.

* ``PITCH/p`` gives p threads per unit length: lead = 1/p. ``PITCH/p, INCR|DECR, pf[, s]``
  is a linearly variable lead from 1/p to 1/pf (INCR: the pitch increases, the lead
  decreases) over the screw length s, or over the thread path when s is not given.
* ``THREAD/TURN|FACE`` makes the next motion record a thread along X (TURN) or Y (FACE).
* ``COUPLE/ON|OFF`` couples the spindle encoder (TABLEM 51, 52) in a block of its own, or
  in the option-92 dwell block; a negative option 92, or a speed above option 175, first
  brings the spindle to the lowest speed of its range (on coupling only).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import Diagnostic, InputError
from gecent.core.output.block import Block, Code

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post

ENCODER_ON, ENCODER_OFF = 51, 52
NO_ENCODER = "COUPLE IS NOT AVAILABLE ON THIS MACHINE; STATEMENT DISREGARDED"
RAPID_THREAD = "RAPID AND THREAD CANNOT BE USED TOGETHER; THE THREAD IS CUT AT ITS LEAD"


def pitch(run: Post, statement: Statement) -> None:
    threading = run.state.threading
    args = statement.args
    where = statement.where
    words = [a.name for a in args if isinstance(a, Word)]
    numbers = statement.numbers()
    if not numbers or isinstance(args[0], Word) or numbers[0] <= 0:
        raise InputError("PITCH expects the threads per unit length, a number > 0", where)
    lead = run.units.length(1.0 / numbers[0])
    if not words:
        if len(numbers) != 1:
            raise InputError("PITCH/p takes one value; a variable lead needs INCR or DECR", where)
        threading.lead, threading.mode = lead, 0
        threading.final_lead = threading.length = None
        return
    if words not in (["INCR"], ["DECR"]) or not isinstance(args[1], Word):
        raise InputError("PITCH expects PITCH/p or PITCH/p, INCR|DECR, pf[, s]", where)
    if len(numbers) not in (2, 3) or any(n <= 0 for n in numbers):
        raise InputError(
            "PITCH/p, INCR|DECR needs the final pitch and, if given, the length, all > 0", where
        )
    final = numbers[1]
    increasing_pitch = words[0] == "INCR"
    if (final > numbers[0]) != increasing_pitch or final == numbers[0]:
        raise InputError(
            f"PITCH/{numbers[0]:g},{words[0]},{final:g}: the final pitch must be "
            f"{'above' if increasing_pitch else 'below'} the first",
            where,
        )
    threading.lead = lead
    threading.final_lead = run.units.length(1.0 / final)
    threading.mode = -1 if increasing_pitch else 1  # THMODE is the lead's way (L15941-15951)
    threading.length = run.units.length(numbers[2]) if len(numbers) == 3 else None


def thread(run: Post, statement: Statement) -> None:
    words = [a.name for a in statement.args if isinstance(a, Word)]
    if words not in (["TURN"], ["FACE"]) or len(statement.args) != 1:
        raise InputError("THREAD expects THREAD/TURN or THREAD/FACE", statement.where)
    threading = run.state.threading
    threading.armed = True
    threading.facing = words[0] == "FACE"


def couple(run: Post, statement: Statement) -> None:
    words = [a.name for a in statement.args if isinstance(a, Word)]
    if words not in (["ON"], ["OFF"]) or len(statement.args) != 1:
        raise InputError("COUPLE expects COUPLE/ON or COUPLE/OFF", statement.where)
    machine = run.machine
    coupling = words[0] == "ON"
    code = machine.m_code(ENCODER_ON if coupling else ENCODER_OFF)
    if code is None:
        run.warn(Diagnostic(NO_ENCODER, statement.where))
        return
    dwell = machine.number_option(92)
    spindle = run.state.spindle
    restore = None
    if coupling and spindle.on and spindle.speed is not None:
        lowest = _lowest_in_range(run)
        too_fast = spindle.speed > machine.number_option(175)
        if (dwell < 0 or too_fast) and lowest is not None and lowest < spindle.speed:
            restore = None if too_fast else spindle.speed
            run.spindle.change_speed(lowest, statement.where, statement.number, spindle.range)
    run.output.store_m(code)
    if dwell:
        block = run.output.dwell(abs(dwell))
        block.record = statement.number
        run.output.output(block)
    else:
        run.output.output(Block(Code.AUX_ONLY, statement.number))
    run.state.threading.coupled = coupling
    if restore is not None:
        run.spindle.change_speed(restore, statement.where, statement.number, spindle.range)


def _lowest_in_range(run: Post) -> float | None:
    """The lowest speed of the range the spindle turns in, as its spindle type says (types
    13, 15, 17 and 18 keep more than speeds in SRTAB)."""
    spindle_type = run.spindle.spindle_type
    number = run.state.spindle.range
    if spindle_type is None or not 1 <= number <= spindle_type.range_count(run.machine):
        return None
    return spindle_type.speed_limits(run.machine, number)[0]


HANDLERS = {
    "PITCH": pitch,
    "THREAD": thread,
    "COUPLE": couple,
}
