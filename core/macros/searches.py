"""What each look-ahead searches for and gathers (spec 09 §7.2-§7.9, §8): a search sits in
the snapshot engine, the hooks tell it what the snapshot does, and it ends the look-ahead by
raising :class:`Found` with its result.

============  ===============================  =========================================
search        ends at                          result
============  ===============================  =========================================
tool ($NT)    the next tool change             its tool (None at FINI)
motion        the next motion                  its end point (the current one at FINI)
OPTYPE (OE)   the first cutting motion, an     the operation type and ``$OE.*``
              OPTYPE, a tool change, FINI
$FINFO        a rapid after cutting, OPTYPE,   the last record read (-2 at FINI), and
              a tool change, FINI, ``end``     ``$INFO.*``
$FLOOK(n)     ``$LOOK(n) = v``, ``$FLOOK(n)``  v, -1, -2
              again, FINI
============  ===============================  =========================================
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from gecent.core.cl.records import Motion, MotionSubtype, Record
from gecent.core.feed.rapid import MODAL
from gecent.core.macros.context import NextMotion
from gecent.core.macros.model import Found, MacroError
from gecent.core.macros.operations import Operations

if TYPE_CHECKING:
    from gecent.core.macros.host import MacroHost

TOOL, MILL, TURN, AXIAL = 1.0, 2.0, 3.0, 4.0
OPTYPE_FIRST, FINI_FIRST = -1.0, -2.0
OPTYPE_WORDS = {"TOOL": TOOL, "MILL": MILL, "TURN": TURN, "AXIAL": AXIAL}


def next_motion(
    run: MacroHost, record: Motion, base: tuple[float, ...] | None = None
) -> NextMotion:
    """Where a motion record ends (its last point), machine and CL values (§7.2); an
    incremental move counts from ``base`` when given (the end of a move not yet made)."""
    position = run.state.position
    translation = position.translation
    last = record.points[-1]
    if record.subtype is MotionSubtype.GODLTA:
        delta = last if len(last) == 3 else (0.0, 0.0, last[0])
        start = base if base is not None else position.previous_part
        machine = tuple(start[a] + delta[a] for a in range(3))
        cl = tuple(machine[a] - translation[a] for a in range(3))
    else:
        cl = tuple(float(v) for v in last[:3])  # as written: no round trip through TRANS
        machine = tuple(cl[a] + translation[a] for a in range(3))
    return NextMotion(machine[0], machine[1], machine[2], cl[0], cl[1], cl[2], record.number)


def current_motion(run: MacroHost) -> NextMotion:
    """§7.3: no next motion: the current position."""
    position = run.state.position
    machine = tuple(position.present_part[a] for a in range(3))
    cl = tuple(machine[a] - position.translation[a] for a in range(3))
    return NextMotion(machine[0], machine[1], machine[2], cl[0], cl[1], cl[2], None)


@dataclass(frozen=True)
class KeyMotion:
    """``$INFO.Pn.*`` / ``$OE.Pn.*`` (§8.1): CLN 0 when there is none."""

    CLN: int = 0
    AXES: str = "XYZ***"
    C: tuple[float, ...] | None = None  # CL x y z i j k
    W: tuple[float, ...] | None = None  # local machine (no LCS in gecent: = M)
    M: tuple[float, ...] | None = None
    W2: None = None  # no alternate rotary solution on three axes
    M2: None = None


def key_motion(run: MacroHost, record: Motion, start: bool) -> KeyMotion:
    """A motion's end point, or with ``start`` where it begins (the start of a cut)."""
    if start:
        position = run.state.position
        machine = tuple(float(v) for v in position.present_part[:3])
        cl = tuple(machine[a] - position.translation[a] for a in range(3))
    else:
        end = next_motion(run, record)
        machine, cl = (end.xm, end.ym, end.zm), (end.xc, end.yc, end.zc)
    full = (*machine, 0.0, 0.0, 0.0)
    return KeyMotion(record.number, "XYZ***", (*cl, 0.0, 0.0, 1.0), full, full)


class UserValues(dict[int, Any]):
    """``$INFO.V1``-``V99``: None until set; set only while the look-ahead runs."""

    locked = False

    def __missing__(self, number: int) -> None:
        if not 1 <= number <= 99:
            raise MacroError(f"$INFO.V{number}: the user values run from V1 to V99")
        return None

    def __setitem__(self, number: int, value: Any) -> None:
        if not 1 <= number <= 99:
            raise MacroError(f"$INFO.V{number}: the user values run from V1 to V99")
        if not self.locked:
            super().__setitem__(number, value)


@dataclass
class Gathered:
    """``$OE.*`` or ``$INFO.*``: the status at the start of the first cut, the key motions,
    the processing flags and (``$INFO``) the user's ``V1``-``V99``. Writable by macros
    while its look-ahead runs, read-only afterwards (§7.8, §7.9)."""

    OPTYPE: float | None = None
    OPARGS: tuple[Any, ...] = ()
    T: float | None = None
    S: float | None = None
    SDIR: int | None = None
    F: float | None = None
    COOLNT: Any = None
    AXES: str = "XYZ***"
    P1: KeyMotion = field(default_factory=KeyMotion)
    P2: KeyMotion = field(default_factory=KeyMotion)
    P3: KeyMotion = field(default_factory=KeyMotion)
    P4: KeyMotion = field(default_factory=KeyMotion)
    OPCNT: int = 0
    # the span's extents and times ($INFO only): X, Y, Z max and min in machine units,
    # and $OPSUM's seven sums (feed s, positioning s, other s, feed and speed min/max)
    TLMAX: tuple[float | None, ...] = ()
    TLMIN: tuple[float | None, ...] = ()
    TLSUM: tuple[float, ...] = ()
    ISIP: bool = False  # rapid positioning
    ISIL: bool = False  # linear interpolation
    ISIC: bool = False  # 2-D circular interpolation
    ISIH: bool = False  # helical interpolation
    ISIT: bool = False  # threading
    ISCY: bool = False  # any CYCLE motion
    ISCYA: bool = False  # a canned cycle the control runs
    ISCYM: bool = False  # a cycle made by moves
    V: UserValues = field(default_factory=lambda: UserValues())
    locked: bool = False

    def __setattr__(self, name: str, value: Any) -> None:
        if getattr(self, "locked", False):
            return  # written while its look-ahead is not running: ignored (§7.8, §7.9)
        object.__setattr__(self, name, value)

    def lock(self) -> None:
        object.__setattr__(self, "locked", True)
        self.V.locked = True

    def status(self, run: MacroHost) -> None:
        state = run.state
        self.T = None if state.tool.number is None else float(state.tool.number)
        self.S = state.spindle.speed
        self.SDIR = state.spindle.direction
        self.F = state.feed.ipm
        self.COOLNT = getattr(state.modes, "coolant", None)


class Search:
    """A look-ahead; the default reactions do nothing."""

    def stop(self, run: MacroHost) -> None:
        """Ended by a macro (only the operation searches can be)."""

    kind = ""
    context = 0

    def record(self, run: MacroHost, record: Record) -> None: ...

    def tool_change(self, run: MacroHost, tool: float | None) -> None: ...

    def motion(self, run: MacroHost, record: Motion) -> None: ...

    def optype(self, run: MacroHost) -> None: ...

    def flook(self, context: int) -> None: ...

    def look(self, context: int, value: float) -> None: ...

    def fini(self, run: MacroHost) -> Any:
        return None


class ToolSearch(Search):
    kind = "tool"

    def tool_change(self, run: MacroHost, tool: float | None) -> None:
        raise Found(tool)


class MotionSearch(Search):
    kind = "motion"

    def __init__(self, base: tuple[float, ...] | None = None) -> None:
        self.base = base  # where the current move ends, when the search starts before it

    def motion(self, run: MacroHost, record: Motion) -> None:
        raise Found(next_motion(run, record, self.base))

    def fini(self, run: MacroHost) -> Any:
        return current_motion(run)


def _cutting(run: MacroHost, record: Motion) -> bool:
    """A motion at a programmed feed, not rapid (§7.8's cutting motion)."""
    feed = run.state.feed  # before the motion: a one-shot RAPID (+1) was the last move's
    return not (feed.rapid_requested or feed.rapid_mode == MODAL)


class OperationSearch(Search):
    """The OPTYPE look-ahead (``oe``) and ``$FINFO`` (``finfo``)."""

    def __init__(self, kind: str, turning: bool, end: int | None = None) -> None:
        self.operations = Operations()  # the span's blocks, counted by an OperationSink
        self.kind = kind
        self.turning = turning
        self.end = end  # None: to the operation's end; 0: to FINI; n: past record n
        self.bounded = end is not None
        self.info = Gathered()
        self.cutting = False
        self.last = 0
        self.first_type: float | None = None

    def _done(self, value: Any) -> None:
        raise Found(self.result(value))

    def result(self, value: Any) -> tuple[Any, Gathered]:
        info = self.info
        if self.kind == "finfo":
            operations = self.operations
            info.TLMAX = tuple(operations.max[axis, 1] for axis in (1, 2, 3))
            info.TLMIN = tuple(operations.min[axis, 1] for axis in (1, 2, 3))
            info.TLSUM = tuple(operations.sum[column, 1] for column in range(1, 8))
        return (value, info)

    def record(self, run: MacroHost, record: Record) -> None:
        if self.kind == "finfo" and self.end and record.number > self.end:
            self._done(self.last)
        self.last = record.number

    def tool_change(self, run: MacroHost, tool: float | None) -> None:
        if self.kind == "oe":
            self._done(TOOL)
        if not self.bounded:
            self._done(self.last)

    def optype(self, run: MacroHost) -> None:
        if self.kind == "oe":
            self._done(OPTYPE_FIRST)
        if not self.bounded:
            self._done(self.last)

    def motion(self, run: MacroHost, record: Motion) -> None:
        if record.subtype is MotionSubtype.FROM:
            return
        info = self.info
        cutting = _cutting(run, record)
        if run.state.threading.armed:
            info.ISIT = True
        if not info.P1.CLN:
            info.P1 = key_motion(run, record, start=False)
        if run.cycle is not None:
            info.ISCY = True
            if run.control_cycles is not None:
                info.ISCYA = True
            else:
                info.ISCYM = True
        elif cutting:
            info.ISIL = True
            circle = run._circle
            if circle is not None and circle.centre is not None:
                info.ISIC = True
        else:
            info.ISIP = True
        if cutting and not self.cutting:
            self.cutting = True
            info.OPCNT += 1
            info.P2 = key_motion(run, record, start=True)
            info.status(run)
            if self.kind == "oe":
                self._done(AXIAL if run.cycle is not None else TURN if self.turning else MILL)
        if cutting:
            info.P3 = key_motion(run, record, start=False)
        else:
            info.P4 = key_motion(run, record, start=False)
            if self.cutting and self.kind == "finfo" and not self.bounded:
                self._done(self.last)  # a rapid after the cut: the operation is over
            self.cutting = False

    def fini(self, run: MacroHost) -> Any:
        return self.result(FINI_FIRST)

    def stop(self, run: MacroHost) -> None:
        """$ILOOK or $OELOOK set false in a macro: the search ends here (§7.8, §7.9)."""
        if self.kind == "oe":
            self._done(AXIAL if run.cycle is not None else TURN if self.turning else MILL)
        self._done(self.last)


class FlookSearch(Search):
    """``$FLOOK(context)`` (§7.7): returns what ``$LOOK(context)`` is set to, -1 when
    ``$FLOOK(context)`` is called again, -2 at FINI."""

    kind = "flook"

    def __init__(self, context: int) -> None:
        self.context = context

    def flook(self, context: int) -> None:
        if context == self.context:
            raise Found(-1.0)

    def look(self, context: int, value: float) -> None:
        if context == self.context:
            raise Found(float(value))

    def fini(self, run: MacroHost) -> Any:
        return -2.0
