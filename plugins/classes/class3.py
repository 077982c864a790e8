"""CLASS 3 (manual §4.2.3, 001 L12945-13024; spec 05 §8.4): 5(2,0,3), two linear axes (X, Z)
and three rotary ones: a head turning about two axes (A and B, "head rotation angle") and a
rotary table (C) that brings the head's pivot onto the machine's Y = 0 line. The pivot (the
gauge point) is TL from the tool tip along the tool axis.

Direct (part to machine), as the digest restores the OCR's symbols::

    Xe = x + i TL                 (the pivot: tip + TL (i, j, k))
    Ye = y + j TL
    Ze = z + k TL
    H  = sqrt(Xe^2 + Ye^2)
    i' = (i Xe + j Ye) / H        (the tool axis in the frame the table has turned)
    j' = (j Xe - i Ye) / H
    k' = k
    G  = sqrt(j'^2 + k'^2)
    X  = H
    Y  = 0                        (by definition)
    Z  = Ze
    A  = tan^-1((-j' sign k) / |k|)     (head: atan2(-j' sign k, |k|), -90..90 degrees)
    B  = tan^-1(i' / (G sign k))        (head: atan2(i', G sign k), cos B of k's sign)
    C  = tan^-1(-Xe / Ye)               (table: atan2(-Xe, Ye), -180..180 degrees)

Inverse::

    i = -sin C sin B + cos C cos B sin A
    j =  cos C sin B + sin C cos B sin A
    k =  cos B cos A
    x = -X sin C - TL i
    y =  X cos C - TL j
    z =  Z - TL k

Each tan^-1 is the two-argument arctangent of the numerator and denominator as printed:
its quadrants are the ones the inverse needs (X = H >= 0, cos A >= 0, cos B and k of one
sign), and the two transforms are then exact inverses of each other. With (Xe, Ye) =
H (-sin C, cos C), i' = -i sin C + j cos C and j' = -j sin C - i cos C: the same equations
serve when H = 0. ``sign k`` is +1 at k = 0 (Fortran's SIGN), so a horizontal tool axis
takes A = -90 degrees sign j' and B in -90..90.

Singular cases (the manual has none): the pivot on the table's axis (H = 0) leaves C
indeterminate, and a tool axis along the turned frame's x (G = 0, B = +-90 degrees) leaves
A indeterminate; the angle stays where it was and the linearity test is disregarded over
the move (as CLASS 1's singular case, L12845-12870). Y is 0 (the machine has no Y axis);
TL is the class's reach (R + TL with R = 0: the manual gives this head no R).
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.hookspecs import Register, hookimpl
from gecent.core.multiaxis.transform import (
    SINGULAR,
    A,
    B,
    C,
    Kinematics,
    MachinePoints,
    Points,
    as_points,
    keep_previous,
)


@dataclass(frozen=True)
class Class3:
    number: int = 3
    name: str = "CLASS3"
    section: str = "§4.2.3"
    structure: str = "5(2,0,3)"
    rotary: tuple[int, ...] = (A, B, C)

    def direct(
        self, part: Points, kinematics: Kinematics, previous: Points | None = None
    ) -> MachinePoints:
        import numpy as np

        part = as_points(part)
        x, y, z, i, j, k = part.T
        tool = kinematics.reach
        pivot_x, pivot_y, pivot_z = x + i * tool, y + j * tool, z + k * tool
        span = np.hypot(pivot_x, pivot_y)
        off_axis = span < SINGULAR
        table = keep_previous(np.arctan2(-pivot_x, pivot_y), off_axis, previous, C)
        sin_c, cos_c = np.sin(table), np.cos(table)
        turned_i = j * cos_c - i * sin_c
        turned_j = -j * sin_c - i * cos_c
        sign_k = np.where(k >= 0.0, 1.0, -1.0)
        g = np.hypot(turned_j, k)
        locked = g < SINGULAR
        head_a = keep_previous(np.arctan2(-turned_j * sign_k, np.abs(k)), locked, previous, A)
        machine = np.zeros_like(part)
        machine[:, 0] = np.where(off_axis, pivot_y * cos_c - pivot_x * sin_c, span)
        machine[:, 2] = pivot_z
        machine[:, A] = head_a
        machine[:, B] = np.arctan2(turned_i, g * sign_k)
        machine[:, C] = table
        return MachinePoints(machine, off_axis | locked)

    def inverse(self, machine: Points, kinematics: Kinematics) -> Points:
        import numpy as np

        machine = as_points(machine)
        big_x, big_z = machine[:, 0], machine[:, 2]
        sin_a, cos_a = np.sin(machine[:, A]), np.cos(machine[:, A])
        sin_b, cos_b = np.sin(machine[:, B]), np.cos(machine[:, B])
        sin_c, cos_c = np.sin(machine[:, C]), np.cos(machine[:, C])
        tool = kinematics.reach
        i = -sin_c * sin_b + cos_c * cos_b * sin_a
        j = cos_c * sin_b + sin_c * cos_b * sin_a
        k = cos_b * cos_a
        part = np.empty_like(machine)
        part[:, 0] = -big_x * sin_c - tool * i
        part[:, 1] = big_x * cos_c - tool * j
        part[:, 2] = big_z - tool * k
        part[:, 3] = i
        part[:, 4] = j
        part[:, 5] = k
        return part


@hookimpl
def register_transform_classes(register: Register) -> None:
    register(Class3())
