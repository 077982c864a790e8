"""SEQNO, TRANS and ORIGIN (manual SEQNO 001 L37337-37373, TRANS L38801-38835, ORIGIN
L34267-34308), read in docs/research/statements-misc.md §11, §15, §16."""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement
from gecent.core.errors import Diagnostic, InputError
from gecent.core.output.block import Block, Code

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post


def seqno(run: Post, statement: Statement) -> None:
    """SEQNO/n[,INCR,k]: the blocks that follow are numbered n, n + k, ...; SEQNO/OFF drops
    the N word; SEQNO/ON numbers by option 143 again, or resumes a series."""
    numbering = run.state.numbering
    words = statement.words()
    numbers = statement.numbers()
    if len(words) == 1 and words[0] in ("ON", "OFF") and not numbers:
        if words[0] == "OFF":
            numbering.off = True
        else:
            numbering.switch_on(run.machine.number_option(143))
        return
    if words not in ((), ("INCR",)) or len(numbers) != (2 if words else 1):
        raise InputError("SEQNO expects n[,INCR,k], ON or OFF", statement.where)
    if any(v != int(v) or v < 0 for v in numbers):
        raise InputError("SEQNO expects whole numbers >= 0", statement.where)
    increment = int(numbers[1]) if words else 1
    start = int(numbers[0])
    if numbering.series is not None and start < numbering.series[0] and not numbering.off:
        # the CL asks for it; a control's block search finds the first of the two
        run.warn(
            Diagnostic(
                f"SEQNO/{start}: THE TAPE HAS REACHED N{numbering.series[0] - 1}; "
                "BLOCK NUMBERS REPEAT",
                statement.where,
            )
        )
    numbering.series = (start, increment)
    numbering.off = False


def trans(run: Post, statement: Statement) -> None:
    """TRANS/x,y,z: replaces the translation added to every later CL point (L38816-38819);
    an incremental machine's next departure carries the change. On a positioning machine
    the tool-length term of option 86 is kept in z (core/tool.py)."""
    numbers = statement.numbers()
    if len(numbers) != len(statement.args) or not 1 <= len(numbers) <= 3:
        raise InputError("TRANS expects up to three distances x, y, z", statement.where)
    x, y, z = (*(run.units.length(v) for v in numbers), 0.0, 0.0)[:3]
    # option 86 = 1 or 2: the tool length stays in z (TOOLEN "may be figured into z",
    # L38833-38835), as TOOLGP put it there
    run.state.position.translation = (x, y, z + run.tool.length_term)


def origin(run: Post, statement: Statement) -> None:
    """ORIGIN/x,y,z: for the operator printout only, carried by an information block
    (CODE -9, never printed or punched): OPR = absolute - origin."""
    numbers = statement.numbers()
    if len(numbers) != len(statement.args) or not 1 <= len(numbers) <= 3:
        raise InputError("ORIGIN expects up to three coordinates x, y, z", statement.where)
    x, y, z = (*(run.units.length(v) for v in numbers), 0.0, 0.0)[:3]
    run.state.modes.origin = (x, y, z)
    block = Block(Code.INFORMATION, statement.number)
    block.cells[2] = 2.0
    block.cells[3], block.cells[4], block.cells[5] = x, y, z
    run.text_block(block)


HANDLERS = {"SEQNO": seqno, "TRANS": trans, "ORIGIN": origin}
