"""The macro engine of one run (spec 09 §1-§6): matching records against user-defined
macros, running event macros around the post's built-in actions, OUTPUT, MATCH and TERMAC.

Processing model (§1, 002 L1-23, L136-138)::

    record -> the first inactive user macro whose SDL matches (if matching is on)
                 its body runs; OUTPUT passes the record on: the next inactive match, else
                 built-in processing
           -> built-in processing; an event-bearing record runs
                 startup macro -> built-in action -> shutdown macro

The hooks the run installs are bound methods of this engine, so a snapshot of the run
(look-ahead, :mod:`gecent.core.macros.lookahead`) carries its own engine and never writes to
the real outputs.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from gecent.core.cl.apt_source import TEXT_MAJORS, AptSourceReader
from gecent.core.cl.records import Comment, PartText, Record, Statement
from gecent.core.cl.vocabulary import vocabulary
from gecent.core.errors import Diagnostic, GecentError, InputError
from gecent.core.families import HookPoint
from gecent.core.macros.context import Frame, LookaheadFlags, MacroContext
from gecent.core.macros.host import MacroHost
from gecent.core.macros.looks import LookAheads, describe
from gecent.core.macros.model import (
    NO_COMMANDS,
    NOT_DONE,
    OUTPUT_ALLOWED,
    Found,
    Kind,
    Macro,
    MacroError,
    MacroFailure,
    Phase,
    TerminateMacro,
)
from gecent.core.macros.operations import Operations
from gecent.core.macros.params import NoParams, PParams, SyntaxParams
from gecent.core.macros.searches import (
    Gathered,
    Search,
)
from gecent.core.macros.sysvars import SystemVariables
from gecent.core.macros.table import MacroTable

if TYPE_CHECKING:
    from gecent.core.cl.stream import Lookahead

# a built-in action; one returning NOT_DONE (core/macros/model.py) has not done the event
# yet, so a later OUTPUT (or the startup macro's exit) does it (a cycle's feed alone, §5.6)
Action = Callable[[], object]
MAX_DEPTH = 200  # nested activations: a macro that keeps issuing what matches another


class MacroEngine(LookAheads):
    def __init__(self, table: MacroTable, run: MacroHost) -> None:
        self.table = table
        self.run = run
        self.frames: list[Frame] = []
        self.globals: dict[str, Any] = {}
        self.sv = SystemVariables(self)
        self.flags = LookaheadFlags()
        self.looking: str | None = None  # the look-ahead this (snapshot) engine runs
        self.search: Search | None = None  # what it searches for (core/macros/searches.py)
        self.flook_stack: tuple[int, ...] = ()  # the $FLOOK contexts this engine runs in
        self.offset = 0  # a snapshot: the records it has read beyond the real run's place
        self.info: Gathered | None = None  # $INFO.*, from the last $FINFO
        self.oe: Gathered | None = None  # $OE.*, from the last OPTYPE look-ahead
        self.operations = Operations()
        self.written: set[int] = set()  # records TAPEWT processed early: skipped when read
        # the operation-event macro's redundancy guard (§5.9): the CL records $P3..$P4, and
        # the last statement of each major word processed (what a redundant one repeats)
        self.guard: tuple[int, int] | None = None
        self.last_statements: dict[str, tuple[Any, ...]] = {}
        self.macfuns = dict(table.macfuns)  # the MACFUN hook points in force (MACHIN may change)
        self.records: Lookahead | None = None
        self._running: set[Kind] = set()  # event kinds in progress: no re-entry (§4.2 rule 3)
        self._occurrences: dict[str, int] = {}
        self.hooks: Any = None  # the EventHooks install_macros puts in
        self.macfun_data: dict[str, Any] = {}  # what MACFUN handlers keep for the run

    # -- user-defined macros -------------------------------------------------------------

    def dispatch(self, record: Record) -> None:
        """A record read from the CL file."""
        if self.search is not None:
            self.search.record(self.run, record)
        if self.written and record.number in self.written:
            self.written.discard(record.number)  # TAPEWT processed it already
            return
        if self.guard is not None and self._redundant(record):
            return
        self._match_or_builtin(record, matching=True)

    def _redundant(self, record: Record) -> bool:
        """§5.9: from the OPTYPE to the first cut ($P3..$P4) a post-processor command the
        same as the last of its major word (the state it would set is in force: the OE
        macro output it, or the program repeats itself) is not output again."""
        assert self.guard is not None
        first, last = self.guard
        if record.number > last:
            self.guard = None  # the cut has begun: commands are output even when redundant
            return False
        return (
            record.number >= first
            and isinstance(record, Statement)
            and record.major in MODAL_COMMANDS
            and self.last_statements.get(record.major) == _statement_key(record)
        )

    def fget(self, majors: tuple[str, ...], first: int, last: int) -> int:
        """$FGET (X9): the CL record number of the first record from ``first`` to
        ``last`` (0: to the end) whose major word is one of ``majors``, else -1."""
        assert self.records is not None
        wanted = {m.upper() for m in majors}
        for record in self.records.ahead(None, self.offset):
            if last and record.number > last:
                break
            if (
                record.number >= first
                and isinstance(record, Statement)
                and record.major in wanted
                and record.number not in self.written
            ):
                return record.number
        return -1

    def tapewt(self, frame: Frame, number: int) -> None:
        """TAPEWT (X9): the record ``number`` ahead processed now (through the user
        macros, as if read); when it is read later it is skipped."""
        self._commands_allowed(frame)
        assert self.records is not None
        for record in self.records.ahead(None, self.offset):
            if record.number == number:
                if number not in self.written:
                    self.written.add(number)
                    self._match_or_builtin(record, frame.matching)
                return
            if record.number > number:
                break
        raise MacroError(f"TAPEWT: record {number} is not ahead in the CL file")

    def _active(self) -> set[int]:
        return {id(frame.macro) for frame in self.frames}

    def _match_or_builtin(self, record: Record, matching: bool) -> None:
        if matching and self.table.syntax:
            active = self._active()
            for macro in self.table.candidates(record):
                if id(macro) in active:
                    continue
                assert macro.parsed is not None
                values = macro.parsed.match(record)
                if values is None:
                    continue
                params = SyntaxParams()
                for number, value in values.items():
                    params.set(number, value)
                if macro.body is None:
                    return  # an SDL with no body ignores what it matches (§6.1)
                frame = Frame(macro, params, record, {}, on_output=self._output_record)
                self._run(frame)
                return
        if isinstance(record, Statement) and record.major in MODAL_COMMANDS:
            self.last_statements[record.major] = _statement_key(record)
        self.run.builtin(record)

    def _output_record(self, frame: Frame) -> None:
        assert frame.record is not None
        self._match_or_builtin(frame.record, frame.matching)

    # -- running a macro -----------------------------------------------------------------

    def _run(self, frame: Frame) -> None:
        if len(self.frames) >= MAX_DEPTH:
            raise MacroFailure(
                f"macro {frame.macro.key}: more than {MAX_DEPTH} macros nested "
                "(a macro keeps issuing records that start another)",
                self._where(frame),
            )
        body = frame.macro.body
        assert body is not None
        if self.frames:
            self.frames[-1].looked.clear()  # look-ahead values last within one activation
        self.frames.append(frame)
        try:
            body(MacroContext(self, frame))
        except TerminateMacro:
            return  # TERMAC: the macro ends here (the frame is popped below)
        except (GecentError, Found):
            raise
        except MacroError as error:
            raise MacroFailure(f"macro {frame.macro.key}: {error}", self._where(frame)) from None
        except Exception as error:  # the pack's bug: named, with the record it was on
            raise MacroFailure(
                f"macro {frame.macro.key} failed: {type(error).__name__}: {error}",
                self._where(frame),
            ) from error
        finally:
            self.frames.pop()
            if self.frames:
                self.frames[-1].looked.clear()  # (§7.3: reset on any macro's entry and exit)

    def _where(self, frame: Frame) -> Any:
        record = frame.record or self.run.current_record
        return None if record is None else record.where

    def output(self, frame: Frame) -> None:
        if frame.macro.slot not in OUTPUT_ALLOWED or frame.on_output is None:
            raise MacroError(f"OUTPUT is not allowed in the {describe(frame.macro)} macro (§3)")
        frame.outputs += 1
        frame.on_output(frame)

    def command(self, frame: Frame, text: str) -> None:
        """A post-processor or motion command issued by a macro, read as APT source."""
        self._commands_allowed(frame)
        origin = frame.record or self.run.current_record
        reader = AptSourceReader(origin.file if origin is not None else "")
        number = origin.number if origin is not None else 0
        line = origin.line if origin is not None else None
        try:
            records = list(reader.read_lines([text]))
        except InputError as error:
            raise MacroError(f"command {text!r}: {error.message}") from None
        for record in records:
            record.line, record.number = line, number
            self._allowed_in(frame, record)
            self._match_or_builtin(record, frame.matching)

    def text(self, frame: Frame, major: str, text: str) -> None:
        self._commands_allowed(frame)
        origin = frame.record or self.run.current_record
        record = Statement(
            origin.file if origin is not None else "",
            origin.line if origin is not None else None,
            origin.number if origin is not None else 0,
            major,
            vocabulary().major_code(major),
            (),
            text,
        )
        assert major in TEXT_MAJORS
        self._match_or_builtin(record, frame.matching)

    def _allowed_in(self, frame: Frame, record: Record) -> None:
        """An LCS macro issues no motion and none of the commands §5.8 lists."""
        if frame.macro.kind is not Kind.LCS:
            return
        if isinstance(record, Statement):
            refused = record.major in LCS_REFUSED
        else:
            refused = not isinstance(record, Comment | PartText)
        if refused:
            name = record.major if isinstance(record, Statement) else type(record).__name__
            raise MacroError(f"an LCS macro may not issue {name} (§5.8)")

    def _commands_allowed(self, frame: Frame) -> None:
        if frame.macro.kind in NO_COMMANDS:
            raise MacroError(f"the {describe(frame.macro)} macro issues no commands (§4.3)")

    def warn(self, frame: Frame, text: str) -> None:
        record = frame.record or self.run.current_record
        self.run.warn(Diagnostic(text, record.where if record is not None else None))

    # -- event macros --------------------------------------------------------------------

    def enabled(self, kind: Kind) -> bool:
        switch = _SWITCH.get(kind)
        return switch is None or bool(self.sv.get(switch))

    def event(
        self,
        kind: Kind,
        params: PParams,
        record: Record | None,
        builtin: Action,
        *,
        proceed: Callable[[PParams], bool] | None = None,
        then: Callable[[PParams], bool] | None = None,
    ) -> None:
        """Startup macro, built-in action, shutdown macro (§4.2); ``proceed`` reads the $P
        the startup macro left and says whether the action (and the shutdown) still run,
        ``then`` whether the shutdown does after the action."""
        startup = self.table.event(kind, Phase.STARTUP)
        shutdown = self.table.event(kind, Phase.SHUTDOWN)
        event = _EVENT.get(kind, kind)  # a first tool change is a tool change (no re-entry)
        if (
            (startup is None and shutdown is None)
            or event in self._running
            or not self.enabled(kind)
        ):
            builtin()
            return
        shared: dict[str, Any] = {}
        done = False
        named = startup or shutdown
        assert named is not None

        def judged(rule: Callable[[PParams], bool] | None) -> bool:
            """A rule on the $P the startup macro left; a value it may not take is the
            macro's error, named."""
            if rule is None:
                return True
            try:
                return rule(params)
            except MacroError as error:
                raise MacroFailure(f"macro {named.key}: {error}", self._where_of(record)) from None

        def once(frame: Frame) -> None:
            nonlocal done
            if not judged(proceed):
                return
            if not done:
                done = builtin() is not NOT_DONE

        self._running.add(event)
        try:
            if startup is not None:
                frame = Frame(startup, params, record, shared, on_output=once)
                self._run(frame)
            if not judged(proceed):
                return
            if not done:
                done = True
                builtin()
            if shutdown is not None and judged(then):
                local = {} if kind is Kind.MACHINE else shared  # §4.2: machine keeps none
                self._run(Frame(shutdown, params, record, local))
        finally:
            self._running.discard(event)

    def _where_of(self, record: Record | None) -> Any:
        record = record or self.run.current_record
        return None if record is None else record.where

    def single(
        self,
        kind: Kind,
        params: PParams,
        record: Record | None,
        on_output: Callable[[Frame], None],
        local: dict[str, Any] | None = None,
    ) -> Frame | None:
        """A single event macro (register, tape, diagnostic, ...): its frame after it ran,
        or None when none is installed, enabled and not already running."""
        macro = self.table.event(kind, Phase.EVENT)
        if macro is None or kind in self._running or not self.enabled(kind):
            return None
        frame = Frame(macro, params, record, {} if local is None else local, on_output)
        self._running.add(kind)
        try:
            self._run(frame)
        finally:
            self._running.discard(kind)
        return frame

    def run_event(self, macro: Macro, params: PParams, record: Record | None) -> None:
        """One macro of a pair the caller sequences itself (break: shutdown first)."""
        if macro.kind in self._running:
            return
        self._running.add(macro.kind)
        try:
            self._run(Frame(macro, params, record, {}))
        finally:
            self._running.discard(macro.kind)

    def start(self) -> None:
        """MACFUN's initialization call (MCHCON 0), the declaration macro, then machine
        startup (§5.1, §5.2)."""
        self.hooks.macfun(HookPoint.INIT)
        declaration = self.table.event(Kind.DECLARATION, Phase.EVENT)
        if declaration is not None:
            self._run(Frame(declaration, NoParams(), None, {}))
        startup = self.table.event(Kind.MACHINE, Phase.STARTUP)
        if startup is not None:
            self._run(Frame(startup, NoParams(), None, {}))

    def finish(self, record: Record | None) -> None:
        """Machine shutdown: at FINI, at the end of a file without one, and when a
        look-ahead reaches FINI (§5.2, §7.6)."""
        shutdown = self.table.event(Kind.MACHINE, Phase.SHUTDOWN)
        if shutdown is not None and Kind.MACHINE not in self._running:
            self._running.add(Kind.MACHINE)
            try:
                self._run(Frame(shutdown, NoParams(), record, {}))
            finally:
                self._running.discard(Kind.MACHINE)

    # -- look-ahead ----------------------------------------------------------------------


_EVENT = {Kind.FIRST_TOOL_CHANGE: Kind.TOOL_CHANGE}
# what an LCS macro may not issue besides motion (002 L779-793; MOVETO and CLAMP are allowed)
LCS_REFUSED = frozenset(
    [
        "APPLY",
        "BREAK",
        "CYCLE",
        "END",
        "OPTYPE",
        "REWIND",
        "CALSUB",
        "COPY",
        "DEFSUB",
        "ENDSUB",
        "INDEX",
        "COUPLE",
        "HEAD",
        "THREAD",
        "LOAD",
        "LOADTL",
        "SELECT",
        "SELCTL",
        "TLNAME",
        "TOOLNO",
        "TURRET",
        "UNLOAD",
        "FINI",
        "MULTAX",
        "UNITS",
    ]
)
_SWITCH = {
    Kind.CYCLE: "CYCMAC",
    Kind.MOTION: "MTNMAC",
    Kind.LCS: "LCSMAC",
    Kind.OPERATION_EVENT: "OEMAC",
    Kind.REGISTER: "REGMAC",
    Kind.TAPE: "TAPMAC",
    Kind.DIAGNOSTIC: "DIAGMAC",
}


# the post-processor commands that set a state a repeat leaves as it is (a repeat is
# "redundant", §5.9); one-shot commands (STOP, RAPID, a tool change, INSERT...) are never
MODAL_COMMANDS = frozenset({"SPINDL", "COOLNT", "FEDRAT", "CUTCOM", "CYCLE", "TRANS", "CLAMP",
                            "AIR", "MODE", "OPSKIP"})  # fmt: skip


def _statement_key(statement: Statement) -> tuple[Any, ...]:
    """What makes two statements the same command: their arguments and text."""
    return (statement.args, statement.text)
