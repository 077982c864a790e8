"""What a macro body sees: ``ctx`` (spec 09 §13.3).

=====================  ============================================
macro language         Python
=====================  ============================================
``OUTPUT``             ``ctx.output()``
``MATCH/ON|OFF``       ``ctx.match(True|False)``
``TERMAC``             ``ctx.terminate()``
``$P2``, ``$P2(3)``    ``ctx.p[2]``, ``ctx.p[2][2]`` (tuples are 0-based in Python)
``COOLNT/FLOOD``       ``ctx.cmd("COOLNT/FLOOD")`` or ``ctx.cmd("COOLNT", "FLOOD")``
``GOTO/x,y,z``         ``ctx.goto(x, y, z)`` (also ``from_``, ``godlta``)
``INSERT/text``        ``ctx.insert("M07")``; ``ctx.pprint(text)``
``$NT``, ``$NXM``      ``ctx.next.tool``, ``ctx.next.motion.xm``
``$LOOKAH``, ``$TLOOK``  ``ctx.la.active``, ``ctx.la.tool``, ``ctx.la.motion``
``$FT``, ``$TAPMAC``   ``ctx.sv.FT``, ``ctx.sv.TAPMAC`` (also ``ctx.sv["$FT"]``)
%L01, GLOBAL           ``ctx.locals``, ``ctx.globals`` (dicts)
=====================  ============================================
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, NoReturn, Protocol

from gecent.core.macros.host import MacroHost
from gecent.core.macros.model import MacroError, TerminateMacro
from gecent.core.macros.params import PParams

if TYPE_CHECKING:
    from gecent.core.cl.records import Record
    from gecent.core.machine.definition import MachineDefinition
    from gecent.core.macros.model import Macro
    from gecent.core.state import PostState


class Engine(Protocol):
    """What a macro body reaches of the engine (core/macros/engine.py)."""

    run: MacroHost
    globals: dict[str, Any]
    sv: Any
    flags: LookaheadFlags

    def look(self, kind: str, frame: Frame) -> Any: ...

    def output(self, frame: Frame) -> None: ...

    def command(self, frame: Frame, text: str) -> None: ...

    def text(self, frame: Frame, major: str, text: str) -> None: ...

    def warn(self, frame: Frame, text: str) -> None: ...

    def flook(self, frame: Frame, context: int, keep: tuple[str, ...]) -> float: ...

    def set_look(self, context: int, value: float) -> None: ...

    def finfo(self, frame: Frame, start: int, end: int | None) -> float: ...

    def fget(self, majors: tuple[str, ...], first: int, last: int) -> int: ...

    def tapewt(self, frame: Frame, number: int) -> None: ...

    flook_stack: tuple[int, ...]
    operations: Any
    search: Any

    def gathered(self, kind: str) -> Any: ...


@dataclass
class Frame:
    """One activation of a macro: its $P, its locals, its MATCH state and what OUTPUT does
    for it; look-ahead results are cached per frame (§7.3)."""

    macro: Macro
    params: PParams
    record: Record | None
    locals: dict[str, Any]
    on_output: Callable[[Frame], None] | None = None
    matching: bool = True
    outputs: int = 0
    looked: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class NextMotion:
    """The next motion's end point (§7.2): machine values ``xm``... and CL values ``xc``..."""

    xm: float
    ym: float
    zm: float
    xc: float
    yc: float
    zc: float
    record: int | None = None


class _Next:
    def __init__(self, engine: Engine, frame: Frame) -> None:
        self._engine = engine
        self._frame = frame

    @property
    def tool(self) -> float | None:
        """$NT: the tool of the next tool change after the record that invoked this macro,
        None when there is none (or when a look-ahead is running already, §7.3 step 2)."""
        return self._engine.look("tool", self._frame)  # type: ignore[no-any-return]

    @property
    def motion(self) -> NextMotion | None:
        """$NXM...: the next motion's end point; the current position when none follows
        (§7.3), None inside another look-ahead."""
        return self._engine.look("motion", self._frame)  # type: ignore[no-any-return]


@dataclass(frozen=True)
class LookaheadFlags:
    active: bool = False  # $LOOKAH
    tool: bool = False  # $TLOOK
    motion: bool = False  # $MLOOK
    finfo: bool = False  # $ILOOK
    oe: bool = False  # $OELOOK


class _Look:
    def __init__(self, engine: Engine) -> None:
        self._engine = engine

    def __setitem__(self, context: int, value: float) -> None:
        self._engine.set_look(int(context), value)

    def __getitem__(self, context: int) -> int:
        return self.active(context)

    def active(self, context: int) -> int:
        return 1 if int(context) in self._engine.flook_stack else 0


class MacroContext:
    def __init__(self, engine: Engine, frame: Frame) -> None:
        self._engine = engine
        self._frame = frame

    @property
    def p(self) -> PParams:
        return self._frame.params

    @property
    def record(self) -> Record | None:
        """The record that invoked the macro (a user macro: the record it matched)."""
        return self._frame.record

    @property
    def locals(self) -> dict[str, Any]:
        return self._frame.locals

    @property
    def globals(self) -> dict[str, Any]:
        return self._engine.globals

    @property
    def sv(self) -> Any:
        return self._engine.sv

    @property
    def next(self) -> _Next:
        return _Next(self._engine, self._frame)

    @property
    def la(self) -> LookaheadFlags:
        return self._engine.flags

    @property
    def machine(self) -> MachineDefinition:
        return self._engine.run.machine

    @property
    def state(self) -> PostState:
        """The post's state, to read (writing it bypasses the post's own bookkeeping)."""
        return self._engine.run.state

    @property
    def look(self) -> _Look:
        """$LOOK: ``ctx.look[n] = v`` ends $FLOOK context n with v; ``ctx.look.active(n)``."""
        return _Look(self._engine)

    def flook(self, context: int, keep: tuple[str, ...] = ()) -> float:
        """$FLOOK(context): the value its look-ahead ends with ($LOOK(context) set, -1 when
        $FLOOK(context) is called again, -2 at FINI); the ``keep`` globals come back with
        their future values. ``flook(0)`` is the active context (0 for none)."""
        return self._engine.flook(self._frame, int(context), tuple(keep))

    def finfo(self, start: int = 0, end: int | None = None) -> float:
        """$FINFO (§7.8): ``finfo()`` to the end of the coming operation, ``finfo(s, e)``
        from record s (0: here) past record e (0: to FINI); then ``ctx.info`` holds $INFO.*."""
        return self._engine.finfo(self._frame, int(start), None if end is None else int(end))

    @property
    def info(self) -> Any:
        """$INFO.*: of the $FINFO running (writable), else of the last one (None before)."""
        return self._engine.gathered("finfo")

    @property
    def oe(self) -> Any:
        """$OE.*: of the OPTYPE look-ahead running (writable), else of the last one."""
        return self._engine.gathered("oe")

    @property
    def ops(self) -> Any:
        """The operation tables (§9): ``ops.tab[8, ops.oi]`` is $OPTAB(8,$OI)."""
        return self._engine.operations

    def fget(self, majors: tuple[str, ...] | list[str], first: int, last: int = 0) -> int:
        """$FGET (X9): the record number of the first statement ahead, from record
        ``first`` to ``last`` (0: the end), whose major word is listed; -1 if none."""
        return self._engine.fget(tuple(majors), int(first), int(last))

    def tapewt(self, number: int) -> None:
        """TAPEWT (X9): that record ahead processed now; it is skipped when reached."""
        self._engine.tapewt(self._frame, int(number))

    def format_register(self, index: int, value: float) -> str:
        """A value in register ``index``'s own format, letter first ($FSWRIT($FREGFMT(n),
        value), X10); an error names a register the machine has not."""
        for formatter in self._engine.run.output.words.formatters:
            if formatter.location == int(index):
                return f"{formatter.letter}{formatter.format(float(value)).punched}"
        raise MacroError(f"register {index} is not one of this machine's registers")

    def output(self) -> None:
        self._engine.output(self._frame)

    def match(self, on: bool) -> None:
        self._frame.matching = bool(on)

    def terminate(self) -> NoReturn:
        raise TerminateMacro

    def cmd(self, major: str, *args: str | float) -> None:
        """A post-processor command, as an APT statement: ``cmd("SPINDL/300,CLW")`` or
        ``cmd("SPINDL", 300, "CLW")``."""
        text = major if not args else f"{major}/" + ",".join(_item(a) for a in args)
        self._engine.command(self._frame, text)

    def goto(self, x: float, y: float, z: float, *axis: float) -> None:
        self.cmd("GOTO", x, y, z, *axis)

    def from_(self, x: float, y: float, z: float, *axis: float) -> None:
        self.cmd("FROM", x, y, z, *axis)

    def godlta(self, *deltas: float) -> None:
        self.cmd("GODLTA", *deltas)

    def insert(self, text: str) -> None:
        """INSERT/text: a block punched as written."""
        self._engine.text(self._frame, "INSERT", text)

    def pprint(self, text: str) -> None:
        self._engine.text(self._frame, "PPRINT", text)

    def warn(self, text: str) -> None:
        """A diagnostic in the listing and on stderr (the run goes on)."""
        self._engine.warn(self._frame, text)


def _item(value: str | float) -> str:
    if isinstance(value, str):
        return value
    return repr(float(value))
