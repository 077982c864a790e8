"""The macro layer (spec 09): event macros, user-defined macros matched by their syntax
definition line, look-ahead. A pack registers :class:`Macro` objects with the
``register_macros`` hook; docs/macros.md shows how. (What a macro body gets, ``ctx``, is
:class:`gecent.core.macros.context.MacroContext`.)

This package's ``__init__`` imports the model alone: the machine loader reads macros from
machine files, and must not pull in the engine (which sits above the machine)."""

from gecent.core.macros.model import Kind, Macro, MacroError, Macros, Phase

__all__ = ["Kind", "Macro", "MacroError", "Macros", "Phase"]
