"""Spindle type 15: ratio between ranges (manual §4.5.16, 001 L15358-15464; TYPE15
L39738-39775).

For spindle tables with a direct ratio between the speed and the command in each range:
speed = command x ratio(range). SRTAB(1..2R) holds the minimum and maximum speed of each of
the R = option 7 ranges (option 8 = 2, the two testing limits) and SRTAB(2R + r) the ratio
of range r: SRTAB(7), (8) and (9) for the manual's three ranges. No speeds are stored.

A requested speed is first held to the limits of its range (the lowest range that holds
it, or RANGE,n), with comment 80 or 63 outside them. Speed / ratio is the command; when it
is not a whole number, option 90 takes the next lower (-1), the closest (0) or the next
higher (+1) command, and the speed becomes command x ratio. So the range's speeds are the
whole commands whose speed lies within its limits, and the choice among them is the usual
table choice. With ratios 5, 7.5 and 20, 35 RPM is S7 in range 1; in range 2, 35/7.5 = 4.67
is S5 (37.5 RPM) under option 90 = 0 or +1 and S4 (30 RPM) under -1; range 3 raises the
speed to its minimum, 100 RPM: S5.

Range-and-direction M codes may come from TABLEM 71-76 (TABLEM(70 + 2n) CLW, (69 + 2n) CCLW):
when the machine has range 1's CLW code, each range's pair is output on a start, a reversal
or a range change and a repeated code is not output again; otherwise TABLEM 4/5.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from gecent.core.absent import ABSENT
from gecent.core.errors import MachineDefinitionError
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.core.spindle_types import CCLW, CLW, SpindleRequest, SpindleSelection, choose_speed

LARGEST_COMMAND = 9999  # four digits: more commands than any S register holds
_WHOLE = 1e-9  # 60 / 7.5 held as 7.999... is still command 8

EXAMPLE = """
[machine]
name = "type15-example"
title = "TYPE 15 SPINDLE"
[optab]
7 = 3.0
8 = 2.0
19 = 15.0
[spindle_table]
speeds = [5.0, 40.0, 30.0, 60.0, 100.0, 160.0, 5.0, 7.5, 20.0]
"""


@dataclass(frozen=True, slots=True)
class RatioRange:
    """One range: its ratio and its commands from ``first`` up, with their speeds."""

    ratio: float
    first: int
    speeds: tuple[float, ...]


def _range(machine: MachineDefinition, number: int, count: int) -> RatioRange:
    cells = (2 * number - 1, 2 * number, 2 * count + number)
    values = [machine.srtab(i) for i in cells]
    if ABSENT in values:
        raise MachineDefinitionError(
            machine.origin,
            "spindle_table",
            f"SRTAB({cells[values.index(ABSENT)]})",
            f"spindle type 15 range {number} needs its minimum, maximum and ratio in "
            f"SRTAB({cells[0]}), SRTAB({cells[1]}) and SRTAB({cells[2]})",
        )
    low, high, ratio = (float(v) for v in values if v is not ABSENT)
    first = math.ceil(low / ratio - _WHOLE) if ratio > 0 else 0
    last = math.floor(high / ratio + _WHOLE) if ratio > 0 else -1
    if not 0 <= low <= high or ratio <= 0 or first > last or last > LARGEST_COMMAND:
        raise MachineDefinitionError(
            machine.origin,
            "spindle_table",
            f"SRTAB({cells[2]})",
            f"spindle type 15 range {number}: needs 0 <= minimum <= maximum, a ratio above 0 "
            f"and at least one whole command (at most {LARGEST_COMMAND}) whose speed lies "
            f"within the limits; found {low:g} .. {high:g} RPM, ratio {ratio:g}",
        )
    return RatioRange(ratio, first, tuple(c * ratio for c in range(first, last + 1)))


@dataclass(frozen=True)
class RatioSpindle:
    number: int = 15
    name: str = "ratio between ranges"
    section: str = "§4.5.16"
    manual_example: str = EXAMPLE

    def ranges(self, machine: MachineDefinition) -> tuple[RatioRange, ...]:
        count = int(machine.number_option(7))
        if machine.number_option(8) != 2:
            raise MachineDefinitionError(
                machine.origin,
                "optab",
                8,
                "spindle type 15 needs option 8 = 2 (the two testing limits of each range); "
                f"found {machine.number_option(8):g}",
            )
        ranges = tuple(_range(machine, n, count) for n in range(1, count + 1))
        if machine.m_code(72) is not None:
            missing = [
                cell
                for n in range(1, count + 1)
                for cell in (69 + 2 * n, 70 + 2 * n)
                if cell > 82 or machine.m_code(cell) is None
            ]
            if missing:
                raise MachineDefinitionError(
                    machine.origin,
                    "tablem",
                    missing[0],
                    "spindle type 15 with range-and-direction codes (TABLEM(72) is set) needs "
                    "the CLW and CCLW code of every range in TABLEM 71-82",
                )
        return ranges

    def range_count(self, machine: MachineDefinition) -> int:
        return len(self.ranges(machine))

    def speed_limits(self, machine: MachineDefinition, range_number: int) -> tuple[float, float]:
        speeds = self.ranges(machine)[range_number - 1].speeds
        return speeds[0], speeds[-1]

    def table_speeds(
        self, machine: MachineDefinition, range_number: int
    ) -> tuple[float, ...] | None:
        return self.ranges(machine)[range_number - 1].speeds

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        ranges = self.ranges(machine)
        choice = choose_speed(
            tuple(r.speeds for r in ranges),
            request.speed,
            request.range,
            machine.number_option(90),
        )
        command = ranges[choice.range - 1].first + choice.row
        cells = None
        if machine.m_code(72) is not None:
            cells = {CLW: 70 + 2 * choice.range, CCLW: 69 + 2 * choice.range}
        return SpindleSelection(
            choice.speed,
            float(command),
            choice.range,
            choice.comments,
            direction_cells=cells,
            row=choice.row,
        )


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(RatioSpindle())
