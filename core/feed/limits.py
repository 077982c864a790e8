"""Per-axis feed limits, FEDLIM (option 25 < 0; manual §4.1.5.3, 001 L11988-12439; spec 05
§7.2-7.3): machines whose axes have their own lowest and highest feeds.

The table holds, per feed range (option 18), a [min, max] pair for each axis: the three
linear axes in the CL axis order (option 59's order; a two-axis machine's third pair may be
zero), then on a multiaxis machine each rotary axis in DBFSEG's order (head, table, third),
the rotary limits in RPM. A move's feed along each axis is F d / S (S its path: the CL path
on a multiaxis machine); an axis over its maximum sets the highest feed the move may have,
F = F_max S / d, the most limiting axis winning; a rotary axis counts its turn as the arc
at its radius (option 128 the head's tool swing, option 112 the part on the table). An
axis under its minimum raises the feed as far as no maximum forbids. The feed is then held
to |option 25|.
"""

from __future__ import annotations

from collections.abc import Sequence
from math import pi, radians

from gecent.core.absent import ABSENT, or_zero
from gecent.core.machine.definition import ROTARY_CELLS, MachineDefinition
from gecent.core.motion.rotary import UNITS_PER_DEGREE
from gecent.core.output.block import Block


def limited_feed(
    feed: float,
    departures: Sequence[float],
    path: float,
    limits: Sequence[tuple[float, float]],
    highest: float,
) -> float:
    """FEDLIM: the feed (IPM) a move of ``departures`` (inches, one per table slot) over a
    path of ``path`` inches may have, given the slots' (min, max) feeds in IPM."""
    if path <= 0.0:
        return min(feed, highest)
    allowed = feed
    wanted = 0.0
    for departure, (low, high) in zip(departures, limits, strict=False):
        along = abs(departure)
        if along == 0.0 or (low == 0.0 and high == 0.0):
            continue  # no move on the axis, or a slot "set to zero" (001 L12096-12104)
        component = along * feed / path
        if high > 0.0 and component > high:
            allowed = min(allowed, high * path / along)
        if low > 0.0 and component < low:
            wanted = max(wanted, low * path / along)
    if wanted > allowed:
        # a minimum asks for more than the move had: as much as every maximum allows
        ceiling = min(
            (high * path / abs(d) for d, (_, high) in zip(departures, limits, strict=False)
             if d and high > 0.0),
            default=wanted,
        )  # fmt: skip
        allowed = min(wanted, ceiling)
    return min(allowed, highest)


class FeedLimits:
    """One machine's FEDLIM table, by feed range, and a block's feed under it."""

    def __init__(self, machine: MachineDefinition) -> None:
        self.rotary = machine.rotary_axes
        pairs = machine.feed_ranges
        per_range = 3 + self.rotary
        self.ranges = [
            list(pairs[start : start + per_range]) for start in range(0, len(pairs), per_range)
        ]
        self.highest = abs(machine.number_option(25))
        self.radii = (
            machine.number_option(128),  # the head's tool swing
            machine.number_option(112),  # the part on the table
            machine.number_option(112),
        )
        self.step = machine.number_option(14)
        self.per_degree = UNITS_PER_DEGREE.get(machine.number_option(118), 1.0)
        self.noted: int | None = None  # the record last reported (once for its segments)

    def limits(self, feed_range: int) -> list[tuple[float, float]]:
        """The range's pairs in IPM (a rotary axis's RPM at its radius)."""
        table = self.ranges[min(max(feed_range, 1), len(self.ranges)) - 1] if self.ranges else []
        out = list(table[:3])
        for index, (low, high) in enumerate(table[3:]):
            around = 2.0 * pi * self.radii[index]
            out.append((low * around, high * around))
        return out

    def block_feed(
        self, block: Block, ipm: float, path: float, feed_range: int
    ) -> tuple[float, str | None]:
        """The feed a motion block may have over its ``path``, and the diagnostic when it
        is lowered (once for a move's segments)."""
        assert block.steps is not None
        departures = [s * self.step for s in block.steps[:3]]
        departures += [0.0] * (3 - len(departures))
        for index, cell in enumerate(ROTARY_CELLS[: self.rotary]):
            turned = radians(or_zero(block.cells[cell]) / self.per_degree)
            departures.append(turned * self.radii[index])
        limited = limited_feed(ipm, departures, path, self.limits(feed_range), self.highest)
        if limited >= ipm - 1e-9 or block.record == self.noted:
            return limited, None
        self.noted = block.record
        return limited, f"FEEDRATE REDUCED TO {limited:.3f} BY THE AXIS FEED LIMITS"


HEAD_FEED_REDUCED = "FEEDRATE REDUCED TO {:.3f} BY THE HEAD'S MAXIMUM OF {:g} RPM (OPTION 192)"
# the multiaxis classes (option 116) whose DBFSEG(6) axis, the head's register by GECENT's
# convention (001 L1793-1796, L5600-5606), turns a head: classes 2 and 4 turn a table there,
# class 7 a work-holding fixture and class 5 nothing (plugins/classes)
HEAD_CLASSES = frozenset({1, 3, 6, 8, 9})
HEAD_CELL = ROTARY_CELLS[0]


def head_degrees(machine: MachineDefinition, block: Block) -> float:
    """How far a multiaxis block turns the rotary head (degrees; 0.0 when the machine's
    class has no head, or the block does not turn it). A five-axis machine by data has its
    own axis limits and no head option (docs/five-axis.md)."""
    if machine.kinematics is not None or int(machine.number_option(116)) not in HEAD_CLASSES:
        return 0.0
    value = block.cells[HEAD_CELL]
    if value is ABSENT:
        return 0.0
    return float(value) / UNITS_PER_DEGREE.get(machine.number_option(118), 1.0)


class HeadFeedLimit:
    """Option 192 on a multiaxis head machine, a block at a time: the feed lowered to the
    head's maximum RPM, the diagnostic once for a move's segments."""

    def __init__(self, machine: MachineDefinition) -> None:
        self.machine = machine
        self.noted: int | None = None

    @staticmethod
    def applies(machine: MachineDefinition) -> bool:
        return (
            machine.number_option(192) > 0
            and machine.kinematics is None
            and int(machine.number_option(116)) in HEAD_CLASSES
        )

    def block_feed(self, block: Block, ipm: float, path: float) -> tuple[float, str | None]:
        degrees = head_degrees(self.machine, block)
        limited, note = head_limited_feed(self.machine, ipm, degrees, path)
        if note is None or block.record == self.noted:
            return limited, None
        self.noted = block.record
        return limited, note


def head_limited_feed(
    machine: MachineDefinition, ipm: float, head_degrees: float, path: float
) -> tuple[float, str | None]:
    """Option 192 (001 L26511-26516): the rotary head turns at most this many RPM. A block
    that turns the head ``head_degrees`` while its feed ``ipm`` covers ``path`` inches
    takes path / ipm minutes, so the head turns at (degrees / 360) ipm / path RPM; above
    the maximum the feed is lowered until the head turns at it, with a diagnostic. The
    manual gives no action; lowering the feed is what FEDLIM does for an axis over its
    maximum (001 L11988-12104). 0 (the standard) sets no limit."""
    maximum = machine.number_option(192)
    if maximum <= 0 or head_degrees == 0.0 or path <= 0.0 or ipm <= 0.0:
        return ipm, None
    rpm = abs(head_degrees) / 360.0 * ipm / path
    if rpm <= maximum * (1 + 1e-12):
        return ipm, None
    allowed = maximum * 360.0 * path / abs(head_degrees)
    return allowed, HEAD_FEED_REDUCED.format(allowed, maximum)
