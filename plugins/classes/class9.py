"""CLASS 9 (manual §4.2.9, 001 L13345-13403; spec 05 §8.10): 5(3,0,2), a rotary table about Z
(C) and a rotary head about X (A) carried on a ram inclined at Ram Angle from vertical, the
machine of Diagram 4.2.8A with the head turned to pivot about X.

Direct (part to machine), as printed and cleaned::

    A = tan^-1 [k / sqrt(i^2 + j^2)]
    C = tan^-1 (i / j)                          (implemented: atan2(-i, j); see below)
    X = x cos C + y sin C                       (printed "x + Cos C": '+' for '*')
    Y = (Z - ZMO) sin(Ram Angle) + TL cos A - x sin C + y cos C
    Z = [z - TL (1 - sin A)] / cos(Ram Angle)

Inverse (machine to part)::

    i = -(cos A sin C)
    j = cos A cos C
    k = sin A
    x = -TIVAL sin C + X cos C
    y =  TIVAL cos C + X sin C
    z =  Z cos(Ram Angle) + TL (1 - sin A)
    TIVAL = Y - [(Z - ZMO) sin(Ram Angle) + TL cos A]
    ZMO   = [(option 125 + 50.3389) - TL] / cos(Ram Angle)

Readings (docs/decisions.md, "Transform classes"): Z is computed first and the Y equation
uses the machine Z, as TIVAL does (the OCR's case of z and Z is noise: it prints "z = z *
Cos" for the inverse's z = Z cos); C = atan2(-i, j), the sign the inverse's i = -(cos A sin C)
and the turn of x, y by C demand (the printed tan^-1(i/j) drops the minus: with it the tool
axis would not come into the head's plane); TL is the reach (R + TL), Ram Angle option 100
in degrees, "option 125 + 50.3389" option 101 (see inclined_ram.py).

Quadrants: A = atan2(k, sqrt(i^2 + j^2)) in [-90, 90] degrees (cos A >= 0: the head leans the
tool towards machine +Y, and a tool leaning the other way turns the table half round);
C = atan2(-i, j) in (-180, 180] (ROTMOV later brings it into [0, 360)). A positive Ram Angle
leans the ram, going up, towards machine -Y (Z raises the head by cos(Ram Angle) and moves
it by -sin(Ram Angle) against a fixed Y); with a negative Ram Angle a tool at A = 90 degrees
+ Ram Angle lies along the ram, and a move along the tool axis is a move of Z alone.

Singular case (not in the manual): a vertical tool (i = j = 0, A = +-90 degrees) leaves C
indeterminate; as in CLASS 1, C stays where it was and the linearity test is disregarded.
With Ram Angle 0 the class is CLASS 1 with C a quarter turn less and Z less TL (CLASS 9's Z
is the tip's height with the tool vertical, CLASS 1's the head's).
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
    Y,
)

from . import inclined_ram


@dataclass(frozen=True)
class Class9:
    number: int = 9
    name: str = "CLASS9"
    section: str = "§4.2.9"
    structure: str = "5(3,0,2)"
    rotary: tuple[int, ...] = (A, C)

    def direct(
        self, part: Points, kinematics: Kinematics, previous: Points | None = None
    ) -> MachinePoints:
        return inclined_ram.direct(part, kinematics, previous, lean=Y)

    def inverse(self, machine: Points, kinematics: Kinematics) -> Points:
        return inclined_ram.inverse(machine, kinematics, lean=Y)


@hookimpl
def register_transform_classes(register: Register) -> None:
    register(Class9())
