"""Contract: every registered CL reader sniffs its own format and streams records."""

from __future__ import annotations

import inspect

import pytest
from gecent.core.families import ClReader
from gecent.core.plugins import PluginInfo

from .conftest import plugin_params

pytestmark = pytest.mark.contract


@pytest.mark.parametrize("info", **plugin_params("readers"))
def test_reader_contract(info: PluginInfo) -> None:
    reader = info.obj
    assert isinstance(reader, ClReader)
    assert reader.name == info.key and reader.description
    assert isinstance(reader.sniff(b""), bool)
    assert not reader.sniff(b"\x00\x00\x00\x10\x00\x00")
    assert callable(reader.read) and not inspect.isclass(reader)
