"""Spindle type 4: quasi-EIA 3-digit code number with range and direction M code (manual
§4.5.5, 001 L14894-14930; TYPE04 L39285-39340).

The spindle command is an M code chosen by the range and the spindle direction, and the EIA
3-digit ("magic three") code of the speed in the lowest range that occupies the same row as
the desired speed. The code is the true speed only in range 1; in the other ranges it is
an arbitrary row label. In the manual's table speed 600 can be S660 with range 1's code,
S630 with range 2's or S610 with range 3's; the lowest range is used unless RANGE,n is
given. The M code of range n is TABLEM(70 + 2n) clockwise and TABLEM(69 + 2n)
counter-clockwise (TABLEM 71..82, at most six ranges), output when the spindle starts,
reverses or changes range.

Down-shift protection (TYPE04, 001 L39310-39322): before a range change from a speed above
the shift speed SHFSPD the spindle first drops to SHFSPD in its present range, with a dwell.
TYPE04 does not say how SHFSPD is found; its method is TYPE10's step for step (L39493-39509),
and TYPE10 finds it from a negative option 137, "|N| percent of maximum in current range
with a 6 second dwell" (L26008-26023). Type 4 reads option 137 the same way; its SHFSPD is
then the table speed of the present range that option 90 gives for that percentage (a type
4 spindle turns only at its table's speeds), coded as every type 4 speed is. A positive
option 137 (shift rows) is type 2's and a machine-definition error here.
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.errors import MachineDefinitionError
from gecent.core.feed.magic3 import magic3
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.core.spindle_types import (
    CCLW,
    CLW,
    SAME_SPEED,
    SpindleRequest,
    SpindleSelection,
    SpindleStep,
    TableSpindle,
    choose_speed,
    speed_table,
)

KIND = "spindle type 4"
MOST_RANGES = 6  # TABLEM 71..82 hold two codes for each of six ranges
SHIFT_DWELL = 6.0  # seconds: option 137's -N "with a 6 second dwell" (001 L26019-26021)

# The §4.5.5 table: three ranges (Low, Medium, High) of six speeds; M1, M2, M3 clockwise
# are M41, M42, M43 here, and M44, M45, M46 counter-clockwise (001 L14906-14925).
MANUAL_EXAMPLE = """
[machine]
name = "spindle-type04"
title = "TYPE 4 SPINDLE (4.5.5)"
[optab]
7 = 3.0
8 = 6.0
19 = 4.0
[tablem]
4 = "absent"
5 = "absent"
71 = 44
72 = 41
73 = 45
74 = 42
75 = 46
76 = 43
[spindle_table]
speeds = [
  100.0, 200.0, 300.0, 400.0, 500.0, 600.0,
  400.0, 500.0, 600.0, 700.0, 800.0, 900.0,
  600.0, 700.0, 800.0, 900.0, 1000.0, 1100.0,
]
"""


def range_cells(number: int) -> dict[int, int]:
    """The TABLEM slots of a range's codes by direction."""
    return {CLW: 70 + 2 * number, CCLW: 69 + 2 * number}


@dataclass(frozen=True)
class QuasiEiaRangeSpindle(TableSpindle):
    number: int = 4
    name: str = "quasi EIA 3-digit code number with range and direction M code"
    section: str = "§4.5.5"
    # TYPE04 prints "NO DIRECTION GIVEN IN FIRST SPINDLE STATEMENT" (001 L39305-39334)
    names_missing_direction: bool = True
    manual_example: str = MANUAL_EXAMPLE

    def ranges(self, machine: MachineDefinition) -> tuple[tuple[float, ...], ...]:
        ranges = speed_table(machine, KIND)
        if len(ranges) > MOST_RANGES:
            raise MachineDefinitionError(
                machine.origin,
                "optab",
                7,
                f"{KIND} codes at most {MOST_RANGES} ranges in TABLEM 71..82; found {len(ranges)}",
            )
        if any(magic3(speed) is None or speed <= 0 for speed in ranges[0]):
            raise MachineDefinitionError(
                machine.origin,
                "spindle_table",
                "speeds",
                f"{KIND}: the range 1 speeds are the S codes of every range, so each must be "
                f"0.0001..9999 RPM for the EIA code; found {list(ranges[0])}",
            )
        return ranges

    def check_codes(self, machine: MachineDefinition, count: int) -> None:
        for number in range(1, count + 1):
            cells = range_cells(number)
            for cell in sorted(cells.values()):
                if machine.m_code(cell) is None:
                    raise MachineDefinitionError(
                        machine.origin,
                        "tablem",
                        cell,
                        f"{KIND}: range {number} needs its range-and-direction M codes in "
                        f"TABLEM {cells[CCLW]} (CCLW) and {cells[CLW]} (CLW)",
                    )

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        ranges = self.ranges(machine)
        self.check_codes(machine, len(ranges))
        rule = machine.number_option(90)
        choice = choose_speed(ranges, request.speed, request.range, rule)
        return SpindleSelection(
            choice.speed,
            _code(ranges, choice.row),
            choice.range,
            choice.comments,
            direction_cells=range_cells(choice.range),
            steps=self._down_shift(machine, ranges, choice.range, request),
            row=choice.row,
        )

    def _down_shift(
        self,
        machine: MachineDefinition,
        ranges: tuple[tuple[float, ...], ...],
        new_range: int,
        request: SpindleRequest,
    ) -> tuple[SpindleStep, ...]:
        """SHFSPD: on a range change from above it, the present range's table speed for
        |option 137| of the range's maximum (a fraction up to 1, else a percent), with the
        6-second dwell; nothing when option 137 is 0."""
        option = machine.number_option(137)
        if option > 0:
            raise MachineDefinitionError(
                machine.origin,
                "optab",
                137,
                f"{KIND}: option 137 = +{option:g} shifts through a row, which only type 2 "
                "does; type 4's down-shift takes -N, a percentage of the range's maximum",
            )
        running = request.running
        if option == 0 or running is None or running.range == new_range:
            return ()
        fraction = -option if -option <= 1 else -option / 100
        present = ranges[running.range - 1]
        rule = machine.number_option(90)
        shift = choose_speed(ranges, fraction * present[-1], running.range, rule)
        if running.speed <= shift.speed + SAME_SPEED:
            return ()  # at or below the shift speed: a direct shift
        return (SpindleStep(_code(ranges, shift.row), running.range, SHIFT_DWELL),)


def _code(ranges: tuple[tuple[float, ...], ...], row: int) -> float:
    """The S command of a row: the magic three of range 1's speed in that row."""
    code = magic3(ranges[0][row])
    assert code is not None  # ranges() keeps the range 1 speeds within magic three's span
    return float(code)


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(QuasiEiaRangeSpindle())
