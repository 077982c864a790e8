"""Feed type 2: a table of discrete IPR feeds by spindle range; the command is the row
(manual §4.1.2.3, 001 L11289-11370; options 62, 63, 78, 144; FRTAB L27010-27065).

This type is selected by setting option 78 to +2. FRTAB holds option 62 ranges of option 63
IPR feeds, and the current spindle range names the feed range to use. Subroutine FTYPE2
works twice:

* called from FEDRAT (K = 0) whenever a feed is given, it makes sure the feed exists: the
  IPM feed becomes IPR (FIPR = FIPM / spindle speed), the exact or next lowest IPR of the
  spindle range is taken, and FIPM = FIPR x speed becomes the programmed feed;
* called from POSFED (K = 1), it finds the row of that IPR in the spindle range and forms
  FCOM = row number + option 144, the rows numbered from 0 across the whole table.

Example: spindle 100 RPM in range 2, 7 IPM programmed: 0.07 IPR, next lowest 0.06, so
6 IPM is programmed; 0.06 is at row 6, and FCOM = 6 + 11 = 17. The text says "the closest
value" but its example takes the "closest and next lowest"; next lowest is used, as in
every other table type (spec 05 open question 2).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from gecent.core.feed.positioning import FeedCommand, FeedContext, FeedSnap
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.plugins.feedtypes._frtab import ftype2_lookup

KIND = "feed type 2"

# The manual's example: 15 IPR feeds in three ranges (001 L11324-11345).
MANUAL_EXAMPLE = """
[machine]
name = "feed-type-2-example"
title = "FEED TYPE 2 (IPR TABLE)"
description = "Manual 4.1.2.3: IPR feeds by spindle range, FCOM = row + option 144"
source = "001 L11289-11370"

[optab]
1 = 1.0
78 = 2.0
62 = 3.0
63 = 5.0
144 = 11.0
174 = 15.0

[feed_table]
feeds = [
    0.01, 0.02, 0.03, 0.04, 0.05,
    0.04, 0.06, 0.08, 0.10, 0.12,
    0.10, 0.14, 0.18, 0.22, 0.26,
]
"""


@dataclass(frozen=True)
class IprTableFeed:
    number: int = 2
    name: str = "IPR table by spindle range, row + option 144"
    section: str = "§4.1.2.3"
    manual_example: str = field(default=MANUAL_EXAMPLE, repr=False)

    def snap(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedSnap:
        hit = ftype2_lookup(machine, feed, context, KIND, per_revolution=True)
        return FeedSnap(hit.ipm, hit.row, hit.speed_comments + hit.comments)

    def command(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedCommand:
        hit = ftype2_lookup(machine, feed, context, KIND, per_revolution=True)
        return FeedCommand(hit.row + machine.number_option(144), hit.ipm, hit.comments)


@hookimpl
def register_feed_types(register: Register) -> None:
    register(IprTableFeed())
