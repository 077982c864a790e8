"""The contract shared by the numbered families (spindle types, feed types, transform
classes, printouts): a manual number within the selecting option's range, a name, the
manual section it implements, and a module docstring that cites it."""

from __future__ import annotations

import importlib

from gecent.core.families import FAMILY_BY_NAME, NumberedPlugin
from gecent.core.plugins import PluginInfo, get_plugins


def check_numbered_plugin(family: str, info: PluginInfo) -> None:
    spec = FAMILY_BY_NAME[family]
    plugin = info.obj
    assert isinstance(plugin, NumberedPlugin)
    assert spec.numbers is not None and plugin.number in spec.numbers
    assert info.key == plugin.number
    assert plugin.name and plugin.section.startswith("§")
    module = importlib.import_module(info.module)
    assert module.__doc__ and "§" in module.__doc__, "the module docstring cites the manual"


def check_family_loads(family: str) -> None:
    plugins = get_plugins()
    assert plugins.failures == []
    keys = list(plugins.family(family))
    assert len(keys) == len(set(keys))
