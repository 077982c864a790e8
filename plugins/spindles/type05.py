"""Spindle type 5: discrete EIA 3-digit code number (manual §4.5.6, 001 L14931-14964;
TYPE05 L39349-39375).

The speed command is derived by selecting the spindle speed from SRTAB and converting it
into the EIA 3-digit ("magic three") number. There are no multiple ranges, only discrete
speeds, and the table need not hold every EIA-coded speed. A speed that is not exactly in
the table gets the next lower table speed: a machine with an AC motor drive that uses the
discrete EIA values may turn at a wrong speed if it is sent a speed it does not have. In
the manual's table (2, 3, 5, 7, 10, 12, 15, 17, ... 193, 197, 200) speed 13 is S512.

The manual makes "next lower" part of the type, so a type 5 machine must keep option 90 at
its standard -1 (docs/decisions.md); a speed outside the table gets its nearer end with
comment 80 or 63, as for every type.
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.errors import MachineDefinitionError
from gecent.core.feed.magic3 import magic3
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.core.spindle_types import (
    SpindleRequest,
    SpindleSelection,
    TableSpindle,
    check_ascending,
    choose_speed,
)

NEXT_LOWER = -1.0  # option 90's "next lower speed"

# The §4.5.6 table as printed (2 ... 17 and 193, 197, 200); its elided middle is filled with
# EIA two-digit speeds so that the example's values sit in one 23-speed range (001 L14946-14960).
MANUAL_EXAMPLE = """
[machine]
name = "spindle-type05"
title = "TYPE 5 SPINDLE (4.5.6)"
[optab]
7 = 1.0
8 = 23.0
19 = 5.0
[spindle_table]
speeds = [
  2.0, 3.0, 5.0, 7.0, 10.0, 12.0, 15.0, 17.0,
  20.0, 25.0, 30.0, 40.0, 50.0, 60.0, 80.0, 100.0, 120.0, 150.0, 170.0, 190.0,
  193.0, 197.0, 200.0,
]
"""


@dataclass(frozen=True)
class DiscreteEiaSpindle(TableSpindle):
    number: int = 5
    name: str = "discrete EIA 3-digit code number"
    section: str = "§4.5.6"
    manual_example: str = MANUAL_EXAMPLE

    def speeds(self, machine: MachineDefinition) -> tuple[float, ...]:
        """The one range of discrete speeds, each codable in magic three."""
        ranges = machine.spindle_ranges()
        if len(ranges) != 1:
            raise MachineDefinitionError(
                machine.origin,
                "optab",
                7,
                f"{self.kind} has no multiple ranges: option 7 must be 1 and SRTAB one "
                f"range of option 8 speeds; found {len(ranges)} ranges",
            )
        check_ascending(machine, ranges, self.kind)
        speeds = ranges[0]
        if any(magic3(speed) is None or speed <= 0 for speed in speeds):
            raise MachineDefinitionError(
                machine.origin,
                "spindle_table",
                "speeds",
                f"{self.kind}: each speed must be 0.0001..9999 RPM for the EIA code; "
                f"found {list(speeds)}",
            )
        if machine.number_option(90) != NEXT_LOWER:
            raise MachineDefinitionError(
                machine.origin,
                "optab",
                90,
                f"{self.kind} always takes the next lower table speed (§4.5.6): option 90 "
                f"must be -1; found {machine.number_option(90):g}",
            )
        return speeds

    def ranges(self, machine: MachineDefinition) -> tuple[tuple[float, ...], ...]:
        return (self.speeds(machine),)

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        speeds = self.speeds(machine)
        choice = choose_speed((speeds,), request.speed, 1, NEXT_LOWER)
        code = magic3(choice.speed)
        assert code is not None  # speeds() keeps every table speed within magic three's span
        return SpindleSelection(choice.speed, float(code), 1, choice.comments, row=choice.row)


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(DiscreteEiaSpindle())
