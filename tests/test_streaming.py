"""The streaming outputs of `gecent post` (core/output/sinks.py): where the files go, that
each is whole or absent whatever ends the run, that a run's memory does not grow with its
input, and the bounds on absurd moves (core/motion/guard.py)."""

from __future__ import annotations

import tracemalloc
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.dispatch.post import post
from gecent.core.output.punch import ODD, punch, readable_frames, table, unpunch
from gecent.core.output.sinks import CollectSink, Ending, Sinks, TapeSink

from .conftest import ROOT

HELLO = ROOT / "examples" / "hello.apt"


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(main, list(args))
    return result.exit_code, result.stdout, result.stderr


def names(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir())


@pytest.fixture
def part_folder(tmp_path: Path) -> Path:
    folder = tmp_path / "parts"
    folder.mkdir()
    (folder / "hello.apt").write_bytes(HELLO.read_bytes())
    return folder


def test_default_outputs_go_to_the_current_folder_not_the_inputs(
    tmp_path: Path, part_folder: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    work = tmp_path / "work"
    work.mkdir()
    monkeypatch.chdir(work)
    code, _, err = run("post", str(part_folder / "hello.apt"))
    assert code == 0, err
    assert names(part_folder) == ["hello.apt"]
    assert names(work) == ["hello.lis", "hello.tape"]


def test_the_listing_goes_beside_the_tape(tmp_path: Path, part_folder: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    code, _, err = run("post", str(part_folder / "hello.apt"), "-o", str(out / "p.tape"))
    assert code == 0, err
    assert names(out) == ["p.lis", "p.tape"]
    assert names(part_folder) == ["hello.apt"]


def test_a_g_code_machine_writes_a_listing_only_when_asked(tmp_path: Path) -> None:
    tape = tmp_path / "p.ngc"
    code, _, err = run("post", str(HELLO), "--machine", "linuxcnc-mill", "-o", str(tape))
    assert code == 0, err
    assert names(tmp_path) == ["p.ngc"]
    assert tape.read_text().startswith("%\n")
    listing = tmp_path / "p.lis"
    code, _, err = run(
        "post", str(HELLO), "--machine", "linuxcnc-mill", "-o", str(tape), "--listing", str(listing)
    )
    assert code == 0, err
    assert "GECENT III" in listing.read_text()


def test_streamed_outputs_equal_the_blocks_rendered_at_once(tmp_path: Path, plugins) -> None:  # type: ignore[no-untyped-def]
    """The tape, punch and listing written block by block are what the collected blocks
    render to in one piece."""
    tape, listing, eia = tmp_path / "h.tape", tmp_path / "h.lis", tmp_path / "h.eia"
    code, _, err = run(
        "post", str(HELLO), "-o", str(tape), "--listing", str(listing), "--punch", "eia", str(eia)
    )
    assert code == 0, err
    result = post(str(HELLO), plugins)
    lines = [line for line in (t for t in map(_tape_line, result.blocks)) if line is not None]
    assert tape.read_text() == "".join(line + "\n" for line in lines)
    assert unpunch(eia.read_bytes(), "eia", readable=True) == lines
    # the punch is the lines' frames with MACH23's readable PARTNO where the PARTNO comes
    end_of_block = bytes([table("eia")["EOB"]])
    readable = end_of_block + readable_frames(result.partno, ODD) + end_of_block
    assert readable in eia.read_bytes()
    assert eia.read_bytes().replace(readable, b"", 1) == punch(lines, "eia")
    printout = plugins.get("printouts", 1)
    assert listing.read_text() == printout.render(result.machine, result.blocks, result.partno)


def _tape_line(block):  # type: ignore[no-untyped-def]
    from gecent.core.output.tape import tape_line

    return tape_line(block)


def test_a_fatal_error_leaves_the_listing_with_its_dump_and_nothing_else(tmp_path: Path) -> None:
    source = tmp_path / "part.apt"
    source.write_text("MACHIN/GECENT,23,OPTAB,27,-1\nPPRINT BEFORE\nSPINDL/CLW\nFINI\n")
    tape, listing, eia = tmp_path / "p.tape", tmp_path / "p.lis", tmp_path / "p.eia"
    code, _, err = run(
        "post", str(source), "-o", str(tape), "--listing", str(listing), "--punch", "eia", str(eia)
    )
    assert code == 1, err
    assert names(tmp_path) == ["p.lis", "part.apt"]  # no tape, no punch, no temporaries
    text = listing.read_text()
    assert "BEFORE" in text and text.rstrip().endswith("}") and "*** GEDUMP ***" in text


def test_bad_input_midway_leaves_no_file_at_all(tmp_path: Path) -> None:
    source = tmp_path / "part.apt"
    source.write_text("MACHIN/GECENT,23\nFEDRAT/20\nGOTO/1,1,0\nGOTO/2,2,0\nGOTO/1,,2\nFINI\n")
    tape, listing, eia = tmp_path / "p.tape", tmp_path / "p.lis", tmp_path / "p.eia"
    code, _, err = run(
        "post", str(source), "-o", str(tape), "--listing", str(listing), "--punch", "eia", str(eia)
    )
    assert code == 2 and f"{source}:5" in err
    assert names(tmp_path) == ["part.apt"]


def test_a_character_the_punch_code_lacks_stops_the_run_with_no_file(tmp_path: Path) -> None:
    """An INSERT's ":" has no EIA RS-244 code: found while punching, mid-run."""
    source = tmp_path / "in" / "p.apt"
    source.parent.mkdir()
    source.write_text(HELLO.read_text().replace("INSERT N001 M00", "INSERT (NOTE: STOP)"))
    out = tmp_path / "out"
    out.mkdir()
    tape, eia = out / "p.ngc", out / "p.eia"
    code, _, err = run(
        "post", str(source), "--machine", "fanuc-mill", "-o", str(tape), "--punch", "eia", str(eia)
    )
    assert code == 2 and "('(NOTE:STOP)'): ':' has no EIA code" in err, err
    assert names(out) == []


def test_sinks_close_all_even_when_one_fails(tmp_path: Path) -> None:
    class Failing:
        def block(self, block, line):  # type: ignore[no-untyped-def]
            """Takes the blocks and writes nothing."""

        def close(self, ending: Ending) -> None:
            raise OSError("disk gone")

    tape = TapeSink(tmp_path / "t.tape")
    sinks = Sinks([Failing(), tape, CollectSink()])  # type: ignore[list-item]
    with pytest.raises(OSError):
        sinks.close(Ending(True))
    assert names(tmp_path) == []  # the tape after the failure was discarded, not committed


@pytest.mark.parametrize(
    ("machine", "expected"),
    [
        ("23", "this move would make 10,000,011 segment blocks"),
        ("4", "this move would make 100,001,001 segment blocks"),
        ("24", "X 1e+09 is beyond what the X register holds (99.9999)"),
        ("linuxcnc-mill", "X 1e+09 is beyond what the X register holds (99999.999)"),
    ],
)
def test_an_absurd_move_is_refused_before_anything_is_written(
    tmp_path: Path, machine: str, expected: str
) -> None:
    source = tmp_path / "big.apt"
    source.write_text("PARTNO BIG\nFEDRAT/10\nGOTO/1e9,1,1\nFINI\n")
    tape = tmp_path / "big.tape"
    code, _, err = run("post", str(source), "--machine", machine, "-o", str(tape))
    assert code == 2
    assert f"{source}:3 (record 3): error: {expected}" in err
    assert names(tmp_path) == ["big.apt"]


def test_the_segment_bound_is_the_users_to_move(tmp_path: Path) -> None:
    """GOTO/1e5 on the sample mill (departures to 99.9999) is 1,001 blocks: refused under
    a bound of 1,000, made with the bound raised or removed."""
    source = tmp_path / "long.apt"
    source.write_text("PARTNO LONG\nMACHIN/GECENT,23\nFEDRAT/10\nGOTO/1e5,0,0\nFINI\n")
    tape = tmp_path / "long.tape"
    code, _, err = run("post", str(source), "-o", str(tape), "--max-segments", "1000")
    assert code == 2 and "would make 1,001 segment blocks" in err and "--max-segments" in err
    for bound in ("1001", "0"):
        code, _, err = run("post", str(source), "-o", str(tape), "--max-segments", bound)
        assert code == 0, err
        assert sum(1 for line in tape.read_text().splitlines() if "X+999" in line) == 1001


@pytest.mark.parametrize(
    ("statement", "message"),
    [
        ("GOTO/1e400,0,0", "GOTO has a value that is not a finite number (inf)"),
        ("GOTO/1e300,0,0", "coordinate 1e+300 is beyond any position the machine can reach"),
        ("FEDRAT/1e999", "FEDRAT has a value that is not a finite number (inf)"),
        ("CIRCLE/0,0,0,0,0,1,1e999", "CIRCLE has a value that is not a finite number (inf)"),
        ("MACHIN/GECENT,23,OPTAB,4,1e999", "MACHIN has a value that is not a finite number"),
    ],
)
def test_numbers_no_machine_can_take_are_bad_input(
    tmp_path: Path, statement: str, message: str
) -> None:
    source = tmp_path / "bad.apt"
    source.write_text(f"MACHIN/GECENT,23\nFEDRAT/10\n{statement}\nGOTO/1,0,0\nFINI\n")
    code, _, err = run("post", str(source), "-o", str(tmp_path / "bad.tape"))
    assert code == 2
    assert f"{source}:3 (record 3): error: {message}" in err
    assert names(tmp_path) == ["bad.apt"]


def _peak_bytes(tmp_path: Path, copies: int) -> int:
    body = ["GOTO/1,1,0", "GOTO/2,1,0", "GOTO/2,2,0", "GOTO/1,2,0", "PPRINT ROUND"]
    source = tmp_path / f"loop{copies}.apt"
    source.write_text("\n".join(["MACHIN/GECENT,23", "FEDRAT/20", *body * copies, "FINI"]) + "\n")
    out = tmp_path / f"out{copies}"
    out.mkdir()
    tracemalloc.start()
    try:
        code, _, err = run(
            "post",
            str(source),
            "-o",
            str(out / "t.tape"),
            "--punch",
            "eia",
            str(out / "t.eia"),
            "--listing",
            str(out / "t.lis"),
        )
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert code == 0, err
    return peak


def test_memory_does_not_grow_with_the_input(tmp_path: Path) -> None:
    """Ten times the records, about the same peak: nothing keeps per-block objects."""
    _peak_bytes(tmp_path, 10)  # first-use caches (templates, plugins) are not the run's
    small = _peak_bytes(tmp_path, 150)
    large = _peak_bytes(tmp_path, 1500)
    assert large < small * 1.25, (small, large)


def test_a_json_reader_that_goes_away_ends_the_json_not_the_post(tmp_path: Path) -> None:
    """`gecent post --json | head -1`: the tape is still written whole, exit 0."""
    import subprocess
    import sys

    moves = [f"GOTO/{i % 50},{i % 7},0" for i in range(6000)]
    source = tmp_path / "long.apt"
    source.write_text("\n".join(["MACHIN/GECENT,23", "FEDRAT/20", *moves, "FINI"]) + "\n")
    tape = tmp_path / "long.tape"
    command = [sys.executable, "-m", "gecent.core.cli", "post", str(source), "-o", str(tape)]
    process = subprocess.Popen([*command, "--json"], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert process.stdout is not None
    assert process.stdout.readline().startswith(b"{")
    process.stdout.close()  # the reader goes away with megabytes still to come
    _, err = process.communicate(timeout=120)
    assert process.returncode == 0, err
    whole = subprocess.run([*command[:-2], "-o", str(tmp_path / "whole.tape")], check=True)
    assert whole.returncode == 0
    assert tape.read_bytes() == (tmp_path / "whole.tape").read_bytes()


def test_a_value_no_register_can_hold_stops_the_run_naming_it(tmp_path: Path) -> None:
    """DELAY/1e9 is a number a statement can carry, but its dwell word overflows the
    format: the manual's register overflow, with file and line, the listing kept with its
    dump, no tape. (DELAY/1e308 is bad input: no time is that long.)"""
    source = tmp_path / "d.apt"
    source.write_text("MACHIN/GECENT,23\nFROM/0,0,0\nDELAY/1e9\nFINI\n")
    code, _, err = run(
        "post", str(source), "-o", str(tmp_path / "d.tape"), "--listing", str(tmp_path / "d.lis")
    )
    assert code == 1 and f"{source}:3 (record 3): error: X1e+08 does not fit" in err
    assert names(tmp_path) == ["d.apt", "d.lis"]
