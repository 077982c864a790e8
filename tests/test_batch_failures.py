"""gecent batch when things go wrong: a bad job, a job that hangs or kills its worker
(locally and on Dask), a stopped batch, a damaged state file, bad manifest values; and the
Dask cluster's equivalence with the local run (docs/batch.md)."""

from __future__ import annotations

import contextlib
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from .batchkit import CORPUS, HELLO, batch, programs, statuses, summary


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
    try:
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
    finally:  # a batch that did not stop must not leave its hanging workers behind
        process.kill()
        for pid in workers:
            with contextlib.suppress(OSError):
                if b"gecent" in Path(f"/proc/{pid}/cmdline").read_bytes():  # (still ours)
                    os.kill(pid, signal.SIGKILL)


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
