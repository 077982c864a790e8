"""One postprocessor run: CL records in, command blocks out (manual §3.1 general flow).

The dispatcher handles each record by its type and, for postprocessor statements, by its
major word. A statement whose handler is not built yet stops the run with a "not yet
supported" error naming the statement and its line; nothing is written then.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from typing import TYPE_CHECKING

from gecent.core.cl.records import (
    Arelem,
    Circle,
    Comment,
    Fini,
    Motion,
    MotionSubtype,
    Multiax,
    Other,
    PartText,
    Record,
    Statement,
    Surface,
    Word,
)
from gecent.core.cl.stream import Lookahead
from gecent.core.cl.vocabulary import vocabulary
from gecent.core.dispatch.context import Post
from gecent.core.dispatch.elements import Elements
from gecent.core.dispatch.holes import CycleHoles
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
from gecent.core.feed.rapid import MODAL, RapidTraverse
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.selection import POSTPROCESSOR_NAME
from gecent.core.macros.engine import MacroEngine
from gecent.core.macros.install import install_macros
from gecent.core.macros.table import MacroTable
from gecent.core.motion.circle import CircularMotion
from gecent.core.motion.control_cycles import ControlCycles
from gecent.core.motion.cycles import Cycle
from gecent.core.motion.fastpath import FastLinear
from gecent.core.motion.guard import (
    DEFAULT_MAX_SEGMENTS,
    CoordinateGuard,
    check_numbers,
)
from gecent.core.motion.linear import LinearMotion, path_length
from gecent.core.motion.mixed import (
    MIXED_CONTROL,
    contouring_moved,
    enter_way,
    goes_positioning,
)
from gecent.core.motion.positioning import PositioningMotion
from gecent.core.motion.rotary import RotaryElement
from gecent.core.motion.thread import ThreadElement
from gecent.core.motion.tool_axis import three_axis_motion
from gecent.core.motion.unmade import refuse_on_multiaxis, refuse_on_positioning
from gecent.core.output.block import Block, Code
from gecent.core.output.element import OutputElement
from gecent.core.output.format import FormatOverflow
from gecent.core.output.modern import modern_output, program_end, program_start
from gecent.core.output.sinks import CollectSink, Ending, Sinks
from gecent.core.plugins import PluginSet, get_plugins
from gecent.core.reinstate import restat
from gecent.core.spindle import SpindleElement
from gecent.core.state import PostState, RunResult
from gecent.core.statements import Handler, handlers
from gecent.core.statements.safety import safety_motion
from gecent.core.statements.threading import RAPID_THREAD
from gecent.core.tool import ToolElement
from gecent.core.units import UnitScale

if TYPE_CHECKING:
    from gecent.core.motion.multiaxis import MultiaxisMotion


class Run(CycleHoles, Elements):
    """The state of one run and the record dispatch (spec 02 §7)."""

    def __init__(
        self,
        machine: MachineDefinition,
        plugins: PluginSet | None = None,
        sinks: Sinks | None = None,
        report: Callable[[Diagnostic], None] | None = None,
        max_segments: int = DEFAULT_MAX_SEGMENTS,
        fast: bool = True,
    ) -> None:
        self.plugins = plugins
        # False: every record by the general path (tests; a multiaxis machine's points
        # go through its transform class)
        self.fast_allowed = fast and not machine.multiaxis
        self.use_fast_path = self.fast_allowed
        self._fast: FastLinear | None = None
        self.result = RunResult(machine=machine)
        if sinks is None:  # no outputs named: keep the blocks for the caller
            collector = CollectSink(self.result.blocks)
            sinks = Sinks([collector])
        self.sinks = sinks
        self.report = report
        self.state = PostState(machine)
        self.finished = False
        # a MACHIN/GECENT statement was read: the file was written for this postprocessor,
        # whose CL tapes always end with FINI (end of file before it is an error)
        self.written_for_gecent = False
        self.quiet = False  # warnings dropped (a multihead record head 1 has warned about)
        self._file = ""
        self._record: Record | None = None
        self._before: Record | None = None  # the record before it (an arc goes out late)
        self.units = UnitScale(machine)
        self._output: OutputElement | None = None
        self._motion: LinearMotion | None = None
        self._multiaxis: MultiaxisMotion | None = None
        self._circle: CircularMotion | None = None
        self._rapid_traverse: RapidTraverse | None = None
        self._spindle: SpindleElement | None = None
        self._tool_element: ToolElement | None = None
        self._rotary: RotaryElement | None = None
        self._thread: ThreadElement | None = None
        self._positioning: PositioningMotion | None = None
        self.cycle: Cycle | None = None  # the canned cycle in force (CYCFLG, ICYTYP)
        self.cycle_first_z: float | None = None
        self._control_cycles: ControlCycles | None = None
        self.control_cycles: ControlCycles | None = None  # the control runs the cycle in force
        self.safety_motions = 0  # a one-shot SAFETY (option 21 = 0) counting its motions down
        self._guard: CoordinateGuard | None = None
        # a modern control's CL file with no UNITS before its first move is warned about
        self._units_checked = not modern_output(machine)
        self.state.max_segments = max_segments
        self._statements = handlers()
        self._statements["UNITS"] = _units
        self._builtin_statements = dict(self._statements)
        self.macros: MacroEngine | None = None
        self._motion_record: Callable[[Motion], None] = self.motion_builtin
        table = MacroTable.for_machine(plugins or get_plugins(), machine)
        if table is not None:
            self.macros = install_macros(self, table)

    @property
    def current_record(self) -> Record | None:
        return self._record

    def builtin(self, record: Record) -> None:
        """A record's built-in processing (a macro's OUTPUT, a command it issues)."""
        self._general(self.units.record(record))

    def builtin_statement(self, major: str) -> Handler:
        return self._builtin_statements[major]

    def warn(self, diagnostic: Diagnostic) -> None:
        if self.quiet:
            return
        self.result.warnings += 1
        if self.report is not None:
            self.report(diagnostic)
        else:
            self.result.diagnostics.append(diagnostic)
        self.text_block(
            Block(
                Code.COMMENT, diagnostic.where.record if diagnostic.where else None, diagnostic.text
            )
        )

    warn_builtin = warn  # (a diagnostic macro takes ``warn``'s place and calls this)

    def text_block(self, block: Block) -> None:
        """Text blocks bypass OUTPUT: they take no N and leave the pending S and M alone."""
        self.output.emit(block)

    def process(self, records: Iterator[Record]) -> RunResult:
        """Run the records through and close the sinks: renamed into place when the run
        finished, the listing alone (with the dump) after a fatal error, nothing after bad
        input or any other failure."""
        try:
            result = self._process(records)
        except FormatOverflow as overflow:
            record = self._record
            if record is not None and (
                overflow.where is None or overflow.where.record == record.number
            ):
                overflow.where = record.where  # the record being posted: its file and line
            elif (
                overflow.where is not None
                and self._before is not None
                and overflow.where.record == self._before.number
            ):
                overflow.where = self._before.where  # an arc goes out at the next record
            elif overflow.where is not None:  # the element knows the record, the run the file
                overflow.where = SourcePosition(self._file, None, None, overflow.where.record)
            self._stopped_by(overflow)
            raise
        except (FatalError, RunStopped) as error:
            if error.where is None and self._record is not None:
                error.where = self._record.where
            self._stopped_by(error)
            raise
        except GecentError as error:  # every message names the file and line
            if isinstance(error, InputError | NotYetSupported) and error.where is None:
                error.where = self._record.where if self._record is not None else None
            self.sinks.close(Ending(False))
            raise
        except Exception as error:  # a bug: reported as one, with the record being posted
            self.sinks.close(Ending(False))
            where = self._record.where if self._record is not None else None
            raise InternalError(error, where) from error
        except BaseException:
            self.sinks.close(Ending(False))
            raise
        self.sinks.close(Ending(True, punch_suppressed=result.punch_suppressed))
        return result

    def _stopped_by(self, error: GecentError) -> None:
        """A fatal error: the sinks close with the GEDUMP dump, so the listing is still
        written (never the tape); the dump also goes with the error."""
        self.result.dump = state_dump(str(error), self.state, self._record)
        error.partial = self.result
        self.sinks.close(Ending(False, dump=self.result.dump))

    def _process(self, records: Iterator[Record]) -> RunResult:
        for text in program_start(self.machine, self.state.numbering):
            self.text_block(Block(Code.INSERT, None, text))
        engine = self.macros
        if engine is None:
            self.feed(records, True, self.builtin)
        else:
            stream = engine.records = Lookahead(records)
            engine.start()
            self.feed(stream, engine.hooks.fast_path_allowed(), engine.dispatch)
        return self.end_of_input()

    def feed(
        self, records: Iterable[Record], fast_ok: bool, dispatch: Callable[[Record], None]
    ) -> None:
        """The record loop: a GOTO by the fast path when ``fast_ok`` (no macro can see it)
        and nothing special is in force, any other record to ``dispatch`` (the post's own
        processing, or the macro engine's matching first). A look-ahead's snapshot runs
        this too."""
        fast: FastLinear | None = None
        result = self.result
        state = self.state
        goto = MotionSubtype.GOTO
        for record in records:
            self._file = record.file
            self._before, self._record = self._record, record
            result.records += 1
            if self.finished:
                raise InputError("record after FINI", record.where)
            state.sequence = record.number
            if fast_ok and type(record) is Motion and record.subtype is goto:
                circle = self._circle
                if fast is None and circle is not None and circle.collecting:
                    circle.finish()  # a GOTO ends the arc before it, as any record does
                    fast = self._fast_path()
                if fast is not None and fast.goto(record):  # (it applies UNITS itself)
                    continue
            fast = None  # the general path: the conditions are looked at again after it
            dispatch(record)
            if fast_ok:
                fast = self._fast_path()

    def end_of_input(self) -> RunResult:
        if self._circle is not None and self._circle.collecting:
            self._circle.finish()
        return self._finish()  # (with no FINI: the machine shutdown macro at the end)

    def _fast_path(self) -> FastLinear | None:
        """The fast path (core/motion/fastpath.py), when nothing special is in force."""
        if not self.use_fast_path or self._output is None or not self._units_checked:
            return None  # (the general path makes the elements, with their errors)
        fast = self._fast
        if fast is None:
            if self._guard is None:
                self._guard = CoordinateGuard(self.machine, self.output.words.shuffle)
            rapid = self.rapid
            fast = self._fast = FastLinear(
                self.state,
                self.output,
                self.motion,
                self.sinks,
                self._guard,
                rapid.motion,
                self.units,
            )
            if not fast.possible:
                self.use_fast_path = False
                return None
        circle = self._circle
        special = (
            self.cycle is not None
            or self.safety_motions != 0  # its off code waits for a motion (safety_motion)
            or (circle is not None and (circle.collecting or circle.centre is not None))
        )
        return fast if fast.ready(special) else None

    def _general(self, record: Record) -> None:
        """One record through the dispatcher (the general path)."""
        self._check_values(record)
        if self._circle is not None and self._circle.collecting:
            if isinstance(record, Motion) and record.subtype is MotionSubtype.CONTINUATION:
                self._circle.add(record)
                return
            self._circle.finish()  # any other record ends the circle (001 L4749-4781)
        if isinstance(record, Motion):
            if not self._units_checked:
                self._units_checked = True
                if not self.units.stated:
                    self.warn(self.units.unstated(record.where))
            self._motion_record(record)
        elif isinstance(record, Statement):
            if record.major == "MACHIN" and _names_gecent(record):
                self.written_for_gecent = True
            handler = self._statements.get(record.major)
            if handler is not None:
                handler(self, record)
            elif record.major in vocabulary().gecent_majors:
                raise NotYetSupported(f"{record.major} statement", record.where)
            elif record.major in CURVE_WORDS:  # motion the post would miss: never disregarded
                raise NotYetSupported(
                    f"{record.major}: NURBS motion outside a dialect that reads it (--dialect nx)",
                    record.where,
                )
            else:  # "not recognized ... therefore, disregarded" (001 L3203-3205)
                self.warn(Diagnostic(f"{record.major} {UNKNOWN_WORD}", record.where))
        elif isinstance(record, Arelem):
            self.state.tolerances.take(record.subtype, record.values)
        elif isinstance(record, Circle):
            if self.machine.multiaxis:
                self._multiaxis_circle()
            self.circle.surface(record)  # ignored on a linear-only control (option 9 = 0)
        elif isinstance(record, Fini):
            if self.macros is not None:
                self.macros.finish(record)
            self.output.finish_program(record.number)
            for text in program_end(self.machine):
                self.text_block(Block(Code.INSERT, record.number, text))
            self.text_block(Block(Code.FINI, record.number))
            self.finished = True
        elif isinstance(record, Comment | PartText | Surface | Other):
            return
        elif isinstance(record, Multiax):
            return  # each point's tool axis goes with its motion (or is checked with it)
        else:
            kind = type(record).__name__.upper()
            raise NotYetSupported(
                f"{kind} record (type {_TYPE_NAMES.get(kind, kind)})", record.where
            )
        self._collect_notes(record)

    def _finish(self) -> RunResult:
        if not self.finished:
            if self.written_for_gecent:
                # "EOF counts as an error": a CL tape made for GECENT always ends with FINI,
                # so one without is cut short (001 L2650-2656; docs/decisions.md)
                last = self._record
                raise InputError(
                    "the CL file ends without FINI: a file written for GECENT (it has "
                    "MACHIN/GECENT) ends with FINI, so this one is cut short",
                    last.where if last is not None else SourcePosition(self._file),
                )
            # CAM systems end files without FINI (NX: END-OF-PATH): the program ends as at
            # FINI, with the warning (docs/decisions.md)
            self.warn(Diagnostic("NO FINI STATEMENT AT THE END OF THE CL FILE"))
            last = self._record
            self._general(Fini(self._file, None, last.number + 1 if last is not None else 1))
        self.result.cut_minutes = self.output.cut_minutes
        self.result.dwell_minutes = self.output.dwell_minutes
        reels = self.sinks.reels
        for text, number in reels.notes if reels is not None else ():
            # a reel broken at option 134's maximum (core/output/reels.py), at CL record n
            where = SourcePosition(self._file, record=number) if number is not None else None
            self.warn(Diagnostic(text, where))
        if self.output.slide_limits.exceeded and self.machine.number_option(110) == 2:
            self.result.punch_suppressed = True
            self.warn(Diagnostic("SLIDE LIMITS EXCEEDED: NO PUNCHED OUTPUT (OPTION 110 = 2)"))
        if self.machine.number_option(173) == 0 and not self.result.punch_suppressed:
            # printed output only: the listing, no tape image, no punch (001 L26380-26388)
            self.result.punch_suppressed = True
            self.warn(Diagnostic(PRINTED_ONLY))
        return self.result

    def _check_values(self, record: Record) -> None:
        """Numbers the machine cannot take are bad input (core/motion/guard.py)."""
        if not isinstance(record, Motion):
            check_numbers(record)
            return
        if self._guard is None:
            self._guard = CoordinateGuard(self.machine, self.output.words.shuffle)
        position = self.state.position
        self._guard.motion(record, position.previous_part, position.translation)

    def _collect_notes(self, record: Record) -> None:
        notes = self.output.diagnostics
        while notes:
            note = notes.pop(0)
            self.warn(Diagnostic(note.text, note.where or record.where))

    def motion_builtin(self, record: Motion) -> None:
        control = self.machine.number_option(1)
        mixed = control == MIXED_CONTROL  # the 7500: each move one way (core/motion/mixed.py)
        positioning = control != 0
        multiaxis = self.machine.multiaxis
        if len(record.points[0]) == 6 and not multiaxis:
            record = three_axis_motion(record, self.machine)  # (or an error naming the line)
        modes = self.state.modes
        if modes.ended:
            modes.ended = False
            if record.subtype is not MotionSubtype.FROM:
                self.warn(Diagnostic(AFTER_END, record.where))
        if modes.stopped and record.subtype is not MotionSubtype.FROM:
            restat(self, record.number)
        if multiaxis and record.subtype is not MotionSubtype.FROM:
            refuse_on_multiaxis(self.state, record, positioning)
        if self.safety_motions:
            safety_motion(self, record)  # TSTFLG's SAFETO/SAFETX
        if mixed:
            positioning = self._mixed_way(record)
        if positioning:
            refuse_on_positioning(self.state, record)
            self.positioning.record(record, self.cycle)
            return
        if self.cycle is not None and record.subtype is not MotionSubtype.FROM:
            if multiaxis:
                self._multiaxis_holes(record)  # CYCLGX: along the tool axis
            else:
                self._cycle_points(record)
            return
        if self.state.threading.armed and record.subtype is not MotionSubtype.FROM:
            feed = self.state.feed
            if feed.rapid_requested or feed.rapid_mode == MODAL:
                self.warn(Diagnostic(RAPID_THREAD, record.where))
                feed.rapid_requested = False
            if feed.rapid_mode:
                self.rapid.leave()  # a thread is cut in the feed range
            self.thread.record(record)
            return
        if record.subtype is not MotionSubtype.FROM:
            feed = self.state.feed
            if feed.rapid_requested or feed.rapid_mode:
                self.rapid.motion(path_length(self.state.position, record))
        if multiaxis:
            if self._circle is None or not self.circle.begin(record):
                self.multiaxis.record(record)
            return
        if self.circle.begin(record):
            return
        self.motion.record(record)

    def _mixed_way(self, record: Motion) -> bool:
        """Option 1 = 3: True when the record goes out by the positioning control, else by
        the contouring one, whose moves make the positioning control's held words stale."""
        way = goes_positioning(self.state, record, self.cycle is not None)
        enter_way(self.state, self.positioning, way)  # options 140 and 86 < 0: Z's frame
        if way:
            if self._circle is not None:
                self._circle.centre = None  # a rapid move is never an arc: CIRFLG is spent
            return True
        if record.subtype is not MotionSubtype.FROM:
            contouring_moved(self._positioning)
        return False

    def _multiaxis_circle(self) -> None:
        """A multiaxis machine's circle goes out through its transform class (manual
        §3.4.7.1, core/motion/multiaxis_circle.py)."""
        from gecent.core.motion.multiaxis_circle import MultiaxisCircle

        self.circle.finisher = MultiaxisCircle(self.multiaxis, self.circle).finish


def _units(run: Post, statement: Statement) -> None:
    run.units.set_units(statement)


def _names_gecent(statement: Statement) -> bool:
    """MACHIN/GECENT,...: the statement names this postprocessor."""
    args = statement.args
    return bool(args) and isinstance(args[0], Word) and args[0].name == POSTPROCESSOR_NAME


CURVE_WORDS = frozenset({"NURBS", "KNOT", "CNTRL", "SPLINE", "BSPLINE"})
AFTER_END = "END OR RESET HAS NOT BEEN FOLLOWED BY A FROM POINT."  # comment 47 (L34080)
UNKNOWN_WORD = "IS NOT A GECENT III POSTPROCESSOR WORD; STATEMENT DISREGARDED"
PRINTED_ONLY = "PRINTED OUTPUT ONLY: NO TAPE IS PUNCHED (OPTION 173 = 0)"

_TYPE_NAMES = {"MOTION": "5000", "CIRCLE": "3000", "ARELEM": "6000", "MULTIAX": "9000"}
