"""Register formatting: a cell value to its printed and punched text (CONBCD, manual §3.5.1-
3.5.2, 001 L853-975, L8838-8925, L16289-16290; REGFOR §5.6.4, 001 L23965-24066).

* ±(10·L + R): L digits before the decimal point, R after; negative REGFOR = the sign is
  output. Leading zeros are kept to L digits (``-03.2468``, ``G04X04``, ``F0015``).
* Trailing zeros are dropped on incremental (contouring) systems (001 L16289-16290) and kept
  on positioning machines' X, Y and Z (001 L8918-8921); a dropped zero prints as a blank.
* The printed decimal point appears when R > 0 and the location is not NDP (001 L24057-24062);
  blanks and periods are never punched (001 L889-890, L8849).
* A signed register shows ``+`` for a positive value, as the manual's computer-printed sample
  does (001 L10341-10355).
* Option 255 = 1 (gecent, modern controls): a register with fractional digits is written
  with its decimal point, punched too, and without leading or trailing zeros (``X12.5``,
  ``X-0.25``, ``X10.``): a Fanuc control reads ``X10`` as ten least increments. Whole-number
  words lose their leading zeros too (``N12``, ``S1200``), except G, T and M, whose width
  names the code (``G01``, ``T0101``, ``M03``).

Each register's formatter is built once per machine, so the hot loop only quantises and joins.
"""

from __future__ import annotations

from dataclasses import dataclass
from decimal import Decimal

from gecent.core.errors import EXIT_FATAL, GecentError, SourcePosition
from gecent.core.machine.regformat import RegisterFormat
from gecent.core.motion.rounding import half_up

NO_DECIMAL_POINT = frozenset({1, 2, 12, 13, 14, 17})  # NDP locations (001 L24057-24062)
CODE_WIDTH = frozenset({2, 13, 14})  # G, T, M keep their leading zeros under option 255


class FormatOverflow(GecentError):
    """A value too large for its register format. Motion is segmented to option 4 and N
    wraps at SEQLIM, so only a machine whose formats are smaller than its option 4 (a load
    warning) gets here; the run stops, naming the record."""

    exit_status = EXIT_FATAL

    def __init__(self, letter: str, value: float, fmt: RegisterFormat) -> None:
        self.text = f"{letter}{value:g} does not fit register format {fmt.regfor:g}"
        self.where: SourcePosition | None = None
        super().__init__(self.text)

    def __str__(self) -> str:
        prefix = f"{self.where}: " if self.where is not None else ""
        return f"{prefix}error: {self.text}"


@dataclass(frozen=True, slots=True)
class Formatted:
    printed: str
    punched: str


class RegisterFormatter:
    """Formats values of one register (one REGSTR/REGFOR location)."""

    __slots__ = (
        "_dot",
        "_fraction_width",
        "_limit",
        "_power",
        "_whole_width",
        "bare",
        "decimal",
        "drop_trailing",
        "fmt",
        "letter",
        "location",
        "modern",
        "point",
    )

    def __init__(
        self,
        location: int,
        letter: str,
        fmt: RegisterFormat,
        *,
        drop_trailing: bool,
        decimal: bool = False,
    ) -> None:
        self.location = location
        self.letter = letter
        self.fmt = fmt
        self.drop_trailing = drop_trailing and fmt.right > 0
        self.point = fmt.right > 0 and location not in NO_DECIMAL_POINT
        self.decimal = decimal and fmt.right > 0
        self.bare = decimal and fmt.right == 0 and location not in CODE_WIDTH
        self.modern = self.decimal or self.bare  # one test on the manual's hot path
        # worked out once: the units of a whole number, the first that overflows, widths
        self._power = 10**fmt.right
        self._limit = 10**fmt.left
        self._whole_width = f"0{fmt.left}d"
        self._fraction_width = f"0{fmt.right}d"
        self._dot = "." if self.point else ""

    def format(self, value: float, suppress_leading: int | None = None) -> Formatted:
        """The printed and punched forms. ``suppress_leading`` (option 51 = -2, the 100M's
        G11/G12 departures) drops the punched integer digits' leading zeros and that many
        zeros after the point (001 L16270-16295); the printed form keeps them."""
        try:
            units = _units(abs(value), self.fmt.right)
        except (OverflowError, ValueError):  # infinite or NaN: no register holds it
            raise FormatOverflow(self.letter, value, self.fmt) from None
        printed, punched = self.texts(units, value < 0, value, suppress_leading)
        return Formatted(printed, punched)

    def texts(
        self,
        units: int,
        negative: bool,
        value: float | None = None,
        suppress_leading: int | None = None,
    ) -> tuple[str, str]:
        """(printed, punched) of a magnitude in units of the last decimal: the decimal-point
        word of a modern control (option 255), the bare whole number, or the manual's fixed
        digits with their sign, point and trailing zeros (001 L24057-24062)."""
        whole_units, fraction_units = divmod(units, self._power)
        if whole_units >= self._limit:
            if value is None:
                value = (-units if negative else units) / float(self._power)
            raise FormatOverflow(self.letter, value, self.fmt)
        if self.decimal:
            shown = format(fraction_units, self._fraction_width).rstrip("0")
            text = f"-{whole_units}.{shown}" if negative and units else f"{whole_units}.{shown}"
            return text, text
        if self.bare:
            text = f"-{units}" if negative and units else str(units)
            return text, text
        fmt = self.fmt
        whole = format(whole_units, self._whole_width) if fmt.left else ""
        fraction = format(fraction_units, self._fraction_width) if fmt.right else ""
        kept = fraction.rstrip("0") if self.drop_trailing else fraction
        sign = ("-" if negative and units else "+") if fmt.signed else ""
        printed = sign + whole + self._dot + (kept.ljust(fmt.right) if self.drop_trailing else kept)
        if suppress_leading is not None:
            whole = whole.lstrip("0")
            if not whole and kept.startswith("0" * suppress_leading):
                kept = kept[suppress_leading:]
        if not whole and not kept:
            return printed, sign + "0"
        return printed, sign + whole + kept


def _units(magnitude: float, decimals: int) -> int:
    """``magnitude`` in units of the last decimal, rounded half-up exactly. Values on the
    grid already (departures are whole steps) take the float path; others, and anything
    near a half, go through Decimal."""
    scaled = magnitude * float(10**decimals)
    nearest = round(scaled)
    if abs(scaled - nearest) < 1e-6:
        return nearest
    exact: Decimal = half_up(magnitude, decimals).scaleb(decimals)
    return int(exact)
