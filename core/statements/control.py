"""The special machine categories of option 132 and the words the manual names without a
routine: DRESS (DRESGP, 001 L30580-30610), WELD (WELDGP, L40047-40090), FLAME (FLAMGF,
L31217-31290), DRAFT (DRFTGD, L30529-30578); SWITCH, PPUNCH, MODE, SET and PIVOTZ.

Option 132 picks the machine's main overlay (001 L415-441, L25946-25961): 3 drafting
(GEDRAF), 4 flame cutter (GEFLAM), 5 welder (GEWELD). Their statements are M codes
(WELD, FLAME, DRESS) or D-register codes (DRAFT) in blocks by themselves; the motion is a
mill's or a positioning machine's, by option 1. WELD is a positioning routine (OPTAB(1)
positive), FLAME needs option 132 = 4, DRAFT option 132 = 3.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.absent import ABSENT
from gecent.core.cl.records import Statement, Word
from gecent.core.cl.vocabulary import vocabulary
from gecent.core.errors import Diagnostic, InputError
from gecent.core.output.block import Block, Code
from gecent.core.output.element import NOT_AVAILABLE
from gecent.core.statements.auxiliary import code_by_itself
from gecent.core.statements.surfaces import require_positioning

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post

DRAFTING, FLAME_CUTTER = 3, 4  # option 132
DRESS_CELL = 28  # "Dress (welder or grinder)" (001 L23196)
WELD_OFF_CELL = 87  # the weld-cycle-off code POSMOV outputs after WELD/OFF (001 L34951)
# WELD's modifiers -> TABLEM cell of each alternative (001 L40068-40076, chart L23327-23347)
WELD_CELLS = {
    "TILT": {1: 83, 2: 84},
    "SHIFT": {1: 88, 2: 89, 3: 90, 4: 91, 0: 92},  # weld shift n = BEAM n; 92 = BEAM 0
    "SCHEDL": {1: 85, 2: 86},
    "FIXTUR": {1: 66, 2: 67},
}
FIXTUR_CODE = 300  # ICLDAT(4) = 300 (001 L40073); not in the minor word list
# FLAME: (action, ON?) -> (master head cell, slave head cell) (001 L23327-23347)
FLAME_CELLS = {
    ("PREHET", True): (85, 86),
    ("PREHET", False): (87, 88),
    ("OXYGEN", True): (89, 90),
    ("OXYGEN", False): (91, 92),
    ("DOWN", None): (93, 94),
    ("UP", None): (95, 96),
}
FLAME_HEADS = {"MASTER": 0, "SLAVE": 1, "BOTH": -1}
FLAME_VOCABULARY = "THE VOCABULARY IS NOT ACCEPTABLE IN THE FLAME STATEMENT."  # comment 42
# DRAFT's D-register codes (001 L30555-30570)
PEN_DOWN, PEN_UP, DASH_ON, DASH_OFF = 1.0, 2.0, 4.0, 5.0
D_REGISTER = 16
NO_PROCESSING = "GECENT III DESCRIBES NO PROCESSING FOR THIS WORD; STATEMENT DISREGARDED"


def _is(arg: object, name: str) -> bool:
    """The minor word ``name``, by its code as the postprocessor reads it (a binary CL file
    gives 171 for PREHET, which the vocabulary shares with MMPM)."""
    if not isinstance(arg, Word):
        return False
    code = FIXTUR_CODE if name == "FIXTUR" else vocabulary().minor_code(name)
    return arg.name == name or (code is not None and arg.code == code)


def _name(arg: object, names: tuple[str, ...]) -> str | None:
    return next((name for name in names if _is(arg, name)), None)


def _whole(arg: object) -> int | None:
    if isinstance(arg, Word) or not isinstance(arg, int | float) or arg != int(arg):
        return None
    return int(arg)


# -- DRESS and WELD ------------------------------------------------------------------------


def dress(run: Post, statement: Statement) -> None:
    """DRESS: TABLEM(28) in a block by itself (STOREM(28), STOREM(130))."""
    if statement.args:
        raise InputError("DRESS takes no arguments", statement.where)
    run.output.flush_m(statement.number)
    code_by_itself(run, statement, DRESS_CELL)


def weld(run: Post, statement: Statement) -> None:
    """WELD/ON | OFF | TILT,n | SHIFT,n | SCHEDL,n | FIXTUR,n on a positioning machine.
    OFF sets IGEFLG: the weld-cycle-off code TABLEM(87) goes out with the next block; ON
    clears it. The others output their TABLEM code in a block by itself; any other
    modifier is comment 22."""
    require_positioning(run, statement, "WELDGP")
    args = statement.args
    if not args:
        raise InputError("WELD expects ON, OFF, TILT, SHIFT, SCHEDL or FIXTUR", statement.where)
    switch = _name(args[0], ("ON", "OFF"))
    if switch is not None:
        if len(args) != 1:
            raise InputError(f"WELD/{switch} takes nothing after it", statement.where)
        _weld_switch(run, statement, switch == "OFF")
        return
    modifier = _name(args[0], tuple(WELD_CELLS))
    if modifier is None:
        run.warn(Diagnostic(NOT_AVAILABLE, statement.where))  # comment 22
        return
    cells = WELD_CELLS[modifier]
    number = _whole(args[1]) if len(args) == 2 else None
    if number not in cells:
        choices = ", ".join(str(n) for n in sorted(cells))
        raise InputError(f"WELD/{modifier} expects one of {choices}", statement.where)
    assert number is not None
    run.output.flush_m(statement.number)
    code_by_itself(run, statement, cells[number])


def _weld_switch(run: Post, statement: Statement, off: bool) -> None:
    state = run.state
    pending = state.pending
    weld_off = run.machine.m_code(WELD_OFF_CELL)
    state.weld_off = off
    if off:
        if weld_off is None:
            run.warn(Diagnostic(NOT_AVAILABLE, statement.where))
        else:
            run.output.store_m(weld_off)
    elif weld_off is not None and pending.m_code == weld_off:
        pending.m_code = ABSENT  # no move came between: POSMOV never output it


# -- FLAME ---------------------------------------------------------------------------------


def flame(run: Post, statement: Statement) -> None:
    """FLAME/[MASTER|SLAVE|BOTH,] UP | DOWN | OXYGEN,ON|OFF | PREHET,ON|OFF, ...: out of
    rapid first (RAPIDX); each request's code for the head (IHEAD, kept from one FLAME to
    the next) in a block by itself, the master's first for BOTH. A statement the scan cannot
    read is comment 42 and nothing is output."""
    if run.machine.number_option(132) != FLAME_CUTTER:
        raise InputError(
            "FLAME is a flame-cutter statement (overlay GEFLAM: option 132 = 4); this machine "
            f"has option 132 = {run.machine.number_option(132):g}",
            statement.where,
        )
    scanned = _flame_cells(statement.args, run.state.flame_head)
    if scanned is None:
        run.warn(Diagnostic(FLAME_VOCABULARY, statement.where))
        return
    cells, run.state.flame_head = scanned
    if run.state.feed.rapid_mode:
        run.rapid.leave()
    run.output.flush_m(statement.number)
    for cell in cells:
        code_by_itself(run, statement, cell)


def _flame_cells(args: tuple[object, ...], head: int) -> tuple[list[int], int] | None:
    """The TABLEM cells in the statement's order, for the head in force at each, and the
    head at the end; None when a word is not FLAME vocabulary."""
    cells: list[int] = []
    index = 0
    while index < len(args):
        arg = args[index]
        index += 1
        named_head = _name(arg, tuple(FLAME_HEADS))
        if named_head is not None:
            head = FLAME_HEADS[named_head]
            continue
        action = _name(arg, ("UP", "DOWN", "OXYGEN", "PREHET"))
        if action is None:
            return None
        state: bool | None = None
        if action in ("OXYGEN", "PREHET"):
            switch = _name(args[index], ("ON", "OFF")) if index < len(args) else None
            if switch is None:
                return None
            index += 1
            state = switch == "ON"
        master, slave = FLAME_CELLS[(action, state)]
        cells.extend({0: (master,), 1: (slave,), -1: (master, slave)}[head])
    return cells, head


# -- DRAFT ---------------------------------------------------------------------------------


def draft(run: Post, statement: Statement) -> None:
    """DRAFT/ON[,SOLID] (D1, pen down), DRAFT/OFF (D2, pen up), DRAFT/OFF,DASH (D5) and
    DRAFT/ON,DASH (D1 first when the pen is up, then D4), each D in a block of its own."""
    machine = run.machine
    if machine.number_option(132) != DRAFTING:
        raise InputError(
            "DRAFT is a drafting-machine statement (overlay GEDRAF: option 132 = 3); this "
            f"machine has option 132 = {machine.number_option(132):g}",
            statement.where,
        )
    args = statement.args
    switches = [a for a in args if _name(a, ("ON", "OFF")) is not None]
    lines = [a for a in args if _name(a, ("DASH", "SOLID")) is not None]
    if len(switches) != 1 or len(lines) > 1 or len(switches) + len(lines) != len(args):
        raise InputError("DRAFT expects ON or OFF, and DASH or SOLID", statement.where)
    on = _is(switches[0], "ON")
    dash = bool(lines) and _is(lines[0], "DASH")
    if lines and not on and not dash:
        raise InputError("DRAFT/OFF,SOLID: OFF goes with DASH only", statement.where)
    if machine.registers.formats[D_REGISTER] is None:
        raise InputError(
            "DRAFT: this machine has no D register for the drafting codes (REGSTR 16)",
            statement.where,
        )
    state = run.state
    codes: list[float] = []
    if on:
        if not dash or not state.pen_down:
            codes.append(PEN_DOWN)
        if dash:
            codes.append(DASH_ON)
        state.pen_down = True
    elif dash:
        codes.append(DASH_OFF)
    else:
        codes.append(PEN_UP)
        state.pen_down = False
    for code in codes:
        block = Block(Code.NONMOTION, statement.number)
        block.cells[D_REGISTER] = code
        run.output.output(block)


# -- words with no routine -----------------------------------------------------------------


def disregarded(run: Post, statement: Statement) -> None:
    """SWITCH and PPUNCH (no AUXLRY routine), SET, MODE and PIVOTZ (AUXLRY routines the
    manual does not describe): disregarded with a warning in the listing, on every machine.
    MODE and PIVPLN are GEMAXS routines with no write-up (001 L19040-19067); the MACFUN
    list names a "Subroutine MODE" hook (L27566) with no number and no text, and the
    sample MACFUN MACF40 answers MCHCON 1, 2, 6, 7, 8 only (RETURN = 0 for the rest), so a
    machine with special functions (option 133 = 1) or a multiaxis machine does the same
    (docs/decisions.md, "Statement forms")."""
    run.warn(Diagnostic(f"{statement.major}: {NO_PROCESSING}", statement.where))


HANDLERS = {
    "DRESS": dress,
    "WELD": weld,
    "FLAME": flame,
    "DRAFT": draft,
    "SWITCH": disregarded,
    "PPUNCH": disregarded,
    "SET": disregarded,
    "MODE": disregarded,
    "PIVOTZ": disregarded,
}
