"""SELECT (SLCTGB, manual 001 L36895-36925): the minor word names the subroutine. Built:
FEDOVR (feedrate override, L31066-31100), PALLET (SELPAL) and READER (SELRDR)
(L37184-37248), each an M code in a block by itself. SELECT/HEAD,n (SELHED, 001 L7214-7216)
is routed by a multihead program's first pass (core/multihead/first_pass.py); met by a
single-head run it is refused. SELECT/OFSETL,n (SELOFS, L37146-37182) puts the offset n in
register 17 of a CODE 1 block, SELECT/TABLE,n (SELTAB, L37250-37285) the table n in
register 16; SELECT/TOOL,n (SELTUL, L37287-37335) preselects a tool (core/tool.py).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import Diagnostic, InputError, NotYetSupported
from gecent.core.output.block import Block, Code
from gecent.core.statements.auxiliary import code_by_itself

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


def select(run: Post, statement: Statement) -> None:
    args = statement.args
    if not args or not isinstance(args[0], Word):
        raise InputError(
            "SELECT expects a minor word first (FEDOVR, PALLET, READER, ...)", statement.where
        )
    minor = args[0].name
    handler = _MINORS.get(minor)
    if handler is None:
        raise NotYetSupported(f"SELECT/{minor}", statement.where)
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
    """SELECT/HEAD,n reaches a run only when the program is not a multihead one."""
    raise InputError(
        "SELECT/HEAD selects a head of a multihead program: COMBIN/2 must come first, "
        "before the first motion, on a machine with two heads",
        statement.where,
    )


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
