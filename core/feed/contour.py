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


class RapidCommand:
    """The rapid-traverse F command (CONTUR, manual §4.1.5.4, 001 L12530-12638).

    Option 36 = 0: vector optimisation, each axis at its own rapid rate (options 42, 43,
    44; option 39 for all axes in a low-range rapid): rho = max |d_axis| / rate, command
    D / rho, vector feed S / rho. Option 36 = N: N IPM at most, then the feedrate number.
    The command is held to |option 45|; a negative option 45 outputs no rapid F.
    """

    def __init__(self, machine: MachineDefinition) -> None:
        self.feed = FeedCommand(machine)
        self.vector = machine.number_option(36)
        self.rates = tuple(machine.number_option(n) for n in (42, 43, 44))
        self.low_rate = machine.number_option(39)
        limit = machine.number_option(45)
        self.output = limit >= 0
        self.maximum = abs(limit)

    def command(
        self, departures: tuple[float, ...], gdimul: float, rapid_ipm: float, *, low: bool
    ) -> tuple[float | None, float]:
        """(command or None when not output, vector feed in IPM) for a rapid block."""
        length = sum(d * d for d in departures) ** 0.5
        if self.vector == 0:
            rates = (self.low_rate,) * 3 if low else self.rates
            rho = max(
                (abs(d) / rate for d, rate in zip(departures, rates, strict=False) if d and rate),
                default=0.0,
            )
            ipm = length / rho if rho else abs(rapid_ipm)
        else:
            ipm = min(abs(rapid_ipm), self.vector)
        if rapid_ipm > 0:  # held down by the tape reader (001 L11890-11910)
            ipm = min(ipm, rapid_ipm)
        command = gdimul * ipm / length
        if command > self.maximum:
            command = self.maximum
            ipm = command * length / gdimul
        return (self.feed._rounded(command) if self.output else None), ipm
