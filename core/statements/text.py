"""PARTNO, PPRINT and INSERT: text printed and, for PARTNO and INSERT, punched as written
(manual §3.5.3.2 CODE -7, +7, +6; 001 L9087-9098, L9189-9296). Under gecent option 257 = 1
PARTNO and PPRINT are punched as comments in parentheses, which modern controls skip."""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement
from gecent.core.output.block import Block, Code

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post


def partno(run: Post, statement: Statement) -> None:
    text = statement.text or ""
    if not run.result.partno:
        run.result.partno = run.sinks.partno = text
    run.text_block(_comment(run, Code.PARTNO, statement.number, text))


def pprint(run: Post, statement: Statement) -> None:
    run.text_block(_comment(run, Code.PPRINT, statement.number, statement.text or ""))


def _comment(run: Post, code: Code, number: int, text: str) -> Block:
    """The text block, or under option 257 = 1 a punched comment: "(TEXT)", a parenthesis
    inside the text turned into a bracket, since controls end a comment at the first ")"."""
    if run.machine.number_option(257) != 1:
        return Block(code, number, text)
    inner = text.strip().translate(_BRACKETS)
    block = Block(Code.INSERT, number, f"({inner})")
    block.keep_blanks = run.machine.number_option(256) == 1
    return block


_BRACKETS = str.maketrans("()", "[]")


def insert(run: Post, statement: Statement) -> None:
    run.text_block(Block(Code.INSERT, statement.number, statement.text or ""))


HANDLERS = {
    "PARTNO": partno,
    "PPRINT": pprint,
    "INSERT": insert,
}
