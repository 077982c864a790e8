"""Spindle type 20 (gecent, modern controls; docs/modern-controls.md): S is the speed in RPM.

A Fanuc- or LinuxCNC-style control takes ``S1200 M03``: the S word is the speed itself and
the direction is M03/M04 (TABLEM 4/5), the stop M05 (TABLEM 6), as for every type. The
speed is rounded to whole RPM (the S format's resolution when REGFOR(12) has decimals)
and held to the one range SRTAB(1) (lowest) .. SRTAB(2) (highest) with the manual's
comments 80 and 63 (§4.5 common rules). Unlike type 12 (§4.5.13) nothing is truncated to
tens and there is no cross-over dwell: modern spindle drives take any speed.
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.errors import MachineDefinitionError
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.rounding import half_up
from gecent.core.spindle_types import OneRangeSpindle, SpindleRequest, SpindleSelection, limited

EXAMPLE = """
[machine]
name = "type20-example"
title = "TYPE 20 SPINDLE"
[optab]
7 = 1.0
8 = 2.0
19 = 20.0
[spindle_table]
speeds = [50.0, 24000.0]
"""


@dataclass(frozen=True)
class DirectRpmSpindle(OneRangeSpindle):
    number: int = 20
    name: str = "S in RPM (modern controls)"
    section: str = "§4.5 (gecent type, docs/modern-controls.md)"
    manual_example: str = EXAMPLE

    def limits(self, machine: MachineDefinition) -> tuple[float, float]:
        speeds = machine.spindle_speeds()
        if machine.number_option(7) != 1 or len(speeds) < 2 or not 0 < speeds[0] <= speeds[1]:
            raise MachineDefinitionError(
                machine.origin,
                "spindle_table",
                "speeds",
                "spindle type 20 is one range (option 7 = 1, option 8 = 2): SRTAB(1) = lowest "
                f"and SRTAB(2) = highest speed, 0 < lowest <= highest; found {list(speeds[:2])} "
                f"with option 7 = {machine.number_option(7):g}",
            )
        return speeds[0], speeds[1]

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        low, high = self.limits(machine)
        speed, comments = limited(request.speed, low, high)
        fmt = machine.registers.formats[12]
        decimals = fmt.right if fmt is not None else 0
        command = float(half_up(speed, decimals))
        return SpindleSelection(command, command, 1, comments)


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(DirectRpmSpindle())
