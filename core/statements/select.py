"""SELECT (SLCTGB, manual 001 L36895-36925): the minor word names the subroutine. Built:
FEDOVR (feedrate override, L31066-31100), PALLET (SELPAL) and READER (SELRDR)
(L37184-37248), each an M code in a block by itself. SELECT/HEAD,n (SELHED, 001 L7214-7216)
is routed by a multihead program's first pass (core/multihead/first_pass.py); met by a
single-head run, SELECT/HED,1|2|3|BAR is SELHED's head code (L36846-36893).
SELECT/OFSETL,n (SELOFS, L37146-37182) puts the offset n in register 17 of a CODE 1
block, SELECT/TABLE,n (SELTAB, L37250-37285) the table n in register 16;
SELECT/TOOL,n (SELTUL, L37287-37335) preselects a tool (core/tool.py).

SELECT/HED,SADDLE, d[, TRAV | , f[, IPM|IPR]] (SELHED to SADDLE, GELATH, L36448-36512):
the saddle's move d in register 16, at rapid (TRAV: TABLEM(25) with option 87's dwell
into rapid and back to feed) or at the feed f (none: option 84) in the mode given (none:
option 85, with "OPTION FEEDRATE MODE ASSUMED."), the F left in IPM or IPR, not a command;
a move longer than the maximum departure (option 4) is cut into equal blocks (SEGSAD).
The statement's layout is not in the manual: docs/decisions.md ("Statement forms").
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import Diagnostic, InputError, MachineDefinitionError
from gecent.core.motion.rounding import to_steps
from gecent.core.output.block import Block, Code
from gecent.core.statements.auxiliary import code_by_itself
from gecent.core.statements.feed import feed_limits

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post

# FEDOVR's own text: "If ON is given, TABLEM(112) is output. If OFF is given, TABLEM(111)"
# (001 L31094-31096), though the TABLEM chart names 111 "on" and 112 "off" (L23537-23539):
# the routine is what the program does, so a machine file follows it
FEED_OVERRIDE_CELLS = {"ON": 112, "OFF": 111}
PALLET_CELL = 13  # "Pallet select change" (001 L23103)
READER_CELL = 14  # "Switch reader" (001 L23105)
OFFSET_REGISTER = 17  # SELOFS: "The offset code is stored in DBFSEG(17)" (001 L37160)
TABLE_REGISTER = 16  # SELTAB: "stored in DBFSEG(16) and is output" (001 L37272)
SADDLE_REGISTER = 16  # "The saddle move is stored in DBFSEG(16)" (001 L36482)
SADDLE_RAPID_CELL = 25  # TABLEM(25) "Rapid traverse on saddle" (001 L23115)
FEED_REGISTER = 11
FEED_MODE_ASSUMED = "OPTION FEEDRATE MODE ASSUMED."  # SADDLE's comment (001 L36490-36491)
SADDLE_USAGE = "SELECT/HED,SADDLE expects a move d, then TRAV, or a feed f with IPM or IPR"
# SELHED's heads: "Head n - On", TABLEM(125)-(127), and "Engage Bar", TABLEM(57)
# (001 L23591-23595, L23247): docs/decisions.md (SAFETY and SELECT/HED)
HEAD_USAGE = "SELECT/HED expects 1, 2, 3, BAR, or SADDLE and its move"
HEAD_CELLS: dict[str | float, int] = {1.0: 125, 2.0: 126, 3.0: 127, "BAR": 57}


def select(run: Post, statement: Statement) -> None:
    args = statement.args
    if not args or not isinstance(args[0], Word):
        raise InputError(
            "SELECT expects a minor word first (FEDOVR, PALLET, READER, ...)", statement.where
        )
    minor = args[0].name
    handler = _MINORS.get(minor)
    if handler is None:
        # SELECT calls the routine its minor word names (001 L36895-36925); SELANG's word
        # is not in the manual
        known = ", ".join(sorted(_MINORS))
        hint = "; the saddle is SELECT/HED,SADDLE,..." if minor == "SADDLE" else ""
        raise InputError(f"SELECT/{minor}: SELECT takes one of {known}{hint}", statement.where)
    handler(run, statement)


def _feed_override(run: Post, statement: Statement) -> None:
    """SELECT/FEDOVR,ON|OFF (FEDOVR)."""
    rest = statement.args[1:]
    if len(rest) != 1 or not isinstance(rest[0], Word) or rest[0].name not in ("ON", "OFF"):
        raise InputError("SELECT/FEDOVR expects ON or OFF", statement.where)
    code_by_itself(run, statement, FEED_OVERRIDE_CELLS[rest[0].name])


def _numbered(cell: int, minor: str) -> Callable[[Post, Statement], None]:
    """SELECT/PALLET[,n] and SELECT/READER[,n]: the machine has one code for each
    (TABLEM 13, 14), so n names the pallet or reader for the programmer, not the tape."""

    def handler(run: Post, statement: Statement) -> None:
        rest = statement.args[1:]
        if len(rest) > 1 or any(isinstance(a, Word) or a < 1 or a != int(a) for a in rest):
            raise InputError(f"SELECT/{minor} expects a {minor.lower()} number", statement.where)
        code_by_itself(run, statement, cell)

    return handler


def _register(cell: int, minor: str) -> Callable[[Post, Statement], None]:
    """SELECT/OFSETL,n and SELECT/TABLE,n: n in the machine's register ``cell`` (17, 16)
    in a CODE 1 block; a machine without that register gets comment 22's sense as a
    warning and no block."""

    def handler(run: Post, statement: Statement) -> None:
        rest = statement.args[1:]
        if len(rest) != 1 or isinstance(rest[0], Word) or rest[0] < 0 or rest[0] != int(rest[0]):
            raise InputError(
                f"SELECT/{minor} expects one {minor.lower()} number, a whole number >= 0",
                statement.where,
            )
        if run.machine.registers.formats[cell] is None:
            run.warn(
                Diagnostic(
                    f"SELECT/{minor}: THE MACHINE HAS NO REGISTER {cell} FOR IT", statement.where
                )
            )
            return
        block = Block(Code.NONMOTION, statement.number)
        block.cells[cell] = float(rest[0])
        run.output.output(block)

    return handler


def _tool(run: Post, statement: Statement) -> None:
    run.tool.select_tool(statement)


def _head(run: Post, statement: Statement) -> None:
    """SELECT/HED,1|2|3|BAR (SELHED, 001 L36846-36893): the head's M code in a block by
    itself, TABLEM(125), (126), (127) "Head n - On" or (57) "Engage Bar" (L23247,
    L23591-23595), after leaving rapid: the rapid flags are SELHED's, so the new head
    starts in its feed range. SELECT/HEAD,n of a multihead program is routed by its
    first pass and never reaches this; SELECT/HED,SADDLE is the saddle's move."""
    rest = statement.args[1:]
    if rest and isinstance(rest[0], Word) and rest[0].name == "SADDLE":
        saddle(run, statement)
        return
    where = statement.where
    if len(rest) != 1:
        raise InputError(HEAD_USAGE, where)
    name: str | float = rest[0].name if isinstance(rest[0], Word) else float(rest[0])
    cell = HEAD_CELLS.get(name)
    if cell is None:
        raise InputError(HEAD_USAGE, where)
    machine = run.machine
    if all(machine.m_code(c) is None for c in HEAD_CELLS.values()):
        raise InputError(
            f"SELECT/HED,{name if isinstance(name, str) else f'{name:g}'}: machine "
            f"{machine.label} has no head codes "
            "(TABLEM(125)-(127), (57) for BAR); to select a head of a multihead program, "
            "COMBIN/2 must come first, before the first motion, on a machine with two heads",
            where,
        )
    feed = run.state.feed
    feed.rapid_requested = False  # RAPFLG
    if feed.rapid_mode:
        run.rapid.leave()  # RAPIDX: FLRPON, FRAPID, RAPLOW, RAPRNG (the old head's gears)
    if not isinstance(name, str):
        # TLHEAD: RAPID shifts the selected head's gears, TABLEM 42-47, 142-147 or 148-153
        run.rapid.select_head(int(name))
    code_by_itself(run, statement, cell)


def saddle(run: Post, statement: Statement) -> None:
    """SELECT/HED,SADDLE, d[, TRAV | , f[, IPM|IPR]] (SADDLE, 001 L36448-36512)."""
    machine = run.machine
    where = statement.where
    rest = statement.args[2:]
    numbers = [float(a) for a in rest if not isinstance(a, Word)]
    words = [a.name for a in rest if isinstance(a, Word)]
    rapid = "TRAV" in words
    units = [w for w in words if w in ("IPM", "IPR")]
    if (
        not rest
        or isinstance(rest[0], Word)
        or any(w not in ("TRAV", "IPM", "IPR") for w in words)
        or len(words) != len(set(words))
        or len(units) > 1
        or len(numbers) > (1 if rapid else 2)
        or (rapid and units)
    ):
        raise InputError(SADDLE_USAGE, where)
    if machine.registers.formats[SADDLE_REGISTER] is None:
        raise InputError(
            f"SELECT/HED,SADDLE: machine {machine.label} has no saddle register "
            f"(REGFOR({SADDLE_REGISTER}))",
            where,
        )
    # under SFM, SADDLE calls SFMO (SADSFM, 001 L36474-36478, L36505): its radius is a CL
    # coordinate or a fixed one (SFMRAD), which a saddle move changes neither of, so SFMO's
    # sequence ends at once (a constant radius, L14230-14549) and the move goes out at the
    # speed in force (docs/decisions.md, issue 22 wave 7)
    step = machine.number_option(14)
    steps = to_steps(run.units.length(numbers[0]), step)
    if steps == 0:
        return  # no move: no block
    feed, per_minute = (None, False) if rapid else _saddle_feed(run, statement, numbers[1:], units)
    # CODE +15: "an auxiliary head motion having its feed command in IPM" (001 L1190-1193
    # list; spec 01 CODE table): the F stays IPM; an IPR or rapid move stays a plain block
    code = Code.AUX_HEAD_IPM if per_minute else Code.NONMOTION
    dwell = machine.number_option(87) if rapid else 0.0
    output = run.output
    if dwell > 0:
        _dwell(run, statement, dwell)  # into rapid
    if rapid:
        output.store_cell(SADDLE_RAPID_CELL, run.warn, where)
    for part in _segments(steps, machine.number_option(4), step):
        block = Block(code, statement.number)
        block.cells[SADDLE_REGISTER] = part * step
        if feed is not None:
            block.cells[FEED_REGISTER] = feed
        output.output(block)
    if dwell > 0:
        _dwell(run, statement, dwell)  # back to feed


def _saddle_feed(
    run: Post, statement: Statement, given: list[float], units: list[str]
) -> tuple[float, bool]:
    """The saddle's F: f as given (option 84 when none), in the mode given (option 85 when
    none, with the comment); an IPM feed is held to the feed range's limits. With it, True
    for IPM (SADMOD = 1)."""
    machine = run.machine
    if given:
        feed = given[0]
        if feed <= 0:
            raise InputError(f"SELECT/HED,SADDLE needs a feed > 0, found {feed:g}", statement.where)
    else:
        feed = machine.number_option(84)
        if feed <= 0:
            raise MachineDefinitionError(
                machine.origin, "optab", 84, f"option 84 = {feed:g}: the saddle's feed must be > 0"
            )
    if units:
        per_minute = units[0] == "IPM"
    else:
        assumed = machine.number_option(85)
        if assumed == 0:
            raise MachineDefinitionError(
                machine.origin,
                "optab",
                85,
                "option 85 = 0: a saddle move without IPM or IPR stops the run (001 L25395-25405)",
            )
        run.warn(Diagnostic(FEED_MODE_ASSUMED, statement.where))
        per_minute = assumed > 0
    if not per_minute:
        return feed, False
    low, high = feed_limits(run)
    used = min(max(feed, low), high)
    if used != feed:
        run.warn(
            Diagnostic(
                f"FEEDRATE {feed:g} IPM IS OUTSIDE THE MACHINE RANGE {low:g}-{high:g}; "
                f"{used:g} IPM USED",
                statement.where,
            )
        )
    return used, True


def _segments(steps: int, maximum: float, step: float) -> list[int]:
    """SEGSAD: a move longer than the maximum departure in equal parts, in whole steps,
    the last taking what rounding left."""
    largest = to_steps(maximum, step) if maximum > 0 else abs(steps)
    count = -(-abs(steps) // largest) if largest > 0 else 1
    part = int(steps / count)
    return [part] * (count - 1) + [steps - part * (count - 1)]


def _dwell(run: Post, statement: Statement, seconds: float) -> None:
    block = run.output.dwell(seconds)
    block.record = statement.number
    run.output.output(block)


_MINORS: dict[str, Callable[[Post, Statement], None]] = {
    "HEAD": _head,
    "HED": _head,
    "FEDOVR": _feed_override,
    "PALLET": _numbered(PALLET_CELL, "PALLET"),
    "READER": _numbered(READER_CELL, "READER"),
    "OFSETL": _register(OFFSET_REGISTER, "OFSETL"),
    "TABLE": _register(TABLE_REGISTER, "TABLE"),
    "TOOL": _tool,
}

HANDLERS = {"SELECT": select}
