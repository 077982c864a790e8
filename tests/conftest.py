from __future__ import annotations

from pathlib import Path

import pytest
from gecent.core.plugins import PluginSet, get_plugins

ROOT = Path(__file__).resolve().parent.parent
SHARED = ROOT.parent / "shared"
DATA = Path(__file__).resolve().parent / "data"
MACHINES = ROOT / "plugins" / "machines"
# the packs for modern controls (docs/modern-controls.md)
MODERN_PACKS = (
    "linuxcnc-mill",
    "linuxcnc-mill-inch",
    "fanuc-mill",
    "fanuc-lathe",
    "haas-mill",
    "sinumerik-840d-iso",
)


@pytest.fixture(scope="session")
def plugins() -> PluginSet:
    return get_plugins()
