"""Hook specifications: one ``register_*`` hook per plugin family.

A plugin module implements any of these with ``@hookimpl`` and calls ``register`` once per
thing it provides, e.g.::

    from gecent.core.hookspecs import hookimpl

    @hookimpl
    def register_machines(register):
        register(MachinePack.from_package(__name__, "mach23.toml"))

Built-in plugins are registered exactly like a third-party pack's: each is a module named
by an entry point in the ``gecent`` group.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pluggy

PROJECT = "gecent"

hookspec = pluggy.HookspecMarker(PROJECT)
hookimpl = pluggy.HookimplMarker(PROJECT)

Register = Callable[[Any], None]


@hookspec
def register_machines(register: Register) -> None:
    """Register machine definitions (:class:`gecent.core.families.MachinePack`)."""


@hookspec
def register_spindle_types(register: Register) -> None:
    """Register spindle types selected by option 19 (``NumberedPlugin``)."""


@hookspec
def register_feed_types(register: Register) -> None:
    """Register positioning feed types selected by option 78 (``NumberedPlugin``)."""


@hookspec
def register_rotary_feed_types(register: Register) -> None:
    """Register positioning rotary feed types selected by option 141 (``NumberedPlugin``)."""


@hookspec
def register_transform_classes(register: Register) -> None:
    """Register multiaxis transform classes selected by option 116 (``NumberedPlugin``)."""


@hookspec
def register_printouts(register: Register) -> None:
    """Register printout layouts selected by option 164 (:class:`gecent.core.families.Printout`)."""


@hookspec
def register_macfuns(register: Register) -> None:
    """Register machine special functions, MACFUN (:class:`gecent.core.families.Macfun`)."""


@hookspec
def register_cl_readers(register: Register) -> None:
    """Register CL file readers (:class:`gecent.core.families.ClReader`)."""


@hookspec
def register_macros(register: Register) -> None:
    """Register macros: event and user-defined (:class:`gecent.core.macros.model.Macro`)."""


@hookspec
def register_dialects(register: Register) -> None:
    """Register CAM dialects (:class:`gecent.core.macros.dialect.Dialect`)."""
