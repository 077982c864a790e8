"""Spindle type 1: EIA 3-digit code number, variable spindle (manual §4.5.2,
001 L14635-14660; TYPE01 L39133-39160; EIACOM L30854-30904).

Any speed between the minimum SRTAB(1) and the maximum SRTAB(2); no ranges are coded. The S
command is the EIA "magic three" of the speed (137.2 RPM -> S614). A speed outside the
table gets the nearest listed speed, with the manual's comments 80 (below) and 63 (above)
(L14588-14590, L30766-30777; docs/decisions.md).
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.errors import MachineDefinitionError
from gecent.core.feed.magic3 import magic3
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.core.spindle_types import OneRangeSpindle, SpindleRequest, SpindleSelection, limited

# One range of a minimum and a maximum speed (option 7 = 1, option 8 = 2, 001 L14646-14654);
# the limits span the manual's examples 137.2 RPM -> S614 and 0.0123 RPM -> S212 and reach
# the largest speed magic three codes.
MANUAL_EXAMPLE = """
[machine]
name = "spindle-type01"
title = "TYPE 1 SPINDLE (4.5.2)"
[optab]
7 = 1.0
8 = 2.0
19 = 1.0
[spindle_table]
speeds = [0.01, 9999.0]
"""


@dataclass(frozen=True)
class EiaThreeDigitSpindle(OneRangeSpindle):
    number: int = 1
    name: str = "EIA 3-digit code number (variable spindle)"
    section: str = "§4.5.2"
    manual_example: str = MANUAL_EXAMPLE

    def limits(self, machine: MachineDefinition) -> tuple[float, float]:
        speeds = machine.spindle_speeds()
        if len(speeds) < 2 or not 0 < speeds[0] <= speeds[1] <= 9999:
            raise MachineDefinitionError(
                machine.origin,
                "spindle_table",
                "speeds",
                "spindle type 1 needs SRTAB(1) = minimum and SRTAB(2) = maximum speed, "
                f"0 < minimum <= maximum <= 9999 RPM; found {list(speeds[:2])}",
            )
        return speeds[0], speeds[1]

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        low, high = self.limits(machine)
        speed, comments = limited(request.speed, low, high)
        code = magic3(speed)
        assert code is not None  # the limits keep the speed within magic three's range
        return SpindleSelection(speed, float(code), 1, comments)


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(EiaThreeDigitSpindle())
