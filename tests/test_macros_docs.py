"""docs/macros.md's examples are complete and runnable: each Python or machine-file example
posts its input to exactly its output."""

from __future__ import annotations

import re
import sys
import types
from pathlib import Path

import pytest
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.families import MachinePack
from gecent.core.output.tape import tape_image
from gecent.core.plugins import (
    PluginInfo,
    PluginSet,
    _entry_point_modules,
    _Source,
    build_plugin_set,
)
from gecent.core.run import Run

from .conftest import ROOT

DOC = ROOT / "docs" / "macros.md"
PACK = ROOT / "examples" / "packs" / "acme-mill"
_EXAMPLE = re.compile(r"<!-- example: (\w+)(?: ([\w-]+))? -->\n```\w*\n(.*?)```", re.DOTALL)


def examples() -> list[tuple[str, str, str, str, str]]:
    """(kind, machine, source, input, output) of each example, in order."""
    found = _EXAMPLE.findall(DOC.read_text(encoding="utf-8"))
    made = []
    for index in range(0, len(found), 3):
        (kind, machine, source), (_, _, given), (_, _, expected) = found[index : index + 3]
        made.append((kind, machine, source, given, expected))
    return made


def test_the_doc_has_its_three_examples() -> None:
    assert [kind for kind, *_ in examples()] == ["python", "python", "machine"]
    # the second is the acme-mill pack's macros.py, as shipped
    assert examples()[1][2] == (PACK / "acme_mill" / "macros.py").read_text(encoding="utf-8")


@pytest.mark.parametrize("example", examples(), ids=lambda e: f"{e[0]}-{e[1] or 'file'}")
def test_a_doc_example_posts_as_shown(example: tuple[str, str, str, str, str]) -> None:
    kind, machine, source, given, expected = example
    modules, failures = _entry_point_modules()
    sys.path.insert(0, str(PACK))
    try:
        import acme_mill.machine

        modules.append((acme_mill.machine, _Source("acme", "acme-mill", "1.0.0")))
        if kind == "python":
            module = types.ModuleType("doc_example")
            exec(compile(source, str(DOC), "exec"), module.__dict__)
            modules.append((module, _Source("doc_example", "my-shop", "")))
        plugins: PluginSet = build_plugin_set(modules, failures)
    finally:
        sys.path.remove(str(PACK))
    assert plugins.failures == []
    if kind == "machine":
        pack = MachinePack.from_text(source, str(Path("shop-mill.toml")))
        plugins.family("machines")[pack.name] = PluginInfo(
            "machines", pack.name, pack.name, "(doc)", "", "doc", pack
        )
        machine = pack.name
    pack = plugins.machine(machine)
    assert pack is not None
    result = Run(pack.load(), plugins).process(
        AptSourceReader("doc.apt").read_lines(given.splitlines(keepends=True))
    )
    assert tape_image(result.blocks) == expected
    assert [d.text for d in result.diagnostics] == []


def _cli(*args: str):  # type: ignore[no-untyped-def]
    from click.testing import CliRunner
    from gecent.core.cli import main

    return CliRunner().invoke(main, list(args))


def test_gecent_post_takes_a_macro_file(tmp_path: Path) -> None:
    """The first example as a file of its own, tried with ``gecent post --macros``."""
    _, machine, source, given, expected = examples()[0]
    (tmp_path / "shop.py").write_text(source)
    (tmp_path / "probe.apt").write_text(given)
    tape = tmp_path / "probe.tape"
    done = _cli("post", str(tmp_path / "probe.apt"), "--machine", machine,
                "--macros", str(tmp_path / "shop.py"), "-o", str(tape))  # fmt: skip
    assert done.exit_code == 0, done.output
    assert tape.read_text() == expected


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("def broken(:\n", "shop.py:1"),
        ("x = 1\n", "registers no macro"),
        ("import no_such_module_here\n", "ModuleNotFoundError"),
        ("from gecent.core.macros import Macros\nm = Macros()\nm.ignore('COOLNT/[')\n", "SDL"),
    ],
)
def test_a_bad_macro_file_is_bad_input(tmp_path: Path, text: str, message: str) -> None:
    (tmp_path / "shop.py").write_text(text)
    (tmp_path / "p.apt").write_text("PARTNO P\nFINI\n")
    done = _cli("post", str(tmp_path / "p.apt"), "--machine", "linuxcnc-mill",
                "--macros", str(tmp_path / "shop.py"), "-o", str(tmp_path / "p.tape"))  # fmt: skip
    assert done.exit_code == 2 and message in done.output
    assert not (tmp_path / "p.tape").exists()
