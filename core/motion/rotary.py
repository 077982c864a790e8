"""Rotary tables and heads: ROTATE/TABLE and ROTATE/HEAD (manual §3.4.5, 001 L5385-5835;
ROTABL L36012-36053, ROTABI L35939-36010, ROTOUT L36304-36343; options 29, 111, 117-120).

Angles are degrees; the table's position is kept in [0, 360). A move is a signed travel,
positive clockwise (CLW: a right-hand screw advancing along the negative axis, option
117's definition). Option 117 says whether CLW increases the scale reading; option 118
gives the output units (revolutions, degrees or hundredths of a revolution); option 119 the
step. On an incremental system (ROTABI) each block carries the departure, moves longer than
option 111 are split equally, and each departure is rounded with the difference carried,
so the table never drifts more than half a step (§3.4.5.3). An absolute system (ROTABA,
positioning machines, core/motion/rotary_absolute.py) outputs the target, in two moves
when the programmed direction is the long way round. Option 206 says which way a CLW turns
a table; options 220 and 221 are the table's travel limits, warned about when passed.

ROTATE/TABLE,OFF|CLW|CCLW,RPM,s,RANGE,n, a spinning table's speed (TABSPD), is in
core/motion/rotary_devices.py. ROTATE/TORCH, INCR|ATANGL, angle [, CLW|CCLW] turns a flame
cutter's torch (ROTORC, GEFLAM, 001 L36260-36302; option 132 = 4): its departure in the
rotary register (DBFSEG 6, or the one there is), CODE +2, in option 118's units rounded to
option 14's step with the difference carried (SRAREC), split equally when the register
cannot hold it, and a warning once the torch has turned more than 360 degrees from where
it started (its hoses wind up). docs/decisions.md (issue 22).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import Diagnostic, InputError, NotYetSupported
from gecent.core.machine.definition import ROTARY_CELLS, MachineDefinition
from gecent.core.motion.gcode import RotaryCodes
from gecent.core.motion.rotary_devices import (
    TableOutput,
    TableSpeed,
    is_table_speed,
    rotate_turret,
)
from gecent.core.motion.rounding import to_steps
from gecent.core.motion.segments import segment_place
from gecent.core.output.block import Block, Code
from gecent.core.state import PostState


class RotarySystem(Protocol):
    """A rotary element made elsewhere (ROTABA, core/motion/rotary_absolute.py)."""

    cut_minutes: float

    def statement(self, statement: Statement) -> None: ...


CLW, CCLW = 1, -1
ROTATION_LIMIT_OPTIONS = {"TABLE": (220, 221), "HEAD": (149, 150)}  # lower, upper (degrees)
# options 199, 200 (001 L26569-26579): the second rotary head's limits, degrees as 149/150
ROTATION_LIMIT_OPTIONS["SECOND HEAD"] = (199, 200)
# the multiaxis classes whose head turns about two axes, the second in DBFSEG(7)
SECOND_HEAD_CLASSES = frozenset({3, 6})
HEAD_CELL, TABLE_CELL = ROTARY_CELLS[:2]  # DBFSEG(6) head, DBFSEG(7) table (001 L5600-5606)
UNITS_PER_DEGREE = {0.0: 1 / 360, 1.0: 1.0, -1.0: 100 / 360}  # option 118


def normalise(angle: float) -> float:
    """An angle in [0, 360): -40 -> 320, -400 -> 320, 360 -> 0 (001 L5476-5477)."""
    value = angle % 360.0
    return 0.0 if value >= 360.0 else value


@dataclass(frozen=True, slots=True)
class RotaryMove:
    """The new position (degrees, scale reading) and the signed travel (degrees, + = CLW)."""

    position: float
    travel: float


def rotary_move(
    previous: float,
    value: float,
    *,
    absolute: bool,
    direction: int | None,
    clw_increases: bool = True,
) -> RotaryMove:
    """INCR alpha (no direction: CLW) or ATANGL beta (no direction: the shorter way)
    from ``previous`` (001 L5440-5480, L5620-5650)."""
    scale = 1 if clw_increases else -1
    if not absolute:
        travel = value if (direction or CLW) == CLW else -value
        return RotaryMove(normalise(previous + scale * travel), travel)
    target = normalise(value)
    clockwise = normalise(scale * (target - previous))  # the CLW travel, 0 <= t < 360
    if direction == CLW or clockwise == 0:
        travel = clockwise
    elif direction == CCLW:
        travel = clockwise - 360.0
    else:
        travel = clockwise if clockwise <= 180.0 else clockwise - 360.0
    return RotaryMove(target, travel)


FLAME_CUTTER = 4  # option 132: the overlay GEFLAM, where ROTORC is
TORCH_PAST_360 = "WARNING -- TORCH ROTATION HAS EXCEEDED 360 DEGREES -- WARNING."
TORCH_SEGMENTED = "TORCH ROTATION IS TOO LARGE TO BE PUT IN A BLOCK WITHOUT SEGMENTATION."
HALF_TURN_STEP = 179.0  # each forced move of a long way round (001 L5584-5592, W17)


def absolute_targets(previous: float, move: RotaryMove, clw_increases: bool = True) -> list[float]:
    """ROTABA: the positions an absolute table is sent to (001 L5570-5592)."""
    return long_way_targets(previous, move.travel, clw_increases)


def long_way_targets(previous: float, travel: float, clw_increases: bool = True) -> list[float]:
    """The positions an absolute table is sent to for a signed travel (+ = CLW, degrees).
    Such a table takes the shorter way, so the table goes in moves of 179 degrees along
    the programmed direction until what is left is below 180 (W17: 90 -> 180 CLW via 271;
    spec 03 open question 9: the one example's rule carried on, so a half turn is two
    moves and a whole turn three)."""
    scale = 1 if clw_increases else -1
    sign = 1.0 if travel >= 0 else -1.0
    targets: list[float] = []
    position, left = previous, abs(travel)
    while left >= 180.0:
        position = normalise(position + scale * sign * HALF_TURN_STEP)
        targets.append(position)
        left -= HALF_TURN_STEP
    targets.append(normalise(previous + scale * travel))
    return targets


def carried_departures(
    travel_units: float, maximum_units: float, step: float, carry: float
) -> tuple[list[int], float]:
    """ROTOUT: the travel (output units) split into equal parts no longer than the maximum,
    each rounded to whole steps (SROREC) with the rounding difference carried and added
    back once it reaches half a step (001 L5520-5546, L5717-5831). Returns the departures
    in steps and the carry left."""
    count = int(abs(travel_units) / maximum_units) + 1 if abs(travel_units) > maximum_units else 1
    part = travel_units / count
    out: list[int] = []
    for _ in range(count):
        rounded = to_steps(part, step)
        difference = part - rounded * step + carry
        correction = to_steps(difference, step)
        out.append(rounded + correction)
        carry = difference - correction * step
    return out, carry


class RotaryElement:
    """ROTATE/TABLE|HEAD on an incremental contouring machine (ROTABI without ROTREF)."""

    def __init__(
        self,
        state: PostState,
        emit: Callable[[Block], None],
        warn: Callable[[Diagnostic], None],
    ) -> None:
        machine = state.machine
        self.state = state
        self.emit = emit
        self.warn = warn
        scaling = machine.number_option(118)
        if scaling not in UNITS_PER_DEGREE:
            raise NotYetSupported(f"rotary scaling option 118 = {scaling:g}")
        self.per_degree = UNITS_PER_DEGREE[scaling]
        self.step = machine.number_option(119)
        maximum = machine.number_option(111) * self.per_degree
        self.maximum = RotaryCodes(machine, maximum).block_limit(maximum)
        self.clw_increases = machine.number_option(117) >= 0
        self.positive_is_clw = machine.number_option(120) != -1
        self.tracked = machine.number_option(29) != 0
        self.positions = {HEAD_CELL: 0.0, TABLE_CELL: 0.0}
        self.carries = {HEAD_CELL: 0.0, TABLE_CELL: 0.0}
        # ROTABA on a positioning machine (core/motion/rotary_absolute.py), made by the
        # ROTATE handler on first use: it shares the positions
        self.absolute_system: RotarySystem | None = None
        self.torch = TorchRotation()
        self.table_speed = TableSpeed()
        # TABSPD's dwells and M codes need the output element itself, of which the run
        # hands this element only its OUTPUT (core/dispatch/elements.py)
        owner = getattr(emit, "__self__", None)
        self.table_output = owner if isinstance(owner, TableOutput) else None

    def statement(self, statement: Statement) -> None:
        words = [a.name for a in statement.args if isinstance(a, Word)]
        if words[:1] == ["TORCH"]:
            self.torch.statement(statement, self.state.machine, self.emit, self.warn)
            return
        if is_table_speed(statement):
            if self.table_output is None:
                raise NotYetSupported("ROTATE/TABLE speed control without an output element")
            self.table_speed.statement(statement, self.state.machine, self.table_output, self.warn)
            return
        request = parse_rotate(statement, self.state.machine)
        cell, absolute, value, direction = (
            request.cell,
            request.absolute,
            request.value,
            request.direction,
        )
        machine = self.state.machine
        if machine.registers.formats[cell] is None:
            # head in 6, table in 7 is "merely a convention and not a set rule" (001
            # L1793-1796): a machine with one rotary register drives either device with it
            other = TABLE_CELL if cell == HEAD_CELL else HEAD_CELL
            if machine.registers.formats[other] is None:
                raise InputError(
                    f"ROTATE: machine {machine.label} has no rotary register (DBFSEG 6 or 7)",
                    statement.where,
                )
            cell = other
        if absolute and not self.tracked:
            self.warn(Diagnostic("ROTREF AND ATANGL CANNOT BE USED", statement.where))
        move = rotary_move(
            self.positions[cell],
            value,
            absolute=absolute,
            direction=direction,
            clw_increases=self.clw_increases,
        )
        if request.cell in (TABLE_CELL, HEAD_CELL):
            text = travel_limit_warning(
                machine,
                self.positions[cell],
                move.travel,
                self.clw_increases,
                "TABLE" if request.cell == TABLE_CELL else "HEAD",
            )
            if text:
                self.warn(Diagnostic(text, statement.where))
        self.positions[cell] = move.position
        sign = 1 if self.positive_is_clw else -1
        departures, self.carries[cell] = carried_departures(
            sign * move.travel * self.per_degree, self.maximum, self.step, self.carries[cell]
        )
        moves = [steps for steps in departures if steps != 0]
        # RAPID before ROTATE: every block of the turn at the table's rapid (option 115);
        # OUTPUT then drops the request (RAPFLG = 0, chart 8), so it is one shot
        rapid = self.state.feed.rapid_requested
        for index, steps in enumerate(moves):
            block = Block(Code.ROTARY_INCREMENTAL, statement.number)
            block.cells[cell] = steps * self.step
            block.rotary = (cell, abs(steps * self.step) / self.per_degree)
            block.segment = segment_place(index, len(moves))
            block.rapid = rapid
            self.emit(block)


class TorchRotation:
    """ROTORC: the torch's turns, counted from where it started (degrees, + = CLW), and the
    rounding difference carried from one block to the next."""

    def __init__(self) -> None:
        self.turned = 0.0
        self.carry = 0.0

    def statement(
        self,
        statement: Statement,
        machine: MachineDefinition,
        emit: Callable[[Block], None],
        warn: Callable[[Diagnostic], None],
    ) -> None:
        if machine.number_option(132) != FLAME_CUTTER:
            raise InputError(
                "ROTATE/TORCH is a flame-cutter statement (ROTORC, overlay GEFLAM: option "
                f"132 = 4); machine {machine.label} has option 132 = "
                f"{machine.number_option(132):g}",
                statement.where,
            )
        absolute, value, direction = _parse_torch(statement)
        cell = _rotary_register(machine, HEAD_CELL, statement)
        scaling = machine.number_option(118)
        if scaling not in UNITS_PER_DEGREE:
            raise NotYetSupported(f"rotary scaling option 118 = {scaling:g}", statement.where)
        move = rotary_move(normalise(self.turned), value, absolute=absolute, direction=direction)
        self.turned += move.travel
        if abs(self.turned) > 360.0 + 1e-9:
            warn(Diagnostic(TORCH_PAST_360, statement.where))
        step = machine.number_option(14)
        register = machine.registers.formats[cell]
        assert register is not None
        # the largest departure the register holds, less a step for the carried correction
        largest = register.largest - step
        departures, self.carry = carried_departures(
            move.travel * UNITS_PER_DEGREE[scaling], largest, step, self.carry
        )
        moves = [steps for steps in departures if steps != 0]
        if len(departures) > 1:
            warn(Diagnostic(TORCH_SEGMENTED, statement.where))
        for index, steps in enumerate(moves):
            block = Block(Code.ROTARY_ABSOLUTE, statement.number)  # CODE +2 (001 L36280)
            block.cells[cell] = steps * step
            block.segment = segment_place(index, len(moves))
            emit(block)


def _parse_torch(statement: Statement) -> tuple[bool, float, int | None]:
    """ROTATE/TORCH, INCR | ATANGL, angle [, CLW | CCLW]: ROTABL's form for the torch."""
    words = [a.name for a in statement.args if isinstance(a, Word)]
    numbers = statement.numbers()
    modes = [w for w in words if w in ("INCR", "ATANGL")]
    directions = [w for w in words if w in ("CLW", "CCLW")]
    if len(modes) != 1 or len(numbers) != 1 or len(modes) + len(directions) != len(words) - 1:
        raise InputError(
            "ROTATE/TORCH expects INCR or ATANGL, one angle and at most one of CLW, CCLW",
            statement.where,
        )
    if len(directions) > 1:
        raise InputError("ROTATE/TORCH takes at most one of CLW, CCLW", statement.where)
    direction = None if not directions else (CLW if directions[0] == "CLW" else CCLW)
    return modes[0] == "ATANGL", numbers[0], direction


def _rotary_register(machine: MachineDefinition, cell: int, statement: Statement) -> int:
    """The device's DBFSEG cell, or the machine's one rotary register (001 L1793-1796)."""
    if machine.registers.formats[cell] is not None:
        return cell
    other = TABLE_CELL if cell == HEAD_CELL else HEAD_CELL
    if machine.registers.formats[other] is None:
        raise InputError(
            f"ROTATE: machine {machine.label} has no rotary register (DBFSEG 6 or 7)",
            statement.where,
        )
    return other


@dataclass(frozen=True, slots=True)
class RotateRequest:
    """A ROTATE/TABLE|HEAD statement: the device's cell, ATANGL (absolute) or INCR, the
    angle and the direction (None: INCR turns CLW, ATANGL the shorter way)."""

    cell: int
    absolute: bool
    value: float
    direction: int | None


def parse_rotate(statement: Statement, machine: MachineDefinition) -> RotateRequest:
    """ROTATE/TABLE|HEAD with option 206: the way a CLW (and so INCR's default) turns the
    table, +1 CLW, -1 CCLW (001 L26616-26626); a head is not a table and keeps its CLW.
    ROTATE/TURRET goes by the machine's type (rotate_turret)."""
    if [a.name for a in statement.args if isinstance(a, Word)][:1] == ["TURRET"]:
        rotate_turret(statement, machine)
    cell, absolute, value, direction = _parse(statement)
    if cell == TABLE_CELL and machine.number_option(206) == -1:
        if direction is None and not absolute:
            direction = CLW
        if direction is not None:
            direction = -direction
    return RotateRequest(cell, absolute, value, direction)


def travel_limit_warning(
    machine: MachineDefinition,
    previous: float,
    travel: float,
    clw_increases: bool = True,
    device: str = "TABLE",
) -> str | None:
    """Options 220 and 221: the table turns between these scale readings (degrees; both 0:
    no limits, 001 L26698-26708); options 149 and 150 the head (001 L26154-26166). The
    manual gives no action, so a move that passes outside them is warned about, as a slide
    limit is (option 110), and still made."""
    # (each pair read by number: tools/checklist.py finds the options a module reads)
    if device == "HEAD":
        lower, upper = machine.number_option(149), machine.number_option(150)
    elif device == "SECOND HEAD":
        lower, upper = machine.number_option(199), machine.number_option(200)
    else:
        lower, upper = machine.number_option(220), machine.number_option(221)
    low_option, high_option = ROTATION_LIMIT_OPTIONS[device]
    if lower == 0 and upper == 0:
        return None
    end = previous + (1 if clw_increases else -1) * travel
    low, high = min(previous, end), max(previous, end)
    turns = math.floor((low - lower) / 360.0)
    if low >= lower + 360.0 * turns - 1e-9 and high <= upper + 360.0 * turns + 1e-9:
        return None
    return (
        f"{device} ROTATION LIMIT HAS BEEN EXCEEDED ({lower:g} TO {upper:g} DEGREES, "
        f"OPTIONS {low_option}, {high_option}) *** WARNING"
    )


def _parse(statement: Statement) -> tuple[int, bool, float, int | None]:
    """ROTATE/TABLE|HEAD, INCR|ATANGL, angle [, CLW|CCLW] (001 L36012-36053)."""
    words = [a.name for a in statement.args if isinstance(a, Word)]
    numbers = statement.numbers()
    device = words[0] if words else ""
    if device == "TORCH":
        # reached only from the multiaxis element (the other rotary elements turn a torch
        # themselves): ROTORC turns a two-axis flame cutter's torch (GEFLAM, option 132 =
        # 4, 001 L433, L36260-36302); under GEMAXS (option 116, L443) the rotary axes
        # follow the tool axis, which would undo a torch turned beside them
        raise InputError(
            "ROTATE/TORCH on a multiaxis machine: its rotary axes follow the tool axis of "
            "the GOTO records; turn the torch by the tool axis (ROTORC is the two-axis "
            "flame cutter's)",
            statement.where,
        )
    if device == "TURRET":
        # reached only from the multiaxis element (parse_rotate checks the machine first):
        # a multiaxis machine is a contouring one, with no spindle or drafting turret
        raise InputError(
            "ROTATE/TURRET on a multiaxis machine: ROTATE/TURRET turns a positioning "
            "machine's spindle turret (ROTUR) or a drafting machine's turret (ROTDRF)",
            statement.where,
        )
    if device in ("MAGAZINE", "INDEXER"):
        raise NotYetSupported(f"ROTATE/{device}", statement.where)
    if device not in ("TABLE", "HEAD"):
        raise InputError("ROTATE expects TABLE or HEAD first", statement.where)
    speed = [w for w in words[1:] if w in ("OFF", "RPM", "RANGE")]
    if device == "TABLE" and speed:
        # ROTABL hands a speed to TABSPD, a table that spins on its M codes (TABLEM 83,
        # 84, 50), and a move to ROTABI/ROTABA (001 L36012-36053, L38089-38171); the manual
        # gives no order or meaning for a table both spun and positioned by one statement
        raise InputError(
            f"ROTATE/TABLE takes a move (INCR or ATANGL) or a speed (OFF, CLW or CCLW with "
            f"RPM, RANGE), not both ({speed[0]} with a move): give them as two statements",
            statement.where,
        )
    unbuilt = [w for w in words[1:] if w not in ("INCR", "ATANGL", "CLW", "CCLW")]
    if unbuilt:
        raise NotYetSupported(f"ROTATE/{device},{unbuilt[0]}", statement.where)
    modes = [w for w in words if w in ("INCR", "ATANGL")]
    directions = [w for w in words if w in ("CLW", "CCLW")]
    if len(modes) != 1 or len(numbers) != 1 or len(directions) > 1:
        raise InputError(
            f"ROTATE/{device} expects INCR or ATANGL, one angle and at most one of CLW, CCLW",
            statement.where,
        )
    direction = None if not directions else (CLW if directions[0] == "CLW" else CCLW)
    cell = TABLE_CELL if device == "TABLE" else HEAD_CELL
    return cell, modes[0] == "ATANGL", numbers[0], direction
