"""The first pass of a multihead program (manual §3.4.8.1 and §2.4.5.2, 001 L7170-7297,
L2180-2213): every record is processed for the head SELECT/HEAD,n selected last, by that
head's own run (its own position, feed, spindle and tool, and its own registers), and each
finished block is dumped onto the head's scratch tape instead of being printed and
punched. Records before the first SELECT/HEAD (PARTNO, MACHIN, COMBIN, ...) and FINI go
to both heads, as the manual's example has a PARTNO, a FROM and an END on each tape
(001 L2214-2300).

With macros (the machine's macro table or MACFUN) each head's run reads its own records
from start to end through its own macro engine, so that a macro's look-ahead runs along
that head's records (SELECT/HEAD routes them before the runs start).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator

from gecent.core.cl.records import Fini, Motion, Record, Statement, Word
from gecent.core.cl.stream import Lookahead
from gecent.core.dump import state_dump
from gecent.core.errors import (
    Diagnostic,
    FatalError,
    GecentError,
    InputError,
    InternalError,
    NotYetSupported,
    RunStopped,
    SourcePosition,
)
from gecent.core.machine.definition import MachineDefinition
from gecent.core.multihead.dump import ScratchTape
from gecent.core.multihead.heads import head_machine
from gecent.core.output.block import Block
from gecent.core.output.sinks import Ending, Sinks
from gecent.core.plugins import PluginSet
from gecent.core.run import Run
from gecent.core.state import RunResult
from gecent.core.statements.multihead import MAX_HEADS


def combined_program(records: Iterable[Record]) -> bool:
    """True when COMBIN comes before the first motion record: the program is a multihead
    one (the environment is set up at the start, 001 L7170-7176)."""
    for record in records:
        if isinstance(record, Motion):
            return False
        if isinstance(record, Statement) and record.major == "COMBIN":
            return True
    return False


def multihead_flag(machine: MachineDefinition) -> bool:
    """Option 191 = 1 (001 L26501-26510): the machine sets MULTHD itself, every program on
    it is a multihead one without a COMBIN/ statement. A machine of one head cannot."""
    if machine.number_option(191) != 1:
        return False
    if len(machine.heads) < MAX_HEADS:
        raise InputError(
            f"option 191 = 1 sets the multihead flag MULTHD, but machine {machine.label} has "
            "one head (its machine file has no [heads.2] register table)",
            SourcePosition(machine.origin),
        )
    return True


class HeadSinks(Sinks):
    """A head run's one sink, its scratch tape: blocks go there unconverted (no tape line
    yet: the merge pass makes it with the head's registers)."""

    def __init__(self, tape: ScratchTape) -> None:
        super().__init__([tape])
        self.tape = tape

    # (through ``sinks``, not ``tape``: a macro's look-ahead copies the run with a Sinks
    # of no sink in its place, core/macros/lookahead.py, and these methods come with it)
    def emit(self, block: Block) -> None:
        for sink in self.sinks:
            sink.block(block, None)

    def emit_known(self, block: Block, line: str) -> None:
        for sink in self.sinks:
            sink.block(block, None)


class FirstPass:
    """Both heads' runs and the routing of records between them."""

    def __init__(
        self,
        machine: MachineDefinition,
        plugins: PluginSet | None,
        report: Callable[[Diagnostic], None] | None,
        max_segments: int,
    ) -> None:
        self.machine = machine
        self.tapes: list[ScratchTape] = []
        self.runs: list[Run] = []
        try:
            for head in range(1, MAX_HEADS + 1):
                tape = ScratchTape(head)
                self.tapes.append(tape)
                run = Run(
                    head_machine(machine, head), plugins, HeadSinks(tape), report, max_segments
                )
                run.use_fast_path = run.fast_allowed = False  # every block must reach the tape
                run.state.head = head
                self.runs.append(run)
        except BaseException:
            self.remove()
            raise
        self.selected: Run | None = None  # None: every head (before the first SELECT/HEAD)
        self.record: Record | None = None
        self.used: set[int] = set()  # the heads SELECT/HEAD has named
        self.combin = False  # COMBIN/ was given (else option 191 set MULTHD)

    def process(self, records: Iterator[Record]) -> RunResult:
        """Run the whole file through; the scratch tapes are ready to read after it. On
        any error they are removed and the error raised, naming the record."""
        try:
            if any(run.macros is not None for run in self.runs):
                self._by_head(records)
            else:
                for record in records:
                    self.record = record
                    self._route(record)
            for run in self.runs:
                run.end_of_input()
            if len(self.used) < MAX_HEADS:
                given = "COMBIN/2 was given" if self.combin else "option 191 sets MULTHD"
                raise FatalError(7003, f"{given}, but the program selects one head only")
        except (FatalError, RunStopped) as error:
            if error.where is None and self.record is not None:
                error.where = self.record.where
            run = self.selected or self.runs[0]
            error.partial = run.result
            run.result.dump = state_dump(str(error), run.state, self.record)
            self.remove()
            raise
        except GecentError as error:
            if isinstance(error, InputError | NotYetSupported) and error.where is None:
                error.where = self.record.where if self.record is not None else None
            self.remove()
            raise
        except Exception as error:
            self.remove()
            raise InternalError(error, self.record.where if self.record else None) from error
        except BaseException:
            self.remove()
            raise
        for tape in self.tapes:
            tape.close(Ending(True))
        return self.runs[0].result

    def _route(self, record: Record) -> None:
        if self._selects(record):
            return
        if self.selected is None or isinstance(record, Fini):
            first, second = self.runs
            if not first.finished:
                first.feed((record,), False, first.builtin)
            if not second.finished:
                second.quiet = True  # a record both heads post is warned about by head 1
                try:
                    second.feed((record,), False, second.builtin)
                finally:
                    second.quiet = False
        else:
            self.selected.feed((record,), False, self.selected.builtin)

    def _by_head(self, records: Iterator[Record]) -> None:
        """With macros (a macro table or MACFUN for the machine): each head's run reads its
        own records as a single-head run reads the file, through its macro engine, which
        looks ahead along them (the manual's first pass processes the CL file "for both
        heads separately", 001 L7170-7206). SELECT/HEAD routes every record as it is met,
        so each head's records are known before its run starts."""
        streams: tuple[list[Record], list[Record]] = ([], [])
        both: set[int] = set()  # the records both heads process (by id)
        for record in records:
            self.record = record
            if self._selects(record):
                continue
            if self.selected is None or isinstance(record, Fini):
                both.add(id(record))
                for stream in streams:
                    stream.append(record)
            else:
                streams[self.selected.state.head - 1].append(record)
        for run, stream in zip(self.runs, streams, strict=True):
            self.selected = run
            engine = run.macros
            dispatch = run.builtin if engine is None else engine.dispatch
            quiet = run is not self.runs[0]  # a record both heads post is warned about once

            def heads_dispatch(
                record: Record,
                run: Run = run,
                dispatch: Callable[[Record], None] = dispatch,
                quiet: bool = quiet,
            ) -> None:
                run.quiet = quiet and id(record) in both
                try:
                    dispatch(record)
                finally:
                    run.quiet = False

            try:
                if engine is None:
                    run.feed(stream, False, heads_dispatch)
                else:
                    engine.records = Lookahead(iter(stream))
                    engine.start()
                    run.feed(engine.records, False, heads_dispatch)
            except BaseException:
                self.record = run.current_record or self.record
                raise

    def _selects(self, record: Record) -> bool:
        """COMBIN is noted; SELECT/HEAD,n selects head n (True: the record is routing)."""
        if isinstance(record, Statement) and record.major == "COMBIN":
            self.combin = True
        if isinstance(record, Statement) and record.major == "SELECT":
            args = record.args
            if args and isinstance(args[0], Word) and args[0].name in ("HEAD", "HED"):
                self._select(record)
                return True
        return False

    def _select(self, record: Statement) -> None:
        """SELECT/HEAD,n (SELHED, 001 L7214-7216): IHEAD = n."""
        rest = record.args[1:]
        if (
            len(rest) != 1
            or isinstance(rest[0], Word)
            or rest[0] != int(rest[0])
            or not 1 <= rest[0] <= MAX_HEADS
        ):
            raise InputError(f"SELECT/HEAD expects a head number 1..{MAX_HEADS}", record.where)
        self.selected = self.runs[int(rest[0]) - 1]
        self.used.add(int(rest[0]))

    def remove(self) -> None:
        for tape in self.tapes:
            tape.remove()
