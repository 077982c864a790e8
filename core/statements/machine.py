"""MACHIN/GECENT,nm[,OPTAB,n,v...][,OFF] and MACHIN/OFF met during the run (manual §3.1.1.1,
001 L2420-2445; the MACHIN subroutine, L33974-34011): the machine was chosen by the first
pass; here its options change, and OFF ends the machine's section: with option 218 = 1 the
listing prints the total cut and dwell times and slews a page (001 L26678-26687)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement
from gecent.core.errors import Diagnostic
from gecent.core.listing import page_slew, totals_text
from gecent.core.machine.selection import apply_machin_options, is_machin_off, parse_machin
from gecent.core.output.block import Block, Code

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post


def machin(run: Post, statement: Statement) -> None:
    if is_machin_off(statement):
        machin_off(run, statement)
        return
    request = parse_machin(statement)
    if request is None:
        return  # another postprocessor's MACHIN: reported when the machine was chosen
    if request.number is not None and run.machine.number != request.number:
        # --machine stands for the manual's PTONLY/2 run: the tape's MACHIN statements choose
        # no machine, but "it will recognize all of the MACHIN statements for changes to the
        # option table" (001 L2553-2565): only the number is ignored
        used = f"THE RUN USES MACHINE {run.machine.label}"
        text = (
            f"MACHIN/GECENT,{request.number}: {used}; ONLY THE MACHINE NUMBER IS IGNORED, "
            "ITS OPTAB CHANGES APPLY"
            if request.options or request.modifiers
            else f"MACHIN/GECENT,{request.number} IGNORED: {used}"
        )
        run.warn(Diagnostic(text, statement.where))
    changed, notes = apply_machin_options(run.machine, request)
    if changed is not run.machine:
        run.rebuild(changed)
    for note in notes:
        run.warn(note)
    if request.off:
        machin_off(run, statement)


def machin_off(run: Post, statement: Statement) -> None:
    """The OFF modifier: option 218 = 1 prints the total cut and dwell times so far and
    slews a page (001 L26678-26687); with 0 it prints nothing."""
    if run.machine.number_option(218) != 1:
        return
    output = run.output
    totals = totals_text(output.cut_minutes, output.dwell_minutes)
    run.text_block(Block(Code.COMMENT, statement.number, totals))
    run.text_block(page_slew(statement.number))


HANDLERS = {
    "MACHIN": machin,
}
