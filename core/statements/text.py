"""PARTNO, PPRINT and INSERT: text printed and, for PARTNO and INSERT, punched as written
(manual §3.5.3.2 CODE -7, +7, +6; 001 L9087-9098, L9189-9296)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement
from gecent.core.output.block import Block, Code

if TYPE_CHECKING:
    from gecent.core.run import Run


def partno(run: Run, statement: Statement) -> None:
    text = statement.text or ""
    if not run.result.partno:
        run.result.partno = text
    run.text_block(Block(Code.PARTNO, statement.number, text))


def pprint(run: Run, statement: Statement) -> None:
    run.text_block(Block(Code.PPRINT, statement.number, statement.text or ""))


def insert(run: Run, statement: Statement) -> None:
    run.text_block(Block(Code.INSERT, statement.number, statement.text or ""))


HANDLERS = {
    "PARTNO": partno,
    "PPRINT": pprint,
    "INSERT": insert,
}
