"""DELAY and OPSKIP (manual §4.10 and §4.11; DELAY 001 L30293-30346, OPSKIP L34233-34250,
L16375-16398), read in docs/research/dwell-times.md.

DELAY/t dwells t seconds; DELAY/n,REV dwells n spindle revolutions. DELAY/0 is a bare
block. A machine with no dwell G code (TABLEG(5)) and no F-register dwell uses its preset
timer, TABLEM(18), in a block by itself; the time is then the timer's. OPSKIP/ON gives
every following block the block-delete code, until OPSKIP/OFF.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement
from gecent.core.errors import Diagnostic, InputError
from gecent.core.output.block import Block, Code

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post

NO_SPEED = "DELAY TIME FOR REV NOT CORRECT SINCE NO SPEED IS GIVEN."
NO_PRESET = "REQUESTED MISCELLANEOUS FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE"
NO_SKIP = "OPSKIP NOT AVAILABLE ON THIS MACHINE (OPTION 30 = 0); STATEMENT IGNORED"


def delay(run: Post, statement: Statement) -> None:
    words = statement.words()
    numbers = statement.numbers()
    if len(numbers) != 1 or any(w != "REV" for w in words) or len(words) > 1:
        raise InputError("DELAY expects a time in seconds, or n,REV", statement.where)
    seconds = numbers[0]
    if seconds < 0:
        raise InputError(f"DELAY expects a time >= 0, found {seconds:g}", statement.where)
    if words:
        speed = run.state.spindle.speed
        if not speed:
            run.warn(Diagnostic(NO_SPEED, statement.where))  # the count is taken as seconds
        else:
            seconds = seconds * 60.0 / speed
    machine = run.machine
    output = run.output
    if seconds == 0:
        output.output(Block(Code.AUX_ONLY, statement.number))
        return
    if machine.g_code(5) is None and machine.number_option(57) != 11:
        preset = machine.m_code(18)
        if preset is None:
            run.warn(Diagnostic(NO_PRESET, statement.where))
            return
        output.store_m(preset)
        output.output(Block(Code.AUX_ONLY, statement.number))
        return
    block = output.dwell(seconds)
    block.record = statement.number
    output.output(block)


def opskip(run: Post, statement: Statement) -> None:
    words = statement.words()
    if words not in (("ON",), ("OFF",)) or len(statement.args) != 1:
        raise InputError("OPSKIP expects ON or OFF", statement.where)
    if run.machine.number_option(30) != 1:
        run.warn(Diagnostic(NO_SKIP, statement.where))
        return
    run.state.skipping = words[0] == "ON"


HANDLERS = {"DELAY": delay, "OPSKIP": opskip}
