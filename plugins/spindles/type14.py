"""Spindle type 14: speed changes by mode (manual §4.5.15, 001 L15304-15357; TYPE14
L39690-39725; GESCOM L32807-32850).

The spindle is coded as a type 2 spindle, except that M codes select a mode, a set of
several ranges. Each mode is programmed as a separate type 2 spindle and all modes have
the same S codes: S = option 47 + row + (range in the mode - 1) x (N - 1 + option 31), rows
counted from 0 and N = option 8 speeds per range. Ranges 1-10 are mode 1 and ranges 11-20
mode 2 (TYPE14); SRTAB holds them by that number, option 7 being the highest range used,
so a machine with mode-2 ranges has option 7 > 10 and fills the mode-1 ranges it does not
use with zeros (a range of zeros is no range). RANGE,13 is range 3 of mode 2.

When the mode changes, the new mode's M code goes out: TABLEM(72) for mode 1, TABLEM(74)
for mode 2; within a mode no M code is output. The direction is TABLEM 4/5 as usual.
Example (option 47 = 10, option 31 = 3): 40 RPM in range 3 is S35 in mode 1; in range 13
(mode 2) 40 RPM is below the range minimum, 120, which gives S30.
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
    range_for,
)

RANGES_PER_MODE = 10  # ranges 1-10 are mode 1, 11-20 mode 2 (001 L39705-39710)
MODE_CELLS = {1: 72, 2: 74}  # TABLEM cell of each mode's M code
NOT_AVAILABLE = "RANGE REQUESTED IS NOT AVAILABLE, USE HIGHEST"

_EXAMPLE_SPEEDS = (
    [5.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0, 18.0]
    + [14.0, 16.0, 18.0, 20.0, 22.0, 24.0, 26.0, 28.0]
    + [30.0, 32.0, 34.0, 36.0, 38.0, 40.0, 42.0, 44.0]
    + [0.0] * 8 * 7
    + [20.0, 24.0, 32.0, 40.0, 48.0, 56.0, 64.0, 68.0]
    + [56.0, 64.0, 68.0, 80.0, 88.0, 96.0, 104.0, 112.0]
    + [120.0, 128.0, 136.0, 144.0, 152.0, 160.0, 168.0, 176.0]
)
EXAMPLE = f"""
[machine]
name = "type14-example"
title = "TYPE 14 SPINDLE"
[optab]
7 = 13.0
8 = 8.0
19 = 14.0
31 = 3.0
47 = 10.0
[tablem]
72 = 26
74 = 27
[spindle_table]
speeds = {_EXAMPLE_SPEEDS}
"""


def mode_of(range_number: int) -> int:
    return 1 if range_number <= RANGES_PER_MODE else 2


@dataclass(frozen=True)
class ModeSpindle(TableSpindle):
    number: int = 14
    name: str = "speed changes by mode"
    section: str = "§4.5.15"
    manual_example: str = EXAMPLE

    def ranges(self, machine: MachineDefinition) -> tuple[tuple[float, ...], ...]:
        """SRTAB's ranges by number; an unused range (all zeros) is empty."""
        table = machine.spindle_ranges()
        count = int(machine.number_option(7))
        if count > 2 * RANGES_PER_MODE or len(table) != count:
            raise MachineDefinitionError(
                machine.origin,
                "optab",
                7,
                f"spindle type 14 has at most {2 * RANGES_PER_MODE} ranges (1-10 mode 1, "
                f"11-20 mode 2), each of option 8 speeds; found option 7 = {count} with "
                f"{len(table)} ranges in SRTAB",
            )
        ranges = tuple(() if not any(speeds) else speeds for speeds in table)
        for number, speeds in enumerate(ranges, start=1):
            if speeds and not 0 < speeds[0] <= speeds[-1]:
                raise MachineDefinitionError(
                    machine.origin,
                    "spindle_table",
                    "speeds",
                    f"spindle type 14 range {number}: speeds above 0 in ascending order, or "
                    f"all zeros for a range the machine does not have; found {list(speeds)}",
                )
        for mode in (1, 2):
            used = any(ranges[r - 1] for r in range(1, count + 1) if mode_of(r) == mode)
            if used and machine.m_code(MODE_CELLS[mode]) is None:
                raise MachineDefinitionError(
                    machine.origin,
                    "tablem",
                    MODE_CELLS[mode],
                    f"spindle type 14 mode {mode} has ranges, so it needs its mode M code in "
                    f"TABLEM({MODE_CELLS[mode]})",
                )
        if not any(ranges):
            raise MachineDefinitionError(
                machine.origin, "spindle_table", "speeds", "spindle type 14 has no range"
            )
        return ranges

    def speed_limits(self, machine: MachineDefinition, range_number: int) -> tuple[float, float]:
        speeds = self.ranges(machine)[range_number - 1]
        # an unused range holds zeros in SRTAB: no speed can start in it
        return (speeds[0], speeds[-1]) if speeds else (0.0, 0.0)

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        ranges = self.ranges(machine)
        comments: tuple[str, ...] = ()
        requested = request.range
        if requested is not None:
            requested = min(requested, len(ranges))
            if not ranges[requested - 1]:
                # a range its mode does not have: the highest range of that mode
                same_mode = [
                    r
                    for r, speeds in enumerate(ranges, start=1)
                    if speeds and mode_of(r) == mode_of(requested)
                ]
                requested = same_mode[-1] if same_mode else None
                comments = (NOT_AVAILABLE,)
        number = range_for(ranges, request.speed, requested)
        choice = choose_speed(ranges, request.speed, number, machine.number_option(90))
        mode = mode_of(number)
        in_mode = number - (mode - 1) * RANGES_PER_MODE
        per_range = int(machine.number_option(8))
        code = (
            machine.number_option(47)
            + choice.row
            + (in_mode - 1) * (per_range - 1 + machine.number_option(31))
        )
        return SpindleSelection(
            choice.speed,
            code,
            number,
            comments + choice.comments,
            range_cell=MODE_CELLS[mode],
            row=choice.row,
        )


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(ModeSpindle())
