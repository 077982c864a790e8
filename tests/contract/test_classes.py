"""Contract: every registered transform class (option 116, manual §4.2): it names its axes,
takes a run of points at once, and its inverse undoes its direct transform to 1e-12 over
valid tool axes (unit vectors the class can reach), for several tool reaches."""

from __future__ import annotations

import numpy as np
import pytest
from gecent.core.multiaxis.transform import Kinematics, TransformClass, as_points
from gecent.core.plugins import PluginInfo

from .conftest import plugin_params
from .numbered import check_family_loads, check_numbered_plugin

pytestmark = pytest.mark.contract


def test_family_loads() -> None:
    check_family_loads("classes")


@pytest.mark.parametrize("info", **plugin_params("classes"))
def test_plugin_contract(info: PluginInfo) -> None:
    check_numbered_plugin("classes", info)
    plugin = info.obj
    assert isinstance(plugin, TransformClass)
    assert set(plugin.rotary) <= {3, 4, 5}
    assert plugin.structure and plugin.structure[0].isdigit()


def _reachable(plugin: TransformClass, count: int, seed: int) -> np.ndarray:
    """Random part points whose tool axes the class can reach: made from random machine
    points by the class's own inverse (the rotary angles drawn away from singular
    positions), so the test asks direct to find them again."""
    rng = np.random.default_rng(seed)
    if not plugin.rotary:  # a class that drives no rotary axis: any unit tool axes
        part = np.zeros((count, 6))
        part[:, :3] = rng.uniform(-20.0, 20.0, (count, 3))
        axes = rng.normal(size=(count, 3))
        part[:, 3:] = axes / np.linalg.norm(axes, axis=1, keepdims=True)
        return part
    machine = np.zeros((count, 6))
    machine[:, :3] = rng.uniform(-20.0, 20.0, (count, 3))
    for column in plugin.rotary:
        machine[:, column] = rng.uniform(-1.3, 1.3, count)  # radians, clear of the poles
    return plugin.inverse(machine, Kinematics(reach=7.5, options=(10.0, 2.0, 3.0, 8.5, 4.0, 9.5)))


@pytest.mark.parametrize("info", **plugin_params("classes"))
@pytest.mark.parametrize("reach", [0.0, 7.5])
def test_inverse_undoes_direct(info: PluginInfo, reach: float) -> None:
    plugin = info.obj
    kinematics = Kinematics(reach=reach, options=(10.0, 2.0, 3.0, 8.5, 4.0, 9.5))
    part = _reachable(plugin, 200, seed=plugin.number)
    if reach == 0.0:  # the same tool axes at no reach
        part = plugin.inverse(
            plugin.direct(part, Kinematics(7.5, kinematics.options)).axes, kinematics
        )
    lengths = np.linalg.norm(part[:, 3:], axis=1)
    assert np.allclose(lengths, 1.0, atol=1e-12), "the inverse gives unit tool axes"
    machine = plugin.direct(part, kinematics)
    assert machine.axes.shape == part.shape
    back = plugin.inverse(machine.axes, kinematics)
    assert np.allclose(back, part, rtol=0.0, atol=1e-12)


@pytest.mark.parametrize("info", **plugin_params("classes"))
def test_one_point_is_a_run_of_one(info: PluginInfo) -> None:
    plugin = info.obj
    kinematics = Kinematics(reach=5.0, options=(10.0, 2.0, 3.0, 8.5, 4.0, 9.5))
    part = _reachable(plugin, 5, seed=99)
    whole = plugin.direct(part, kinematics).axes
    for row, expected in zip(part, whole, strict=True):
        assert np.allclose(plugin.direct(as_points(row), kinematics).axes[0], expected)
