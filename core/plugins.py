"""Load every plugin from the ``gecent`` entry-point group, built-in and third-party alike.

A plugin that fails to import or to register is reported by name and skipped; it never
stops the program. Each registered thing is recorded with the family, key, module and
distribution it came from, which is what ``gecent --list-plugins`` prints.
"""

from __future__ import annotations

import importlib
from collections.abc import Iterable
from dataclasses import dataclass, field
from functools import cache
from importlib.metadata import EntryPoint, entry_points
from types import ModuleType
from typing import TYPE_CHECKING, Any

import pluggy
from gecent.core import hookspecs
from gecent.core.families import FAMILIES, FamilySpec, HookPoint, Macfun, MacfunHandler, MachinePack

if TYPE_CHECKING:
    from gecent.core.machine.definition import MachineDefinition

GROUP = "gecent"


@dataclass(frozen=True)
class PluginInfo:
    family: str
    key: str | int
    name: str
    distribution: str
    version: str
    module: str
    obj: Any = field(repr=False, compare=False)


@dataclass(frozen=True)
class PluginFailure:
    """An entry point (or one of its registrations) that could not be used."""

    entry_point: str
    distribution: str
    error: str


@dataclass
class PluginSet:
    """Everything registered, by family and key, plus what failed."""

    by_family: dict[str, dict[str | int, PluginInfo]] = field(default_factory=dict)
    failures: list[PluginFailure] = field(default_factory=list)

    def family(self, name: str) -> dict[str | int, PluginInfo]:
        return self.by_family.setdefault(name, {})

    def copy(self) -> PluginSet:
        """A set of its own to add to (the plugins themselves shared)."""
        return PluginSet(
            {family: dict(found) for family, found in self.by_family.items()},
            list(self.failures),
        )

    def all(self) -> list[PluginInfo]:
        return [info for family in FAMILIES for info in self.family(family.name).values()]

    def get(self, family: str, key: str | int) -> Any | None:
        info = self.family(family).get(key)
        return None if info is None else info.obj

    def machines(self) -> list[MachinePack]:
        return [info.obj for info in self.family("machines").values()]

    def machine(self, key: str | int) -> MachinePack | None:
        """A machine by number (MACHIN/GECENT,n) or by name."""
        text = str(key).strip()
        for pack in self.machines():
            if pack.name == text.lower() or (
                pack.number is not None and text.isdigit() and pack.number == int(text)
            ):
                return pack
        return None


@dataclass(frozen=True)
class _Source:
    name: str
    distribution: str
    version: str


def _key(family: FamilySpec, obj: Any) -> str | int:
    key = getattr(obj, family.key, None)
    if key is None:
        raise TypeError(f"{family.name} plugin {obj!r} has no {family.key!r}")
    if family.numbers is not None and key not in family.numbers:
        raise ValueError(
            f"{family.name} plugin {getattr(obj, 'name', obj)!r} has number {key}; "
            f"option {family.option} allows {_spans(family.numbers)}"
        )
    return key  # type: ignore[no-any-return]


def _spans(numbers: frozenset[int]) -> str:
    """0..6, 8..19: the allowed numbers as runs."""
    runs: list[list[int]] = []
    for number in sorted(numbers):
        if runs and number == runs[-1][1] + 1:
            runs[-1][1] = number
        else:
            runs.append([number, number])
    return ", ".join(f"{a}..{b}" if a != b else str(a) for a, b in runs)


def _register_family(
    manager: pluggy.PluginManager,
    family: FamilySpec,
    sources: dict[str, _Source],
    plugins: PluginSet,
) -> None:
    caller = getattr(manager.hook, family.hook)
    for impl in caller.get_hookimpls():
        source = sources[impl.plugin_name]
        registered: list[Any] = []
        try:
            impl.function(register=registered.append)
        except Exception as exc:  # a third-party plugin's bug must not stop gecent
            plugins.failures.append(
                PluginFailure(source.name, source.distribution, f"{family.hook}: {exc}")
            )
            continue
        for obj in registered:
            try:
                key = _key(family, obj)
            except (TypeError, ValueError) as exc:
                plugins.failures.append(PluginFailure(source.name, source.distribution, str(exc)))
                continue
            existing = plugins.family(family.name).get(key)
            if existing is not None:
                plugins.failures.append(
                    PluginFailure(
                        source.name,
                        source.distribution,
                        f"{family.name} {key!r} is already registered by {existing.module} "
                        f"({existing.distribution}); this one is ignored",
                    )
                )
                continue
            plugins.family(family.name)[key] = PluginInfo(
                family=family.name,
                key=key,
                name=str(getattr(obj, "name", key)),
                distribution=source.distribution,
                version=source.version,
                module=getattr(impl.plugin, "__name__", impl.plugin_name),
                obj=obj,
            )


def build_plugin_set(
    modules: Iterable[tuple[ModuleType, _Source]], failures: Iterable[PluginFailure] = ()
) -> PluginSet:
    manager = pluggy.PluginManager(hookspecs.PROJECT)
    manager.add_hookspecs(hookspecs)
    plugins = PluginSet(failures=list(failures))
    sources: dict[str, _Source] = {}
    for module, source in modules:
        try:
            manager.register(module, name=source.name)
        except (ValueError, pluggy.PluginValidationError) as exc:
            plugins.failures.append(PluginFailure(source.name, source.distribution, str(exc)))
            continue
        sources[source.name] = source
    for family in FAMILIES:
        _register_family(manager, family, sources, plugins)
    return plugins


def _entry_point_modules() -> tuple[list[tuple[ModuleType, _Source]], list[PluginFailure]]:
    modules: list[tuple[ModuleType, _Source]] = []
    failures: list[PluginFailure] = []
    names: dict[int, str] = {}

    def distribution(point: EntryPoint) -> str:
        if point.dist is None:
            return ""
        if id(point.dist) not in names:
            names[id(point.dist)] = point.dist.name
        return names[id(point.dist)]

    points: list[EntryPoint] = sorted(
        entry_points(group=GROUP), key=lambda ep: (distribution(ep), ep.name)
    )
    seen: set[str] = set()
    # a distribution's name and version come from parsing its METADATA: once each
    described: dict[int, tuple[str, str]] = {}
    for point in points:
        if point.dist is None:
            dist, version = "(unknown)", ""
        else:
            if id(point.dist) not in described:
                described[id(point.dist)] = (point.dist.name, point.dist.version)
            dist, version = described[id(point.dist)]
        if point.name in seen:  # the same distribution seen twice on sys.path
            continue
        seen.add(point.name)
        try:
            loaded = point.load()
        except Exception as exc:  # report by name; never crash on a broken plugin
            failures.append(PluginFailure(point.name, dist, f"cannot import {point.value}: {exc}"))
            continue
        if not isinstance(loaded, ModuleType):
            failures.append(PluginFailure(point.name, dist, f"{point.value} is not a module"))
            continue
        modules.append((loaded, _Source(point.name, dist, version)))
    return modules, failures


def load_module_plugins(*names: str) -> PluginSet:
    """Build a plugin set from named modules only (used by tests and scripts)."""
    modules = [(importlib.import_module(name), _Source(name, "(local)", "")) for name in names]
    return build_plugin_set(modules)


@cache
def get_plugins() -> PluginSet:
    """All plugins installed in this environment (loaded once per process)."""
    modules, failures = _entry_point_modules()
    return build_plugin_set(modules, failures)


def macfun_handler(
    plugins: PluginSet, machine: MachineDefinition, point: HookPoint
) -> MacfunHandler | None:
    """The machine's own MACFUN code for a hook point (option 133 = 1), or None."""
    if machine.number_option(133) != 1:
        return None
    for info in plugins.family("macfuns").values():
        macfun: Macfun = info.obj
        if macfun.machine == machine.name and point in macfun.handlers:
            return macfun.handlers[point]
    return None
