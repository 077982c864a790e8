"""GEOUT2, the combined printout (manual §3.5.5, 001 L9583-9707).

The Incremental, Absolute and Operator data of a block on consecutive lines tagged INC,
ABS and OPR, under one register title (plugins/printouts/lines.py). A motion record
(moves, circles, positioning, rotary, thread, cycle, FROM) prints all three; any other
block only its INC line, and its ABS line too when it carries a spindle speed. The INC
and OPR lines show a unit-increasing sequence number whatever option 143 says, the ABS
line the CL record number; the tape keeps its own N (docs/decisions.md). Text blocks print
their text. Cut and dwell times at the bottom of every page, the tape footage on the last;
pages hold option 79 lines. GEOUT1 falls back to it when its line does not fit (§3.5.4).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass

from gecent.core.absent import ABSENT
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.listing import environment, is_page_slew
from gecent.core.machine.definition import MachineDefinition
from gecent.core.output.block import TEXT_CODES, Block, Code
from gecent.core.output.element import MOTION_CODES, POSITION_CODES, THREAD_CODES
from gecent.core.output.tape import tape_line
from gecent.plugins.printouts.layout import (
    FIRST_COLUMN,
    NOT_ON_ABSOLUTE,
    Pages,
    Tally,
    centred_heading,
    lines_per_page,
    machine_title,
    single_head,
)
from gecent.plugins.printouts.lines import DataLines, data_columns

PAGE_TEMPLATE = "geout2_page.j2"
TAG_WIDTH = 3  # INC, ABS, OPR
# the records printed on three lines (a FROM states the point the summing starts from)
MOTION_RECORDS = (
    MOTION_CODES
    | POSITION_CODES
    | THREAD_CODES
    | {
        Code.ROTARY_INCREMENTAL,
        Code.ROTARY_ABSOLUTE,
        Code.TURRET_CORRECTION,
        Code.CYCLE,
        Code.FROM,
    }
)


@dataclass(frozen=True)
class Geout2:
    number: int = 2
    name: str = "GEOUT2"
    section: str = "§3.5.5"
    template: str = PAGE_TEMPLATE

    def listing(self, machine: MachineDefinition, partno: Callable[[], str]) -> Geout2Pages:
        """The page maker of a streaming listing; ``partno`` gives the PARTNO heading."""
        return Geout2Pages(machine, partno)

    def render(self, machine: MachineDefinition, blocks: Iterable[Block], partno: str) -> str:
        """The whole listing of a list of blocks at once (scripts and tests)."""
        pages = self.listing(machine, lambda: partno)
        text = [pages.block(block, tape_line(block)) for block in blocks]
        text.extend(pages.finish())
        return "".join(text)


class Geout2Pages:
    """The pages as the blocks come; a block's lines stay on one page (:class:`Pages`)."""

    def __init__(self, machine: MachineDefinition, partno: Callable[[], str]) -> None:
        registers = machine.registers
        columns = data_columns(
            machine, registers, name="GEOUT2", first=FIRST_COLUMN + TAG_WIDTH, records=True
        )
        self.data = DataLines(machine, registers, columns, "GEOUT2")
        self.tally = tally = Tally(machine)
        self.count = 0  # the unit-increasing sequence number
        title = machine_title(machine)
        heading = centred_heading(columns)
        self.pages = Pages(
            environment().get_template(PAGE_TEMPLATE),
            lines_per_page(machine),
            lambda: {
                "title": title,
                "partno": partno(),
                "heading": heading,
                "tape_feet": tally.tape_feet,
            },
        )

    def block(self, block: Block, line: str | None) -> str:
        single_head(block, "GEOUT2")
        tally = self.tally
        tally.count(block, line)
        data = self.data
        data.follow(block)
        if is_page_slew(block):
            return self.pages.slew()
        if not block.printed:
            return ""
        code = block.code
        if code in TEXT_CODES or code is Code.LEADER:
            text = block.text or ""
            if code is Code.INSERT:  # tape data: an INC line, as every line of the tape
                text = "INC".ljust(data.first) + text
            return self.pages.add_line(text, tally.cut, tally.dwell)
        sequence = None
        if block.punched and code is not Code.TMARK:  # (TMARK's code is where its N is)
            # every tape block is numbered, whatever the tape's N (option 143, SEQNO)
            self.count += 1
            sequence = data.sequence_text(self.count)
        lines = [_tagged("INC", data.incremental(block, sequence))]
        record = None if block.record is None else str(block.record)
        if code in MOTION_RECORDS:
            if code not in NOT_ON_ABSOLUTE:  # (a turret correction has no ABS line)
                lines.append(_tagged("ABS", data.absolute(block, record)))
            lines.append(_tagged("OPR", data.operator(block, tally.origin, sequence)))
        elif block.cells[20] is not ABSENT:  # a spindle speed: its RPM on the ABS line
            lines.append(_tagged("ABS", data.absolute(block, record)))
        return self.pages.add(lines, tally.cut, tally.dwell)

    def finish(self) -> Iterator[str]:
        yield self.pages.finish(self.tally.cut, self.tally.dwell)

    def discard(self) -> None:
        """Nothing is held outside memory."""


def _tagged(tag: str, line: str) -> str:
    return tag + line[TAG_WIDTH:]


@hookimpl
def register_printouts(register: Register) -> None:
    register(Geout2())
