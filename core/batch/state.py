"""The skip-unchanged rule: a job is posted again only when its CL file, its settings, its
machine's file, the installed plugins or gecent's version changed, or when one of its outputs
is missing or was changed since (a content hash of each, kept in a state file beside the
outputs; ``--force`` posts everything)."""

from __future__ import annotations

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


def job_key(job: Job, fingerprint: str) -> str:
    """What the job's outputs depend on, besides the machine the CL file's MACHIN chooses
    (checked apart: :meth:`State.unchanged`)."""
    settings = {
        "gecent": __version__,
        "plugins": fingerprint,
        "input": file_hash(job.input),
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
    def load(cls, path: Path) -> State:
        if not path.exists():
            return cls(path)
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError) as exc:
            raise InputError(
                f"the batch state file cannot be read ({exc}); remove it or give --force",
                SourcePosition(str(path)),
            ) from None
        if not isinstance(data, dict) or data.get("format") != STATE_FORMAT:
            return cls(path)  # another format: everything posts again
        return cls(path, dict(data.get("jobs", {})))

    def unchanged(self, job: Job, key: str, plugins: PluginSet) -> Outcome | None:
        """The job's last outcome when nothing it depends on changed, else None."""
        entry = self.jobs.get(_entry_key(job))
        if entry is None or entry.get("key") != key:
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
        for path, digest in entry.get("outputs", {}).items():
            if not os.path.exists(path) or file_hash(path) != digest:
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
            verify="passed" if job.verify else "",
        )

    def record(self, job: Job, key: str, outcome: Outcome, written: dict[str, str]) -> None:
        """A job posted (and written): remember what it depended on and what it wrote."""
        self.jobs[_entry_key(job)] = {
            "key": key,
            "input": job.input,
            "machine": outcome.machine,
            "machine_hash": outcome.machine_hash,
            "outputs": written,
            "verified": outcome.verify == "passed",
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

    def save(self) -> None:
        self.path.parent.mkdir(parents=True, exist_ok=True)
        temporary = self.path.with_name(self.path.name + f".{os.getpid()}.tmp")
        data = {"format": STATE_FORMAT, "gecent": __version__, "jobs": self.jobs}
        temporary.write_text(json.dumps(data, indent=1, sort_keys=True), encoding="utf-8")
        os.replace(temporary, self.path)


def _entry_key(job: Job) -> str:
    return str(Path(job.tape).resolve())
