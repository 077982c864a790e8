"""CLASS 8 (manual §4.2.8, 001 L13303-13344, terms L13389-13403; spec 05 §8.9): 5(3,0,2), a
rotary table about Z (C) and a rotary head (A) pivoting about Y, carried on a ram inclined at
Ram Angle from vertical (Diagram 4.2.8A: CLASS 9's machine with the head turned to pivot
about Y, L13351-13353).

As printed and cleaned, the page gives CLASS 9's equations (a head about X)::

    A = tan^-1 [k / sqrt(i^2 + j^2)]
    C = tan^-1 [unreadable, "[1]"]
    X = x cos C + y sin C
    Y = (Z - ZMO) sin(Ram Angle) + TL cos A - x sin C + y cos C
    Z = [z - TL (1 - sin A)] / cos(Ram Angle)

    i = -(cos A sin A)                          (sic: CLASS 9 has -(cos A sin C))
    j = cos A cos C
    k = sin A
    x = -TIVAL sin C + X cos C
    y =  TIVAL cos C + X sin C
    z =  Z cos(Ram Angle) + TL (1 - sin A)
    TIVAL = Y - [(Z - ZMO) sin(Ram Angle) + TL cos A]

Implemented (docs/decisions.md, "Transform classes"): the head the text describes, pivoting
about Y, so the tool swings in the machine XZ plane and its TL cos A goes to X; the ram is
the same as CLASS 9's (its sin(Ram Angle) term stays in Y)::

    A = atan2(k, sqrt(i^2 + j^2))
    C = atan2(j, i)
    X = x cos C + y sin C + TL cos A
    Y = (Z - ZMO) sin(Ram Angle) - x sin C + y cos C
    Z = [z - TL (1 - sin A)] / cos(Ram Angle)

    i = cos A cos C,  j = cos A sin C,  k = sin A
    XIVAL = X - TL cos A,  TIVAL = Y - (Z - ZMO) sin(Ram Angle)
    x = -TIVAL sin C + XIVAL cos C
    y =  TIVAL cos C + XIVAL sin C
    z =  Z cos(Ram Angle) + TL (1 - sin A)
    ZMO = [(option 125 + 50.3389) - TL] / cos(Ram Angle)

TL is the reach (R + TL), Ram Angle option 100 in degrees, "option 125 + 50.3389" option 101
(see inclined_ram.py). Quadrants: A in [-90, 90] degrees (cos A >= 0: the head leans the tool
towards machine +X, a tool leaning the other way turns the table half round); C = atan2(j, i)
in (-180, 180], CLASS 1's table angle (ROTMOV later brings it into [0, 360)).

Singular case (not in the manual): a vertical tool (i = j = 0, A = +-90 degrees) leaves C
indeterminate; as in CLASS 1, C stays where it was and the linearity test is disregarded.
With Ram Angle 0 the class is CLASS 1 turned a quarter about Z: CLASS 8's X is CLASS 1's Y,
its Y CLASS 1's -X, the same A and C, and Z less TL (the tip's height with the tool vertical).
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.hookspecs import Register, hookimpl
from gecent.core.multiaxis.transform import (
    A,
    C,
    Kinematics,
    MachinePoints,
    Points,
    X,
)

from . import inclined_ram


@dataclass(frozen=True)
class Class8:
    number: int = 8
    name: str = "CLASS8"
    section: str = "§4.2.8"
    structure: str = "5(3,0,2)"
    rotary: tuple[int, ...] = (A, C)

    def direct(
        self, part: Points, kinematics: Kinematics, previous: Points | None = None
    ) -> MachinePoints:
        return inclined_ram.direct(part, kinematics, previous, lean=X)

    def inverse(self, machine: Points, kinematics: Kinematics) -> Points:
        return inclined_ram.inverse(machine, kinematics, lean=X)


@hookimpl
def register_transform_classes(register: Register) -> None:
    register(Class8())
