"""The contouring feed command (CONTUR, manual §4.1.2, 001 L10776-11078), option 10 = 0:
the feedrate number Fc = D * FIPM / S.

D is GDIMUL, the dimension multiplier times ten of the block's G code (SELG); S the length of
the block's machine departures. Fc is held between option 49 (minimum) and option 24 (maximum);
a clamped command gives back the feed it really produces, FIPM = Fc * S / D (001 L10799-10815),
for the absolute printout. The command is rounded half-up to the F register's decimals.
"""

from __future__ import annotations

from decimal import ROUND_HALF_UP, Decimal

from gecent.core.errors import NotYetSupported
from gecent.core.machine.definition import MachineDefinition


class FeedCommand:
    def __init__(self, machine: MachineDefinition) -> None:
        self.form = machine.number_option(10)
        fmt = machine.registers.formats[11]
        self.quantum = Decimal(1).scaleb(-(fmt.right if fmt is not None else 0))
        self.maximum = machine.number_option(24)
        self.minimum = machine.number_option(49)

    def linear(self, ipm: float, gdimul: float, length: float) -> tuple[float, float]:
        """(command, feed in IPM) for a linear block of ``length`` inches."""
        if self.form != 0:
            raise NotYetSupported(f"contouring feed command form option 10 = {self.form:g}")
        command = gdimul * ipm / length
        if command > self.maximum:
            command = self.maximum
        elif command < self.minimum:
            command = self.minimum
        else:
            return self._rounded(command), ipm
        return self._rounded(command), command * length / gdimul

    def _rounded(self, command: float) -> float:
        return float(Decimal(repr(command)).quantize(self.quantum, ROUND_HALF_UP))
