"""Spindle type 0: combination range and row (manual §4.5.1, 001 L14604-14634; TYPE00
L39093-39125).

The speed command is formed by using the range number as its first digit(s), and the row
number of the speed in that range, plus the increment given by option 47, as its last
digit(s). Rows are numbered from 0, separately in each range. With at most ten rows in a
range the row takes one digit (speed 12 in the manual's table is S15, range 1 row 5, or
S20, range 2 row 0); with more than ten rows it takes two (S622 is range 6, row 22), and
more than ten ranges simply give a longer command (S1204 is range 12, row 4; S1011 range
10, row 11). TYPE00 states the rule: K = 10, or 100 when a range holds more than ten
speeds, and S = range x K + row + option 47.

The range is the lowest that holds the speed unless RANGE,n is given, and a speed between
table speeds is chosen by option 90 (the kernel's LOCRNG and DSRROW).
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

KIND = "spindle type 0"

# The §4.5.1 table: three ranges of ten rows, option 47 = 0 (001 L14612-14624).
MANUAL_EXAMPLE = """
[machine]
name = "spindle-type00"
title = "TYPE 0 SPINDLE (4.5.1)"
[optab]
7 = 3.0
8 = 10.0
19 = 0.0
47 = 0.0
[regfor]
12 = 20.0
[spindle_table]
speeds = [
  2.0, 4.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0, 18.0, 20.0,
  12.0, 14.0, 16.0, 18.0, 20.0, 22.0, 24.0, 26.0, 28.0, 30.0,
  26.0, 28.0, 30.0, 32.0, 34.0, 36.0, 38.0, 40.0, 42.0, 44.0,
]
"""


@dataclass(frozen=True)
class CombinationRangeAndRowSpindle(TableSpindle):
    number: int = 0
    name: str = "combination range and row"
    section: str = "§4.5.1"
    manual_example: str = MANUAL_EXAMPLE

    def row_field(self, machine: MachineDefinition, rows: int) -> int:
        """TYPE00's K: the range number is multiplied by 10, or by 100 when a range holds
        more than ten speeds; the row code (row + option 47) must fit below it, or range r's
        last code would read as range r + 1."""
        field = 10 if rows <= 10 else 100
        increment = machine.number_option(47)
        if increment != int(increment) or increment < 0 or rows - 1 + increment >= field:
            raise MachineDefinitionError(
                machine.origin,
                "optab",
                47,
                f"{KIND}: the row codes 0 + option 47 .. {rows - 1} + option 47 must be whole "
                f"numbers 0..{field - 1} (range x {field} + row code); found option 47 = "
                f"{increment:g}",
            )
        return field

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        ranges = self.ranges(machine)
        field = self.row_field(machine, len(ranges[0]))
        choice = choose_speed(ranges, request.speed, request.range, machine.number_option(90))
        command = choice.range * field + choice.row + int(machine.number_option(47))
        return SpindleSelection(
            choice.speed, float(command), choice.range, choice.comments, row=choice.row
        )


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(CombinationRangeAndRowSpindle())
