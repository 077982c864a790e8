"""Automatic reinstatement of program conditions after STOP, OPSTOP and BREAK (manual
§4.7, 001 L16024-16143; RESTAT/ENTRAP L35498-35573, L30953-30990; option 145), read in
docs/research/statements-misc.md §5.

The statements that set a condition record it in the STATE vector. A stop sets STOPON;
under option 145 = -1 or -2 it also puts the machine in rapid gear (ENTRAP). At the next
motion RESTAT outputs, slot by slot, every condition that was on before the stop and was
not given again since: the tool, the spindle (S and its direction M), the feed or rapid
gear, the coolant. A condition given again after the stop was output when given; the
manual's negative-value mark for it is the ``respecified`` set here (decision: §4.7's
reading, "negative = already output, skip").

Option 136 = 1 (001 L25995-26007): the control itself turns spindle and coolant back to
their former conditions when the program restarts after the stop, so RESTAT leaves them out
(the tool and the feed or rapid gear still come back); a new SPINDL or COOLNT after the
stop is output when given, which is the manual's "takes precedence".
"""

from __future__ import annotations

from gecent.core.dispatch.context import Post
from gecent.core.output.block import Block, Code
from gecent.core.state import (
    COOLANT,
    COOLANT2,
    FEED_M,
    FEED_M2,
    SPINDLE_COMMAND,
    SPINDLE_M,
    T_CODE,
)


def restat(run: Post, record: int) -> None:
    """RESTAT, at the first motion after a stop: one block for the tool, one for the spindle
    (S with its direction M), then the feed/rapid gear and coolant codes, which wait for
    the motion block. Option 145 = -2 reinstates the rapid gear only (ENTRAP did it);
    option 136 = 1 leaves spindle and coolant to the control."""

    state = run.state
    option = run.machine.number_option(145)
    by_post = run.machine.number_option(136) != 1  # spindle and coolant: the post's to restore
    conditions = state.conditions
    if option in (1.0, -1.0):
        output = run.output
        tool = conditions.due(T_CODE)
        if tool is not None:
            block = Block(Code.NONMOTION, record)
            block.cells[13] = tool
            output.output(block)
        direction = conditions.due(SPINDLE_M) if by_post else None
        if direction is not None:
            command = conditions.due(SPINDLE_COMMAND)
            if command is not None:
                state.pending.spindle = command
                state.pending.rpm = state.spindle.speed
            output.store_m(direction)
            output.output(Block(Code.NONMOTION, record))
            state.spindle.on = True
        for slot in (FEED_M, FEED_M2):
            gear = conditions.due(slot)
            if gear is not None and option == 1.0:
                output.store_m(gear)
        for slot in (COOLANT, COOLANT2):
            coolant = conditions.due(slot) if by_post else None
            if coolant is not None:
                output.store_m(coolant)
                state.modes.coolant_on = True
    state.modes.stopped = False
    conditions.respecified.clear()
