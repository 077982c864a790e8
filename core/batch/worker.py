"""One batch job, run where a worker is (a local process or a Dask worker): the post into a
folder of its own, its outputs read back as bytes, and with ``verify`` the tape checked
against the CL file by LinuxCNC's rs274. Nothing here raises: every failure is the job's
outcome, so one bad job never stops the others."""

from __future__ import annotations

import hashlib
import signal
import tempfile
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field, replace
from functools import lru_cache
from pathlib import Path

from gecent.core.batch.jobs import Job
from gecent.core.errors import EXIT_INTERNAL, Diagnostic, GecentError, InputError, SourcePosition
from gecent.core.machine.definition import MachineDefinition
from gecent.core.output.tape import tape_feet
from gecent.core.plugins import PluginSet

EXIT_TIMEOUT = 124  # as timeout(1) reports a command it stopped


@dataclass
class Outcome:
    """What a job came to. ``outputs`` maps "tape", "listing" and "punch" to their bytes
    (none when the post failed); ``machine`` is the pack or file the post used and
    ``machine_hash`` its text's hash, for the skip-unchanged rule."""

    number: int
    status: str  # posted, failed, skipped, verify-failed, crashed
    exit_status: int
    error: str = ""
    warnings: int = 0
    machine: str = ""
    machine_hash: str = ""
    blocks: int = 0
    tape_feet: float = 0.0
    cut_minutes: float = 0.0
    seconds: float = 0.0
    verify: str = ""  # passed, FAILED, n/a (...), or "" when not asked
    messages: list[str] = field(default_factory=list)  # the warnings, as gecent post gives them
    outputs: dict[str, bytes] = field(default_factory=dict, repr=False)

    @property
    def ok(self) -> bool:
        return self.status in ("posted", "skipped")


class JobTimedOut(BaseException):
    """A BaseException, as KeyboardInterrupt is: no handler of the post's own for a bad
    record or a failing macro file may take it for the job's error."""


def run_job(job: Job, timeout: float | None = None) -> Outcome:
    """Post ``job`` (and verify it when asked); every failure is in the outcome."""
    started = time.perf_counter()
    try:
        with _time_limit(timeout), tempfile.TemporaryDirectory(prefix="gecent-job-") as folder:
            outcome = _post(job, Path(folder))
    except JobTimedOut:
        outcome = Outcome(
            job.number, "failed", EXIT_TIMEOUT, f"timed out after {timeout:g} s (--timeout)"
        )
    except GecentError as exc:
        outcome = Outcome(job.number, "failed", exc.exit_status, str(exc))
    except Exception as exc:  # a bug in gecent: this job fails, the batch goes on
        outcome = Outcome(
            job.number, "failed", EXIT_INTERNAL, f"internal error: {type(exc).__name__}: {exc}"
        )
    outcome.seconds = time.perf_counter() - started
    return outcome


def run_jobs(jobs: list[Job], timeout: float | None = None) -> list[Outcome]:
    """Several jobs in one task (a Dask task costs more than a small post)."""
    return [run_job(job, timeout) for job in jobs]


def _post(job: Job, folder: Path) -> Outcome:
    from gecent.core.dispatch.post import post
    from gecent.core.output.modern import modern_output
    from gecent.core.output.sinks import Sinks, output_sinks

    source = _source(job, folder)
    plugins = _plugins(job.macros, folder)
    warnings: list[str] = []
    machine = _machine(job, plugins, warnings)
    tape = folder / "tape"
    listing = folder / "listing"
    punch = (job.punch[0], str(folder / "punch")) if job.punch is not None else None
    used: list[MachineDefinition] = []

    def make_sinks(chosen: MachineDefinition) -> Sinks:
        used.append(chosen)
        wanted = job.listing is not None and not (job.listing == "auto" and modern_output(chosen))
        return output_sinks(plugins, chosen, tape, str(listing) if wanted else None, punch, None)

    def report(diagnostic: Diagnostic) -> None:
        warnings.append(str(diagnostic).replace(str(source), job.input))

    try:
        result = post(
            str(source),
            plugins,
            machine,
            None,
            make_sinks,
            report,
            job.max_segments,
            fast=True,
            dialect=job.dialect,
        )
    except GecentError as exc:
        message = str(exc).replace(str(source), job.input)
        return Outcome(
            job.number, "failed", exc.exit_status, message, len(warnings), messages=warnings
        )
    chosen = used[0] if used else result.machine
    outputs = {"tape": tape.read_bytes()} if tape.exists() else {}
    if result.punch_suppressed:
        outputs = {}
    if listing.exists():
        outputs["listing"] = listing.read_bytes()
    if punch is not None and Path(punch[1]).exists() and not result.punch_suppressed:
        outputs["punch"] = Path(punch[1]).read_bytes()
    lines = outputs.get("tape", b"").decode("ascii", errors="replace").splitlines()
    outcome = Outcome(
        job.number,
        "posted",
        0,
        warnings=len(warnings),
        machine=_machine_name(job, chosen),
        machine_hash=machine_hash(job, plugins, chosen),
        blocks=sum(1 for line in lines if line.strip()),
        tape_feet=tape_feet(lines),
        cut_minutes=result.cut_minutes,
        messages=warnings,
        outputs=outputs,
    )
    if job.verify:
        _verify(job, outcome, tape, source, plugins, machine, chosen)
    return outcome


def _verify(
    job: Job,
    outcome: Outcome,
    tape: Path,
    source: Path,
    plugins: PluginSet,
    machine: str | MachineDefinition | None,
    chosen: MachineDefinition,
) -> None:
    from gecent.core.output.modern import modern_output
    from gecent.core.verify.check import verify

    if not modern_output(chosen) and chosen.kinematics is None:
        outcome.verify = "n/a (the tape is not G-code for rs274)"
        return
    try:
        result = verify(str(tape), str(source), plugins, machine, dialect=job.dialect)
    except GecentError as exc:
        outcome.status, outcome.exit_status = "verify-failed", exc.exit_status
        outcome.verify = "FAILED"
        outcome.error = f"verify: {exc}".replace(str(source), job.input)
        outcome.outputs = {}
        return
    if result.passed:
        outcome.verify = "passed"
        return
    report = result.report()
    first = next((i for i, line in enumerate(report) if "FAILED" in line), None)
    told = report[first:][:1] if first is not None else ["verify: FAILED"]
    told += [line.strip() for line in report[(first or 0) + 1 :] if line.startswith("  ")][:2]
    outcome.status, outcome.exit_status = "verify-failed", 1
    outcome.verify = "FAILED"
    outcome.error = "; ".join(told).replace(str(source), job.input)
    outcome.outputs = {}  # a tape that does not follow its CL file is not written


def _source(job: Job, folder: Path) -> Path:
    """The CL file: its own path, or its shipped bytes spooled under its own name."""
    if job.input_bytes is None:
        return Path(job.input)
    spooled = folder / "input" / Path(job.input).name
    spooled.parent.mkdir()
    spooled.write_bytes(job.input_bytes)
    return spooled


def _machine(job: Job, plugins: PluginSet, notes: list[str]) -> str | MachineDefinition | None:
    """What ``--machine`` would give the post: a name or number, or the machine file's
    definition; with ``optab`` the definition with those options set as MACHIN's OPTAB
    sets them (the manual's checks and warnings included)."""
    from gecent.core.families import MachinePack
    from gecent.core.machine.selection import MachinRequest, apply_machin_options

    definition: MachineDefinition | None = None
    if job.machine_text is not None and job.machine is not None:
        definition = MachinePack.from_text(job.machine_text, job.machine).load()
    if not job.optab:
        return definition if definition is not None else job.machine
    if definition is None:
        if job.machine is None:
            raise InputError(f"job {job.number}: optab needs the job's machine named")
        pack = plugins.machine(job.machine)
        if pack is None:
            raise InputError(f"machine {job.machine!r} is not installed (see 'gecent machines')")
        definition = pack.load()
    where = SourcePosition(job.input)
    request = MachinRequest(definition.number, [(n, v, where) for n, v in job.optab])
    changed, changes_notes = apply_machin_options(definition, request)
    notes.extend(f"optab: {note.text}" for note in changes_notes)
    return changed


def _machine_name(job: Job, chosen: MachineDefinition) -> str:
    if job.machine_text is not None and job.machine is not None:
        return job.machine
    return chosen.name or str(chosen.number)


def machine_hash(job: Job, plugins: PluginSet, chosen: MachineDefinition) -> str:
    """The hash of the machine file's text the post used (a pack's or the job's file)."""
    if job.machine_text is not None:
        return text_hash(job.machine_text)
    pack = plugins.machine(chosen.name) or (
        plugins.machine(chosen.number) if chosen.number is not None else None
    )
    return text_hash(pack.text) if pack is not None else ""


def text_hash(text: str) -> str:
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


@lru_cache(maxsize=1)
def installed() -> PluginSet:
    """The installed plugins, loaded once per worker process."""
    from gecent.core.plugins import get_plugins

    return get_plugins()


def _plugins(macros: tuple[tuple[str, str], ...], folder: Path) -> PluginSet:
    """The installed plugins (loaded once per worker process), plus the job's macro files."""
    from gecent.core.macros.files import load_macro_file
    from gecent.core.macros.table import with_macros

    plugins = installed()
    for number, (named, text) in enumerate(macros):
        spooled = folder / "macros" / str(number) / Path(named).name
        spooled.parent.mkdir(parents=True)
        spooled.write_text(text, encoding="utf-8")
        try:
            loaded = load_macro_file(spooled)
        except GecentError as exc:  # named as the job names the file, not as spooled
            where = getattr(exc, "where", None)
            if isinstance(where, SourcePosition) and where.file == str(spooled):
                exc.where = replace(where, file=named)  # type: ignore[attr-defined]
            raise
        plugins = with_macros(plugins, loaded, f"file {named}")
    return plugins


@contextmanager
def _time_limit(seconds: float | None) -> Iterator[None]:
    """Stop a job that runs longer than ``seconds`` (on a worker's main thread only: a
    Dask worker's jobs run in threads, where its own timeouts apply)."""
    usable = (
        seconds is not None
        and seconds > 0
        and hasattr(signal, "setitimer")
        and threading.current_thread() is threading.main_thread()
    )
    if not usable:
        yield
        return

    def expire(signum: int, frame: object) -> None:
        raise JobTimedOut()

    previous = signal.signal(signal.SIGALRM, expire)
    signal.setitimer(signal.ITIMER_REAL, seconds)  # type: ignore[arg-type]
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
