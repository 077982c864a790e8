"""The macro layer (spec 09): event macros, user-defined macros matched by their syntax
definition line, look-ahead. A pack registers :class:`Macro` objects with the
``register_macros`` hook; docs/macros.md shows how."""

from gecent.core.macros.context import MacroContext, NextMotion
from gecent.core.macros.model import Kind, Macro, MacroError, Macros, Phase

__all__ = ["Kind", "Macro", "MacroContext", "MacroError", "Macros", "NextMotion", "Phase"]
