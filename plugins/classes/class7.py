"""CLASS 7 (manual §4.2.7, 001 L13187-13302; spec 05 §8.8): 5(3,0,2), a column swivelling
about Y (B) over an angle plate whose "venetian blinds", work-holding fixtures, turn about X
(A) (diagrams 4.2.7A-C; the machine has three blinds and a triple spindle).

Constants (L13260-13267): Q, the directed distance from the pivot plane to the part origin
along Z (option 100, as in CLASS 6); S1 and S2, the directed distances from the blind's axis
to the part origin along Z and along Y (options 101, 102): the blind turns about the line
y = -S2, z = -S1 of the part. No R + TL enters: the manual's equations have none.

Direct (part to machine), L13210-13228, the denominators the print lost restored (the
blind's rotation undone, then CLASS 6's column with j = 0)::

    T7 = [(S1 - Q) sqrt(j^2 + k^2) - (j (y + S2) + k (z + S1))] / (j^2 + k^2)
    X = x + i T7
    Y = -S2 + [k (y + S2) - j (z + S1)] / sqrt(j^2 + k^2)
    Z = -Q - T7
    A = atan(-j / k)                       (blind, atan2(-j, k): -180..180 degrees)
    B = atan(i / sqrt(j^2 + k^2))          (column, -90..90 degrees)

Inverse (machine to part), L13230-13247, its lost signs and parentheses restored::

    x = X + (Z + Q) sin B
    y = -S2 + (Y + S2) cos A - [(S1 - Q) + (Z + Q) cos B] sin A
    z = -S1 + (Y + S2) sin A + [(S1 - Q) + (Z + Q) cos B] cos A
    i = sin B
    j = -sin A cos B                       (printed "-sin B cos B", L13245)
    k = cos A cos B

Quadrants: cos B = sqrt(j^2 + k^2) >= 0 puts B in -90..90; the blind takes any angle,
atan2(-j, k). Singular: j = k = 0, a tool axis along X (B = +-90 degrees): the blind's angle
is indeterminate and the axis, parallel to the pivot plane, never meets it (T7 is
infinite). The manual does not discuss it: such a point is refused as input the machine
cannot reach.
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

# the options holding Q (pivot plane to part origin, Z), S1 (blind axis to part origin, Z)
# and S2 (blind axis to part origin, Y)
Q_OPTION, S1_OPTION, S2_OPTION = 100, 101, 102


@dataclass(frozen=True)
class Class7:
    number: int = 7
    name: str = "CLASS7"
    section: str = "§4.2.7"
    structure: str = "5(3,0,2)"
    rotary: tuple[int, ...] = (A, B)

    def direct(
        self, part: Points, kinematics: Kinematics, previous: Points | None = None
    ) -> MachinePoints:
        import numpy as np

        part = as_points(part)
        x, y, z, i, j, k = part.T
        q, s1, s2 = (kinematics.option(n) for n in (Q_OPTION, S1_OPTION, S2_OPTION))
        r = np.sqrt(j * j + k * k)
        unreachable = r < SINGULAR
        if unreachable.any():
            row = int(np.argmax(unreachable))
            raise InputError(
                f"CLASS7 cannot reach the tool axis ({i[row]}, {j[row]}, {k[row]}) of point "
                f"{row + 1} of the run: along X it is parallel to the pivot plane "
                "(manual §4.2.7)"
            )
        across, up = y + s2, z + s1  # from the blind's axis
        t7 = ((s1 - q) * r - (j * across + k * up)) / (r * r)
        machine = np.zeros_like(part)
        machine[:, 0] = x + i * t7
        machine[:, 1] = -s2 + (k * across - j * up) / r
        machine[:, 2] = -q - t7
        machine[:, A] = np.arctan2(-j, k)
        machine[:, B] = np.arctan2(i, r)
        return MachinePoints(machine, np.zeros(len(part), dtype=bool))

    def inverse(self, machine: Points, kinematics: Kinematics) -> Points:
        import numpy as np

        machine = as_points(machine)
        big_x, big_y, big_z = machine[:, 0], machine[:, 1], machine[:, 2]
        blind, column = machine[:, A], machine[:, B]
        q, s1, s2 = (kinematics.option(n) for n in (Q_OPTION, S1_OPTION, S2_OPTION))
        cos_a, sin_a = np.cos(blind), np.sin(blind)
        cos_b, sin_b = np.cos(column), np.sin(column)
        along = big_z + q
        across = big_y + s2
        up = (s1 - q) + along * cos_b  # the tip above the blind's axis, blind at A = 0
        part = np.empty_like(machine)
        part[:, 0] = big_x + along * sin_b
        part[:, 1] = -s2 + across * cos_a - up * sin_a
        part[:, 2] = -s1 + across * sin_a + up * cos_a
        part[:, 3] = sin_b
        part[:, 4] = -sin_a * cos_b
        part[:, 5] = cos_a * cos_b
        return part


@hookimpl
def register_transform_classes(register: Register) -> None:
    register(Class7())
