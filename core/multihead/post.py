"""Posting a multihead program: the first pass into the scratch tapes, the merge pass into
the outputs (manual §3.4.8, 001 L7170-7359)."""

from __future__ import annotations

from collections.abc import Callable, Iterator

from gecent.core.cl.records import Record
from gecent.core.dump import state_dump
from gecent.core.errors import (
    Diagnostic,
    FatalError,
    GecentError,
    InputError,
    InternalError,
    NotYetSupported,
    SourcePosition,
)
from gecent.core.machine.definition import MachineDefinition
from gecent.core.multihead.first_pass import FirstPass
from gecent.core.multihead.gemult import MergePass
from gecent.core.output.sinks import CollectSink, Ending, Sinks
from gecent.core.plugins import PluginSet
from gecent.core.state import RunResult


def post_multihead(
    machine: MachineDefinition,
    plugins: PluginSet | None,
    records: Iterator[Record],
    sinks: Sinks | None,
    report: Callable[[Diagnostic], None] | None,
    max_segments: int,
) -> RunResult:
    """Both passes; the sinks are closed as a single-head run closes them: renamed into
    place when the run finishes, discarded on bad input."""
    result = RunResult(machine=machine)
    if sinks is None:
        sinks = Sinks([CollectSink(result.blocks)])

    def warn(diagnostic: Diagnostic) -> None:
        result.warnings += 1
        if report is not None:
            report(diagnostic)
        else:
            result.diagnostics.append(diagnostic)

    try:
        first = FirstPass(machine, plugins, warn, max_segments)
    except BaseException:
        sinks.close(Ending(False))
        raise
    ending = Ending(False)  # the outputs are kept only when both passes finish
    try:
        head_result = first.process(records)
        sinks.partno = first.runs[0].sinks.partno  # the listing's page heading
        # (the machine as the program left it: MACHIN may have changed options)
        merge = MergePass(first.runs[0].machine, first.tapes, sinks, warn)
        merge.run()
        for text, _ in sinks.reels.notes if sinks.reels is not None else ():
            # the merged tape broken at option 134's maximum (its blocks have left their
            # CL records behind in the merge)
            warn(Diagnostic(text))
        # option 110 = +2 or 173 = 0 in head 1's run: the listing without the tape
        ending = Ending(True, punch_suppressed=head_result.punch_suppressed)
    except FatalError as error:
        # the manual's fatal error: the listing is kept, with the dump (GEDUMP)
        if isinstance(error.partial, RunResult):  # met in the first pass, by a head's run
            result.dump = error.partial.dump
        else:  # met in the merge pass
            result.dump = state_dump(str(error), first.runs[0].state, None)
        error.partial = result
        if error.where is None and first.record is not None:
            error.where = SourcePosition(first.record.file)
        ending = Ending(False, dump=result.dump)
        raise
    except (InputError, NotYetSupported) as error:
        if error.where is None and first.record is not None:
            error.where = SourcePosition(first.record.file)  # (met in the merge pass)
        raise
    except GecentError:
        raise
    except Exception as error:
        raise InternalError(error, None) from error
    finally:
        first.remove()
        sinks.close(ending)
    result.records = head_result.records
    result.partno = head_result.partno
    result.punch_suppressed = head_result.punch_suppressed
    result.cut_minutes = merge.out.cut_minutes
    result.dwell_minutes = merge.out.dwell_minutes
    return result
