"""What the printouts GEOUT1-GEOUT4 share (manual §3.5.2-3.5.3, 001 L8856-9188): columns
laid out from the register tables over the option-160 print positions, the register title
centred over them, the absolute values widened to 4 integer digits (001 L8936-8965), the
bookkeeping of every block (tape frames, cut and dwell times, the ORIGIN) and the pages:
banner, machine title and page number, PARTNO, register title, option 79 lines, the times
accumulated to the page at its bottom and the tape footage on the last page.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import cache
from math import ceil
from typing import TYPE_CHECKING, Any

from gecent.core.absent import ABSENT
from gecent.core.errors import FatalError, InputError, SourcePosition
from gecent.core.machine.definition import MachineDefinition, RegisterSet
from gecent.core.machine.shuffle import cell_map
from gecent.core.motion.rotary import UNITS_PER_DEGREE, normalise
from gecent.core.output.block import Block, Code
from gecent.core.output.element import MOTION_CODES, POSITION_CODES, THREAD_CODES
from gecent.core.output.format import NO_DECIMAL_POINT
from gecent.core.output.marks import stand_in
from gecent.core.output.tape import frames_to_feet, line_frames

if TYPE_CHECKING:
    import jinja2

FIRST_COLUMN = 3  # column 2 holds the OPSKIP "/" (001 L16394-16397)
# Column 1 is the FORTRAN carriage-control character, not a print position: a line of
# option 160 print positions is option 160 + 1 characters long (docs/decisions.md).
CARRIAGE_CONTROL = 1
GAP = 1  # the least space between two fields; the spare positions are added equally
NOT_REGISTERS = frozenset({15, 19, 20})  # CODE, feed in IPM, speed in RPM
# the axes whose absolute values are printed: X, Y, Z, the rotary A and B, and C
AXIS_CELLS = (3, 4, 5, 6, 7, 18)
ROTARY_CELLS = frozenset({6, 7})
ABSOLUTE_DIGITS = 4  # the absolute columns hold 4 integer digits (001 L8936-8965)
FEED_WIDTH = 9  # F-IPM: 3 decimals, trailing zeros dropped (NPR(25) = -103)
SPEED_WIDTH = 7  # S-RPM
RECORD_WIDTH = 5  # a CL record number

# the numeric blocks the printouts lay out in columns (text blocks print their text)
PRINTABLE = (
    MOTION_CODES
    | THREAD_CODES
    | POSITION_CODES
    | {
        Code.FROM,
        Code.ROTARY_INCREMENTAL,
        Code.ROTARY_ABSOLUTE,
        Code.TURRET_CORRECTION,
        Code.NONMOTION,
        Code.AUX_ONLY,
        Code.AUX_HEAD_IPM,  # a saddle move with its F in IPM (SELECT/HED,SADDLE)
        Code.DWELL,
        Code.G_ONLY,
        Code.END,
        Code.TMARK,
        Code.CYCLE,
    }
)

# "the corrective incremental moves are not summed nor printed on the Absolute Printout,
# though they are for the Operator Printout" (CODE -3, 001 L9225-9233): a turret corrective
# move has an Incremental and an Operator line, no Absolute one (its point is unchanged)
NOT_ON_ABSOLUTE = frozenset({Code.TURRET_CORRECTION})


@dataclass(frozen=True, slots=True)
class Column:
    key: str  # a register location ("3"), "ABS-3", "F-IPM", "S-RPM" or "CLREC"
    heading: str
    width: int
    start: int = 0

    @property
    def end(self) -> int:
        """The string index after the field's last character (index 0 is column 1)."""
        return self.start - 1 + self.width


def format_width(registers: RegisterSet, location: int) -> int:
    """A register's printed width: its sign, digits and decimal point."""
    fmt = registers.formats[location]
    assert fmt is not None
    point = 1 if fmt.right and location not in NO_DECIMAL_POINT else 0
    return (1 if fmt.signed else 0) + fmt.left + point + fmt.right


def absolute_digits(machine: MachineDefinition) -> int:
    """The integer digits of the widened absolute columns: 4 (inches), one more on a
    metric machine ("a similar expansion is also made" for metric, 001 L8960-8962)."""
    return ABSOLUTE_DIGITS + (1 if machine.number_option(138) == 1 else 0)


def absolute_width(registers: RegisterSet, location: int, digits: int = ABSOLUTE_DIGITS) -> int:
    """An axis widened for its absolute values: sign, integer digits, point, decimals."""
    fmt = registers.formats[location]
    assert fmt is not None
    return 2 + digits + fmt.right


def needed(wanted: Sequence[Column], first: int = FIRST_COLUMN) -> int:
    """The print positions a line of these fields takes, from column 2, at least one blank
    apart, the first at column ``first``."""
    widths = [max(c.width, len(c.heading)) for c in wanted]
    return first - 1 - CARRIAGE_CONTROL + sum(widths) + GAP * (len(widths) - 1)


def spread(wanted: Sequence[Column], limit: int, first: int = FIRST_COLUMN) -> list[Column]:
    """The fields placed from column ``first``, each as wide as its format or its heading,
    the spare positions of the ``limit`` shared out equally between them (001
    L9543-9546). The caller has made sure they fit."""
    gap = GAP + (limit - needed(wanted, first)) // max(1, len(wanted) - 1)
    placed: list[Column] = []
    at = first
    for column in wanted:
        width = max(column.width, len(column.heading))
        placed.append(Column(column.key, column.heading, width, at))
        at += width + gap
    return placed


def centred_heading(columns: Sequence[Column]) -> str:
    """Each title centred over its field, as SETLIN places it at (NIP + NFP) / 2
    (001 L9548-9568)."""
    line = ""
    for column in columns:
        centre = column.start + (column.width - 1) // 2
        first = centre - (len(column.heading) - 1) // 2
        line = line.ljust(first - 1) + column.heading
    return line.rstrip()


def expanded_text(value: float, decimals: int, digits: int = ABSOLUTE_DIGITS) -> str:
    """An absolute value in its widened format, its integer digits with their leading
    zeros, as W9 prints them (0892.3456, 1088.1366; 001 L8945-8960), with its sign; a value
    too large for the field is stars, as a FORTRAN format prints it, never a wider field
    running into its neighbour."""
    width, form = _expanded_format(decimals, digits)
    text = form(round(value, decimals) + 0.0)
    return text if len(text) <= width else "*" * width


@cache
def _expanded_format(decimals: int, digits: int) -> tuple[int, Callable[[float], str]]:
    """The field's width and its bound format (worked out once per column: the listing
    formats every absolute column of every block)."""
    width = 2 + digits + decimals
    return width, f"{{:+0{width}.{decimals}f}}".format


class RotaryReading:
    """The rotary axes' scale readings in degrees (cells 6 and 7), for the absolute and
    operator columns: :meth:`follow` sees every block in order. A rotary block (CODE -2)
    turns its axis by its departure, read with option 118's units, option 120's sign and
    option 117's sense, as the rotary element made it; a multiaxis move turns its axes in
    the class's sense and its FROM states them (core/motion/multiaxis.py)."""

    def __init__(self, machine: MachineDefinition) -> None:
        per_degree = UNITS_PER_DEGREE.get(machine.number_option(118), 1.0)
        sign = -1.0 if machine.number_option(120) == -1 else 1.0
        scale = 1.0 if machine.number_option(117) >= 0 else -1.0
        self.degrees_per_unit = sign * scale / per_degree
        self.per_degree = per_degree
        self.degrees = dict.fromkeys(ROTARY_CELLS, 0.0)

    def follow(self, block: Block) -> None:
        if block.rotary is not None:
            cell = block.rotary[0]
            value = block.cells[cell]
            if cell in self.degrees and value is not ABSENT:
                turned = self.degrees[cell] + self.degrees_per_unit * float(value)
                self.degrees[cell] = normalise(turned)
        elif block.code is Code.LINEAR or block.code is Code.FROM:
            for cell in self.degrees:
                value = block.cells[cell]
                if value is ABSENT:
                    continue
                base = 0.0 if block.code is Code.FROM else self.degrees[cell]
                self.degrees[cell] = normalise(base + float(value) / self.per_degree)


def feed_text(ipm: float) -> str:
    return f"{ipm:.3f}".rstrip("0")


def speed_text(rpm: float) -> str:
    return f"{rpm:.1f}".rstrip("0")


def axis_sources(machine: MachineDefinition) -> dict[int, tuple[int, int]]:
    """The register cell each internal axis (CL x, y, z) is printed under, with its sign:
    option 59 as SHUFFL applies it (001 L9019-9082)."""
    return {
        target[0]: (internal, target[1])
        for internal, target in enumerate(cell_map(machine.number_option(59), "XYZ"))
        if target is not None
    }


def machine_title(machine: MachineDefinition) -> str:
    """The page's machine title (TAG)."""
    return machine.title or (f"MACHINE {machine.number}" if machine.number else "STANDARD MACHINE")


def lines_per_page(machine: MachineDefinition) -> int:
    return max(1, int(machine.number_option(79)))


def does_not_fit(machine: MachineDefinition, name: str, wanted: int) -> InputError:
    limit = int(machine.number_option(160))
    return InputError(
        f"the {name} printout's line needs {wanted} print positions, option 160 gives {limit}",
        SourcePosition(machine.origin),
    )


class Tally:
    """What a printout counts as the blocks come, printed or not: the tape's frames (for
    the footage), the cut and dwell minutes (CUTIME, DWTIME) and the ORIGIN of the
    operator data (an information block with cells[2] = 2, never punched)."""

    def __init__(self, machine: MachineDefinition) -> None:
        self.leader = stand_in(machine, 64)
        self.frames = 0
        self.cut = self.dwell = 0.0
        self.origin = (0.0, 0.0, 0.0)
        # a multihead program's ORIGIN is each head's own (OPRVAL, OPRVL2; 001 L9812-9882)
        self.origins: dict[int, tuple[float, float, float]] = {}

    def count(self, block: Block, line: str | None) -> None:
        if line is not None:
            self.frames += line_frames(line, self.leader)
        if block.code is Code.INFORMATION and block.cells[2] == 2.0:
            x, y, z = (block.cells[k] for k in (3, 4, 5))
            origin = (float(x), float(y), float(z))  # type: ignore[arg-type]
            if block.head:
                self.origins[block.head] = origin
            else:
                self.origin = origin
        self.cut += block.cut_minutes
        self.dwell += block.dwell_minutes

    def origin_of(self, head: int) -> tuple[float, float, float]:
        """The ORIGIN a head's operator values are taken from."""
        return self.origins.get(head, self.origin)

    @property
    def tape_feet(self) -> int:
        return ceil(frames_to_feet(self.frames) - 1e-9)


class Pages:
    """One printout's pages as its lines come. A page holds ``per_page`` lines and ends
    with the cut and dwell times accumulated to its last line; the last page ends with the
    run's times and the tape footage (001 L9447-9449; sample footer L10557-10558). A full
    page is held until the next line comes, since only then is it known not to be the
    last. The lines of one block are kept on one page when they fit on a page at all.

    ``frame`` gives the rest of the template's values when a page is printed (the PARTNO
    known then, the tape footage); ``opening``: the first page opens the listing (no form
    feed before it)."""

    def __init__(
        self,
        template: jinja2.Template,
        per_page: int,
        frame: Callable[[], dict[str, Any]],
        opening: bool = True,
    ) -> None:
        self.template = template
        self.per_page = per_page
        self.frame = frame
        self.opening = opening
        self.lines: list[str] = []
        self.full: tuple[list[str], float, float] | None = None  # a full page, held
        self.times = (0.0, 0.0)  # the times to the last line of the page being filled
        self.pages = 0

    def add_line(self, line: str, cut: float, dwell: float) -> str:
        """One line; ``cut`` and ``dwell`` are the times to it. Returns the pages it
        completes (a held full page)."""
        text = ""
        if self.full is not None:
            text = self._page(*self.full, last=False)
            self.full = None
        self.lines.append(line)
        self.times = (cut, dwell)
        if len(self.lines) == self.per_page:
            self.full = (self.lines, cut, dwell)
            self.lines = []
        return text

    def add(self, lines: Sequence[str], cut: float, dwell: float) -> str:
        """A block's lines, on a new page if the one being filled cannot take them all."""
        text = ""
        if self.lines and len(self.lines) + len(lines) > self.per_page:
            text = self._page(self.lines, *self.times, last=False)
            self.lines = []
        for line in lines:
            text += self.add_line(line, cut, dwell)
        return text

    def slew(self) -> str:
        """End the page being filled, with the times to its last line (MACHIN/OFF under
        option 218, 001 L26678-26687): the next line starts a new page."""
        text = ""
        if self.full is not None:
            text = self._page(*self.full, last=False)
            self.full = None
        if self.lines:
            text += self._page(self.lines, *self.times, last=False)
            self.lines = []
        return text

    def finish(self, cut: float, dwell: float) -> str:
        """The last page (and a page held before it), with the run's times; after a slew
        with no line since, a last page of its own for the times and the footage."""
        if self.lines or self.full is None:
            text = "" if self.full is None else self._page(*self.full, last=False)
            self.full = None
            return text + self._page(self.lines, cut, dwell, last=True)
        assert self.full is not None
        lines, _, _ = self.full
        self.full = None
        return self._page(lines, cut, dwell, last=True)

    def _page(self, lines: list[str], cut: float, dwell: float, last: bool) -> str:
        self.pages += 1
        return self.template.render(
            first=self.opening and self.pages == 1,
            last=last,
            number=self.pages,
            body="".join(f"{line}\n" for line in lines),  # the lines, joined here: one value
            cut=cut,
            dwell=dwell,
            **self.frame(),
        )


def single_head(block: Block, name: str) -> None:
    """GEOUT1, GEOUT2 and GEOUT4 print one head's registers: a multihead program's head-2
    or combined block (CODE +-17) is the manual's fatal error 3000 (GEPR01; "processed
    only in GEOUT3; in other GEOUTs it is an error", 001 L9395-9402)."""
    if block.halves is not None or block.head > 1:
        raise FatalError(
            3000,
            f"{name} cannot print a head-2 or combined block of a multihead program; "
            "multihead machines use GEOUT3 (option 164 = 3)",
        )
