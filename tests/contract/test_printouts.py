"""Contract: every registered printouts plugin."""

from __future__ import annotations

import pytest
from gecent.core.plugins import PluginInfo

from .conftest import plugin_params
from .numbered import check_family_loads, check_numbered_plugin

pytestmark = pytest.mark.contract


def test_family_loads() -> None:
    check_family_loads("printouts")


@pytest.mark.parametrize("info", **plugin_params("printouts"))
def test_plugin_contract(info: PluginInfo) -> None:
    check_numbered_plugin("printouts", info)


@pytest.mark.parametrize("info", **plugin_params("printouts"))
def test_printout_renders_a_titled_listing(info: PluginInfo) -> None:
    from gecent.core.machine import standard_machine
    from gecent.core.output.block import Block, Code

    blocks = [Block(Code.PARTNO, 1, "PART 1"), Block(Code.PPRINT, 2, "HELLO")]
    text = info.obj.render(standard_machine(), blocks, "PART 1")
    assert "GECENT III" in text and "PART 1" in text and "HELLO" in text
