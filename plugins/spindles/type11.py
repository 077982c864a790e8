"""Spindle type 11: table lookup (manual §4.5.12, 001 L15112-15166; TYPE11 L39539-39560).

The S command is the code stored at the table position that corresponds to the speed's
position, whatever the range or any other condition: the command table is set up one to
one with the speed table. Both are in SRTAB, so a type-11 machine has at most 150 speeds.
The table counts as one range: option 7 = 1 and option 8 = N, the number of speeds;
SRTAB(1..N) holds the speeds in ascending order and SRTAB(N+1..2N) their commands
(TYPE11: SPNCOM = SRTAB(NRORNG + ISPDRO)). Range 2 must never be called: it would read the
commands as speeds, so RANGE,2 falls back to the one range. A speed between two table
speeds is chosen by option 90; outside the table the nearer end is used, with comment 80
or 63 (§4.5 common rules).
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.absent import ABSENT
from gecent.core.errors import MachineDefinitionError
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.core.spindle_types import (
    SpindleRequest,
    SpindleSelection,
    TableSpindle,
    check_ascending,
    choose_speed,
)

MAX_SPEEDS = 150  # speeds and commands share SRTAB's 300 words

# The manual's table is unreadable past its speeds (5 ... 35 RPM); the commands here are
# an illustration, not the manual's (docs/decisions.md, type 11).
EXAMPLE = """
[machine]
name = "type11-example"
title = "TYPE 11 SPINDLE"
[optab]
7 = 1.0
8 = 7.0
19 = 11.0
[spindle_table]
speeds = [5.0, 10.0, 15.0, 20.0, 25.0, 30.0, 35.0, 12.0, 3.0, 27.0, 8.0, 40.0, 19.0, 33.0]
"""


@dataclass(frozen=True)
class TableLookupSpindle(TableSpindle):
    number: int = 11
    name: str = "table lookup"
    section: str = "§4.5.12"
    manual_example: str = EXAMPLE

    def table(self, machine: MachineDefinition) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """The speeds SRTAB(1..N) and their commands SRTAB(N+1..2N)."""
        count = int(machine.number_option(8))
        if machine.number_option(7) != 1 or not 1 <= count <= MAX_SPEEDS:
            raise MachineDefinitionError(
                machine.origin,
                "optab",
                7,
                "spindle type 11 is one range (option 7 = 1) of option 8 = N speeds, "
                f"1 <= N <= {MAX_SPEEDS}; found option 7 = {machine.number_option(7):g}, "
                f"option 8 = {machine.number_option(8):g}",
            )
        speeds = machine.spindle_speeds()[:count]
        commands = []
        for index in range(count + 1, 2 * count + 1):
            command = machine.srtab(index)
            if command is ABSENT or float(command) < 0:
                raise MachineDefinitionError(
                    machine.origin,
                    "spindle_table",
                    f"SRTAB({index})",
                    "spindle type 11 keeps the command of speed "
                    f"{index - count} in SRTAB(N + {index - count}) = SRTAB({index}), "
                    "a number >= 0; found " + ("nothing" if command is ABSENT else f"{command:g}"),
                )
            commands.append(float(command))
        check_ascending(machine, (speeds,), "spindle type 11")
        return speeds, tuple(commands)

    def ranges(self, machine: MachineDefinition) -> tuple[tuple[float, ...], ...]:
        return (self.table(machine)[0],)

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        speeds, commands = self.table(machine)
        choice = choose_speed((speeds,), request.speed, 1, machine.number_option(90))
        return SpindleSelection(
            choice.speed, commands[choice.row], 1, choice.comments, row=choice.row
        )


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(TableLookupSpindle())
