"""The multiple printouts GEOUT3 and GEOUT4 (manual §3.5.6-3.5.7, 001 L9708-9936): a
separate Incremental, Absolute and Operator printout, as option 17 asks, one after the
other, each under its own title (*** INCREMENTAL *** ...), with its own page numbers and
its cut and dwell times and tape footage at its end (TIMES).

The first printout asked for is printed as the blocks come; the others are written line by
line to temporary files as they come (GMWRIT to TAPES1 and TAPES4) and printed after it
when the run ends (ABSOPR). A digit 2 in option 17 leaves out of its printout the middle
segments of a departure the postprocessor segmented (only the first and last points).
Comments (CODE +9) are on the Incremental printout only; PPRINT, PARTNO, INSERT, LEADER,
TMARK and FROM lines are on all of them.

:class:`MultiplePrintout` takes the heads' layouts, a line prefix and a register table
each: GEOUT4 prints one head unprefixed; GEOUT3 prefixes HEAD1, HEAD2 with each head's
registers and says which head each part of a block belongs to (:meth:`parts`).
"""

from __future__ import annotations

import json
import os
import tempfile
from collections.abc import Callable, Iterable, Iterator, Sequence
from contextlib import suppress
from dataclasses import dataclass
from typing import IO

from gecent.core.errors import InputError, SourcePosition
from gecent.core.listing import environment, is_page_slew
from gecent.core.machine.definition import MachineDefinition, RegisterSet
from gecent.core.output.block import TEXT_CODES, Block, Code
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

PAGE_TEMPLATE = "multiple_page.j2"
INCREMENTAL, ABSOLUTE, OPERATOR = "INCREMENTAL", "ABSOLUTE", "OPERATOR"
KINDS = (INCREMENTAL, ABSOLUTE, OPERATOR)  # option 17's digits: 100, 10, 1


def requested(machine: MachineDefinition) -> list[tuple[str, bool]]:
    """Option 17 (001 L24571-24591): the printouts in order, each with True when its digit
    is 2 (the first and last points of a segmented departure only)."""
    value = machine.number_option(17)
    digits = f"{int(value):03d}" if value == int(value) and 0 <= value <= 222 else ""
    if len(digits) != 3 or not set(digits) <= set("012"):
        raise InputError(
            f"option 17 = {value:g}: its digits (incremental, absolute, operator) are "
            "0 (not printed), 1 (printed) or 2 (printed without the middle segments)",
            SourcePosition(machine.origin),
        )
    return [(kind, digit == "2") for kind, digit in zip(KINDS, digits, strict=True) if digit != "0"]


@dataclass(frozen=True, slots=True)
class HeadLayout:
    """One head's lines: the prefix at their start and the head's register table."""

    prefix: str
    registers: RegisterSet


class MultiplePrintout:
    """The plugin side of GEOUT3 and GEOUT4: a subclass names itself and its heads."""

    number: int
    name: str
    section: str
    template: str

    def layouts(self, machine: MachineDefinition) -> list[HeadLayout]:
        """One head, unprefixed (GEOUT4)."""
        return [HeadLayout("", machine.registers)]

    def parts(self, block: Block) -> Sequence[tuple[int, Block]]:
        """The parts of a numeric block, each with the index of the head (layout) it is
        printed under: the block itself, under the only head."""
        single_head(block, self.name)
        return ((0, block),)

    def listing(self, machine: MachineDefinition, partno: Callable[[], str]) -> MultiplePages:
        """The page maker of a streaming listing; ``partno`` gives the PARTNO heading."""
        return MultiplePages(self, machine, partno)

    def render(self, machine: MachineDefinition, blocks: Iterable[Block], partno: str) -> str:
        """The whole listing of a list of blocks at once (scripts and tests)."""
        pages = self.listing(machine, lambda: partno)
        text = [pages.block(block, tape_line(block)) for block in blocks]
        text.extend(pages.finish())
        return "".join(text)


class Spool:
    """A printout's lines kept until the run ends, one JSON line per block (its lines and
    the times to it), in a temporary file whose name is removed as soon as it is open: the
    system frees it when it is closed, or when the process dies."""

    def __init__(self) -> None:
        self.file: IO[str] | None = None
        self.name: str | None = None  # kept only where an open file cannot be removed

    @property
    def closed(self) -> bool:
        return self.file is None or self.file.closed

    def write(self, lines: Sequence[str], cut: float, dwell: float) -> None:
        if self.file is None:
            handle, name = tempfile.mkstemp(prefix="gecent-printout-")
            self.file = os.fdopen(handle, "w+", encoding="utf-8")
            try:
                os.unlink(name)
            except OSError:
                self.name = name
        self.file.write(json.dumps([cut, dwell, list(lines)]) + "\n")

    def read(self) -> Iterator[tuple[list[str], float, float]]:
        if self.file is None:
            return
        self.file.seek(0)
        for record in self.file:
            cut, dwell, lines = json.loads(record)
            yield lines, cut, dwell

    def close(self) -> None:
        if self.file is not None:
            self.file.close()
        if self.name is not None:
            with suppress(OSError):
                os.unlink(self.name)
            self.name = None


@dataclass
class Printed:
    """One printout of the listing: its kind, option 17's digit 2, its pages, and its
    spool unless it is printed as the blocks come."""

    kind: str
    ends_only: bool
    pages: Pages
    spool: Spool | None


class MultiplePages:
    """The listing of a multiple printout as the blocks come."""

    def __init__(
        self, printout: MultiplePrintout, machine: MachineDefinition, partno: Callable[[], str]
    ) -> None:
        self.printout = printout
        self.tally = tally = Tally(machine)
        self.heads: list[DataLines] = []
        self.prefixes: list[str] = []
        headings = []
        layouts = printout.layouts(machine)
        first = FIRST_COLUMN + max(len(layout.prefix) for layout in layouts)
        every = [layout.registers for layout in layouts]
        for layout in layouts:
            columns = data_columns(
                machine, layout.registers, name=printout.name, first=first, heads=every
            )
            self.heads.append(DataLines(machine, layout.registers, columns, printout.name))
            self.prefixes.append(layout.prefix)
            headings.append(centred_heading(columns))
        title = machine_title(machine)
        heading = "\n".join(headings)
        template = environment().get_template(printout.template)
        per_page = lines_per_page(machine)

        def frame(kind: str) -> Callable[[], dict[str, object]]:
            return lambda: {
                "kind": f"*** {kind} ***",
                "title": title,
                "partno": partno(),
                "heading": heading,
                "tape_feet": tally.tape_feet,
            }

        self.printed = [
            Printed(
                kind,
                ends_only,
                Pages(template, per_page, frame(kind), opening=index == 0),
                None if index == 0 else Spool(),
            )
            for index, (kind, ends_only) in enumerate(requested(machine))
        ]

    def block(self, block: Block, line: str | None) -> str:
        tally = self.tally
        tally.count(block, line)
        parts = () if block.code in TEXT_CODES else self.printout.parts(block)
        for head, part in parts:
            self.heads[head].follow(part)
        if is_page_slew(block):
            return self._slew()
        if not block.printed:
            return ""
        text = ""
        for printed in self.printed:
            lines = self._lines(printed, block, parts)
            if not lines:
                continue
            if printed.spool is None:
                text += printed.pages.add(lines, tally.cut, tally.dwell)
            else:
                printed.spool.write(lines, tally.cut, tally.dwell)
        return text

    def _slew(self) -> str:
        """MACHIN/OFF's page slew (option 218) in every printout: a kept printout's spool
        holds it as a record without lines."""
        text = ""
        for printed in self.printed:
            if printed.spool is None:
                text += printed.pages.slew()
            else:
                printed.spool.write([], self.tally.cut, self.tally.dwell)
        return text

    def _lines(
        self, printed: Printed, block: Block, parts: Sequence[tuple[int, Block]]
    ) -> list[str]:
        code = block.code
        if code in TEXT_CODES or code is Code.LEADER:
            if code is Code.COMMENT and printed.kind != INCREMENTAL:
                return []
            return [block.text or ""]
        if printed.ends_only and block.segment is not None and not any(block.segment):
            return []  # a middle segment
        lines = []
        for head, part in parts:
            data = self.heads[head]
            if printed.kind == ABSOLUTE and part.code in NOT_ON_ABSOLUTE:
                continue  # a turret corrective move (CODE -3, or its half of a +-14 block)
            if printed.kind == INCREMENTAL:
                line = data.incremental(part)
            elif printed.kind == ABSOLUTE:
                line = data.absolute(part)
            else:
                line = data.operator(part, self.tally.origin_of(part.head))
            prefix = self.prefixes[head]
            lines.append(prefix + line[len(prefix) :])
        return lines

    def finish(self) -> Iterator[str]:
        """The first printout's last page, then each kept printout, page by page; the
        temporary files are removed whatever happens."""
        tally = self.tally
        try:
            for printed in self.printed:
                if printed.spool is not None:
                    for lines, cut, dwell in printed.spool.read():
                        pages = printed.pages  # (a block's record always has lines)
                        text = pages.add(lines, cut, dwell) if lines else pages.slew()
                        if text:
                            yield text
                yield printed.pages.finish(tally.cut, tally.dwell)
        finally:
            self.discard()

    def discard(self) -> None:
        for printed in self.printed:
            if printed.spool is not None:
                printed.spool.close()
