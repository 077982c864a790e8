"""GEOUT4, the multiple printout of a single-head machine (manual §3.5.7, 001
L9883-9936; the standard printout of GECENT II).

Separate Incremental, Absolute and Operator printouts as option 17 asks (100, 10, 1; a
digit 2 leaves out the middle segments of a segmented departure), each titled
``*** INCREMENTAL ***``, ``*** ABSOLUTE ***`` or ``*** OPERATOR ***`` with its own page
numbers and its times and tape footage at its end; the first is printed as the blocks come,
the others are kept in temporary files until the run ends (plugins/printouts/multiple.py).
The Absolute and Operator lines carry the block's N, as the Incremental one does.
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.hookspecs import Register, hookimpl
from gecent.plugins.printouts.multiple import PAGE_TEMPLATE, MultiplePrintout


@dataclass(frozen=True)
class Geout4(MultiplePrintout):
    number: int = 4
    name: str = "GEOUT4"
    section: str = "§3.5.7"
    template: str = PAGE_TEMPLATE


@hookimpl
def register_printouts(register: Register) -> None:
    register(Geout4())
