"""Multiaxis linear motion (manual §3.4.7, 001 L6284-6445; spec 03 §12, spec 05 §3.1.4):
a CL point with its tool axis (x, y, z, i, j, k) goes through the machine's transform class
(option 116, GEOM5 -> CLASSn, plugins/classes) to the machine's linear and rotary axes.

* FROM5: a FROM's tool axis whose length is not 1 is fatal error 19; a later point's is
  warned about and taken as its unit vector;
* the linear axes are rounded to whole steps; each rotary axis turns from its last angle
  to the class's new one the shorter way round (the manual's W5 turns B from 0 to -25 by
  -25, 001 L4243-4255), its departure rounded to option 119's step in the output units of
  option 118; the positions the listing prints are kept in [0, 360) (ROTMOV, -400 becomes
  320); the departures go in DBFSEG(6), (7) and (18), the class's rotary axes in order
  (head, table, third; 001 L6330-6345), a positive one turning the class's angle up;
* a move beyond DEPMAX (option 4) or ROTMAX (option 111) is cut into equal segments;
* the block is CODE 0 (a multiaxis move is a linear move, 001 L6400-6420), its feed command
  worked from the path's length in part coordinates (E2, 001 L10985-11038), or for a turn
  of the tool alone from the rotary travel at option 112's radius;
* with LINTOL, each move is first tested for linearity and cut where the tool tip would
  leave the tolerance (LINRTY, core/motion/linearity.py).

A point with three values keeps the tool axis in force (the last one given; +Z at first).
"""

from __future__ import annotations

from collections.abc import Callable
from math import acos, ceil, degrees, isfinite, radians, sqrt

import numpy as np
from gecent.core.cl.records import Motion, MotionSubtype
from gecent.core.errors import Diagnostic, FatalError, InputError, SourcePosition
from gecent.core.feed.limits import HEAD_CLASSES
from gecent.core.machine.definition import ROTARY_CELLS
from gecent.core.motion.gcode import RotaryCodes
from gecent.core.motion.guard import check_segments
from gecent.core.motion.linear import godlta_delta
from gecent.core.motion.linearity import LinearityLimit, LinearityTest
from gecent.core.motion.rotary import (
    SECOND_HEAD_CLASSES,
    UNITS_PER_DEGREE,
    travel_limit_warning,
)
from gecent.core.motion.rounding import to_steps
from gecent.core.motion.segments import segment_count, segment_place, segments
from gecent.core.multiaxis.chain import KinematicChain, Unreachable
from gecent.core.multiaxis.transform import Kinematics, TransformClass
from gecent.core.output.block import Block, Code
from gecent.core.state import PostState

UNIT_TOLERANCE = 1e-4  # FROM5: a tool axis this close to length 1 is a unit vector
NOT_UNIT = "TOOL AXIS DIRECTION COSINES ARE NOT A UNIT VECTOR; THEY ARE NORMALIZED"

PartPoint = tuple[float, float, float, float, float, float]

# R, the rotary head's axis to the spindle face, by (head, large gripper) (001 L25639-25665)
GRIPPER_OPTIONS = {(1, False): 104, (1, True): 105, (2, False): 102, (2, True): 103}


def gripper_key(state: PostState) -> tuple[int, bool, float | None]:
    """What R + TL depends on: the head (TLHEAD), the gripper (GRPLOD), the length."""
    return (2 if state.head == 2 else 1, state.tool.large_gripper, state.tool.length)


def gripper_reach(state: PostState) -> float:
    """R + TL (001 L12735-12741): R of the head and gripper, plus the tool's length."""
    head, large, length = gripper_key(state)
    return state.machine.number_option(GRIPPER_OPTIONS[head, large]) + (length or 0.0)


class MultiaxisMotion:
    """GOLINE on a multiaxis machine: GEOM5, DEPART with ROTMOV, SEGMNT."""

    def __init__(
        self,
        state: PostState,
        emit: Callable[[Block], None],
        transform: TransformClass,
        warn: Callable[[Diagnostic], None],
    ) -> None:
        machine = state.machine
        self.state = state
        self.emit = emit
        self.transform = transform
        self.warn = warn
        self.step = machine.number_option(14)
        self.depmax = round(machine.number_option(4) / self.step)
        # R + TL: R by the head and the gripper LOAD chose (head 1's small one, option 104,
        # before any LOAD), TL the tool's length (LOAD or LOADTL LENGTH; 0 when not given)
        options = tuple(machine.number_option(n) for n in range(100, 106))
        self._constants_for = gripper_key(state)
        self.kinematics = Kinematics(
            reach=gripper_reach(state),
            options=(options[0], options[1], options[2], options[3], options[4], options[5]),
        )
        self.per_degree = UNITS_PER_DEGREE.get(machine.number_option(118), 1.0)
        self.rotary_step = machine.number_option(119) or 0.0001
        # ROTMAX in rotary steps: option 111 is in degrees
        maximum = machine.number_option(111) * self.per_degree
        if not isinstance(transform, KinematicChain):
            # SELGRO's codes bound a block's turn (a five-axis pack's G01 takes any)
            maximum = RotaryCodes(machine, maximum).block_limit(maximum)
        self.rotmax = max(1, int(maximum / self.rotary_step))
        self.columns = transform.rotary  # the machine columns A, B, C it drives
        self.cells = ROTARY_CELLS[: len(self.columns)]
        for cell in self.cells:
            if machine.registers.formats[cell] is None:
                raise InputError(
                    f"option 116 = {transform.number} ({transform.name}) drives "
                    f"{len(self.columns)} rotary axes, but register {cell} has no format",
                    SourcePosition(machine.origin),
                )
        # a five-axis machine by data (core/multiaxis/chain.py, docs/five-axis.md): the reach
        # is the tool's length where the head swings it (LOADTL LENGTH), else none (the
        # control's length offset makes the tip the controlled point)
        self.chain = transform if isinstance(transform, KinematicChain) else None
        if self.chain is not None:
            self.kinematics = Kinematics(reach=0.0, options=self.kinematics.options)
        self.linearity = LinearityTest(transform, self.kinematics)
        self.limited = frozenset(
            axis.column for axis in (self.chain.axes if self.chain else ()) if axis.limits
        )
        self.modern_absolute = machine.number_option(251) == 1
        # options 149, 150: the head's rotation limits, on a class whose DBFSEG(6) is a head
        self.head_limited = (
            self.chain is None
            and transform.number in HEAD_CLASSES
            and (machine.number_option(149) != 0 or machine.number_option(150) != 0)
        )
        # options 199, 200: the second rotary head's limits, on a class whose head turns
        # about two axes, the second in DBFSEG(7) (CLASS 3's A and B, CLASS 6's A on B)
        self.second_head_limited = (
            self.chain is None
            and transform.number in SECOND_HEAD_CLASSES
            and (machine.number_option(199) != 0 or machine.number_option(200) != 0)
        )
        self.where: SourcePosition | None = None
        self.tool_axis: tuple[float, float, float] = (0.0, 0.0, 1.0)
        # the last machine point (radians); none before the first (a five-axis machine's
        # preferred way)
        self.machine_previous: np.ndarray | None = None
        # each rotary axis's angle so far, unwrapped (degrees), and in rotary steps
        self.angles = [0.0] * len(self.columns)
        self.rotary_previous = [0] * len(self.columns)
        self.machine_raw = np.zeros(6)
        self.singular = False  # the last point was singular (no linearity test from it)

    # -- records -----------------------------------------------------------------------

    def record(self, record: Motion) -> None:
        self.where = record.where
        if record.subtype is MotionSubtype.FROM:
            self._from(record)
        elif record.subtype is MotionSubtype.GODLTA:
            delta = godlta_delta(record.points[0])
            previous = self.state.position.previous_part
            translation = self.state.position.translation
            point = tuple(previous[a] + delta[a] - translation[a] for a in range(3))
            self._goto(record, point)
        else:
            for point in record.points:
                self._goto(record, point)

    def _part(self, record: Motion, point: tuple[float, ...]) -> PartPoint:
        """The point with TRANS and its tool axis (FROM5's unit check)."""
        if len(point) >= 6:
            i, j, k = point[3:6]
            length = sqrt(i * i + j * j + k * k)
            if length == 0.0:
                raise InputError("the tool axis i, j, k is 0, 0, 0", record.where)
            if not isfinite(length):
                raise InputError(
                    f"the tool axis {i:g}, {j:g}, {k:g} is too large to normalise", record.where
                )
            if abs(length - 1.0) > UNIT_TOLERANCE:
                if record.subtype is MotionSubtype.FROM:  # FROM5's error 19 (001 L31455)
                    raise FatalError(19, f"|i, j, k| = {length:.6g}", record.where)
                self.warn(Diagnostic(NOT_UNIT, record.where))
            self.tool_axis = (i / length, j / length, k / length)
        tx, ty, tz = self.state.position.translation
        i, j, k = self.tool_axis
        return (point[0] + tx, point[1] + ty, point[2] + tz, i, j, k)

    def _machine(self, part: PartPoint) -> tuple[list[int], list[int], bool]:
        """GEOM5: the machine point in steps (linear) and the rotary axes' unwrapped
        positions in rotary steps, and whether the point is singular."""
        if self.chain is not None and self.chain.needs_tool_length:
            self._tool_length()
        elif self.chain is None and gripper_key(self.state) != self._constants_for:
            self.load_constants()
        try:
            result = self.transform.direct(
                np.array([part]), self.kinematics, previous=self.machine_previous
            )
        except Unreachable as exc:
            raise InputError(str(exc), self.where) from None
        axes = result.axes[0]
        self.machine_previous = result.axes
        linear = [to_steps(float(axes[a]), self.step) for a in range(3)]
        rotary = []
        raw = axes.copy()
        for index, column in enumerate(self.columns):
            degrees = float(np.degrees(axes[column]))
            if column in self.limited:  # within the axis's travel, as the chain chose
                self.angles[index] = degrees
            else:
                turn = (degrees - self.angles[index] + 180.0) % 360.0 - 180.0  # the shorter way
                self.angles[index] += turn
            raw[column] = np.radians(self.angles[index])
            rotary.append(round(self.angles[index] * self.per_degree / self.rotary_step))
        if self.chain is not None and not self.chain.tool_centre_point:
            # the slides for the angles as punched: the tip lands on the CL point to the
            # slides' own step, not off it by the angles' rounding times the tip's radius
            punched = [radians(steps * self.rotary_step / self.per_degree) for steps in rotary]
            slides = self.chain.slides(part[:3], (punched[0], punched[1]), self.kinematics.reach)
            linear = [to_steps(v, self.step) for v in slides]
        self.machine_raw = raw  # (unrounded, the angles unwrapped: LINRTY's machine point)
        singular = bool(result.singular[0]) if result.singular.size else False
        return linear, rotary, singular

    def _from(self, record: Motion) -> None:
        position = self.state.position
        part = self._part(record, record.points[0])
        linear, rotary, self.singular = self._machine(part)
        position.present_part[:] = list(part)
        position.present[:3] = linear
        block = Block(Code.FROM, record.number)
        for axis in range(3):
            block.cells[3 + axis] = linear[axis] * self.step
        for cell, steps in zip(self.cells, rotary, strict=True):
            # the rotary positions, in the output units (the listing's FROM line)
            whole = 360.0 * self.per_degree
            block.cells[cell] = (steps * self.rotary_step) % whole
        block.position = tuple(linear)
        position.previous_part[:] = position.present_part
        position.previous[:] = position.present
        position.from_given = True
        self.rotary_previous = rotary
        self.emit(block)

    def goline(self, record: Motion, point: tuple[float, ...], *, tested: bool = False) -> None:
        """GOLINE for a point another element makes (ROTREF's move, a multiaxis circle's
        chords, core/motion/multiaxis_rotate.py, multiaxis_circle.py): ``point`` as a CL
        point (before TRANS); ``tested``: linearity-tested under LINTOL/OFF too."""
        self._goto(record, point, tested)

    def _goto(self, record: Motion, point: tuple[float, ...], tested: bool = False) -> None:
        if self.chain is None:
            self._goto_moves(record, point, tested)
            return
        axis = tuple(self.state.position.previous_part[3:6])
        before = list(self.rotary_previous)
        self._goto_moves(record, point, tested)
        self._pole(record, axis, before)

    def _goto_moves(self, record: Motion, point: tuple[float, ...], tested: bool) -> None:
        part = self._part(record, point)
        if self.singular and self.chain is not None and not self.chain.tool_centre_point:
            self._turn_at_pole(record, part)
        rule = self.state.linearity
        if (
            rule.radius > 0.0
            and not self.state.feed.rapid_ipm
            and (rule.one_point_records or len(record.points) > 1 or tested)
            and not self.singular
            and (self.chain is not None or not self._singular(part))
        ):
            # LINRTY: not for rapid moves, nor one-point records under LINTOL/OFF, nor a
            # move into or out of a singular point ("linearity testing is disregarded over
            # this move", 001 L12845-12870; the angle kept there is no path to test)
            start = self.state.position.previous_part
            begin: PartPoint = (start[0], start[1], start[2], start[3], start[4], start[5])
            try:
                points, met = self.linearity.points(
                    begin, self.machine_raw, part, rule, self.state.max_segments
                )
            except LinearityLimit as limit:
                check_segments(limit.count, self.state.max_segments, record.where, "move")
                raise
            if not met:
                self.warn(
                    Diagnostic(
                        "LINEARITY TOLERANCE CANNOT BE MET ON THIS MOVE: ITS REST IS NOT "
                        "TESTED (THE TOOL AXIS PASSES WHERE THE MACHINE CANNOT FOLLOW IT)",
                        record.where,
                    )
                )
            for inserted in points:
                self._move(record, inserted)
            return
        self._move(record, part)

    def _singular(self, part: PartPoint) -> bool:
        """The class leaves an angle of this point undetermined (its tool axis along the
        axis that angle turns about)."""
        try:
            result = self.transform.direct(np.array([part]), self.kinematics, self.machine_previous)
        except Unreachable as exc:
            raise InputError(str(exc), self.where) from None
        return bool(result.singular.any()) if result.singular.size else False

    def _tool_length(self) -> None:
        """Slides computed for a head that swings the tool: the tool's length (LOADTL
        LENGTH) is part of the reach from the head's pivot to the tip."""
        length = self.state.tool.length
        if length is None:
            raise InputError(
                "this five-axis machine's slides are computed for the tool the head swings "
                "(option 265 = 0): give the tool's length, LOADTL/n,LENGTH,l",
                self.where,
            )
        if length != self.kinematics.reach:
            self.kinematics = Kinematics(reach=length, options=self.kinematics.options)
            self.linearity = LinearityTest(self.transform, self.kinematics)

    def load_constants(self) -> None:
        """CLASS with MAFORK = 0 (LOAD, 001 L33878-33925; CLASS1 L12749-12870): the loaded
        tool's R + TL, for the manual's classes (a five-axis chain takes its reach in
        ``_tool_length``)."""
        self._constants_for = gripper_key(self.state)
        reach = gripper_reach(self.state)
        if self.chain is None and reach != self.kinematics.reach:
            self.kinematics = Kinematics(reach=reach, options=self.kinematics.options)
            self.linearity = LinearityTest(self.transform, self.kinematics)

    def _move(self, record: Motion, part: PartPoint) -> None:
        linear, rotary, singular = self._machine(part)
        self.singular = singular
        self._reach(record, part, linear, rotary)

    def _turn_at_pole(self, record: Motion, part: PartPoint) -> None:
        """Leaving the pole, where the tool lies along an axis whose angle it left open:
        that axis turns to its new angle first, the tool tip held where it is (the slides
        follow the part round), so the move after it does not sweep the part under the
        tool."""
        assert self.chain is not None
        index = self.chain.axes.index(self.chain.pole)
        column = self.columns[index]
        try:
            result = self.transform.direct(np.array([part]), self.kinematics, self.machine_previous)
        except Unreachable as exc:
            raise InputError(str(exc), self.where) from None
        if bool(result.singular[0]):
            return  # (from the pole to the pole: nothing to turn)
        wanted = float(np.degrees(result.axes[0, column]))
        if column not in self.limited:
            wanted = self.angles[index] + (wanted - self.angles[index] + 180.0) % 360.0 - 180.0
        target = round(wanted * self.per_degree / self.rotary_step)
        if target == self.rotary_previous[index]:
            self.singular = False  # the angle kept is the move's own: testable
            return
        rotary = list(self.rotary_previous)
        rotary[index] = target
        at = self.state.position.previous_part
        start: PartPoint = (at[0], at[1], at[2], at[3], at[4], at[5])
        begin, total = self.rotary_previous[index], rotary[index] - self.rotary_previous[index]
        pieces = 1
        rule = self.state.linearity
        if rule.radius > 0.0 and not self.state.feed.rapid_ipm:
            # LINTOL: the slides follow the tip's circle about the axis in chords within r
            angles = self._radians(self.rotary_previous)
            radius = self.chain.radius_about(self.chain.pole, start[:3], angles)
            if radius > rule.radius:
                per_piece = 2.0 * acos(1.0 - rule.radius / radius)
                turn = abs(total) * self.rotary_step / self.per_degree
                pieces = max(1, ceil(radians(turn) / per_piece))
                check_segments(pieces, self.state.max_segments, record.where, "move")
        slides: tuple[float, float, float] = (0.0, 0.0, 0.0)
        for piece in range(1, pieces + 1):
            turned = list(self.rotary_previous)
            turned[index] = begin + round(total * piece / pieces)
            slides = self.chain.slides(start[:3], self._radians(turned), self.kinematics.reach)
            self._reach(record, start, [to_steps(v, self.step) for v in slides], turned)
        # the machine stands at the turned angle now: no longer at an open one
        degrees_now = target * self.rotary_step / self.per_degree
        self.angles[index] = degrees_now
        assert self.machine_previous is not None
        for row in (self.machine_previous[0], self.machine_raw):
            row[column] = radians(degrees_now)
            row[0:3] = slides
        self.singular = False

    def _radians(self, rotary: list[int]) -> tuple[float, float]:
        """The chain's two angles (radians) of rotary positions in rotary steps."""
        first, second = (radians(s * self.rotary_step / self.per_degree) for s in rotary)
        return (first, second)

    def _reach(self, record: Motion, part: PartPoint, linear: list[int], rotary: list[int]) -> None:
        """The blocks from the last machine point to this one (segmented by DEPMAX and
        ROTMAX)."""
        position = self.state.position
        departures = [linear[a] - position.previous[a] for a in range(3)]
        turns = [r - p for r, p in zip(rotary, self.rotary_previous, strict=True)]
        if not any(departures) and not any(turns) and not self._unstated():
            return  # no move (001 L4283-4290)
        if self.head_limited and turns[0]:
            scale = self.rotary_step / self.per_degree  # rotary steps to degrees
            text = travel_limit_warning(
                self.state.machine,
                self.rotary_previous[0] * scale,
                turns[0] * scale,
                device="HEAD",
            )
            if text:
                self.warn(Diagnostic(text, record.where))
        if self.second_head_limited and turns[1]:
            scale = self.rotary_step / self.per_degree
            text = travel_limit_warning(
                self.state.machine,
                self.rotary_previous[1] * scale,
                turns[1] * scale,
                device="SECOND HEAD",
            )
            if text:
                self.warn(Diagnostic(text, record.where))
        count = segment_count(departures + turns, [self.depmax] * 3 + [self.rotmax] * len(turns))
        if count > 1:
            check_segments(count, self.state.max_segments, record.where, "move")
        previous_part = position.previous_part
        path = sqrt(sum((part[a] - previous_part[a]) ** 2 for a in range(3)))
        reached = list(position.previous[:3])
        pieces = segments(departures + turns, count) if count > 1 else (tuple(departures + turns),)
        angles = list(self.rotary_previous)
        if path < self.step:
            path = 0.0  # (a tip that moves less than a step: a turn of the tool alone)
        # G93 on a modern control: a move the slides make while the tool turns (the control
        # would take F over the slides' and angles' travel), or a turn alone
        timed = (
            self.chain is not None
            and any(turns)
            and (not self.chain.tool_centre_point or path == 0.0)
        )
        for index, piece in enumerate(pieces):
            linear_piece = piece[:3]
            for axis, steps in enumerate(linear_piece):
                reached[axis] += steps
            block = Block.motion(
                Code.LINEAR, record.number, tuple(linear_piece), tuple(reached), self.step
            )
            for cell, steps in zip(self.cells, piece[3:], strict=True):
                block.cells[cell] = steps * self.rotary_step
            if self.modern_absolute:
                angles = [a + t for a, t in zip(angles, piece[3:], strict=True)]
                block.angles = tuple(angles)
            block.inverse_time = timed
            # the tip's path in the part (E2), or for a turn alone the rotary arc
            block.feed_length = (
                path / count
                if path > 0.0
                else self._turn_length(list(piece[3:]), list(linear_piece))
            )
            block.segment = segment_place(index, count)
            self.emit(block)
        position.present_part[:] = list(part)
        position.present[:3] = linear
        position.previous_part[:] = position.present_part
        position.previous[:] = position.present
        self.rotary_previous = rotary

    def _unstated(self) -> bool:
        """The first move after a tool change on a modern control (G43 H or the tool centre
        point still to go out): it states every axis even where the tool already is."""
        return self.state.tool.length_pending and self.modern_absolute

    def _turn_length(self, turns: list[int], slides: list[int]) -> float:
        """The path of a move that turns the tool without moving its tip in the part: the
        longer of the slides' travel and each rotary axis's arc at its radius (option 128,
        the head's tool swing, for the head; option 112, the part's, for a table), as
        FEDLIM counts a rotary axis (001 L12225-12300)."""
        machine = self.state.machine
        longest = sqrt(sum((s * self.step) ** 2 for s in slides))
        turned = [abs(t) * self.rotary_step / self.per_degree for t in turns]
        if self.chain is not None:
            # the axes' arcs at their radii: the slides' travel is the machine's, not the
            # cut's (under the control's tool centre point the slides stand)
            radii = machine.number_option(112), machine.number_option(128)
            longest = self.chain.swing(turned, *radii)
        else:
            for cell, degrees in zip(self.cells, turned, strict=True):
                radius = machine.number_option(128 if cell == 6 else 112)
                longest = max(longest, radians(degrees) * radius)
        # options 112, 128 = 0: F is degrees per minute, as a G94 control reads it (issue 22 wave 9)
        return longest if longest > 0.0 else max(turned, default=0.0)

    def _pole(self, record: Motion, start: tuple[float, ...], before: list[int]) -> None:
        """A move whose tool axis passes near the pole (along the axis whose angle it then
        leaves open) swings that axis fast: the warning names how near and how far."""
        assert self.chain is not None
        pole = self.chain.pole
        direction = pole.direction
        part = self.state.position.previous_part
        nearest = 180.0
        for n in range(17):
            t = n / 16
            v = [start[a] + t * (part[3 + a] - start[a]) for a in range(3)]
            length = sqrt(sum(c * c for c in v)) or 1.0
            cosine = abs(sum(v[a] * direction[a] for a in range(3))) / length
            nearest = min(nearest, degrees(acos(min(1.0, cosine))))
        if nearest > self.chain.pole_zone:
            return
        index = self.chain.axes.index(pole)
        swing = (
            abs(self.rotary_previous[index] - before[index]) * self.rotary_step / self.per_degree
        )
        if swing >= 1.0:
            self.warn(
                Diagnostic(
                    f"TOOL AXIS WITHIN {nearest:.3f} DEGREES OF THE POLE OF {pole.letter}: "
                    f"{pole.letter} TURNS {swing:.3f} DEGREES ON THIS MOVE",
                    record.where,
                )
            )
