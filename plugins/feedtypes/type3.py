"""Feed type 3: the EIA "magic 3" code of the feed in IPM (manual §4.1.2.4, 001
L11372-11388; appendix 7.1, L40132-40175; option 78, L25311-25350).

This type is selected by setting option 78 to +3. The feedrate in IPM is converted directly
to its EIA "magic 3" code (subroutine EIACOM, called from POSFED): 40 IPM is F540 and 2 IPM
is F420. The section's third example, 0.1 IPM = F210, contradicts the appendix's rule (the
first digit is 3 minus the zeros right after the point: none here), which gives F310, as
its own .153 = 315 does; the rule is followed (spec 05 open question 1).

The code exists for 0.0001 to 9999 only; a feed outside that span is taken at the nearer
end, with a comment. The code holds two significant digits, so the feed used and printed is
the one the code stands for.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from gecent.core.feed.magic3 import LARGEST, SMALLEST, decode, magic3
from gecent.core.feed.positioning import FeedCommand, FeedContext, FeedSnap
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition

LOWEST, HIGHEST = float(SMALLEST), float(LARGEST)
OUTSIDE_MAGIC3 = (
    f"FEEDRATE IS OUTSIDE THE EIA MAGIC 3 SPAN {LOWEST:g}-{HIGHEST:g} IPM; THE LIMIT IS USED."
)

# The manual's example: option 78 = 3; a magic-3 code needs F format 30 (001 L11189-11191).
MANUAL_EXAMPLE = """
[machine]
name = "feed-type-3-example"
title = "FEED TYPE 3 (EIA MAGIC 3)"
description = "Manual 4.1.2.4: positioning feed command = EIA magic 3 of the IPM"
source = "001 L11372-11388"

[regfor]
11 = 30.0

[optab]
1 = 1.0
78 = 3.0
"""


def within_span(feed: float) -> tuple[float, tuple[str, ...]]:
    if feed < LOWEST:
        return LOWEST, (OUTSIDE_MAGIC3,)
    if feed > HIGHEST:
        return HIGHEST, (OUTSIDE_MAGIC3,)
    return feed, ()


@dataclass(frozen=True)
class MagicThreeIpmFeed:
    number: int = 3
    name: str = "EIA magic 3 of the IPM"
    section: str = "§4.1.2.4"
    manual_example: str = field(default=MANUAL_EXAMPLE, repr=False)
    # the feed is rounded to the nearest one a command makes, which may be above it
    rounds_to_nearest: bool = True

    def snap(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedSnap:
        command = self.command(machine, feed, context)
        return FeedSnap(command.ipm, comments=command.comments)

    def command(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedCommand:
        """The code keeps two significant digits: the feed made (and printed) is the one
        the code stands for, 7.82 IPM -> F478 -> 7.8 IPM."""
        used, comments = within_span(feed)
        code = magic3(used)
        assert code is not None  # within_span keeps the feed inside magic 3's span
        return FeedCommand(float(code), decode(code), comments)


@hookimpl
def register_feed_types(register: Register) -> None:
    register(MagicThreeIpmFeed())
