"""Thread cutting on a contouring lathe (manual §4.6, 001 L15648-16023; THREDO
L38391-38446), read in docs/research/threading.md.

A THREAD makes the next motion record a thread (one-shot). Its path is linear, rounded and
segmented like any move; each block carries:

* the departures;
* the lead components in I and J, proportional to the departures: the lead itself on the
  threading axis (X for TURN, Y for FACE), scaled by a power of ten M that shifts the
  lead's leading zeros out of the register, so a fine lead keeps five significant digits
  (CODE +13: a five-digit lead, -13: a six-digit lead with its leading zero passed over);
* the thread G code by lead type (constant, increasing, decreasing), lead range (normal,
  extended) and control (the 100S has its own codes, halves an extended lead and outputs
  the excess over 10 inches of an extended departure);
* for a variable lead only, F = the threading rate THRATE (scaled by M, in the lead
  register's format); a constant lead needs no F, the control follows the spindle.

The tool-tip feed S x lead, printed in the F-IPM column, is checked against the maximum
feedrate ("MAXIPM EXCEEDED."); the spindle speed against the capability tables.
"""

from __future__ import annotations

from collections.abc import Callable
from math import sqrt

from gecent.core.cl.records import Motion, MotionSubtype
from gecent.core.errors import Diagnostic, InputError, SourcePosition
from gecent.core.machine.shuffle import cell_map
from gecent.core.motion.guard import check_segments
from gecent.core.motion.linear import LinearMotion
from gecent.core.motion.segments import segment_count, segment_place, segments
from gecent.core.output.block import Block, Code
from gecent.core.spindle import TOO_FAST_FOR_THREADING, assumed_speed
from gecent.core.state import PostState

# TABLEG cells of the thread G codes by THMODE (0 constant, +1 increasing, -1 decreasing)
NORMAL_LEAD = {0: 34, 1: 35, -1: 36}
EXTENDED_LEAD = {0: 37, 1: 38, -1: 39}
# the 100S (option 165 = 1) by the largest lead each code takes: the normal and the
# extended-departure code (TABLEG 101-103, 98-100) and the highest spindle speed, for 0.1-inch
# and 1-mm resolver gearing (§4.6 table 2, 001 L15839-15860; TABLEG L22983-23011)
MARK_100S_INCH = (
    (0.099999, 103, 100, 2500.0),
    (0.99999, 102, 99, 400.0),
    (1.99998, 101, 98, 200.0),
)
MARK_100S_MM = ((2.9999, 103, None, 2500.0), (29.999, 102, None, 400.0), (59.998, 101, None, 200.0))
MAXIPM_EXCEEDED = "MAXIPM EXCEEDED."
NOT_COUPLED = "THE ENCODER IS NOT COUPLED FOR THREADING."


class ThreadElement:
    """THREDO: the thread blocks of one motion record."""

    def __init__(
        self,
        state: PostState,
        emit: Callable[[Block], None],
        motion: LinearMotion,
        warn: Callable[[Diagnostic], None],
        machine_mm: float,
    ) -> None:
        machine = state.machine
        self.state = state
        self.emit = emit
        self.motion = motion
        self.warn = warn
        self.step = machine.number_option(14)
        metric = machine_mm == 1.0
        # normal leads end at .99999 in or 9.9999 mm (table 1); the 100S's codes, its extended
        # lead (halved) above the middle row, its extended departure over 9.9999 in (inch only)
        self.extended_lead = 10.0 if metric else 1.0
        self.mark_100s = machine.number_option(165) == 1
        self.table_100s = MARK_100S_MM if metric else MARK_100S_INCH
        self.halved_above = self.table_100s[1][0]
        self.long_departure = None if metric else 9.9999
        self.lead_registers = cell_map(machine.number_option(60), "IJK")

    def record(self, record: Motion) -> None:
        threading = self.state.threading
        threading.armed = False  # THREAD is one-shot (001 L15733-15736)
        if threading.lead is None:
            raise InputError("THREAD needs a PITCH statement before its motion", record.where)
        points = (
            (self.motion.godlta_point(record),)
            if record.subtype is MotionSubtype.GODLTA
            else record.points
        )
        axis = 1 if threading.facing else 0
        travel = self._travel(points, axis)
        if travel == 0.0:
            name = "FACE" if threading.facing else "TURN"
            raise InputError(
                f"THREAD/{name} needs a move along {'XY'[axis]}, its threading axis", record.where
            )
        rate = self._rate(travel, record.where)
        self._check_spindle(rate, travel, record.where)
        lead = threading.lead
        done = 0.0
        for point in points:
            done = self._point(record, point, axis, rate, lead, done)

    def _travel(self, points: tuple[tuple[float, ...], ...], axis: int) -> float:
        at = self.state.position.previous_part[axis] - self.state.position.translation[axis]
        total = 0.0
        for point in points:
            total += abs(point[axis] - at)
            at = point[axis]
        return total

    def _rate(self, travel: float, where: SourcePosition) -> float:
        """THRATE = (Lf^2 - Li^2) / (2 s), s the screw length: PITCH's, or this path's
        travel along the threading axis (001 L34630-34645)."""
        threading = self.state.threading
        if threading.mode == 0 or threading.final_lead is None or threading.lead is None:
            return 0.0
        length = threading.length if threading.length is not None else travel
        return (threading.final_lead**2 - threading.lead**2) / (2 * length)

    def _largest_lead(self) -> float:
        threading = self.state.threading
        assert threading.lead is not None
        return max(threading.lead, threading.final_lead or 0.0)

    def _g_code(self, lead: float, extended_departure: bool, where: SourcePosition) -> int:
        machine = self.state.machine
        mode = self.state.threading.mode
        if self.mark_100s:
            if mode != 0:
                raise InputError(
                    "the 100S control (option 165 = 1) cuts constant leads only", where
                )
            for largest, normal, extended, _ in self.table_100s:
                if lead <= largest:
                    cell = extended if extended_departure and extended else normal
                    break
            else:
                top = self.table_100s[-1][0]
                raise InputError(f"a lead of {lead:g} is over the 100S control's {top:g}", where)
        else:
            cell = (EXTENDED_LEAD if lead >= self.extended_lead else NORMAL_LEAD)[mode]
        code = machine.g_code(cell)
        if code is None:
            kind = ("increasing", "constant", "decreasing")[1 - mode]
            raise InputError(
                f"machine {machine.name} has no thread G code (TABLEG {cell}) for a {kind} "
                f"lead of {lead:g}",
                where,
            )
        return int(code)

    def _check_spindle(self, rate: float, travel: float, where: SourcePosition) -> None:
        """The speed the thread is cut at, against the encoder (option 175) and the
        capability tables (§4.6 tables 1 and 2); the encoder must be coupled where the
        machine couples it by M code (TABLEM 51)."""
        machine = self.state.machine
        spindle = self.state.spindle
        if spindle.speed is None:
            self.warn(Diagnostic("OPTION VALUE IS ASSUMED FOR THE SPINDLE SPEED", where))
            spindle.speed = assumed_speed(machine, where)
        if machine.m_code(51) is not None and not self.state.threading.coupled:
            self.warn(Diagnostic(NOT_COUPLED, where))
        lead = self._largest_lead()
        if self.mark_100s:
            limit = next((rpm for top, _, _, rpm in self.table_100s if lead <= top), 200.0)
        elif lead >= self.extended_lead:
            limit = 60.0
        else:
            limit = 370.0 if machine.number_option(205) == 1 else 600.0
        if spindle.speed > limit or (
            self.state.threading.coupled and spindle.speed > machine.number_option(175)
        ):
            self.warn(Diagnostic(TOO_FAST_FOR_THREADING, where))

    def _scale(self, register_cell: int, where: SourcePosition) -> int:
        """k of M = 10^k: the smallest shift putting the largest lead's first significant
        digit in the register's first place (001 L15680-15693, L15975-15990)."""
        machine = self.state.machine
        fmt = machine.registers.formats[register_cell]
        if fmt is None:
            raise InputError(
                f"machine {machine.name} has no register for the thread lead "
                f"(location {register_cell})",
                where,
            )
        lead = self._largest_lead()
        if self.mark_100s and lead > self.halved_above:
            lead /= 2
        k = 0
        floor = 10.0 ** (fmt.left - 1) if fmt.left > 0 else 0.1
        while lead * 10**k < floor * (1 - 1e-12) and k < 12:
            k += 1
        return k

    def _point(
        self,
        record: Motion,
        point: tuple[float, ...],
        axis: int,
        rate: float,
        lead: float,
        done: float,
    ) -> float:
        """One CL point of the thread: its blocks; returns the travel along the threading
        axis done so far."""
        position = self.state.position
        motion = self.motion
        tx, ty, tz = position.translation
        position.present_part[:3] = [point[0] + tx, point[1] + ty, point[2] + tz]
        position.present[:3] = motion.machine_point(position.present_part)
        departures = [position.present[a] - position.previous[a] for a in range(motion.axes)]
        if not any(departures):
            return done
        limits = [motion.depmax] * motion.axes
        if self.mark_100s and self.long_departure is not None:
            limits[axis] = round(19.9999 / self.step)  # the 100S's extended departure
        count = segment_count(departures, limits)
        if count > 1:
            check_segments(count, self.state.max_segments, record.where, "thread")
        reached = list(position.previous[:3])
        target = self.lead_registers[axis]
        assert target is not None
        k = self._scale(target[0], record.where)
        regfor = self.state.machine.registers.regfor[target[0]]
        speed = self.state.spindle.speed or 0.0
        parts = segments(departures, count) if count > 1 else (tuple(departures),)
        for index, part in enumerate(parts):
            for a, steps in enumerate(part):
                reached[a] += steps
            along = abs(part[axis]) * self.step
            start = _lead_at(lead, rate, done, record.where)
            end = _lead_at(lead, rate, done + along, record.where)
            done += along
            block = self._block(record, part, tuple(reached), axis, start, rate, k, regfor)
            block.segment = segment_place(index, count)
            block.cells[19] = speed * _vector_length(part, axis, start)
            if float(block.cells[19]) > abs(self.state.machine.number_option(25)):  # type: ignore[arg-type]
                self.warn(Diagnostic(MAXIPM_EXCEEDED, record.where))
            revolutions = abs(end - start) / abs(rate) if rate else along / start
            block.cut_minutes = revolutions / speed if speed else 0.0
            self.emit(block)
        position.previous_part[:] = position.present_part
        position.previous[:] = position.present
        return done

    def _block(
        self,
        record: Motion,
        part: tuple[int, ...],
        reached: tuple[int, ...],
        axis: int,
        lead: float,
        rate: float,
        k: int,
        regfor: float,
    ) -> Block:
        step = self.step
        along = abs(part[axis]) * step
        extended_departure = (
            self.mark_100s and self.long_departure is not None and along > self.long_departure
        )
        g_code = self._g_code(self._largest_lead(), extended_departure, record.where)
        out_lead = lead
        if self.mark_100s and self._largest_lead() > self.halved_above:
            out_lead = lead / 2  # the 100S's extended lead: half the lead (001 L15937-15939)
        block = Block.motion(
            Code.THREAD_6 if k >= 2 else Code.THREAD_5, record.number, part, reached, step
        )
        if extended_departure:
            sign = 1.0 if part[axis] > 0 else -1.0
            block.cells[3 + axis] = sign * (along - 10.0)
        block.cells[2] = float(g_code)
        # rounded to 12 digits first, so an exact decimal (.000625 x 10) rounds half up at
        # output as it would by hand, not down from its binary neighbour .0062499...
        scaled = round(out_lead * 10**k, 12)
        other = 1 - axis
        block.cells[8 + axis] = scaled
        if other < len(part) and part[other]:
            block.cells[8 + other] = round(abs(part[other] * scaled / part[axis]), 12)
        if rate:
            block.cells[11] = round(abs(rate) * 10**k, 12)
            block.f_format = regfor
        return block


def _lead_at(lead: float, rate: float, travel: float, where: SourcePosition) -> float:
    """The lead after ``travel`` along the axis: dL/dn = THRATE and dx/dn = L give
    L^2 = Li^2 + 2 THRATE x, the relation THRATE's formula comes from."""
    if not rate:
        return lead
    squared = lead * lead + 2 * rate * travel
    if squared <= 0:
        raise InputError("the decreasing lead reaches zero before the thread ends", where)
    return sqrt(squared)


def _vector_length(part: tuple[int, ...], axis: int, lead: float) -> float:
    """|lead vector|: the lead on the threading axis and the ratioed other component."""
    along = abs(part[axis])
    other = abs(part[1 - axis]) if len(part) > 1 else 0
    return lead * sqrt(1.0 + (other / along) ** 2) if along else lead
