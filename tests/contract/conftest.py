"""Contract tests run over every plugin a family has registered, built-in or third-party,
so a new plugin is tested without new test code (``tox -e <family>`` runs one family)."""

from __future__ import annotations

from typing import Any

from gecent.core.plugins import PluginInfo, get_plugins


def registered(family: str) -> list[PluginInfo]:
    return list(get_plugins().family(family).values())


def ids(infos: list[PluginInfo]) -> list[str]:
    return [f"{info.key}" for info in infos]


def plugin_params(family: str) -> dict[str, Any]:
    infos = registered(family)
    return {"argvalues": infos, "ids": ids(infos)}
