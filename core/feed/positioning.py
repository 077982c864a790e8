"""Positioning feedrate commands: the protocol of the feed-type plugins (option 78) and of
the rotary feed types (option 141), and the table lookup they share (manual §4.1.2 and
§4.1.3, 001 L11198-11808; spec 05 §4-5).

A feed type works in two steps, as the manual's FTYPEn routines do with their K flag:

* ``snap`` (K = 0, at FEDRAT): the feed the machine can really make of the programmed one;
  it becomes the programmed feed (FEDIPM), so the listing prints the true value used;
* ``command`` (K = 1, at output in POSFED): the F command for a block, from the snapped
  feed and the block's axis (type 5 has separate Z and XY tables).

The kernel keeps the positioning FRTAB (``MachineDefinition.feed_table``, rows numbered
from 0 across the whole table) and the one lookup every table type uses: the exact table
value, else the next lower one.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import pairwise
from typing import Protocol, runtime_checkable

from gecent.core.errors import MachineDefinitionError
from gecent.core.machine.definition import MachineDefinition

XY, Z = "xy", "z"
_EXACT = 1e-9

BELOW_TABLE = "FEEDRATE IS BELOW THE LOWEST IN THE TABLE; LOWEST USED."


@dataclass(frozen=True, slots=True)
class FeedContext:
    """What a positioning feed type may depend on.

    ``spindle_speed`` (RPM; None when no speed was given) and ``spindle_range`` serve the
    IPR types; ``feed_range`` is FEDRAT/RANGE's IFDRNG (0 = none given); ``milling`` is
    CYCLE/MILL in force (type 6); ``axis`` is the block's axis group, XY or Z (type 5).
    """

    spindle_speed: float | None = None
    spindle_range: int = 1
    feed_range: int = 0
    milling: bool = False
    axis: str = XY


@dataclass(frozen=True, slots=True)
class FeedSnap:
    """A feed as the machine can make it: the IPM actually used, the table row (0-based
    across FRTAB; None for types without a table) and the manual's comments."""

    ipm: float
    row: int | None = None
    comments: tuple[str, ...] = ()


@dataclass(frozen=True, slots=True)
class FeedCommand:
    """The F command of one block and the IPM it stands for (printed in the listing)."""

    command: float
    ipm: float
    comments: tuple[str, ...] = ()


@runtime_checkable
class FeedType(Protocol):
    """A positioning feed type (option 78) or rotary feed type (option 141)."""

    number: int
    name: str
    section: str

    def snap(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedSnap: ...

    def command(
        self, machine: MachineDefinition, feed: float, context: FeedContext
    ) -> FeedCommand: ...


@dataclass(frozen=True, slots=True)
class TableHit:
    """A lookup in one segment of FRTAB: the 0-based row within the segment, the value."""

    index: int
    value: float
    comments: tuple[str, ...] = ()


def next_lowest(values: tuple[float, ...], wanted: float) -> TableHit:
    """The exact table value or the next lower one (every worked example of §4.1.2 and
    §4.1.3 does this, 001 L11324-11808). Below the smallest value the smallest is used,
    with a comment; values ascend."""
    if not values:
        raise ValueError("empty feed table segment")
    if wanted < values[0] - _EXACT:
        return TableHit(0, values[0], (BELOW_TABLE,))
    index = 0
    for position, value in enumerate(values):
        if value <= wanted + _EXACT * max(1.0, abs(wanted)):
            index = position
        else:
            break
    return TableHit(index, values[index])


def table_segment(
    machine: MachineDefinition, range_number: int, kind: str
) -> tuple[int, tuple[float, ...]]:
    """Range ``range_number`` (1-based) of the positioning FRTAB: the row of its first
    value (0-based across the table) and its values. A missing range or a table out of
    ascending order is a machine-file error naming the feed type (``kind``)."""
    ranges = machine.feed_table_ranges()
    if not 1 <= range_number <= len(ranges):
        raise MachineDefinitionError(
            machine.origin,
            "feed_table",
            "feeds",
            f"{kind} needs feed range {range_number}; the table has {len(ranges)} "
            f"(option 62 = {machine.number_option(62):g}, option 63 = "
            f"{machine.number_option(63):g})",
        )
    values = ranges[range_number - 1]
    if any(b < a for a, b in pairwise(values)):
        raise MachineDefinitionError(
            machine.origin,
            "feed_table",
            "feeds",
            f"{kind}: feed range {range_number} must ascend; found {list(values)}",
        )
    per_range = max(1, int(machine.number_option(63)))
    return (range_number - 1) * per_range, values
