"""Canned cycles on a contouring machine whose control has none: each CL point under a
CYCLE is expanded into rapid and feed moves (docs/research/cycles.md; the manual's own
cycle routines CYCLEL/CYCLGP/CYCLGX serve lathes, positioning and multiaxis machines, and
its RAPIDP simulates the R register the same way, 001 L30038-30246, L35274-35313).

A cycle point is the hole's top, as APT and CAM systems write it. The hole is drilled along
the machine's spindle axis, the CL axis option 59 puts on Z: CL z on a mill, CL x on an APT
lathe (MACH04), always from the CL axis's positive side, where the tool stands:

1. rapid across to the hole at the current level;
2. rapid in to R = top + CLEAR - RAPTO;
3. feed to top - DEPTH (DEEP: pecks of STEP counted from the top, each from R and back to R);
4. FACE (and a DWELL given): a dwell at the bottom;
5. back to R, or to the RETURN level: at rapid, or at feed for BORE and BORE,DWELL; TAP
   reverses the spindle for the way out (TABLEM(5), or TABLEM(4) for a left-hand tap with
   the spindle CCLW) and restores it.

The BORE forms of TABLEG 91-95 (001 L22895-22977): DRAG stops the spindle (TABLEM(6)) and
comes out at rapid; MANUAL stops the spindle and the program (TABLEM(1)) so the operator can
take the tool out, then comes out at rapid; both start the spindle again. OUT (TABLEG 89,
"spindle forward") drills in and stays at the bottom; IN (TABLEG 90, "spindle withdraw")
takes the tool out to the return level at rapid, then across to the point.

The tool then stays at the return level: the next point's departures start there.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import Diagnostic, InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.shuffle import decode_shuffle

# cycle -> (how it comes out, the TABLEG cell of the control's own cycle, 001 L22875-22977)
CYCLE_TYPES = {
    "DRILL": ("rapid", 82),
    "FACE": ("rapid", 83),
    "DEEP": ("rapid", 84),
    "TAP": ("tap", 85),
    "BORE": ("feed", 86),
    "MILL": ("rapid", 87),
    "THRU": ("rapid", 88),
    "OUT": ("stay", 89),
    "IN": ("withdraw", 90),
    "BORE,DRAG": ("drag", 91),
    "BORE,MANUAL": ("manual", 92),
    "BORE,DWELL,DRAG": ("drag", 93),
    "BORE,DWELL": ("feed", 94),
    "BORE,DWELL,MANUAL": ("manual", 95),
}
# Creo words without a GECENT cycle, read as the nearest one (with a warning)
STAND_INS = {"BRKCHP": "DEEP", "CSINK": "DRILL", "REAM": "BORE"}
FEED_UNITS = ("IPM", "IPR", "MMPM", "MMPR")
COUPLETS = ("DEPTH", "STEP", "CLEAR", "RAPTO", "RETURN", "DWELL", "TIMES")
BORE_WAYS_OUT = ("DRAG", "MANUAL")  # BORE's modifiers besides DWELL (ICYTYP 10-14)
# INHIBT has no text in the manual (CYCLGP's word list only, 001 L30126): read as OFF
INHIBITED = "CYCLE/INHIBT IS PROCESSED AS CYCLE/OFF: THE CYCLE IS SUSPENDED"
SPINDLE_OFF, PROGRAM_STOP = 6, 1  # TABLEM cells of DRAG's and MANUAL's stops
SPINDLE_CLW, SPINDLE_CCLW = 4, 5  # TABLEM cells of the spindle's two directions
ACROSS_TOLERANCE = 1e-9  # a hole this near across is where the tool stands


@dataclass(frozen=True, slots=True)
class Cycle:
    kind: str  # a CYCLE_TYPES key
    depth: float  # below the hole top (CL units)
    clearance: float  # R above the hole top
    step: float | None = None  # DEEP's peck
    rapto: float = 0.0
    return_level: float | None = None  # RETURN: None = R; 0 = the first point's height
    dwell: float = 0.0  # seconds at the bottom (FACE, DWELL)
    feed: tuple[float, Word | None] | None = None  # the cycle feed and its unit word
    axis: int = 2  # the CL axis drilled along (the machine's spindle axis, option 59)
    restart_cell: int = 4  # TABLEM cell the spindle turns by (again after DRAG, MANUAL, TAP)


def parse_cycle(
    statement: Statement, warn: Callable[[Diagnostic], None], needs_depth: bool = True
) -> Cycle | None:
    """CYCLE/type, couplets (DEPTH,d  STEP,s  CLEAR,c  RAPTO,r  RETURN,e  DWELL,t), the feed
    (IPM|IPR|MMPM|MMPR, f), or APT's fixed form CYCLE/type, depth, IPM, f, clearance[, step];
    BORE's modifiers DWELL (with or without a time), DRAG and MANUAL; None for CYCLE/OFF and
    CYCLE/INHIBT. ``needs_depth`` False: a lathe's CYCLEL block, which carries no depth."""
    args = statement.args
    if not args or not isinstance(args[0], Word):
        raise InputError(
            "CYCLE expects a cycle type (DRILL, DEEP, TAP, ... or OFF)", statement.where
        )
    kind = args[0].name
    if kind in ("OFF", "INHIBT"):
        if len(args) > 1:
            raise InputError(f"CYCLE/{kind} takes nothing else", statement.where)
        if kind == "INHIBT":
            warn(Diagnostic(INHIBITED, statement.where))
        return None
    if kind in STAND_INS:
        warn(Diagnostic(f"CYCLE/{kind} IS PROCESSED AS CYCLE/{STAND_INS[kind]}", statement.where))
        kind = STAND_INS[kind]
    if kind not in CYCLE_TYPES or "," in kind:
        # CYCLGP's minor words are the manual's cycles (001 L30106-30130); any other is
        # not a GECENT III cycle (docs/decisions.md, issue 22 wave 7)
        raise InputError(
            f"CYCLE/{kind} is not a GECENT III cycle; the cycles are "
            f"{', '.join(k for k in CYCLE_TYPES if ',' not in k)}, INHIBT and OFF",
            statement.where,
        )
    named: dict[str, float] = {}
    modifiers: list[str] = []
    bare: list[float] = []
    feed: tuple[float, Word | None] | None = None
    index = 1
    while index < len(args):
        arg = args[index]
        if isinstance(arg, Word):
            following = args[index + 1] if index + 1 < len(args) else None
            valued = following is not None and not isinstance(following, Word)
            if kind == "BORE" and (arg.name in BORE_WAYS_OUT or arg.name == "DWELL"):
                if arg.name in modifiers and arg.name != "DWELL":  # BORE,DWELL then DWELL,t
                    raise InputError(f"CYCLE/BORE: {arg.name} twice", statement.where)
                if arg.name not in modifiers:
                    modifiers.append(arg.name)
                if not (arg.name == "DWELL" and valued):
                    index += 1  # the manual's BORE,DWELL names no time
                    continue
            if arg.name in BORE_WAYS_OUT:
                raise InputError(f"CYCLE/{kind}: {arg.name} is a BORE modifier", statement.where)
            if arg.name in COUPLETS or arg.name in FEED_UNITS:
                if not valued:
                    raise InputError(f"CYCLE: {arg.name} expects a value", statement.where)
                assert following is not None and not isinstance(following, Word)
                if arg.name in FEED_UNITS:
                    feed = (float(following), arg)
                else:
                    named[arg.name] = float(following)
                index += 2
                continue
            raise InputError(
                f"CYCLE/{kind} does not take {arg.name}; it takes "
                f"{', '.join((*COUPLETS, *FEED_UNITS))}"
                + (f", {', '.join(('DWELL', *BORE_WAYS_OUT))}" if kind == "BORE" else ""),
                statement.where,
            )
        bare.append(float(arg))
        index += 1
    for name in ("DEPTH", "CLEAR", "STEP"):  # the fixed form's numbers, in this order
        if name not in named and bare and (name != "STEP" or kind == "DEEP"):
            named[name] = bare.pop(0)
    if bare:
        raise InputError(f"CYCLE/{kind}: {len(bare)} value(s) left over", statement.where)
    if "DEPTH" not in named and kind != "IN" and needs_depth:  # IN goes to R: no depth
        raise InputError(f"CYCLE/{kind} needs a depth", statement.where)
    if named.get("DEPTH", 1.0) <= 0 or named.get("STEP", 1.0) <= 0:
        raise InputError(f"CYCLE/{kind}: depth and step must be positive", statement.where)
    if named.get("DWELL", 0.0) < 0:
        raise InputError(f"CYCLE/{kind}: the dwell must not be negative", statement.where)
    if kind == "DEEP" and "STEP" not in named:
        warn(Diagnostic("CYCLE/DEEP WITHOUT A STEP IS DRILLED IN ONE PASS", statement.where))
    if kind == "BORE":
        if all(way in modifiers for way in BORE_WAYS_OUT):
            raise InputError("CYCLE/BORE: DRAG and MANUAL exclude each other", statement.where)
        if "DWELL" in named and "DWELL" not in modifiers:
            modifiers.append("DWELL")  # Creo's DWELL,t is the BORE,DWELL cycle
        order = ("DWELL", *BORE_WAYS_OUT)
        kind = ",".join(("BORE", *(word for word in order if word in modifiers)))
    return Cycle(
        kind,
        named.get("DEPTH", 0.0),
        named.get("CLEAR", 0.0),
        named.get("STEP"),
        named.get("RAPTO", 0.0),
        named.get("RETURN"),
        named.get("DWELL", 0.0),
        feed,
    )


def cycle_cell(cycle: Cycle) -> int:
    """The TABLEG cell of the control's own cycle for ``cycle``."""
    return CYCLE_TYPES[cycle.kind][1]


def spindle_axis(machine: MachineDefinition) -> int | None:
    """The CL axis option 59 outputs on Z, the axis a hole is drilled along (CL z on a mill,
    CL x on an APT lathe); None when no CL axis goes to Z."""
    targets = decode_shuffle(machine.number_option(59), "XYZ")
    return next((k for k, t in enumerate(targets) if t is not None and t.axis == "Z"), None)


def in_machine_units(cycle: Cycle, length: Callable[[float], float]) -> Cycle:
    """The cycle's distances in machine units (its feed keeps its own unit word)."""
    return replace(
        cycle,
        depth=length(cycle.depth),
        clearance=length(cycle.clearance),
        step=None if cycle.step is None else length(cycle.step),
        rapto=length(cycle.rapto),
        return_level=None if cycle.return_level is None else length(cycle.return_level),
    )


@dataclass(frozen=True, slots=True)
class Leg:
    """One move of an expanded cycle: the end point (CL units) and whether it is rapid."""

    point: tuple[float, float, float]
    rapid: bool
    m_code_cell: int | None = None  # TABLEM cell stored before the move (TAP's reversal)
    dwell: float = 0.0  # seconds, a dwell block before the move


def cycle_legs(
    cycle: Cycle,
    at: tuple[float, float, float],
    hole: tuple[float, float, float],
    first_z: float,
    pecks_from_plane: bool = False,
) -> list[Leg]:
    """The moves that drill ``hole`` (its top) from ``at``, in CL units, along the cycle's
    axis; ``first_z`` is the level along that axis the cycle started from. DEEP's pecks
    count from the hole's top, as the post makes them; ``pecks_from_plane`` counts them from
    the R plane, as a control's own peck cycle (G83) does."""
    axis = cycle.axis

    def on_axis(point: tuple[float, float, float], level: float) -> tuple[float, float, float]:
        moved = list(point)
        moved[axis] = level
        return (moved[0], moved[1], moved[2])

    def across(point: tuple[float, float, float]) -> tuple[float, ...]:
        return point[:axis] + point[axis + 1 :]

    def apart(a: tuple[float, float, float], b: tuple[float, float, float]) -> bool:
        # (a tilted hole's frame, multiaxis_cycles.py, leaves rounding noise across)
        return any(abs(u - v) > ACROSS_TOLERANCE for u, v in zip(across(a), across(b), strict=True))

    top = hole[axis]
    plane = top + cycle.clearance - cycle.rapto
    bottom = top - cycle.depth
    if cycle.return_level is None:
        back = plane
    elif cycle.return_level == 0:
        back = max(first_z, plane)  # the start level, never below R (as a control's G98)
    else:
        back = top + cycle.return_level
    way_out = CYCLE_TYPES[cycle.kind][0]
    legs: list[Leg] = []
    if way_out == "withdraw":
        level = max(at[axis], back)  # a withdrawal never goes deeper
        legs.append(Leg(on_axis(at, level), rapid=True))
        if apart(at, hole):
            legs.append(Leg(on_axis(hole, level), rapid=True))
        return legs
    if apart(at, hole):
        legs.append(Leg(on_axis(hole, at[axis]), rapid=True))
    legs.append(Leg(on_axis(hole, plane), rapid=True))
    if cycle.kind == "DEEP" and cycle.step:
        depth = cycle.step
        start = plane if pecks_from_plane else top
        while start - depth > bottom + 1e-9:
            legs.append(Leg(on_axis(hole, start - depth), rapid=False))
            legs.append(Leg(on_axis(hole, plane), rapid=True))
            depth += cycle.step
    legs.append(Leg(on_axis(hole, bottom), rapid=False))
    dwell = cycle.dwell if cycle.kind == "FACE" or cycle.dwell else 0.0
    at_bottom, out = on_axis(hole, bottom), on_axis(hole, back)
    if way_out == "stay":
        if dwell:
            legs.append(Leg(at_bottom, rapid=False, dwell=dwell))
    elif way_out == "tap":
        # out with the spindle reversed, then turning as it did: M04 then M03 for a
        # right-hand tap, M03 then M04 for a left-hand one (the spindle CCLW)
        reverse = SPINDLE_CLW + SPINDLE_CCLW - cycle.restart_cell
        legs.append(Leg(out, rapid=False, m_code_cell=reverse, dwell=dwell))
        legs.append(Leg(out, rapid=False, m_code_cell=cycle.restart_cell))
    elif way_out == "drag":
        # M05 goes with the way out: a control that stops the spindle at the end of the
        # block would turn it through the bore, which is only a plain way out, never a cut
        legs.append(Leg(out, rapid=True, m_code_cell=SPINDLE_OFF, dwell=dwell))
        legs.append(Leg(out, rapid=True, m_code_cell=cycle.restart_cell))
    elif way_out == "manual":
        # M05 and M00 each in a block of their own at the bottom (the second M stored
        # pushes the first out alone), then out at rapid with the spindle starting again
        legs.append(Leg(at_bottom, rapid=False, m_code_cell=SPINDLE_OFF, dwell=dwell))
        legs.append(Leg(at_bottom, rapid=False, m_code_cell=PROGRAM_STOP))
        legs.append(Leg(out, rapid=True, m_code_cell=cycle.restart_cell))
    else:
        legs.append(Leg(out, rapid=way_out == "rapid", dwell=dwell))
    return legs
