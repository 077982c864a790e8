"""Command blocks: the DBFSEG cells and the block CODE (manual §3.2-3.3, 001 L629-823)."""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import IntEnum

from gecent.core.absent import ABSENT, Absent

CELLS = 30


class Code(IntEnum):
    """Command-block identification CODE (DBFSEG(15)); drives print and punch."""

    LINEAR = 0
    NONMOTION = 1
    AUX_ONLY = -1
    ROTARY_ABSOLUTE = 2
    ROTARY_INCREMENTAL = -2
    FROM = 3
    TURRET_CORRECTION = -3
    DWELL = 4
    G_ONLY = -4
    END = 5
    RESET = -5
    INSERT = 6
    BREAK = -6
    PPRINT = 7
    PARTNO = -7
    TMARK = 8
    LEADER = -8
    COMMENT = 9
    INFORMATION = -9
    CIRCLE_XY_CLW = 10
    CIRCLE_XY_CCLW = -10
    CIRCLE_ZX_CLW = 11
    CIRCLE_ZX_CCLW = -11
    CIRCLE_YZ_CLW = 12
    CIRCLE_YZ_CCLW = -12
    THREAD_5 = 13
    THREAD_6 = -13
    MULTIHEAD_TURRET_1 = 14
    MULTIHEAD_TURRET_2 = -14
    AUX_HEAD_IPM = 15
    POSITION_XY = 16
    POSITION_Z = -16
    MULTIHEAD_1 = 17
    MULTIHEAD_2 = -17
    FINI = 18
    CYCLE = 19  # gecent: a modern control's canned-cycle block (G81-G85, option 251 = 1)


# Blocks that never reach the tape (manual §3.5.3.2 per-CODE disposition).
NOT_PUNCHED = frozenset(
    {Code.FROM, Code.RESET, Code.PPRINT, Code.COMMENT, Code.INFORMATION, Code.FINI}
)
NOT_PRINTED = frozenset({Code.RESET, Code.INFORMATION, Code.FINI})
TEXT_CODES = frozenset({Code.INSERT, Code.PPRINT, Code.PARTNO, Code.COMMENT})


@dataclass(slots=True)
class Block:
    """One command block: cells 1..30 as in DBFSEG (index 0 unused) plus its CODE.

    Text blocks (PARTNO, PPRINT, INSERT, comments) carry their text instead of cells.
    """

    code: Code
    record: int | None = None
    text: str | None = None
    cells: list[float | Absent] = field(default_factory=lambda: [ABSENT] * (CELLS + 1))
    # the machine point reached (steps, CL axis order) and the departures in steps, for the
    # absolute printout and for checking a tape against its CL points
    position: tuple[int, ...] | None = None
    steps: tuple[int, ...] | None = None
    radius: float | None = None  # CIRRAD of a circular block
    feed_length: float = 0.0  # a cycle block's travel at feed; a multiaxis move's part path
    sweep: float | None = None  # the angle a whole-arc block turns (radians, option 253)
    rapid: bool = False
    rotary: tuple[int, float] | None = None  # a rotary block's cell and travel in degrees
    # the time this block takes: cutting (feed and rapid moves) and dwelling (CUTIME, DWTIME)
    cut_minutes: float = 0.0
    dwell_minutes: float = 0.0
    stop: bool = False  # a STOP or OPSTOP block (option 148 < 0 dwells only in these)
    skipped: bool = False  # output under OPSKIP/ON: "/" before the block
    keep_blanks: bool = False  # a text block punched with its blanks (option 256)
    # a cycle macro's output switches (spec 09 §5.6): cell -> True forces the register out
    # even when modal, False leaves it out (the control keeps the value it had)
    switched: dict[int, bool] | None = None
    # a segment of a departure the postprocessor segmented: (first, last) of its segments;
    # None for a block not cut from a longer move (option 17's digit 2 prints only those two)
    segment: tuple[bool, bool] | None = None
    f_format: float | None = None  # REGFOR(11) for this block under inverse time
    # a five-axis move on a modern control: the rotary axes' positions reached (rotary
    # steps, unwrapped), and whether its F is inverse time (G93)
    angles: tuple[int, ...] | None = None
    inverse_time: bool = False
    # set by the output element: the printed value of each register output, and the tape line
    words: tuple[tuple[int, str], ...] = ()
    punch: str | None = None
    # multihead (manual §3.4.8): the head a block belongs to (0: a single-head run), and a
    # combined block's two halves, head 1's and head 2's (GMHBUF 1-20 and 21-40)
    head: int = 0
    halves: tuple[Block, Block] | None = None
    # a tape reel starts at this block: 1 at the first PARTNO, n at the BREAK sequence's
    # reel heading; the punch puts the readable identification there (core/output/reels.py)
    reel: int = 0

    @classmethod
    def motion(
        cls,
        code: Code,
        record: int,
        departures: tuple[int, ...],
        reached: tuple[int, ...],
        step: float,
    ) -> Block:
        """A motion block: departures (steps) in cells 3.. and the point reached."""
        block = cls(code, record)
        for axis, steps in enumerate(departures):
            block.cells[3 + axis] = steps * step
        block.steps = departures
        block.position = reached
        return block

    @property
    def punched(self) -> bool:
        return self.code not in NOT_PUNCHED

    @property
    def printed(self) -> bool:
        """Filler cards (leader blocks without text) are punched, not printed."""
        if self.code is Code.LEADER and self.text is None:
            return False
        return self.code not in NOT_PRINTED
