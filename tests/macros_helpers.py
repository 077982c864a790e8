"""Posting APT text with macros (tests of the macro layer)."""

from __future__ import annotations

from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.cl.records import Record
from gecent.core.macros import Macro, Macros
from gecent.core.macros.table import with_macros
from gecent.core.output.tape import tape_image
from gecent.core.plugins import PluginSet, get_plugins
from gecent.core.run import Run
from gecent.core.state import RunResult


def records(text: str, file: str = "test.apt") -> list[Record]:
    return list(AptSourceReader(file).read_lines(text.splitlines(keepends=True)))


def record(text: str) -> Record:
    return records(text)[0]


def post(
    text: str,
    macros: Macros | list[Macro] | None,
    machine: str = "linuxcnc-mill",
    fast: bool = True,
    plugins: PluginSet | None = None,
) -> tuple[str, RunResult]:
    """The tape image and the result of posting ``text`` with the macros."""
    listed = [] if macros is None else macros.macros if isinstance(macros, Macros) else macros
    plugins = with_macros(plugins or get_plugins(), listed)
    pack = plugins.machine(machine)
    assert pack is not None
    run = Run(pack.load(), plugins, fast=fast)
    result = run.process(iter(records(text)))
    return tape_image(result.blocks), result


def warnings(result: RunResult) -> list[str]:
    return [d.text for d in result.diagnostics]
