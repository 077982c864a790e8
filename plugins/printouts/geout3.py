"""GEOUT3, the multiple printout of a multihead machine (manual §3.5.6, 001 L9708-9882).

The Incremental, Absolute and Operator printouts of GEOUT4, as option 17 asks, for a
machine with two heads: each line starts HEAD1 or HEAD2 and is laid out in that head's
registers (REGSTR/REGFOR for head 1, GMWORD/GMFORM for head 2; CALCP3 is called once per
head, L9771-9811), the register title has a line per head, and a combined block (CODE
+-17, GMHBUF 1-40) prints as two lines, head 1's then head 2's, for one tape block with one
end of block (L9812-9882). Comments are on the Incremental printout only. A single-head
machine's GEOUT3 prints as GEOUT4 does, without the head prefixes.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.core.output.block import Block
from gecent.plugins.printouts.multiple import PAGE_TEMPLATE, HeadLayout, MultiplePrintout


@dataclass(frozen=True)
class Geout3(MultiplePrintout):
    number: int = 3
    name: str = "GEOUT3"
    section: str = "§3.5.6"
    template: str = PAGE_TEMPLATE

    def layouts(self, machine: MachineDefinition) -> list[HeadLayout]:
        if len(machine.heads) == 1:
            return [HeadLayout("", machine.registers)]
        return [
            HeadLayout(f"HEAD{number}", registers)
            for number, registers in enumerate(machine.heads[:2], start=1)
        ]

    def parts(self, block: Block) -> Sequence[tuple[int, Block]]:
        if block.halves is not None:
            return tuple(enumerate(block.halves))
        return ((max(block.head, 1) - 1, block),)


@hookimpl
def register_printouts(register: Register) -> None:
    register(Geout3())
