"""The GEDUMP error dump in readable form (manual §5.7, 001 L28324-28365): after a fatal
error, the error and its explanation, the CL record being processed (ICLDAT and DATACL)
and the postprocessor's state, grouped by concern, for the listing."""

from __future__ import annotations

from gecent.core.absent import ABSENT
from gecent.core.cl.clprint import clprint_lines
from gecent.core.cl.records import Record
from gecent.core.state import PostState


def _point(values: list[float] | tuple[float, ...]) -> str:
    return " ".join(f"{v:+.4f}" for v in values)


def state_dump(error: str, state: PostState, record: Record | None) -> list[str]:
    """The lines of the dump: what the manual's debugging procedure checks first (SEQCTR,
    DPREVP, DPRESP, ICLDAT/DATACL), then the run's conditions."""
    position, feed, spindle, modes = state.position, state.feed, state.spindle, state.modes
    step = state.machine.number_option(14)
    lines = ["*** GEDUMP ***", error]
    if record is not None:
        lines.append(f"CL RECORD {record.number} ({record.where}):")
        lines.extend("  " + line for line in clprint_lines(record))
    pending = state.pending
    lines += [
        f"MACHINE          {state.machine.label}",
        f"SEQCTR           {state.sequence}",
        f"DPREVP (part)    {_point(position.previous_part[:3])}",
        f"DPRESP (part)    {_point(position.present_part[:3])}",
        f"DPREVM (machine) {_point([v * step for v in position.previous[:3]])}",
        f"DPRESM (machine) {_point([v * step for v in position.present[:3]])}",
        f"TRANSL           {_point(position.translation)}",
        f"FEDIPM           {feed.ipm:g} (programmed {feed.programmed}, "
        f"{'per revolution' if feed.per_revolution else 'per minute'})",
        f"RAPID            requested {feed.rapid_requested}, FLRPON {feed.rapid_mode}, "
        f"FRAPID {feed.rapid_ipm:g}",
        f"SPINDLE          {spindle.speed} RPM, direction {spindle.direction}, on {spindle.on}, "
        f"range {spindle.range}",
        f"TOOL             {state.tool.number}",
        f"COOLANT          on {modes.coolant_on}, mode {modes.coolant_mode}",
        f"STOPON {modes.stopped}  ENDFLG {modes.ended}  SKPFLG {state.skipping}",
        "PENDING          S "
        + ("-" if pending.spindle is ABSENT else f"{pending.spindle:g}")
        + "  M "
        + ("-" if pending.m_code is ABSENT else f"{pending.m_code:g}"),
        f"STATE            {dict(sorted(state.conditions.values.items()))}",
    ]
    return lines
