"""Feed type 1: the feed in IPM is the command (manual §4.1.2.2, 001 L11268-11287; option
78, L25311-25350).

This type is selected by setting option 78 to +1. The feedrate in IPM is also the feedrate
command; there is no conversion. The F register's format does the only rounding, when the
block is written: with REGFOR(11) = 21, 0.1 IPM prints as 00.1, 2.63 as 02.6, 35.17 as 35.2
and 40.0 as 40.0. The type is formed in POSFED itself and has no table, so the feed is not
snapped.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from gecent.core.feed.positioning import FeedCommand, FeedContext, FeedSnap
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.rounding import half_up

# The manual's example: option 78 = 1, FORMAT(11) = 21 (001 L11274-11284).
MANUAL_EXAMPLE = """
[machine]
name = "feed-type-1-example"
title = "FEED TYPE 1 (F = IPM)"
description = "Manual 4.1.2.2: positioning feed command = the feed in IPM"
source = "001 L11268-11287"

[regfor]
11 = 21.0

[optab]
1 = 1.0
78 = 1.0
"""


@dataclass(frozen=True)
class IpmFeed:
    number: int = 1
    name: str = "feed in IPM"
    section: str = "§4.1.2.2"
    manual_example: str = field(default=MANUAL_EXAMPLE, repr=False)
    # the feed is rounded to the nearest one a command makes, which may be above it
    rounds_to_nearest: bool = True

    def snap(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedSnap:
        return FeedSnap(self.command(machine, feed, context).ipm)

    def command(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedCommand:
        """The F register's decimals decide the feed the control makes (35.17 IPM in format
        21 is 35.2); that is the feed used and printed."""
        fmt = machine.registers.formats[11]
        decimals = fmt.right if fmt is not None else 0
        used = float(half_up(feed, decimals))
        return FeedCommand(used, used)


@hookimpl
def register_feed_types(register: Register) -> None:
    register(IpmFeed())
