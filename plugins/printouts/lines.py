"""The Incremental, Absolute and Operator lines of a block (manual §3.5.5-3.5.7, 001
L9583-9936), shared by GEOUT2 (the three on consecutive lines) and the multiple printouts
GEOUT3 and GEOUT4 (each a printout of its own).

One set of columns serves the three kinds, so the register title stands over all of them:
each register in output order, as wide as its printed format, its heading and, for the
axes X Y Z A B C, the absolute values widened to 4 integer digits (CALCP2's NIPA/NPTA, 001
L8936-8965, L9659-9672); F is wide enough for the feed in IPM and S for the speed in RPM.
A machine without an F or S register gets an F-IPM or S-RPM column at the end, and a
printout that shows CL record numbers on a machine without N a CLREC column.

* Incremental: the block's words as punched, without their letters (the tape image with
  its decimal points); a FROM shows its point in the widened format (001 L8936-8965).
* Absolute: the sequence number, the summed position of every axis (rotary axes in
  degrees), the feed in IPM and the speed in RPM.
* Operator: the sequence number, the absolute positions less the ORIGIN, and the block's
  other words (G, F, S, T, M ...) as on the Incremental line; not the arc centre I, J, K.
"""

from __future__ import annotations

from collections.abc import Sequence

from gecent.core.absent import ABSENT
from gecent.core.errors import NotYetSupported
from gecent.core.machine.definition import MachineDefinition, RegisterSet
from gecent.core.output.block import Block, Code
from gecent.core.output.format import RegisterFormatter
from gecent.plugins.printouts.layout import (
    AXIS_CELLS,
    FEED_WIDTH,
    FIRST_COLUMN,
    NOT_REGISTERS,
    PRINTABLE,
    RECORD_WIDTH,
    SPEED_WIDTH,
    Column,
    RotaryReading,
    absolute_digits,
    absolute_width,
    axis_sources,
    does_not_fit,
    expanded_text,
    feed_text,
    format_width,
    needed,
    speed_text,
    spread,
)

CENTRE_CELLS = frozenset({8, 9, 10})  # I, J, K: not positions, not on the Operator line
LABELS = {Code.FROM: "FROM", Code.TMARK: "TMARK"}  # printed at the line's first field
FEED, SPEED, RECORD = "F-IPM", "S-RPM", "CLREC"


def data_columns(
    machine: MachineDefinition,
    registers: RegisterSet,
    *,
    name: str,
    first: int = FIRST_COLUMN,
    records: bool = False,
    heads: Sequence[RegisterSet] = (),
) -> list[Column]:
    """The columns of one head's lines from column ``first``, spread over the option-160
    print positions; ``records``: the N column holds CL record numbers too (GEOUT2's
    Absolute line). ``heads``: every head's registers, when the heads' lines share one
    grid (GEOUT3: a register under the same register of the other head, as W17 prints
    them, 001 L9751-9757), each column as wide as the widest head needs and titled with
    this head's letter. A line that does not fit is an error naming option 160."""
    every = [registers, *(h for h in heads if h is not registers)]
    order = [k for k in (machine.output_order or range(1, 31)) if k not in NOT_REGISTERS]
    wanted: list[Column] = []
    for location in order:
        having = [h for h in every if h.formats[location] is not None]
        if not having:
            continue
        width = max(format_width(h, location) for h in having)
        if location in AXIS_CELLS:
            digits = absolute_digits(machine)
            width = max(width, *(absolute_width(h, location, digits) for h in having))
        elif location == 11:
            width = max(width, FEED_WIDTH)
        elif location == 12:
            width = max(width, SPEED_WIDTH)
        elif location == 1 and records:
            width = max(width, RECORD_WIDTH)
        letter = registers.letters[location] if registers.formats[location] is not None else ""
        wanted.append(Column(str(location), letter, width))
    if all(h.formats[11] is None for h in every):
        metric = machine.number_option(138) == 1
        wanted.append(Column(FEED, "F-MPM" if metric else "F-IPM", FEED_WIDTH))
    if all(h.formats[12] is None for h in every):
        wanted.append(Column(SPEED, "S-RPM", SPEED_WIDTH))
    if records and registers.formats[1] is None:
        wanted.append(Column(RECORD, "CLREC", RECORD_WIDTH))
    width = needed(wanted, first)
    if width > machine.number_option(160):
        raise does_not_fit(machine, name, width)
    return spread(wanted, int(machine.number_option(160)), first)


class DataLines:
    """The three kinds of line of one head's blocks. :meth:`follow` sees every block, in
    order, printed or not (the positions it reaches); the line methods then make its lines.
    A line starts at string index 0 (column 1): a prefix (the tag INC, ABS or OPR, or
    HEAD1) goes there, the OPSKIP "/" just before the first field."""

    def __init__(
        self,
        machine: MachineDefinition,
        registers: RegisterSet,
        columns: Sequence[Column],
        name: str,
    ) -> None:
        self.name = name
        self.step = machine.number_option(14)
        self.digits = absolute_digits(machine)
        self.places = [(column.key, column.end) for column in columns]
        self.first = columns[0].start - 1 if columns else 0  # the first field's index
        keys = {column.key for column in columns}
        self.feed_key = "11" if "11" in keys else FEED
        self.speed_key = "12" if "12" in keys else SPEED
        self.record_key = "1" if "1" in keys else RECORD
        self.sources = axis_sources(machine)
        self.decimals = {
            cell: fmt.right
            for cell in AXIS_CELLS
            if str(cell) in keys and (fmt := registers.formats[cell]) is not None
        }
        self.point: tuple[int, ...] | None = None  # the machine point (steps), once known
        self.rotary = RotaryReading(machine)  # the rotary scale readings in degrees
        self.degrees = self.rotary.degrees
        fmt = registers.formats[1]
        self.numbers = (
            None
            if fmt is None
            else RegisterFormatter(
                1,
                registers.letters[1],
                fmt,
                drop_trailing=False,
                decimal=machine.number_option(255) == 1,
            )
        )
        self.sequence_limit = 10**fmt.left - 1 if fmt is not None else 0

    def follow(self, block: Block) -> None:
        """The point a block reaches, and a rotary block's turn."""
        if block.position is not None:
            self.point = block.position
        self.rotary.follow(block)

    def sequence_text(self, number: int) -> str | None:
        """A unit-increasing sequence number in the N format, wrapped at SEQLIM as the
        output element wraps N (001 L9117-9126); None without an N register."""
        if self.numbers is None:
            return None
        if number > self.sequence_limit:
            number %= self.sequence_limit
        return self.numbers.format(float(number)).printed

    def check(self, block: Block) -> None:
        if block.code not in PRINTABLE:
            raise NotYetSupported(
                f"{self.name} line for a CODE {int(block.code)} block ({block.code.name})"
            )

    def incremental(self, block: Block, sequence: str | None = None) -> str:
        """The block as punched, without letters; ``sequence`` replaces its N word."""
        self.check(block)
        if block.code is Code.FROM:
            values = self._axes(block, (0.0, 0.0, 0.0))
        else:
            values = {str(location): text for location, text in block.words}
            if sequence is not None:
                values["1"] = sequence
        return self._line(block, values)

    def absolute(self, block: Block, sequence: str | None = None) -> str:
        """The summed positions, feed in IPM and speed in RPM; ``sequence`` in the N
        column (else the block's N word)."""
        self.check(block)
        values = self._axes(block, (0.0, 0.0, 0.0))
        self._number(block, values, sequence)
        cells = block.cells
        if cells[19] is not ABSENT:
            values[self.feed_key] = feed_text(float(cells[19]))
        if cells[20] is not ABSENT:
            values[self.speed_key] = speed_text(float(cells[20]))
        return self._line(block, values)

    def operator(
        self, block: Block, origin: tuple[float, float, float], sequence: str | None = None
    ) -> str:
        """The positions less the ORIGIN, with the block's other words."""
        self.check(block)
        values = {
            str(location): text
            for location, text in block.words
            if location not in AXIS_CELLS and location not in CENTRE_CELLS
        }
        values.update(self._axes(block, origin))
        self._number(block, values, sequence)
        return self._line(block, values)

    def _number(self, block: Block, values: dict[str, str], sequence: str | None) -> None:
        if block.code in LABELS:  # FROM and TMARK carry no N; their label takes its place
            values.pop(self.record_key, None)
            return
        if sequence is not None:
            values[self.record_key] = sequence
            return
        values.pop(self.record_key, None)
        word = next((text for location, text in block.words if location == 1), None)
        if word is not None:
            values["1"] = word

    def _axes(self, block: Block, origin: tuple[float, float, float]) -> dict[str, str]:
        """The absolute (``origin`` zero) or operator values of every axis once a point is
        known, on a block that moves or states a point (not on a non-motion block)."""
        if block.position is None and block.rotary is None:
            return {}
        values: dict[str, str] = {}
        point = self.point
        step = self.step
        for cell, decimals in self.decimals.items():
            if cell in self.degrees:
                values[str(cell)] = expanded_text(self.degrees[cell], decimals, self.digits)
                continue
            source = self.sources.get(cell)
            if source is None or point is None:
                continue
            internal, sign = source
            value = sign * (point[internal] * step - origin[internal])
            values[str(cell)] = expanded_text(value, decimals, self.digits)
        return values

    def _line(self, block: Block, values: dict[str, str]) -> str:
        line = ""
        for key, end in self.places:
            text = values.get(key)
            if text:
                line = line.ljust(end - len(text)) + text
        label = LABELS.get(block.code)
        at = self.first
        if label is not None:
            line = line[:at].ljust(at) + label + line[at + len(label) :]
        if block.punch is not None and block.punch.startswith("/") and at > 0:
            line = line[: at - 1].ljust(at - 1) + "/" + line[at:]
        return line.rstrip()
