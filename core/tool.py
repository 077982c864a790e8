"""Loading a tool: TOOLNO/n and APT IV's LOADTL/n on a contouring mill (manual TOOLNO
001 L38733-38799 and TOOLGM L38605-38646, read in docs/research/spindle-tool.md).

The tool-change M code TABLEM(7) waits for the next block (STOREM). A machine with a T
register gets a dwell block of option 83 seconds carrying the T word; one without (MACH23)
records the tool and outputs nothing. Tool length changes, offsets, lathes and positioning
machines are not built yet and stop the run with an error naming them.
"""

from __future__ import annotations

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import InputError, NotYetSupported
from gecent.core.output.element import OutputElement
from gecent.core.reinstate import T_CODE
from gecent.core.state import PostState


class ToolElement:
    def __init__(self, state: PostState, output: OutputElement) -> None:
        self.state = state
        self.output = output

    def statement(self, statement: Statement) -> None:
        machine = self.state.machine
        words = [a.name for a in statement.args if isinstance(a, Word)]
        if words:
            raise NotYetSupported(f"{statement.major}/{words[0]}", statement.where)
        numbers = statement.numbers()
        if len(numbers) != 1 or numbers[0] < 0 or numbers[0] != int(numbers[0]):
            raise InputError(
                f"{statement.major} expects one tool number, a whole number >= 0", statement.where
            )
        if machine.number_option(1) != 0:
            raise NotYetSupported(
                f"{statement.major} on a positioning machine (TOOLGP)", statement.where
            )
        if machine.number_option(132) != 1:
            raise NotYetSupported(f"{statement.major} on a lathe (TOOLL)", statement.where)
        tool = numbers[0]
        self.state.tool.number = tool
        if machine.registers.formats[13] is not None:
            self.state.remember(T_CODE, tool)
        change = machine.m_code(7)
        if change is not None:
            self.output.store_m(change)
        if machine.registers.formats[13] is not None:
            block = self.output.dwell(machine.number_option(83))
            block.record = statement.number
            block.cells[13] = tool
            self.output.output(block)
