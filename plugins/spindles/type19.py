"""Spindle type 19: stop, comment and new speed on every range change (manual §4.5.20,
001 L15630-15647; TYPE19 L39904-39935). It is the old type 7 spindle of GECENT II.

Each time the spindle changes ranges the postprocessor issues three blocks: a block with
the stop M code, the postprocessor comment "A SPINDLE SPEED CHANGE OCCURS AT THIS POINT",
and a non-motion block carrying the new spindle speed:

    N123G04M00
    A SPINDLE SPEED CHANGE OCCURS AT THIS POINT
    N125G04S45

The stop code is TABLEM(1), the program stop (M00 in the example): the gears are changed
while the machine waits. The G04 comes from option 38, as on every block without a G code.
The manual does not say how the S code is made; TYPE19 reads the range, the row, the
options and SRTAB, so it is taken to be type 2's associated code (GESCOM):
S = option 47 + row + (range - 1) x (option 8 - 1 + option 31), rows counted from 0 in each
range of option 8 speeds. (Option 31 = 1 - option 8 repeats the same codes in every range.)
The range is the lowest that holds the speed unless RANGE,n is given, option 90 chooses
between table speeds, and a speed outside the table gets its nearer end, with comment 80
or 63.
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
    check_ascending,
    choose_speed,
)

STOP_CELL = 1  # TABLEM(1), program stop
SPEED_CHANGE = "A SPINDLE SPEED CHANGE OCCURS AT THIS POINT"

EXAMPLE = """
[machine]
name = "type19-example"
title = "TYPE 19 SPINDLE"
[optab]
7 = 2.0
8 = 6.0
19 = 19.0
31 = 1.0
38 = 1.0
47 = 40.0
[spindle_table]
speeds = [
  50.0, 63.0, 80.0, 100.0, 125.0, 160.0,
  200.0, 250.0, 315.0, 400.0, 500.0, 630.0,
]
"""


@dataclass(frozen=True)
class RangeStopSpindle(TableSpindle):
    number: int = 19
    name: str = "stop, comment and new speed on a range change"
    section: str = "§4.5.20"
    manual_example: str = EXAMPLE

    def ranges(self, machine: MachineDefinition) -> tuple[tuple[float, ...], ...]:
        ranges = machine.spindle_ranges()
        count = int(machine.number_option(7)) * int(machine.number_option(8))
        if len(machine.spindle_speeds()) != count:
            raise MachineDefinitionError(
                machine.origin,
                "spindle_table",
                "speeds",
                f"spindle type 19 needs option 7 x option 8 = {count} speeds in SRTAB; "
                f"found {len(machine.spindle_speeds())}",
            )
        check_ascending(machine, ranges, "spindle type 19")
        if len(ranges) > 1 and machine.m_code(STOP_CELL) is None:
            raise MachineDefinitionError(
                machine.origin,
                "tablem",
                STOP_CELL,
                "spindle type 19 stops the program (TABLEM(1)) on every range change; the "
                "machine has more than one range but no program stop code",
            )
        return ranges

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        ranges = self.ranges(machine)
        choice = choose_speed(ranges, request.speed, request.range, machine.number_option(90))
        per_range = int(machine.number_option(8))
        code = (
            machine.number_option(47)
            + choice.row
            + (choice.range - 1) * (per_range - 1 + machine.number_option(31))
        )
        running = request.running
        change = running is not None and running.range != choice.range
        return SpindleSelection(
            choice.speed,
            code,
            choice.range,
            choice.comments,
            stop_cell=STOP_CELL if change else None,
            stop_comment=SPEED_CHANGE if change else None,
            row=choice.row,
        )


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(RangeStopSpindle())
