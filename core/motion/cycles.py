"""Canned cycles on a contouring machine whose control has none: each CL point under a
CYCLE is expanded into rapid and feed moves (docs/research/cycles.md; the manual's own
cycle routines CYCLEL/CYCLGP/CYCLGX serve lathes, positioning and multiaxis machines, and
its RAPIDP simulates the R register the same way, 001 L30038-30246, L35274-35313).

A cycle point (x, y, zc) is the hole's top, as APT and CAM systems write it:

1. rapid in X, Y at the current height;
2. rapid down to R = zc + CLEAR - RAPTO;
3. feed to zc - DEPTH (DEEP: pecks of STEP counted from zc, each from R and back to R);
4. FACE (and a DWELL given): a dwell at the bottom;
5. back to R, or to the RETURN level: at rapid, or at feed for BORE and REAM; TAP reverses
   the spindle (TABLEM(5)) for the way out and restores it (TABLEM(4)).

The tool then stays at the return level: the next point's departures start there.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import Diagnostic, InputError, NotYetSupported

# cycle word -> (how it retracts, the TABLEG cell of the control's own cycle, 001 L22875-22977)
CYCLE_TYPES = {
    "DRILL": ("rapid", 82),
    "FACE": ("rapid", 83),
    "DEEP": ("rapid", 84),
    "TAP": ("tap", 85),
    "BORE": ("feed", 86),
    "MILL": ("rapid", 87),
    "THRU": ("rapid", 88),
}
# Creo words without a GECENT cycle, read as the nearest one (with a warning)
STAND_INS = {"BRKCHP": "DEEP", "CSINK": "DRILL", "REAM": "BORE"}
FEED_UNITS = ("IPM", "IPR", "MMPM", "MMPR")
COUPLETS = ("DEPTH", "STEP", "CLEAR", "RAPTO", "RETURN", "DWELL", "TIMES")


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


def parse_cycle(statement: Statement, warn: Callable[[Diagnostic], None]) -> Cycle | None:
    """CYCLE/type, couplets (DEPTH,d  STEP,s  CLEAR,c  RAPTO,r  RETURN,e  DWELL,t), the feed
    (IPM|IPR|MMPM|MMPR, f), or APT's fixed form CYCLE/type, depth, IPM, f, clearance[, step];
    None for CYCLE/OFF."""
    args = statement.args
    if not args or not isinstance(args[0], Word):
        raise InputError(
            "CYCLE expects a cycle type (DRILL, DEEP, TAP, ... or OFF)", statement.where
        )
    kind = args[0].name
    if kind == "OFF":
        if len(args) > 1:
            raise InputError("CYCLE/OFF takes nothing else", statement.where)
        return None
    if kind in STAND_INS:
        warn(Diagnostic(f"CYCLE/{kind} IS PROCESSED AS CYCLE/{STAND_INS[kind]}", statement.where))
        kind = STAND_INS[kind]
    if kind not in CYCLE_TYPES:
        raise NotYetSupported(f"CYCLE/{kind}", statement.where)
    named: dict[str, float] = {}
    bare: list[float] = []
    feed: tuple[float, Word | None] | None = None
    index = 1
    while index < len(args):
        arg = args[index]
        if isinstance(arg, Word):
            following = args[index + 1] if index + 1 < len(args) else None
            if arg.name in COUPLETS or arg.name in FEED_UNITS:
                if following is None or isinstance(following, Word):
                    raise InputError(f"CYCLE: {arg.name} expects a value", statement.where)
                if arg.name in FEED_UNITS:
                    feed = (float(following), arg)
                else:
                    named[arg.name] = float(following)
                index += 2
                continue
            raise NotYetSupported(f"CYCLE/{kind},{arg.name}", statement.where)
        bare.append(float(arg))
        index += 1
    for name in ("DEPTH", "CLEAR", "STEP"):  # the fixed form's numbers, in this order
        if name not in named and bare and (name != "STEP" or kind == "DEEP"):
            named[name] = bare.pop(0)
    if bare:
        raise InputError(f"CYCLE/{kind}: {len(bare)} value(s) left over", statement.where)
    if "DEPTH" not in named:
        raise InputError(f"CYCLE/{kind} needs a depth", statement.where)
    if named["DEPTH"] <= 0 or named.get("STEP", 1.0) <= 0:
        raise InputError(f"CYCLE/{kind}: depth and step must be positive", statement.where)
    if kind == "DEEP" and "STEP" not in named:
        warn(Diagnostic("CYCLE/DEEP WITHOUT A STEP IS DRILLED IN ONE PASS", statement.where))
    return Cycle(
        kind,
        named["DEPTH"],
        named.get("CLEAR", 0.0),
        named.get("STEP"),
        named.get("RAPTO", 0.0),
        named.get("RETURN"),
        named.get("DWELL", 0.0),
        feed,
    )


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
    """The moves that drill ``hole`` (x, y, top) from ``at``, in CL units. DEEP's pecks
    count from the hole's top, as the post makes them; ``pecks_from_plane`` counts them from
    the R plane, as a control's own peck cycle (G83) does."""
    x, y, top = hole
    plane = top + cycle.clearance - cycle.rapto
    bottom = top - cycle.depth
    if cycle.return_level is None:
        back = plane
    elif cycle.return_level == 0:
        back = max(first_z, plane)  # the start level, never below R (as a control's G98)
    else:
        back = top + cycle.return_level
    legs: list[Leg] = []
    if (at[0], at[1]) != (x, y):
        legs.append(Leg((x, y, at[2]), rapid=True))
    legs.append(Leg((x, y, plane), rapid=True))
    if cycle.kind == "DEEP" and cycle.step:
        depth = cycle.step
        start = plane if pecks_from_plane else top
        while start - depth > bottom + 1e-9:
            legs.append(Leg((x, y, start - depth), rapid=False))
            legs.append(Leg((x, y, plane), rapid=True))
            depth += cycle.step
    legs.append(Leg((x, y, bottom), rapid=False))
    retract = CYCLE_TYPES[cycle.kind][0]
    dwell = cycle.dwell if cycle.kind == "FACE" or cycle.dwell else 0.0
    if retract == "tap":
        legs.append(Leg((x, y, back), rapid=False, m_code_cell=5, dwell=dwell))
        legs.append(Leg((x, y, back), rapid=False, m_code_cell=4))
    else:
        legs.append(Leg((x, y, back), rapid=retract == "rapid", dwell=dwell))
    return legs
