"""CUTCOM (CTCMGB, manual 001 L30025-30060): the cutter-compensation G code in a block by
itself (CODE -4, which the output stage never drops as a redundant G, L9241-9250).

The manual does not list CUTCOM's modifiers; they come from TABLEG's cutter-compensation
functions: 40 off, 41 left, 42 right (L22628-22691), 46 plus, 47 minus.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement
from gecent.core.errors import Diagnostic, InputError
from gecent.core.output.block import Block, Code

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post

CUTCOM_CELLS = {"OFF": 40, "LEFT": 41, "RIGHT": 42, "PLUS": 46, "MINUS": 47}
# comment 22's wording (001 L29355-29358), for a G code: the manual has no comment of its own
G_NOT_AVAILABLE = "REQUESTED PREPARATORY FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE"


def cutcom(run: Post, statement: Statement) -> None:
    """CUTCOM/LEFT|RIGHT|OFF|PLUS|MINUS: TABLEG(40, 41, 42, 46, 47) in a G-only block; a
    code the machine lacks is reported and nothing is output."""
    words = statement.words()
    if len(statement.args) != 1 or len(words) != 1 or words[0] not in CUTCOM_CELLS:
        raise InputError("CUTCOM expects one of LEFT, RIGHT, OFF, PLUS or MINUS", statement.where)
    code = run.machine.g_code(CUTCOM_CELLS[words[0]])
    if code is None:
        run.warn(Diagnostic(G_NOT_AVAILABLE, statement.where))
        return
    block = Block(Code.G_ONLY, statement.number)
    block.cells[2] = code
    run.output.output(block)


HANDLERS = {"CUTCOM": cutcom}
