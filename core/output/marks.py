"""Leader and tape marks (manual §3.5.3.2 CODE -8 and +8, 001 L9298-9324; options 64, 65,
98, 99, 146).

LEADER/L punches whole 72-column cards of the option-64 space code: ``<0.14 L + 1>`` cards,
printed as ``7.2 N - 1`` inches, and that many tenths of an inch of frames are punched
(docs/decisions.md). TMARK punches the option-65 end-of-record code where the sequence
number would be, with the words options 98 and 146 ask for.
"""

from __future__ import annotations

from math import floor

from gecent.core.errors import InputError, SourcePosition
from gecent.core.machine.definition import MachineDefinition
from gecent.core.output.block import Block, Code

FRAMES_PER_INCH = 10


def stand_in(machine: MachineDefinition, option: int) -> str:
    """The BCD stand-in of options 64-67: only the first character counts."""
    value = machine.option(option)
    return (str(value) or " ")[0]


def leader_cards(requested: float) -> int:
    return floor(requested * 0.14 + 1)


def leader_inches(requested: float) -> float:
    return 7.2 * leader_cards(requested) - 1


def leader_block(
    machine: MachineDefinition,
    requested: float,
    record: int | None,
    where: SourcePosition | None,
) -> Block:
    if requested < 0:
        raise InputError(f"LEADER expects a length in inches >= 0, found {requested:g}", where)
    inches = leader_inches(requested)
    block = Block(Code.LEADER, record, f"{inches:.1f} INCHES OF LEADER HERE")
    block.cells[3] = requested
    block.punch = stand_in(machine, 64) * round(inches * FRAMES_PER_INCH)
    return block


def tmark_cells(machine: MachineDefinition, block: Block) -> None:
    """Option 98: an F in every non-motion block (stored, not printed, in a TMARK block);
    option 146: +1 adds G = TABLEG(5), -1 adds that G and S = option 99 (001 L26119-26130)."""
    feed = machine.number_option(98)
    if feed:
        block.cells[11] = feed
    contents = machine.number_option(146)
    dwell_g = machine.g_code(5)
    if contents in (1.0, -1.0) and dwell_g is not None:
        block.cells[2] = dwell_g
    if contents == -1.0:
        block.cells[12] = machine.number_option(99)
