"""The macros one run uses (spec 09 §13.1): those registered for its machine (or for every
machine), layered user pack first, then the machine's own pack, then gecent's built-ins.

* An event takes the first layer's macro for each (kind, phase); within a layer the first
  registered. The others are shadowed (``--list-plugins`` says so).
* User-defined macros are all candidates, in the SDL search order of §6.2 (``#*:*``,
  ``#class:*``, ``#*:subclass``, then exact SDLs), then by layer, then registration order.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from gecent.core.families import HookPoint, MacfunHandler
from gecent.core.macros.macfun import macfun_handlers
from gecent.core.macros.model import Kind, Macro, Phase
from gecent.core.macros.sdl import Key, record_key

if TYPE_CHECKING:
    from gecent.core.cl.records import Record
    from gecent.core.machine.definition import MachineDefinition
    from gecent.core.plugins import PluginSet

BUILT_IN = "gecent"
USER, MACHINE_PACK, BUILT_IN_LAYER = 0, 1, 2
LAYER_NAMES = {USER: "user pack", MACHINE_PACK: "machine pack", BUILT_IN_LAYER: "built-in"}


def with_macros(
    plugins: PluginSet, macros: list[Macro], distribution: str = "(local)"
) -> PluginSet:
    """The plugins plus macros from outside any pack (a script, a test): a user layer."""
    from gecent.core.plugins import PluginInfo

    extended = plugins.copy()
    family = extended.family("macros")
    for macro in macros:
        if macro.key in family:
            raise ValueError(f"macro {macro.key!r} is registered twice")
        family[macro.key] = PluginInfo(
            "macros", macro.key, macro.name, distribution, "", distribution, macro
        )
    return extended


@dataclass(frozen=True)
class Placed:
    macro: Macro
    layer: int
    order: int
    distribution: str


@dataclass
class MacroTable:
    events: dict[tuple[Kind, Phase], Placed] = field(default_factory=dict)
    syntax: list[Placed] = field(default_factory=list)
    shadowed: list[Placed] = field(default_factory=list)
    # the machine's MACFUN handlers at the engine's hook points (core/macros/macfun.py)
    macfuns: dict[HookPoint, MacfunHandler] = field(default_factory=dict)
    _by_key: dict[Key, tuple[Macro, ...]] = field(default_factory=dict, repr=False)

    def event(self, kind: Kind, phase: Phase) -> Macro | None:
        placed = self.events.get((kind, phase))
        return None if placed is None else placed.macro

    def has(self, kind: Kind) -> bool:
        return any(k is kind for k, _ in self.events)

    def candidates(self, record: Record) -> tuple[Macro, ...]:
        """The user-defined macros whose SDL major covers the record, in search order."""
        key = record_key(record)
        if key is None:
            return ()
        found = self._by_key.get(key)
        if found is None:
            found = tuple(
                placed.macro
                for placed in self.syntax
                if placed.macro.parsed is not None and placed.macro.parsed.covers(key)
            )
            self._by_key[key] = found
        return found

    def covers(self, key: Key) -> bool:
        return any(p.macro.parsed is not None and p.macro.parsed.covers(key) for p in self.syntax)

    @classmethod
    def build(cls, placed: list[Placed]) -> MacroTable:
        table = cls()
        for item in sorted(placed, key=lambda p: (p.layer, p.order)):
            macro = item.macro
            if macro.kind is Kind.SYNTAX:
                table.syntax.append(item)
            elif macro.slot in table.events:
                table.shadowed.append(item)
            else:
                table.events[macro.slot] = item
        table.syntax.sort(
            key=lambda p: (p.macro.parsed.level if p.macro.parsed else 3, p.layer, p.order)
        )
        return table

    @classmethod
    def for_machine(
        cls, plugins: PluginSet, machine: MachineDefinition, extra: list[Macro] | None = None
    ) -> MacroTable | None:
        """The table of the machine, or None when no macro serves it (the run then takes
        no macro path at all)."""
        machine_info = plugins.family("machines").get(machine.name)
        machine_distribution = machine_info.distribution if machine_info is not None else None
        placed: list[Placed] = []
        for order, info in enumerate(plugins.family("macros").values()):
            macro: Macro = info.obj
            if macro.machine not in ("*", machine.name):
                continue
            if info.distribution == BUILT_IN:
                layer = BUILT_IN_LAYER
            elif info.distribution == machine_distribution:
                layer = MACHINE_PACK
            else:
                layer = USER
            placed.append(Placed(macro, layer, order, info.distribution))
        for order, macro in enumerate((*machine.macros, *(extra or ())), start=len(placed)):
            placed.append(Placed(macro, MACHINE_PACK, order, machine.origin))
        macfuns = macfun_handlers(plugins, machine)
        if not placed and not macfuns:
            return None
        table = cls.build(placed)
        table.macfuns = macfuns
        return table
