"""CLASS 5 (manual §4.2.5, 001 L13074-13079; spec 05 §8.6): 4(2,0,2), a filament winder.

The manual's own dummy: "This class is essentially a dummy class subroutine for a filament
winder. It satisfies the postprocessor necessity of providing a class subroutine within the
multiaxis sequence. In effect, all that it does is to set DPRESM equal to DPRESP"
(L13076-13079; the cross-reference lists of §5.3 give CLASS5 no ARCTAN, SIN or COS). So::

    DPRESM = DPRESP      (X Y Z A B C = x y z i j k, all six components, spec 05 E23)

Direct and inverse are both that copy. The rotary columns A, B, C carry the tool axis i, j, k
unchanged, not angles: the class drives no rotary axis through an equation, so ``rotary`` is
empty. There is no singular case and no quadrant choice (no angle is computed).
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.hookspecs import Register, hookimpl
from gecent.core.multiaxis.transform import Kinematics, MachinePoints, Points, as_points


@dataclass(frozen=True)
class Class5:
    number: int = 5
    name: str = "CLASS5"
    section: str = "§4.2.5"
    structure: str = "4(2,0,2)"
    rotary: tuple[int, ...] = ()

    def direct(
        self, part: Points, kinematics: Kinematics, previous: Points | None = None
    ) -> MachinePoints:
        import numpy as np

        machine = as_points(part).copy()
        return MachinePoints(machine, np.zeros(len(machine), dtype=bool))

    def inverse(self, machine: Points, kinematics: Kinematics) -> Points:
        return as_points(machine).copy()


@hookimpl
def register_transform_classes(register: Register) -> None:
    register(Class5())
