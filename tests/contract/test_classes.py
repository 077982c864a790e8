"""Contract: every registered classes plugin."""

from __future__ import annotations

import pytest
from gecent.core.plugins import PluginInfo

from .conftest import plugin_params
from .numbered import check_family_loads, check_numbered_plugin

pytestmark = pytest.mark.contract


def test_family_loads() -> None:
    check_family_loads("classes")


@pytest.mark.parametrize("info", **plugin_params("classes"))
def test_plugin_contract(info: PluginInfo) -> None:
    check_numbered_plugin("classes", info)
