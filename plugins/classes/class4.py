"""CLASS 4 (manual §4.2.4, 001 L13030-13073; spec 05 §8.5): 4(3,0,1), a rotary table about
X (A) under a fixed head, the part's origin on the table's axis (no offsets).

Direct (part to machine)::

    X = x
    Y = y k - z j
    Z = y j + z k
    A = tan^-1(k / j),  0 <= A <= 2 pi      (atan2(k, j), brought into 0..2 pi)

Inverse::

    x = X
    y = Y sin A + Z cos A
    z = -Y cos A + Z sin A
    j = cos A
    k = sin A
    i = 0

The two are exact inverses of each other (the printed lowercase y, z of the inverse are the
machine's Y, Z). A is kept in [0, 2 pi): an angle that would round to 2 pi is 0. The table
turns the part about X only, so the tool axes it can give have i = 0; a tool axis with
i != 0 is taken as its projection on the YZ plane, (j, k) made (cos A, sin A), which is the
manual's equations wherever i = 0. A tool axis along X (j = k = 0) leaves the table's angle
indeterminate: A stays where it was and the linearity test is disregarded over the move (as
CLASS 1's singular case, L12845-12870).
"""

from __future__ import annotations

from dataclasses import dataclass
from math import tau

from gecent.core.hookspecs import Register, hookimpl
from gecent.core.multiaxis.transform import (
    SINGULAR,
    A,
    Kinematics,
    MachinePoints,
    Points,
    as_points,
    keep_previous,
)

TURN = tau


def full_turn(angle: Points) -> Points:
    """An angle of atan2 (-pi..pi) brought into [0, 2 pi), as the manual's 0 <= A <= 2 pi."""
    import numpy as np

    turned = np.where(angle < 0.0, angle + TURN, angle)
    # a small negative angle plus 2 pi rounds to 2 pi itself; + 0.0 makes -0.0 plain 0.0
    return np.where(turned >= TURN, 0.0, turned) + 0.0


@dataclass(frozen=True)
class Class4:
    number: int = 4
    name: str = "CLASS4"
    section: str = "§4.2.4"
    structure: str = "4(3,0,1)"
    rotary: tuple[int, ...] = (A,)

    def direct(
        self, part: Points, kinematics: Kinematics, previous: Points | None = None
    ) -> MachinePoints:
        import numpy as np

        part = as_points(part)
        x, y, z, _, j, k = part.T
        singular = np.hypot(j, k) < SINGULAR
        table = keep_previous(full_turn(np.arctan2(k, j)), singular, previous, A)
        # (j, k) = (cos A, sin A) for every tool axis the table can give
        cos_a, sin_a = np.cos(table), np.sin(table)
        machine = np.zeros_like(part)
        machine[:, 0] = x
        machine[:, 1] = y * sin_a - z * cos_a
        machine[:, 2] = y * cos_a + z * sin_a
        machine[:, A] = table
        return MachinePoints(machine, singular)

    def inverse(self, machine: Points, kinematics: Kinematics) -> Points:
        import numpy as np

        machine = as_points(machine)
        big_x, big_y, big_z = machine[:, 0], machine[:, 1], machine[:, 2]
        table = machine[:, A]
        cos_a, sin_a = np.cos(table), np.sin(table)
        part = np.zeros_like(machine)
        part[:, 0] = big_x
        part[:, 1] = big_y * sin_a + big_z * cos_a
        part[:, 2] = big_z * sin_a - big_y * cos_a
        part[:, 4] = cos_a
        part[:, 5] = sin_a
        return part


@hookimpl
def register_transform_classes(register: Register) -> None:
    register(Class4())
