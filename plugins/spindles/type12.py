"""Spindle type 12: command equal to the selected speed (manual §4.5.13, 001 L15167-15188;
TYPE12 L39566-39600; option 196 L26540-26545).

The S command is the speed itself. A speed that is not a whole number of RPM is set to the
next lower integer (S = 28.4 and S = 28.7 both give S28); from 200 RPM up, to the next
lower multiple of 10 (418 gives S410, 422 gives S420). The speed the spindle turns is the
command. The machine's range of speeds is SRTAB(1) (minimum) and SRTAB(2) (maximum), one
range (option 7 = 1, option 8 = 2), e.g. 25 and 600 RPM; a speed outside it gets the nearer
limit, with comment 80 or 63 (§4.5 common rules).

When a speed change crosses the cross-over speed, 199 RPM or option 196 when that is set
(from 70 to 200 RPM, or from 300 to 180 RPM), the S code goes out in a dwell block of
option 54 seconds; with option 54 = 0 it goes out in a block by itself, as every SPINDL
speed does. The first speed, and a speed that starts a stopped spindle, crosses nothing.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from gecent.core.errors import MachineDefinitionError
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.core.spindle_types import OneRangeSpindle, SpindleRequest, SpindleSelection, limited

TENS_FROM = 200.0  # from here up, the command is a multiple of 10 (001 L15175-15179)
CROSS_OVER = 199.0  # the standard cross-over speed when option 196 = 0 (001 L15181)
_ROUNDING = 1e-9  # 418.0 held as 417.99999... still truncates to 410

EXAMPLE = """
[machine]
name = "type12-example"
title = "TYPE 12 SPINDLE"
[optab]
7 = 1.0
8 = 2.0
19 = 12.0
54 = 2.0
[spindle_table]
speeds = [25.0, 600.0]
"""


def speed_command(speed: float) -> float:
    """The speed truncated as the machine takes it: whole RPM below 200, tens from 200."""
    if speed >= TENS_FROM:
        return float(math.floor(speed / 10 + _ROUNDING) * 10)
    return float(math.floor(speed + _ROUNDING))


@dataclass(frozen=True)
class SpeedCommandSpindle(OneRangeSpindle):
    number: int = 12
    name: str = "command equal to selected speed"
    section: str = "§4.5.13"
    manual_example: str = EXAMPLE

    def limits(self, machine: MachineDefinition) -> tuple[float, float]:
        speeds = machine.spindle_speeds()
        if (
            machine.number_option(7) != 1
            or len(speeds) < 2
            or not 0 < speeds[0] <= speeds[1]
            or any(speed_command(s) != s for s in speeds[:2])
        ):
            raise MachineDefinitionError(
                machine.origin,
                "spindle_table",
                "speeds",
                "spindle type 12 is one range (option 7 = 1): SRTAB(1) = minimum and "
                "SRTAB(2) = maximum speed, 0 < minimum <= maximum, each a speed the machine "
                "can be commanded (whole RPM below 200, tens from 200); found "
                f"{list(speeds[:2])} with option 7 = {machine.number_option(7):g}",
            )
        return speeds[0], speeds[1]

    def table_speeds(
        self, machine: MachineDefinition, range_number: int
    ) -> tuple[float, ...] | None:
        """Every command the machine takes: SFM steps through them as a discrete table
        (option 15's variable types are 1, 10 and 18 only, 001 L24551-24556)."""
        low, high = self.limits(machine)
        whole = range(int(low), int(min(high, TENS_FROM - 1)) + 1)
        tens = range(int(max(low, TENS_FROM)), int(high) + 1, 10)
        return tuple(float(s) for s in (*whole, *tens))

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        low, high = self.limits(machine)
        speed, comments = limited(request.speed, low, high)
        command = speed_command(speed)
        dwell = None
        cross_over = machine.number_option(196) or CROSS_OVER
        running = request.running
        seconds = machine.number_option(54)
        if (
            running is not None
            and seconds > 0
            and (running.speed > cross_over) != (command > cross_over)
        ):
            dwell = seconds
        return SpindleSelection(command, command, 1, comments, dwell_after=dwell)


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(SpeedCommandSpindle())
