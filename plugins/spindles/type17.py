"""Spindle type 17: proportional three-digit code within each range (manual §4.5.18,
001 L15518-15555; TYPE17 L39825-39855).

Speeds are selected within each range by a three-digit S code, S000 through S999:

    SN = (SD - SMIN) / (SMAX - SMIN) x 1000

SN is the S code, SD the desired speed and SMIN, SMAX the minimum and maximum speed of the
range, kept in SRTAB(2r - 1) and SRTAB(2r) (option 7 = number of ranges; option 8 is the
two limits). The range is the lowest whose limits hold the speed, or RANGE,n; a speed
outside them gets the nearer limit, with comment 80 or 63. S999 is the highest code, so the
maximum speed itself is S999. A speed between two codes is chosen by option 90 (next lower,
closest, next higher code), and the spindle turns SMIN + SN x (SMAX - SMIN) / 1000.

Speed changes within a range are made without stopping the spindle. When the spindle must
stop before a range change, the manual says "set option 216 = 1"; the option table has
option 194 for that, which the kernel honours for every type, and this type honours 216
as well: TABLEM(6), then the new speed with TABLEM 4/5 to restart. TYPE17 uses no M code
table, so there are no range M codes. In SFM, with its thousand codes per range, the type
is variable (option 15 steps).
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.errors import MachineDefinitionError
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.core.spindle_types import (
    CCLW,
    CLW,
    SpindleRequest,
    SpindleSelection,
    choose_speed,
    limited,
    range_for,
)

SCALE = 1000  # the proportional code's full scale (001 L15522-15530)
HIGHEST_CODE = 999
STOP_CELL = 6  # TABLEM(6), spindle off
SPINDLE_ON_CELLS = {CLW: 4, CCLW: 5}

EXAMPLE = """
[machine]
name = "type17-example"
title = "TYPE 17 SPINDLE"
[optab]
7 = 2.0
8 = 2.0
19 = 17.0
[spindle_table]
speeds = [50.0, 550.0, 400.0, 2400.0]
"""


def code_speeds(low: float, high: float) -> tuple[float, ...]:
    """The speed of each code S000 .. S999 of a range."""
    step = (high - low) / SCALE
    return tuple(low + code * step for code in range(HIGHEST_CODE + 1))


@dataclass(frozen=True)
class ProportionalSpindle:
    number: int = 17
    name: str = "proportional 3-digit code within each range"
    section: str = "§4.5.18"
    manual_example: str = EXAMPLE

    def limits(self, machine: MachineDefinition) -> tuple[tuple[float, float], ...]:
        ranges = machine.spindle_ranges()
        if (
            machine.number_option(8) != 2
            or not ranges
            or any(len(r) != 2 or not 0 <= r[0] < r[1] for r in ranges)
        ):
            raise MachineDefinitionError(
                machine.origin,
                "spindle_table",
                "speeds",
                "spindle type 17 needs option 8 = 2 and SRTAB(2r - 1) = minimum < SRTAB(2r) "
                f"= maximum speed for each range; found {[list(r) for r in ranges]}",
            )
        return tuple((r[0], r[1]) for r in ranges)

    def range_count(self, machine: MachineDefinition) -> int:
        return len(self.limits(machine))

    def speed_limits(self, machine: MachineDefinition, range_number: int) -> tuple[float, float]:
        return self.limits(machine)[range_number - 1]

    def table_speeds(
        self, machine: MachineDefinition, range_number: int
    ) -> tuple[float, ...] | None:
        return None  # a thousand codes per range: variable in SFM

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        limits = self.limits(machine)
        number = range_for(limits, request.speed, request.range)
        low, high = limits[number - 1]
        speed, comments = limited(request.speed, low, high)
        codes = code_speeds(low, high)
        # S999 is the top code: the speeds above it, up to the maximum, are S999
        choice = choose_speed((codes,), min(speed, codes[-1]), 1, machine.number_option(90))
        stop = None
        restart = None
        running = request.running
        range_change = running is not None and running.range != number
        if range_change and machine.number_option(216) == 1 and machine.number_option(194) != 1:
            stop, restart = STOP_CELL, SPINDLE_ON_CELLS
        return SpindleSelection(
            choice.speed,
            float(choice.row),
            number,
            comments,
            direction_cells=restart,
            stop_cell=stop,
            row=choice.row,
        )


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(ProportionalSpindle())
