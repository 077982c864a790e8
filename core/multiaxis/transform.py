"""The transform-class protocol (manual §4.2, 001 L12639-12748; spec 05 §8.1).

APT gives a multiaxis point as the tool tip (x, y, z) and the tool axis (i, j, k), the
direction cosines pointing back from the tip towards the holder. A machine's class
(option 116) carries such points to its axes X, Y, Z, A, B, C (the direct transform,
part to machine) and back (the inverse, machine to part: linearity checks and MAFORK).
Each class is a plugin of the ``classes`` family, vectorised over a run of points with
numpy: a point is a row, the columns are x y z i j k (part) or X Y Z A B C (machine),
angles in radians, the rotary columns a class does not drive 0.0.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Protocol, runtime_checkable

# numpy is imported where a class computes, not when the plugins load: a three-axis run
# never pays for it
if TYPE_CHECKING:
    import numpy as np
    from numpy.typing import NDArray

    Points = NDArray[np.float64]  # (n, 6)
    Flags = NDArray[np.bool_]
else:
    Points = Flags = Any

# machine columns
X, Y, Z, A, B, C = range(6)
# a quantity the classes divide by, or take an angle from, within this of 0 is a singular
# case (an angle kept from the point before) or an unreachable tool axis
SINGULAR = 1e-9
# part columns
PX, PY, PZ, PI, PJ, PK = range(6)


@dataclass(frozen=True)
class Kinematics:
    """The equation constants a class may need (001 L12735-12741): ``reach`` is the
    distance from the rotary head's axis to the tool tip (R + TL: the head axis to the
    spindle face, options 102-105 by head and gripper, plus the tool length), and
    ``options`` options 100-105 of the machine, in order (the Machine Subroutine's
    constants: head spacing, head offsets, inclined-ram angles...)."""

    reach: float = 0.0
    options: tuple[float, float, float, float, float, float] = (0.0,) * 6

    def option(self, number: int) -> float:
        """Option 100..105."""
        return self.options[number - 100]


@dataclass
class MachinePoints:
    """A direct transform's answer: the machine axes of each point, and which points are
    singular (the tool axis where a rotary angle is indeterminate and the previous one is
    kept: the linearity test is disregarded over such a move, 001 L12845-12870)."""

    axes: Points
    singular: Flags = field(default_factory=lambda: _flags())


@runtime_checkable
class TransformClass(Protocol):
    """A multiaxis transform class (CLASSn, n = option 116)."""

    # (read-only: a class may give them as attributes or as properties)
    @property
    def number(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def section(self) -> str: ...
    @property
    def structure(self) -> str:
        """The axes in the manual's I(P,T,R) notation, e.g. "5(3,0,2)"."""
        ...

    @property
    def rotary(self) -> tuple[int, ...]:
        """The machine columns it drives among A, B, C (3, 4, 5)."""
        ...

    def direct(
        self, part: Points, kinematics: Kinematics, previous: Points | None = None
    ) -> MachinePoints:
        """Part (x y z i j k rows) to machine (X Y Z A B C rows). ``previous`` is the
        machine point before the run (one row), for the angles a singular point keeps."""
        ...

    def inverse(self, machine: Points, kinematics: Kinematics) -> Points:
        """Machine (X Y Z A B C rows) to part (x y z i j k rows)."""
        ...


def _flags() -> Flags:
    import numpy as np

    return np.zeros(0, dtype=bool)


def keep_previous(angle: Points, singular: Flags, previous: Points | None, column: int) -> Points:
    """A singular point keeps the angle of the point before it: the run's own, or for the
    first, column ``column`` of ``previous`` (0 with none): a forward fill along the run."""
    import numpy as np

    if not singular.any():
        return angle
    before = 0.0 if previous is None else float(as_points(previous)[-1, column])
    filled = angle.copy()
    indices = np.where(singular, -1, np.arange(len(angle)))
    last = np.maximum.accumulate(indices)
    taken = last >= 0
    filled[taken] = angle[last[taken]]
    filled[~taken] = before
    return filled


def as_points(values: object) -> Points:
    """One point or a run of them as an (n, 6) float array."""
    import numpy as np

    points = np.asarray(values, dtype=np.float64)
    if points.ndim == 1:
        points = points.reshape(1, -1)
    if points.ndim != 2 or points.shape[1] != 6:
        raise ValueError(f"points are rows of six values, not an array of shape {points.shape}")
    return points
