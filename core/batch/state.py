"""The skip-unchanged rule: a job is posted again only when its CL file, its settings, its
machine's file, the installed plugins or gecent's version changed, or when one of its outputs
is missing or was changed since (a content hash of each, kept in a state file beside the
outputs; ``--force`` posts everything)."""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from gecent.core import __version__
from gecent.core.batch.jobs import Job, listing_path
from gecent.core.batch.worker import Outcome, text_hash
from gecent.core.errors import InputError, SourcePosition
from gecent.core.plugins import PluginSet

STATE_NAME = ".gecent-batch.json"
STATE_FORMAT = 1
_KINDS = ("tape", "listing", "punch")


def plugins_fingerprint(plugins: PluginSet) -> str:
    """Every installed plugin with its distribution's version: upgrading a pack re-posts."""
    rows = sorted(
        f"{info.family}:{info.key}:{info.distribution}:{info.version}" for info in plugins.all()
    )
    return hashlib.sha256("\n".join(rows).encode()).hexdigest()


def file_hash(path: str | Path) -> str:
    digest = hashlib.sha256()
    with open(path, "rb") as handle:
        for chunk in iter(lambda: handle.read(1 << 20), b""):
            digest.update(chunk)
    return digest.hexdigest()


def job_key(job: Job, fingerprint: str) -> str | None:
    """What the job's outputs depend on, besides the machine the CL file's MACHIN chooses
    (checked apart: :meth:`State.unchanged`); None when the CL file cannot be read (the job
    then posts, and fails naming why)."""
    try:
        input_hash = file_hash(job.input)
    except OSError:
        return None
    settings = {
        "gecent": __version__,
        "plugins": fingerprint,
        "input": input_hash,
        "machine": job.machine,
        "machine_text": text_hash(job.machine_text) if job.machine_text is not None else None,
        "listing": job.listing,
        "punch": job.punch,
        "dialect": job.dialect,
        "optab": job.optab,
        "macros": [(name, text_hash(text)) for name, text in job.macros],
        "max_segments": job.max_segments,
        "outputs": [job.tape, listing_path(job) if job.listing is not None else None],
    }
    return hashlib.sha256(json.dumps(settings, sort_keys=True).encode()).hexdigest()


def output_paths(job: Job, outcome: Outcome) -> dict[str, str]:
    """Where each output the job made goes."""
    paths = {"tape": job.tape, "listing": listing_path(job)}
    if job.punch is not None:
        paths["punch"] = job.punch[1]
    return {kind: paths[kind] for kind in _KINDS if kind in outcome.outputs}


@dataclass
class State:
    path: Path
    jobs: dict[str, dict[str, Any]] = field(default_factory=dict)

    @classmethod
    def load(cls, path: Path, force: bool = False) -> State:
        """The state file's record; with ``force`` a record that cannot be read is started
        afresh (everything posts anyway)."""
        state = cls(path)
        if not path.exists():
            return state
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError) as exc:
            if force:
                return state
            raise InputError(
                f"the batch state file cannot be read ({exc}); remove it or give --force",
                SourcePosition(str(path)),
            ) from None
        jobs = data.get("jobs") if isinstance(data, dict) else None
        if (
            not isinstance(data, dict)
            or data.get("format") != STATE_FORMAT
            or not isinstance(jobs, dict)
            or not all(isinstance(entry, dict) for entry in jobs.values())
        ):
            if path.stat().st_size and not force:
                raise InputError(
                    "this is not a gecent batch state file (or one of another format): give "
                    "another --state, remove it, or give --force to replace it",
                    SourcePosition(str(path)),
                )
            return state
        state.jobs = dict(jobs)
        return state

    def unchanged(self, job: Job, key: str | None, plugins: PluginSet) -> Outcome | None:
        """The job's last outcome when nothing it depends on changed, else None (also when
        its entry was damaged: the job then simply posts)."""
        try:
            return self._unchanged(job, key, plugins)
        except (TypeError, ValueError, AttributeError):
            return None

    def _unchanged(self, job: Job, key: str | None, plugins: PluginSet) -> Outcome | None:
        entry = self.jobs.get(_entry_key(job))
        if key is None or entry is None or entry.get("key") != key:
            return None
        if job.verify and not entry.get("verified"):
            return None  # posted before without the check asked for now
        if job.machine_text is not None:
            current = text_hash(job.machine_text)
        else:
            pack = plugins.machine(entry.get("machine", ""))
            current = text_hash(pack.text) if pack is not None else ""
        if not current or current != entry.get("machine_hash"):
            return None
        for path, digest in dict(entry.get("outputs", {})).items():
            try:
                if file_hash(path) != digest:
                    return None
            except OSError:
                return None
        summary = entry.get("summary", {})
        return Outcome(
            job.number,
            "skipped",
            0,
            warnings=int(summary.get("warnings", 0)),
            machine=str(entry.get("machine", "")),
            machine_hash=str(entry.get("machine_hash", "")),
            blocks=int(summary.get("blocks", 0)),
            tape_feet=float(summary.get("tape_feet", 0.0)),
            cut_minutes=float(summary.get("cut_minutes", 0.0)),
            verify=str(entry.get("verify", "")) if job.verify else "",
        )

    def remove_left_over(self, job: Job, written: dict[str, str]) -> list[str]:
        """The files this job's last batch wrote that it writes no longer (a listing or
        punch its settings dropped) are removed, when they are still as the batch wrote
        them (a file changed since is someone else's now); the paths removed."""
        entry = self.jobs.get(_entry_key(job))
        earlier = entry.get("outputs") if isinstance(entry, dict) else None
        removed = []
        for path, digest in dict(earlier or {}).items():
            if path in written:
                continue
            try:
                if file_hash(path) == digest:
                    os.remove(path)
                    removed.append(path)
            except OSError:
                continue
        return removed

    def record(self, job: Job, key: str | None, outcome: Outcome, written: dict[str, str]) -> None:
        """A job posted (and written): remember what it depended on and what it wrote."""
        if key is None:
            return
        self.jobs[_entry_key(job)] = {
            "key": key,
            "input": job.input,
            "machine": outcome.machine,
            "machine_hash": outcome.machine_hash,
            "outputs": written,
            # a tape rs274 cannot read (not G-code) counts as checked as far as it can be
            "verified": outcome.verify == "passed" or outcome.verify.startswith("n/a"),
            "verify": outcome.verify,
            "summary": {
                "warnings": outcome.warnings,
                "blocks": outcome.blocks,
                "tape_feet": outcome.tape_feet,
                "cut_minutes": outcome.cut_minutes,
            },
        }

    def forget(self, job: Job) -> None:
        """A job failed: it posts again next time, whatever changed."""
        self.jobs.pop(_entry_key(job), None)

    def save(self) -> str | None:
        """Write the record; what went wrong, or None (the batch's outputs stand either way:
        the next batch then posts them again)."""
        temporary = self.path.with_name(self.path.name + f".{os.getpid()}.tmp")
        data = {"format": STATE_FORMAT, "gecent": __version__, "jobs": self.jobs}
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)
            temporary.write_text(json.dumps(data, indent=1, sort_keys=True), encoding="utf-8")
            os.replace(temporary, self.path)
        except OSError as exc:
            with contextlib.suppress(OSError):
                temporary.unlink(missing_ok=True)
            return f"cannot write the batch state file {self.path}: {exc.strerror or exc}"
        return None


def _entry_key(job: Job) -> str:
    return str(Path(job.tape).resolve())
