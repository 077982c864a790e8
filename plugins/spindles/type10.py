"""Spindle type 10: variable speed with range and direction M code, and protective
multiple shifting (manual §4.5.11 and §4.5.11.1, 001 L15040-15111; TYPE10 L39462-39505).

Each range is a minimum and a maximum speed (SRTAB, option 8 = 2). The lowest range that
holds the speed is used unless RANGE,n is given; the S command is the EIA magic three of
the speed, and the M code names range and direction: TABLEM(70 + 2n) CLW and TABLEM(69 + 2n)
CCLW for range n (001 L23350-23400). With a negative option 137, a range change from a
speed above |option 137| x the present range's maximum first drops to that speed with a
6-second dwell (option 54 is not used by this type).
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
    SpindleRequest,
    SpindleSelection,
    SpindleStep,
    TableSpindle,
    limited,
    range_for,
)

# The §4.5.11 example: ranges 1.2-13, 3.1-31 and 6.6-69 RPM with M60/M61, M62/M63,
# M64/M65 for CLW/CCLW (001 L15050-15062).
MANUAL_EXAMPLE = """
[machine]
name = "spindle-type10"
title = "TYPE 10 SPINDLE (4.5.11)"
[optab]
7 = 3.0
8 = 2.0
19 = 10.0
[tablem]
71 = 61
72 = 60
73 = 63
74 = 62
75 = 65
76 = 64
[spindle_table]
speeds = [1.2, 13.0, 3.1, 31.0, 6.6, 69.0]
"""

SHIFT_DWELL = 6.0  # seconds, fixed by the manual (001 L15092-15097)


def _code(speed: float) -> float:
    code = magic3(speed)
    assert code is not None  # the ranges keep the speed within magic three's span
    return float(code)


@dataclass(frozen=True)
class VariableRangeSpindle(TableSpindle):
    number: int = 10
    name: str = "variable speed with range and direction M code"
    section: str = "§4.5.11"
    # TYPE10 prints "NO DIRECTION GIVEN IN FIRST SPINDLE STATEMENT" (001 L39493-39524)
    names_missing_direction: bool = True
    manual_example: str = MANUAL_EXAMPLE
    own_dwells: bool = True  # its shift dwell is fixed at 6 s; option 54 is not used

    def ranges(self, machine: MachineDefinition) -> tuple[tuple[float, float], ...]:
        ranges = machine.spindle_ranges()
        if (
            machine.number_option(8) != 2
            or not ranges
            or any(len(r) != 2 or not 0 < r[0] <= r[1] <= 9999 for r in ranges)
        ):
            raise MachineDefinitionError(
                machine.origin,
                "spindle_table",
                "speeds",
                "spindle type 10 needs option 8 = 2 and a minimum and maximum speed per range, "
                f"0 < minimum <= maximum <= 9999 RPM; found {list(ranges)}",
            )
        return tuple((r[0], r[1]) for r in ranges)

    def table_speeds(
        self, machine: MachineDefinition, range_number: int
    ) -> tuple[float, ...] | None:
        return None  # variable: SFM steps by option 15

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        ranges = self.ranges(machine)
        number = range_for(ranges, request.speed, request.range)
        low, high = ranges[number - 1]
        speed, comments = limited(request.speed, low, high)
        running = request.running
        cells = {CLW: 70 + 2 * number, CCLW: 69 + 2 * number}
        steps: tuple[SpindleStep, ...] = ()
        fraction = abs(machine.number_option(137))
        if machine.number_option(137) < 0 and running is not None and running.range != number:
            fraction = fraction if fraction <= 1 else fraction / 100  # "percent" in the text
            shift_speed = fraction * ranges[running.range - 1][1]
            if running.speed > shift_speed:
                steps = (SpindleStep(_code(shift_speed), running.range, SHIFT_DWELL),)
        return SpindleSelection(
            speed, _code(speed), number, comments, direction_cells=cells, steps=steps
        )


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(VariableRangeSpindle())
