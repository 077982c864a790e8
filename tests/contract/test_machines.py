"""Contract: every registered machine loads, passes the checklist and is selectable."""

from __future__ import annotations

import pytest
from gecent.core.families import MachinePack
from gecent.core.machine.rules import check_definition
from gecent.core.plugins import PluginInfo, get_plugins

from .conftest import plugin_params

pytestmark = pytest.mark.contract


@pytest.mark.parametrize("info", **plugin_params("machines"))
def test_machine_contract(info: PluginInfo) -> None:
    pack: MachinePack = info.obj
    machine = pack.load()
    assert (machine.name, machine.number) == (pack.name, pack.number)
    assert len(machine.title) <= 36
    errors, _ = check_definition(machine)
    assert errors == []
    assert get_plugins().machine(pack.name) is pack
    if pack.number is not None:
        assert 1 <= pack.number <= 99
        assert get_plugins().machine(str(pack.number)) is pack


def test_machine_numbers_are_unique() -> None:
    numbers = [p.number for p in get_plugins().machines() if p.number is not None]
    assert len(numbers) == len(set(numbers))
