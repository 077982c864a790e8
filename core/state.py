"""The run state (the manual's labeled COMMON, §5.1.1), grouped by concern.

Slotted dataclasses, so the hot loop reads attributes, not dictionaries. Machine positions
are whole numbers of steps (see core/motion/rounding.py).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from gecent.core.absent import ABSENT, Absent
from gecent.core.errors import Diagnostic
from gecent.core.machine.definition import MachineDefinition
from gecent.core.output.block import Block

if TYPE_CHECKING:
    from gecent.core.motion.ladder import SurfaceSpeedDriver


T_CODE, SPINDLE_COMMAND, SPINDLE_M, SPINDLE_RANGE, SFM, FEED_M, FEED_M2, COOLANT, COOLANT2 = range(
    1, 10
)


@dataclass(slots=True)
class StateVector:
    """STATE(1..9): the last value of each condition; ``None`` for an absent or OFF one."""

    values: dict[int, float] = field(default_factory=dict)
    respecified: set[int] = field(default_factory=set)

    def store(self, slot: int, value: float | None, stopped: bool) -> None:
        if value is None:
            self.values.pop(slot, None)
        else:
            self.values[slot] = value
        if stopped:
            self.respecified.add(slot)

    def due(self, slot: int) -> float | None:
        """The value to reinstate, or None when absent or given again since the stop."""
        if slot in self.respecified:
            return None
        return self.values.get(slot)


@dataclass(slots=True)
class Position:
    """DPRESP/DPREVP (part, with TRANS) and DPRESM/DPREVM (machine, in steps)."""

    present_part: list[float] = field(default_factory=lambda: [0.0] * 6)
    previous_part: list[float] = field(default_factory=lambda: [0.0] * 6)
    present: list[int] = field(default_factory=lambda: [0] * 6)
    previous: list[int] = field(default_factory=lambda: [0] * 6)
    translation: tuple[float, float, float] = (0.0, 0.0, 0.0)
    from_given: bool = False


@dataclass(slots=True)
class Feed:
    """FEDIPM, FDHOLD, FRMOD, the rapid flags RAPFLG, FLRPON, FRAPID, the feed range IFDRNG and
    MAXIPM's SFMAXI (001 L17011-18104, L17356)."""

    ipm: float = 0.0
    programmed: float | None = None
    per_revolution: bool = False  # FRMOD: the programmed feed is per revolution (FEDIPR)
    per_revolution_value: float = 0.0
    rapid_requested: bool = False
    rapid_mode: int = 0  # FLRPON: 0 off, +1 one-shot, -1 modal
    rapid_ipm: float = 0.0  # FRAPID: 0 = not rapid; negative = rapid; positive = reader-limited
    rapid_low: bool = False  # RAPLOW: a move shorter than option 37 stays in the feed range
    range: int = 0  # IFDRNG: the feed range of a multi-range machine (option 18); 0 = none yet
    maximum_ipm: float | None = None  # SFMAXI: FEDRAT/...,MAXIPM,v, held to the range's FRMAX


@dataclass(slots=True)
class Spindle:
    """SPNSPD (RPM), SPNDIR (+1 CLW, -1 CCLW, 0 not yet given), FLONSP, CURNGE; and TOOL."""

    speed: float | None = None
    direction: int = 0
    on: bool = False
    range: int = 1
    range_code: float | None = None  # the last range (or mode) M code output
    # a modern control's tool change stopped the turning spindle: (S command, M code) to
    # start it again with the first move, unless a SPINDL comes first
    restart: tuple[float, float] | None = None


@dataclass(slots=True)
class Tool:
    """TOOL (the loaded tool number) and FORK (a tool has been loaded); on a modern control
    (option 263) the tool's offset number and whether its G43 H is still to go out."""

    number: float | None = None
    offset: int | None = None
    length_pending: bool = False
    length: float | None = None  # LOADTL LENGTH (machine units): a five-axis head's reach
    large_gripper: bool = False  # GRPLOD: LOAD's gripper (R is option 103 or 105, not 102, 104)
    ready_to_unload: int | None = None  # TLNOFF: the tool PICKUP put in the spindle


@dataclass(slots=True)
class Pending:
    """What rides along in the next block OUTPUT emits: SPNCOM and VALUEM."""

    spindle: float | Absent = ABSENT
    m_code: float | Absent = ABSENT
    rpm: float | None = None  # the speed the waiting S command stands for (listing S-RPM)
    # option 1 = 2: TOOLNO's T held for the next motion block (001 L24332-24358)
    tool: float | Absent = ABSENT


@dataclass(slots=True)
class Tolerances:
    """TOLIN, TOLOUT, CUTRAD and the ball-cutter flag (type 6000 records, 001 L3544-3615)."""

    inside: float = 0.0
    outside: float = 0.0
    cutter_radius: float = 0.0
    ball: bool = False

    def take(self, subtype: int, values: tuple[float, ...]) -> None:
        """An ARELEM record: 4 INTOL, 5 OUTTOL, 6 CUTTER."""
        if subtype == 4 and values:
            self.inside = values[0]
        elif subtype == 5 and values:
            self.outside = values[0]
        elif subtype == 6 and values:
            # CUTRAD = D/2; a ball cutter when the corner radius is D/2 (001 L3589-3615)
            self.cutter_radius = values[0] / 2
            corner = values[1] if len(values) > 1 else 0.0
            self.ball = abs(corner - self.cutter_radius) < 1e-6


@dataclass(slots=True)
class Modes:
    """FLONKL and ICLMOD (coolant), STOPON (a stop was given), ENDFLG (END given, a FROM
    must follow), ORGIN (the ORIGIN for the operator printout) (001 L16980-16988,
    L17085-17093, L17395-17403, L18529-18535)."""

    coolant_on: bool = False
    coolant_mode: int = 0  # 0: option 33's mode
    stopped: bool = False
    ended: bool = False
    origin: tuple[float, float, float] = (0.0, 0.0, 0.0)
    compensation: str = ""  # CUTCOM in force: "LEFT", "RIGHT" (or PLUS, MINUS), "" off
    positioning: int = 0  # MODPOS (POSITN): 0 OFF, 1 FINE, 2 NOBACK, 3 COARSE, 4 CORMIL; < 0 TRAV


@dataclass(slots=True)
class Linearity:
    """LINTOL (001 L6980-7043): RADLIN, the sphere's radius (0: no testing), the cone's
    half-angle in degrees (None: no cone test) and LINTOL/OFF's exclusion of one-point
    records."""

    radius: float = 0.0
    cone: float | None = None
    one_point_records: bool = True


@dataclass(slots=True)
class Threading:
    """PITCH's THLEAD, THMODE and THRATE (with the final lead and the thread length they
    come from), THREAD's THFLAG and ITHTYP, and ENCODE (the encoder is coupled)
    (001 L15941-15951, L34612-34686, L38323-38356)."""

    lead: float | None = None  # THLEAD, in machine units per revolution
    mode: int = 0  # THMODE: +1 increasing lead, 0 constant, -1 decreasing
    final_lead: float | None = None
    length: float | None = None  # the screw length THRATE is taken over (None: the path's)
    armed: bool = False  # THFLAG: the next motion record is a thread (one-shot)
    facing: bool = False  # ITHTYP = 2 (FACE); 1 (TURN) otherwise
    coupled: bool = False  # ENCODE


@dataclass(slots=True)
class Sfm:
    """The SFM mode (manual §4.4, 001 L14436-14462; parameters L17563-17570, L18365-18440):
    SFMFLG, SFMDES, ISFMOD/SFMRAD, SFMAXR and SFMLOK with the range it locks. MAXIPM's
    SFMAXI is the feed's (``Feed.maximum_ipm``), which FEDRAT/...,MAXIPM also sets.

    ``driver`` is the spindle element that gives the locked range's speeds and turns the
    spindle for each piece of a path (SFMO's calls of SPTYPE and TSTSAF)."""

    active: bool = False  # SFMFLG: 1 = SFM mode, 0 = RPM mode
    surface_feet: float = 0.0  # SFMDES: the surface speed, feet per minute
    radius_axis: int | None = 0  # ISFMOD - 1: the CL axis (0 x, 1 y, 2 z); None: fixed
    fixed_radius: float = 0.0  # SFMRAD >= 0: the radius, machine units, when axis is None
    maximum_rpm: float | None = None  # SFMAXR: MAXRPM, s
    locked_range: int | None = None  # SFMLOK: the spindle range no speed may leave
    last_end: int = 0  # SFMLIM's cause for the last path (EndCondition; 0: could not start)
    driver: SurfaceSpeedDriver | None = None


@dataclass(slots=True)
class Numbering:
    """SEQNO: ``series`` gives the next N and the increment; ``off`` drops N words;
    ``unrepeated``: an N equal to the last one punched is left out (option 143 = -1)."""

    series: tuple[int, int] | None = None
    off: bool = False
    unrepeated: bool = False
    last: int | None = None

    def switch_on(self, source: float) -> None:
        """SEQNO/ON (001 L26079-26095): option 143 says what numbers the blocks: 0 the CL
        record number, +1 a number going up by one (from 1, or where a series stands),
        -1 the record number without repeats."""
        self.off = False
        self.unrepeated = source == -1
        if source == 1 and self.series is None:
            self.series = (1, 1)


@dataclass(slots=True)
class PostState:
    machine: MachineDefinition
    position: Position = field(default_factory=Position)
    feed: Feed = field(default_factory=Feed)
    pending: Pending = field(default_factory=Pending)
    spindle: Spindle = field(default_factory=Spindle)
    tool: Tool = field(default_factory=Tool)
    tolerances: Tolerances = field(default_factory=Tolerances)
    modes: Modes = field(default_factory=Modes)
    numbering: Numbering = field(default_factory=Numbering)
    threading: Threading = field(default_factory=Threading)
    sfm: Sfm = field(default_factory=Sfm)
    conditions: StateVector = field(default_factory=StateVector)  # STATE(12), option 145
    header: list[str] = field(default_factory=list)  # comments before the start block (264)
    sequence: int = 0  # SEQCTR: the CL record number of the record being processed
    skipping: bool = False  # SKPFLG (OPSKIP)
    max_segments: int = 100_000  # gecent's bound on one CL move's blocks (0: none)
    linearity: Linearity = field(default_factory=Linearity)  # LINTOL (multiaxis)
    head: int = 0  # IHEAD of a multihead run's head (0: a single-head run)
    multihead_op: int = 0  # NOP: the last OP/n of this head
    # core/statements/surfaces.py and control.py (001 L16746-16809, L17958-17961)
    clearance_plane: float | None = None  # CLERP: CLRSRF's height (machine units)
    overcenter: float = 0.0  # OVCVAL: OVRCNT/n (0 after OVRCNT/OFF)
    overcenter_given: float = 0.0  # the last OVRCNT/n, which OVRCNT/ON puts back
    pen_down: bool = False  # UPFLAG: DRAFT/ON lowered the pen (turret)
    flame_head: int = 0  # FLAME's IHEAD: 0 MASTER, 1 SLAVE, -1 BOTH
    weld_off: bool = False  # IGEFLG = 1: WELD/OFF

    def remember(self, slot: int, value: float | None) -> None:
        """Record a condition in STATE; while stopped it counts as given again."""
        self.conditions.store(slot, value, self.modes.stopped)


@dataclass
class RunResult:
    """What a run leaves besides its outputs: ``blocks`` only when the run collects them
    (no sinks given: scripts and tests), ``diagnostics`` only when no reporter is given."""

    machine: MachineDefinition
    blocks: list[Block] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    warnings: int = 0
    partno: str = ""
    records: int = 0
    cut_minutes: float = 0.0
    dwell_minutes: float = 0.0
    # option 110 = +2 and a slide limit exceeded: "warn and continue with no punched output"
    punch_suppressed: bool = False
    dump: list[str] = field(default_factory=list)  # GEDUMP, after a fatal error
