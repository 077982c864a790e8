"""The words of an RPM SPINDL statement, and the statements that stop or hold the spindle
without a speed: NEUTRL (option 99), ORIENT and LOCK (TABLEM 68, 69) (manual §4.5, SPINDL
001 L37566-37637; core/spindle.py keeps the element that acts on a speed).

The manual's SPINDL words are RPM, SFM (core/spindle_sfm.py), CLW, CCLW, RANGE,r, ON, OFF,
NEUTRL and DWELL (minor word 197, 001 L3253); TABLEM names a spindle orient code (68) and a
spindle lock code (69), with option 54 "also used for a spindle locking dwell time" (001
L23358-23364, L25078-25083). DWELL sets IDWLFL, "DBFSEG(2) contains the spindle-dwell G
code" (001 L17348-17352), but no TABLEG location or value is given for that code.
"""

from __future__ import annotations

from collections.abc import Callable

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import Diagnostic, InputError, MachineDefinitionError
from gecent.core.output.block import Block, Code
from gecent.core.output.element import OutputElement
from gecent.core.state import SPINDLE_M, PostState

RPM_WORDS = ("RPM", "CLW", "CCLW", "RANGE", "ON", "OFF")
ORIENT_CELL = 68  # TABLEM(68): spindle orient
LOCK_CELL = 69  # TABLEM(69): spindle lock (the multiaxis sample's M19)
HOLDING = {"ORIENT": ORIENT_CELL, "LOCK": LOCK_CELL}


def check_rpm_words(statement: Statement, words: list[str]) -> None:
    """An RPM SPINDL takes RPM, CLW, CCLW, RANGE, ON and OFF; DWELL is the manual's word
    but it defines no code or time for it (bad input, with the reason); any other word is
    not a SPINDL word (the manual's "IMPROPER FORMAT, STATEMENT SKIPPED", an input error
    here as elsewhere in gecent)."""
    for word in words:
        if word == "DWELL":
            # the manual gives the word (minor 197) and a flag (IDWLFL: "DBFSEG(2)
            # contains the spindle-dwell G code", which POSMOV leaves for the next move)
            # but no TABLEG cell for that G code and no time: a tape gecent cannot make
            raise InputError(
                "SPINDL/DWELL: the manual names a spindle-dwell G code (IDWLFL, 001 "
                "L17348-17352, L34952-34955) but gives no G code cell and no time for it; "
                "program the dwell with DELAY after the SPINDL",
                statement.where,
            )
        if word not in RPM_WORDS:
            raise InputError(
                f"SPINDL does not take {word}: it takes a speed with RPM, CLW, CCLW, "
                "RANGE,r, ON or OFF; or SFM; or NEUTRL, ORIENT, LOCK",
                statement.where,
            )


def speed_and_range(statement: Statement) -> tuple[float | None, int | None]:
    """The speed is the first number not taken by RANGE,r; minor words may come before or
    after it (SPINDL/10,RPM,CLW or SPINDL/RPM,10,CLW as Creo writes it)."""
    speed: float | None = None
    requested_range: int | None = None
    args = statement.args
    index = 0
    while index < len(args):
        arg = args[index]
        if isinstance(arg, Word) and arg.name == "RANGE":
            if index + 1 >= len(args) or isinstance(args[index + 1], Word):
                raise InputError("SPINDL RANGE expects a range number", statement.where)
            requested_range = int(float(args[index + 1]))  # type: ignore[arg-type]
            index += 2
            continue
        if not isinstance(arg, Word):
            if speed is not None:
                raise InputError("SPINDL expects one speed", statement.where)
            speed = float(arg)
        index += 1
    return speed, requested_range


def neutral(
    state: PostState, output: OutputElement, statement: Statement, has_s_register: bool
) -> None:
    """SPINDL/NEUTRL (option 99, 001 L25604-25617): the S command option 99 gives, in
    command form (0.1 punches S00), in a block of its own as any SPINDL's S; option 99
    = 0 outputs nothing. The speed and range in force stay (a later SPINDL/ON finds
    them), and the listing's S-RPM shows the command."""
    if len(statement.args) != 1:
        raise InputError("SPINDL/NEUTRL takes nothing else", statement.where)
    machine = state.machine
    command = machine.number_option(99)
    if command == 0:
        return
    if not has_s_register:
        raise MachineDefinitionError(
            machine.origin,
            "optab",
            99,
            f"option 99 = {command:g} is the S code of SPINDL/NEUTRL, but the machine has "
            "no S register (REGFOR(12) = 0)",
        )
    state.pending.spindle = command
    state.pending.rpm = command
    output.output(Block(Code.NONMOTION, statement.number))


def hold(
    state: PostState,
    output: OutputElement,
    warn: Callable[[Diagnostic], None],
    statement: Statement,
    word: str,
) -> None:
    """SPINDL/ORIENT and SPINDL/LOCK (decision): TABLEM(68) or (69) in a block of its own;
    the lock's block is a dwell of option 54 seconds when that is not 0 (the spindle
    locking dwell). An oriented or locked spindle does not turn: a later SPINDL starts it
    with its direction code. A machine without the code gets comment 22 and no block."""
    if len(statement.args) != 1:
        raise InputError(f"SPINDL/{word} takes nothing else", statement.where)
    spindle = state.spindle
    spindle.on = False
    spindle.restart = None
    state.remember(SPINDLE_M, None)
    if output.store_cell(HOLDING[word], warn, statement.where) is None:
        return
    seconds = state.machine.number_option(54)
    if word == "LOCK" and seconds > 0:
        block = output.dwell(seconds)
        block.record = statement.number
    else:
        block = Block(Code.AUX_ONLY, statement.number)
    output.output(block)
