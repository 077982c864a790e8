"""CLASS 1 (manual §4.2.1, 001 L12749-12870; spec 05 §8.2): 5(3,0,2), a rotary table about
Z (C) and a rotary head about X (A), the tool tip at R + TL from the head's axis.

Direct (part to machine)::

    s = sqrt(1 - k^2)
    X = x j / s - y i / s
    Y = x i / s + y j / s + (R + TL) s
    Z = z + (R + TL) k
    A = atan2(k, s)            (head, -90..90 degrees)
    C = atan2(j, i)            (table)

Inverse::

    x = X sin C + (Y - (R + TL) cos A) cos C
    y = (Y - (R + TL) cos A) sin C - X cos C
    z = Z - (R + TL) sin A
    i, j, k = cos A cos C, cos A sin C, sin A

A tool axis along Z (k = 1) leaves the table's angle indeterminate: C stays where it was,
A = 90 degrees, and the linearity test is disregarded over the move (L12845-12870).
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.hookspecs import Register, hookimpl
from gecent.core.multiaxis.transform import (
    SINGULAR,
    A,
    C,
    Kinematics,
    MachinePoints,
    Points,
    as_points,
    keep_previous,
)


@dataclass(frozen=True)
class Class1:
    number: int = 1
    name: str = "CLASS1"
    section: str = "§4.2.1"
    structure: str = "5(3,0,2)"
    rotary: tuple[int, ...] = (A, C)

    def direct(
        self, part: Points, kinematics: Kinematics, previous: Points | None = None
    ) -> MachinePoints:
        import numpy as np

        part = as_points(part)
        x, y, z, i, j, k = part.T
        reach = kinematics.reach
        s = np.sqrt(np.clip(1.0 - k * k, 0.0, None))
        singular = s < SINGULAR
        table = keep_previous(np.arctan2(j, i), singular, previous, C)
        # with s > 0, (i/s, j/s) = (cos C, sin C): the same equations serve both cases
        cos_c, sin_c = np.cos(table), np.sin(table)
        machine = np.zeros_like(part)
        machine[:, 0] = x * sin_c - y * cos_c
        machine[:, 1] = x * cos_c + y * sin_c + reach * s
        machine[:, 2] = z + reach * k
        machine[:, A] = np.arctan2(k, s)
        machine[:, C] = table
        return MachinePoints(machine, singular)

    def inverse(self, machine: Points, kinematics: Kinematics) -> Points:
        import numpy as np

        machine = as_points(machine)
        big_x, big_y, big_z = machine[:, 0], machine[:, 1], machine[:, 2]
        head, table = machine[:, A], machine[:, C]
        reach = kinematics.reach
        cos_a, sin_a = np.cos(head), np.sin(head)
        cos_c, sin_c = np.cos(table), np.sin(table)
        level = big_y - reach * cos_a
        part = np.empty_like(machine)
        part[:, 0] = big_x * sin_c + level * cos_c
        part[:, 1] = level * sin_c - big_x * cos_c
        part[:, 2] = big_z - reach * sin_a
        part[:, 3] = cos_a * cos_c
        part[:, 4] = cos_a * sin_c
        part[:, 5] = sin_a
        return part


@hookimpl
def register_transform_classes(register: Register) -> None:
    register(Class1())
