"""Feed type 6: discrete IPM feeds in a low (milling) and a high range; the command is K
times the feed (manual §4.1.2.7, 001 L11558-11619; options 62, 63, 78).

This type is selected by setting option 78 to +6. The feeds are discrete IPM values in two
ranges, a low and a high one. The low range is used only for milling: it is selected by a
CYCLE/MILL statement followed by FEDRAT/RANGE,1. Otherwise, whatever range is selected,
range 2 (the high range) is always in force. The command is FCOM = K x FIPM, with K = 12
in range 1 and K = 2 in range 2.

Since only discrete feeds exist, subroutine FTYPE6, called from FEDRAT (K = 0), makes sure
the programmed feed is available and otherwise takes the next lowest; called from POSFED
(K = 1), it forms the command. The option table words it by axis ("XY (milling) = 12 x
IPM, Z = 2 x IPM"); the section's range rule is followed (spec 05 open question 5).

Examples: 3.6 IPM in feed range 1 with CYCLE/MILL (ICTYP = 6): next lowest 3.5,
FCOM = 12 x 3.5 = 42. 7.9 IPM in feed range 2: 7 IPM, FCOM = 2 x 7 = 14.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from decimal import Decimal

from gecent.core.feed.positioning import (
    FeedCommand,
    FeedContext,
    FeedSnap,
    TableHit,
    next_lowest,
    table_segment,
)
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.plugins.feedtypes._frtab import require_table

KIND = "feed type 6"
MULTIPLIERS = {1: Decimal(12), 2: Decimal(2)}  # K by range (001 L11572-11574)

# The manual's example: ten low and ten high feeds (001 L11585-11603).
MANUAL_EXAMPLE = """
[machine]
name = "feed-type-6-example"
title = "FEED TYPE 6 (LOW/HIGH IPM RANGES)"
description = "Manual 4.1.2.7: milling range 1 (K = 12) and range 2 (K = 2), FCOM = K x IPM"
source = "001 L11558-11619"

[optab]
1 = 1.0
78 = 6.0
62 = 2.0
63 = 10.0
174 = 20.0

[feed_table]
feeds = [
    0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 5.0,
    2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 12.0,
]
"""


def feed_range(context: FeedContext) -> int:
    """Range 1 only for milling (CYCLE/MILL) with FEDRAT/RANGE,1; range 2 otherwise."""
    return 1 if context.milling and context.feed_range == 1 else 2


def lookup(
    machine: MachineDefinition, feed: float, context: FeedContext
) -> tuple[int, int, TableHit]:
    """The range, the row across FRTAB and the exact or next lowest feed of the range."""
    require_table(machine, KIND, ranges=2)
    range_number = feed_range(context)
    first_row, values = table_segment(machine, range_number, KIND)
    hit = next_lowest(values, feed)
    return range_number, first_row + hit.index, hit


@dataclass(frozen=True)
class LowHighRangeFeed:
    number: int = 6
    name: str = "low (milling) and high IPM ranges, K x IPM"
    section: str = "§4.1.2.7"
    manual_example: str = field(default=MANUAL_EXAMPLE, repr=False)

    def snap(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedSnap:
        _, row, hit = lookup(machine, feed, context)
        return FeedSnap(hit.value, row, hit.comments)

    def command(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedCommand:
        range_number, _, hit = lookup(machine, feed, context)
        product = Decimal(repr(hit.value)) * MULTIPLIERS[range_number]
        return FeedCommand(float(product), hit.value, hit.comments)


@hookimpl
def register_feed_types(register: Register) -> None:
    register(LowHighRangeFeed())
