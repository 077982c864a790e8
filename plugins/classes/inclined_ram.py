"""The arithmetic CLASS 8 and CLASS 9 share (manual §4.2.8-§4.2.9, 001 L13303-13403; spec
05 §8.9-§8.10): a rotary table about Z (C) and a rotary head (A) carried on a ram (the Z
slide) inclined at Ram Angle from vertical. Not a plugin: class8.py and class9.py register.

Both classes turn the part by the table, ``across = x cos C + y sin C`` and
``along = -x sin C + y cos C``, and put the tool axis in the plane through Z in which the head
swings: towards machine X for CLASS 8, towards machine Y for CLASS 9 (the ``lean`` column).
The tool tip is at TL from the head's pivot, so the pivot is TL cos A along the lean and
TL sin A above the tip. The ram moves the pivot by (Z - ZMO) sin(Ram Angle) in machine Y and
Z cos(Ram Angle) in height::

    Z   = [z - TL (1 - sin A)] / cos(Ram Angle)
    Y   = (Z - ZMO) sin(Ram Angle) + along      (+ TL cos A when the head leans to Y)
    X   = across                                (+ TL cos A when the head leans to X)
    ZMO = [(option 125 + 50.3389) - TL] / cos(Ram Angle)

The constants (docs/decisions.md, "Transform classes"): TL is the Kinematics reach (R + TL,
the head's pivot to the tool tip); Ram Angle, in degrees, is option 100; ZMO's height
"option 125 + 50.3389" is option 101 (a one-head machine has no use for options 100-101, the
distances between two heads' spindles). With a unit tool axis cos A = sqrt(i^2 + j^2) and
sin A = k: the direct transform uses those, exact where the tool is vertical or level.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from gecent.core.multiaxis.transform import (
    SINGULAR,
    A,
    C,
    Kinematics,
    MachinePoints,
    Points,
    X,
    Y,
    Z,
    as_points,
    keep_previous,
)

# the option holding the ram's inclination from vertical, degrees
RAM_ANGLE = 100
# the option holding ZMO's height, "option 125 + 50.3389" on the manual's machine
RAM_HEIGHT = 101


# |cos(Ram Angle)| below this is a ram lying down: the equations divide by it
LEVEL = 1e-9


@dataclass(frozen=True)
class Ram:
    """The ram's constants for one tool: cos and sin of Ram Angle, ZMO, and TL (the reach)."""

    cos: float
    sin: float
    zmo: float
    reach: float

    @classmethod
    def of(cls, kinematics: Kinematics) -> Ram:
        angle = math.radians(kinematics.option(RAM_ANGLE))
        cos, sin = math.cos(angle), math.sin(angle)
        if abs(cos) < LEVEL:
            raise ValueError(
                f"option {RAM_ANGLE} (Ram Angle) = {kinematics.option(RAM_ANGLE)} degrees: "
                "a ram at 90 degrees from vertical has no Z (the equations divide by its cosine)"
            )
        zmo = (kinematics.option(RAM_HEIGHT) - kinematics.reach) / cos
        return cls(cos, sin, zmo, kinematics.reach)


def _check(lean: int) -> None:
    if lean not in (X, Y):
        raise ValueError(f"the head leans the tool towards machine X (0) or Y (1), not {lean}")


def direct(
    part: Points, kinematics: Kinematics, previous: Points | None, lean: int
) -> MachinePoints:
    """Part to machine for a head whose tool leans towards machine column ``lean`` (X or Y).

    C = atan2(j, i) (lean X) or atan2(-i, j) (lean Y), in (-180, 180] degrees;
    A = atan2(k, sqrt(i^2 + j^2)), in [-90, 90] degrees. A vertical tool (sqrt(i^2 + j^2)
    below SINGULAR) keeps the previous C and is singular."""
    import numpy as np

    _check(lean)
    part = as_points(part)
    x, y, z, i, j, k = part.T
    ram = Ram.of(kinematics)
    level = np.hypot(i, j)  # cos A
    singular = level < SINGULAR
    # + 0.0 turns a -0.0 into +0.0, so a tool straight behind gives C = +180, not -180
    angle = np.arctan2(j + 0.0, i + 0.0) if lean == X else np.arctan2(0.0 - i, j + 0.0)
    table = keep_previous(angle, singular, previous, C)
    cos_c, sin_c = np.cos(table), np.sin(table)
    machine = np.zeros_like(part)
    machine[:, Z] = (z - ram.reach * (1.0 - k)) / ram.cos
    machine[:, X] = x * cos_c + y * sin_c
    machine[:, Y] = (machine[:, Z] - ram.zmo) * ram.sin - x * sin_c + y * cos_c
    machine[:, lean] += ram.reach * level
    machine[:, A] = np.arctan2(k, level)
    machine[:, C] = table
    return MachinePoints(machine, singular)


def inverse(machine: Points, kinematics: Kinematics, lean: int) -> Points:
    """Machine to part for a head whose tool leans towards machine column ``lean``::

    TIVAL = Y - [(Z - ZMO) sin(Ram Angle)]   (- TL cos A when the head leans to Y)
    XIVAL = X                                (- TL cos A when the head leans to X)
    x = -TIVAL sin C + XIVAL cos C
    y =  TIVAL cos C + XIVAL sin C
    z =  Z cos(Ram Angle) + TL (1 - sin A)
    """
    import numpy as np

    _check(lean)
    machine = as_points(machine)
    big_z, head, table = machine[:, Z], machine[:, A], machine[:, C]
    ram = Ram.of(kinematics)
    cos_a, sin_a = np.cos(head), np.sin(head)
    cos_c, sin_c = np.cos(table), np.sin(table)
    xival = machine[:, X].copy()
    tival = machine[:, Y] - (big_z - ram.zmo) * ram.sin
    if lean == X:
        xival -= ram.reach * cos_a
    else:
        tival -= ram.reach * cos_a
    part = np.empty_like(machine)
    part[:, 0] = -tival * sin_c + xival * cos_c
    part[:, 1] = tival * cos_c + xival * sin_c
    part[:, 2] = big_z * ram.cos + ram.reach * (1.0 - sin_a)
    if lean == X:
        part[:, 3] = cos_a * cos_c
        part[:, 4] = cos_a * sin_c
    else:
        part[:, 3] = -(cos_a * sin_c)
        part[:, 4] = cos_a * cos_c
    part[:, 5] = sin_a
    return part
