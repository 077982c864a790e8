"""Options 59 and 60: output axis shuffle and sign (manual §5.6.5, 001 L25144-25190).

Three two-digit groups for internal X, Y, Z (or I, J, K); each group is a sign code
(0 blank, 1 +, 2 -) and an axis code (3 X, 4 Y, 5 Z, 6 I, 7 J, 8 K). A blank group (00)
drops that internal axis. A badly formed value is fatal error 7 (DECODE).
"""

from __future__ import annotations

from dataclasses import dataclass

_SIGNS = {1: 1, 2: -1}
_AXES = {3: "X", 4: "Y", 5: "Z", 6: "I", 7: "J", 8: "K"}


@dataclass(frozen=True, slots=True)
class AxisTarget:
    sign: int
    axis: str

    def __str__(self) -> str:
        return f"{'+' if self.sign > 0 else '-'}{self.axis}"


def decode_shuffle(value: float, axes: str) -> tuple[AxisTarget | None, ...]:
    """Decode option 59 (``axes='XYZ'``) or option 60 (``axes='IJK'``).

    Returns, for each internal axis, where it goes, or ``None`` when it is dropped.
    Raises ValueError naming the broken group.
    """
    if value != int(value) or not 0 <= value <= 999999:
        raise ValueError(f"{value!r} is not a six-digit code")
    digits = f"{int(value):06d}"
    targets: list[AxisTarget | None] = []
    used: set[str] = set()
    for index, internal in enumerate(axes):
        sign_code, axis_code = int(digits[2 * index]), int(digits[2 * index + 1])
        if sign_code == 0 and axis_code == 0:
            targets.append(None)
            continue
        if sign_code not in _SIGNS or axis_code not in _AXES:
            raise ValueError(
                f"group {digits[2 * index : 2 * index + 2]} for internal {internal} "
                "must be a sign code 1/2 followed by an axis code 3-8, or 00"
            )
        axis = _AXES[axis_code]
        if (axis in "XYZ") != (axes == "XYZ"):
            raise ValueError(f"internal {internal} cannot be output on {axis}")
        if axis in used:
            raise ValueError(f"two internal axes are output on {axis}")
        used.add(axis)
        targets.append(AxisTarget(_SIGNS[sign_code], axis))
    return tuple(targets)


def describe_shuffle(targets: tuple[AxisTarget | None, ...]) -> str:
    return "".join(str(t) for t in targets if t is not None) or "(none)"


_CELLS = {"X": 3, "Y": 4, "Z": 5, "I": 8, "J": 9, "K": 10}


def cell_map(value: float, axes: str) -> tuple[tuple[int, int] | None, ...]:
    """SHUFFL's vector: for each internal axis, (DBFSEG cell, sign) on output, or None."""
    return tuple(
        None if target is None else (_CELLS[target.axis], target.sign)
        for target in decode_shuffle(value, axes)
    )
