"""SPINDL/SFM's statement read into its request, and leaving the SFM mode (manual §4.4,
001 L14436-14462; core/spindle.py keeps the element that acts on them)."""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.cl.records import Arg, Statement, Word
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.shuffle import decode_shuffle
from gecent.core.motion.sfm import range_feed_limits
from gecent.core.spindle_types import CCLW, CLW
from gecent.core.state import SFM, PostState

_DIRECTION_WORDS = {"CLW": CLW, "CCLW": CCLW}


def leave_sfm(state: PostState) -> None:
    """SFMFLG = SFMLOK = 0: back to RPM mode at the present speed; STATE(5) is cleared and
    a per-minute feed MAXIPM had lowered is the programmed one again."""
    sfm = state.sfm
    if not sfm.active:
        return
    sfm.active = False
    sfm.locked_range = None
    sfm.driver = None
    state.remember(SFM, None)
    feed = state.feed
    if not feed.per_revolution and feed.programmed is not None:
        low, high = range_feed_limits(state.machine, feed.range)
        feed.ipm = min(max(feed.programmed, low), high)


def machine_mm(machine: MachineDefinition) -> float:
    """Millimetres per machine unit: 1 on a metric machine (option 138 = 1), else 25.4."""
    return 1.0 if machine.number_option(138) == 1 else 25.4


@dataclass(frozen=True, slots=True)
class SfmRequest:
    surface_feet: float
    direction: int | None = None
    range: int | None = None
    radius_axis: int | None = None
    fixed_radius: float = 0.0
    maximum_ipm: float | None = None
    maximum_rpm: float | None = None


_COORDINATES = {"XCOORD": 0, "YCOORD": 1, "ZCOORD": 2}


def radial_axis(machine: MachineDefinition) -> int:
    """The CL axis the machine outputs as X (option 59), the lathe's radial axis in the
    manual's Diagram 4.4C; CL x when none is (decision: the radius SFM reads without
    RADIUS)."""
    targets = decode_shuffle(machine.number_option(59), "XYZ")
    return next((k for k, t in enumerate(targets) if t is not None and t.axis == "X"), 0)


def sfm_request(statement: Statement, words: list[str], default_axis: int) -> SfmRequest:
    """The SFM statement's items: one surface speed, SFM, at most one of CLW/CCLW, ON, and the
    couplets RANGE,r, RADIUS,XCOORD|YCOORD|ZCOORD|R, MAXIPM,v and MAXRPM,s in any order;
    without RADIUS the radius is ``default_axis``."""
    where = statement.where
    if "RPM" in words:
        raise InputError("SPINDL takes one of RPM and SFM", where)
    surface: float | None = None
    couplets: dict[str, Arg] = {}
    directions: list[int] = []
    args = statement.args
    index = 0
    while index < len(args):
        arg = args[index]
        index += 1
        if not isinstance(arg, Word):
            if surface is not None:
                raise InputError("SPINDL/SFM expects one surface speed", where)
            surface = float(arg)
        elif arg.name in ("RANGE", "RADIUS", "MAXIPM", "MAXRPM"):
            if index >= len(args) or arg.name in couplets:
                raise InputError(f"SPINDL/SFM {arg.name} expects one value after it", where)
            couplets[arg.name] = args[index]
            index += 1
        elif arg.name in _DIRECTION_WORDS:
            directions.append(_DIRECTION_WORDS[arg.name])
        elif arg.name not in ("SFM", "ON"):  # (ON: the statement starts the spindle anyway)
            raise InputError(
                f"SPINDL/SFM does not take {arg.name}: it takes CLW or CCLW, RANGE,r, "
                "RADIUS,XCOORD|YCOORD|ZCOORD|r, MAXIPM,v and MAXRPM,s",
                where,
            )
    if surface is None or surface <= 0:
        raise InputError("SPINDL/SFM expects a surface speed > 0 (feet per minute)", where)
    if len(directions) > 1:
        raise InputError("SPINDL takes one of CLW and CCLW", where)
    numbers = {}
    for name, item in couplets.items():
        if name == "RADIUS" and isinstance(item, Word):
            continue
        if isinstance(item, Word):
            raise InputError(f"SPINDL/SFM {name} expects a number, found {item.name}", where)
        numbers[name] = float(item)
        if numbers[name] < 0 or (name != "RADIUS" and numbers[name] == 0):
            raise InputError(f"SPINDL/SFM {name} expects a positive number", where)
    radius = couplets.get("RADIUS")
    radius_axis: int | None = default_axis
    fixed = 0.0
    if isinstance(radius, Word):
        if radius.name not in _COORDINATES:
            raise InputError("SPINDL/SFM RADIUS expects XCOORD, YCOORD, ZCOORD or a radius", where)
        radius_axis = _COORDINATES[radius.name]
    elif radius is not None:
        radius_axis, fixed = None, numbers["RADIUS"]
    range_number = numbers.get("RANGE")
    if range_number is not None and range_number != int(range_number):
        raise InputError(f"SPINDL/SFM RANGE expects a range number, found {range_number:g}", where)
    return SfmRequest(
        surface,
        directions[0] if directions else None,
        None if range_number is None else int(range_number),
        radius_axis,
        fixed,
        numbers.get("MAXIPM"),
        numbers.get("MAXRPM"),
    )
