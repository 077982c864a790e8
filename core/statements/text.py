"""PARTNO, PPRINT and INSERT: text printed and, for PARTNO and INSERT, punched as written
(manual §3.5.3.2 CODE -7, +7, +6; 001 L9087-9098, L9189-9296). Under gecent option 257 = 1
PARTNO and PPRINT are punched as comments in parentheses, which modern controls skip."""

from __future__ import annotations

import unicodedata
from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement
from gecent.core.errors import Diagnostic, SourcePosition
from gecent.core.output.block import Block, Code

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post


def partno(run: Post, statement: Statement) -> None:
    """The first PARTNO starts the first tape reel: the punch puts the readable PARTNO
    there (options 20, 161, 163; core/output/sinks.py). Option 169 = 1 leaves the PARTNO
    itself (its "non-readable image") off the tape: printed only, as PPRINT is
    (001 L26328-26338)."""
    text = statement.text or ""
    first = not run.result.partno
    if first:
        run.result.partno = run.sinks.partno = text
    if run.machine.number_option(169) == 1:
        block = Block(Code.PPRINT, statement.number, text)
    else:
        block = _comment(run, Code.PARTNO, statement.number, text, statement.where)
    block.reel = 1 if first else 0
    run.text_block(block)


def pprint(run: Post, statement: Statement) -> None:
    text = statement.text or ""
    run.text_block(_comment(run, Code.PPRINT, statement.number, text, statement.where))


def _comment(run: Post, code: Code, number: int, text: str, where: SourcePosition) -> Block:
    """The text block, or under option 257 = 1 a punched comment: "(TEXT)", a parenthesis
    inside the text turned into a bracket, since controls end a comment at the first ")",
    and the text held to what the tape can carry (see :func:`carried`)."""
    if run.machine.number_option(257) != 1:
        return Block(code, number, text)
    inner, replaced = carried(text.strip().translate(_BRACKETS), run.sinks.punch_characters)
    if replaced:
        shown = ", ".join(repr(c) for c in replaced)
        run.warn(Diagnostic(f"{code.name} TEXT: {shown} CANNOT GO ON THE TAPE; REPLACED", where))
    block = Block(Code.INSERT, number, f"({inner})")
    block.keep_blanks = run.machine.number_option(256) == 1
    return block


_BRACKETS = str.maketrans("()", "[]")


def carried(text: str, punchable: frozenset[str] | None) -> tuple[str, list[str]]:
    """A comment's text as the tape can carry it: printable ASCII (a tab and a % are blanks,
    an accented letter its base letter), and with a punch only the punch code's characters
    (a lower-case letter in upper case, anything else a blank). Also what was replaced (a
    letter put in upper case is not counted)."""
    kept: list[str] = []
    replaced: list[str] = []
    for character in text:
        new = character
        if character == "\t" or character == "%":  # % ends a program on the tape
            new = " "
        elif not " " <= character <= "~":
            base = unicodedata.normalize("NFKD", character).encode("ascii", "ignore").decode()
            new = base if base and all(" " <= c <= "~" for c in base) else " "
        if punchable is not None:
            new = "".join(
                c if c in punchable else c.upper() if c.upper() in punchable else " " for c in new
            )
        if new not in (character, character.upper()) and character not in replaced:
            replaced.append(character)
        kept.append(new)
    return "".join(kept), replaced


def insert(run: Post, statement: Statement) -> None:
    run.text_block(Block(Code.INSERT, statement.number, statement.text or ""))


HANDLERS = {
    "PARTNO": partno,
    "PPRINT": pprint,
    "INSERT": insert,
}
