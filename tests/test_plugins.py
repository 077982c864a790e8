"""Plugin loading: broken plugins are reported by name and never stop gecent."""

from __future__ import annotations

import sys
from importlib.metadata import EntryPoint
from pathlib import Path

import pytest
from gecent.core import plugins as plugin_module
from gecent.core.plugins import build_plugin_set, load_module_plugins

DATA = Path(__file__).resolve().parent / "data" / "plugins"


def test_builtin_plugins_each_have_their_own_entry_point() -> None:
    plugins = plugin_module.get_plugins()
    modules = {info.module for info in plugins.all()}
    assert len(modules) == len(plugins.all())
    assert {info.distribution for info in plugins.all()} == {"gecent"}
    assert {p.number for p in plugins.machines() if p.number} >= {4, 23, 24, 40, 51}


def test_failing_plugins_are_reported_by_name(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.syspath_prepend(str(DATA))
    points = [
        EntryPoint("broken_import", "broken_import", "gecent"),
        EntryPoint("broken_register", "broken_register", "gecent"),
        EntryPoint("missing_module", "no_such_module_anywhere", "gecent"),
        EntryPoint("machine_mach23", "gecent.plugins.machines.mach23", "gecent"),
    ]
    monkeypatch.setattr(plugin_module, "entry_points", lambda group: points)
    modules, failures = plugin_module._entry_point_modules()
    plugins = build_plugin_set(modules, failures)
    errors: dict[str, list[str]] = {}
    for failure in plugins.failures:
        errors.setdefault(failure.entry_point, []).append(failure.error)
    assert "not installed" in errors["broken_import"][0]
    assert "no_such_module_anywhere" in errors["missing_module"][0]
    assert any("printout template missing" in e for e in errors["broken_register"])
    assert any("option 19 allows 0..6, 8..20" in e for e in errors["broken_register"])
    assert plugins.machine(23) is not None
    sys.modules.pop("broken_import", None)
    sys.modules.pop("broken_register", None)


def test_duplicate_registration_keeps_the_first() -> None:
    plugins = load_module_plugins(
        "gecent.plugins.machines.mach23", "gecent.plugins.machines.mach23"
    )
    assert len(plugins.machines()) == 1


def test_every_package_folder_is_listed_in_pyproject() -> None:
    """A folder missing from [tool.setuptools] packages installs fine in editable mode and
    breaks every non-editable install: keep the list complete."""
    import tomllib

    from .conftest import ROOT

    listed = set(
        tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["setuptools"]["packages"]
    )
    found = {
        "gecent." + ".".join(path.parent.relative_to(ROOT).parts)
        for top in ("core", "plugins")
        for path in (ROOT / top).rglob("__init__.py")
    }
    assert found <= listed, f"add to pyproject packages: {sorted(found - listed)}"
