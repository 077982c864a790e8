"""The CL path a tape must follow, read from the CL file itself (not from the post), in the
machine's axes and units: every point in order, its motion kind, the arc it ends (centre,
radius, sense) and the feed in force.

What the CL file means is read as the post reads it, from the same definitions: UNITS and
FEDRAT units (core/units.py), TRANS, RAPID (one motion record, or modal under option
109 = -1), the CIRCLE record before the motion that ends on the arc (its sense from the
first two points about the centre, or with one point counterclockwise about the circle
axis), and CYCLE: each point a hole drilled as core/motion/cycles.py spells out. Options 59
and 60 put the CL axes on the machine's; the interpreter reports radii on a diameter lathe,
so no doubling here.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field, replace
from math import hypot, sqrt

from gecent.core.cl.records import (
    Arelem,
    Circle,
    Fini,
    Motion,
    MotionSubtype,
    Record,
    Statement,
    Word,
)
from gecent.core.errors import Diagnostic, InputError, SourcePosition
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.shuffle import cell_map
from gecent.core.motion.cycles import (
    Cycle,
    cycle_cell,
    cycle_legs,
    in_machine_units,
    parse_cycle,
    spindle_axis,
)
from gecent.core.motion.linear import TWO_AXIS
from gecent.core.motion.tool_axis import three_axis_motion
from gecent.core.output.modern import CL_PLANES
from gecent.core.statements.feed import scan_fedrat
from gecent.core.units import UnitScale

Point = tuple[float, float, float]
# CL records that move the tool in ways neither the post nor verify follows yet: a file with
# one of them fails verification, since the tape cannot be shown to follow it
UNFOLLOWED_MOTION = frozenset({"NURBS", "KNOT", "CNTRL", "SPLINE", "BSPLINE"})
# rs274's ARC_FEED plane axes, (first, second) machine axis indices
PLANE_AXES = {"XY": (0, 1), "XZ": (2, 0), "YZ": (1, 2)}


@dataclass(frozen=True, slots=True)
class ArcSpec:
    centre: Point  # machine axes; the plane's normal axis holds nothing to compare
    radius: float
    plane: str  # rs274's name of the machine plane
    counterclockwise: bool  # in rs274's (first, second) axis order
    on_arc: tuple[Point, ...] = ()  # the record's other points, on the arc within ``slack``
    slack: float = 0.0  # INTOL/OUTTOL in force: how far APT lets those points stray
    chords: bool = False  # the machine posts it as straight moves ending on the arc
    sag: float = 0.0  # how far such a chord may fall inside the arc (option 262, or a step)
    full: bool = False  # it ends where it began: a whole circle (the post's rule)
    # a circle about an axis along none of the machine's: its unit axis (machine axes);
    # the post gives it as chords in its own plane (core/motion/arc_pieces.py)
    normal: Point | None = None
    rise: tuple[float, float] = (0.0, 0.0)  # its start's and end's offsets along ``normal``


@dataclass(frozen=True, slots=True)
class Target:
    """A point the tape must reach. ``kind``: "rapid", "feed", "cycle-entry" (a hole's R
    plane: any moves may lead there) or "cycle" (the control's own moves, on the hole's
    axis). ``feed``: the feed in force, (value, per revolution), or None before FEDRAT."""

    point: Point
    kind: str
    where: SourcePosition
    statement: str
    feed: tuple[float, bool] | None = None
    arc: ArcSpec | None = None
    machine: MachineState | None = None  # what the CL has loaded and switched on


@dataclass(frozen=True, slots=True)
class MachineState:
    """What the CL file has the machine do while it cuts toward a point; None: the CL has
    not said. ``tool``: the T code its LOADTL makes; ``spindle``: +1 CLW, -1 CCLW, 0 OFF;
    ``side``: CUTCOM "left", "right" or "" (off); ``h``, ``d``: a modern mill's offset
    numbers (option 263 = 1)."""

    tool: int | None = None
    spindle: int | None = None
    side: str | None = None
    h: int | None = None
    d: int | None = None


@dataclass
class ClPath:
    targets: list[Target] = field(default_factory=list)
    compared: tuple[int, ...] = (0, 1, 2)  # machine axes the CL path gives
    notes: list[Diagnostic] = field(default_factory=list)
    unfollowed: list[Statement] = field(default_factory=list)  # UNFOLLOWED_MOTION records


class _Reader:
    def __init__(self, machine: MachineDefinition) -> None:
        self.machine = machine
        self.units = UnitScale(machine)
        shuffle = cell_map(machine.number_option(59), "XYZ")
        two_axes = machine.number_option(22) in TWO_AXIS
        self.axes = [
            None if target is None or (two_axes and axis == 2) else (target[0] - 3, target[1])
            for axis, target in enumerate(shuffle)
        ]
        self.path = ClPath(compared=tuple(sorted(m for m, _ in filter(None, self.axes))))
        self.at: Point = (0.0, 0.0, 0.0)  # CL units, with TRANS
        self.translation: Point = (0.0, 0.0, 0.0)
        self.rapid_once = False
        self.rapid_modal = False
        self.modal_rapid_mode = machine.number_option(109) == -1
        self.feed: tuple[float, bool] | None = None
        self.per_revolution = False
        self.circle: Circle | None = None
        self.arc: tuple[Circle, Motion, list[Point]] | None = None
        self.cycle: Cycle | None = None
        # a control's own peck cycle (G83, option 251 = 1) pecks from the R plane: its peck
        # depths are the control's, the CL's peck size is kept (docs/decisions.md)
        self.control_pecks = machine.number_option(251) == 1 and machine.g_code(84) is not None
        self.cycle_first_z: float | None = None
        self.circles = machine.number_option(9) == 1
        self.offsets = int(machine.number_option(263))
        self.state = MachineState()
        # options 261/262: which arcs the post gives as straight moves along them
        self.chords = machine.number_option(262) > 0
        self.chord_sag = machine.number_option(262) if self.chords else machine.number_option(14)
        self.helical = machine.number_option(253) == 1 and machine.number_option(261) == 1
        self.tolerances = [0.0, 0.0]  # INTOL, OUTTOL (CL units scaled to the machine's)

    def machine_point(self, point: Iterable[float]) -> Point:
        out = [0.0, 0.0, 0.0]
        for value, target in zip(point, self.axes, strict=False):
            if target is not None:
                out[target[0]] = target[1] * value
        return (out[0], out[1], out[2])

    def read(self, records: Iterable[Record]) -> ClPath:
        for record in records:
            record = self.units.record(record)
            if self.arc is not None:
                if isinstance(record, Motion) and record.subtype is MotionSubtype.CONTINUATION:
                    self.arc[2].extend(self._points(record))
                    continue
                self._finish_arc()
            if isinstance(record, Motion):
                self._motion(record)
            elif isinstance(record, Circle):
                self.circle = record if self.circles and len(record.values) >= 6 else None
            elif isinstance(record, Statement):
                self._statement(record)
            elif isinstance(record, Arelem) and record.subtype in (4, 5) and record.values:
                self.tolerances[record.subtype - 4] = abs(record.values[0])
            elif isinstance(record, Fini):
                break
        if self.arc is not None:
            self._finish_arc()
        return self.path

    def _points(self, record: Motion) -> list[Point]:
        tx, ty, tz = self.translation
        if record.subtype is MotionSubtype.GODLTA:
            values = record.points[0]
            delta = (0.0, 0.0, values[0]) if len(values) == 1 else values[:3]
            x, y, z = self.at
            return [(x + delta[0], y + delta[1], z + delta[2])]
        if len(record.points[0]) == 6:  # the spindle axis on a three-axis machine
            record = three_axis_motion(record, self.machine)
        return [(p[0] + tx, p[1] + ty, p[2] + tz) for p in record.points]

    def _statement(self, statement: Statement) -> None:
        major = statement.major
        if major in UNFOLLOWED_MOTION:
            self.path.unfollowed.append(statement)
        elif major in ("LOADTL", "TOOLNO", "TURRET"):
            self._load(statement)
        elif major == "SPINDL":
            words = statement.words()
            direction = 1 if "CLW" in words else -1 if "CCLW" in words else None
            if "OFF" in words:
                direction = 0
            if direction is not None:
                self.state = replace(self.state, spindle=direction)
        elif major == "CUTCOM":
            words = statement.words()
            given = statement.numbers()
            side = "left" if "LEFT" in words else "right" if "RIGHT" in words else ""
            if "OFF" in words or side:
                d = int(given[0]) if given and side else self.state.h if side else None
                self.state = replace(self.state, side=side, d=d if self.offsets == 1 else None)
        elif major == "UNITS":
            self.units.set_units(statement)
        elif major == "RAPID":
            self.rapid_once = True
            self.rapid_modal = self.modal_rapid_mode
        elif major == "FEDRAT":
            self.rapid_modal = False
            request = scan_fedrat(statement)
            if request.value is not None:
                self._program_feed(request.value, request.unit)
        elif major == "TRANS":
            numbers = [self.units.length(v) for v in statement.numbers()]
            x, y, z = (*numbers, 0.0, 0.0, 0.0)[:3]
            self.translation = (x, y, z)
        elif major == "CYCLE":
            lathe = self.machine.number_option(132) == 0 and self.machine.number_option(1) == 0
            parsed = parse_cycle(statement, lambda note: None, needs_depth=not lathe)
            self.cycle = None if parsed is None else in_machine_units(parsed, self.units.length)
            if self.cycle is not None and lathe and self.machine.g_code(cycle_cell(self.cycle)):
                self.cycle = None  # CYCLEL: the lathe's control runs the points as moves
            axis = spindle_axis(self.machine)
            if self.cycle is not None and axis is not None:
                self.cycle = replace(self.cycle, axis=axis)  # drilled as the post drills
            self.cycle_first_z = None
            if parsed is not None and parsed.feed is not None:
                self._program_feed(*parsed.feed)

    def _load(self, statement: Statement) -> None:
        """The T code and offset number a tool change makes (docs/modern-controls.md, option
        263); None where this reading does not follow the machine's T layout."""
        args = statement.args
        plain: list[int] = []
        valued: dict[str, int] = {}
        index = 0
        while index < len(args):
            arg = args[index]
            if isinstance(arg, Word):
                if arg.name in ("OFSETL", "ADJUST", "LENGTH") and index + 1 < len(args):
                    following = args[index + 1]
                    if not isinstance(following, Word):
                        valued[arg.name] = int(float(following))
                    index += 1
            else:
                plain.append(int(arg))
            index += 1
        if not plain:
            return
        tool = plain[0]
        offset = valued.get("ADJUST", valued.get("OFSETL", tool))
        code: int | None
        if statement.major == "TURRET":
            station = plain[1] if len(plain) > 1 else tool
            code = station * 100 + valued.get("OFSETL", tool) if self.offsets == 2 else None
        elif self.offsets == 2:
            code = tool if tool > 99 else tool * 100 + offset
        elif self.offsets == 1 or "OFSETL" not in valued:
            code = tool
        else:
            code = tool * 100 + valued["OFSETL"]
        self.state = replace(
            self.state, tool=code, h=offset if self.offsets == 1 else None, side=""
        )

    def _program_feed(self, value: float, unit: Word | None) -> None:
        """A feed in machine units, per revolution as its unit word says, or without one in
        the last mode (as FEDRAT and a cycle's feed program it in the post)."""
        if unit is not None:
            self.per_revolution = unit.name in ("IPR", "MMPR")
        elif self.feed is None:  # the first feed without one: option 35's assumed mode
            self.per_revolution = self.machine.number_option(35) == 1
        self.feed = (self.units.per_minute(value, unit), self.per_revolution)

    def _kind(self) -> str:
        rapid = self.rapid_once or self.rapid_modal
        self.rapid_once = False
        return "rapid" if rapid else "feed"

    def _motion(self, record: Motion) -> None:
        if record.subtype is MotionSubtype.FROM:
            self.at = self._points(record)[0]
            self.circle = None
            return
        points = self._points(record)
        if self.cycle is not None:
            self._holes(record, points)
            return
        circle, self.circle = self.circle, None
        if circle is not None and record.subtype is MotionSubtype.GOTO:
            self.arc = (circle, record, list(points))
            self.rapid_once = False
            return
        kind = self._kind()
        for point in points:
            self._target(point, kind, record, None)

    def _target(self, point: Point, kind: str, record: Motion, arc: ArcSpec | None) -> None:
        name = record.subtype.name
        text = f"{name}/" + ",".join(f"{v:.4f}" for v in point)
        self.path.targets.append(
            Target(self.machine_point(point), kind, record.where, text, self.feed, arc, self.state)
        )
        self.at = point

    def _holes(self, record: Motion, points: list[Point]) -> None:
        assert self.cycle is not None
        self.rapid_once = False
        for hole in points:
            if self.cycle_first_z is None:
                self.cycle_first_z = self.at[self.cycle.axis]
            legs = cycle_legs(self.cycle, self.at, hole, self.cycle_first_z, self.control_pecks)
            if legs and legs[0].point[2] == self.at[2] and legs[0].point[:2] != self.at[:2]:
                legs = legs[1:]  # positioning at the present height: the control's own way
            for index, leg in enumerate(legs):
                kind = "cycle-entry" if index == 0 else "cycle"
                self._target(leg.point, kind, record, None)

    def _finish_arc(self) -> None:
        assert self.arc is not None
        circle, record, points = self.arc
        self.arc = None
        xc, yc, zc, i, j, k = circle.values[:6]
        tx, ty, tz = self.translation
        centre = (xc + tx, yc + ty, zc + tz)
        epsilon = self.machine.number_option(5)
        if sum(abs(c) > epsilon for c in (i, j, k)) > 1:
            self._tilted_arc(centre, (i, j, k), record, points)
            return
        plane = 2 if abs(i) > epsilon else 1 if abs(j) > epsilon else 0
        u, v, _ = CL_PLANES[plane]
        start = self.at
        sense = (k, j, i)[plane]
        a = (start[u] - centre[u], start[v] - centre[v])
        ccw: bool | None = None
        for point in points if len(points) > 1 else ():
            b = (point[u] - centre[u], point[v] - centre[v])
            cross = a[0] * b[1] - a[1] * b[0]
            if abs(cross) > 1e-12:
                ccw = cross > 0
                break
        if ccw is None:
            ccw = sense > 0
        # the tool path's radius: APT's circle record is the drive surface, which the tool
        # may be offset from (TLRGT), so the points, not r, give it
        end = points[-1]
        radius = hypot(end[u] - centre[u], end[v] - centre[v])
        normal = 3 - u - v
        helix = len(points) == 1 and abs(start[normal] - end[normal]) > epsilon
        chords = self.chords or (helix and not self.helical)
        spec = self._arc_spec(centre, radius, u, v, ccw, points[:-1], chords)
        if spec is not None:  # within 0.01 step of its start: a full circle (core/motion/circle.py)
            closed = hypot(end[u] - start[u], end[v] - start[v])
            spec = replace(spec, full=closed <= 0.01 * self.machine.number_option(14))
        kind = self._kind()
        if spec is None:  # the plane is not one the machine has: the post goes linear
            for point in points:
                self._target(point, kind, record, None)
            return
        self._target(points[-1], "feed", record, spec)

    def _tilted_arc(self, centre: Point, axis: Point, record: Motion, points: list[Point]) -> None:
        """A circle about a tilted axis, as the post gives it: one CL point (CAM) is chords
        counterclockwise about the axis, each ending on the circle within the chord
        tolerance; APT's several points are straight cuts through them."""
        kind = self._kind()
        if len(points) > 1 or kind == "rapid":
            for point in points:
                self._target(point, kind, record, None)
            return
        length = sqrt(sum(c * c for c in axis))
        n = [c / length for c in axis]
        offset = [a - b for a, b in zip(points[-1], centre, strict=True)]
        along = sum(a * b for a, b in zip(offset, n, strict=True))
        radius = sqrt(max(0.0, sum(c * c for c in offset) - along * along))
        rise = sum((a - b) * c for a, b, c in zip(self.at, centre, n, strict=True)), along
        origin = self.machine_point((0.0, 0.0, 0.0))
        normal = [a - b for a, b in zip(self.machine_point(n), origin, strict=True)]
        size = sqrt(sum(c * c for c in normal)) or 1.0
        columns = [self.machine_point(e) for e in ((1, 0, 0), (0, 1, 0), (0, 0, 1))]
        a, b, c = columns  # a mirrored axis map turns the sense about the axis
        det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
        det += a[2] * (b[0] * c[1] - b[1] * c[0])
        spec = ArcSpec(
            self.machine_point(centre),
            radius,
            "XY",
            det >= 0,
            chords=True,
            sag=self.chord_sag,
            normal=(normal[0] / size, normal[1] / size, normal[2] / size),
            rise=rise,
        )
        self._target(points[-1], kind, record, spec)

    def _arc_spec(
        self,
        centre: Point,
        radius: float,
        u: int,
        v: int,
        ccw: bool,
        on_arc: list[Point],
        chords: bool,
    ) -> ArcSpec | None:
        mu, mv = self.axes[u], self.axes[v]
        if mu is None or mv is None:
            return None
        found = next(
            (
                (name, (mu[0], mv[0]) == axes)
                for name, axes in PLANE_AXES.items()
                if {mu[0], mv[0]} == set(axes)
            ),
            None,
        )
        if found is None:  # pragma: no cover - two distinct machine axes make a plane
            return None
        plane, in_order = found
        same = (mu[1] * mv[1] > 0) == in_order
        return ArcSpec(
            self.machine_point(centre),
            radius,
            plane,
            ccw if same else not ccw,
            tuple(self.machine_point(p) for p in on_arc),
            max(self.tolerances),
            chords,
            self.chord_sag,
        )


def cl_path(records: Iterable[Record], machine: MachineDefinition) -> ClPath:
    """The path of a CL file on a machine; InputError for what cannot be read."""
    try:
        return _Reader(machine).read(records)
    except (ValueError, IndexError) as exc:
        raise InputError(f"the CL file cannot be followed: {exc}", None) from None


def radius_of(point: Point, centre: Point, plane: str) -> float:
    first, second = PLANE_AXES[plane]
    return hypot(point[first] - centre[first], point[second] - centre[second])
