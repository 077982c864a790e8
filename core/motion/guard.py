"""Bounds on what one CL move may ask of the post (gecent's guard against absurd input).

The manual puts no limit on the number of segments of a long move (§3.4.3.2): on the sample
mill, whose departures hold 99.9999, a legal ``GOTO/1e7`` is 100,001 blocks. Such a move
almost always comes from a slip (a missing decimal point, a unit mix-up), so gecent stops at
a bound before making any of its blocks: by default 100,000 segment blocks for one CL move,
raised by ``gecent post --max-segments N`` (0: no bound). The decision is in
docs/decisions.md. A coordinate that is not a finite number, or that no register of an
absolute-coded machine can hold, is bad input too.
"""

from __future__ import annotations

from collections.abc import Sequence
from math import isfinite

from gecent.core.cl.records import Arelem, Circle, Motion, MotionSubtype, Record, Statement
from gecent.core.errors import InputError, SourcePosition
from gecent.core.machine.definition import MachineDefinition

DEFAULT_MAX_SEGMENTS = 100_000
# beyond 2**53 steps a float no longer holds every whole step: no machine position is there
LARGEST_STEPS = 2**53


def check_segments(count: int, bound: int, where: SourcePosition | None, what: str) -> None:
    """Refuse a move that would make more than ``bound`` segment blocks (0: no bound)."""
    if bound and count > bound:
        raise InputError(
            f"this {what} would make {count:,} segment blocks, more than the bound of "
            f"{bound:,} for one CL move (a slip in the coordinates? --max-segments N raises "
            "the bound, 0 removes it)",
            where,
        )


# no length, feed, speed, time or count a CL statement gives means anything beyond this
# (10**12 mm is a million kilometres); past it the arithmetic of the post overflows
LARGEST_NUMBER = 1e12


def check_finite(values: tuple[float, ...], where: SourcePosition | None, what: str) -> None:
    for value in values:
        if not isfinite(value):
            raise InputError(f"{what} has a value that is not a finite number ({value})", where)


def check_size(values: tuple[float, ...], where: SourcePosition | None, what: str) -> None:
    for value in values:
        if abs(value) > LARGEST_NUMBER:
            raise InputError(
                f"{what} has a value no length, feed, speed or count can have ({value:g}; "
                f"at most {LARGEST_NUMBER:g})",
                where,
            )


def check_numbers(record: Record) -> None:
    """Every number a statement, CIRCLE or ARELEM record carries is finite and at most
    LARGEST_NUMBER in size."""
    if isinstance(record, Statement):
        numbers = tuple(a for a in record.args if isinstance(a, float))
        check_finite(numbers, record.where, record.major)
        check_size(numbers, record.where, record.major)
    elif isinstance(record, Circle | Arelem):
        kind = type(record).__name__.upper()
        check_finite(record.values, record.where, kind)
        check_size(record.values, record.where, kind)


class CoordinateGuard:
    """The coordinates a machine can take: finite everywhere, within 2**53 steps, and on an
    absolute-coded machine (option 251 = 1, or positioning, option 1 != 0) within what the
    axis's own register holds (X in diameters under option 260)."""

    def __init__(self, machine: MachineDefinition, shuffle: Sequence[tuple[int, float] | None]):
        step = machine.number_option(14)
        self.reach = [LARGEST_STEPS * step] * 3
        self.registers: list[str | None] = [None] * 3
        absolute = machine.number_option(251) == 1 or machine.number_option(1) != 0
        if absolute:
            for axis, target in enumerate(shuffle[:3]):
                if target is None:
                    continue
                fmt = machine.registers.formats[target[0]]
                if fmt is None:
                    continue
                factor = 2.0 if machine.number_option(260) == 1 and target[0] == 3 else 1.0
                self.reach[axis] = fmt.largest / factor
                self.registers[axis] = machine.registers.letters[target[0]]

    def motion(
        self,
        record: Motion,
        previous: Sequence[float],
        translation: tuple[float, float, float],
    ) -> None:
        """Check each point a motion record reaches (GODLTA: from the previous point)."""
        godlta = record.subtype is MotionSubtype.GODLTA
        at = list(previous[:3])
        for point in record.points:
            check_finite(point, record.where, record.subtype.name)
            if godlta:
                delta = (0.0, 0.0, point[0]) if len(point) == 1 else point[:3]
                at = [at[a] + delta[a] for a in range(3)]
            else:
                at = [point[a] + translation[a] for a in range(min(3, len(point)))]
            for axis, value in enumerate(at):
                if abs(value) > self.reach[axis]:
                    self._beyond(record, axis, value)

    def _beyond(self, record: Motion, axis: int, value: float) -> None:
        letter = self.registers[axis]
        if letter is None:
            raise InputError(
                f"coordinate {value:g} is beyond any position the machine can reach "
                f"({LARGEST_STEPS:,} steps)",
                record.where,
            )
        raise InputError(
            f"{'XYZ'[axis]} {value:g} is beyond what the {letter} register holds "
            f"({self.reach[axis]:.12g})",
            record.where,
        )
