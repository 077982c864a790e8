"""GEOUT1, the summary printout (manual §3.5.4, 001 L9410-9582).

One line per block under a title of the machine's registers, then the absolute (option
172 = 0) or operator (= 1) columns, F-IPM (F-MPM when metric) and S-RPM; cut and dwell
times at the bottom of every page and the tape length on the last one. Pages hold option
79 lines (the title lines not counted). A machine whose line does not fit the option-160
print positions gets GEOUT2 with CALCP1's warning comment (001 L9452-9476, L28989-28992).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass

from gecent.core.absent import ABSENT
from gecent.core.errors import NotYetSupported
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.listing import environment, is_page_slew
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.shuffle import cell_map
from gecent.core.output.block import TEXT_CODES, Block, Code
from gecent.core.output.sinks import PrintoutUnfit
from gecent.core.output.tape import tape_line
from gecent.plugins.printouts.layout import (
    PRINTABLE,
    ROTARY_CELLS,
    Column,
    Pages,
    RotaryReading,
    Tally,
    absolute_digits,
    absolute_width,
    centred_heading,
    expanded_text,
    feed_text,
    format_width,
    lines_per_page,
    machine_title,
    needed,
    single_head,
    speed_text,
    spread,
)

PAGE_TEMPLATE = "geout1_page.j2"
ABSOLUTE_AXES = ((3, "X"), (4, "Y"), (5, "Z"), (6, "A"), (7, "B"), (18, "C"))
# CALCP1's diagnostic when the line does not fit (001 L28989-28992)
CANNOT_BE_USED = "GEOUT1 CANNOT BE USED."
GEOUT2 = 2


def columns(machine: MachineDefinition) -> list[Column]:
    """The line layout: incremental registers in output order, then the absolute (or
    operator) axes, F-IPM, S-RPM and, with option 143 != 0, the CL record number (CALCP1,
    001 L9454-9582). A field is as wide as its format or its heading, whichever is wider;
    fields start at column 3 at least one blank apart, spread equally over the option-160
    print positions. A line that does not fit drops S-RPM, then F-IPM; if it still does
    not fit GEOUT1 cannot be used (:class:`PrintoutUnfit`: the listing is GEOUT2's)."""
    registers = machine.registers
    order = [k for k in (machine.output_order or range(1, 31)) if k not in (15, 19, 20)]
    wanted: list[Column] = [
        Column(str(k), registers.letters[k], format_width(registers, k))
        for k in order
        if registers.formats[k] is not None
    ]
    prefix = "OPR" if machine.number_option(172) == 1 else "ABS"
    digits = absolute_digits(machine)
    for location, letter in ABSOLUTE_AXES:
        if registers.formats[location] is not None:
            # the absolute columns are widened to 4 integer digits, 5 when metric (001
            # L8936-8965)
            width = absolute_width(registers, location, digits)
            wanted.append(Column(f"ABS-{location}", f"{prefix}-{letter}", width))
    wanted.append(Column("F-IPM", "F-MPM" if machine.number_option(138) == 1 else "F-IPM", 9))
    wanted.append(Column("S-RPM", "S-RPM", 7))
    if machine.number_option(143) != 0:
        wanted.append(Column("CLREC", "CLREC", 5))
    limit = int(machine.number_option(160))
    for optional in ("S-RPM", "F-IPM"):  # dropped in this order when the line is too long
        if needed(wanted) > limit:
            wanted = [c for c in wanted if c.key != optional]
    width = needed(wanted)
    if width > limit:
        detail = f"its line needs {width} print positions, option 160 gives {limit}"
        raise PrintoutUnfit(
            f"{CANNOT_BE_USED} ({detail})",
            f"{CANNOT_BE_USED} (GEOUT2 IS USED IN THIS CASE: {detail.upper()})",
            GEOUT2,
        )
    return spread(wanted, limit)


def heading(machine: MachineDefinition) -> str:
    """Each title centred over its field (001 L9548-9568)."""
    return centred_heading(columns(machine))


@dataclass(frozen=True)
class Geout1:
    number: int = 1
    name: str = "GEOUT1"
    section: str = "§3.5.4"
    template: str = PAGE_TEMPLATE

    def listing(self, machine: MachineDefinition, partno: Callable[[], str]) -> Geout1Pages:
        """The page maker of a streaming listing; ``partno`` gives the PARTNO heading."""
        return Geout1Pages(self, machine, partno)

    def render(self, machine: MachineDefinition, blocks: Iterable[Block], partno: str) -> str:
        """The whole listing of a list of blocks at once (scripts and tests)."""
        pages = self.listing(machine, lambda: partno)
        text = [pages.block(block, tape_line(block)) for block in blocks]
        text.extend(pages.finish())
        return "".join(text)


class LineMaker:
    """One block's line, with the layout's columns worked out once: the incremental
    registers as printed, the absolute (or, option 172 = 1, operator: less the ORIGIN,
    001 L9128-9134) axes, F-IPM, S-RPM and the CL record number. The absolute values are
    printed in their widened format with leading zeros (W9, 001 L8945-8960) on a block that
    moves: the linear axes at the point reached (the last one on a rotary block), the
    rotary axes A and B at their scale readings in degrees (:meth:`follow` sees every
    block)."""

    def __init__(self, machine: MachineDefinition, layout: list[Column]) -> None:
        self.step = machine.number_option(14)
        self.digits = absolute_digits(machine)
        self.point: tuple[int, ...] | None = None  # the machine point (steps), once known
        self.rotary = RotaryReading(machine)
        self.operator = 1.0 if machine.number_option(172) == 1 else 0.0
        shuffle = cell_map(machine.number_option(59), "XYZ")
        self.columns: list[tuple[int, int, int, tuple[tuple[int, int], ...], int]] = []
        for column in layout:
            key = column.key
            end = column.start - 1 + column.width
            axes: tuple[tuple[int, int], ...] = ()
            decimals = 0
            cell = 0
            if key.isdigit():
                kind, cell = REGISTER, int(key)
            elif key.startswith("ABS-"):
                kind, cell = ABSOLUTE, int(key[4:])
                fmt = machine.registers.formats[cell]
                if fmt is not None:
                    decimals = fmt.right
                    axes = tuple(
                        (internal, target[1])
                        for internal, target in enumerate(shuffle)
                        if target is not None and target[0] == cell
                    )
            else:
                kind = {"F-IPM": FEED, "S-RPM": SPEED, "CLREC": RECORD}[key]
            self.columns.append((kind, end, cell, axes, decimals))
        self.register_ends = {
            cell: end for kind, end, cell, _, _ in self.columns if kind == REGISTER
        }
        self.trailing = [
            (kind, end, cell, axes, decimals)
            for kind, end, cell, axes, decimals in self.columns
            if kind != REGISTER
        ]
        registers = [i for i, (kind, *_) in enumerate(self.columns) if kind == REGISTER]
        # words are laid out in their own order: the register columns must come first
        assert registers == list(range(len(registers)))

    def follow(self, block: Block) -> None:
        """The point a block reaches and the rotary axes' turns (every block, in order)."""
        if block.position is not None:
            self.point = block.position
        self.rotary.follow(block)

    def line(self, block: Block, origin: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> str:
        code = block.code
        if code in TEXT_CODES or code is Code.LEADER:
            return block.text or ""
        if code not in PRINTABLE:
            raise NotYetSupported(f"GEOUT1 line for a CODE {int(code)} block")
        moves = block.position is not None or block.rotary is not None
        position = block.position if block.position is not None else self.point
        degrees = self.rotary.degrees
        digits = self.digits
        cells = block.cells
        step = self.step
        operator = self.operator
        line = ""
        if code is not Code.FROM:
            # the words come in the machine's output order, which is the columns' order
            ends = self.register_ends
            for location, text in block.words:
                end = ends.get(location)
                if end is not None:
                    line = line.ljust(end - len(text)) + text
        for kind, end, cell, axes, decimals in self.trailing:
            if kind == ABSOLUTE:
                if not moves:
                    continue
                if cell in ROTARY_CELLS:
                    text = expanded_text(degrees[cell], decimals, digits)
                    line = line.ljust(end - len(text)) + text
                    continue
                if position is None:
                    continue
                for internal, sign in axes:
                    at = position[internal] * step - operator * origin[internal]
                    text = expanded_text(sign * at, decimals, digits)
                    line = line.ljust(end - len(text)) + text
            elif kind == FEED:
                if cells[19] is not ABSENT:
                    text = feed_text(float(cells[19]))
                    line = line.ljust(end - len(text)) + text
            elif kind == SPEED:
                if cells[20] is not ABSENT:
                    text = speed_text(float(cells[20]))
                    line = line.ljust(end - len(text)) + text
            elif block.record is not None:
                text = str(block.record)
                line = line.ljust(end - len(text)) + text
        line = line.rstrip()
        if code is Code.FROM:
            line = "FROM" + line[4:]
        elif code is Code.TMARK:
            line = "TMARK" + line[5:]
        if block.punch is not None and block.punch.startswith("/"):
            line = line[:1] + "/" + line[2:]
        return line


REGISTER, ABSOLUTE, FEED, SPEED, RECORD = range(5)


class Geout1Pages:
    """The pages as the blocks come, one line per printed block (:class:`Pages`)."""

    def __init__(
        self, printout: Geout1, machine: MachineDefinition, partno: Callable[[], str]
    ) -> None:
        self.printout = printout
        self.layout = columns(machine)
        self.lines = LineMaker(machine, self.layout)
        self.line = self.lines.line
        self.tally = tally = Tally(machine)
        title = machine_title(machine)
        titles = centred_heading(self.layout)
        self.pages = Pages(
            environment().get_template(PAGE_TEMPLATE),
            lines_per_page(machine),
            lambda: {
                "title": title,
                "partno": partno(),
                "heading": titles,
                "tape_feet": tally.tape_feet,
            },
        )

    def block(self, block: Block, line: str | None) -> str:
        if block.head > 1 or block.halves is not None:
            single_head(block, "GEOUT1")
        tally = self.tally
        tally.count(block, line)
        self.lines.follow(block)
        if is_page_slew(block):
            return self.pages.slew()
        if not block.printed:
            return ""
        return self.pages.add_line(self.line(block, tally.origin), tally.cut, tally.dwell)

    def finish(self) -> Iterator[str]:
        yield self.pages.finish(self.tally.cut, self.tally.dwell)

    def discard(self) -> None:
        """Nothing is held outside memory."""


@hookimpl
def register_printouts(register: Register) -> None:
    register(Geout1())
