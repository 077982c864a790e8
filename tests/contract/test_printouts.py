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


@pytest.mark.parametrize("info", **plugin_params("printouts"))
def test_printout_pages_stream_as_it_renders(info: PluginInfo) -> None:
    """The page maker the listing sink drives gives the same text as ``render``, whatever
    the number of pages (a page holds option 79 lines)."""
    from gecent.core.machine import standard_machine
    from gecent.core.output.block import Block, Code
    from gecent.core.output.tape import tape_line

    machine = standard_machine()
    blocks = [Block(Code.PARTNO, 1, "PART 1")]
    blocks += [Block(Code.PPRINT, n, f"NOTE {n}") for n in range(2, 200)]
    pages = info.obj.listing(machine, lambda: "PART 1")
    streamed = "".join(pages.block(block, tape_line(block)) for block in blocks)
    streamed += "".join(pages.finish())
    assert streamed == info.obj.render(machine, blocks, "PART 1")
    assert streamed.count("PAGE ") > 1
