"""MACHIN/GECENT,nm,OPTAB,n,v from the part program (spec 07 §7.1, WE-1)."""

from __future__ import annotations

from pathlib import Path

import pytest
from gecent.core.cl.records import Statement, Word
from gecent.core.dispatch.post import post
from gecent.core.errors import FatalError, InputError
from gecent.core.machine.selection import apply_machin_options, parse_machin, resolve_machine
from gecent.core.plugins import PluginSet, get_plugins


def machin(*args: object) -> Statement:
    converted = tuple(Word(a, None) if isinstance(a, str) else a for a in args)
    return Statement("t.apt", 1, 1, "MACHIN", 1015, converted)  # type: ignore[arg-type]


def test_option_change_we1(plugins: PluginSet) -> None:
    request = parse_machin(machin("GECENT", 40, "OPTAB", 4, 20))
    assert request is not None and request.number == 40
    machine = resolve_machine(plugins, None, request)
    changed, notes = apply_machin_options(machine, request)
    assert changed.option(4) == 20.0 and notes == []


def test_non_reassignable_option_is_refused(plugins: PluginSet) -> None:
    request = parse_machin(machin("GECENT", 23, "OPTAB", 7, 3, 4, 50))
    assert request is not None
    machine = resolve_machine(plugins, None, request)
    changed, notes = apply_machin_options(machine, request)
    assert changed.option(7) == machine.option(7) and changed.option(4) == 50.0
    assert len(notes) == 1 and "OPTION 7" in notes[0].text


def test_linear_and_lincir_set_option_28(plugins: PluginSet) -> None:
    for word, value in (("LINEAR", 0.0), ("LINCIR", 1.0)):
        request = parse_machin(machin("GECENT", 23, word))
        assert request is not None
        changed, _ = apply_machin_options(resolve_machine(plugins, None, request), request)
        assert changed.option(28) == value


def test_plan_met_by_the_run_is_ignored_here(plugins: PluginSet) -> None:
    """GEPLAD plans the tape before the run (core/plan.py, tests/test_geplad.py); the
    planned tape's MACHIN has no PLAN, so one the run meets is said to be ignored."""
    request = parse_machin(machin("GECENT", 24, "PLAN"))
    assert request is not None
    _, notes = apply_machin_options(resolve_machine(plugins, None, request), request)
    assert any("PLAN IGNORED HERE" in n.text for n in notes)


def test_machine_number_out_of_range_is_fatal_999(plugins: PluginSet) -> None:
    request = parse_machin(machin("GECENT", 100))
    with pytest.raises(FatalError) as caught:
        resolve_machine(plugins, None, request)
    assert caught.value.number == 999


def test_uninstalled_machine_and_other_postprocessors(plugins: PluginSet) -> None:
    with pytest.raises(InputError, match="machine 98 is not installed"):
        resolve_machine(plugins, None, parse_machin(machin("GECENT", 98)))
    assert parse_machin(machin("UNCX01", 1)) is None
    assert resolve_machine(plugins, None, None).name == "standard"


def test_option_change_that_breaks_the_machine(plugins: PluginSet) -> None:
    request = parse_machin(machin("GECENT", 23, "OPTAB", 59, 191415))
    assert request is not None
    with pytest.raises(InputError, match="fatal error 7"):
        apply_machin_options(resolve_machine(plugins, None, request), request)


def test_machin_after_the_first_motion_cannot_choose_the_machine(tmp_path: Path) -> None:
    """The first pass stops at the first motion record: motion is made for the machine
    known by then; a later MACHIN/GECENT naming another machine is reported and ignored."""
    source = tmp_path / "late.apt"
    source.write_text("FROM/0,0,0\nFEDRAT/10\nGOTO/1,0,0\nMACHIN/GECENT,23\nFINI\n")
    result = post(str(source), get_plugins())
    assert result.machine.name == "standard"
    assert [d.text for d in result.diagnostics] == [
        f"MACHIN/GECENT,23 IGNORED: THE RUN USES MACHINE {result.machine.label}"
    ]


def test_a_machine_number_that_is_not_finite_is_bad_input(tmp_path) -> None:  # type: ignore[no-untyped-def]
    """The first pass reads MACHIN before the run's checks: it refuses 1e400 itself."""
    from click.testing import CliRunner
    from gecent.core.cli import main

    source = tmp_path / "m.apt"
    source.write_text("MACHIN/GECENT,1e400\nFINI\n")
    result = CliRunner().invoke(main, ["post", str(source), "-o", str(tmp_path / "m.tape")])
    assert result.exit_code == 2
    assert "MACHIN/GECENT has a value that is not a finite number (inf)" in result.stderr
