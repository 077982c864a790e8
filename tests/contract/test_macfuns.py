"""Contract: every registered MACFUN belongs to an installed machine that enables it."""

from __future__ import annotations

import pytest
from gecent.core.families import HookPoint, Macfun
from gecent.core.plugins import PluginInfo, get_plugins

from .conftest import plugin_params

pytestmark = pytest.mark.contract


@pytest.mark.parametrize("info", **plugin_params("macfuns"))
def test_macfun_contract(info: PluginInfo) -> None:
    macfun: Macfun = info.obj
    pack = get_plugins().machine(macfun.machine)
    assert pack is not None, f"MACFUN {macfun.name} names machine {macfun.machine}, not installed"
    assert pack.load().option(133) == 1.0, "option 133 must enable the machine's MACFUN"
    assert macfun.handlers and all(isinstance(p, HookPoint) for p in macfun.handlers)
    assert all(callable(h) for h in macfun.handlers.values())
