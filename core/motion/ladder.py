"""What SFM needs from the spindle (manual §4.4): the speeds of the locked range and a
spindle that turns at a piece's speed. Low in the import graph, so the run state can name
the spindle that drives SFM without importing the motion that uses it."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

from gecent.core.errors import SourcePosition


@dataclass(frozen=True, slots=True)
class SpeedLadder:
    """The speeds SFM may use in the locked range: the range's lowest and highest speed,
    its ascending table of discrete speeds (None: a variable spindle, stepped by
    ``step``, a fraction) and MAXRPM (SFMAXR, None when not given)."""

    low: float
    high: float
    table: tuple[float, ...] | None = None
    step: float = 0.1
    maximum: float | None = None

    @property
    def top(self) -> float | None:
        """The highest speed SFM may use (range and MAXRPM); None when MAXRPM is below
        every speed of the range."""
        if self.table is not None:
            allowed = [s for s in self.table if self.maximum is None or s <= self.maximum]
            return allowed[-1] if allowed else None
        top = self.high if self.maximum is None else min(self.high, self.maximum)
        return top if top >= self.low else None


class SurfaceSpeedDriver(Protocol):
    """What SFMO needs from the spindle: the locked range's speeds, and a spindle turning
    at a piece's speed (SPTYPE's S command riding in the piece's block, TSTSAF's feed)."""

    def ladder(self) -> SpeedLadder: ...

    def turn(self, speed: float, where: SourcePosition, record: int) -> None: ...
