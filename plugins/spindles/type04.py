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

TYPE04 also lowers the spindle to a shift speed SHFSPD before a range change, but neither
the manual nor the option table says how SHFSPD is found (option 137 names types 2 and 10
only), so a type 4 machine with option 137 set stops with "not yet supported".
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.errors import MachineDefinitionError, NotYetSupported
from gecent.core.feed.magic3 import magic3
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

KIND = "spindle type 4"
MOST_RANGES = 6  # TABLEM 71..82 hold two codes for each of six ranges

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
        if machine.number_option(137) != 0:
            raise NotYetSupported(
                "spindle type 4 down-shift protection (option 137): the manual does not say "
                "how the shift speed SHFSPD is found"
            )
        choice = choose_speed(ranges, request.speed, request.range, machine.number_option(90))
        code = magic3(ranges[0][choice.row])
        assert code is not None  # ranges() keeps the range 1 speeds within magic three's span
        return SpindleSelection(
            choice.speed,
            float(code),
            choice.range,
            choice.comments,
            direction_cells=range_cells(choice.range),
            row=choice.row,
        )


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(QuasiEiaRangeSpindle())
