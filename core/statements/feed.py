"""FEDRAT and RAPID (manual §4.1, 001 L31113-31212; §4.1.4, L11809-11910), with the feed
ranges of a multi-range machine (option 18, FRTAB; options 91, 93, 219; TABLEM 113-119)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Protocol, runtime_checkable

from gecent.core.cl.records import Arg, Statement, Word
from gecent.core.errors import Diagnostic, InputError, MachineDefinitionError
from gecent.core.families import HookPoint
from gecent.core.feed.positioning import FeedContext
from gecent.core.feed.rapid import feed_range_cell
from gecent.core.motion.sfm import range_feed_limits
from gecent.core.spindle import assumed_speed
from gecent.core.spindle_sfm import leave_sfm
from gecent.core.state import FEED_M

_FEED_UNITS = ("IPM", "MMPM", "IPR", "MMPR")
# FEDRAT/...,RANGE,LOW|MEDIUM|HIGH: the manual scans for the three words, then for a number
_RANGE_WORDS = {"LOW": 1, "MEDIUM": 2, "HIGH": 3}
RANGE_ASSUMED = "OPTION FEED RATE RANGE ASSUMED."  # 001 L31199-31200
RANGE_NOT_AVAILABLE = "RANGE REQUESTED IS NOT AVAILABLE, USE HIGHEST"  # SPINDL's, 001 L37617

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post


class _Hooks(Protocol):
    def macfun(self, hook: HookPoint, **fields: Any) -> bool: ...

    def has_macfun(self, hook: HookPoint) -> bool: ...


class _Engine(Protocol):
    @property
    def hooks(self) -> _Hooks: ...


@runtime_checkable
class _Macros(Protocol):
    """A run that may have a macro engine, with the machine's MACFUN (core/run.py's)."""

    @property
    def macros(self) -> _Engine | None: ...


@dataclass(slots=True)
class FedratRequest:
    """What one FEDRAT statement says: the feed (FDHOLD), its unit word (FRMOD), the
    range (IRANGE) and MAXIPM (SFMAXI); None for what it does not say."""

    value: float | None = None
    unit: Word | None = None
    range: int | None = None
    maximum: float | None = None


def fedrat(run: Post, statement: Statement) -> None:
    """FEDRAT/f[,IPM|IPR][,RANGE,LOW|MEDIUM|HIGH|n][,MAXIPM,v] or FEDRAT/IPM,f
    (001 L31113-31212), in the manual's order: the feed in machine units per minute (per
    revolution: times the spindle speed); option 109's rapid test; the range change
    (STOREM of its M code, STATE(6), the option-93 dwell); the range's limits FRMIN/FRMAX
    for MAXIPM and the feed. MMPM and MMPR are APT IV's; a bare value is in the CL unit and
    keeps the last mode. Without a feed value the held one is kept (FEDRAT/RANGE,2)."""
    request = scan_fedrat(statement)
    feed = run.state.feed
    per_minute = request.unit is not None and request.unit.name in ("IPM", "MMPM")
    if per_minute and run.machine.number_option(2) == 1:
        leave_sfm(run.state)  # option 2 = 1: FEDRAT/n,IPM also ends SFM (001 L24361-24374)
    ipm: float | None = None
    if request.value is not None:
        value = run.units.per_minute(request.value, request.unit)
        if value <= 0:
            raise InputError(
                f"FEDRAT needs a positive feedrate, found {request.value:g}", statement.where
            )
        ipm = _mode_ipm(run, value, request.unit, statement)
    elif feed.programmed is not None:  # FDHOLD: the last feed, in its mode
        ipm = _revolution_ipm(run, statement) if feed.per_revolution else feed.programmed
    # option 109 = +1/+2: a feed above option 25 is a rapid request; tested before the
    # range, as the manual orders it (step 6)
    rapid = ipm is not None and run.rapid.feedrate(ipm, abs(run.machine.number_option(25)))
    _select_range(run, request.range, statement)
    if request.maximum is not None:
        maximum = run.units.per_minute(request.maximum, request.unit)
        if maximum <= 0:
            raise InputError(
                f"FEDRAT MAXIPM needs a positive feedrate, found {request.maximum:g}",
                statement.where,
            )
        feed.maximum_ipm = min(maximum, feed_limits(run)[1])
    if ipm is not None:
        _hold_feed(run, ipm, statement, report=not rapid)


def scan_fedrat(statement: Statement) -> FedratRequest:
    """The statement's items in order: one feed value, at most one unit word (before or
    after it), RANGE and MAXIPM each with the item after them."""
    request = FedratRequest()
    values: list[float] = []
    args = statement.args
    index = 0
    while index < len(args):
        arg = args[index]
        index += 1
        if not isinstance(arg, Word):
            values.append(float(arg))
            continue
        name = arg.name
        if name in _FEED_UNITS and request.unit is None:
            request.unit = arg
        elif name in ("RANGE", "MAXIPM"):
            if index >= len(args):
                raise InputError(f"FEDRAT {name} needs a value after it", statement.where)
            item = args[index]
            index += 1
            if name == "MAXIPM":
                if isinstance(item, Word):
                    raise InputError("FEDRAT MAXIPM expects a feedrate value", statement.where)
                request.maximum = float(item)
            else:
                request.range = _range_number(item, statement)
        else:
            # FEDRAT's scan knows IPM, IPR, RANGE (LOW, MEDIUM, HIGH) and MAXIPM only
            # (001 L31139-31164); MMPM and MMPR are APT IV's metric IPM and IPR
            raise InputError(
                f"FEDRAT/{name}: FEDRAT takes a feed with IPM, IPR, MMPM or MMPR (one of "
                "them), RANGE and MAXIPM",
                statement.where,
            )
    # a feed value may be left out only when RANGE or MAXIPM says something (FEDRAT/RANGE,2)
    alone = request.range is None and request.maximum is None
    if len(values) > 1 or (not values and (alone or request.unit is not None)):
        raise InputError(f"FEDRAT expects one feedrate value, found {len(values)}", statement.where)
    request.value = values[0] if values else None
    return request


def _range_number(item: Arg, statement: Statement) -> int:
    if isinstance(item, Word):
        if item.name not in _RANGE_WORDS:
            raise InputError(
                "FEDRAT RANGE expects LOW, MEDIUM, HIGH or a range number", statement.where
            )
        return _RANGE_WORDS[item.name]
    number = float(item)
    if number < 1 or number != int(number):
        raise InputError(
            f"FEDRAT RANGE expects a range number 1, 2, ..., found {number:g}", statement.where
        )
    return int(number)


def _select_range(run: Post, requested: int | None, statement: Statement) -> None:
    """Step 7 (001 L31170-31185), only on a machine with several feed ranges (option 18 > 1):
    a range different from the present one STOREs its M code TABLEM(112 + r), records it in
    STATE(6) for reinstatement (negative while stopped) and makes the option-93 dwell;
    no range ever given: option 91's range is assumed, with the comment, once."""
    machine = run.machine
    count = int(machine.number_option(18))
    feed = run.state.feed
    if count <= 1:
        if requested is not None and machine.number_option(1) != 0:
            # a positioning feed type's table range (types 4, 5, 6), no M code or dwell
            feed.range = requested
        return  # one range: nothing to select
    if requested is None:
        if feed.range == 0:
            run.warn(Diagnostic(RANGE_ASSUMED, statement.where))
            feed.range = min(max(int(machine.number_option(91)), 1), count)
        return
    if requested > count:
        run.warn(Diagnostic(RANGE_NOT_AVAILABLE, statement.where))
        requested = count
    if requested == feed.range:
        return
    feed.range = requested
    output = run.output
    code = output.store_cell(feed_range_cell(requested), run.warn, statement.where)
    if code is None:
        return
    run.state.remember(FEED_M, code)
    seconds = machine.number_option(93)
    if seconds < 0:
        # "dwell is output by a special machine function subroutine" (001 L25507-25511)
        if machine.number_option(133) != 1:
            raise MachineDefinitionError(
                machine.origin,
                "optab",
                93,
                f"option 93 = {seconds:g} leaves the feed range change dwell to the machine's "
                "MACFUN, but the machine has none (option 133 = 0)",
            )
        # FEDRAT's MACSRT call, at the hook point named for it (its MCHCON number is not
        # legible, L27406-27568): the handler outputs the dwell, the range M code waiting
        engine = run.macros if isinstance(run, _Macros) else None
        hooks = None if engine is None else engine.hooks
        if hooks is None or not hooks.has_macfun(HookPoint.FEED_RANGE):
            raise MachineDefinitionError(
                machine.origin,
                "optab",
                93,
                f"option 93 = {seconds:g} leaves the feed range change dwell to the machine's "
                f"MACFUN, but machine {machine.label}'s MACFUN has no feed range hook "
                f"({HookPoint.FEED_RANGE.value})",
            )
        hooks.macfun(HookPoint.FEED_RANGE, record=statement, values=(float(requested), -seconds))
        return
    if seconds > 0:
        if machine.number_option(219) == 1:
            output.flush_m(statement.number)  # the M code in a block before the dwell
        block = output.dwell(seconds)
        block.record = statement.number
        output.output(block)


def feed_limits(run: Post) -> tuple[float, float]:
    """FRMIN, FRMAX (step 8) of the present feed range; SFM's TSTSAF reads the same."""
    return range_feed_limits(run.machine, run.state.feed.range)


def program_feed(run: Post, value: float, unit: Word | None, statement: Statement) -> None:
    """A programmed feed in machine units (a cycle's): per minute or per revolution as its
    unit word says, or in the last mode without one."""
    _hold_feed(run, _mode_ipm(run, value, unit, statement), statement)


def feed_per_revolution(run: Post, statement: Statement) -> None:
    """FEDIPM = FEDIPR x the spindle speed, again at every speed change."""
    _hold_feed(run, _revolution_ipm(run, statement), statement)


def _mode_ipm(run: Post, value: float, unit: Word | None, statement: Statement) -> float:
    """The feed per minute; a feed without a unit word keeps the last mode, and the first
    one takes option 35's assumed mode, 0 IPM or 1 IPR (001 L24823-24831)."""
    feed = run.state.feed
    if unit is not None:
        feed.per_revolution = unit.name in ("IPR", "MMPR")
    elif feed.programmed is None:
        feed.per_revolution = run.machine.number_option(35) == 1
    if not feed.per_revolution:
        return value
    feed.per_revolution_value = value
    return _revolution_ipm(run, statement)


def _revolution_ipm(run: Post, statement: Statement) -> float:
    speed = run.state.spindle.speed
    if speed is None:
        run.warn(Diagnostic("NO SPINDLE SPEED GIVEN FOR IPR MODE.", statement.where))
        speed = run.state.spindle.speed = assumed_speed(run.machine, statement.where)
    return run.state.feed.per_revolution_value * speed


def _hold_feed(run: Post, feed: float, statement: Statement, *, report: bool = True) -> None:
    """TSTEXT: FEDIPM within FRMIN..FRMAX, with a comment when it was not (none for a feed
    that option 109 turned into a rapid request)."""
    low, high = feed_limits(run)
    used = min(max(feed, low), high)
    if report and used != feed:
        per_minute = "MMPM" if run.units.machine_mm == 1.0 else "IPM"
        run.warn(
            Diagnostic(
                f"FEEDRATE {feed:g} {per_minute} IS OUTSIDE THE MACHINE RANGE "
                f"{low:g}-{high:g}; {used:g} {per_minute} USED",
                statement.where,
            )
        )
    if run.machine.number_option(1) not in (0.0, 3.0):
        # (3, the 7500: the contouring moves take the feed as programmed; its positioning
        # blocks get POSFED's feed at output, core/motion/mixed.py)
        used = _positioning_snap(run, used, statement)
    run.state.feed.ipm = used
    run.state.feed.programmed = feed


def _positioning_snap(run: Post, feed: float, statement: Statement) -> float:
    """K = 0 of the positioning feed type (FTYPEn from FEDRAT, 001 L11316-11322): the feed
    the machine can make becomes FEDIPM, so the listing prints the true value used."""
    state = run.state
    context = FeedContext(
        state.spindle.speed, state.spindle.range, state.feed.range, run.output.milling
    )
    snap = run.feed_type.snap(run.machine, feed, context)
    for comment in snap.comments:
        run.warn(Diagnostic(comment, statement.where))
    return snap.ipm


def rapid(run: Post, statement: Statement) -> None:
    """RAPID: the next motion record goes at rapid traverse (option 109). RAPID takes
    nothing: RAPGB reads no values and its only input is the call (001 L35202-35230)."""
    if statement.args:
        shown = ",".join(a.name if isinstance(a, Word) else f"{a:g}" for a in statement.args)
        raise InputError(
            f"RAPID/{shown}: RAPID takes no values (the manual's RAPID is the word alone)",
            statement.where,
        )
    run.rapid.request()


HANDLERS = {
    "FEDRAT": fedrat,
    "RAPID": rapid,
}
