"""CLASS 6 (manual §4.2.6, 001 L13080-13186; spec 05 §8.7): 5(3,0,2), a head tilting about X
(A) on a column swivelling about Y (B), single-head or gantry (diagrams 4.2.6A/B).

The pivot plane is parallel to XY and holds both rotary axes; Q is the directed distance from
it to the part origin along Z (option 100), so the plane is z = -Q in part coordinates. The
machine X, Y are where the tool axis meets the pivot plane, t = (-Q - z)/k from the tip
back along (i, j, k); Z = -Q - t (Z = z with the tool along Z). No R + TL enters: the
manual's equations have none (the reach is ignored).

Direct (part to machine), L13125-13142::

    X = x + i (-Q - z) / k
    Y = y + j (-Q - z) / k
    Z = -Q - (-Q - z) / k
    A = atan(-j / sqrt(1 - j^2))    (head tilt, -90..90 degrees)
    B = atan(i / k)                 (column swivel, atan2(i, k): -180..180 degrees)

Inverse (machine to part), L13144-13170::

    x = X + (Z + Q) i
    y = Y + (Z + Q) j
    z = -Q + (Z + Q) k              (printed "z = Q + (Z+Q) k", L13150: the minus is lost)
    i = cos A sin B
    j = -sin A
    k = cos A cos B

Quadrants: cos A = sqrt(1 - j^2) >= 0 puts A in -90..90; B = atan2(i, k) takes the sign of
k, so k < 0 (the tool pointing up) swings the column past 90 degrees and the inverse gives it
back. Singular: k = 0, a tool axis parallel to the pivot plane, never meets it (t is
infinite, or indeterminate with the tip in the plane); j = +-1, where B is indeterminate,
lies inside it. The manual does not discuss it: such a point is refused as input the
machine cannot reach.
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.errors import InputError
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.multiaxis.transform import (
    SINGULAR,
    A,
    B,
    Kinematics,
    MachinePoints,
    Points,
    as_points,
)

# the option holding Q, the pivot plane to the part origin along Z
Q_OPTION = 100


@dataclass(frozen=True)
class Class6:
    number: int = 6
    name: str = "CLASS6"
    section: str = "§4.2.6"
    structure: str = "5(3,0,2)"
    rotary: tuple[int, ...] = (A, B)

    def direct(
        self, part: Points, kinematics: Kinematics, previous: Points | None = None
    ) -> MachinePoints:
        import numpy as np

        part = as_points(part)
        x, y, z, i, j, k = part.T
        unreachable = np.abs(k) < SINGULAR
        if unreachable.any():
            row = int(np.argmax(unreachable))
            raise InputError(
                f"CLASS6 cannot reach the tool axis ({i[row]}, {j[row]}, {k[row]}) of point "
                f"{row + 1} of the run: k = 0 is parallel to the pivot plane (manual §4.2.6)"
            )
        pivot = -kinematics.option(Q_OPTION)
        t = (pivot - z) / k
        machine = np.zeros_like(part)
        machine[:, 0] = x + i * t
        machine[:, 1] = y + j * t
        machine[:, 2] = pivot - t
        machine[:, A] = np.arctan2(-j, np.sqrt(np.clip(1.0 - j * j, 0.0, None)))
        machine[:, B] = np.arctan2(i, k)
        return MachinePoints(machine, np.zeros(len(part), dtype=bool))

    def inverse(self, machine: Points, kinematics: Kinematics) -> Points:
        import numpy as np

        machine = as_points(machine)
        big_x, big_y, big_z = machine[:, 0], machine[:, 1], machine[:, 2]
        tilt, swivel = machine[:, A], machine[:, B]
        q = kinematics.option(Q_OPTION)
        i = np.cos(tilt) * np.sin(swivel)
        j = -np.sin(tilt)
        k = np.cos(tilt) * np.cos(swivel)
        along = big_z + q
        part = np.empty_like(machine)
        part[:, 0] = big_x + along * i
        part[:, 1] = big_y + along * j
        part[:, 2] = -q + along * k
        part[:, 3] = i
        part[:, 4] = j
        part[:, 5] = k
        return part


@hookimpl
def register_transform_classes(register: Register) -> None:
    register(Class6())
