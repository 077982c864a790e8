"""Posting a CL file: the first pass chooses the machine (as GEINIT does, up to MACHIN),
the main pass runs every record through a :class:`~gecent.core.run.Run` into the sinks."""

from __future__ import annotations

from collections.abc import Callable, Iterator

from gecent.core.cl.records import Record
from gecent.core.errors import Diagnostic, GecentError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.selection import apply_machin_options, first_machin, resolve_machine
from gecent.core.macros.dialect import choose_dialect, read_in_dialect, read_raw
from gecent.core.motion.guard import DEFAULT_MAX_SEGMENTS
from gecent.core.multihead.first_pass import combined_program, multihead_flag
from gecent.core.output.sinks import Sinks
from gecent.core.plan import planned_records, plans
from gecent.core.plugins import PluginSet
from gecent.core.run import Run
from gecent.core.state import RunResult
from gecent.core.toollist import tool_list
from gecent.core.units import UnitScale


def post(
    path: str,
    plugins: PluginSet,
    machine_override: str | MachineDefinition | None = None,
    watch: Callable[[Iterator[Record]], Iterator[Record]] | None = None,
    sinks: Callable[[MachineDefinition], Sinks] | None = None,
    report: Callable[[Diagnostic], None] | None = None,
    max_segments: int = DEFAULT_MAX_SEGMENTS,
    fast: bool = True,
    dialect: str | None = None,
) -> RunResult:
    """Select the machine (first pass up to MACHIN, as GEINIT does), then process the file;
    ``watch`` may wrap the records of the main pass (a progress bar). ``sinks`` makes the
    outputs for the machine chosen (none: the result keeps the blocks); ``report`` gets
    each warning as it is made (none: the result keeps them). ``dialect`` forces the CAM
    dialect (core/macros/dialect.py; "none" for none), else the file's own is detected."""
    spoken = choose_dialect(path, plugins, dialect)
    request, notes = first_machin(read_raw(path, plugins, spoken))
    machine = resolve_machine(plugins, machine_override, request)
    # the outputs are laid out for the machine as the first MACHIN leaves it: its OPTAB
    # pairs choose the printout and its print positions (164, 17, 79, 160), as the
    # manual's GEOUT4 sample does (001 L10011); the run applies them again at MACHIN
    layout = machine
    if request is not None:
        try:
            layout = apply_machin_options(machine, request)[0]
        except GecentError:
            layout = machine  # (the run reports the bad pair at its MACHIN)
    if multihead_flag(machine) or (
        len(machine.heads) > 1 and combined_program(read_raw(path, plugins, spoken))
    ):
        from gecent.core.multihead.post import post_multihead

        outputs = sinks(layout) if sinks is not None else None
        for note in [*notes, *(outputs.notes if outputs is not None else [])]:
            if report is not None:
                report(note)
        records = read_in_dialect(
            path, plugins, spoken, report or _ignore, UnitScale(machine).machine_mm == 1.0
        )
        return post_multihead(
            machine, plugins, watch(records) if watch else records, outputs, report, max_segments
        )
    run = Run(
        machine,
        plugins,
        sinks(layout) if sinks is not None else None,
        report,
        max_segments,
        fast,
    )
    if machine.number_option(264) == 1:
        run.state.header = tool_list(path, plugins, machine, spoken)
    for note in [*notes, *run.sinks.notes]:  # the outputs' (GEOUT1 replaced) after MACHIN's
        run.warn(note)
    records = read_in_dialect(path, plugins, spoken, run.warn, run.units.machine_mm == 1.0)
    if plans(machine, request):  # MACHIN/GECENT,n,PLAN with option 1 = +1: GEPLAD first
        records = planned_records(records, layout, run.warn)
    return run.process(watch(records) if watch is not None else records)


def _ignore(diagnostic: Diagnostic) -> None:
    """Diagnostics of the reader are reported by the heads' runs."""
