"""Feed type 9: type 2 with a table of IPM feeds (manual §4.1.2.10, 001 L11667-11711;
options 62, 63, 78, 144; FRTAB L27010-27065).

This type is selected by setting option 78 to +9. It is identical to feed type 2 in every
respect (subroutine FTYPE2), except that the values stored in FRTAB are in IPM, so the feed
is looked up as it is, without the spindle speed. The current spindle range names the feed
range; the exact or next lowest feed of that range becomes the programmed feed, and the
command is its row number (from 0 across the whole table) + option 144.

Example: 45 IPM in spindle range 2 (14, 18, 26, 30, 40): 40 IPM is used, at row 9, and
FCOM = 9 + 11 = 20. The printed row "1" of 26 IPM is an OCR slip for row 7.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from gecent.core.feed.positioning import FeedCommand, FeedContext, FeedSnap
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.plugins.feedtypes._frtab import ftype2_lookup

KIND = "feed type 9"

# The manual's example: 15 IPM feeds in three ranges (001 L11681-11697).
MANUAL_EXAMPLE = """
[machine]
name = "feed-type-9-example"
title = "FEED TYPE 9 (IPM TABLE)"
description = "Manual 4.1.2.10: IPM feeds by spindle range, FCOM = row + option 144"
source = "001 L11667-11711"

[optab]
1 = 1.0
78 = 9.0
62 = 3.0
63 = 5.0
144 = 11.0
174 = 15.0

[feed_table]
feeds = [
    1.0, 3.0, 6.0, 9.0, 11.0,
    14.0, 18.0, 26.0, 30.0, 40.0,
    50.0, 60.0, 70.0, 80.0, 90.0,
]
"""


@dataclass(frozen=True)
class IpmTableFeed:
    number: int = 9
    name: str = "IPM table by spindle range, row + option 144"
    section: str = "§4.1.2.10"
    manual_example: str = field(default=MANUAL_EXAMPLE, repr=False)

    def snap(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedSnap:
        hit = ftype2_lookup(machine, feed, context, KIND, per_revolution=False)
        return FeedSnap(hit.ipm, hit.row, hit.comments)

    def command(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedCommand:
        hit = ftype2_lookup(machine, feed, context, KIND, per_revolution=False)
        return FeedCommand(hit.row + machine.number_option(144), hit.ipm, hit.comments)


@hookimpl
def register_feed_types(register: Register) -> None:
    register(IpmTableFeed())
