"""Feed type 4: an IPR table of at most two feed ranges, range 2 five times range 1; the
command is the row (manual §4.1.2.5, 001 L11390-11444; options 62, 63, 78, 144).

This type is selected by setting option 78 to +4. It uses two feed ranges or fewer, and
only the range 1 IPR feeds are stored in FRTAB (so option 62 = 1): the range 2 feeds are
five times the range 1 values. The feed in IPM is first converted to IPR (FIPR = FIPM /
spindle speed); the range's values are scanned for the exact or next lowest IPR, and
FCOM = row number + option 144, the same row in both ranges (subroutine FTYPE4).

The range is the feed range of FEDRAT/RANGE (the examples say "Feed Range", not the spindle
range; spec 05 open question 3); with none given, range 1. A higher range is not available
and range 2 is used, with the comment FEDRAT gives for that case.

Examples: 0.2 IPM at 100 RPM in feed range 1 is 0.002 IPR, row 1, FCOM = 1 + 0 = 1; 4 IPM
at 200 RPM in feed range 2 is 0.02 IPR, found at row 3 of the range 1 values x 5, so
FCOM = 3 + 0 = 3.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from decimal import Decimal

from gecent.core.feed.positioning import (
    FeedCommand,
    FeedContext,
    FeedSnap,
    next_lowest,
    table_segment,
)
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.core.statements.feed import RANGE_NOT_AVAILABLE
from gecent.plugins.feedtypes._frtab import require_table, spindle_speed

KIND = "feed type 4"
RANGE_TWO_FACTOR = Decimal(5)  # "five times the range one values" (001 L11397-11398)

# The manual's example: six range 1 IPR feeds (001 L11400-11418).
MANUAL_EXAMPLE = """
[machine]
name = "feed-type-4-example"
title = "FEED TYPE 4 (TWO-RANGE IPR TABLE)"
description = "Manual 4.1.2.5: range 1 IPR feeds, range 2 = 5 x range 1, FCOM = row"
source = "001 L11390-11444"

[optab]
1 = 1.0
78 = 4.0
62 = 1.0
63 = 6.0
144 = 0.0
174 = 6.0

[feed_table]
feeds = [0.001, 0.002, 0.003, 0.004, 0.006, 0.009]
"""


@dataclass(frozen=True, slots=True)
class _Hit:
    """The row, the feed in IPM, the lookup's comments, and the comments about the range
    and the spindle speed, which are given once, at FEDRAT."""

    row: int
    ipm: float
    comments: tuple[str, ...]
    fedrat_comments: tuple[str, ...]


def feed_range(context: FeedContext) -> tuple[int, tuple[str, ...]]:
    """The programmed feed range, 1 when none was given; above 2, range 2 with a comment."""
    if context.feed_range > 2:
        return 2, (RANGE_NOT_AVAILABLE,)
    return max(1, context.feed_range), ()


def range_values(machine: MachineDefinition, range_number: int) -> tuple[float, ...]:
    """The IPR feeds of range 1 or 2 (range 2: the stored values x 5, in decimal so that
    5 x .003 is .015 exactly as the manual prints it)."""
    require_table(machine, KIND, ranges=1)
    _, stored = table_segment(machine, 1, KIND)
    if range_number == 1:
        return stored
    return tuple(float(Decimal(repr(value)) * RANGE_TWO_FACTOR) for value in stored)


def lookup(machine: MachineDefinition, feed: float, context: FeedContext) -> _Hit:
    range_number, range_comments = feed_range(context)
    values = range_values(machine, range_number)
    speed, speed_comments = spindle_speed(machine, context)
    hit = next_lowest(values, feed / speed)
    return _Hit(hit.index, hit.value * speed, hit.comments, range_comments + speed_comments)


@dataclass(frozen=True)
class TwoRangeIprFeed:
    number: int = 4
    name: str = "IPR table, range 2 = 5 x range 1, row + option 144"
    section: str = "§4.1.2.5"
    manual_example: str = field(default=MANUAL_EXAMPLE, repr=False)

    def snap(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedSnap:
        hit = lookup(machine, feed, context)
        return FeedSnap(hit.ipm, hit.row, hit.fedrat_comments + hit.comments)

    def command(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedCommand:
        hit = lookup(machine, feed, context)
        return FeedCommand(hit.row + machine.number_option(144), hit.ipm, hit.comments)


@hookimpl
def register_feed_types(register: Register) -> None:
    register(TwoRangeIprFeed())
