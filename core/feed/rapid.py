"""Rapid traverse on a contouring machine: RAPID, RAPIDO, RAPIDX and the option-109 modes
(manual §4.1.4, 001 L11809-11910; TSTFLG L38926-38958; option 109 L25698-25719).

RAPID only raises a request (RAPFLG). The next motion record enters rapid (RAPIDO): a move
shorter than option 37 stays in the feed range at option 39's feed; otherwise the gears
shift into rapid (option 46) and the block is marked rapid at option 42, or at the tape
reader's limit (option 13). A one-shot rapid ends at the following motion record, a modal
one at a FEDRAT (RAPIDX), shifting the gears back.
"""

from __future__ import annotations

from collections.abc import Callable

from gecent.core.machine.definition import MachineDefinition
from gecent.core.output.block import Block
from gecent.core.state import FEED_M, PostState

ONE_SHOT, MODAL = 1, -1

# TABLEM cells of the gear-shift M codes (001 L23165-23227): X, Y, Z into rapid and back.
_INTO_RAPID = (42, 44, 46)
_BACK_TO_FEED = (43, 45, 47)
# heads 2 and 3's own gear cells (001 L23165-23227), the selected head's (TLHEAD, SELHED)
_HEAD_GEAR_CELLS = {
    2: ((142, 144, 146), (143, 145, 147)),
    3: ((148, 150, 152), (149, 151, 153)),
}


class RapidTraverse:
    def __init__(
        self,
        state: PostState,
        emit: Callable[[Block], None],
        store_m: Callable[[float], None],
        dwell: Callable[[float], Block],
    ) -> None:
        machine = state.machine
        self.state = state
        self.emit = emit
        self.store_m = store_m
        self.dwell = dwell
        self.mode = machine.number_option(109)
        self.shifting = machine.number_option(46)
        self.minimum_path = machine.number_option(37)
        self.range_top = machine.number_option(39)
        self.rapid_rate = machine.number_option(42)
        self.reader_time = machine.number_option(13)
        self.catch_up = machine.number_option(16)
        self.into_dwell = machine.number_option(81)
        self.back_dwell = machine.number_option(82)
        self.into_codes: tuple[float, ...] = ()
        self.back_codes: tuple[float, ...] = ()
        self.select_head(1)

    def select_head(self, head: int) -> None:
        """SELECT/HED,n (SELHED sets TLHEAD): the gears shifted from now on are the head's,
        "the M code belonging to the head then in mode" (001 L7270-7278); a head-2 or
        head-3 cell the machine leaves absent shifts nothing on that axis."""
        machine = self.state.machine
        into, back = _HEAD_GEAR_CELLS.get(head, (_INTO_RAPID, _BACK_TO_FEED))
        axes = (0,) if self.shifting < 0 else (0, 1, 2)
        self.into_codes = _codes(machine, into, axes)
        self.back_codes = _codes(machine, back, axes)

    @property
    def modal(self) -> bool:
        return self.mode in (-1.0, 2.0)

    def request(self) -> None:
        """RAPID: the next motion record goes at rapid traverse."""
        self.state.feed.rapid_requested = True

    def feedrate(self, programmed: float, maximum: float) -> bool:
        """FEDRAT under option 109: True when this feedrate means rapid (+1, +2: above the
        range's maximum). A FEDRAT ends a modal rapid (-1: any; +2: one within range)."""
        above = self.mode in (1.0, 2.0) and programmed > maximum
        if above:
            self.request()
        elif self.state.feed.rapid_mode == MODAL:
            self.leave()
        return above

    def motion(self, path_length: float) -> None:
        """TSTFLG, before a motion record is processed."""
        feed = self.state.feed
        if feed.rapid_requested:
            feed.rapid_requested = False
            if feed.rapid_mode:
                return  # already in rapid: no redundant gear shift (001 L11871-11876)
            self.enter(path_length)
        elif feed.rapid_mode == ONE_SHOT:
            self.leave()

    def enter(self, path_length: float) -> None:
        """RAPIDO."""
        feed = self.state.feed
        feed.rapid_mode = MODAL if self.modal else ONE_SHOT
        if self.minimum_path > path_length:
            # too short to be worth a gear shift: the feed range's highest feed (001 L11878-11884)
            feed.rapid_ipm, feed.rapid_low = self.range_top, True
            return
        self._shift(self.into_codes, self.into_dwell)
        if self.shifting and self.into_codes:
            self.state.remember(FEED_M, self.into_codes[-1])
        rate = self.rapid_rate
        reader = self.reader_time
        if reader > 0 and path_length > 0 and rate > path_length / reader:
            feed.rapid_ipm = path_length / reader  # held down by the tape reader: positive
        else:
            feed.rapid_ipm = -rate

    def leave(self) -> None:
        """RAPIDX: back to the feed range; FEDIPM was never changed, so the feed returns."""
        feed = self.state.feed
        shifted = not feed.rapid_low
        feed.rapid_mode, feed.rapid_ipm, feed.rapid_low = 0, 0.0, False
        if shifted:
            codes = self._back_to_range() or self.back_codes
            self._shift(codes, self.back_dwell)
            if self.shifting and codes:
                self.state.remember(FEED_M, codes[-1])

    def _back_to_range(self) -> tuple[float, ...]:
        """On a machine with feed ranges (option 18 > 1) the way back from rapid is the
        present range's own code, not the single TABLEM(43) (FEDRAT's RAPFED, 001
        L31174-31180): MACH04's TABLEM(43) is range 2's M41, wrong in range 1."""
        machine = self.state.machine
        number = self.state.feed.range
        if machine.number_option(18) <= 1 or number < 1:
            return ()
        code = machine.m_code(feed_range_cell(number))
        return () if code is None else (code,)

    def entrap(self) -> None:
        """ENTRAP (option 145 = -1 or -2): after a stop the machine is put in rapid gear, so
        the restart finds it there; the first feed move shifts back (001 L30953-30990)."""
        feed = self.state.feed
        if self.shifting == 0 or not self.into_codes or feed.rapid_mode:
            return
        self._shift(self.into_codes, self.into_dwell)
        self.state.remember(FEED_M, self.into_codes[-1])
        feed.rapid_mode, feed.rapid_ipm, feed.rapid_low = ONE_SHOT, -self.rapid_rate, False

    def _shift(self, codes: tuple[float, ...], dwell: float) -> None:
        """The gear-shift blocks (001 L24979-24995, L24560-24569, L25367-25380; sample
        printout L10362-10383): a catch-up dwell, the M codes, and the shift dwell, which
        carries the last M code; without a shift dwell the last M rides in the motion."""
        if self.shifting == 0 or not codes:
            return
        if self.catch_up > 0:
            self.emit(self.dwell(self.catch_up))
        for code in codes:
            self.store_m(code)
        if dwell > 0:
            self.emit(self.dwell(dwell))


def feed_range_cell(number: int) -> int:
    """TABLEM(112 + r): feed range r's M code (001 L23541-23576)."""
    return 112 + number


def _codes(
    machine: MachineDefinition, cells: tuple[int, ...], axes: tuple[int, ...]
) -> tuple[float, ...]:
    codes = (machine.m_code(cells[axis]) for axis in axes)
    return tuple(code for code in codes if code is not None)
