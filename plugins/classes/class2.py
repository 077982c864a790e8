"""CLASS 2 (manual §4.2.2, 001 L12876-12944; spec 05 §8.3): 4(3,0,1), a rotary table about
Y (B) under a fixed head, the tool tip at R + TL from the head's axis (R, the head's axis to
the spindle face, is 3 as standard: option 102).

Direct (part to machine)::

    X = x k - z i
    Y = y
    Z = x i + z k + (R + TL)
    B = tan^-1(i / k)          (table: atan2(i, k), -180..180 degrees)

Inverse::

    x = [Z - (R + TL)] sin B + X cos B
    y = Y
    z = [Z - (R + TL)] cos B - X sin B
    i = sin B
    j = 0
    k = cos B

The two are exact inverses of each other (the printed lowercase x of the inverse is the
machine's X). The table turns the part about Y only, so the tool axes it can give have
j = 0; a tool axis with j != 0 is taken as its projection on the XZ plane, (i, k) made
(sin B, cos B), which is the manual's equations wherever j = 0. A tool axis along Y
(i = k = 0) leaves the table's angle indeterminate: B stays where it was and the
linearity test is disregarded over the move (as CLASS 1's singular case, L12845-12870).
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.hookspecs import Register, hookimpl
from gecent.core.multiaxis.transform import (
    SINGULAR,
    B,
    Kinematics,
    MachinePoints,
    Points,
    as_points,
    keep_previous,
)


@dataclass(frozen=True)
class Class2:
    number: int = 2
    name: str = "CLASS2"
    section: str = "§4.2.2"
    structure: str = "4(3,0,1)"
    rotary: tuple[int, ...] = (B,)

    def direct(
        self, part: Points, kinematics: Kinematics, previous: Points | None = None
    ) -> MachinePoints:
        import numpy as np

        part = as_points(part)
        x, y, z, i, _, k = part.T
        reach = kinematics.reach
        singular = np.hypot(i, k) < SINGULAR
        table = keep_previous(np.arctan2(i, k), singular, previous, B)
        # (i, k) = (sin B, cos B) for every tool axis the table can give
        sin_b, cos_b = np.sin(table), np.cos(table)
        machine = np.zeros_like(part)
        machine[:, 0] = x * cos_b - z * sin_b
        machine[:, 1] = y
        machine[:, 2] = x * sin_b + z * cos_b + reach
        machine[:, B] = table
        return MachinePoints(machine, singular)

    def inverse(self, machine: Points, kinematics: Kinematics) -> Points:
        import numpy as np

        machine = as_points(machine)
        big_x, big_y, big_z = machine[:, 0], machine[:, 1], machine[:, 2]
        table = machine[:, B]
        sin_b, cos_b = np.sin(table), np.cos(table)
        level = big_z - kinematics.reach
        part = np.zeros_like(machine)
        part[:, 0] = level * sin_b + big_x * cos_b
        part[:, 1] = big_y
        part[:, 2] = level * cos_b - big_x * sin_b
        part[:, 3] = sin_b
        part[:, 5] = cos_b
        return part


@hookimpl
def register_transform_classes(register: Register) -> None:
    register(Class2())
