"""LEADER and TMARK: tape marks (manual §3.5.3.2 CODE -8 and +8, 001 L9298-9324)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import InputError
from gecent.core.output.block import Block, Code
from gecent.core.output.marks import leader_block, tmark_cells

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post


def leader(run: Post, statement: Statement) -> None:
    """LEADER/L: L inches of leader, in whole cards (CODE -8, 001 L9306-9324)."""
    numbers = statement.numbers()
    if len(numbers) != 1 or len(statement.args) != 1:
        raise InputError("LEADER expects one length in inches", statement.where)
    # tape is measured in inches whatever the CL units (docs/decisions.md)
    run.text_block(leader_block(run.machine, numbers[0], statement.number, statement.where))


def tmark(run: Post, statement: Statement) -> None:
    """TMARK or TMARK/1: the end-of-record (rewind stop) code in a block of its own (CODE
    +8). The manual has no write-up of TMARK; its one use, TMARK/1 in the GEOUT4 example
    (001 L10122), prints one TMARK line, so TMARK/1 is TMARK and any other form is bad
    input (docs/decisions.md, "Statement forms")."""
    if statement.args and list(statement.args) != [1.0]:
        shown = ",".join(a.name if isinstance(a, Word) else f"{a:g}" for a in statement.args)
        raise InputError(
            f"TMARK/{shown}: the manual defines TMARK and TMARK/1 (one end-of-record mark) only",
            statement.where,
        )
    block = Block(Code.TMARK, statement.number)
    tmark_cells(run.machine, block)
    run.output.output(block)


HANDLERS = {
    "LEADER": leader,
    "TMARK": tmark,
}
