"""docs/checklist.md, the table of where each feature of the manual lives, is current and
true to the tree: tools/checklist.py regenerates the same text; every module and test
docs/checklist.toml names exists; every option of options.toml is read by the code or says
why it has no effect; every fatal error of core/errors.py is raised (with a test), cannot
arise (a line in docs/decisions.md) or is named as pending in someone's work."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from types import ModuleType

import pytest

ROOT = Path(__file__).resolve().parent.parent
SPEC = ROOT.parent / "shared" / "spec"


def _tool() -> ModuleType:
    spec = importlib.util.spec_from_file_location(
        "gecent_checklist", ROOT / "tools" / "checklist.py"
    )
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up by name
    spec.loader.exec_module(module)
    return module


checklist = _tool()
needs_spec = pytest.mark.skipif(not SPEC.is_dir(), reason="../shared/spec is not beside the tree")


@needs_spec
def test_the_generated_checklist_is_current() -> None:
    expected = checklist.render()
    assert (ROOT / "docs" / "checklist.md").read_text(encoding="utf-8") == expected, (
        "docs/checklist.md is out of date: run python tools/checklist.py"
    )


@needs_spec
def test_the_data_agrees_with_the_tree() -> None:
    assert checklist.problems() == []


@needs_spec
def test_every_checklist_item_of_the_digests_is_recorded() -> None:
    items = checklist.spec_items()
    assert len(items) > 500 and {item.id[:2] for item in items} == set(checklist.DIGESTS)
    recorded = {entry["id"] for entry in checklist.load_data()["item"]}
    assert recorded == {item.id for item in items}


def test_every_option_is_read_or_explained() -> None:
    """An option nothing reads carries options.toml's effect ("none: ..." or "missing:
    ..."); one the code reads carries none (the data would contradict the code)."""
    reads = checklist.option_reads()
    indirect = {int(k) for k in checklist.load_data()["options"]["indirect"]}
    for option in checklist.options_catalogue():
        read = option["number"] in reads or option["number"] in indirect
        assert read != bool(option.get("effect")), option["number"]
    assert reads[27] >= {"core/spindle.py"}  # number_option(27)
    assert 164 in reads  # a plugin family's option=164


def test_the_catalogue_model_accepts_only_a_reasoned_effect() -> None:
    from gecent.core.machine.catalogue import OptionSpec, catalogue
    from pydantic import ValidationError

    assert catalogue().option(250).effect is not None
    assert catalogue().option(4).effect is None
    fields = catalogue().option(4).model_dump()
    with pytest.raises(ValidationError):
        OptionSpec(**{**fields, "effect": "no reason"})
    assert OptionSpec(**{**fields, "effect": "none: a reason"}).effect == "none: a reason"


def test_every_fatal_error_is_accounted_for() -> None:
    recorded = {int(k): v for k, v in checklist.load_data()["fatal"].items()}
    catalogue = checklist.fatal_catalogue()
    assert len(catalogue) >= 33 and set(recorded) == set(catalogue)
    raised = checklist.fatal_raises()
    for number, entry in recorded.items():
        if entry["status"] == "raised":
            assert number in raised and entry["tests"], number
    decided = checklist._fatal_decisions(ROOT)
    assert {n for n, e in recorded.items() if e["status"] == "cannot-arise"} <= decided


def test_a_wrong_entry_is_a_problem(tmp_path: Path) -> None:
    """The checks fail when they should: a missing test, an unexplained option."""
    assert not checklist._test_exists(ROOT, "tests/test_checklist.py::test_no_such_test")
    assert checklist._test_exists(ROOT, "tests/test_checklist.py::test_a_wrong_entry_is_a_problem")
    found = checklist._paths(ROOT, "item x", {"modules": ["core/nothing.py"], "tests": []})
    assert found == ["item x: no module core/nothing.py"]
