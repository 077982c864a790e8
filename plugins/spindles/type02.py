"""Spindle type 2: associated speed code, with protective multiple shifting (manual §4.5.3
and §4.5.3.1, 001 L14662-14800; TYPE02 L39170-39210; option 137 L26008-26022).

For a given spindle speed there is an associated code number: the row number of the speed
plus the increment given in option 47, rising by one from row to row. There may be several
ranges, each with the same number of codes; the jump from the last code of one range to the
first code of the next is option 31. With rows numbered from 0 in each range and N speeds
per range, S = option 47 + row + (range - 1) x (N - 1 + option 31): in the manual's table
(option 47 = 10, option 31 = 3) speed 14 is S15 in range 1 or S20 in range 2.

Protective multiple shifting. On some machines it is damaging to change ranges while the
spindle turns high in its range; option 137 = +N names the shift-point row, counted from 1
at the lowest speed, at or below which a range change is safe. A change of range is then
made only between rows at or below the shift point:

* old and new speed above the shift row: down to the shift row in the old range, across
  to the shift row of the new range, then up to the new speed (30 -> 160 RPM outputs 10,
  120, 160; 160 -> 30 outputs 120, 10, 30);
* old speed above, new speed at or below it: down in the old range to the new speed's row,
  then across at that row (160 -> 4 RPM outputs 60, 4);
* both at or below it: direct (8 -> 100 RPM);
* old speed at or below, new speed above it (a case the manual does not describe): across
  at the old speed's row, then up (the reverse of the case before; docs/decisions.md).

Each intermediate speed is a block of its own; with option 54 it carries that dwell, so the
spindle settles before the next change (TYPE02 calls DWELL).
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.errors import MachineDefinitionError
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.core.spindle_types import (
    SpindleRequest,
    SpindleSelection,
    SpindleStep,
    TableSpindle,
    choose_speed,
)

KIND = "spindle type 2"

# The §4.5.3 table: three ranges of eight speeds, codes 10-17, 20-27, 30-37 (001 L14690-14744).
MANUAL_EXAMPLE = """
[machine]
name = "spindle-type02"
title = "TYPE 2 SPINDLE (4.5.3)"
[optab]
7 = 3.0
8 = 8.0
19 = 2.0
31 = 3.0
47 = 10.0
[regfor]
12 = 20.0
[spindle_table]
speeds = [
  5.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0, 18.0,
  14.0, 16.0, 18.0, 20.0, 22.0, 24.0, 26.0, 28.0,
  30.0, 32.0, 34.0, 36.0, 38.0, 40.0, 42.0, 44.0,
]
"""


def _whole(machine: MachineDefinition, option: int, low: float, rule: str) -> int:
    value = machine.number_option(option)
    if value != int(value) or value < low:
        raise MachineDefinitionError(
            machine.origin, "optab", option, f"{KIND}: {rule}; found {value:g}"
        )
    return int(value)


@dataclass(frozen=True)
class AssociatedSpeedCodeSpindle(TableSpindle):
    number: int = 2
    name: str = "associated speed code"
    section: str = "§4.5.3"
    manual_example: str = MANUAL_EXAMPLE

    def codes(
        self, machine: MachineDefinition, ranges: tuple[tuple[float, ...], ...]
    ) -> list[float]:
        """GESCOM's associated code of every speed, range after range: row 0 of range 1
        is option 47, and each range starts option 31 above the last code of the one
        before."""
        increment = _whole(
            machine, 47, 0, "option 47 (the code of row 0) must be a whole number >= 0"
        )
        between = 0
        if len(ranges) > 1:
            # 0 would give a range's last speed and the next range's first the same code
            between = _whole(
                machine,
                31,
                1,
                "with several ranges option 31 (last code of a range to the first of the "
                "next) must be a whole number >= 1",
            )
        rows = len(ranges[0])
        return [
            float(increment + row + (number - 1) * (rows - 1 + between))
            for number in range(1, len(ranges) + 1)
            for row in range(rows)
        ]

    def shift_row(self, machine: MachineDefinition) -> int:
        """Option 137 = +N: the shift-point row counted from 1; 0 = no protective shifting."""
        return _whole(
            machine,
            137,
            0,
            "option 137 is the shift-point row (a whole number >= 1, counted from the lowest "
            "speed) or 0; a negative value is type 10's shift speed",
        )

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        ranges = self.ranges(machine)
        codes = self.codes(machine, ranges)
        rows = len(ranges[0])
        choice = choose_speed(ranges, request.speed, request.range, machine.number_option(90))
        dwell = self._dwell(machine)
        steps = tuple(
            SpindleStep(codes[(number - 1) * rows + row], number, dwell)
            for number, row in self._shift_path(machine, ranges, request, choice.range, choice.row)
        )
        return SpindleSelection(
            choice.speed,
            codes[(choice.range - 1) * rows + choice.row],
            choice.range,
            choice.comments,
            steps=steps,
            row=choice.row,
        )

    def _shift_path(
        self,
        machine: MachineDefinition,
        ranges: tuple[tuple[float, ...], ...],
        request: SpindleRequest,
        new_range: int,
        new_row: int,
    ) -> list[tuple[int, int]]:
        """The (range, row) of each intermediate speed before the new one (rows 0-based)."""
        shift = self.shift_row(machine) - 1
        running = request.running
        if shift < 0 or running is None or running.range == new_range:
            return []
        old_range = running.range
        old_row = choose_speed(ranges, running.speed, old_range, -1).row
        if old_row <= shift and new_row <= shift:
            return []
        if old_row > shift and new_row > shift:
            return [(old_range, shift), (new_range, shift)]
        if old_row > shift:
            return [(old_range, new_row)]
        return [(new_range, old_row)]

    @staticmethod
    def _dwell(machine: MachineDefinition) -> float | None:
        seconds = machine.number_option(54)
        return seconds if seconds > 0 else None


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(AssociatedSpeedCodeSpindle())
