"""Selecting the dimension G code of a linear move (SELG, manual §3.4.6, 001 L5836-6036).

The control reads a departure in the range its G code announces, so the block's G code must
cover the largest departure: the smallest available range that does. GDIMUL is that range's
dimension multiplier times ten (001 L5946-5957), used later by the feedrate number.
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.absent import ABSENT
from gecent.core.errors import FatalError
from gecent.core.machine.definition import MachineDefinition

# (TABLEG location, GDIMUL) in order of range, smallest first (001 L6001-6013)
LINEAR_RANGES = ((13, 0.1), (12, 1.0), (2, 10.0), (11, 100.0), (14, 1000.0), (15, 10000.0))
INCH_LIMITS = (0.1, 1.0, 10.0, 100.0, 1000.0)  # RNGDEP, option 138 = 0 (001 L5885-5897)
METRIC_LIMITS = (1.0, 10.0, 100.0, 1000.0)  # option 138 = 1; the fifth is option 4
# a range's rank in magnitude order, by its linear TABLEG location (13 < 12 < 2 < 11 < 14 < 15)
RANK = {location: rank for rank, (location, _) in enumerate(LINEAR_RANGES)}


@dataclass(frozen=True, slots=True)
class DimensionCode:
    code: int  # the G code number (TABLEG value)
    location: int  # its TABLEG location
    gdimul: float
    size_class: int = 0  # the linear range location of its size (13, 12, 2, 11, 14, 15)


class LinearCodes:
    """SELG for one machine: the departure limits in steps and the available codes."""

    def __init__(self, machine: MachineDefinition, step: float) -> None:
        metric = machine.number_option(138) == 1
        limits = (*METRIC_LIMITS, machine.number_option(4)) if metric else INCH_LIMITS
        # RNGDEP in steps: a departure of d steps is in range i when d < limit_i / STEP
        self.limits = tuple(limit / step for limit in limits)
        self.depmax = round(machine.number_option(4) / step)
        codes: list[DimensionCode | None] = []
        for location, gdimul in LINEAR_RANGES:
            value = machine.tableg[location]
            codes.append(
                None if value is ABSENT else DimensionCode(int(value), location, gdimul, location)
            )
        self.codes = tuple(codes)

    def select(self, largest_steps: int) -> DimensionCode:
        """The code for a block whose largest |departure| is ``largest_steps`` steps."""
        if largest_steps > self.depmax:
            raise FatalError(139, f"departure of {largest_steps} steps exceeds option 4")
        code = _covering(self.codes, self.limits, largest_steps)
        if code is None:
            raise FatalError(138, f"no TABLEG code covers a departure of {largest_steps} steps")
        return code

    def smaller(self, code: DimensionCode) -> list[tuple[DimensionCode, float]]:
        """The available codes below ``code``, largest first, each with its upper limit in
        steps (a departure must stay under it): TSTFCM's candidates."""
        index = next(
            i for i, c in enumerate(self.codes) if c is not None and c.location == code.location
        )
        return [
            (candidate, self.limits[i])
            for i in range(index - 1, -1, -1)
            if (candidate := self.codes[i]) is not None
        ]


class RotaryCodes:
    """SELGRO (001 L6171-6282): a rotary departure (output units) against option 111's
    maximum over 1000, 100, 10 and 1, in TABLEG 13, 12, 2, 11 (no rotary TABLEG(14))."""

    def __init__(self, machine: MachineDefinition, maximum_units: float) -> None:
        self.limits = tuple(maximum_units / d for d in (1000.0, 100.0, 10.0))
        self.maximum = maximum_units  # ROTMAX: SEGMNT keeps every block within it
        codes: list[DimensionCode | None] = []
        for location, gdimul in LINEAR_RANGES[:4]:
            value = machine.tableg[location]
            codes.append(
                None if value is ABSENT else DimensionCode(int(value), location, gdimul, location)
            )
        self.codes = tuple(codes)

    def block_limit(self, maximum_units: float) -> float:
        """The largest rotary departure one block can hold on this machine (output units):
        ROTMAX (option 111), or where the machine lacks TABLEG(11) the top of the largest
        range it has a code for (ROTMAX / 10 with TABLEG(2) ...): SEGMNT cuts turns to
        it, so a machine without the top code turns in more blocks rather than stopping
        with fatal 39 (docs/decisions.md)."""
        tops = (*self.limits, maximum_units)
        present = [top for top, code in zip(tops, self.codes, strict=True) if code is not None]
        return max(present) if present else maximum_units

    def select(self, largest_units: float) -> DimensionCode:
        if largest_units > self.maximum * (1 + 1e-9):  # SELGRO's error 39 (001 L37130)
            raise FatalError(39, f"rotary departure {largest_units:g} exceeds option 111")
        code = _covering(self.codes, self.limits, largest_units)
        if code is None:
            # SELGRO's one fatal error is 39 (001 L37106-37144; 138 is SELG's, L36925-36971):
            # a turn no code takes should have been segmented shorter
            raise FatalError(39, f"no TABLEG code covers a rotary departure of {largest_units:g}")
        return code

    def needed(self, largest_units: float) -> int:
        """The rank (in LINEAR_RANGES' order) of the smallest rotary range that covers
        ``largest_units``: 0 for TABLEG(13)'s up to 3 for TABLEG(11)'s."""
        return next(
            (i for i, limit in enumerate(self.limits) if largest_units < limit), len(self.limits)
        )

    def covers(self, code: DimensionCode, largest_units: float) -> bool:
        """Whether a linear or circular code's range, read as a rotary range, takes the
        rotary departure ``largest_units`` (a code above TABLEG(11)'s size takes any)."""
        return largest_units == 0.0 or RANK[code.size_class] >= self.needed(largest_units)

    def with_linear(self, code: DimensionCode, largest_units: float) -> DimensionCode:
        """SELG, then SELGRO for a multiaxis move (001 L6052-6069, L6261-6282, W22): the
        linear code stays when its rotary range covers the largest rotary departure;
        otherwise SELGRO's own code, which is then the larger and covers the linear
        departures too. Fatal 39 when the machine has no code for the rotary departure."""
        return code if self.covers(code, largest_units) else self.select(largest_units)


def larger(first: DimensionCode, second: DimensionCode) -> DimensionCode:
    """The combination rule: a block with linear (or circular) and rotary departures takes
    the larger of the two ranges, which covers both (001 L6261-6282)."""
    return first if RANK[first.size_class] >= RANK[second.size_class] else second


# (CLW location, CCLW location, GDIMUL) per radius band (SELGCR, 001 L6076-6170)
CIRCULAR_RANGES = (
    (23, 33, 0.1),
    (22, 32, 1.0),
    (3, 4, 10.0),
    (21, 31, 100.0),
    (44, 45, 1000.0),
    (49, 50, 10000.0),
)


def circular_departure(machine: MachineDefinition) -> float:
    """The maximum departure of circular interpolation: option 223 when it gives one, else
    option 4, which then bounds lines and circles alike (001 L26719-26728)."""
    separate = machine.number_option(223)
    return separate if separate > 0 else machine.number_option(4)


class CircularCodes:
    """SELGCR: the circular G code for the radius band and direction, skipping absent codes
    upward as SELG does; fatal 142 beyond the circular maximum departure (option 223, or
    option 4), fatal 144 with no code."""

    def __init__(self, machine: MachineDefinition) -> None:
        metric = machine.number_option(138) == 1
        self.depmax = circular_departure(machine)
        self.limits = (*METRIC_LIMITS, self.depmax) if metric else INCH_LIMITS
        self.codes: dict[bool, tuple[DimensionCode | None, ...]] = {}
        for clockwise in (True, False):
            codes: list[DimensionCode | None] = []
            for (cw, ccw, gdimul), (size_class, _) in zip(
                CIRCULAR_RANGES, LINEAR_RANGES, strict=True
            ):
                location = cw if clockwise else ccw
                value = machine.tableg[location]
                # an arc's radius band is the same size class as a linear range (inverse time)
                codes.append(
                    None
                    if value is ABSENT
                    else DimensionCode(int(value), location, gdimul, size_class)
                )
            self.codes[clockwise] = tuple(codes)

    def select(self, radius: float, clockwise: bool) -> DimensionCode:
        if radius > self.depmax:
            raise FatalError(
                142, f"radius {radius:g} exceeds the maximum departure {self.depmax:g}"
            )
        code = _covering(self.codes[clockwise], self.limits, radius)
        if code is None:
            raise FatalError(144, f"no TABLEG code for a radius of {radius:g}")
        return code


def circle_code(
    circular: CircularCodes, rotary: RotaryCodes, radius: float, clockwise: bool, turn: float
) -> DimensionCode:
    """SELGCR, then SELGRO for a multiaxis circle (001 L6150-6170, L6261-6282, W24): the
    circular code for the radius unless the largest rotary departure ``turn`` (output units)
    needs a larger range; then the circular code of the smallest rotary range that covers
    it, skipping absent codes upward within the rotary ranges (open question 11: a
    circular block keeps a circular code). Fatal 144 when the machine has none."""
    code = circular.select(radius, clockwise)
    if rotary.covers(code, turn):
        return code
    if turn > rotary.maximum * (1 + 1e-9):  # SELGRO's error 39 (001 L37130)
        raise FatalError(39, f"rotary departure {turn:g} exceeds option 111")
    bands = circular.codes[clockwise][rotary.needed(turn) : len(rotary.limits) + 1]
    found = next((c for c in bands if c is not None), None)
    if found is None:
        raise FatalError(144, f"no circular TABLEG code covers a rotary departure of {turn:g}")
    return found


def _covering(
    codes: tuple[DimensionCode | None, ...], limits: tuple[float, ...], size: float
) -> DimensionCode | None:
    """The smallest range whose limit exceeds ``size`` (the last range has none), moving
    up past codes the machine lacks: "only those G codes which are actually available"
    (001 L5959-5962)."""
    index = next((i for i, limit in enumerate(limits) if size < limit), len(limits))
    return next((code for code in codes[index:] if code is not None), None)
