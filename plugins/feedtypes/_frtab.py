"""What the table feed types share (manual §4.1.2, 001 L11198-11236): the check that the
positioning FRTAB is there and holds option 62 x option 63 feeds, the spindle speed the IPR
types divide by (types 2, 4 and 8), and subroutine FTYPE2's lookup, which serves types 2, 8
and 9 (§4.1.2.3, §4.1.2.9, §4.1.2.10; 001 L11289-11370, L11641-11711).

FTYPE2 scans the range of FRTAB that the current spindle range names, in IPR (types 2 and
8: the IPM feed divided by the spindle speed) or in IPM (type 9), and takes the exact value
or the next lowest. The row it reports is numbered from 0 across the whole table.

A type that needs a spindle speed when none was ever given assumes option 27, with the
manual's comment for that case (001 L28310-28314); option 27 <= 0 is fatal error 24, as it
is for SPINDL and FEDRAT/IPR (001 L24722-24727).
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.errors import MachineDefinitionError
from gecent.core.feed.positioning import FeedContext, next_lowest, table_segment
from gecent.core.machine.definition import MachineDefinition
from gecent.core.spindle import assumed_speed

SPEED_ASSUMED = "OPTION VALUE IS ASSUMED FOR THE SPINDLE SPEED"


def require_table(machine: MachineDefinition, kind: str, ranges: int | None = None) -> None:
    """The positioning FRTAB must exist and hold option 62 x option 63 feeds; a type with a
    fixed number of ranges (``ranges``) also needs option 62 to say so."""
    if not machine.feed_table:
        raise MachineDefinitionError(
            machine.origin,
            "feed_table",
            "feeds",
            f"{kind} needs the positioning feed table (FRTAB: option 62 ranges of "
            "option 63 feeds); the machine has none",
        )
    range_count = machine.number_option(62)
    per_range = machine.number_option(63)
    count = int(range_count) * int(per_range)
    if len(machine.feed_table) != count or range_count < 1 or per_range < 1:
        raise MachineDefinitionError(
            machine.origin,
            "feed_table",
            "feeds",
            f"{kind}: option 62 x option 63 = {range_count:g} x {per_range:g} feeds, but "
            f"the table lists {len(machine.feed_table)}",
        )
    if ranges is not None and range_count != ranges:
        raise MachineDefinitionError(
            machine.origin,
            "optab",
            62,
            f"{kind} needs option 62 = {ranges} feed ranges; found {range_count:g}",
        )


def spindle_speed(
    machine: MachineDefinition, context: FeedContext
) -> tuple[float, tuple[str, ...]]:
    """The speed an IPR feed is taken at: the current one, else option 27 with a comment."""
    speed = context.spindle_speed
    if speed is not None and speed > 0:
        return speed, ()
    return assumed_speed(machine, None), (SPEED_ASSUMED,)


@dataclass(frozen=True, slots=True)
class Ftype2Hit:
    """FTYPE2's answer: the row (0-based across FRTAB), the table value (IPR or IPM), the
    feed in IPM it stands for, the comments of the lookup, and the comment of an assumed
    spindle speed (given once, at FEDRAT: the blocks that follow would only repeat it)."""

    row: int
    value: float
    ipm: float
    comments: tuple[str, ...] = ()
    speed_comments: tuple[str, ...] = ()


def ftype2_lookup(
    machine: MachineDefinition,
    feed: float,
    context: FeedContext,
    kind: str,
    *,
    per_revolution: bool,
) -> Ftype2Hit:
    """The exact or next lowest table value for ``feed`` (IPM) in the spindle range's
    segment of FRTAB; an IPR table is scanned with the feed per revolution."""
    require_table(machine, kind)
    first_row, values = table_segment(machine, max(1, context.spindle_range), kind)
    speed, speed_comments = spindle_speed(machine, context) if per_revolution else (1.0, ())
    hit = next_lowest(values, feed / speed)
    return Ftype2Hit(
        first_row + hit.index, hit.value, hit.value * speed, hit.comments, speed_comments
    )
