"""Contract: every registered macro, and every macro of an installed machine's file, is a
well-formed Macro for an installed machine (or all of them) and runs in a short program on
its machine without an error."""

from __future__ import annotations

import pytest
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.macros import Kind, Macro, Phase
from gecent.core.plugins import get_plugins
from gecent.core.run import Run

pytestmark = pytest.mark.contract

PROGRAM = (
    "PARTNO CONTRACT\nFROM/0,0,1\nLOADTL/1\nSPINDL/300,CLW\nFEDRAT/10\nGOTO/1,0,0\n"
    "LOADTL/2\nGOTO/1,1,0\nFINI\n"
)


def every_macro() -> list[tuple[str, Macro]]:
    plugins = get_plugins()
    found = [(info.distribution, info.obj) for info in plugins.family("macros").values()]
    for pack in plugins.machines():
        found.extend((pack.origin, macro) for macro in pack.load().macros)
    return found


@pytest.mark.parametrize(("origin", "macro"), every_macro(), ids=lambda v: getattr(v, "key", ""))
def test_macro_contract(origin: str, macro: Macro) -> None:
    plugins = get_plugins()
    assert isinstance(macro, Macro) and macro.key == f"{macro.machine}:{macro.name}"
    if macro.kind is Kind.SYNTAX:
        assert macro.parsed is not None and macro.phase is Phase.EVENT
    else:
        assert callable(macro.body)
    machines = [p.name for p in plugins.machines()] if macro.machine == "*" else [macro.machine]
    for name in machines[:3]:
        pack = plugins.machine(name)
        assert pack is not None, f"{macro.key} ({origin}) names machine {name}, not installed"
        run = Run(pack.load(), plugins)
        run.process(AptSourceReader("contract.apt").read_lines(PROGRAM.splitlines(True)))
