"""Feed type 5: separate IPM tables for Z and for XY, each with its own codes (manual
§4.1.2.6, 001 L11454-11557; options 49, 62, 63, 78, 144, 201, 202, 215).

This type is selected by setting option 78 to 5. The XY axes have their own set of feeds
and so does the Z axis: the XY feed command goes in the XY motion block, the Z command in
the Z motion block. FRTAB holds N Z ranges first (option 201 = N), then M XY ranges
(option 62 = N + M), each of option 63 IPM feeds. The exact or next lowest feed of the
range is taken (subroutine FTYPE5).

The codes are counted from option 49 for Z and from option 202 for XY, through that axis
group's ranges, with option 144 as the difference in FCOM from the last code of one range
to the first of the next (15 to 21, 25 to 31): for entry e (1-based) of range r, n feeds
per range,

    row  = start + (r - 1) n + (e - 1)
    FCOM = row + (r - 1)(option 144 - 1)

which is the manual's "row number + option 144 - 1" for range 2 and F11, F21, F31 for the
first codes of Z ranges 1 to 3 (spec 05 §4.6). The option table gives type 5 an option of
its own for that increment, option 215 (001 L26661-26669); when it is set it is the
increment, and at its standard 0 option 144 is, as §4.1.2.6 says.

The programmed feed range applies to Z;
"when range 3 is programmed for Z, range 2 is used for XY", so each group takes the
programmed range or its own highest. A range above both groups' counts takes the highest,
with FEDRAT's comment (given at FEDRAT, not in every block).

Example: 40 IPM in feed range 2. XY range 2 is 28.6, 35.9, 50.1, 57.8, 65.2: next lowest
35.9, entry 2, row 21 + 5 + 1 = 27, FCOM = 27 + 6 - 1 = 32. Z range 2 is 10.2 ... 15.1:
15.1, entry 5, row 11 + 5 + 4 = 20, FCOM = 20 + 6 - 1 = 25 (printed unreadable; F25 of the
table).

The manual snaps the feed while forming each block's command, so the feed is found at
output, in the table of the block's axis; at FEDRAT the programmed feed is kept, since one
feed serves two tables (a Z table value would be the wrong feed for the XY blocks).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from gecent.core.errors import MachineDefinitionError
from gecent.core.feed.positioning import (
    FeedCommand,
    FeedContext,
    FeedSnap,
    Z,
    next_lowest,
    table_segment,
)
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.core.statements.feed import RANGE_NOT_AVAILABLE
from gecent.plugins.feedtypes._frtab import require_table

KIND = "feed type 5"

# The manual's example: three Z and two XY ranges of five feeds (001 L11476-11521). The
# third XY range 1 feed is 15.6 in the table and 15.5 in the FRTAB listing; the table's
# 15.6 is kept (decisions-feedtypes.md).
MANUAL_EXAMPLE = """
[machine]
name = "feed-type-5-example"
title = "FEED TYPE 5 (Z AND XY TABLES)"
description = "Manual 4.1.2.6: separate Z and XY IPM tables with their own codes"
source = "001 L11454-11557"

[optab]
1 = 1.0
78 = 5.0
49 = 11.0
62 = 5.0
63 = 5.0
144 = 6.0
174 = 25.0
201 = 3.0
202 = 21.0

[feed_table]
feeds = [
    4.2, 6.8, 7.9, 8.5, 9.1,
    10.2, 11.4, 12.6, 13.8, 15.1,
    21.3, 25.6, 28.9, 31.7, 38.9,
    6.3, 10.9, 15.6, 18.9, 22.5,
    28.6, 35.9, 50.1, 57.8, 65.2,
]
"""


@dataclass(frozen=True, slots=True)
class AxisGroups:
    """The number of Z ranges (option 201) and of XY ranges (option 62 - option 201)."""

    z_ranges: int
    xy_ranges: int


def axis_groups(machine: MachineDefinition) -> AxisGroups:
    require_table(machine, KIND)
    z_ranges = machine.number_option(201)
    total = machine.number_option(62)
    if z_ranges != int(z_ranges) or not 1 <= z_ranges < total:
        raise MachineDefinitionError(
            machine.origin,
            "optab",
            201,
            f"{KIND} needs option 201 = the number of Z ranges, at least 1 and less than "
            f"option 62 = {total:g} (the XY ranges follow them); found {z_ranges:g}",
        )
    return AxisGroups(int(z_ranges), int(total) - int(z_ranges))


def programmed_range(groups: AxisGroups, context: FeedContext) -> tuple[int, tuple[str, ...]]:
    """The programmed feed range (1 when none was given); above both groups' counts, the
    highest, with FEDRAT's comment."""
    highest = max(groups.z_ranges, groups.xy_ranges)
    if context.feed_range > highest:
        return highest, (RANGE_NOT_AVAILABLE,)
    return max(1, context.feed_range), ()


def _command(machine: MachineDefinition, feed: float, context: FeedContext) -> FeedCommand:
    groups = axis_groups(machine)
    programmed, _ = programmed_range(groups, context)
    if context.axis == Z:
        group_range = min(programmed, groups.z_ranges)
        table_range, start = group_range, machine.number_option(49)
    else:
        group_range = min(programmed, groups.xy_ranges)
        table_range, start = groups.z_ranges + group_range, machine.number_option(202)
    _, values = table_segment(machine, table_range, KIND)
    hit = next_lowest(values, feed)
    row = start + (group_range - 1) * len(values) + hit.index
    gap = range_increment(machine)
    return FeedCommand(row + (group_range - 1) * (gap - 1), hit.value, hit.comments)


def range_increment(machine: MachineDefinition) -> float:
    """The FCOM increment between ranges: option 215, type 5's own (001 L26661-26669), or
    option 144 while 215 is at its standard 0 (001 L11471-11472, L11502-11505)."""
    own = machine.number_option(215)
    return own if own != 0 else machine.number_option(144)


@dataclass(frozen=True)
class ZAndXyTableFeed:
    number: int = 5
    name: str = "separate Z and XY IPM tables"
    section: str = "§4.1.2.6"
    manual_example: str = field(default=MANUAL_EXAMPLE, repr=False)

    def snap(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedSnap:
        _, comments = programmed_range(axis_groups(machine), context)
        return FeedSnap(feed, comments=comments)

    def command(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedCommand:
        return _command(machine, feed, context)


@hookimpl
def register_feed_types(register: Register) -> None:
    register(ZAndXyTableFeed())
