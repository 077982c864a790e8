"""``gecent batch``: many CL files on many machines, posted in parallel on the local cores
or on a Dask cluster, with a summary (docs/batch.md)."""

from __future__ import annotations

import shutil
import signal
import sys
import threading
import time
from collections.abc import Callable
from functools import wraps
from pathlib import Path
from typing import Any

import click
from gecent.core.batch.jobs import (
    JobDefaults,
    check_settings,
    checked,
    jobs_from_manifest,
    jobs_from_sources,
    parse_optab,
)
from gecent.core.batch.runner import Settings, default_workers, run_batch
from gecent.core.batch.state import STATE_NAME
from gecent.core.batch.summary import as_csv, as_json, rows, table, totals
from gecent.core.batch.worker import Outcome
from gecent.core.cli_support import DIALECT_HELP, installed_plugins, reporting_errors
from gecent.core.errors import EXIT_BAD_INPUT, InputError
from gecent.core.motion.guard import DEFAULT_MAX_SEGMENTS

EXIT_SOME_FAILED = 1
EXIT_INTERRUPTED = 130


def _interruptible(command: Callable[..., None]) -> Callable[..., None]:
    """Ctrl-C, and SIGTERM (a service stopping) as Ctrl-C, stop the batch with exit 130: the
    queued jobs are dropped, the workers stopped and what finished is recorded."""

    def stop(signum: int, frame: object) -> None:
        raise KeyboardInterrupt

    @wraps(command)
    def run(*args: Any, **kwargs: Any) -> None:
        if threading.current_thread() is threading.main_thread():
            signal.signal(signal.SIGTERM, stop)
        try:
            command(*args, **kwargs)
        except KeyboardInterrupt:
            click.echo("gecent batch: interrupted; the jobs that finished are recorded", err=True)
            sys.exit(EXIT_INTERRUPTED)

    return run


@click.command("batch")
@click.argument("sources", nargs=-1, type=click.Path(exists=True))
@click.option(
    "-m", "--manifest", type=click.Path(dir_okay=False), help="A TOML or CSV list of jobs."
)
@click.option(
    "--machine",
    "machines",
    multiple=True,
    metavar="ID",
    help="Machine number, name or .toml file for every file (default: each file's "
    "MACHIN/GECENT); repeat to post every file on several machines, each into a folder of "
    "its own.",
)
@click.option(
    "--out",
    type=click.Path(file_okay=False),
    default="posted",
    show_default=True,
    help="Folder of the outputs (the inputs' folders mirrored in it).",
)
@click.option("--suffix", default=".tape", show_default=True, help="The tape files' suffix.")
@click.option(
    "--listing/--no-listing",
    default=None,
    help="Write every listing, or none (default: as gecent post, only where the tape is "
    "not G-code).",
)
@click.option("--punch", type=click.Choice(["eia", "ascii"]), help="Also punch each tape.")
@click.option("--dialect", metavar="NAME", help=DIALECT_HELP)
@click.option(
    "--optab",
    metavar="N=V;...",
    help="Options set on every job's machine as MACHIN's OPTAB sets them.",
)
@click.option(
    "--macros", multiple=True, type=click.Path(dir_okay=False, exists=True), metavar="FILE"
)
@click.option(
    "--max-segments", type=click.IntRange(min=0), default=DEFAULT_MAX_SEGMENTS, show_default=True
)
@click.option(
    "-j",
    "--jobs",
    "workers",
    type=click.IntRange(min=1),
    help="Local worker processes (default: one per core).",
)
@click.option(
    "--scheduler",
    metavar="ADDRESS",
    help="Post on this Dask cluster (tcp://host:8786) instead of local processes; needs "
    "pip install 'gecent[dask]' here and gecent with the packs on the workers.",
)
@click.option("--verify", is_flag=True, help="Check each G-code tape with rs274 (gecent verify).")
@click.option("--force", is_flag=True, help="Post every job, changed or not.")
@click.option(
    "--dry-run",
    is_flag=True,
    help="Only list the jobs: which would post and which are unchanged (skipped).",
)
@click.option(
    "--timeout",
    type=click.FloatRange(min=0, min_open=True),
    metavar="SECONDS",
    help="Stop a job that runs longer (local workers).",
)
@click.option(
    "--state",
    type=click.Path(dir_okay=False),
    help=f"The skip-unchanged record (default: {STATE_NAME} in the output folder, or "
    "beside the manifest).",
)
@click.option("--json", "json_path", type=click.Path(dir_okay=False, allow_dash=True))
@click.option("--csv", "csv_path", type=click.Path(dir_okay=False, allow_dash=True))
@click.option("--progress/--no-progress", default=None, help="Default: on a terminal.")
@click.option("-q", "--quiet", is_flag=True, help="No table; only the totals line.")
@reporting_errors
@_interruptible
def batch_command(
    sources: tuple[str, ...],
    manifest: str | None,
    machines: tuple[str, ...],
    out: str,
    suffix: str,
    listing: bool | None,
    punch: str | None,
    dialect: str | None,
    optab: str | None,
    macros: tuple[str, ...],
    max_segments: int,
    workers: int | None,
    scheduler: str | None,
    verify: bool,
    force: bool,
    dry_run: bool,
    timeout: float | None,
    state: str | None,
    json_path: str | None,
    csv_path: str | None,
    progress: bool | None,
    quiet: bool,
) -> None:
    """Post CL files (files, folders searched for CL files, or a manifest's jobs) in
    parallel and print a summary. Jobs whose CL file, machine, settings and gecent are
    unchanged since the last batch into the same outputs are skipped (--force posts them).
    Exit 0 when every job posted (or was skipped), 1 when any failed, 2 for bad batch
    input."""
    if bool(sources) == bool(manifest):
        raise InputError("name CL files or folders, or give --manifest (not both)")
    plugins = installed_plugins()  # (its warnings, once)
    defaults = JobDefaults(
        machines=tuple(machines) or (None,),
        out=Path(out),
        suffix=suffix if suffix.startswith(".") else "." + suffix,
        listing=listing,
        punch=punch,
        dialect=dialect,
        optab=parse_optab(optab) if optab else (),
        macros=macros,
        max_segments=max_segments,
        verify=verify,
    )
    if manifest is not None:
        if len(machines) > 1:
            raise InputError("a manifest names each job's machine: give at most one --machine")
        jobs = jobs_from_manifest(manifest, defaults)
        state_folder = Path(manifest).parent  # (the jobs' outputs go where it says)
    else:
        jobs = jobs_from_sources(list(sources), defaults)
        state_folder = Path(out)
    state_path = Path(state) if state else state_folder / STATE_NAME
    protected = {str(state_path): "the batch's state file"}
    if manifest is not None:
        protected[manifest] = "the manifest"
    for given, what in ((json_path, "the JSON summary"), (csv_path, "the CSV summary")):
        if given is not None and given != "-":
            protected[given] = what
    checked(jobs, protected)
    check_settings(jobs, plugins)
    count = workers or default_workers()
    settings = Settings(
        workers=count,
        scheduler=scheduler,
        force=force,
        dry_run=dry_run,
        timeout=timeout,
        state=state_path,
    )
    show = sys.stderr.isatty() if progress is None else progress
    bar = None
    if show:
        from tqdm import tqdm

        tqdm.monitor_interval = 0  # no monitor thread in a process the pool forks
        bar = tqdm(total=len(jobs), unit=" jobs", file=sys.stderr, leave=False)

    def advance(outcome: Outcome) -> None:
        if bar is not None:
            bar.update(1)
            bar.set_postfix_str(outcome.status)

    started = time.perf_counter()
    try:
        result = run_batch(jobs, settings, advance)
    finally:
        if bar is not None:
            bar.close()
    seconds = time.perf_counter() - started
    outcomes = result.outcomes
    for problem in result.problems:
        click.echo(f"gecent batch: warning: {problem}", err=True)
    found = rows(jobs, outcomes)
    where = f"Dask at {scheduler}" if scheduler else f"{count} worker{'s' * (count != 1)}"
    total = totals(found, seconds, where)
    unwritten = [
        failure
        for path, text in ((json_path, as_json(found, total)), (csv_path, as_csv(found)))
        if path is not None and (failure := _write(path, text)) is not None
    ]
    on_stdout = "-" in (json_path, csv_path)
    echo = click.echo if not on_stdout else lambda text: click.echo(text, err=True)
    if not quiet:
        width = shutil.get_terminal_size().columns if sys.stdout.isatty() else None
        echo(table(found, width))
    echo(total)
    for failure in unwritten:
        click.echo(f"gecent batch: error: {failure}", err=True)
    if unwritten:
        sys.exit(EXIT_BAD_INPUT)
    if not dry_run and any(not outcome.ok for outcome in outcomes):
        sys.exit(EXIT_SOME_FAILED)


def _write(path: str, text: str) -> str | None:
    """Write a summary file; what went wrong, or None."""
    if path == "-":
        click.echo(text, nl=False)
        return None
    try:
        Path(path).parent.mkdir(parents=True, exist_ok=True)
        Path(path).write_text(text, encoding="utf-8")
    except OSError as exc:
        return f"cannot write the summary {path}: {exc.strerror or exc}"
    return None
