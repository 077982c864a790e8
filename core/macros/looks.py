"""The engine's look-aheads and operation event (spec 09 §5.9, §7): the look-ahead
variables, $FLOOK and $LOOK, $FINFO, and OPTYPE with its look-ahead; a part of
:class:`gecent.core.macros.engine.MacroEngine`."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from gecent.core.cl.records import Statement
from gecent.core.errors import InputError
from gecent.core.macros.context import Frame, LookaheadFlags
from gecent.core.macros.host import MacroHost
from gecent.core.macros.lookahead import look_ahead
from gecent.core.macros.model import Kind, Macro, MacroError, MacroFailure, Phase
from gecent.core.macros.operations import NOT_PROCESSED, Operations
from gecent.core.macros.params import OperationEventParams
from gecent.core.macros.searches import (
    FINI_FIRST,
    OPTYPE_FIRST,
    OPTYPE_WORDS,
    FlookSearch,
    Gathered,
    MotionSearch,
    OperationSearch,
    Search,
    ToolSearch,
)

MAX_FLOOK = 5
# the kinds whose macros may not look ahead (§4.3)
NO_LOOKAHEAD = frozenset({Kind.DECLARATION, Kind.LCS, Kind.REGISTER, Kind.TAPE, Kind.DIAGNOSTIC})


class LookAheads:
    run: MacroHost
    looking: str | None
    search: Search | None
    flook_stack: tuple[int, ...]
    info: Gathered | None
    oe: Gathered | None
    operations: Operations
    globals: dict[str, Any]
    flags: LookaheadFlags
    guard: tuple[int, int] | None

    # the engine's own (core/macros/engine.py)
    enabled: Callable[[Kind], bool]
    single: Callable[..., Frame | None]

    def _may_look(self, frame: Frame, what: str) -> None:
        if frame.macro.kind in NO_LOOKAHEAD:
            raise MacroError(f"the {describe(frame.macro)} macro cannot {what} (§4.3)")

    def look(self, kind: str, frame: Frame) -> Any:
        """A look-ahead variable (§7.3): cached in the frame; None inside another
        look-ahead (step 2); else a snapshot of the run searches forward."""
        if kind in frame.looked:
            return frame.looked[kind]
        if self.looking is not None:
            return None
        self._may_look(frame, "look ahead")
        if kind == "tool":
            search: Search = ToolSearch()
        else:
            # read in a motion startup macro, the current move is not made yet: an
            # incremental next move counts from its end
            before = frame.macro.kind is Kind.MOTION and frame.macro.phase is Phase.STARTUP
            search = MotionSearch(tuple(frame.params[3][:3]) if before else None)
        result, _ = look_ahead(self.run, search)
        frame.looked[kind] = result
        return result

    def flook(self, frame: Frame, context: int, keep: tuple[str, ...]) -> float:
        """$FLOOK (§7.7): the value the look-ahead of ``context`` ends with."""
        if context == 0:
            return float(self.flook_stack[-1]) if self.flook_stack else 0.0
        if not 1 <= context <= MAX_FLOOK:
            raise MacroError(f"$FLOOK contexts run from 1 to {MAX_FLOOK}, not {context}")
        self._may_look(frame, "call $FLOOK")
        if context in self.flook_stack:
            if self.search is not None and self.search.context == context:
                self.search.flook(context)  # on top: ends it with -1
            return 0.0  # in the stack, not on top: starts nothing (§7.7)
        if self.looking is not None and self.looking != "flook":
            return 0.0  # (Q8: no $FLOOK inside another kind of look-ahead)
        result, clone = look_ahead(self.run, FlookSearch(context))
        for name in keep:
            if name in clone.globals:
                self.globals[name] = clone.globals[name]
        return float(result)

    def set_look(self, context: int, value: float) -> None:
        """$LOOK(context) = value: ends that look-ahead if it is the one on top."""
        if self.search is not None and self.search.context == context:
            self.search.look(context, value)

    def finfo(self, frame: Frame, start: int, end: int | None) -> float:
        """$FINFO (§7.8): the last CL record the operation look-ahead read (-2 at FINI,
        -1 inside another $FINFO); $INFO.* keeps what it gathered."""
        self._may_look(frame, "call $FINFO")
        if self.looking == "finfo":
            return -1.0
        if self.looking is not None:
            return -1.0  # (Q8)
        search = OperationSearch("finfo", self.turning, end)
        (value, info), _ = look_ahead(self.run, search, start)
        info.lock()
        self.info = info
        return float(value)

    def gathered(self, kind: str) -> Gathered | None:
        """$INFO.* (``finfo``) or $OE.* (``oe``): the running look-ahead's own while it runs
        (macros may set them then), else the last one's."""
        search = self.search
        if isinstance(search, OperationSearch) and search.kind == kind:
            return search.info
        return self.info if kind == "finfo" else self.oe

    @property
    def turning(self) -> bool:
        machine = self.run.machine
        return machine.number_option("machine_type") == 0 or machine.number_option(263) == 2

    def operation_event(self, statement: Statement) -> None:
        """OPTYPE (§5.9, §7.9): the OPTYPE look-ahead, the operation-event macro, then the
        operation tables."""
        if self.search is not None:
            self.search.optype(self.run)
        words = statement.words()
        word = words[0] if words else ""
        if word not in OPTYPE_WORDS and word != "AUTO":
            raise InputError(
                "OPTYPE expects TOOL, MILL, TURN, AXIAL or AUTO first", statement.where
            )
        args = statement.args
        resolved = OPTYPE_WORDS.get(word, NOT_PROCESSED)
        if self.looking is None and self.enabled(Kind.OPERATION_EVENT):
            search = OperationSearch("oe", self.turning)
            (found, info), _ = look_ahead(self.run, search)
            if word == "AUTO" or found in (OPTYPE_FIRST, FINI_FIRST):
                resolved = found
            info.OPTYPE, info.OPARGS = resolved, args
            info.lock()
            self.oe = info
            params = OperationEventParams()
            for number, value in ((1, resolved), (2, args), (3, statement.number),
                                  (4, info.P2.CLN), (5, 1 if info.P1.CLN else 0)):  # fmt: skip
                params.set(number, value)
            self.single(Kind.OPERATION_EVENT, params, statement, _no_output)
            self.guard = _guard(params, statement)
        self.operations.operation_type(resolved, args)


def _guard(params: OperationEventParams, statement: Statement) -> tuple[int, int] | None:
    """The redundancy guard's CL records, $P3 to $P4 as the OE macro left them (§5.9):
    $P4 = 0 disables it, a larger $P4 carries it into the cut."""
    if params.cut_record is None:
        return None  # no cut ahead (another OPTYPE or FINI first): nothing to guard
    try:
        first, last = int(params.first_record), int(params.cut_record)
    except (TypeError, ValueError):
        raise MacroFailure(
            "the operation-event macro's $P3 and $P4 are CL record numbers, not "
            f"{params.first_record!r} and {params.cut_record!r}",
            statement.where,
        ) from None
    return None if last == 0 else (first, last)


def _no_output(frame: Frame) -> None:
    raise MacroError("OUTPUT is not allowed in the operation-event macro (§3)")


def describe(macro: Macro) -> str:
    if macro.kind is Kind.SYNTAX:
        return "user-defined"
    if macro.phase is Phase.EVENT:
        return str(macro.kind.value)
    return f"{macro.kind.value} {macro.phase.value}"
