"""Spindle type 8: associated speed code independent of range (manual §4.5.9,
001 L14982-15009; TYPE08 L39390-39420).

For a given spindle speed there is a speed code related to the row of the range the speed
falls in, the same whatever the range: the code of row 2 of range 1 is the code of row 2 of
range 2. The code is the row number, counted from 0 separately in each range, plus the
increment in option 47. Shifting between ranges is not tape controlled, so no range code is
output. In the manual's table (option 47 = 1) speed 40 is S04 in range 1 and S01 in range
2, and speed 70 with range 3 in use is S01. The range is the lowest holding the speed
unless RANGE,n is given.
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.errors import MachineDefinitionError
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.core.spindle_types import (
    SpindleRequest,
    SpindleSelection,
    TableSpindle,
    choose_speed,
)

# The §4.5.9 table: three ranges of five speeds, codes 1..5 (001 L14996-15002).
MANUAL_EXAMPLE = """
[machine]
name = "spindle-type08"
title = "TYPE 8 SPINDLE (4.5.9)"
[optab]
7 = 3.0
8 = 5.0
19 = 8.0
47 = 1.0
[regfor]
12 = 20.0
[spindle_table]
speeds = [
  10.0, 20.0, 30.0, 40.0, 50.0,
  40.0, 50.0, 60.0, 70.0, 80.0,
  70.0, 80.0, 90.0, 100.0, 110.0,
]
"""


@dataclass(frozen=True)
class RangeFreeSpeedCodeSpindle(TableSpindle):
    number: int = 8
    name: str = "associated speed code independent of range"
    section: str = "§4.5.9"
    manual_example: str = MANUAL_EXAMPLE

    def row_code(self, machine: MachineDefinition, row: int) -> float:
        """TYPE08: the 1-based row ISPDRO + option 47 - 1, i.e. row (0-based) + option 47."""
        increment = machine.number_option(47)
        if increment != int(increment) or increment < 0:
            raise MachineDefinitionError(
                machine.origin,
                "optab",
                47,
                f"{self.kind}: option 47 (the code of row 0) must be a whole number >= 0; "
                f"found {increment:g}",
            )
        return float(row + int(increment))

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        ranges = self.ranges(machine)
        choice = choose_speed(ranges, request.speed, request.range, machine.number_option(90))
        return SpindleSelection(
            choice.speed,
            self.row_code(machine, choice.row),
            choice.range,
            choice.comments,
            row=choice.row,
        )


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(RangeFreeSpeedCodeSpindle())
