"""Contract: every registered spindles plugin."""

from __future__ import annotations

import pytest
from gecent.core.plugins import PluginInfo

from .conftest import plugin_params
from .numbered import check_family_loads, check_numbered_plugin

pytestmark = pytest.mark.contract


def test_family_loads() -> None:
    check_family_loads("spindles")


@pytest.mark.parametrize("info", **plugin_params("spindles"))
def test_plugin_contract(info: PluginInfo) -> None:
    check_numbered_plugin("spindles", info)
