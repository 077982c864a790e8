"""CLASS 5 (manual §4.2.5): the filament winder's dummy, DPRESM = DPRESP (spec 05 E23)."""

from __future__ import annotations

import numpy as np
from gecent.core.multiaxis.transform import Kinematics
from gecent.plugins.classes.class5 import Class5

KINEMATICS = Kinematics(reach=7.5, options=(10.0, 2.0, 3.0, 8.5, 4.0, 9.5))


def test_the_output_equals_the_input() -> None:
    """E23: all six components are copied, the tool axis into the A B C columns."""
    part = np.array([[1.0, 2.0, 3.0, 0.0, 0.6, 0.8], [-4.25, 0.5, 12.0, 1.0, 0.0, 0.0]])
    result = Class5().direct(part, KINEMATICS)
    assert result.axes.tolist() == part.tolist()
    assert result.singular.tolist() == [False, False]
    assert Class5().inverse(result.axes, KINEMATICS).tolist() == part.tolist()


def test_the_copy_is_a_new_array() -> None:
    part = np.array([[1.0, 2.0, 3.0, 0.0, 0.0, 1.0]])
    machine = Class5().direct(part, KINEMATICS).axes
    machine[0, 0] = 99.0
    assert part[0, 0] == 1.0
    back = Class5().inverse(machine, KINEMATICS)
    back[0, 1] = 99.0
    assert machine[0, 1] == 2.0


def test_it_drives_no_rotary_axis_through_an_equation() -> None:
    """No angle is computed: no singular case, and neither the reach nor the options count."""
    part = np.array([1.0, 2.0, 3.0, 0.0, 0.0, 1.0])
    assert Class5().rotary == ()
    assert Class5().structure == "4(2,0,2)" and Class5().section == "§4.2.5"
    assert Class5().direct(part, Kinematics()).axes.tolist() == [part.tolist()]
