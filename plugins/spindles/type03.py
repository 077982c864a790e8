"""Spindle type 3: associated speed code with range and/or direction M codes (manual §4.5.4,
001 L14801-14893; TYPE03 L39227-39280).

The spindle command is an S code and an M code. The S code is the row number of the speed
plus the increment in option 47, rows numbered from 0 separately in each range, so it is
the same for every range. The range is selected by M code in one of two ways:

(a) range-only codes: one code per range, stored in both TABLEM slots of the range (71 and
    72 for range 1, 73 and 74 for range 2, ...); the direction comes from M03/M04 in
    TABLEM 4 and 5. The range code is output when it differs from the last one output.
(b) combined range-and-direction codes: two codes per range in TABLEM 71..82 (at most six
    ranges), replacing M03/M04, so TABLEM 4 and 5 are DMBITS. As for every 70-series
    pair, range n turns clockwise with TABLEM(70 + 2n) and counter-clockwise with
    TABLEM(69 + 2n) (the TABLEM list, 001 L23350-23400; docs/decisions.md).

The manual's table (option 47 = 2): speed 400 is S5 with range 1's code, or S3 with range
2's. The lowest range holding the speed is used unless RANGE,n is given. A spindle stop
before a range change is option 194's, applied by the kernel for every type.
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
    TableSpindle,
    choose_speed,
    speed_table,
)

KIND = "spindle type 3"
MOST_RANGES = 6  # TABLEM 71..82 hold two codes for each of six ranges

# The §4.5.4 table, scheme (a): range codes M41, M42, M43 standing for the manual's M1, M2,
# M3, each in both slots of its range, with M03/M04 (001 L14827-14861; range 3 row 3 is
# 900 as the second printing reads, docs/decisions.md).
MANUAL_EXAMPLE = """
[machine]
name = "spindle-type03"
title = "TYPE 3 SPINDLE (4.5.4)"
[optab]
7 = 3.0
8 = 5.0
19 = 3.0
47 = 2.0
[regfor]
12 = 10.0
[tablem]
71 = 41
72 = 41
73 = 42
74 = 42
75 = 43
76 = 43
[spindle_table]
speeds = [
  100.0, 200.0, 300.0, 400.0, 500.0,
  300.0, 400.0, 500.0, 600.0, 700.0,
  600.0, 700.0, 800.0, 900.0, 1000.0,
]
"""


def range_cells(number: int) -> dict[int, int]:
    """The TABLEM slots of a range's codes by direction."""
    return {CLW: 70 + 2 * number, CCLW: 69 + 2 * number}


@dataclass(frozen=True)
class RangeCodeSpindle(TableSpindle):
    number: int = 3
    name: str = "associated speed code with range and/or direction M codes"
    section: str = "§4.5.4"
    # TYPE03 prints "NO DIRECTION GIVEN IN FIRST SPINDLE STATEMENT" (001 L39250-39267)
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
        return ranges

    def range_only(self, machine: MachineDefinition, count: int) -> bool:
        """True for scheme (a) (M03/M04 present), False for scheme (b); the 70-series
        codes of every range must be there, and equal in scheme (a)."""
        clockwise, counter = machine.m_code(4), machine.m_code(5)
        if (clockwise is None) != (counter is None):
            raise MachineDefinitionError(
                machine.origin,
                "tablem",
                4 if clockwise is None else 5,
                f"{KIND}: TABLEM 4 and 5 are both direction codes (range-only M codes in "
                "71..82) or both absent (combined range-and-direction codes)",
            )
        range_only = clockwise is not None
        for number in range(1, count + 1):
            cells = range_cells(number)
            for cell in sorted(cells.values()):
                if machine.m_code(cell) is None:
                    raise MachineDefinitionError(
                        machine.origin,
                        "tablem",
                        cell,
                        f"{KIND}: range {number} needs its M codes in TABLEM "
                        f"{cells[CCLW]} (CCLW) and {cells[CLW]} (CLW)",
                    )
            if range_only and machine.m_code(cells[CLW]) != machine.m_code(cells[CCLW]):
                raise MachineDefinitionError(
                    machine.origin,
                    "tablem",
                    cells[CCLW],
                    f"{KIND}: with M03/M04 in TABLEM 4 and 5, range {number}'s range-only "
                    f"code goes in both TABLEM {cells[CCLW]} and {cells[CLW]}; set TABLEM 4 "
                    "and 5 absent for combined range-and-direction codes",
                )
        return range_only

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        ranges = self.ranges(machine)
        range_only = self.range_only(machine, len(ranges))
        increment = machine.number_option(47)
        if increment != int(increment) or increment < 0:
            raise MachineDefinitionError(
                machine.origin,
                "optab",
                47,
                f"{KIND}: option 47 (the code of row 0) must be a whole number >= 0; "
                f"found {increment:g}",
            )
        choice = choose_speed(ranges, request.speed, request.range, machine.number_option(90))
        cells = range_cells(choice.range)
        return SpindleSelection(
            choice.speed,
            float(choice.row + int(increment)),
            choice.range,
            choice.comments,
            direction_cells=None if range_only else cells,
            range_cell=cells[CLW] if range_only else None,
            row=choice.row,
        )


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(RangeCodeSpindle())
