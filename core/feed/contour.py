"""The contouring feed command (CONTUR, manual §4.1.2, 001 L10776-11197), by option 10:

* 0, feedrate number: Fc = D * FIPM / S, D the GDIMUL of the block's G code (SELG), S the
  length of its machine departures (the radius for an arc); held within options 49 and 24.
* -1 .. -4, inverse time: D = 1, so Fc = FIPM / S = 1 / minutes; the F format and limits
  change with the block's dimension code (the 16-row table, 001 L11113-11146; FVARGO).
* +1, EIA magic three (appendix 7.1): needs REGFOR(11) = 30 and option 26 = 1.

A clamped command gives back the feed it really produces, FIPM = Fc * S / D (001
L10799-10815), for the absolute printout; commands are rounded half-up to the F format.
"""

from __future__ import annotations

from math import ceil, floor

from gecent.core.errors import Diagnostic, NotYetSupported
from gecent.core.feed.magic3 import decode, magic3
from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.gcode import LINEAR_RANGES
from gecent.core.motion.rounding import half_up, half_up_float

# (option 10, TABLEG location of the dimension code) -> (REGFOR(11), FCOMIN, FCOMAX); the
# manual names the codes G12/G11/G01/G10/G23/G26, locations 13/12/2/11/14/15 (001 L11113-11146;
# -3/G12's FCOMAX 9999.0 as the chapter prints it, the option text's "999" is a misprint)
INVERSE_TIME = {
    (-1, 12): (31.0, 1.0, 999.9),
    (-1, 2): (32.0, 0.1, 99.99),
    (-1, 11): (33.0, 0.01, 9.999),
    (-2, 12): (30.0, 1.0, 999.0),
    (-2, 2): (31.0, 0.1, 99.9),
    (-2, 11): (32.0, 0.01, 9.99),
    (-3, 13): (40.0, 1.0, 9999.0),
    (-3, 12): (41.0, 0.1, 999.9),
    (-3, 2): (42.0, 0.01, 99.99),
    (-3, 11): (43.0, 0.001, 9.999),
    (-4, 13): (42.0, 1.0, 9999.99),
    (-4, 12): (43.0, 0.1, 999.999),
    (-4, 2): (44.0, 0.01, 99.9999),
    (-4, 11): (45.0, 0.001, 9.99999),
    (-4, 14): (46.0, 0.0001, 0.999999),
    (-4, 15): (47.0, 0.00001, 0.0999999),
}
_CLASS_ORDER = [location for location, _ in LINEAR_RANGES]
# EIACOM's diagnostic (001 L30854-30904) and the feeds it converts, 0.0001 to 9999
MAGIC_THREE_RANGE = "THE NUMBER TO BE CONVERTED TO THE MAGIC THREE FORM IS TOO LARGE OR TOO SMALL."
MAGIC_SMALLEST, MAGIC_LARGEST = 0.0001, 9999.0


class FeedCommand:
    def __init__(self, machine: MachineDefinition) -> None:
        # the comments for the block being finished (EIACOM's); the output element's own
        self.diagnostics: list[Diagnostic] = []
        # magic three's REGFOR(11) = 30 and option 26 = 1 are checked when the machine loads
        self.form = machine.number_option(10)
        fmt = machine.registers.formats[11]
        self.decimals = fmt.right if fmt is not None else 0
        self.maximum = machine.number_option(24)
        self.minimum = machine.number_option(49)
        # the merge pass's GFDLIM divides until the command is below FCOMAX, not at it
        # (001 L32886-32903; CONTUR's "or below", L12470-12480: docs/decisions.md)
        self.strictly_below = False
        if self.form not in (0, 1, -1, -2, -3, -4):
            raise NotYetSupported(f"contouring feed command form option 10 = {self.form:g}")

    def command(
        self, ipm: float, gdimul: float, length: float, dimension_class: int
    ) -> tuple[float, float, float | None]:
        """(command, feed in IPM it gives, F format for this block or None for the machine's)
        for a block of ``length`` (its path, or its radius for an arc) whose dimension code
        has the TABLEG location ``dimension_class`` (a linear range location)."""
        if self.form == 0:
            return (*self.linear(ipm, gdimul, length), None)
        if self.form == 1:
            code = magic3(ipm)
            if code is None:
                # EIACOM's comment, then the code of the nearest feed it can convert
                # (0.0001 or 9999, 001 L30854-30904): the feed the block gets is reported
                self.diagnostics.append(Diagnostic(MAGIC_THREE_RANGE))
                code = magic3(min(max(ipm, MAGIC_SMALLEST), MAGIC_LARGEST))
                assert code is not None
            return float(code), decode(code), None
        regfor, lowest, highest = self._row(dimension_class)
        command = ipm / length
        used = min(max(command, lowest), highest)
        rounded = float(half_up(used, int(regfor) % 10))
        return rounded, (ipm if used == command else used * length), regfor

    def multiplier(
        self, ipm: float, gdimul: float, length: float, dimension_class: int
    ) -> tuple[int, float, float | None] | None:
        """The feedrate multiplier constant (option 26 = 0, manual §4.1.5.2, 001
        L12440-12529): when a linear block's command exceeds its maximum, the smallest whole
        c with Fc / c below the maximum, as (c, command, F format); None when the command
        is within its maximum or the form has no multiplier (magic three). The block's
        departures times c go in I, J, K."""
        if self.form == 1:
            return None
        command, highest, regfor, decimals = self._command_limits(
            ipm, gdimul, length, dimension_class
        )
        if command <= highest:
            return None
        if self.strictly_below:
            constant = floor(command / highest + 1e-9) + 1  # GFDLIM: "less than" FCOMAX
        else:
            constant = ceil(command / highest - 1e-9)  # to the maximum "or below" (L12470-12480)
        return constant, float(half_up(command / constant, decimals)), regfor

    def _command_limits(
        self, ipm: float, gdimul: float, length: float, dimension_class: int
    ) -> tuple[float, float, float | None, int]:
        """A linear block's command, its maximum, its F format and its decimals (the
        multiplier and option 224 both start from them)."""
        if self.form == 0:
            return gdimul * ipm / length, self.maximum, None, self.decimals
        regfor, _, highest = self._row(dimension_class)
        return ipm / length, highest, regfor, int(regfor) % 10

    def decimal_shift(
        self, ipm: float, gdimul: float, length: float, dimension_class: int
    ) -> tuple[int, float, float | None] | None:
        """Option 224's scaling (the 100S in metric, 001 L26729-26738; docs/decisions.md):
        the most places k that the block's command can be moved left and stay within its
        maximum, as (k, command x 10^k, F format); None when it cannot move one place or the
        form is magic three. The departures over 10^k go in I, J, K, so the control's
        feed is unchanged while the command keeps k more significant digits."""
        if self.form == 1:
            return None
        command, highest, regfor, decimals = self._command_limits(
            ipm, gdimul, length, dimension_class
        )
        k = 0
        while command * 10 ** (k + 1) <= highest * (1 + 1e-12) and k < 9:
            k += 1
        if k == 0:
            return None
        return k, float(half_up(command * 10**k, decimals)), regfor

    def _row(self, location: int) -> tuple[float, float, float]:
        """The chart's row for the block's dimension code, else the next larger code's;
        past the largest code the form's chart lists (G23 and G26 under -1 .. -3), the
        largest's: the command is 1 / minutes whatever the code (D = 1), so the row gives
        only the F format and limits, and the longest moves' row fits a longer one best
        (docs/decisions.md, issue 22 wave 9)."""
        start = _CLASS_ORDER.index(location)
        for candidate in _CLASS_ORDER[start:]:
            row = INVERSE_TIME.get((int(self.form), candidate))
            if row is not None:
                return row
        for candidate in reversed(_CLASS_ORDER[:start]):
            row = INVERSE_TIME.get((int(self.form), candidate))
            if row is not None:
                return row
        raise AssertionError(f"no inverse time row for option 10 = {self.form:g}")

    def linear(self, ipm: float, gdimul: float, length: float) -> tuple[float, float]:
        """The feedrate number (option 10 = 0): (command, feed in IPM)."""
        command = gdimul * ipm / length
        if command > self.maximum:
            command = self.maximum
        elif command < self.minimum:
            command = self.minimum
        else:
            return half_up_float(command, self.decimals), ipm
        return half_up_float(command, self.decimals), command * length / gdimul


class RapidCommand:
    """The rapid-traverse F command (CONTUR, manual §4.1.5.4, 001 L12530-12638).

    Option 36 = 0: vector optimisation, each axis at its own rapid rate (options 42, 43,
    44; option 39 for all axes in a low-range rapid): rho = max |d_axis| / rate, command
    D / rho, vector feed S / rho. Option 36 = N: N IPM at most, then the feedrate number.
    The command is held to |option 45|; a negative option 45 outputs no rapid F.
    """

    def __init__(
        self, machine: MachineDefinition, axis_cells: tuple[tuple[int, float] | None, ...]
    ) -> None:
        fmt = machine.registers.formats[11]
        self.decimals = fmt.right if fmt is not None else 0
        self.vector = machine.number_option(36)
        # options 42-44 are the machine's X, Y, Z rates (MACH04 sets 43 = 0: a lathe has no
        # Y); each CL axis (option 59: to register 3, 4 or 5) moves at its register's rate
        self.rates = tuple(
            machine.number_option(39 + target[0]) if target else 0.0 for target in axis_cells
        )
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
        if length == 0.0:
            # a rapid that only turns the rotary axes (a multiaxis machine): no slide to time
            return None, ipm
        command = gdimul * ipm / length
        if command > self.maximum:
            command = self.maximum
            ipm = command * length / gdimul
        return (float(half_up(command, self.decimals)) if self.output else None), ipm
