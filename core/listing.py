"""The Jinja environment the printout plugins render their listings with, and the page slew
of MACHIN/OFF (option 218, 001 L26678-26687): the totals line the statement prints and the
information block that tells every printout to end its page there."""

from __future__ import annotations

from functools import cache
from typing import TYPE_CHECKING

from gecent.core.output.block import Block, Code

if TYPE_CHECKING:
    import jinja2

# DBFSEG(2) of the information block (CODE -9, never printed or punched) that ends the page
# being printed: gecent's own kind of information block, numbered after option 218 (the
# manual's ORIGIN is kind 2).
PAGE_SLEW = 218.0


def totals_text(cut_minutes: float, dwell_minutes: float) -> str:
    """MACHIN/OFF's totals, worded as the page bottom's times."""
    return f"TOTAL CUT TIME {cut_minutes:.2f} MIN; TOTAL DWELL TIME {dwell_minutes:.2f} MIN;"


def page_slew(record: int | None) -> Block:
    """The information block after which a printout starts a new page."""
    block = Block(Code.INFORMATION, record)
    block.cells[2] = PAGE_SLEW
    return block


def is_page_slew(block: Block) -> bool:
    return block.code is Code.INFORMATION and block.cells[2] == PAGE_SLEW


@cache
def environment() -> jinja2.Environment:
    import jinja2  # only a run that writes a listing pays for it

    return jinja2.Environment(
        loader=jinja2.PackageLoader("gecent.plugins.printouts", "templates"),
        autoescape=False,
        undefined=jinja2.StrictUndefined,
        keep_trailing_newline=True,
        trim_blocks=True,
        lstrip_blocks=True,
    )
