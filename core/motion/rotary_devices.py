"""Rotary devices other than a positioned table or head: ROTATE/INDEXER (ROTIND) and
ROTATE/MAGAZINE (ROTMAG), moved by M codes on a positioning machine, and the rotary
table's speed control, ROTATE/TABLE,OFF|CLW|CCLW,RPM,s,RANGE,n (TABSPD) (manual ROTATE
001 L36055-36095, ROTIND L36126-36160, ROTMAG L36176-36217, MINMOV L34013-34055, TABSPD
L38089-38171; TABLEM 1, 48, 49, 50, 83, 84; options 88, 179-183). The torch (ROTORC) is
in core/motion/rotary.py.

* ROTATE/INDEXER, n [, RIGHT | LEFT]: n blocks, each with the step M code, TABLEM(48) to
  the right (the default) or TABLEM(49) to the left; STOREM(130) flushes the last one.
* ROTATE/MAGAZINE [, p] [, CLW | CCLW]: the magazine brings pocket p (default: the one in
  the up position) up, turning CLW (TABLEM 83) or CCLW (84), as programmed or the shorter
  way (MINMOV, |option 88| pockets); the pocket number goes in the T register, CODE -1.
  Both are positioning-machine routines (restriction "OPTAB(1) must equal 1 or 2").
* ROTATE/TURRET: bad input on a contouring machine (rotate_turret); ROTUR and ROTDRF, the
  positioning and drafting machines' turrets, are in core/motion/rotary_turret.py.
* ROTATE/TABLE, OFF | CLW | CCLW [, RPM, s] [, RANGE, n]: a table that spins. The speed
  nearest s among the table speeds SRTAB(141 ..) (option 179 ranges of option 180; no RPM:
  option 181's) goes in DBFSEG(17), the direction's M code (TABLEM 83, 84; OFF: TABLEM 50)
  with it. A start waits option 183's dwell, a reversal option 182's after a comment; a
  change of range is a stop (TABLEM 1), the operator's comment, then the start without a
  dwell. TABSPD is in the mill overlay GEMILL (001 L19010-19050): contouring machines only.
  docs/decisions.md (issue 22).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import NoReturn, Protocol, runtime_checkable

from gecent.core.absent import ABSENT
from gecent.core.cl.records import Statement, Word
from gecent.core.errors import Diagnostic, InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import TABLE_SPEED_CELL
from gecent.core.output.block import Block, Code

INDEX_RIGHT, INDEX_LEFT = 48, 49  # TABLEM cells (001 L36145-36149)
TURN_CLW, TURN_CCLW = 83, 84  # TABLEM cells (001 L36199-36201)
INDEXER_WORDS = ("INDEXER", "INDEXR")
MAGAZINE_WORDS = ("MAGAZINE", "MAGZIN")
TABLE_OFF, PROGRAM_STOP = 50, 1  # TABLEM cells: "rotate table or indexer off", the stop
TABLE_SPEED_REGISTER = 17  # "merged and stored in DBFSEG(17)" (001 L38118-38119)
SPEED_WORDS = ("OFF", "CLW", "CCLW", "RPM", "RANGE")
# the comments TABSPD outputs (001 L38138-38145) are not worded in the manual: gecent's
TABLE_REVERSES = "ROTARY TABLE CHANGES DIRECTION"
TABLE_RANGE = "SHIFT THE ROTARY TABLE TO SPEED RANGE {}"


class DeviceOutput(Protocol):
    """What the devices use of the output element: OUTPUT and STOREM."""

    def output(self, block: Block) -> None: ...

    def store_m(self, code: float) -> None: ...


def rotate_indexer(statement: Statement, machine: MachineDefinition, out: DeviceOutput) -> None:
    """ROTIND: n M-code blocks turning the indexer right (default) or left."""
    words = _words(statement)
    numbers = statement.numbers()
    unknown = [w for w in words[1:] if w not in ("RIGHT", "LEFT")]
    if unknown or len(numbers) != 1 or words.count("RIGHT") + words.count("LEFT") > 1:
        raise InputError(
            "ROTATE/INDEXER expects the number of steps and at most one of RIGHT, LEFT",
            statement.where,
        )
    steps = numbers[0]
    if steps != int(steps) or steps < 1:
        raise InputError(
            f"ROTATE/INDEXER expects a whole number of steps >= 1, found {steps:g}",
            statement.where,
        )
    _positioning_only(statement, machine)
    cell = INDEX_LEFT if "LEFT" in words else INDEX_RIGHT
    code = machine.m_code(cell)
    if code is None:
        raise InputError(
            f"ROTATE/INDEXER: machine {machine.label} has no indexer M code TABLEM({cell})",
            statement.where,
        )
    for _ in range(int(steps)):
        out.store_m(code)
        out.output(Block(Code.AUX_ONLY, statement.number))  # STOREM(130): each in its block


def rotate_magazine(
    statement: Statement, machine: MachineDefinition, out: DeviceOutput, up: int | None
) -> int:
    """ROTMAG: the block that brings a pocket up; returns the pocket now up."""
    words = _words(statement)
    numbers = statement.numbers()
    unknown = [w for w in words[1:] if w not in ("CLW", "CCLW")]
    if unknown or len(numbers) > 1 or words.count("CLW") + words.count("CCLW") > 1:
        raise InputError(
            "ROTATE/MAGAZINE expects at most a pocket number and one of CLW, CCLW",
            statement.where,
        )
    _positioning_only(statement, machine)
    if numbers:
        pocket = numbers[0]
        if pocket != int(pocket) or pocket < 1:
            raise InputError(
                f"ROTATE/MAGAZINE expects a pocket number >= 1, found {pocket:g}", statement.where
            )
    elif up is None:
        raise InputError(
            "ROTATE/MAGAZINE without a pocket, and no tool is in the up position yet",
            statement.where,
        )
    wanted = int(numbers[0]) if numbers else up
    assert wanted is not None
    if "CLW" in words or "CCLW" in words:
        cell: int | None = TURN_CLW if "CLW" in words else TURN_CCLW
    else:
        cell = _shorter_way(statement, machine, up, wanted)
    block = Block(Code.AUX_ONLY, statement.number)
    if cell is not None:
        code = machine.m_code(cell)
        if code is None:
            raise InputError(
                f"ROTATE/MAGAZINE: machine {machine.label} has no magazine M code TABLEM({cell})",
                statement.where,
            )
        out.store_m(code)
    if machine.registers.formats[13] is not None:
        block.cells[13] = float(wanted)
    out.output(block)
    return wanted


def _shorter_way(
    statement: Statement, machine: MachineDefinition, up: int | None, wanted: int
) -> int | None:
    """MINMOV: the shorter way round |option 88| pockets, CLW toward higher numbers (the
    pockets are numbered CLW looking at the magazine from the top, TABLEM 83-84 note); no
    turn when the pocket is already up."""
    pockets = int(abs(machine.number_option(88)))
    if pockets == 0:
        raise InputError(
            "ROTATE/MAGAZINE without CLW or CCLW needs option 88, the number of pockets "
            "(MINMOV's restriction)",
            statement.where,
        )
    start = up if up is not None else wanted
    distance = (wanted - start) % pockets
    if distance == 0:
        return None
    return TURN_CLW if distance <= pockets / 2 else TURN_CCLW


DRAFTING = 3  # option 132: the drafting overlay GEDRAF, where ROTDRF is


def rotate_turret(statement: Statement, machine: MachineDefinition) -> NoReturn:
    """ROTATE/TURRET on a contouring machine: neither ROTUR (GEPOS, a positioning
    machine's spindle turret, L36345-36382) nor ROTDRF (GEDRAF) is there, its turret being
    the lathe's TURRET statement ("the TURRET statement (contouring)", option 96, L25532).
    The machines that have the routines turn their turrets in core/motion/rotary_turret.py."""
    raise InputError(
        "ROTATE/TURRET turns a positioning machine's spindle turret (ROTUR, overlay "
        "GEPOS) or a drafting machine's turret (ROTDRF, option 132 = 3); machine "
        f"{machine.label} is a contouring machine (option 1 = 0): a contouring lathe "
        "indexes its turret with TURRET/ (option 96)",
        statement.where,
    )


def _positioning_only(statement: Statement, machine: MachineDefinition) -> None:
    if machine.number_option(1) == 0:
        device = _words(statement)[0]
        raise InputError(
            f"ROTATE/{device} is a positioning-machine statement (ROTIND, ROTMAG: option 1 "
            f"must be 1 or 2); machine {machine.label} is a contouring machine",
            statement.where,
        )


def _words(statement: Statement) -> list[str]:
    return [a.name for a in statement.args if isinstance(a, Word)]


# -- TABSPD --------------------------------------------------------------------------------


@runtime_checkable
class TableOutput(Protocol):
    """What TABSPD uses of the output element: OUTPUT, STOREM and DWELL."""

    def output(self, block: Block) -> None: ...

    def store_m(self, code: float) -> None: ...

    def dwell(self, seconds: float) -> Block: ...


def is_table_speed(statement: Statement) -> bool:
    """ROTATE/TABLE with a speed modifier and no move (neither INCR nor ATANGL)."""
    words = _words(statement)
    return (
        bool(words)
        and words[0] == "TABLE"
        and not {"INCR", "ATANGL"} & set(words)
        and bool(set(SPEED_WORDS) & set(words[1:]))
    )


@dataclass(frozen=True, slots=True)
class SpeedRequest:
    """ROTATE/TABLE, OFF | CLW | CCLW, RPM, s, RANGE, n: None where a part was not given."""

    off: bool
    direction: int | None  # +1 CLW, -1 CCLW
    rpm: float | None
    range: int | None


def parse_table_speed(statement: Statement) -> SpeedRequest:
    """The modifiers in any order after TABLE; RPM and RANGE each take the number after."""
    args = statement.args[1:]
    off, direction, rpm, wanted_range = False, None, None, None
    index = 0
    form = "ROTATE/TABLE expects OFF, or CLW | CCLW with RPM, s and RANGE, n"
    while index < len(args):
        arg = args[index]
        name = arg.name if isinstance(arg, Word) else None
        following = args[index + 1] if index + 1 < len(args) else None
        number = float(following) if isinstance(following, int | float) else None
        if name == "OFF" and not off:
            off = True
        elif name in ("CLW", "CCLW") and direction is None:
            direction = 1 if name == "CLW" else -1
        elif name == "RPM" and rpm is None and number is not None and number > 0:
            rpm, index = number, index + 1
        elif name == "RANGE" and wanted_range is None and number is not None:
            if number != int(number) or number < 1:
                raise InputError(
                    f"ROTATE/TABLE,RANGE expects a whole range number >= 1, found {number:g}",
                    statement.where,
                )
            wanted_range, index = int(number), index + 1
        else:
            raise InputError(form, statement.where)
        index += 1
    if off and (direction is not None or rpm is not None or wanted_range is not None):
        raise InputError("ROTATE/TABLE,OFF takes no speed, direction or range", statement.where)
    return SpeedRequest(off, direction, rpm, wanted_range)


def checked_table_speed(statement: Statement, machine: MachineDefinition) -> SpeedRequest:
    """The request, on a contouring machine: TABSPD is in the mill overlay GEMILL."""
    request = parse_table_speed(statement)
    if machine.number_option(1) != 0:
        raise InputError(
            "ROTATE/TABLE speed control (TABSPD, overlay GEMILL) is a contouring-machine "
            f"statement; machine {machine.label} is a positioning machine (option 1)",
            statement.where,
        )
    return request


class TableSpeed:
    """TABSPD's memory: the way the table turns (TABDIR, 0 while stopped) and its range."""

    def __init__(self) -> None:
        self.direction = 0
        self.range = 1  # the table is taken to stand in its first range at the start

    def statement(
        self,
        statement: Statement,
        machine: MachineDefinition,
        out: TableOutput,
        warn: Callable[[Diagnostic], None],
    ) -> None:
        request = checked_table_speed(statement, machine)
        if request.off:
            out.store_m(_table_code(machine, TABLE_OFF, statement))
            out.output(Block(Code.AUX_ONLY, statement.number))
            self.direction = 0
            return
        if machine.registers.formats[TABLE_SPEED_REGISTER] is None:
            raise InputError(
                f"ROTATE/TABLE,RPM: machine {machine.label} has no table speed register "
                f"DBFSEG({TABLE_SPEED_REGISTER}) (REGFOR 17)",
                statement.where,
            )
        direction = request.direction or self.direction or 1
        wanted = request.rpm if request.rpm is not None else machine.number_option(181)
        speed_range, speed = self._nearest(machine, wanted, request.range, statement)
        # option 206: the way ROTATE/TABLE,CLW turns the table (001 L26616-26626)
        turning = -direction if machine.number_option(206) == -1 else direction
        code = _table_code(machine, 83 if turning > 0 else 84, statement)
        dwell = 0.0
        if speed_range != self.range:
            out.store_m(_table_code(machine, PROGRAM_STOP, statement))
            stop = Block(Code.AUX_ONLY, statement.number)
            stop.stop = True
            out.output(stop)
            warn(Diagnostic(TABLE_RANGE.format(speed_range), statement.where))
        elif self.direction and direction != self.direction:
            warn(Diagnostic(TABLE_REVERSES, statement.where))
            dwell = machine.number_option(182)
        elif not self.direction:
            dwell = machine.number_option(183)
        out.store_m(code)
        if dwell > 0:
            block = out.dwell(dwell)
            block.record = statement.number
        else:
            block = Block(Code.NONMOTION, statement.number)
        block.cells[TABLE_SPEED_REGISTER] = speed
        out.output(block)
        self.direction, self.range = direction, speed_range

    @staticmethod
    def _nearest(
        machine: MachineDefinition,
        rpm: float,
        wanted_range: int | None,
        statement: Statement,
    ) -> tuple[int, float]:
        """The table speed closest to ``rpm`` (ties: the lower speed), within the range
        asked for or over all the ranges, as (range, speed)."""
        ranges = int(machine.number_option(179))
        per_range = int(machine.number_option(180))
        top = TABLE_SPEED_CELL + ranges * per_range - 1
        cells = range(TABLE_SPEED_CELL, top + 1)
        if ranges < 1 or per_range < 1 or any(machine.srtab(i) is ABSENT for i in cells):
            raise InputError(
                f"ROTATE/TABLE at a speed: machine {machine.label} needs its table speeds in "
                f"SRTAB({TABLE_SPEED_CELL}..{max(top, TABLE_SPEED_CELL)}) (options 179 = "
                f"{ranges} ranges x 180 = {per_range} speeds)",
                statement.where,
            )
        if wanted_range is not None and wanted_range > ranges:
            raise InputError(
                f"ROTATE/TABLE,RANGE,{wanted_range}: the table has {ranges} speed range(s) "
                "(option 179)",
                statement.where,
            )
        choices = [
            (abs(float(machine.srtab(cell)) - rpm), float(machine.srtab(cell)), number)  # type: ignore[arg-type]
            for number in range(1, ranges + 1)
            if wanted_range in (None, number)
            for cell in range(
                TABLE_SPEED_CELL + (number - 1) * per_range,
                TABLE_SPEED_CELL + number * per_range,
            )
        ]
        _, speed, number = min(choices)
        return number, speed


def _table_code(machine: MachineDefinition, cell: int, statement: Statement) -> float:
    code = machine.m_code(cell)
    if code is None:
        raise InputError(
            f"ROTATE/TABLE: machine {machine.label} has no M code TABLEM({cell}) "
            "(table off 50, CLW 83, CCLW 84, stop 1)",
            statement.where,
        )
    return code
