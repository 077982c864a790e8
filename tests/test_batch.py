"""gecent batch: the manifest, the skip-unchanged rule, failure isolation (bad input, a job
that hangs, a job that kills its worker) and the Dask cluster's equivalence with the local
run (docs/batch.md)."""

from __future__ import annotations

import csv
import json
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner, Result
from gecent.core.cli import main

from .conftest import SHARED

CORPUS = SHARED / "corpus"
HELLO = Path(__file__).resolve().parent.parent / "examples" / "hello.apt"
MILL = Path(__file__).resolve().parent.parent / "plugins" / "machines" / "linuxcnc-mill.toml"
PROGRAM = """PARTNO BATCH {name}
UNITS/MM
LOADTL/3
FROM/0,0,10
FEDRAT/{feed}
GOTO/10,0,0
GOTO/10,20,0
FINI
"""


def batch(*args: str) -> Result:
    return CliRunner().invoke(main, ["batch", "--no-progress", *args])


def summary(path: Path) -> list[dict[str, object]]:
    jobs: list[dict[str, object]] = json.loads(path.read_text())["jobs"]
    return jobs


def statuses(path: Path) -> list[str]:
    return [str(row["status"]) for row in summary(path)]


def programs(folder: Path, count: int = 3) -> list[Path]:
    folder.mkdir(parents=True, exist_ok=True)
    made = []
    for number in range(count):
        path = folder / f"part{number}.apt"
        path.write_text(PROGRAM.format(name=number, feed=100 + number))
        made.append(path)
    return made


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


def test_one_bad_job_never_stops_the_others_and_writes_nothing(tmp_path: Path) -> None:
    programs(tmp_path / "in", 2)
    (tmp_path / "in" / "broken.apt").write_text("PARTNO BROKEN\nFROM/0,0,10\nGOTO/1,2\nFINI\n")
    out = tmp_path / "out"
    result = batch(
        str(tmp_path / "in"),
        "--machine",
        "linuxcnc-mill",
        "--out",
        str(out),
        "--json",
        str(tmp_path / "s.json"),
    )
    assert result.exit_code == 1
    rows = {row["input"]: row for row in summary(tmp_path / "s.json")}
    assert rows["broken.apt"]["status"] == "failed" and rows["broken.apt"]["exit"] == 2
    assert "broken.apt:3" in str(rows["broken.apt"]["error"])
    assert rows["part0.apt"]["status"] == rows["part1.apt"]["status"] == "posted"
    assert not (out / "broken.apt.tape").exists()
    assert sorted(p.name for p in out.glob("*.tape")) == ["part0.apt.tape", "part1.apt.tape"]
    again = batch(
        str(tmp_path / "in"),
        "--machine",
        "linuxcnc-mill",
        "--out",
        str(out),
        "--json",
        str(tmp_path / "s.json"),
    )
    assert again.exit_code == 1
    assert statuses(tmp_path / "s.json") == ["failed", "skipped", "skipped"]  # failed: again


def test_a_job_that_kills_its_worker_or_hangs_is_named_and_the_others_post(tmp_path: Path) -> None:
    programs(tmp_path, 4)
    (tmp_path / "dies.py").write_text("import os\nos._exit(9)\n")
    (tmp_path / "hangs.py").write_text("while True:\n    pass\n")
    (tmp_path / "jobs.toml").write_text(
        """[defaults]
machine = "linuxcnc-mill"

[[job]]
input = "part0.apt"

[[job]]
input = "part1.apt"
macros = ["dies.py"]

[[job]]
input = "part2.apt"
macros = ["hangs.py"]

[[job]]
input = "part3.apt"
"""
    )
    result = batch(
        "--manifest",
        str(tmp_path / "jobs.toml"),
        "--out",
        str(tmp_path / "out"),
        "-j",
        "2",
        "--timeout",
        "3",
        "--json",
        str(tmp_path / "s.json"),
    )
    assert result.exit_code == 1, result.output
    rows = summary(tmp_path / "s.json")
    assert [row["status"] for row in rows] == ["posted", "crashed", "failed", "posted"]
    assert "worker process died" in str(rows[1]["error"])
    assert rows[2]["exit"] == 124 and "timed out after 3 s" in str(rows[2]["error"])
    assert sorted(p.name for p in (tmp_path / "out").glob("*.tape")) == [
        "part0.apt.tape",
        "part3.apt.tape",
    ]


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


@pytest.mark.skipif(not CORPUS.is_dir(), reason="shared corpus not present")
def test_the_corpus_on_a_dask_cluster_matches_the_local_run(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    distributed = pytest.importorskip("distributed")
    local, remote = tmp_path / "local", tmp_path / "dask"
    common = [str(CORPUS), "--machine", "linuxcnc-mill", "--machine", "mach23"]
    result = batch(*common, "--out", str(local), "-j", "2", "--json", str(tmp_path / "l.json"))
    assert result.exit_code == 1, result.output  # the two APT part programs are not CL data
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0"
    ) as cluster:
        result = batch(
            *common,
            "--out",
            str(remote),
            "--scheduler",
            cluster.scheduler_address,
            "--json",
            str(tmp_path / "d.json"),
        )
        monkeypatch.setattr(  # as if this host had another pack version than the workers
            "gecent.core.batch.runner.plugins_fingerprint", lambda plugins: "another"
        )
        refused = batch(
            str(HELLO), "--out", str(tmp_path / "x"), "--scheduler", cluster.scheduler_address
        )
        monkeypatch.undo()
    assert refused.exit_code == 2 and "other plugins or plugin versions" in refused.output
    assert result.exit_code == 1, result.output
    assert "on Dask at tcp://" in result.output
    written = sorted(p.relative_to(local) for p in local.rglob("*") if p.is_file())
    assert written == sorted(p.relative_to(remote) for p in remote.rglob("*") if p.is_file())
    tapes = [p for p in written if p.suffix in (".tape", ".lis")]
    assert len(tapes) >= 30
    for path in written:
        if path.name != ".gecent-batch.json":
            assert (local / path).read_bytes() == (remote / path).read_bytes(), path

    def comparable(report: Path) -> list[dict[str, object]]:
        return [
            {k: v for k, v in row.items() if k not in ("seconds", "tape")}
            for row in summary(report)
        ]

    assert comparable(tmp_path / "l.json") == comparable(tmp_path / "d.json")


def test_a_stopped_batch_remembers_the_jobs_it_finished(tmp_path: Path) -> None:
    """Ctrl-C: the queued jobs are dropped, the state keeps what finished, so the next
    batch posts only the rest."""
    from gecent.core.batch.jobs import JobDefaults, jobs_from_sources
    from gecent.core.batch.runner import Settings, run_batch

    programs(tmp_path / "in", 6)
    out = tmp_path / "out"
    jobs = jobs_from_sources([str(tmp_path / "in")], JobDefaults(("linuxcnc-mill",), out))
    seen: list[int] = []

    def stop_after_two(outcome: object) -> None:
        seen.append(1)
        if len(seen) == 2:
            raise KeyboardInterrupt

    settings = Settings(workers=1, state=out / ".gecent-batch.json")
    with pytest.raises(KeyboardInterrupt):
        run_batch(jobs, settings, stop_after_two)
    assert len(json.loads((out / ".gecent-batch.json").read_text())["jobs"]) == 2
    result = batch(
        str(tmp_path / "in"),
        "--machine",
        "linuxcnc-mill",
        "--out",
        str(out),
        "--json",
        str(tmp_path / "s.json"),
    )
    assert result.exit_code == 0, result.output
    assert sorted(statuses(tmp_path / "s.json")) == ["posted"] * 4 + ["skipped"] * 2


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


def test_a_state_or_summary_that_cannot_be_written_still_prints_the_summary(tmp_path: Path) -> None:
    programs(tmp_path / "in", 1)
    (tmp_path / "file").write_text("a file, not a folder")
    result = batch(
        str(tmp_path / "in"),
        "--machine",
        "linuxcnc-mill",
        "--out",
        str(tmp_path / "o"),
        "--state",
        str(tmp_path / "file" / "state.json"),
    )
    assert result.exit_code == 0, result.output
    assert "warning: cannot write the batch state file" in result.output
    assert "1 jobs: 1 posted" in result.output and (tmp_path / "o" / "part0.apt.tape").exists()
    result = batch(
        str(tmp_path / "in"),
        "--machine",
        "linuxcnc-mill",
        "--out",
        str(tmp_path / "o"),
        "--json",
        str(tmp_path / "file" / "s.json"),
    )
    assert result.exit_code == 2 and "cannot write the summary" in result.output
    assert "1 jobs: 1 posted" in result.output  # (the state of the first run was not kept)


def test_a_damaged_state_file_is_refused_unless_forced(tmp_path: Path) -> None:
    programs(tmp_path / "in", 1)
    out = tmp_path / "o"
    out.mkdir()
    for text in ("{not json", '{"format": 1, "jobs": [1]}', '{"x": 1}'):
        (out / ".gecent-batch.json").write_text(text)
        common = [str(tmp_path / "in"), "--machine", "linuxcnc-mill", "--out", str(out)]
        result = batch(*common)
        assert result.exit_code == 2 and ".gecent-batch.json" in result.output, result.output
        assert batch(*common, "--force").exit_code == 0
    entry = json.loads((out / ".gecent-batch.json").read_text())
    entry["jobs"][next(iter(entry["jobs"]))]["summary"] = "damaged"
    (out / ".gecent-batch.json").write_text(json.dumps(entry))
    result = batch(
        str(tmp_path / "in"),
        "--machine",
        "linuxcnc-mill",
        "--out",
        str(out),
        "--json",
        str(tmp_path / "s.json"),
    )
    assert result.exit_code == 0 and statuses(tmp_path / "s.json") == ["posted"]


def test_verify_on_a_machine_rs274_cannot_read_is_not_asked_again(tmp_path: Path) -> None:
    report = tmp_path / "s.json"
    for expected in ("posted", "skipped"):
        result = batch(str(HELLO), "--verify", "--out", str(tmp_path / "o"), "--json", str(report))
        assert result.exit_code == 0, result.output
        assert statuses(report) == [expected]
        assert str(summary(report)[0]["verify"]).startswith("n/a")


@pytest.mark.parametrize(
    ("manifest", "expected"),
    [
        ('[[job]]\ninput = "part0.apt"\nmacros = 5\n', "jobs.toml:4: error: macros = 5"),
        ('[[job]]\ninput = "part0.apt"\ntape = "."\n', "is not a file name"),
        ('[[job]]\ninput = "part0.apt"\nmachine = "linux-mill"\n', "'linux-mill' is not installed"),
        ('[[job]]\ninput = "part0.apt"\ndialect = "nxx"\n', "no dialect 'nxx'"),
        ('[[job]]\ninput = "part0.apt"\nout = "x"\n', "unknown manifest key 'out'"),
        ('[[job]]\ninput = "part0.apt"\nmax_segments = -5\n', "max_segments is a whole number"),
        ('job = [1, 2]\n[defaults]\nmachine = "mach23"\n', "[[job]] an array of tables"),
        ('[[job]]\ninput = "part0.apt"\ndialect = 5\n', "dialect = 5: expected text"),
    ],
)
def test_bad_manifest_values_are_bad_input(tmp_path: Path, manifest: str, expected: str) -> None:
    programs(tmp_path, 1)
    (tmp_path / "jobs.toml").write_text(
        '[defaults]\nmachine = "linuxcnc-mill"\n\n' + manifest
        if "machine" not in manifest
        else manifest
    )
    result = batch("--manifest", str(tmp_path / "jobs.toml"), "--out", str(tmp_path / "o"))
    assert result.exit_code == 2, result.output
    assert expected in result.output, result.output
    assert "internal error" not in result.output


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


def test_a_broken_macro_file_is_named_as_the_job_names_it(tmp_path: Path) -> None:
    programs(tmp_path, 1)
    (tmp_path / "shop.py").write_text("x = (\n")
    (tmp_path / "jobs.toml").write_text(
        '[[job]]\ninput = "part0.apt"\nmachine = "linuxcnc-mill"\nmacros = ["shop.py"]\n'
    )
    result = batch(
        "--manifest",
        str(tmp_path / "jobs.toml"),
        "--out",
        str(tmp_path / "o"),
        "--json",
        str(tmp_path / "s.json"),
    )
    assert result.exit_code == 1
    error = str(summary(tmp_path / "s.json")[0]["error"])
    assert error.startswith(str(tmp_path / "shop.py")) and "gecent-job-" not in error


def test_sigterm_stops_the_batch_and_its_workers(tmp_path: Path) -> None:
    import os
    import signal
    import subprocess
    import sys
    import time

    programs(tmp_path, 3)
    (tmp_path / "hangs.py").write_text("while True:\n    pass\n")
    (tmp_path / "jobs.toml").write_text(
        '[defaults]\nmachine = "linuxcnc-mill"\nmacros = ["hangs.py"]\n\n'
        + "".join(f'[[job]]\ninput = "part{n}.apt"\n\n' for n in range(3))
    )
    gecent = Path(sys.executable).parent / "gecent"
    command = [
        str(gecent),
        "batch",
        "--manifest",
        str(tmp_path / "jobs.toml"),
        "-j",
        "2",
        "--no-progress",
        "--out",
        str(tmp_path / "o"),
    ]
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    workers: list[int] = []
    for _ in range(100):  # the two workers busy with their hanging jobs
        time.sleep(0.1)
        children = Path(f"/proc/{process.pid}/task/{process.pid}/children")
        workers = [int(p) for p in children.read_text().split()] if children.exists() else []
        if len(workers) >= 2:
            break
    assert len(workers) >= 2
    time.sleep(0.5)
    process.send_signal(signal.SIGTERM)
    _, err = process.communicate(timeout=30)
    assert process.returncode == 130, err
    time.sleep(0.5)
    for pid in workers:
        assert (
            not Path(f"/proc/{pid}").exists()
            or "Z" in Path(f"/proc/{pid}/stat").read_text().split()[2]
        ), pid
    del os


def test_a_job_that_kills_its_dask_worker_is_named_and_the_others_post(tmp_path: Path) -> None:
    """Jobs go several to a Dask task: the jobs of a task whose worker dies run again one
    by one, so only the job that kills its worker is crashed."""
    distributed = pytest.importorskip("distributed")
    programs(tmp_path, 9)
    (tmp_path / "dies.py").write_text("import os\nos._exit(9)\n")
    jobs = "".join(
        f'[[job]]\ninput = "part{n}.apt"\n' + ('macros = ["dies.py"]\n' if n == 4 else "") + "\n"
        for n in range(9)
    )
    (tmp_path / "jobs.toml").write_text('[defaults]\nmachine = "linuxcnc-mill"\n\n' + jobs)
    with distributed.LocalCluster(
        n_workers=1, threads_per_worker=1, processes=True, dashboard_address=":0"
    ) as cluster:
        result = batch(
            "--manifest",
            str(tmp_path / "jobs.toml"),
            "--out",
            str(tmp_path / "o"),
            "--scheduler",
            cluster.scheduler_address,
            "--json",
            str(tmp_path / "s.json"),
        )
    assert result.exit_code == 1, result.output
    assert statuses(tmp_path / "s.json") == ["posted"] * 4 + ["crashed"] + ["posted"] * 4


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
