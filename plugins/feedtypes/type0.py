"""Feed type 0: the feed in IPM times a constant (manual §4.1.2.1, 001 L11237-11267; option
78, L25311-25350).

This type is selected by a zero or negative option 78. The command is the feedrate in IPM
times the constant K = |option 78|, rounded to the closest integer; if option 78 is zero,
K = 2. With option 78 = -3: 7.123 IPM gives F21, 18.2694 gives F55, 1.74 gives F5 and
94.926 gives F285. The printed "K = I Option 101" is an OCR slip for |option 78|, which the
option table confirms ("ABS(OPTAB(78)) times feedrate in IPM").

The type is formed in POSFED itself. The machine makes only multiples of 1/K IPM, so the
feed used (FEDIPM, printed in the listing) is the command over K: with K = 2, 2.25 IPM is
F5, 2.5 IPM (001 L1160-1168: "the printed feedrate is the true value used"). The smallest
command is 1. "Closest integer" takes a half upward: 0.5 IPM with
K = 5 is F3 (not the F2 of round-half-even).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from decimal import ROUND_HALF_UP, Decimal

from gecent.core.feed.positioning import FeedCommand, FeedContext, FeedSnap
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition

ZERO_OPTION_MULTIPLIER = 2.0  # "If option 78 is zero, K = 2" (001 L11251)

# The manual's example: option 78 = -3, so K = 3 (001 L11253-11264).
MANUAL_EXAMPLE = """
[machine]
name = "feed-type-0-example"
title = "FEED TYPE 0 (OPTION 78 = -3)"
description = "Manual 4.1.2.1: positioning feed command = 3 x IPM"
source = "001 L11237-11267"

[optab]
1 = 1.0
78 = -3.0
"""


def multiplier(machine: MachineDefinition) -> float:
    """K = |option 78|, or 2 when option 78 is zero."""
    setting = abs(machine.number_option(78))
    return setting if setting != 0 else ZERO_OPTION_MULTIPLIER


@dataclass(frozen=True)
class MultipliedIpmFeed:
    number: int = 0
    name: str = "IPM times |option 78| (2 when zero), rounded"
    section: str = "§4.1.2.1"
    manual_example: str = field(default=MANUAL_EXAMPLE, repr=False)
    # the feed is rounded to the nearest one a command makes, which may be above it
    rounds_to_nearest: bool = True

    def snap(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedSnap:
        return FeedSnap(self.command(machine, feed, context).ipm)

    def command(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedCommand:
        k = multiplier(machine)
        product = Decimal(repr(feed)) * Decimal(repr(k))
        command = max(1, int(product.quantize(Decimal(1), ROUND_HALF_UP)))
        return FeedCommand(float(command), command / k)


@hookimpl
def register_feed_types(register: Register) -> None:
    register(MultipliedIpmFeed())
