"""Acceleration/deceleration testing, A/D (manual §4.3, 001 L13404-14229; options 3, 32, 55,
69-74, 001 L24375-24386, L24783-24796, L25094-25108, L25243-25279; MCHTOL, L3142).

:class:`AccelerationTest` is the A/D sequence the output element runs on its finished
command blocks before the GEOUT conversion when option 55 = 1 (the servo analysis of
§4.3.1-4.3.2 it draws on is core/feed/servo.py): a block is held ("saved for later possible
modification as a function of other blocks which will ... follow its output", 001 L700-709)
until the next block shows the corner after it. At each corner the approach feed F1 comes
from the overshoot (2), the slowdown point D lies max(Ts F1, k_ao K_o Fi) before it, the
departing feed F2 from F1 and the undershoot (9), the speedup point U lies Ts F2 after it;
an arc is held to 60 Kc sqrt(E r) (3). The manual's own sequence, §4.3.3, is not in it: the
choices filling that gap are in docs/decisions.md.
"""

from __future__ import annotations

from collections.abc import Callable
from copy import copy
from dataclasses import dataclass, replace
from itertools import pairwise
from math import asin, atan2, hypot, pi, sqrt, tau
from typing import TYPE_CHECKING, Protocol

from gecent.core.absent import ABSENT
from gecent.core.cl.records import Statement
from gecent.core.errors import Diagnostic, InputError
from gecent.core.feed.servo import (
    PER_SECOND,
    arc_feed_limit,
    departing_feed,
    overshoot_feed,
    slowdown_distance,
)
from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.guard import check_segments
from gecent.core.output.block import NOT_PUNCHED, Block, Code
from gecent.core.output.modern import CL_PLANES
from gecent.core.state import Feed, PostState

if TYPE_CHECKING:
    from gecent.core.units import UnitScale


@dataclass(frozen=True, slots=True)
class ServoConstants:
    """The machine's A/D options (001 L24375-24386, L24783-24796, L25243-25279)."""

    change: float  # option 3: the largest change of feed in one step, a fraction
    tolerance: float  # option 32: the dynamic tolerance when no MCHTOL is given
    settling: float  # option 69: Ts, seconds
    extra: float  # option 70: k_ao
    overshoot: float  # option 71: K_o, seconds
    undershoot: float  # option 72: K_B, seconds
    gain: float  # option 73: Kv, per second
    circle: float  # option 74: Kc, per second

    @classmethod
    def of(cls, machine: MachineDefinition) -> ServoConstants:
        values = {n: machine.number_option(n) for n in (3, 32, 69, 70, 71, 72, 73, 74)}
        for number, value in values.items():
            if not value > 0:
                raise InputError(
                    f"option {number} = {value:g}: A/D testing (option 55 = 1) needs it more than 0"
                )
        if values[72] >= 1 / values[73]:
            raise InputError(
                f"option 72 = {values[72]:g} (K_B) is not below 1 / option 73 = "
                f"{1 / values[73]:g} (1/Kv): the servo constants do not fit (001 L13832-13960)"
            )
        return cls(values[3] / 100, *(values[n] for n in (32, 69, 70, 71, 72, 73, 74)))


class Finisher(Protocol):
    """What A/D needs of the output element (core/output/element.py)."""

    state: PostState
    step: float
    cut_minutes: float
    accel_ipm: float | None  # the feed CONTUR takes instead of the state's
    diagnostics: list[Diagnostic]  # the run reports them after the record

    def motion(self, block: Block) -> None: ...

    def number_and_emit(self, block: Block) -> None: ...

    @property
    def sink(self) -> Callable[[Block], None]: ...


@dataclass(frozen=True, slots=True)
class Path:
    """A feed block's path: its unit tangents where it begins and ends, its length, and
    the radius of an arc (None for a straight move)."""

    entry: tuple[float, float, float]
    exit: tuple[float, float, float]
    length: float
    radius: float | None


@dataclass(slots=True)
class Held:
    block: Block
    path: Path
    feed: float  # the feed (IPM) it runs at
    wanted: float  # the feed it was given (CONTUR may have held it lower)
    made_in: Feed  # the feed state it was finished in (a FEDRAT or RAPID may follow)


def acceleration_test(output: Finisher) -> AccelerationTest | None:
    """The A/D sequence when option 55 = 1 on a contouring machine (options 70-74 are
    ignored otherwise, 001 L25243-25250); None when it is off."""
    state = output.state
    machine = state.machine
    if machine.number_option(55) != 1 or machine.number_option(1) != 0:
        return None
    # the manual's own A/D was "not currently tested, therefore the standard value must be
    # used" (001 L25094-25108); gecent builds §4.3's analysis for the three slides of one
    # contouring head and refuses the rest (docs/decisions.md, issue 22 wave 9)
    for refused, why in (
        (state.head != 0, AD_MULTIHEAD),
        (machine.multiaxis, AD_MULTIAXIS),
    ):
        if refused:
            raise InputError(f"A/D testing (option 55 = 1) on {why}")
    return AccelerationTest(output)


AD_MULTIHEAD = (
    "a multihead machine: GEMULT's merge pass puts two heads' blocks in one (001 "
    "L7176-7206), so no block's feed belongs to one servo's corner, and the manual's A/D "
    "is untested, its standard 0 to be used (001 L25094-25108)"
)
AD_MULTIAXIS = (
    "a multiaxis machine: §4.3's servo analysis is of the three linear slides (001 "
    "L13404-14229), while a multiaxis block turns rotary axes whose servos it does not "
    "model, and the manual's A/D is untested, its standard 0 to be used (001 L25094-25108)"
)


class AccelerationTest:
    """Holds the last feed block until the block after it shows the corner between them."""

    def __init__(self, output: Finisher) -> None:
        self.output = output
        self.state = output.state
        self.step = output.step
        self.servo = ServoConstants.of(self.state.machine)
        self.tolerance = self.servo.tolerance  # MCHTOL's, or option 32's
        self.centres = int(self.state.machine.number_option(252))
        self.held: Held | None = None
        self.waiting: list[Block] = []  # comments made after the held block
        self.diagnostics = output.diagnostics

    def take(self, block: Block) -> None:
        """A finished block from OUTPUT: a feed move is held for its corner; anything else
        stops the tool (001 L13696-13705: the overshoot is the same with a dwell)."""
        path = self._path(block) if _feed_move(block) else None
        if path is None:
            self.stop()
            self.output.number_and_emit(block)
            return
        servo = self.servo
        made_in = copy(self.state.feed)
        programmed = made_in.ipm  # (CONTUR's limits apply again to each piece)
        limit = programmed
        if path.radius is not None:
            limit = min(limit, arc_feed_limit(self.tolerance, path.radius, servo.circle))
        start = limit
        held, self.held = self.held, None
        if held is not None:
            turn = _angle(held.path.exit, path.entry)
            approach = min(held.feed, overshoot_feed(self.tolerance, turn, servo.overshoot))
            if path.radius is not None:  # into an arc already at its feed
                approach = min(approach, limit)
            self._slow(held, approach)
            leave = departing_feed(approach, turn, self.tolerance, servo.gain, servo.undershoot)
            start = min(limit, leave, _raised(approach, servo.change))
        pieces = self._speed_up(block, path, start, limit, programmed, made_in)
        last, feed = pieces.pop()
        for piece, _ in pieces:
            self.output.number_and_emit(piece)
        actual = float(last.cells[19])  # type: ignore[arg-type]
        if path.radius is None and last is not block:  # the held piece's own length
            path = replace(path, length=sqrt(sum((s * self.step) ** 2 for s in last.steps or ())))
        self.held = Held(last, path, min(feed, actual), feed, made_in)

    def passing(self, block: Block) -> None:
        """A block that does not go through OUTPUT (text, a tape mark): a comment waits
        behind the held block; anything punched, or the end, stops the tool first."""
        if self.held is not None and block.code in NOT_PUNCHED and block.code is not Code.FINI:
            self.waiting.append(block)
            return
        self.stop()
        self.output.sink(block)

    def stop(self) -> None:
        """The tool stops after the held block: its approach is slowed for the whole
        overshoot (past 90 degrees, 001 L13696-13705), then it goes out."""
        held, self.held = self.held, None
        if held is not None:
            approach = overshoot_feed(self.tolerance, pi, self.servo.overshoot)
            self._slow(held, min(held.feed, approach))

    # -- slowing down before a corner, speeding up after it ------------------------------

    def _slow(self, held: Held, approach: float) -> None:
        """The held block's end at F1: steps of at most option 3 down from its feed, the
        last at D = max(Ts F1, k_ao K_o Fi) before the corner, each earlier one its own
        settling distance before the next (001 L13748-13775, L24375-24386)."""
        servo = self.servo
        feeds = [held.feed]
        while feeds[-1] > approach * (1 + 1e-12):
            feeds.append(max(approach, feeds[-1] * (1 - min(servo.change, 1.0))))
            check_segments(len(feeds), self.state.max_segments, None, "A/D slowdown")
        back, cuts = 0.0, []  # back from the corner to each change, the last change first
        for before, after in reversed(list(pairwise(feeds))):
            back += slowdown_distance(after, before, servo.settling, servo.extra, servo.overshoot)
            cuts.append((held.path.length - back, after))
        cuts.reverse()
        profile = [(0.0, held.wanted), *((d, f) for d, f in cuts if d > 0)]
        if cuts and cuts[0][0] <= 0:  # the steps that do not fit: the block starts lower
            profile[0] = (0.0, min(f for d, f in cuts if d <= 0))
            self.diagnostics.append(
                Diagnostic(
                    f"A/D: NO ROOM TO SLOW DOWN TO {approach:.4g} IPM BEFORE THE CORNER "
                    f"({back:.4g} NEEDED, {held.path.length:.4g} THERE)"
                )
            )
        for piece, _ in self._cut(held.block, held.path, profile, held.wanted, held.made_in):
            self.output.number_and_emit(piece)
        for text in self.waiting:
            self.output.sink(text)
        self.waiting.clear()

    def _speed_up(
        self,
        block: Block,
        path: Path,
        start: float,
        limit: float,
        programmed: float,
        made_in: Feed,
    ) -> list[tuple[Block, float]]:
        """After the corner at F2: U lies Ts F2 on, then steps of at most option 3 up to the
        block's feed, each after its own settling distance (001 L13776-13786)."""
        profile = [(0.0, start)]
        distance, feed = 0.0, start
        while feed < limit * (1 - 1e-12):
            distance += self.servo.settling * feed / PER_SECOND
            if distance >= path.length:
                break
            feed = min(limit, _raised(feed, self.servo.change))
            profile.append((distance, feed))
            check_segments(len(profile), self.state.max_segments, None, "A/D speedup")
        return self._cut(block, path, profile, programmed, made_in)

    def _cut(
        self,
        block: Block,
        path: Path,
        profile: list[tuple[float, float]],
        finished: float,
        made_in: Feed,
    ) -> list[tuple[Block, float]]:
        """The block in pieces at the profile's distances, each given its feed; an arc is
        not cut: it runs whole at the lowest feed it needs (docs/decisions.md)."""
        if path.radius is not None or len(profile) == 1:
            feed = min(f for _, f in profile)
            if abs(feed - finished) > 1e-9 * finished:
                self._refeed(block, feed, made_in)
            return [(block, feed)]
        assert block.steps is not None and block.position is not None
        start = [p - s for p, s in zip(block.position, block.steps, strict=True)]
        pieces: list[tuple[Block, float]] = []
        done = [0] * len(block.steps)
        ends = [d for d, _ in profile[1:]] + [path.length]
        for (_, feed), end in zip(profile, ends, strict=True):
            reach = [round(s * min(1.0, end / path.length)) for s in block.steps]
            steps = tuple(r - d for r, d in zip(reach, done, strict=True))
            if not any(steps):
                continue
            done = reach
            point = tuple(a + r for a, r in zip(start, reach, strict=True))
            piece = Block.motion(block.code, block.record or 0, steps, point, self.step)
            piece.skipped = block.skipped
            piece.cells[15] = block.cells[15]
            pieces.append((piece, feed))
        first = pieces[0][0]
        for cell in range(12, len(block.cells)):
            first.cells[cell] = block.cells[cell]  # the S, M, T and the like ride in the first
        first.cut_minutes, first.dwell_minutes = block.cut_minutes, block.dwell_minutes
        if block.segment is not None:  # pieces of a segment keep its first and last marks
            for index, (piece, _) in enumerate(pieces):
                piece.segment = (
                    block.segment[0] and index == 0,
                    block.segment[1] and index == len(pieces) - 1,
                )
        for piece, feed in pieces:
            self._refeed(piece, feed, made_in)
        return pieces

    def _refeed(self, block: Block, feed: float, made_in: Feed) -> None:
        """CONTUR again at the feed A/D gives, in the feed state the block was made in; its
        cutting time replaces the time it had."""
        output = self.output
        current, self.state.feed = self.state.feed, made_in
        output.cut_minutes -= block.cut_minutes
        output.accel_ipm = feed
        try:
            output.motion(block)
        finally:
            self.state.feed, output.accel_ipm = current, None
        given = block.cells[19]
        if given is not ABSENT and float(given) > feed * (1 + 1e-6):
            self.diagnostics.append(
                Diagnostic(
                    f"A/D: FEEDRATE {feed:.4g} IPM IS BELOW THE FEED COMMAND'S RANGE; "
                    f"{float(given):.4g} IPM USED"
                )
            )

    # -- the geometry of a block -------------------------------------------------------

    def _path(self, block: Block) -> Path | None:
        assert block.steps is not None
        d = [s * self.step for s in block.steps[:3]]
        if block.code is Code.LINEAR:
            length = sqrt(sum(v * v for v in d))
            if length == 0:
                return None
            unit = (d[0] / length, d[1] / length, d[2] / length)
            return Path(unit, unit, length, None)
        return self._arc(block, d)

    def _arc(self, block: Block, d: list[float]) -> Path:
        """An arc's tangents from its centre: found from the chord, the radius and the side
        the sense and the swept angle put it on; a full circle's from its centre words."""
        assert block.radius is not None and block.steps is not None
        u, v, normal = CL_PLANES[abs(int(block.code)) - 10]
        counter = int(block.code) < 0
        radius = block.radius
        chord = hypot(d[u], d[v])
        if chord > self.step / 2:
            half = min(chord / 2, radius)
            across = sqrt(max(0.0, radius * radius - half * half))
            sweep = block.sweep if block.sweep is not None else 2 * asin(half / radius)
            side = 1.0 if counter != (sweep > pi) else -1.0
            centre = (
                d[u] / 2 - side * across * d[v] / chord,
                d[v] / 2 + side * across * d[u] / chord,
            )
        else:  # a full circle (option 253): I, J, K from its start (252 = 1, 3) or absolute
            assert block.position is not None
            offsets = [float(block.cells[8 + a]) for a in (u, v)]  # type: ignore[arg-type]
            if self.centres not in (1, 3):
                offsets = [
                    o - (block.position[a] - block.steps[a]) * self.step
                    for o, a in zip(offsets, (u, v), strict=True)
                ]
            centre = (offsets[0], offsets[1])
            sweep = tau
        rise = d[normal]
        tangents = []
        for ru, rv in ((-centre[0], -centre[1]), (d[u] - centre[0], d[v] - centre[1])):
            size = hypot(ru, rv) or 1.0
            tu, tv = (-rv / size, ru / size) if counter else (rv / size, -ru / size)
            t = [0.0, 0.0, 0.0]
            t[u], t[v], t[normal] = tu * radius * sweep, tv * radius * sweep, rise
            norm = sqrt(sum(x * x for x in t)) or 1.0
            tangents.append((t[0] / norm, t[1] / norm, t[2] / norm))
        return Path(tangents[0], tangents[1], hypot(radius * sweep, rise), radius)


def _raised(feed: float, change: float) -> float:
    """The highest feed one step up reaches: the change at most option 3's fraction of the
    higher feed (100 percent: any change; docs/decisions.md)."""
    return feed / (1 - change) if change < 1 else float("inf")


def _feed_move(block: Block) -> bool:
    return (
        (block.code is Code.LINEAR or 10 <= abs(int(block.code)) <= 12)
        and not block.rapid
        and block.steps is not None
        and block.cells[19] is not ABSENT
    )


def _angle(a: tuple[float, float, float], b: tuple[float, float, float]) -> float:
    """The turn theta between two unit tangents (0 straight on, pi straight back)."""
    cross = (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
    return atan2(hypot(*cross), a[0] * b[0] + a[1] * b[1] + a[2] * b[2])


class _Tested(Protocol):
    accel: AccelerationTest | None


class _Run(Protocol):
    """What MCHTOL needs of the run (a Post; named so A/D imports nothing above it)."""

    @property
    def output(self) -> _Tested: ...

    @property
    def units(self) -> UnitScale: ...


def mchtol(run: _Run, statement: Statement) -> None:
    """MCHTOL/t: the dynamic tolerance of A/D testing (001 L24783-24796); with option
    55 = 0 it has nothing to do."""
    numbers = statement.numbers()
    if len(statement.args) != 1 or len(numbers) != 1 or not numbers[0] > 0:
        raise InputError("MCHTOL expects one tolerance, more than 0", statement.where)
    accel = run.output.accel
    if accel is not None:
        accel.tolerance = run.units.length(numbers[0])


HANDLERS = {"MCHTOL": mchtol}
