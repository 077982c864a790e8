"""GMOUT, the output of the merge pass (manual §3.4.8.2.2, 001 L8404-8792): a head's block
alone goes through GEOUT with that head's registers; two blocks cut together become one
tape block, head 1's words then head 2's before one end of block (GMHBUF 1-20 and 21-40,
001 L9812-9882), with CODE +17 when head 1 is the primary head, -17 when head 2 is; CODE
+14 (-14) when head 1's (head 2's) half is a turret corrective move, cut as a line beside
the other head's regular motion (001 L7676-7677, L9357-9364).

Registers both heads name with the same letter are one register on the control (the
spindle of a two-head lathe, a single G or F register): a combined block carries one
value, in head 1's cell (GMHBUF's layout, 001 L8662-8676): the preferred head's (PRFSEQ;
head 1, the primary head of IH = 3, until one is named). With one G register (option 152 =
0) the G is chosen for both heads' moves: the dimension code of the larger move, or the
circular head's code, the linear head then carrying its "arc-centre offsets" (001
L8737-8785).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from math import hypot

from gecent.core.absent import ABSENT, or_zero
from gecent.core.errors import Diagnostic, InputError, SourcePosition
from gecent.core.feed.rapid import RapidTraverse
from gecent.core.machine.definition import MachineDefinition
from gecent.core.multihead.clearance import ClearanceTest
from gecent.core.multihead.heads import head_machine
from gecent.core.multihead.parking import Parking
from gecent.core.multihead.registers import check_dwell_register, check_own_registers
from gecent.core.output.block import TEXT_CODES, Block, Code
from gecent.core.output.element import CIRCLE_CODES, OutputElement
from gecent.core.output.sinks import Sinks
from gecent.core.state import PostState

# a turret corrective move is cut as a line (001 L7676-7677): beside the other head's move
# it makes a CODE +-14 block (001 L9357-9364)
MERGEABLE = frozenset({Code.LINEAR, Code.DWELL, Code.TURRET_CORRECTION}) | CIRCLE_CODES
SHARABLE_CELLS = (1, 2, 11, 12, 13, 14, 17, *range(21, 31))
# option 156: which (head 1, head 2) interpolation pairs the control can cut together
# (L = linear or dwell, C = circular; 001 L26218-26228)
MODE_PAIRS = {
    0: {("L", "L")},
    1: {("L", "L"), ("C", "L")},
    2: {("L", "L"), ("C", "C")},
    3: {("L", "L"), ("C", "L"), ("C", "C"), ("L", "C")},
}


def mergeable(block: Block) -> bool:
    """Lines, dwells and circles merge (001 L7649-7660); a rapid move is left alone: a
    positioning move has no cut to share."""
    return block.code in MERGEABLE and not block.rapid


def _mode(block: Block) -> str:
    return "C" if block.code in CIRCLE_CODES else "L"


def _time(block: Block) -> float:
    return block.cut_minutes + block.dwell_minutes


class HeadConverter:
    """A head's GEOUT conversion in the merge pass: its registers, its redundancy tests."""

    def __init__(self, machine: MachineDefinition, head: int) -> None:
        self.head = head
        self.machine = head_machine(machine, head)
        self.element = OutputElement(PostState(self.machine))
        self.element.state.head = head  # (its dwells, in a common register: option 195)
        self.element.feed.strictly_below = True  # GMOTIN's GFDLIM (001 L32852-32912)
        self.letters = self.machine.registers.letters
        # the steps of each CL axis's smallest printed value: a piece of a split move is
        # cut on them, or its rounded words would not add up to the move on the tape
        step = self.element.step
        self.quanta: list[int] = []
        for target in self.element.words.shuffle[:3]:
            fmt = self.machine.registers.formats[target[0]] if target is not None else None
            self.quanta.append(max(1, round(10.0**-fmt.right / step)) if fmt else 1)

    def convert(self, block: Block) -> None:
        block.head = self.head
        if block.code in TEXT_CODES or block.punch is not None or block.code is Code.FROM:
            return  # text, FROM, and the TMARK the first pass finished already
        if block.code in (Code.LEADER, Code.FINI, Code.INFORMATION, Code.RESET):
            return
        self.element.convert(block)

    def refinish(self, block: Block, ipm: float) -> None:
        """A piece of a split (or slowed) move: its dimension G, feed command and time
        worked out again, as OUTPUT works them out in the first pass (GMOTIN)."""
        feed = self.element.state.feed  # (this converter's own state: no run reads it)
        feed.ipm = ipm
        feed.programmed = ipm
        feed.rapid_ipm = 0.0
        self.element.motion(block)

    def redwell(self, block: Block, minutes: float) -> None:
        """A piece of a split (or lengthened) dwell: its dwell word made again (DWELL,
        001 L16296-16373)."""
        for cell in range(2, 12):
            block.cells[cell] = ABSENT
        block.dwell_minutes = minutes
        self.element.put_dwell(block, minutes * 60.0)

    @property
    def step(self) -> float:
        return self.element.step

    def rapid_move(
        self, departures: tuple[float, ...], at: tuple[int, ...], record: int | None
    ) -> tuple[list[Block], Block, list[Block]]:
        """A rapid move of this head from ``at`` (steps), as RAPID makes it in the first
        pass: the gear shifts into rapid before it (riding in it or in blocks of their
        own) and back after; (blocks before, the move, blocks after), not yet converted."""
        element = self.element
        step = element.step
        made: list[Block] = []
        element.dump_only = True
        element.emit = made.append
        try:
            rapid = RapidTraverse(element.state, element.output, element.store_m, element.dwell)
            steps = tuple(round(d / step) for d in departures[: len(at)])
            rapid.request()
            rapid.motion(sum((s * step) ** 2 for s in steps) ** 0.5)
            move = Block.motion(
                Code.LINEAR,
                record if record is not None else 0,
                steps,
                tuple(a + s for a, s in zip(at, steps, strict=True)),
                step,
            )
            move.rapid = True
            element.output(move)
            moved = len(made)
            rapid.leave()
            element.flush_m(record)
        finally:
            element.dump_only = False
        for block in made:
            block.head = self.head
        return made[: moved - 1], made[moved - 1], made[moved:]

    def refeed(self, block: Block, code: float) -> None:
        """A linear move under another dimension G code (one G register for both heads):
        its feed command is worked out again with that code's multiplier."""
        element = self.element
        for candidate in element.linear_codes.codes:
            if candidate is not None and candidate.code == code:
                break
        else:
            return
        assert block.steps is not None
        length = sum((s * element.step) ** 2 for s in block.steps) ** 0.5
        ipm = or_zero(block.cells[19])
        if ipm <= 0 or block.cells[11] is ABSENT:
            return
        command, _, f_format = element.feed.command(
            ipm, candidate.gdimul, length, candidate.size_class
        )
        block.cells[11] = command
        block.f_format = f_format


class GMOUT:
    def __init__(
        self, machine: MachineDefinition, sinks: Sinks, warn: Callable[[Diagnostic], None]
    ) -> None:
        self.machine = machine
        self.sinks = sinks
        self.warn = warn
        self.heads = (HeadConverter(machine, 1), HeadConverter(machine, 2))
        self.preferred = 1  # PRFSEQ's head; head 1 until one is named
        self.one_g_register = machine.number_option(152) == 0
        self.one_f_register = machine.number_option(139) == 0
        self.pairs = MODE_PAIRS.get(int(machine.number_option(156)), MODE_PAIRS[0])
        first, second = (h.letters for h in self.heads)
        for cell, option, what in ((2, 152, "preparatory (G)"), (11, 139, "feedrate")):
            if machine.number_option(option) != 0 and first[cell] and first[cell] == second[cell]:
                raise InputError(
                    f"option {option} asks for a {what} register per head, but head 2's has "
                    f"head 1's letter {first[cell]} ([heads.2] regstr {cell})",
                    SourcePosition(machine.origin),
                )
        check_own_registers(machine)
        dwell_cell = check_dwell_register(machine)
        self.shared = tuple(
            cell
            for cell in SHARABLE_CELLS
            if cell < len(first) and first[cell] and first[cell] == second[cell]
        )
        self.dwell_cell = dwell_cell
        if dwell_cell is not None and dwell_cell not in self.shared:
            self.shared += (dwell_cell,)  # one dwell word in a combined block (option 195)
        self.circular_head: int | None = None  # PREPHD's code in effect (TABLEG 16 or 17)
        self.cut_minutes = 0.0
        self.dwell_minutes = 0.0
        self.summed: list[float] | None = None  # each head's time in a combined section
        self.tolerances: tuple[float, float] | None = None  # OP's RPM/SFM and IPM bands
        self.by_rpm = True
        # SFMHD1/SFMHD2, each head's RPM and the point it stands at (steps)
        self.sfm: dict[int, float | None] = {1: None, 2: None}
        self.rpm: dict[int, float | None] = {1: None, 2: None}
        self.positions: dict[int, tuple[int, ...] | None] = {1: None, 2: None}
        self.parking = Parking(self)
        self.clearance = ClearanceTest(machine, self.heads[0].step)

    # -- sections ---------------------------------------------------------------------

    def start_section(self, first_op: Block, second_op: Block) -> None:
        """The heads' OP blocks give the section's restrictions (001 L7626-7645): RPM or
        SFM (DBFSEG(7)) and the tolerance bands in percent, unless either says NONE
        (DBFSEG(11) = 2); the tighter of the two heads' bands holds."""
        self.summed = [0.0, 0.0]
        self.tolerances = None
        ops = (first_op, second_op)
        given = [op for op in ops if op.cells[11] == 0.0 and op.cells[9] is not ABSENT]
        if given and all(op.cells[11] != 2.0 for op in ops):
            spindle = min(or_zero(op.cells[9]) for op in given)
            feed = min(or_zero(op.cells[10]) for op in given)
            self.by_rpm = all(op.cells[7] == 1.0 for op in given)
            self.tolerances = (spindle, feed)

    @property
    def head_outputs(self) -> tuple[HeadConverter, HeadConverter]:
        return self.heads

    def end_section(self) -> None:
        self.summed = None
        self.tolerances = None

    def combinable(self, first: Block, second: Block) -> bool:
        """The control can cut the pair together (option 156, 001 L26218-26228); two
        circles need a G register per head (option 152, 001 L8786-8788)."""
        modes = (_mode(first), _mode(second))
        if first.code is Code.TURRET_CORRECTION and second.code is Code.TURRET_CORRECTION:
            return False  # CODE +-14 pairs a correction with the other head's regular motion
        if modes == ("C", "C") and self.one_g_register:
            return False
        return modes in self.pairs

    def restricted(self, first: Block, second: Block) -> bool:
        """The "three restrictions" (001 L7626-7645): the heads' spindle speeds (RPM, or
        SFM when the OP says SFM) or feedrates differ by more than the OP's bands, in
        percent of the larger. True, with the diagnostic, when the heads may not cut
        together."""
        if self.tolerances is None:
            return False
        spindle, feed = self.tolerances
        speeds = self.rpm if self.by_rpm else self.sfm
        pairs: list[tuple[float | None, float | None, float, str]] = [
            (speeds[1], speeds[2], spindle, "SPINDLE SPEEDS" if self.by_rpm else "SFM VALUES")
        ]
        if Code.DWELL not in (first.code, second.code):  # a delay has no feed to compare
            pairs.append((or_zero(first.cells[19]), or_zero(second.cells[19]), feed, "FEEDRATES"))
        for a, b, band, what in pairs:
            if a is None or b is None or max(a, b) <= 0:
                continue
            if abs(a - b) / max(a, b) * 100.0 > band:
                self.warn(
                    Diagnostic(
                        f"HEADS NOT CUT TOGETHER: THEIR {what} DIFFER BY MORE THAN THE "
                        f"OP TOLERANCE OF {band:g} PERCENT",
                        None,
                    )
                )
                return True
        return False

    def information(self, block: Block) -> None:
        """SAFETY (DBFSEG(11) = 1) and SFM (= 4) information blocks: SAFHD1/SAFHD2 and
        SFMHD1/SFMHD2 (001 L7336-7346)."""
        head = block.head or 1
        if block.cells[11] == 1.0:
            self.parking.safety_given(head, tuple(or_zero(block.cells[k]) for k in (3, 4, 5)))
        else:
            self.sfm[head] = or_zero(block.cells[3])

    def text(self, text: str, record: int | None) -> None:
        """A postprocessor comment (CODE +9) in the listing."""
        self.warn(Diagnostic(text, None))
        self.sinks.emit(Block(Code.COMMENT, record, text))

    # -- output -----------------------------------------------------------------------

    def alone(self, block: Block) -> None:
        """GMOUT(IH = 1 or 2): a head's block by itself."""
        head = block.head or 1
        self.parking.before_alone(block)
        if block.code in CIRCLE_CODES:
            self._prephd(head, block.record)
        self._account(block, head)
        self.heads[head - 1].convert(block)
        self._emit(block)

    def combined(self, first: Block, second: Block, primary: int | None = None) -> None:
        """GMOUT(IH = 3 or 4): both heads' blocks in one tape block; ``primary``: the head
        whose feed command the block carries (else the preferred head's)."""
        self.parking.before_combined(first, second)
        cut, dwell = self._account_pair(first, second)
        primary = primary or self.preferred
        circle_first, circle_second = (b.code in CIRCLE_CODES for b in (first, second))
        if circle_first != circle_second:
            primary = 1 if circle_first else 2  # the sign points at the circular head
            self._prephd(primary, first.record)
        for number, half in ((1, first), (2, second)):
            if half.code is Code.DWELL and (first.code, second.code) != (Code.DWELL,) * 2:
                # a delay beside the other head's move is a zero move, feed command 0
                # (001 L8707-8710): nothing of it goes on the tape but its S, T, M
                for cell in range(2, 12):
                    half.cells[cell] = ABSENT
                if self.dwell_cell is not None:
                    half.cells[self.dwell_cell] = ABSENT
                if primary == number:
                    primary = 3 - number  # the moving head's feed is the block's
        if self.one_g_register:
            self._one_g(first, second)
        for cell in self.shared:
            self._share(cell, first, second, primary)
        if self.one_f_register and 11 not in self.shared:
            # one F register under two letters: GMHBUF(11) takes the primary head's command
            # (001 L8726-8733), and the control's F is then that one
            if primary == 2 and second.cells[11] is not ABSENT:
                first.cells[11] = second.cells[11]
            second.cells[11] = ABSENT
        self.heads[0].convert(first)
        self.heads[1].convert(second)
        if self.one_f_register:
            for converter in self.heads:  # the one register holds the primary's F now
                converter.element.words.previous_f = ABSENT
        code = Code.MULTIHEAD_1 if primary == 1 else Code.MULTIHEAD_2
        if first.code is Code.TURRET_CORRECTION:  # +14: head 1 corrects (001 L9357-9364)
            code = Code.MULTIHEAD_TURRET_1
        elif second.code is Code.TURRET_CORRECTION:
            code = Code.MULTIHEAD_TURRET_2
        block = Block(code, first.record if first.record is not None else second.record)
        block.cells[15] = float(int(code))
        block.halves = (first, second)
        block.head = primary
        block.cut_minutes, block.dwell_minutes = cut, dwell
        separator = self.heads[0].element.separator
        parts = [p for p in (first.punch, second.punch) if p]
        block.punch = separator.join(parts)
        self._emit(block)

    def finish(self, finis: list[Block | None]) -> None:
        """One FINI closes the merged output (the tapes each had theirs)."""
        fini = next((f for f in finis if f is not None), None)
        if fini is not None:
            self.sinks.emit(fini)

    # -- helpers ----------------------------------------------------------------------

    def _emit(self, block: Block) -> None:
        if block.code is Code.RESET:
            return
        for part in block.halves or (block,):
            head = part.head or 1
            if part.cells[20] is not ABSENT:
                self.rpm[head] = or_zero(part.cells[20])
            if part.position is not None and part.code is not Code.FROM:
                self.parking.moved(head, part)
            elif part.position is not None:
                self.parking.placed(head, part)
        self.sinks.emit(block)
        if block.position is not None or block.halves is not None:
            self.clearance.check(self.positions[1], self.positions[2], block.record, self.text)

    def _prephd(self, head: int, record: int | None) -> None:
        """PREPHD (001 L34994-35040, L8664-8669): the G code that lets this head cut the
        circle, TABLEG(16) for head 1, (17) for head 2, in a block by itself; modal, so
        only when the other is in effect (or none yet). A machine without them has none."""
        if self.circular_head == head:
            return
        code = self.machine.g_code(15 + head)
        if code is None:
            return
        self.circular_head = head
        block = Block(Code.G_ONLY, record)
        block.cells[1] = ABSENT if record is None else float(record)  # SEQCTR, as OUTPUT
        block.cells[2] = code
        block.cells[15] = float(int(Code.G_ONLY))
        block.head = 1
        self.heads[0].convert(block)
        self._emit(block)

    def _one_g(self, first: Block, second: Block) -> None:
        circles = [b for b in (first, second) if b.code in CIRCLE_CODES]
        if circles:
            (circle,) = circles  # (option 156 lets two circles through only with two G's)
            line = second if circle is first else first
            self._arc_centre_offsets(circle, line)
            return
        if first.code is Code.DWELL or second.code is Code.DWELL:
            return  # (the dwell's G is gone: the moving head's G serves)
        # both straight: the dimension code of the larger move serves both
        converter = self.heads[0]
        largest = max(
            (abs(s) for b in (first, second) if b.steps is not None for s in b.steps), default=0
        )
        code = converter.element.linear_codes.select(largest)
        for head, block in zip(self.heads, (first, second), strict=True):
            if block.cells[2] != float(code.code):
                block.cells[2] = float(code.code)
                head.refeed(block, float(code.code))

    def _arc_centre_offsets(self, circle: Block, line: Block) -> None:
        """The linear head's I, J, K under one G register (001 L8752-8777): its departures
        over the half angle of the circular head's chord, as the manual writes them."""
        from gecent.core.multihead.split import linear_head_offsets

        step = self.heads[0].element.step
        chord = _three(s * step for s in (circle.steps or ()))
        offsets = tuple(or_zero(v) for v in circle.cells[8:11])
        if not any(offsets) and circle.radius is not None:
            offsets = (circle.radius, 0.0, 0.0)
        departures = _three(s * step for s in (line.steps or ()))
        for axis, value in enumerate(linear_head_offsets(chord, offsets, departures)):
            line.cells[8 + axis] = abs(value) if hypot(*departures) else ABSENT
        line.cells[2] = ABSENT

    def _share(self, cell: int, first: Block, second: Block, primary: int) -> None:
        a, b = first.cells[cell], second.cells[cell]
        if b is ABSENT:
            return
        second.cells[cell] = ABSENT
        if a is ABSENT or a == b:
            first.cells[cell] = b
            return
        keep = primary if cell == 11 else self.preferred
        if cell == 14:  # two M codes cannot share a word: the other goes out first
            other = b if keep == 1 else a
            aside = Block(Code.AUX_ONLY, first.record)
            aside.cells[14] = other
            aside.cells[15] = float(int(Code.AUX_ONLY))
            self._aside(aside)
        first.cells[cell] = a if keep == 1 else b

    def _aside(self, block: Block) -> None:
        """A head-1 block of its own before the combined one (an M code it cannot hold)."""
        self.heads[0].convert(block)
        self._emit(block)

    def _account(self, block: Block, head: int) -> None:
        """The program's time: outside a section each block's own; inside one the heads
        cut at once, so a block adds only what it takes the run past the other head."""
        summed = self.summed
        if summed is None or block.code in TEXT_CODES:
            self.cut_minutes += block.cut_minutes
            self.dwell_minutes += block.dwell_minutes
            return
        before = max(summed)
        summed[head - 1] += _time(block)
        self._shorten(block, max(summed) - before)

    def _account_pair(self, first: Block, second: Block) -> tuple[float, float]:
        """A combined block's (cut, dwell) minutes: what it takes the program past the
        heads' summed times (both heads' times, the longer, outside a section); dwelling
        only when both heads dwell. The halves keep no time of their own."""
        summed = self.summed if self.summed is not None else [0.0, 0.0]
        before = max(summed)
        summed[0] += _time(first)
        summed[1] += _time(second)
        elapsed = max(summed) - before
        both_dwell = first.code is Code.DWELL and second.code is Code.DWELL
        cut, dwell = (0.0, elapsed) if both_dwell else (elapsed, 0.0)
        self.cut_minutes += cut
        self.dwell_minutes += dwell
        for half in (first, second):
            half.cut_minutes = half.dwell_minutes = 0.0
        return cut, dwell

    def _shorten(self, block: Block, elapsed: float) -> None:
        over = max(0.0, _time(block) - elapsed)
        cut = max(0.0, block.cut_minutes - over)
        over -= block.cut_minutes - cut
        block.cut_minutes = cut
        block.dwell_minutes = max(0.0, block.dwell_minutes - over)
        self.cut_minutes += block.cut_minutes
        self.dwell_minutes += block.dwell_minutes


def _three(values: Iterable[float]) -> tuple[float, float, float]:
    """Departures as three axes (a two-axis machine's blocks have two)."""
    x, y, z = (*values, 0.0, 0.0, 0.0)[:3]
    return (x, y, z)
