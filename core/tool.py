"""Loading a tool on a contouring machine: TOOLNO/n (APT IV's LOADTL/n) and TURRET
(manual TOOLNO 001 L38733-38799, TOOLGM L38605-38646, TOOLL L38694-38731, TURRET
L39054-39091, COMTAT L29715-29760, MINMOV L34013-34055, option 96 L25520-25569), read in
docs/research/spindle-tool.md and docs/research/lathe-tools.md.

* The tool-change M code TABLEM(7) waits for the next block (STOREM); a rotating magazine
  or turret turns CLW (TABLEM 83) or CCLW (84), as programmed or the shorter way (MINMOV,
  option 88 negative).
* A machine with a T register gets a dwell block of option 83 seconds carrying the T word;
  one without (MACH23) records the tool and outputs nothing.
* TOOLNO/n, OFSETL, k makes T = n followed by the two offset digits (n x 100 + k).
* TURRET/t[, p][, OFSETL, k][, FRONT|REAR][, CLW|CCLW] packs tool t, turret position p
  (default t) and offset k into T by option 96's layout (COMTAT); FRONT and REAR select the
  turret (TABLEM 29, 30), the index itself is TABLEM(8).

On a positioning machine (TOOLGP) the T goes out at once with the cycle-off G code TABLEG(1)
in a CODE -1 block, and the output adds the spindle command to it (option 1 = 1).

A modern control (gecent option 263, docs/modern-controls.md) numbers the tool's offsets:
ADJUST h, OFSETL k or the tool number. A mill (263 = 1) gives it as H with G43 in the first
move after the tool change and as D with CUTCOM; LOADTL LENGTH is accepted, since the control
holds the lengths. A lathe (263 = 2) punches T as station and offset, two digits each.

The manual's tool-length corrections (LENGTH, ADJUST without option 263), turret corrective
moves (NOW, NEXT), TURRET on a positioning machine and T merged into the next motion block
(option 1 = 2) are not built and stop the run with an error naming them.
"""

from __future__ import annotations

from collections.abc import Callable

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import Diagnostic, InputError, NotYetSupported, SourcePosition
from gecent.core.output.block import Block, Code
from gecent.core.output.element import OutputElement
from gecent.core.output.modern import (
    CUTCOM_OFF,
    LATHE_OFFSETS,
    MILL_OFFSETS,
    TOOL_LENGTH_ON,
    TOOL_LENGTH_REGISTER,
)
from gecent.core.state import SPINDLE_COMMAND, SPINDLE_M, T_CODE, PostState

TOOL_CHANGE, TURRET_INDEX, FRONT_TURRET, REAR_TURRET = 7, 8, 29, 30
TURN_CLW, TURN_CCLW = 83, 84
_DIRECTIONS = {"CLW": TURN_CLW, "CCLW": TURN_CCLW}
_TURRETS = {"FRONT": FRONT_TURRET, "REAR": REAR_TURRET}

# option 96: the T word's fields, first digit first, with their digit counts (001
# L25532-25560). The OCR damaged the type column; 0 and 3-6 are legible, 2 is the sample
# lathe's five-digit layout (MACH04: option 96 = 2, T format 50); 1 and 7 are not built.
T_LAYOUTS: dict[int, tuple[tuple[str, int], ...]] = {
    0: (("tool", 0),),
    2: (("offset", 2), ("tool", 2), ("position", 1)),
    3: (("tool", 1), ("position", 1)),
    4: (("tool", 1), ("offset", 1)),
    5: (("offset", 1), ("tool", 1)),
    6: (("offset", 1), ("tool", 1), ("position", 1)),
}


class ToolElement:
    def __init__(
        self, state: PostState, output: OutputElement, warn: Callable[[Diagnostic], None]
    ) -> None:
        self.state = state
        self.output = output
        self.warn = warn
        self.position: int | None = None  # FFRSTL: where the magazine or turret stands
        self.length_scale: Callable[[float], float] = float  # CL units to the machine's

    def statement(self, statement: Statement) -> None:
        """TOOLNO/n[, OFSETL, k][, CLW|CCLW], and on a modern control [, LENGTH, l][, ADJUST, h]."""
        offsets = int(self.state.machine.number_option(263))
        allowed = ("OFSETL", "CLW", "CCLW") + (("LENGTH", "ADJUST") if offsets else ())
        tool, words, offset = self._parse(statement, allowed=allowed)
        if not offsets:
            t_code = tool if offset is None else tool * 100 + offset
            self._load(statement, tool, t_code, words, index_cell=None)
            return
        modes = self.state.modes
        if modes.compensation:
            # a control does not change tools under G41/G42: compensation ends first
            self.warn(
                Diagnostic(
                    f"TOOL CHANGE WITH CUTCOM/{modes.compensation} ON: G40 FIRST",
                    statement.where,
                )
            )
            modes.compensation = ""
            code = self.state.machine.g_code(CUTCOM_OFF)
            if code is not None:
                block = Block(Code.G_ONLY, statement.number)
                block.cells[2] = code
                self.output.output(block)
        adjust = _value_after(statement, "ADJUST")
        # the control holds the tool's length; a five-axis head's computed slides need it
        _value_after(statement, "LENGTH")
        length = _length_after(statement)
        self.state.tool.length = None if length is None else self.length_scale(length)
        number = adjust if adjust is not None else offset if offset is not None else tool
        if offsets == LATHE_OFFSETS:
            if tool > 99:
                t_code = tool  # station and offset already (T0101 as LOADTL/101)
            elif number > 99:
                raise InputError(
                    f"{statement.major} offset {number} does not fit the two digits of T",
                    statement.where,
                )
            else:
                t_code = tool * 100 + number
        else:
            t_code = tool
        self._load(statement, tool, t_code, words, index_cell=None)
        machine = self.state.machine
        self._spindle_stopped()
        self.state.tool.offset = number
        self.state.tool.length_pending = (
            offsets == MILL_OFFSETS
            and machine.g_code(TOOL_LENGTH_ON) is not None
            and machine.registers.formats[TOOL_LENGTH_REGISTER] is not None
        )

    def turret(self, statement: Statement) -> None:
        """TURRET/t[, p][, OFSETL, k][, FRONT|REAR][, CLW|CCLW]: COMTAT's T word."""
        allowed = ("OFSETL", "CLW", "CCLW", "FRONT", "REAR")
        tool, words, offset = self._parse(statement, allowed=allowed, positions=2)
        numbers = _plain_numbers(statement)
        position = int(numbers[1]) if len(numbers) > 1 else tool
        if self.state.machine.number_option(263) == LATHE_OFFSETS:
            # a modern lathe: the station, then the offset (OFSETL, else the tool number)
            number = offset if offset is not None else tool
            if position > 99 or number > 99:
                raise InputError(
                    f"TURRET station {position} and offset {number} must be 0-99 each",
                    statement.where,
                )
            t_code = position * 100 + number
        else:
            t_code = self._comtat(tool, position, offset or 0, statement.where)
        for word in words:
            if word in _TURRETS:
                self._store(_TURRETS[word], statement.where)
        self._load(statement, position, t_code, words, index_cell=TURRET_INDEX)

    def _parse(
        self, statement: Statement, allowed: tuple[str, ...], positions: int = 1
    ) -> tuple[int, list[str], int | None]:
        machine = self.state.machine
        where = statement.where
        words = [a.name for a in statement.args if isinstance(a, Word)]
        for word in words:
            if word in ("LENGTH", "ADJUST", "NOW", "NEXT") and word not in allowed:
                raise NotYetSupported(f"{statement.major}/{word}", where)
            if word not in allowed:
                raise InputError(
                    f"{statement.major} does not take {word}; expected {', '.join(allowed)}",
                    where,
                )
        if "CLW" in words and "CCLW" in words:
            raise InputError(f"{statement.major} takes one of CLW and CCLW", where)
        if machine.number_option(1) != 0 and positions > 1:
            raise NotYetSupported(f"{statement.major} on a positioning machine", where)
        if machine.number_option(1) == 2:
            raise NotYetSupported("T merged into the following motion block (option 1 = 2)", where)
        numbers = _plain_numbers(statement)
        offset = _value_after(statement, "OFSETL")
        if not 1 <= len(numbers) <= positions or any(n < 0 or n != int(n) for n in numbers):
            expected = "one tool number" if positions == 1 else "a tool and a turret position"
            raise InputError(
                f"{statement.major} expects {expected}, whole numbers >= 0", statement.where
            )
        return int(numbers[0]), words, offset

    def _comtat(self, tool: int, position: int, offset: int, where: SourcePosition) -> int:
        """COMTAT: the fields of option 96's layout, packed first digit first."""
        layout_type = int(self.state.machine.number_option(96))
        layout = T_LAYOUTS.get(layout_type)
        if layout is None:
            raise NotYetSupported(f"T-word layout type {layout_type} (option 96)", where)
        values = {"tool": tool, "position": position, "offset": offset}
        code = 0
        for field, digits in layout:
            value = values[field]
            if digits and value >= 10**digits:
                raise InputError(
                    f"TURRET {field} {value} does not fit the {digits} digit(s) option 96 = "
                    f"{layout_type} gives it",
                    where,
                )
            code = code * 10**digits + value if digits else value
        return code

    def _load(
        self,
        statement: Statement,
        station: int,
        t_code: int,
        words: list[str],
        index_cell: int | None,
    ) -> None:
        machine = self.state.machine
        self.state.tool.number = station
        has_t = machine.registers.formats[13] is not None
        if has_t:
            self.state.remember(T_CODE, t_code)
        change = machine.m_code(TOOL_CHANGE if index_cell is None else index_cell)
        if change is not None:
            self.output.store_m(change)
        direction = next((_DIRECTIONS[w] for w in words if w in _DIRECTIONS), None)
        if direction is None:
            direction = self._shorter_way(station)
        if direction is not None:
            self._store(direction, statement.where)
        self.position = station
        if has_t and machine.number_option(1) != 0:
            # TOOLGP: the cycle-off G code and the T in a CODE -1 block (001 L38648-38692)
            block = Block(Code.AUX_ONLY, statement.number)
            cycle_off = machine.g_code(1)
            if cycle_off is not None:
                block.cells[2] = float(cycle_off)
            block.cells[13] = t_code
            self.output.output(block)
        elif has_t:
            seconds = machine.number_option(83)
            # no change dwell: the T in a block of its own (a G04 P0 says nothing)
            block = self.output.dwell(seconds) if seconds else Block(Code.NONMOTION)
            block.record = statement.number
            block.cells[13] = t_code
            self.output.output(block)

    def _spindle_stopped(self) -> None:
        """A modern control's tool change (M06) stops the spindle (Fanuc, Haas, LinuxCNC):
        a turning spindle is started again, at its speed and in its sense, with the first
        move after the change unless a SPINDL restarts it first."""
        spindle = self.state.spindle
        conditions = self.state.conditions.values
        command, m_code = conditions.get(SPINDLE_COMMAND), conditions.get(SPINDLE_M)
        if spindle.on and command is not None and m_code is not None:
            spindle.restart = (command, m_code)
        spindle.on = False

    def _shorter_way(self, station: int) -> int | None:
        """MINMOV: with option 88 = -N (N stations, turned by M codes) the shorter way from
        the present station, CLW toward higher numbers (stations are numbered CLW looking
        at the magazine from the top, TABLEM 83-84 note)."""
        count = self.state.machine.number_option(88)
        if count >= 0 or self.position is None:
            return None
        stations = int(-count)
        distance = (station - self.position) % stations
        if distance == 0:
            return None
        return TURN_CLW if distance <= stations / 2 else TURN_CCLW

    def _store(self, cell: int, where: SourcePosition) -> None:
        self.output.store_cell(cell, self.warn, where)


_VALUED = ("OFSETL", "ADJUST", "LENGTH")  # words whose value follows them


def _plain_numbers(statement: Statement) -> list[float]:
    """The numbers not taken by OFSETL, k (or ADJUST, h and LENGTH, l)."""
    numbers: list[float] = []
    args = statement.args
    skip = False
    for index, arg in enumerate(args):
        if skip:
            skip = False
            continue
        if isinstance(arg, Word):
            skip = arg.name in _VALUED and index + 1 < len(args)
            continue
        numbers.append(float(arg))
    return numbers


def _value_after(statement: Statement, name: str) -> int | None:
    """OFSETL, k or ADJUST, h: a whole offset number 0-99 (LENGTH, l: a length, checked
    positive); None when the word is not given."""
    args = statement.args
    for index, arg in enumerate(args):
        if isinstance(arg, Word) and arg.name == name:
            if index + 1 >= len(args) or isinstance(args[index + 1], Word):
                what = "a length" if name == "LENGTH" else "an offset number"
                raise InputError(f"{statement.major} {name} expects {what}", statement.where)
            value = float(args[index + 1])  # type: ignore[arg-type]
            if name == "LENGTH":
                if not value > 0:
                    raise InputError(
                        f"{statement.major} LENGTH expects a length > 0, found {value:g}",
                        statement.where,
                    )
                return None
            if value < 0 or value != int(value) or value > 99:
                raise InputError(
                    f"{statement.major} {name} expects an offset number 0-99, found {value:g}",
                    statement.where,
                )
            return int(value)
    return None


def _length_after(statement: Statement) -> float | None:
    """LENGTH, l's length (checked by _value_after first)."""
    args = statement.args
    for index, arg in enumerate(args[:-1]):
        if isinstance(arg, Word) and arg.name == "LENGTH":
            return float(args[index + 1])  # type: ignore[arg-type]
    return None
