"""REGFOR: the register format ±(10·L + R) (manual §5.6.4, 001 L23965-24066).

L digits left of the decimal point, R right of it; a negative value means the sign is
punched; 0 means the machine has no such register.
"""

from __future__ import annotations

from dataclasses import dataclass
from math import isfinite


@dataclass(frozen=True, slots=True)
class RegisterFormat:
    """A decoded REGFOR value."""

    signed: bool
    left: int
    right: int

    @property
    def digits(self) -> int:
        return self.left + self.right

    @property
    def regfor(self) -> float:
        """The REGFOR number this format was decoded from."""
        value = float(10 * self.left + self.right)
        return -value if self.signed else value

    @property
    def largest(self) -> float:
        """The largest magnitude the format can hold (e.g. 30 -> 999, -24 -> 99.9999)."""
        return float(10**self.digits - 1) / float(10**self.right)

    def __str__(self) -> str:
        return f"{'-' if self.signed else ''}{self.left}.{self.right}"


MAX_REGFOR = 99


def decode_regfor(value: float) -> RegisterFormat | None:
    """Decode a REGFOR value; ``None`` for 0 (no register).

    Raises ValueError when the value is not ±(10·L + R) with whole L and R.
    """
    if value == 0:
        return None
    magnitude = abs(value)
    if not isfinite(magnitude) or magnitude != int(magnitude):
        raise ValueError(f"{value!r} is not ±(10·L + R) with whole digit counts")
    if magnitude > MAX_REGFOR:
        # L and R are digit counts of a tape word: no control reads 10 digits on a side
        raise ValueError(f"{value!r} asks for more than 9 digits on a side (at most ±{MAX_REGFOR})")
    left, right = divmod(int(magnitude), 10)
    return RegisterFormat(signed=value < 0, left=left, right=right)
