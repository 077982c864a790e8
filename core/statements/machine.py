"""MACHIN/GECENT,nm[,OPTAB,n,v...] met during the run (manual §3.1.1.1, 001 L2420-2445):
the machine was chosen by the first pass; here its options change."""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement
from gecent.core.errors import Diagnostic
from gecent.core.machine.selection import apply_machin_options, parse_machin

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post


def machin(run: Post, statement: Statement) -> None:
    request = parse_machin(statement)
    if request is None:
        return  # another postprocessor's MACHIN: reported when the machine was chosen
    if request.number is not None and run.machine.number != request.number:
        run.warn(
            Diagnostic(
                f"MACHIN/GECENT,{request.number} IGNORED: THE RUN USES MACHINE {run.machine.label}",
                statement.where,
            )
        )
    changed, notes = apply_machin_options(run.machine, request)
    if changed is not run.machine:
        run.rebuild(changed)
    for note in notes:
        run.warn(note)


HANDLERS = {
    "MACHIN": machin,
}
