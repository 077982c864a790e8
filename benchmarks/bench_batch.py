"""Batch posting throughput (issue 23's measure): ``--copies`` copies of every CL file of the
shared corpus (the two APT part programs, which are not CL data and fail at their first
assignment, stay in as failing jobs) posted on linuxcnc-mill by ``gecent batch`` with 1 and
2 local workers and through a local Dask cluster of 2 worker processes, every job posted
(``--force``). In the same run, the same jobs posted one after another in this process
(``gecent post``'s work with no pool) are the baseline: the figures are jobs/s and each
way's speed as a ratio of the baseline's (this machine is noisy; ratios measured in one run
mean more than absolute times). Best of ``--repeat`` runs each.

    python benchmarks/bench_batch.py [--copies 200] [--repeat 1] [--no-dask] [--json]
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import sys
import tempfile
import time
from pathlib import Path

from gecent.core.batch.jobs import JobDefaults, cl_files, jobs_from_sources
from gecent.core.batch.runner import Settings, run_batch
from gecent.core.batch.worker import run_job

CORPUS = Path(__file__).resolve().parents[2] / "shared" / "corpus"


def library(folder: Path, copies: int) -> int:
    files = cl_files(CORPUS)
    for copy in range(copies):
        target = folder / f"copy{copy:04d}"
        for source in files:
            place = target / source.relative_to(CORPUS)
            place.parent.mkdir(parents=True, exist_ok=True)
            os.link(source, place) if hasattr(os, "link") else shutil.copy(source, place)
    return copies * len(files)


def timed(run: object) -> float:
    started = time.perf_counter()
    run()  # type: ignore[operator]
    return time.perf_counter() - started


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--copies", type=int, default=200)
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--no-dask", action="store_true")
    parser.add_argument("--json", action="store_true")
    arguments = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="gecent-bench-batch-") as scratch:
        folder = Path(scratch)
        count = library(folder / "in", arguments.copies)
        defaults = JobDefaults(machines=("linuxcnc-mill",), out=folder / "out")
        jobs = jobs_from_sources([str(folder / "in")], defaults)
        results: dict[str, float] = {}

        def sequential() -> None:
            for job in jobs:
                run_job(job)

        def pool(workers: int, scheduler: str | None = None) -> None:
            shutil.rmtree(folder / "out", ignore_errors=True)
            outcomes = run_batch(jobs, Settings(workers, scheduler, force=True)).outcomes
            assert len(outcomes) == len(jobs)

        run_job(jobs[0])  # the plugins and the machine loaded before any way is timed
        ways = [("in-process, one after another", sequential)]
        ways += [(f"gecent batch -j {n}", lambda n=n: pool(n)) for n in (1, 2)]
        cluster = None
        if not arguments.no_dask:
            from distributed import LocalCluster

            cluster = LocalCluster(
                n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0"
            )
            address = cluster.scheduler_address
            ways.append(("gecent batch --scheduler (Dask, 2 workers)", lambda: pool(2, address)))
        try:
            for name, way in ways:
                results[name] = min(timed(way) for _ in range(arguments.repeat))
        finally:
            if cluster is not None:
                cluster.close()
    base = results["in-process, one after another"]
    rows = [
        {
            "way": name,
            "seconds": round(s, 2),
            "jobs_per_s": round(count / s, 1),
            "ratio": round(base / s, 2),
        }
        for name, s in results.items()
    ]
    if arguments.json:
        json.dump({"jobs": count, "cpus": os.cpu_count(), "rows": rows}, sys.stdout, indent=1)
        print()
        return
    print(
        f"{count} jobs ({arguments.copies} copies of the corpus) on linuxcnc-mill, "
        f"{os.cpu_count()} CPUs"
    )
    for row in rows:
        print(
            f"  {row['way']:<45} {row['seconds']:>8.2f} s  {row['jobs_per_s']:>7.1f} jobs/s"
            f"  x{row['ratio']:.2f}"
        )


if __name__ == "__main__":
    main()
