"""Macros from packs and machine files: the acme-mill example pack's tool-change sequence,
staged next tool and tool header; macros written in a machine file (Jinja templates); the
layers (user pack over machine pack over built-in); macros in ``--list-plugins``."""

from __future__ import annotations

import importlib
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.errors import InputError
from gecent.core.families import MachinePack
from gecent.core.machine.loader import load_machine_text
from gecent.core.macros import Kind, Macros, Phase
from gecent.core.macros.table import MacroTable, with_macros
from gecent.core.output.block import Code
from gecent.core.output.tape import tape_image
from gecent.core.plugins import PluginSet, _entry_point_modules, _Source, build_plugin_set
from gecent.core.run import Run

from .conftest import ROOT

PACK = ROOT / "examples" / "packs" / "acme-mill"
PROGRAM = """PARTNO ACME
FROM/0,0,10
LOADTL/1
SPINDL/1350,CLW
COOLNT/MIST
FEDRAT/10
OPTYPE/MILL,FINISH
GOTO/1,0,0
LOADTL/2
SPINDL/900,CLW
GOTO/2,0,0
FINI
"""


@pytest.fixture(scope="module")
def acme() -> Iterator[PluginSet]:
    sys.path.insert(0, str(PACK))
    try:
        modules, failures = _entry_point_modules()
        for name in ("acme_mill.machine", "acme_mill.macfun", "acme_mill.macros"):
            modules.append((importlib.import_module(name), _Source(name, "acme-mill", "1.0.0")))
        yield build_plugin_set(modules, failures)
    finally:
        sys.path.remove(str(PACK))


def post(plugins: PluginSet, text: str, machine: str = "acme-vmc1") -> tuple[str, list[str]]:
    """The tape image with the PPRINT lines (listing only) in it as comments, and the
    warnings."""
    pack = plugins.machine(machine)
    assert pack is not None
    result = Run(pack.load(), plugins).process(
        AptSourceReader("acme.apt").read_lines(text.splitlines(keepends=True))
    )
    lines = []
    for block in result.blocks:
        if block.code is Code.PPRINT:
            lines.append(f"({block.text})\n")
        else:
            lines.append(tape_image([block]))
    return "".join(lines), [d.text for d in result.diagnostics]


def test_the_acme_pack_posts_its_tool_changes_with_its_macros(acme: PluginSet) -> None:
    tape, warnings = post(acme, PROGRAM)
    lines = tape.splitlines()
    assert "G53Z0" in lines  # the head up before each change
    assert "(TOOL 1 - NEXT T2)" in lines and "(TOOL 2 - LAST TOOL)" in lines
    staged = lines.index("(TOOL 1 - NEXT T2)") + 1
    assert lines[staged] == "T2"
    assert sum(line == "T2" for line in lines) == 1  # nothing staged after the last tool
    # the machine file's macro: a dwell after the mist
    mist = next(line for line in lines if "M07" in line)
    assert mist.startswith("N005G04X+00015")  # M07 rides in the dwell block (STOREM)
    assert "(MILL FINISH S1350 F10)" in lines  # the operation header (listing)
    assert warnings == []


def test_the_acme_macros_are_listed_with_their_machine(acme: PluginSet) -> None:
    listed = {key: info for key, info in acme.family("macros").items()}
    assert {
        "acme-vmc1:tool_change",
        "acme-vmc1:stage_next_tool",
        "acme-vmc1:operation_header",
    } <= set(listed)
    assert listed["acme-vmc1:tool_change"].distribution == "acme-mill"
    pack = acme.machine("acme-vmc1")
    assert pack is not None
    assert [m.key for m in pack.load().macros] == ["acme-vmc1:mist-settles"]


def test_a_user_macro_takes_the_place_of_the_machine_packs(acme: PluginSet) -> None:
    mine = Macros(machine="acme-vmc1")

    @mine.event(Kind.TOOL_CHANGE, Phase.STARTUP)
    def my_change(ctx):  # type: ignore[no-untyped-def]
        ctx.insert("(MY CHANGE)")

    plugins = with_macros(acme, mine.macros, distribution="my-shop")
    pack = plugins.machine("acme-vmc1")
    assert pack is not None
    table = MacroTable.for_machine(plugins, pack.load())
    assert table is not None
    assert table.event(Kind.TOOL_CHANGE, Phase.STARTUP) is mine.macros[0]
    assert [p.macro.key for p in table.shadowed] == ["acme-vmc1:tool_change"]
    tape, _ = post(plugins, PROGRAM)
    assert "(MYCHANGE)" in tape and "G53Z0" not in tape
    assert "(TOOL 1 - NEXT T2)" in tape  # the pack's shutdown macro still runs


MACHINE = """
[machine]
name = "templated"
title = "TEMPLATED"

[optab]
default_coolant = 3.0

[[macros]]
name = "no-pen"
sdl = "PENUP"

[[macros]]
name = "mist"
sdl = "COOLNT/$P1(MIST)"
body = ["COOLNT/FLOOD", "INSERT/(MIST ASKED AT {{ record.line }})"]

[[macros]]
name = "header"
event = "tool-change"
phase = "shutdown"
body = [
  "PPRINT/TOOL {{ p.tool_id|int }} OF {{ globals.get('tools', '?') }}",
  "{% if next.tool is not none %}INSERT/T{{ next.tool|int }}{% endif %}",
]

[[macros]]
name = "count"
event = "machine"
phase = "startup"
body = ["{% set _ = globals.update(tools=2) %}"]
"""


def templated() -> MachinePack:
    return MachinePack.from_text(MACHINE, "templated.toml")


def test_machine_file_macros_render_their_templates() -> None:
    plugins = _plugins().copy()
    plugins.family("machines")["templated"] = _info(templated())
    tape, warnings = post(
        plugins,
        "PARTNO T\nFROM/0,0,1\nFEDRAT/10\nPENUP\nLOADTL/1\nCOOLNT/MIST\nGOTO/1,0,0\n"
        "LOADTL/2\nFINI\n",
        "templated",
    )
    lines = tape.splitlines()
    assert "(TOOL 1 OF 2)" in lines and "(TOOL 2 OF 2)" in lines
    assert lines[lines.index("(TOOL 1 OF 2)") + 1] == "T2"
    assert "(MISTASKEDAT6)" in lines  # INSERT punches without blanks (PPRINT: listing only)
    assert warnings == []


@pytest.mark.parametrize(
    ("entry", "message"),
    [
        ('name = "x"\nsdl = "PENUP"\nevent = "machine"', "either an sdl"),
        ('name = "x"\nevent = "tool-change"\nbody = ["STOP"]', 'phase = "startup"'),
        ('name = "x"\nevent = "tape"\nphase = "startup"\nbody = ["STOP"]', "has no phase"),
        ('name = "x"\nevent = "lunch"\nbody = ["STOP"]', "event 'lunch' is not one of"),
        ('name = "x"\nsdl = "COOLNT/[$P1"', "column"),
        ('name = "x"\nsdl = "STOP"\nbody = ["{% if %}"]', "body line"),
    ],
)
def test_a_bad_machine_file_macro_names_the_file_table_and_entry(entry: str, message: str) -> None:
    text = f'[machine]\nname = "bad"\n\n[[macros]]\n{entry}\n'
    with pytest.raises(InputError) as refused:
        load_machine_text(text, "bad.toml")
    shown = str(refused.value)
    assert "bad.toml" in shown and "[macros] entry x" in shown and message in shown


def test_an_undefined_template_name_is_named_with_its_macro() -> None:
    text = MACHINE.replace("globals.get('tools', '?')", "no_such_name")
    plugins = _plugins().copy()
    plugins.family("machines")["templated"] = _info(MachinePack.from_text(text, "t.toml"))
    with pytest.raises(
        InputError, match=r"macro templated:header: line .*'no_such_name' is undefined"
    ):
        post(plugins, "PARTNO T\nFROM/0,0,1\nLOADTL/1\nFINI\n", "templated")


def _plugins() -> PluginSet:
    from gecent.core.plugins import get_plugins

    return get_plugins()


def _info(pack: MachinePack):  # type: ignore[no-untyped-def]
    from gecent.core.plugins import PluginInfo

    return PluginInfo("machines", pack.name, pack.name, "(test)", "", "tests", pack)


def test_no_macros_no_engine() -> None:
    """A machine no macro serves runs without the macro engine (the post's own path)."""
    pack = _plugins().machine("linuxcnc-mill")
    assert pack is not None
    assert Run(pack.load(), _plugins()).macros is None
    assert MacroTable.for_machine(_plugins(), pack.load()) is None
    assert Path(ROOT / "core" / "macros").is_dir()


def test_machine_show_lists_a_machine_files_macros(tmp_path: Path) -> None:
    from click.testing import CliRunner
    from gecent.core.cli import main

    path = tmp_path / "templated.toml"
    path.write_text(MACHINE)
    shown = CliRunner().invoke(main, ["machine", "show", str(path)])
    assert shown.exit_code == 0
    assert (
        "  mist: COOLNT/$P1(MIST)" in shown.output
        and "  header: tool-change shutdown" in shown.output
    )
