"""Rotary feed type 1: a table of ten rotary-table feeds in the ratio 1.43; the command is
the row (manual §4.1.3.1, 001 L11730-11808; options 112, 114, 139, 141, L25741-25764,
L26035-26074).

This rotary feed type is selected by setting option 141 to +1. It needs a register of its
own for the rotary feed command, e.g. an E register: an extra register, so DBFSEG(16), with
REGSTR(16), REGFOR(16) and option 139 = 16. Subroutine ROTYP1 generates the IPM table on its
first entry, from option 112 (the table or part radius R_T, inches) and option 114 (the
maximum rotary feed RFMAX, RPM):

    F_RPM(n) = RFMAX / 1.43 ** (9 - n)        F_IPM(n) = 2 pi F_RPM(n) R_T

A programmed feed not exactly in the table is replaced by the next lowest (K = 0, called
through ROTYPE when the feed is stored); the command is the row of the feed (K = 1, called
from POSIT at output).

The text and the option table say n = 1, 2, ..., 9, but the example table has ten rows,
0 to 9 (E0 to E9), and its row 0 is RFMAX / 1.43**9; rows 0 to 9 are generated (spec 05
open question 8). The example's IPM column is 2 pi x 6 in x 0.5 RPM / 1.43**(9 - n) (option
112 = 6, option 114 = 0.5 are implied, not printed): the manual multiplied RPM values
rounded to three or four figures, so its IPM values differ from the formula's by up to
0.21 %; its row 9 RPM "1.0" is 0.5 (18.8496 IPM / 37.699). Example: 7 IPM takes the next
lowest 6.4476 (6.4460 by the formula), at row 6: the rotary feed command is E6.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from gecent.core.errors import MachineDefinitionError
from gecent.core.feed.positioning import FeedCommand, FeedContext, FeedSnap, TableHit, next_lowest
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition

RATIO = 1.43  # RK (001 L11767-11768)
TOP_ROW = 9

# The manual's example: an E register at DBFSEG(16), format 10 (001 L11738-11743), and the
# options its table implies: R_T = 6 in, RFMAX = 0.5 RPM (001 L11782-11793).
MANUAL_EXAMPLE = """
[machine]
name = "rotary-feed-type-1-example"
title = "ROTARY FEED TYPE 1 (E0-E9)"
description = "Manual 4.1.3.1: rotary feeds in the ratio 1.43, E command = row"
source = "001 L11730-11808"

[regstr]
16 = "E"

[regfor]
16 = 10.0

[optab]
1 = 1.0
112 = 6.0
114 = 0.5
139 = 16.0
141 = 1.0
"""


def rotary_feeds(machine: MachineDefinition) -> tuple[float, ...]:
    """The IPM table, rows 0..9, from options 112 and 114."""
    radius = machine.number_option(112)
    maximum = machine.number_option(114)
    for number, value, what in ((112, radius, "table radius"), (114, maximum, "maximum RPM")):
        if value <= 0:
            raise MachineDefinitionError(
                machine.origin,
                "optab",
                number,
                f"rotary feed type 1 builds its feeds from option 112 (table radius) and "
                f"option 114 (maximum RPM); the {what} must be above 0, found {value:g}",
            )
    top = 2 * math.pi * radius * maximum
    return tuple(top / RATIO ** (TOP_ROW - n) for n in range(TOP_ROW + 1))


def lookup(machine: MachineDefinition, feed: float) -> TableHit:
    return next_lowest(rotary_feeds(machine), feed)


@dataclass(frozen=True)
class GeometricRotaryFeed:
    number: int = 1
    name: str = "ten rotary feeds in the ratio 1.43, command = row"
    section: str = "§4.1.3.1"
    manual_example: str = field(default=MANUAL_EXAMPLE, repr=False)

    def snap(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedSnap:
        hit = lookup(machine, feed)
        return FeedSnap(hit.value, hit.index, hit.comments)

    def command(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedCommand:
        hit = lookup(machine, feed)
        return FeedCommand(float(hit.index), hit.value, hit.comments)


@hookimpl
def register_rotary_feed_types(register: Register) -> None:
    register(GeometricRotaryFeed())
