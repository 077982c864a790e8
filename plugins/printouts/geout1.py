"""GEOUT1, the summary printout (manual §3.5.4, 001 L9410-9582).

One line per block under a title of the machine's registers, then the absolute (option
172 = 0) or operator (= 1) columns, F-IPM (F-MPM when metric) and S-RPM; cut and dwell
times at the bottom of every page and the tape length on the last one. Pages hold option
79 lines (the title lines not counted).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from math import ceil

from gecent.core.absent import ABSENT
from gecent.core.errors import NotYetSupported
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.listing import environment
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.shuffle import cell_map
from gecent.core.output.block import TEXT_CODES, Block, Code
from gecent.core.output.element import MOTION_CODES, POSITION_CODES, THREAD_CODES
from gecent.core.output.format import NO_DECIMAL_POINT
from gecent.core.output.marks import stand_in
from gecent.core.output.tape import frames_to_feet, line_frames, tape_line

PAGE_TEMPLATE = "geout1_page.j2"
ABSOLUTE_AXES = ((3, "X"), (4, "Y"), (5, "Z"), (6, "A"), (7, "B"), (18, "C"))
FIRST_COLUMN = 3  # column 2 holds the OPSKIP "/" (001 L16394-16397)
# Column 1 is the FORTRAN carriage-control character, not a print position: a line of
# option 160 print positions is option 160 + 1 characters long (docs/decisions.md).
CARRIAGE_CONTROL = 1
GAP = 1  # the least space between two fields; the spare positions are added equally


@dataclass(frozen=True, slots=True)
class Column:
    key: str  # a register location ("3"), "ABS-3", "F-IPM", "S-RPM" or "CLREC"
    heading: str
    width: int
    start: int = 0


def _format_width(machine: MachineDefinition, location: int) -> int:
    fmt = machine.registers.formats[location]
    assert fmt is not None
    point = 1 if fmt.right and location not in NO_DECIMAL_POINT else 0
    return (1 if fmt.signed else 0) + fmt.left + point + fmt.right


def columns(machine: MachineDefinition) -> list[Column]:
    """The line layout: incremental registers in output order, then the absolute (or
    operator) axes, F-IPM, S-RPM and, with option 143 != 0, the CL record number (CALCP1,
    001 L9454-9582). A field is as wide as its format or its heading, whichever is wider;
    fields start at column 3 at least one blank apart, spread equally over the option-160
    print positions. A line that does not fit drops S-RPM, then F-IPM; if it still does
    not fit GEOUT1 cannot be used (GEOUT2, not built yet)."""
    registers = machine.registers
    order = [k for k in (machine.output_order or range(1, 31)) if k not in (15, 19, 20)]
    wanted: list[Column] = [
        Column(str(k), registers.letters[k], _format_width(machine, k))
        for k in order
        if registers.formats[k] is not None
    ]
    prefix = "OPR" if machine.number_option(172) == 1 else "ABS"
    for location, letter in ABSOLUTE_AXES:
        fmt = registers.formats[location]
        if fmt is not None:
            # the absolute columns are widened to 4 integer digits (001 L8936-8965)
            wanted.append(Column(f"ABS-{location}", f"{prefix}-{letter}", 2 + 4 + fmt.right))
    wanted.append(Column("F-IPM", "F-MPM" if machine.number_option(138) == 1 else "F-IPM", 9))
    wanted.append(Column("S-RPM", "S-RPM", 7))
    if machine.number_option(143) != 0:
        wanted.append(Column("CLREC", "CLREC", 5))
    limit = int(machine.number_option(160))
    for optional in ("S-RPM", "F-IPM"):  # dropped in this order when the line is too long
        if _needed(wanted) > limit:
            wanted = [c for c in wanted if c.key != optional]
    needed = _needed(wanted)
    if needed > limit:
        raise NotYetSupported(
            f"GEOUT2 printout: GEOUT1 CANNOT BE USED. (its line needs {needed} print "
            f"positions, option 160 gives {limit})"
        )
    # the spare positions are shared out equally between the fields (001 L9543-9546)
    gap = GAP + (limit - needed) // max(1, len(wanted) - 1)
    placed: list[Column] = []
    at = FIRST_COLUMN
    for column in wanted:
        width = max(column.width, len(column.heading))
        placed.append(Column(column.key, column.heading, width, at))
        at += width + gap
    return placed


def _needed(wanted: list[Column]) -> int:
    widths = [max(c.width, len(c.heading)) for c in wanted]
    return FIRST_COLUMN - 1 - CARRIAGE_CONTROL + sum(widths) + GAP * (len(widths) - 1)


def heading(machine: MachineDefinition) -> str:
    """Each title centred over its field, as SETLIN places it at (NIP + NFP) / 2
    (001 L9548-9568)."""
    line = ""
    for column in columns(machine):
        centre = column.start + (column.width - 1) // 2
        first = centre - (len(column.heading) - 1) // 2
        line = line.ljust(first - 1) + column.heading
    return line.rstrip()


def _absolute(value: float, decimals: int) -> str:
    return f"{round(value, decimals) + 0.0:+.{decimals}f}"  # + 0.0: no "-0.0000"


# the numeric blocks GEOUT1 lays out in columns (text blocks print their text)
PRINTABLE = (
    MOTION_CODES
    | THREAD_CODES
    | POSITION_CODES
    | {
        Code.FROM,
        Code.ROTARY_INCREMENTAL,
        Code.NONMOTION,
        Code.AUX_ONLY,
        Code.DWELL,
        Code.G_ONLY,
        Code.END,
        Code.TMARK,
        Code.CYCLE,
    }
)


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
        text.append(pages.finish())
        return "".join(text)


class LineMaker:
    """One block's line, with the layout's columns worked out once: the incremental
    registers as printed, the absolute (or, option 172 = 1, operator: less the ORIGIN,
    001 L9128-9134) axes, F-IPM, S-RPM and the CL record number."""

    def __init__(self, machine: MachineDefinition, layout: list[Column]) -> None:
        self.step = machine.number_option(14)
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
            (kind, end, axes, decimals)
            for kind, end, _, axes, decimals in self.columns
            if kind != REGISTER
        ]
        registers = [i for i, (kind, *_) in enumerate(self.columns) if kind == REGISTER]
        # words are laid out in their own order: the register columns must come first
        assert registers == list(range(len(registers)))

    def line(self, block: Block, origin: tuple[float, float, float] = (0.0, 0.0, 0.0)) -> str:
        code = block.code
        if code in TEXT_CODES or code is Code.LEADER:
            return block.text or ""
        if code not in PRINTABLE:
            raise NotYetSupported(f"GEOUT1 line for a CODE {int(code)} block")
        position = block.position
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
        for kind, end, axes, decimals in self.trailing:
            if kind == ABSOLUTE:
                if position is None:
                    continue
                for internal, sign in axes:
                    at = position[internal] * step - operator * origin[internal]
                    text = _absolute(sign * at, decimals)
                    line = line.ljust(end - len(text)) + text
            elif kind == FEED:
                if cells[19] is not ABSENT:
                    text = f"{float(cells[19]):.3f}".rstrip("0")
                    line = line.ljust(end - len(text)) + text
            elif kind == SPEED:
                if cells[20] is not ABSENT:
                    text = f"{float(cells[20]):.1f}".rstrip("0")
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
    """The pages as the blocks come: each page ends with the cut and dwell times
    accumulated to it, the last with the tape footage (001 L9447-9449; sample footer
    L10557-10558). A full page is held until the next line comes, since only then is it
    known not to be the last."""

    def __init__(
        self, printout: Geout1, machine: MachineDefinition, partno: Callable[[], str]
    ) -> None:
        self.printout = printout
        self.machine = machine
        self.partno = partno
        self.layout = columns(machine)
        self.line = LineMaker(machine, self.layout).line
        self.per_page = max(1, int(machine.number_option(79)))
        self.leader = stand_in(machine, 64)
        self.title = machine.title or (
            f"MACHINE {machine.number}" if machine.number else "STANDARD MACHINE"
        )
        self.heading = heading(machine)
        self.template = environment().get_template(PAGE_TEMPLATE)
        self.lines: list[str] = []
        self.full: tuple[list[str], float, float] | None = None  # a full page, held
        self.pages = 0
        self.cut = self.dwell = 0.0
        self.frames = 0
        self.origin = (0.0, 0.0, 0.0)

    def block(self, block: Block, line: str | None) -> str:
        if line is not None:
            self.frames += line_frames(line, self.leader)
        if block.code is Code.INFORMATION and block.cells[2] == 2.0:
            x, y, z = (block.cells[k] for k in (3, 4, 5))
            self.origin = (float(x), float(y), float(z))  # type: ignore[arg-type]
        self.cut += block.cut_minutes
        self.dwell += block.dwell_minutes
        if not block.printed:
            return ""
        text = ""
        if self.full is not None:
            text = self._page(*self.full, last=False)
            self.full = None
        self.lines.append(self.line(block, self.origin))
        if len(self.lines) == self.per_page:
            self.full = (self.lines, self.cut, self.dwell)
            self.lines = []
        return text

    def finish(self) -> str:
        if self.lines or (self.pages == 0 and self.full is None):
            text = "" if self.full is None else self._page(*self.full, last=False)
            self.full = None
            return text + self._page(self.lines, self.cut, self.dwell, last=True)
        assert self.full is not None
        lines, _, _ = self.full
        self.full = None
        return self._page(lines, self.cut, self.dwell, last=True)

    def _page(self, lines: list[str], cut: float, dwell: float, last: bool) -> str:
        self.pages += 1
        return self.template.render(
            first=self.pages == 1,
            last=last,
            number=self.pages,
            body="".join(f"{line}\n" for line in lines),  # the lines, joined here: one value
            cut=cut,
            dwell=dwell,
            title=self.title,
            partno=self.partno(),
            heading=self.heading,
            tape_feet=ceil(frames_to_feet(self.frames) - 1e-9),
        )


@hookimpl
def register_printouts(register: Register) -> None:
    register(Geout1())
