"""Miscellaneous functions: COOLNT, STOP, OPSTOP, BREAK, END, REWIND, AUXFUN, PREFUN and
CLAMP (manual GEBASE routines: COOLNT 001 L29862-29892, STOP/OPSTOP/BREAK L37965-37997,
END L30909-30951, REWIND L35796-35848, AUXFUN L28825-28870, PREFUN L9241-9250, CLAMP
L29337-29394), read in docs/research/statements-misc.md.

COOLNT and CLAMP leave their M code waiting for the next block (STOREM). STOP, OPSTOP,
REWIND and AUXFUN (option 75 = 0) put theirs in a block by itself; END is a CODE +5 block
after the option-97 dwell, followed by the option-168 leader and the option-11 filler.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement
from gecent.core.errors import InputError
from gecent.core.output.block import Block, Code
from gecent.core.output.marks import leader_block, stand_in
from gecent.core.spindle_sfm import leave_sfm
from gecent.core.state import COOLANT, StateVector

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post

# coolant mode (ICLMOD) -> TABLEM cells (on, off) (001 L23095-23117, L23478-23535)
COOLANT_CELLS = {1: (101, 104), 2: (102, 105), 3: (103, 106), 4: (9, 10), 5: (19, 20),
                 6: (107, 108), 7: (109, 110)}  # fmt: skip
COOLANT_MODES = {"TAPKUL": 1, "MIST": 2, "FLOOD": 3, "SADDLE": 5, "FRONT": 6, "REAR": 7}
# CLAMP objects -> TABLEM cells (close, open) (001 L23172-23174, L23239-23245, L23607-23609)
CLAMP_CELLS = {"XAXIS": (22, 23), "TABLE": (22, 23), "PART": (22, 23), "YAXIS": (53, 54),
               "HEAD": (53, 54), "HED": (53, 54), "RAIL": (55, 56), "TUL": (55, 56),
               "ALL": (133, 134)}  # fmt: skip
FILLER_FRAMES = 72  # one card of the tape image


def coolnt(run: Post, statement: Statement) -> None:
    """COOLNT/ON|OFF[,FLOOD|MIST|TAPKUL|SADDLE|FRONT|REAR]: the M code waits for the next
    block. A mode the machine has no code for falls back to TABLEM(9)/(10)."""
    words = statement.words()
    unknown = [w for w in words if w not in ("ON", "OFF") and w not in COOLANT_MODES]
    if unknown or statement.numbers() or not words:
        raise InputError(
            "COOLNT expects ON, OFF or a coolant mode (FLOOD, MIST, TAPKUL, ...)", statement.where
        )
    modes = run.state.modes
    for word in words:
        if word in COOLANT_MODES:
            modes.coolant_mode = COOLANT_MODES[word]
    mode = modes.coolant_mode or int(run.machine.number_option(33)) or 4
    on = "OFF" not in words
    cells = COOLANT_CELLS.get(mode, COOLANT_CELLS[4])
    code = run.machine.m_code(cells[0 if on else 1])
    if code is None:
        code = run.machine.m_code(COOLANT_CELLS[4][0 if on else 1])
    modes.coolant_on = on
    run.state.remember(COOLANT, code if on else None)
    if code is not None:
        run.output.store_m(code)


def _stop(run: Post, statement: Statement, cell: int) -> None:
    """STOP (TABLEM(1)) and OPSTOP (TABLEM(2)): the code in a block by itself; the control
    stops spindle and coolant, so both are off afterwards (001 L37970-37991), unless it
    restores them itself at the restart (option 136 = 1, 001 L25995-26007)."""
    if statement.args:
        raise InputError(f"{statement.major} takes no arguments", statement.where)
    code_by_itself(run, statement, cell, stop=True)
    if not control_restores(run):
        _spindle_and_coolant_off(run)
    run.state.modes.stopped = True
    run.state.conditions.respecified.clear()
    if run.machine.number_option(145) in (-1.0, -2.0):
        run.rapid.entrap()  # ENTRAP: the machine waits in rapid gear (001 L30953-30990)


def control_restores(run: Post) -> bool:
    """Option 136 = 1: after a programmed stop the control itself turns spindle and coolant
    back to their former conditions (001 L25995-26007), so the post keeps them on. An
    optional stop (M01) counts too: whether or not the operator's switch stops there, both
    are in their former conditions when the program goes on (docs/decisions.md)."""
    return run.machine.number_option(136) == 1


def stop(run: Post, statement: Statement) -> None:
    _stop(run, statement, 1)


def opstop(run: Post, statement: Statement) -> None:
    _stop(run, statement, 2)


def break_(run: Post, statement: Statement) -> None:
    """BREAK: an optional-stop block when the machine has one (TABLEM(2); the manual's
    TABLEG(2) is a slip), then the tape is broken there once the reel has passed option
    135's footage (001 L9273-9281, L25984-25994; core/output/reels.py)."""
    if run.machine.m_code(2) is not None:
        _stop(run, statement, 2)
    reels = run.sinks.reels
    if reels is not None and reels.breakable():
        for block in reels.break_blocks(statement.number):
            run.text_block(block)


def code_by_itself(
    run: Post, statement: Statement, cell: int, kind: Code = Code.AUX_ONLY, stop: bool = False
) -> bool:
    """TABLEM(cell) in a block by itself, after any waiting M; comment 22 (and False) when
    the machine has no such code."""
    if run.output.store_cell(cell, run.warn, statement.where) is None:
        return False
    block = Block(kind, statement.number)
    block.stop = stop
    run.output.output(block)
    return True


def _spindle_and_coolant_off(run: Post) -> None:
    state = run.state
    state.spindle.on = False
    state.modes.coolant_on = False
    if run.machine.number_option(129) == 0:
        state.spindle.range = 1


def _dwell_with_t0(run: Post, statement: Statement) -> None:
    """Option 97: a dwell "in a block with a zero T code" before END and REWIND
    (001 L25570-25584)."""
    seconds = run.machine.number_option(97)
    if seconds > 0 and run.machine.registers.formats[13] is not None:
        block = run.output.dwell(seconds)
        block.record = statement.number
        block.cells[13] = 0.0
        run.output.output(block)


def end(run: Post, statement: Statement) -> None:
    """END: the end-of-program code (TABLEM(3)) in a CODE +5 block by itself, then the
    option-168 leader and the option-11 filler card; the run's modes are reset and the
    next motion must start with a FROM (001 L30909-30951, L26320-26327, L24496-24510)."""
    if statement.args:
        raise InputError("END takes no arguments", statement.where)
    run.output.flush_m(statement.number)
    _dwell_with_t0(run, statement)
    code_by_itself(run, statement, 3, Code.END)
    machine = run.machine
    leader = machine.number_option(168)
    if leader > 0:
        run.text_block(leader_block(machine, leader, statement.number, statement.where))
    filler = machine.number_option(11)
    if filler in (0, 1):  # +1 a card of the space (leader) code, 0 a blank card
        block = Block(Code.LEADER, statement.number)
        block.punch = stand_in(machine, 64) * FILLER_FRAMES if filler == 1 else ""
        run.text_block(block)
    _reset(run)


def reset(run: Post, statement: Statement) -> None:
    """RESET, END's second entry: the same resets without the end code, as a CODE -5
    block that is neither printed nor punched (001 L30909-30951)."""
    if statement.args:
        raise InputError("RESET takes no arguments", statement.where)
    run.output.flush_m(statement.number)
    run.text_block(Block(Code.RESET, statement.number))
    _reset(run)


def _reset(run: Post) -> None:
    """ENDGB's resets: spindle, stop, rapid, TRANS and the STATE vector; a FROM must
    follow (comment 47 otherwise)."""
    state = run.state
    _spindle_and_coolant_off(run)
    leave_sfm(state)
    state.spindle.speed = None
    state.modes.stopped = False
    state.modes.ended = True
    state.feed.rapid_requested = False
    state.feed.rapid_mode, state.feed.rapid_ipm, state.feed.rapid_low = 0, 0.0, False
    state.position.translation = (0.0, 0.0, 0.0)
    state.conditions = StateVector()


def air(run: Post, statement: Statement) -> None:
    """AIR/ON|OFF: TABLEM(123) or (124) in a block by itself (001 L28677-28716)."""
    words = list(statement.words())
    if len(statement.args) != 1 or words not in (["ON"], ["OFF"]):
        raise InputError("AIR expects AIR/ON or AIR/OFF", statement.where)
    run.output.flush_m(statement.number)
    code_by_itself(run, statement, 123 if words[0] == "ON" else 124)


def rewind(run: Post, statement: Statement) -> None:
    """REWIND: the option-97 dwell with T0, then the rewind code TABLEM(31) in a block by
    itself; spindle and coolant are off (001 L35796-35848; DWELL(92) read as DWELL(97))."""
    run.output.flush_m(statement.number)
    _dwell_with_t0(run, statement)
    if code_by_itself(run, statement, 31):
        _spindle_and_coolant_off(run)


def auxfun(run: Post, statement: Statement) -> None:
    """AUXFUN/n: M n itself (not a TABLEM cell), in a block by itself under option 75 = 0,
    else waiting for the next block (001 L28825-28870)."""
    code = _whole_number(statement, "AUXFUN")
    output = run.output
    output.flush_m(statement.number)
    output.store_m(code)
    if run.machine.number_option(75) == 0:
        output.output(Block(Code.AUX_ONLY, statement.number))


def prefun(run: Post, statement: Statement) -> None:
    """PREFUN/n: G n in a block by itself, never suppressed (CODE -4, 001 L9241-9250)."""
    block = Block(Code.G_ONLY, statement.number)
    block.cells[2] = _whole_number(statement, "PREFUN")
    run.output.output(block)


def clamp(run: Post, statement: Statement) -> None:
    """CLAMP/[object,]ON|OFF: the clamp M code waits for the next block; with option 76 a
    dwell block carries it (001 L29337-29394, L25290-25295)."""
    words = statement.words()
    objects = [w for w in words if w in CLAMP_CELLS]
    switches = [w for w in words if w in ("ON", "OFF")]
    if len(objects) > 1 or len(switches) > 1 or len(objects) + len(switches) != len(words):
        raise InputError(
            "CLAMP expects an object (XAXIS, TABLE, ...) and ON or OFF", statement.where
        )
    cells = CLAMP_CELLS[objects[0] if objects else "XAXIS"]
    cell = cells[1] if switches == ["OFF"] else cells[0]
    if run.output.store_cell(cell, run.warn, statement.where) is None:
        return
    seconds = run.machine.number_option(76)
    if seconds > 0 and cells[0] < 100:
        block = run.output.dwell(seconds)
        block.record = statement.number
        run.output.output(block)


def _whole_number(statement: Statement, major: str) -> float:
    numbers = statement.numbers()
    if len(statement.args) != 1 or len(numbers) != 1 or numbers[0] != int(numbers[0]):
        raise InputError(f"{major} expects one code number", statement.where)
    if numbers[0] < 0:
        raise InputError(f"{major} expects a code number >= 0", statement.where)
    return numbers[0]


HANDLERS = {
    "AIR": air,
    "RESET": reset,
    "COOLNT": coolnt,
    "STOP": stop,
    "OPSTOP": opstop,
    "BREAK": break_,
    "END": end,
    "REWIND": rewind,
    "AUXFUN": auxfun,
    "PREFUN": prefun,
    "CLAMP": clamp,
}
