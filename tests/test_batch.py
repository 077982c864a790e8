"""gecent batch: files, folders and manifests, the outputs and the summary, the
skip-unchanged rule and --verify (docs/batch.md); failures and Dask are in
tests/test_batch_failures.py."""

from __future__ import annotations

import csv
import json
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main

from .batchkit import HELLO, MILL, PROGRAM, batch, programs, statuses, summary


def test_a_folder_posts_every_cl_file_and_the_summary_names_each(tmp_path: Path) -> None:
    programs(tmp_path / "in" / "sub", 2)
    (tmp_path / "in" / "notes.txt").write_text("not a CL file")
    out = tmp_path / "out"
    result = batch(
        str(tmp_path / "in"),
        "--machine",
        "linuxcnc-mill",
        "--out",
        str(out),
        "-j",
        "2",
        "--json",
        str(tmp_path / "s.json"),
        "--csv",
        str(tmp_path / "s.csv"),
    )
    assert result.exit_code == 0, result.output
    rows = summary(tmp_path / "s.json")
    assert [row["input"] for row in rows] == ["sub/part0.apt", "sub/part1.apt"]
    assert all(row["status"] == "posted" and row["exit"] == 0 for row in rows)
    assert rows[0]["blocks"] == len((out / "sub" / "part0.apt.tape").read_text().splitlines())
    tape = (out / "sub" / "part1.apt.tape").read_text()
    assert "F101" in tape.replace(".", "").replace(" ", "") or "F101." in tape
    with open(tmp_path / "s.csv", newline="") as handle:
        assert [row["status"] for row in csv.DictReader(handle)] == ["posted", "posted"]
    assert "2 jobs: 2 posted" in result.output


def test_the_same_tape_as_gecent_post(tmp_path: Path) -> None:
    single = tmp_path / "single.tape"
    posted = CliRunner().invoke(main, ["post", str(HELLO), "-o", str(single)])
    assert posted.exit_code == 0, posted.output
    result = batch(str(HELLO), "--out", str(tmp_path / "out"))
    assert result.exit_code == 0, result.output
    assert (tmp_path / "out" / "hello.apt.tape").read_bytes() == single.read_bytes()
    assert (tmp_path / "out" / "hello.apt.lis").read_bytes() == single.with_suffix(
        ".lis"
    ).read_bytes()


def test_a_toml_manifest(tmp_path: Path) -> None:
    programs(tmp_path / "cl", 2)
    shutil.copy(MILL, tmp_path / "mill.toml")
    (tmp_path / "jobs.toml").write_text(
        """[defaults]
out = "posted"
machine = "linuxcnc-mill"

[[job]]
input = "cl/part0.apt"
tape = "nc/zero.ngc"
listing = "nc/zero.lis"
punch = "eia"
punch_file = "nc/zero.pch"

[[job]]
input = "cl/part1.apt"
machine = "mill.toml"
optab = { 264 = 0 }
"""
    )
    result = batch("--manifest", str(tmp_path / "jobs.toml"), "--json", str(tmp_path / "s.json"))
    assert result.exit_code == 0, result.output
    assert (tmp_path / "nc" / "zero.ngc").read_text().startswith("%")
    assert (tmp_path / "nc" / "zero.lis").exists() and (tmp_path / "nc" / "zero.pch").exists()
    assert "(T3)" in (tmp_path / "nc" / "zero.ngc").read_text()  # the pack's tool list
    assert "(T3)" not in (tmp_path / "posted" / "part1.apt.tape").read_text()  # 264 = 0
    assert [row["machine"] for row in summary(tmp_path / "s.json")] == [
        "linuxcnc-mill",
        str(tmp_path / "mill.toml"),
    ]


def test_a_csv_manifest_and_its_errors_name_the_line(tmp_path: Path) -> None:
    programs(tmp_path, 2)
    (tmp_path / "jobs.csv").write_text(
        "input,machine,tape\npart0.apt,fanuc-mill,a.nc\npart1.apt,haas-mill,b.nc\n"
    )
    result = batch("--manifest", str(tmp_path / "jobs.csv"), "--out", str(tmp_path / "o"))
    assert result.exit_code == 0, result.output
    assert (tmp_path / "a.nc").exists() and (tmp_path / "b.nc").exists()
    (tmp_path / "bad.csv").write_text("input,machine\npart0.apt,fanuc-mill\nnope.apt,fanuc-mill\n")
    result = batch("--manifest", str(tmp_path / "bad.csv"))
    assert result.exit_code == 2
    assert "bad.csv:3" in result.output and "nope.apt: no such file" in result.output
    (tmp_path / "bad.toml").write_text('[[job]]\ninput = "part0.apt"\n\n[[job]]\ninptu = "x"\n')
    result = batch("--manifest", str(tmp_path / "bad.toml"))
    assert result.exit_code == 2 and "bad.toml:4" in result.output and "'inptu'" in result.output


def test_two_jobs_writing_one_file_are_refused(tmp_path: Path) -> None:
    programs(tmp_path, 2)
    (tmp_path / "jobs.toml").write_text(
        '[[job]]\ninput = "part0.apt"\ntape = "x.ngc"\n\n'
        '[[job]]\ninput = "part1.apt"\ntape = "x.ngc"\n'
    )
    result = batch("--manifest", str(tmp_path / "jobs.toml"), "--machine", "linuxcnc-mill")
    assert (
        result.exit_code == 2 and "jobs 1 (part0.apt) and 2 (part1.apt) both write" in result.output
    )
    assert not (tmp_path / "x.ngc").exists()


def test_unchanged_jobs_are_skipped_and_each_change_posts_again(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    parts = programs(tmp_path / "in", 3)
    machine = tmp_path / "mill.toml"
    shutil.copy(MILL, machine)
    out = tmp_path / "out"
    report = tmp_path / "s.json"

    def run(*extra: str) -> list[str]:
        result = batch(
            str(tmp_path / "in"),
            "--machine",
            str(machine),
            "--out",
            str(out),
            "--json",
            str(report),
            *extra,
        )
        assert result.exit_code == 0, result.output
        return statuses(report)

    assert run() == ["posted"] * 3
    first = (out / "part1.apt.tape").read_bytes()
    assert run() == ["skipped"] * 3
    assert (out / "part1.apt.tape").read_bytes() == first
    assert run("--force") == ["posted"] * 3
    parts[1].write_text(PROGRAM.format(name=1, feed=250))  # an input changes
    assert run() == ["skipped", "posted", "skipped"]
    (out / "part2.apt.tape").unlink()  # an output goes missing
    assert run() == ["skipped", "skipped", "posted"]
    (out / "part0.apt.tape").write_text("edited by hand\n")  # an output was changed
    assert run() == ["posted", "skipped", "skipped"]
    assert run("--listing") == ["posted"] * 3  # other settings
    machine.write_text(machine.read_text().replace('title = "', 'title = "changed ', 1))
    assert run("--listing") == ["posted"] * 3  # the machine file changed
    monkeypatch.setattr("gecent.core.batch.state.__version__", "99.0")
    assert run("--listing") == ["posted"] * 3  # another gecent


def test_a_machine_chosen_by_machin_is_watched_too(tmp_path: Path) -> None:
    """With no --machine, the CL file's MACHIN/GECENT names the machine: the state keeps
    which pack it was and its text's hash."""
    out = tmp_path / "out"
    report = tmp_path / "s.json"
    for expected in ("posted", "skipped"):
        result = batch(str(HELLO), "--out", str(out), "--json", str(report))
        assert result.exit_code == 0, result.output
        assert statuses(report) == [expected]
    state = json.loads((out / ".gecent-batch.json").read_text())
    (entry,) = state["jobs"].values()
    assert entry["machine"] == "mach23" and len(entry["machine_hash"]) == 64
    entry["machine_hash"] = "0" * 64  # as if the pack's file had changed since
    (out / ".gecent-batch.json").write_text(json.dumps(state))
    result = batch(str(HELLO), "--out", str(out), "--json", str(report))
    assert statuses(report) == ["posted"]


@pytest.mark.skipif(shutil.which("rs274") is None, reason="rs274 (linuxcnc-uspace) not installed")
def test_verify_in_the_batch(tmp_path: Path) -> None:
    programs(tmp_path / "in", 2)
    out = tmp_path / "out"
    result = batch(
        str(tmp_path / "in"),
        str(HELLO),
        "--machine",
        "linuxcnc-mill",
        "--verify",
        "--out",
        str(out),
        "--json",
        str(tmp_path / "s.json"),
    )
    assert result.exit_code == 0, result.output
    assert [row["verify"] for row in summary(tmp_path / "s.json")] == ["passed"] * 3
    result = batch(
        str(HELLO), "--verify", "--out", str(tmp_path / "o2"), "--json", str(tmp_path / "s.json")
    )  # MACH23's tape is not G-code
    assert result.exit_code == 0, result.output
    assert summary(tmp_path / "s.json")[0]["verify"].startswith("n/a")  # type: ignore[union-attr]


def test_a_dry_run_lists_what_would_post(tmp_path: Path) -> None:
    parts = programs(tmp_path / "in", 2)
    out, report = tmp_path / "out", tmp_path / "s.json"
    common = [str(tmp_path / "in"), "--machine", "linuxcnc-mill", "--out", str(out)]
    assert batch(*common).exit_code == 0
    parts[0].write_text(PROGRAM.format(name=0, feed=333))
    result = batch(*common, "--dry-run", "--json", str(report))
    assert result.exit_code == 0, result.output
    assert statuses(report) == ["to post", "skipped"]
    assert "F333" not in (out / "part0.apt.tape").read_text()  # nothing posted


def test_an_output_never_overwrites_an_input_or_the_manifest(tmp_path: Path) -> None:
    programs(tmp_path, 2)
    for tape, what in (
        ("part0.apt", "the CL file of job 1"),
        ("part1.apt", "the CL file of job 2"),
        ("jobs.toml", "the manifest"),
    ):
        (tmp_path / "jobs.toml").write_text(
            f'[[job]]\ninput = "part0.apt"\ntape = "{tape}"\n\n[[job]]\ninput = "part1.apt"\n'
        )
        result = batch("--manifest", str(tmp_path / "jobs.toml"), "--machine", "linuxcnc-mill")
        assert result.exit_code == 2 and what in result.output, result.output
    assert (tmp_path / "part0.apt").read_text().startswith("PARTNO")


def test_outputs_inside_the_folder_are_not_posted_again(tmp_path: Path) -> None:
    """The default output folder inside the folder posted: its tapes (x.ncl.8.tape) are not
    CL files, and a Creo version is recognised only as .ncl.<number>."""
    folder = tmp_path / "cam"
    programs(folder, 1)
    shutil.copy(folder / "part0.apt", folder / "drill.ncl.8")
    (folder / "drill.ncl.lis").write_text("a listing, not a CL file\n")
    report = tmp_path / "s.json"
    for expected in (["posted", "posted"], ["skipped", "skipped"]):
        result = batch(
            str(folder),
            "--machine",
            "mach23",
            "--out",
            str(folder / "posted"),
            "--json",
            str(report),
        )
        assert result.exit_code == 0, result.output
        assert statuses(report) == expected
    assert [row["input"] for row in summary(report)] == ["drill.ncl.8", "part0.apt"]


def test_verify_on_a_machine_rs274_cannot_read_is_not_asked_again(tmp_path: Path) -> None:
    report = tmp_path / "s.json"
    for expected in ("posted", "skipped"):
        result = batch(str(HELLO), "--verify", "--out", str(tmp_path / "o"), "--json", str(report))
        assert result.exit_code == 0, result.output
        assert statuses(report) == [expected]
        assert str(summary(report)[0]["verify"]).startswith("n/a")


def test_csv_cells_as_a_spreadsheet_writes_them(tmp_path: Path) -> None:
    """Excel's byte-order mark, false/true for the listing, a file that is not UTF-8."""
    programs(tmp_path, 2)
    (tmp_path / "jobs.csv").write_text(
        "\ufeffinput,machine,listing\npart0.apt,mach23,false\npart1.apt,mach23,true\n",
        encoding="utf-8",
    )
    result = batch("--manifest", str(tmp_path / "jobs.csv"), "--out", str(tmp_path / "o"))
    assert result.exit_code == 0, result.output
    assert not (tmp_path / "false").exists() and not (tmp_path / "true").exists()
    assert not (tmp_path / "o" / "part0.apt.lis").exists()
    assert (tmp_path / "o" / "part1.apt.lis").exists()
    (tmp_path / "latin.csv").write_bytes(b"input,machine\npart0.apt,m\xe4ch23\n")
    result = batch("--manifest", str(tmp_path / "latin.csv"))
    assert result.exit_code == 2 and "not UTF-8" in result.output


def test_an_output_the_settings_no_longer_ask_for_is_removed(tmp_path: Path) -> None:
    """A listing the last batch wrote and this one does not (--no-listing) goes, unless it
    was changed since: then it is someone else's file."""
    programs(tmp_path / "in", 2)
    out = tmp_path / "o"
    common = [str(tmp_path / "in"), "--machine", "mach23", "--out", str(out)]
    assert batch(*common).exit_code == 0
    assert (out / "part0.apt.lis").exists() and (out / "part1.apt.lis").exists()
    (out / "part1.apt.lis").write_text("annotated by the operator\n")
    assert batch(*common, "--no-listing").exit_code == 0
    assert not (out / "part0.apt.lis").exists()
    assert (out / "part1.apt.lis").read_text() == "annotated by the operator\n"
    assert (out / "part0.apt.tape").exists()
