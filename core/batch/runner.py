"""Running a batch: the jobs whose inputs changed go to a pool of local processes or to a Dask
cluster; each outcome's outputs are written here, each in place at once (a temporary file
renamed), only when its job succeeded. One failed, hung or crashed job never stops the
others."""

from __future__ import annotations

import contextlib
import hashlib
import os
import signal
from collections.abc import Callable, Iterable, Iterator
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass
from functools import partial
from importlib import import_module
from multiprocessing import get_all_start_methods, get_context
from multiprocessing.context import BaseContext
from pathlib import Path
from typing import Any, TypeVar

from gecent.core.batch.jobs import Job
from gecent.core.batch.state import State, job_key, output_paths, plugins_fingerprint
from gecent.core.batch.worker import Outcome, installed, run_job, run_jobs
from gecent.core.errors import EXIT_INTERNAL, InputError

T = TypeVar("T")
CRASHED = (
    "the worker process died while posting this job (killed, out of memory or a crash in "
    "an extension); the other jobs went on"
)


@dataclass
class Settings:
    workers: int = 1
    scheduler: str | None = None
    force: bool = False
    dry_run: bool = False  # say which jobs would post, post none
    timeout: float | None = None
    state: Path | None = None


@dataclass
class BatchResult:
    outcomes: list[Outcome]
    problems: list[str]  # what went wrong beside the jobs (the state file not written)


def run_batch(
    jobs: list[Job], settings: Settings, progress: Callable[[Outcome], None] | None = None
) -> BatchResult:
    """Post ``jobs``; the outcomes in the jobs' order."""
    plugins = installed()
    fingerprint = plugins_fingerprint(plugins)
    state = State.load(settings.state, settings.force) if settings.state is not None else None
    keys = {job.number: job_key(job, fingerprint) for job in jobs}
    by_number = {job.number: job for job in jobs}
    outcomes: dict[int, Outcome] = {}
    problems: list[str] = []
    todo: list[Job] = []
    for job in jobs:
        kept = None
        if state is not None and not settings.force:
            kept = state.unchanged(job, keys[job.number], plugins)
        if kept is not None:
            outcomes[job.number] = kept
            if progress is not None:
                progress(kept)
        else:
            todo.append(job)
    if settings.dry_run:
        listed = [outcomes.get(job.number) or Outcome(job.number, "to post", 0) for job in jobs]
        return BatchResult(listed, problems)
    if settings.scheduler is not None:
        stream = _on_dask(todo, settings.scheduler, settings.timeout)
    else:
        stream = _on_local_processes(todo, settings.workers, settings.timeout)
    try:
        for outcome in stream:
            job = by_number[outcome.number]
            if outcome.ok:
                written = _write_outputs(job, outcome)
                if state is not None and outcome.ok:
                    state.remove_left_over(job, written)
                    state.record(job, keys[job.number], outcome, written)
            elif state is not None:
                state.forget(job)
            outcome.outputs = {}
            outcomes[job.number] = outcome
            if progress is not None:
                progress(outcome)
    finally:
        if state is not None:  # what finished is remembered even when the batch is stopped
            problem = state.save()
            if problem is not None:
                problems.append(problem)
    ordered = [outcomes[job.number] for job in jobs if job.number in outcomes]
    return BatchResult(ordered, problems)


def _write_outputs(job: Job, outcome: Outcome) -> dict[str, str]:
    """Every output written to a temporary file first, then all renamed into place, so a
    job's outputs change together or not at all; the hashes of what was written. A file
    that cannot be written fails the job and leaves its earlier outputs as they were."""
    paths = output_paths(job, outcome)
    staged: list[tuple[Path, Path]] = []
    written: dict[str, str] = {}
    try:
        for kind, path in paths.items():
            data = outcome.outputs[kind]
            target = Path(path)
            target.parent.mkdir(parents=True, exist_ok=True)
            temporary = target.with_name(f".{target.name}.{os.getpid()}.tmp")
            staged.append((temporary, target))
            temporary.write_bytes(data)
            written[path] = hashlib.sha256(data).hexdigest()
        for temporary, target in staged:
            os.replace(temporary, target)
    except OSError as exc:
        for temporary, _ in staged:
            with contextlib.suppress(OSError):
                temporary.unlink(missing_ok=True)
        outcome.status, outcome.exit_status = "failed", 2
        failed = next((t for tmp, t in staged if str(tmp) == exc.filename), exc.filename)
        outcome.error = f"cannot write {failed}: {exc.strerror or exc}"
        return {}
    return written


def _warm() -> None:
    """A worker loads the plugins before its first job (not inside its --timeout). It
    leaves Ctrl-C to the batch, which stops it, and dies at SIGTERM (a forked worker would
    otherwise keep the batch's own handlers)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    import gecent.core.dispatch.post  # noqa: F401

    installed()


def _on_local_processes(jobs: list[Job], workers: int, timeout: float | None) -> Iterator[Outcome]:
    """The jobs on ``workers`` local processes. A worker that dies breaks the pool: the
    jobs that were running then each run again in a process of their own (so the one that
    kills its process is named ``crashed``), and the others go to a new pool."""
    if not jobs:
        return
    context = get_context("fork" if "fork" in get_all_start_methods() else "spawn")
    task = partial(run_job, timeout=timeout)
    broken: list[Job] = []
    running: set[Future[Outcome]] = set()
    pool = ProcessPoolExecutor(max_workers=max(1, workers), mp_context=context, initializer=_warm)
    try:
        futures: dict[Future[Outcome], Job] = {pool.submit(task, job): job for job in jobs}
        pending = set(futures)
        while pending:
            running = {future for future in pending if future.running()}
            done, pending = wait(pending, return_when=FIRST_COMPLETED)
            for future in done:
                try:
                    yield future.result()
                except BrokenProcessPool:
                    broken.append(futures[future])
    except BaseException:
        # stopped (Ctrl-C, SIGTERM, the caller gone): the queued jobs are dropped and the
        # workers stopped at once, not left to run on
        _stop(pool)
        raise
    pool.shutdown()
    if not broken:
        return
    was_running = {futures[future].number for future in running}
    suspects = [job for job in broken if job.number in was_running] or broken
    for job in suspects:
        yield _isolated(job, timeout, context)
    rest = [job for job in broken if job not in suspects]
    yield from _on_local_processes(rest, workers, timeout)


def _stop(pool: ProcessPoolExecutor) -> None:
    # (the executor has no public way to stop a job that is running: its processes)
    processes = list((getattr(pool, "_processes", None) or {}).values())
    pool.shutdown(wait=False, cancel_futures=True)
    for process in processes:
        with contextlib.suppress(Exception):
            process.terminate()


def _isolated(job: Job, timeout: float | None, context: BaseContext) -> Outcome:
    with ProcessPoolExecutor(max_workers=1, mp_context=context, initializer=_warm) as pool:
        try:
            outcome: Outcome = pool.submit(run_job, job, timeout).result()
            return outcome
        except BrokenProcessPool:
            return Outcome(job.number, "crashed", EXIT_INTERNAL, CRASHED)


CHUNK_JOBS = 16  # at most this many jobs in one Dask task,
CHUNK_BYTES = 4 << 20  # and at most about this many bytes of CL files


def _on_dask(jobs: list[Job], scheduler: str, timeout: float | None) -> Iterator[Outcome]:
    """The jobs on a Dask cluster: each ships its CL file's bytes and gets its outputs back,
    so the workers need gecent and the machine packs installed, not this file system. Small
    jobs go several to a task (a task costs the scheduler more than a small post), and a
    bounded number of tasks is in flight, so the CL files are not all held at once. The jobs
    of a task whose worker died run again one by one at the end, so the job that kills its
    worker is named ``crashed`` and the others are posted."""
    try:
        distributed: Any = import_module("distributed")
    except ImportError:
        raise InputError(
            "--scheduler needs the Dask distributed package: pip install 'gecent[dask]'"
        ) from None
    if not jobs:
        return
    try:
        client = distributed.Client(scheduler, timeout="30s")
    except (OSError, TimeoutError, ValueError) as exc:
        raise InputError(f"cannot reach the Dask scheduler at {scheduler}: {exc}") from None
    with client:
        _check_workers(client)
        workers = max(1, len(client.scheduler_info().get("workers", {})))
        size = max(1, min(CHUNK_JOBS, len(jobs) // (4 * workers)))
        queue = _chunks(jobs, size)
        in_flight: dict[Any, list[Job]] = {}
        completed = distributed.as_completed()

        def submit(chunk: list[Job]) -> None:
            future = client.submit(run_jobs, chunk, timeout, pure=False)
            in_flight[future.key] = chunk
            completed.add(future)

        for chunk in _take(queue, 2 * workers):
            submit(chunk)
        alone: list[Job] = []  # jobs whose task died: each runs again by itself, at the end
        for future in completed:
            chunk = in_flight.pop(future.key)
            try:
                yield from future.result()
            except Exception:  # KilledWorker: a job took its workers down
                alone.extend(chunk)
            future.release()
            for chunk in _take(queue, 1):
                submit(chunk)
        # one at a time, so a job that kills its worker takes no other job's task with it
        # (Dask counts a worker's death against every task it held)
        for job in sorted(alone, key=lambda job: job.number):
            try:
                yield from client.submit(run_jobs, [job], timeout, pure=False).result()
            except Exception as exc:
                yield Outcome(job.number, "crashed", EXIT_INTERNAL, f"{CRASHED} ({exc})")


def _chunks(jobs: list[Job], size: int) -> Iterator[list[Job]]:
    """The jobs, shipped, ``size`` to a chunk (fewer when their CL files are large)."""
    chunk: list[Job] = []
    held = 0
    for job in jobs:
        shipped = job.shipped()
        chunk.append(shipped)
        held += len(shipped.input_bytes or b"")
        if len(chunk) >= size or held >= CHUNK_BYTES:
            yield chunk
            chunk, held = [], 0
    if chunk:
        yield chunk


def _check_workers(client: Any) -> None:
    """Every worker runs this version of gecent with the same plugins (the machine packs and
    their versions), so its outputs are the ones this host would post."""
    from gecent.core import __version__

    here = (__version__, plugins_fingerprint(installed()))
    found: dict[str, tuple[str, str]] = client.run(_worker_identity)
    if not found:
        raise InputError("the Dask cluster has no workers")
    for worker, (version, fingerprint) in found.items():
        if version != here[0]:
            raise InputError(
                f"Dask worker {worker} runs gecent {version}, this is {here[0]}: install the "
                "same gecent and machine packs on every worker"
            )
        if fingerprint != here[1]:
            raise InputError(
                f"Dask worker {worker} has other plugins or plugin versions than this host "
                "(gecent --list-plugins shows them): install the same machine packs on every "
                "worker"
            )


def _worker_identity() -> tuple[str, str]:
    try:
        from gecent.core import __version__
    except ImportError:
        return ("(not installed)", "")
    return (__version__, plugins_fingerprint(installed()))


def _take(items: Iterator[T], count: int) -> Iterable[T]:
    for _ in range(count):
        item = next(items, None)
        if item is None:
            return
        yield item


def default_workers() -> int:
    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1
