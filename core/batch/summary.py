"""The batch summary: one row per job (status, exit status, first error with its file and
line, blocks, tape length, cut time, seconds, verification) as a table for the terminal and
as JSON or CSV for whatever runs the posting service."""

from __future__ import annotations

import csv
import io
import json
from collections import Counter
from typing import Any

from gecent.core.batch.jobs import Job
from gecent.core.batch.worker import Outcome

COLUMNS = (
    "job",
    "input",
    "machine",
    "status",
    "exit",
    "warnings",
    "blocks",
    "tape_feet",
    "cut_minutes",
    "seconds",
    "verify",
    "tape",
    "error",
)


def rows(jobs: list[Job], outcomes: list[Outcome]) -> list[dict[str, Any]]:
    by_number = {outcome.number: outcome for outcome in outcomes}
    found = []
    for job in jobs:
        outcome = by_number.get(job.number)
        if outcome is None:  # the batch was stopped before this job
            continue
        found.append(
            {
                "job": job.number,
                "input": job.name,
                "machine": outcome.machine or job.machine or "",
                "status": outcome.status,
                "exit": outcome.exit_status,
                "warnings": outcome.warnings,
                "blocks": outcome.blocks,
                "tape_feet": round(outcome.tape_feet, 1),
                "cut_minutes": round(outcome.cut_minutes, 2),
                "seconds": round(outcome.seconds, 3),
                "verify": outcome.verify,
                "tape": job.tape if outcome.ok else "",
                "error": outcome.error,
                "messages": outcome.messages,
            }
        )
    return found


def totals(found: list[dict[str, Any]], seconds: float, workers: str) -> str:
    count = Counter(row["status"] for row in found)
    parts = [
        f"{count[s]} {s}"
        for s in ("posted", "skipped", "failed", "verify-failed", "crashed", "to post")
        if count[s]
    ]
    posted = count["posted"]
    rate = f"; {posted / seconds:.1f} jobs/s posted" if seconds > 0 and posted else ""
    return (
        f"{len(found)} jobs: {', '.join(parts) or 'none'}; "
        f"{sum(row['blocks'] for row in found)} blocks, "
        f"{sum(row['tape_feet'] for row in found):.1f} ft of tape, "
        f"{sum(row['cut_minutes'] for row in found):.1f} min cutting; "
        f"{seconds:.1f} s on {workers}{rate}"
    )


def table(found: list[dict[str, Any]], width: int | None = None) -> str:
    """The rows as a plain-text table; the error column cut to the terminal's width (the
    JSON and CSV keep it whole)."""
    shown = (
        "job",
        "input",
        "machine",
        "status",
        "exit",
        "blocks",
        "tape_feet",
        "cut_minutes",
        "seconds",
        "verify",
        "error",
    )
    heads = {"tape_feet": "tape ft", "cut_minutes": "cut min", "seconds": "s"}
    cells = [[heads.get(c, c) for c in shown]]
    for row in found:
        cells.append([_cell(row[c]) for c in shown])
    widths = [max(len(line[i]) for line in cells) for i in range(len(shown) - 1)]
    lines = []
    for line in cells:
        text = "  ".join(cell.ljust(widths[i]) for i, cell in enumerate(line[:-1]))
        error = line[-1]
        room = max(20, width - len(text) - 2) if width is not None else len(error)
        if len(error) > room:
            error = error[: room - 3] + "..."
        lines.append(f"{text}  {error}".rstrip())
    return "\n".join(lines)


def as_json(found: list[dict[str, Any]], total: str) -> str:
    return json.dumps({"jobs": found, "summary": total}, indent=1) + "\n"


def as_csv(found: list[dict[str, Any]]) -> str:
    """The rows without the warnings' text (their count is a column)."""
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, fieldnames=COLUMNS, lineterminator="\n", extrasaction="ignore")
    writer.writeheader()
    writer.writerows(found)
    return buffer.getvalue()


def _cell(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:g}"
    return str(value)
