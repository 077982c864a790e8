"""Feed type 7: a manual feed-selector code (manual §4.1.2.8, 001 L11621-11639; option 78,
L25311-25350).

This type is selected by setting option 78 to +7. The machine tool has a number of manually
set feedrate combinations (potentiometers), selected by a code number that is neither IPM
nor IPR. The code is given in the FEDRAT statement and the postprocessor outputs it, one
for one, as the feedrate command: FEDRAT/1 gives F1.

The manual does not say what feed is assumed inside the postprocessor. The code stays the
programmed feed (FEDIPM) unchanged, so limit tests and the listing see the code number as
it was programmed (spec 05 open question 7; decisions-feedtypes.md). The type is formed in
POSFED itself and has no table.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from gecent.core.feed.positioning import FeedCommand, FeedContext, FeedSnap
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition

# The manual's example: potentiometer No. 1, FEDRAT/1 (001 L11630-11634).
MANUAL_EXAMPLE = """
[machine]
name = "feed-type-7-example"
title = "FEED TYPE 7 (SELECTOR CODE)"
description = "Manual 4.1.2.8: the FEDRAT value is the feed selector code"
source = "001 L11621-11639"

[optab]
1 = 1.0
78 = 7.0
"""


@dataclass(frozen=True)
class SelectorCodeFeed:
    number: int = 7
    name: str = "manual feed-selector code"
    section: str = "§4.1.2.8"
    manual_example: str = field(default=MANUAL_EXAMPLE, repr=False)

    def snap(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedSnap:
        return FeedSnap(feed)

    def command(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedCommand:
        return FeedCommand(feed, feed)


@hookimpl
def register_feed_types(register: Register) -> None:
    register(SelectorCodeFeed())
