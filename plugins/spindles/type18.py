"""Spindle type 18: associated speed codes on a generated table, variable in SFM (manual
§4.5.19, 001 L15556-15629; TYPE18 L39862-39895; GESCOM L32807-32850).

The speeds have associated code numbers, as for type 2, but SRTAB holds no speeds: SRTAB(1)
is the highest speed of range 1 and SRTAB(2) the change between its speeds, SRTAB(3) and
(4) the same for range 2, and so on. The postprocessor builds option 8 speeds for each of
the option 7 ranges, starting from the highest and changing by that fraction of it:

    speed(r, k) = SRTAB(2r - 1) x (1 - k x SRTAB(2r)),   k = 0 .. option 8 - 1

held as whole RPM, as the manual's table prints them (340, 337, 333 ... 10). With
SRTAB = 340, .01, 1500, .01, option 8 = 98, option 31 = 103 and option 47 = 203, range 1 is
S203 (10 RPM) to S300 (340 RPM) and range 2 S403 (45 RPM) to S500 (1500 RPM).

The code is type 2's (GESCOM), rows counted from the lowest speed of the range:
S = option 47 + row + (range - 1) x (option 8 - 1 + option 31). The range is the lowest that
holds the speed unless RANGE,n is given, option 90 chooses between table speeds, and a
speed outside the table gets its nearer end, with comment 80 or 63. With option 137 = +N,
range changes are shifted through row N as for type 2 (§4.5.3.1). In SFM the type is
variable: each step changes the speed by option 15's percentage, whether or not that is the
next speed in the table.
"""

from __future__ import annotations

from dataclasses import dataclass
from decimal import ROUND_HALF_UP, Decimal
from itertools import pairwise

from gecent.core.absent import ABSENT
from gecent.core.errors import MachineDefinitionError
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.core.spindle_types import (
    SpindleRequest,
    SpindleSelection,
    SpindleStep,
    TableSpindle,
    check_ascending,
    choose_speed,
)
from gecent.plugins.spindles.type02 import AssociatedSpeedCodeSpindle

# Type 18 is coded, and shifted under option 137, as a type 2 spindle (TYPE18 calls GESCOM
# and shifts "as for the Type 2 spindle", 001 L39880-39887).
TYPE_2 = AssociatedSpeedCodeSpindle()

EXAMPLE = """
[machine]
name = "type18-example"
title = "TYPE 18 SPINDLE"
[optab]
7 = 2.0
8 = 98.0
19 = 18.0
31 = 103.0
47 = 203.0
[spindle_table]
speeds = [340.0, 0.01, 1500.0, 0.01]
"""


def whole_rpm(speed: float) -> float:
    """A generated speed as the table holds it: whole RPM, halves up (336.6 -> 337)."""
    return float(Decimal(repr(speed)).quantize(Decimal(1), ROUND_HALF_UP))


@dataclass(frozen=True)
class GeneratedTableSpindle(TableSpindle):
    number: int = 18
    name: str = "associated code on a generated table (variable in SFM)"
    section: str = "§4.5.19"
    manual_example: str = EXAMPLE

    def ranges(self, machine: MachineDefinition) -> tuple[tuple[float, ...], ...]:
        """The generated table, each range ascending."""
        per_range = int(machine.number_option(8))
        ranges = []
        for number in range(1, int(machine.number_option(7)) + 1):
            highest, change = machine.srtab(2 * number - 1), machine.srtab(2 * number)
            if (
                highest is ABSENT
                or change is ABSENT
                or float(highest) <= 0
                or not 0 < float(change) * (per_range - 1) < 1
            ):
                raise MachineDefinitionError(
                    machine.origin,
                    "spindle_table",
                    f"SRTAB({2 * number - 1})",
                    f"spindle type 18 range {number}: SRTAB({2 * number - 1}) = highest speed "
                    f"above 0 and SRTAB({2 * number}) = the change between speeds, a "
                    f"fraction above 0 small enough that {per_range} speeds stay above "
                    "0 RPM; found "
                    + " and ".join(
                        "nothing" if v is ABSENT else f"{v:g}" for v in (highest, change)
                    ),
                )
            speeds = tuple(
                whole_rpm(float(highest) * (1 - k * float(change)))
                for k in reversed(range(per_range))
            )
            if speeds[0] <= 0 or any(b <= a for a, b in pairwise(speeds)):
                raise MachineDefinitionError(
                    machine.origin,
                    "spindle_table",
                    f"SRTAB({2 * number})",
                    f"spindle type 18 range {number}: the generated speeds, in whole RPM, must "
                    f"be above 0 and all different; found {speeds[0]:g} .. {speeds[-1]:g} "
                    "with repeated speeds",
                )
            ranges.append(speeds)
        check_ascending(machine, tuple(ranges), "spindle type 18")
        return tuple(ranges)

    def table_speeds(
        self, machine: MachineDefinition, range_number: int
    ) -> tuple[float, ...] | None:
        return None  # variable in SFM: option 15 steps (001 L15561-15566)

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        ranges = self.ranges(machine)
        codes = TYPE_2.codes(machine, ranges)
        rows = len(ranges[0])
        choice = choose_speed(ranges, request.speed, request.range, machine.number_option(90))
        seconds = machine.number_option(54)
        steps = tuple(
            SpindleStep(codes[(number - 1) * rows + row], number, seconds or None)
            for number, row in TYPE_2._shift_path(
                machine, ranges, request, choice.range, choice.row
            )
        )
        return SpindleSelection(
            choice.speed,
            codes[(choice.range - 1) * rows + choice.row],
            choice.range,
            choice.comments,
            steps=steps,
            row=choice.row,
        )


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(GeneratedTableSpindle())
