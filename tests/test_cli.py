"""The gecent command: plugin and machine listings, machine show, post and its errors."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main

from .conftest import ROOT

HELLO = ROOT / "examples" / "hello.apt"


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(main, list(args))
    return result.exit_code, result.stdout, result.stderr


def test_list_plugins_json_names_every_family() -> None:
    code, out, _ = run("--list-plugins", "--json")
    assert code == 0
    data = json.loads(out)
    families = {row["family"] for row in data["plugins"]}
    assert {"machines", "printouts", "readers"} <= families
    row = next(r for r in data["plugins"] if r["id"] == "mach23")
    assert row == {
        "family": "machines",
        "id": "mach23",
        "name": "mach23",
        "distribution": "gecent",
        "version": row["version"],
        "module": "gecent.plugins.machines.mach23",
    }
    assert data["failures"] == []


def test_list_plugins_table() -> None:
    code, out, _ = run("--list-plugins")
    assert code == 0 and out.splitlines()[0].split() == [
        "FAMILY",
        "ID",
        "NAME",
        "DISTRIBUTION",
        "VERSION",
        "MODULE",
    ]


def test_machines_lists_the_samples() -> None:
    code, out, _ = run("machines", "--json")
    assert code == 0
    numbers = {row["number"] for row in json.loads(out)}
    assert {4, 23, 24, 40, 51} <= numbers


def test_machine_show_readable_and_json() -> None:
    code, out, _ = run("machine", "show", "4")
    assert code == 0
    assert "machine 4 (mach04): SAMPLE LATHE" in out and "+Z-X (option 59)" in out
    assert "  34 thread_constant_lead" in out and "range 2: 18, 600" in out
    code, out, _ = run("machine", "show", "mach24", "--json")
    data = json.loads(out)
    assert data["number"] == 24 and len(data["spindle_ranges"]) == 3
    assert next(o for o in data["options"] if o["number"] == 1)["value"] == 1.0


def test_machine_show_unknown_and_bad_file(tmp_path: Path) -> None:
    code, _, err = run("machine", "show", "97")
    assert code == 2 and "not installed" in err
    bad = tmp_path / "bad.toml"
    bad.write_text('[machine]\nname = "bad"\n[optab]\n300 = 1.0\n')
    code, _, err = run("machine", "show", str(bad))
    assert code == 2 and f"{bad}: error: [optab] entry 300: unknown option" in err
    assert "Traceback" not in err


def test_post_hello_writes_tape_and_listing(tmp_path: Path) -> None:
    tape, listing = tmp_path / "h.tape", tmp_path / "h.lis"
    code, _, err = run("post", str(HELLO), "-o", str(tape), "--listing", str(listing))
    assert code == 0, err
    # MACH23: X/Y/Z format -24, G never suppressed (option 38 = 1), feedrate number
    # 10 * 20 IPM / S; the arc's F is 10 * 20 / 1 (001 L10816-10935)
    assert tape.read_text() == (
        "BRACKET4711OP10\n"
        "N009G01X+01Y+01Z-02F082\n"
        "N010G01X+03F067\n"
        "N012G03X+01Y+01J01F200\n"
        "N013G01Y+04F050\n"
        "N001M00\n"
    )
    text = listing.read_text()
    assert text.startswith("***GENERAL ELECTRIC GECENT III POSTPROCESSOR***\nSAMPLE MILL")
    assert "CLAMP THE PART ON THE LEFT STOP" in text
    first = (tape.read_bytes(), listing.read_bytes())
    run("post", str(HELLO), "-o", str(tape), "--listing", str(listing))
    assert (tape.read_bytes(), listing.read_bytes()) == first  # deterministic


def test_post_machine_override_and_option_change(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    source = tmp_path / "p.apt"
    source.write_text("PARTNO X\nMACHIN/GECENT,23,OPTAB,7,3\nFINI\n")
    code, _, err = run("post", str(source), "--machine", "4")
    assert code == 0
    assert "MACHIN/GECENT,23: THE RUN USES MACHINE 4 (mach04); ONLY THE MACHINE NUMBER" in err
    assert "OPTION 7 (spindle_range_count) CANNOT BE CHANGED BY MACHIN" in err
    assert "SAMPLE LATHE" in (tmp_path / "p.lis").read_text()


def test_unsupported_statement_stops_without_output(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    source = tmp_path / "u.apt"
    # (SAFETY on MACH23 was the example until it became bad input, issue 22 wave 4;
    # SPINDL/DWELL until it became bad input too, wave 5: the manual gives it no code;
    # ROTATE/TURRET on MACH23 until it became bad input on a contouring machine, wave 6;
    # MACHIN/GECENT,24,PLAN until GEPLAD was built, core/plan.py)
    source.write_text("PARTNO X\nMACHIN/GECENT,23\nNURBS/1,2\nFINI\n")
    code, _, err = run("post", str(source))
    assert code == 3
    assert err.strip().startswith(f"{source}:3 (record 3): error: not yet supported: NURBS")
    assert not (tmp_path / "u.tape").exists() and not (tmp_path / "u.lis").exists()
    assert [p.name for p in tmp_path.iterdir()] == ["u.apt"]  # no temporary left either


def test_malformed_statement_is_exit_2_with_position(tmp_path: Path) -> None:
    source = tmp_path / "m.apt"
    source.write_text("PARTNO X\nGOTO / 1, 2,, 3\nFINI\n")
    code, _, err = run("post", str(source))
    assert code == 2 and err.startswith(f"{source}:2:13: error: expected a value before ','")


def test_post_json_prints_one_object_per_block(tmp_path: Path) -> None:
    """`gecent post --json`: the blocks as JSON lines, their tape lines equal to the tape."""
    example = Path(__file__).resolve().parents[1] / "examples" / "drill_mach24.apt"
    tape = tmp_path / "d.tape"
    code, out, _ = run(
        "post", str(example), "-o", str(tape), "--listing", str(tmp_path / "d.lis"), "--json"
    )
    assert code == 0
    blocks = [json.loads(line) for line in out.splitlines()]
    punched = [b["tape"] for b in blocks if b["tape"] is not None]
    assert punched == tape.read_text().splitlines()
    cycle = next(b for b in blocks if b["code"] == "POSITION_Z")
    assert cycle["words"] == {"N": "015", "G": "81", "Z": "+06.1500", "F": "09", "R": "+05.9"}
    assert cycle["feed"] == 4.5 and cycle["position"] == [1.0, 1.0, 6.0]
    speed = next(b for b in blocks if b["rpm"] is not None)
    assert (speed["record"], speed["rpm"], speed["tape"]) == (10, 1060.0, "N010S07")


def test_progress_bar_only_on_a_terminal(monkeypatch: pytest.MonkeyPatch) -> None:
    """A progress bar on standard error while posting on a terminal, never in a pipe."""
    from gecent.core import cli

    example = str(Path(__file__).resolve().parents[1] / "examples" / "hello.apt")
    monkeypatch.setattr(cli.sys.stderr, "isatty", lambda: False, raising=False)
    assert cli._progress(example) is None
    monkeypatch.setattr(cli.sys.stderr, "isatty", lambda: True, raising=False)
    watch = cli._progress(example)
    assert watch is not None
    assert list(watch(iter(range(3)))) == [0, 1, 2]  # type: ignore[arg-type]
