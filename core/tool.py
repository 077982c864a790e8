"""Loading a tool on a contouring machine: TOOLNO/n (APT IV's LOADTL/n), TURRET and
SELECT/TOOL (manual TOOLNO 001 L38733-38799, TOOLGM L38605-38646, TOOLGP L38648-38692, TOOLL
L38694-38731, TURRET L39054-39091, SELTUL L37287-37335, MINMOV L34013-34055, options 86
L25406-25434 and 96 L25520-25569), read in docs/research/spindle-tool.md.

* The tool-change M code TABLEM(7) waits for the next block (STOREM); a rotating magazine
  or turret turns CLW (TABLEM 83) or CCLW (84), as programmed or the shorter way (MINMOV,
  option 88 negative).
* A machine with a T register gets a dwell block of option 83 seconds carrying the T word;
  one without (MACH23) records the tool and outputs nothing.
* TOOLNO/n, OFSETL, k (or ADJUST, k) makes T = n followed by the two offset digits
  (n x 100 + k); with option 96 = -K the offset is the M code k + K instead (WE-11).
* TURRET/t[, p[, a, b]][, OFSETL, k][, FRONT|REAR][, CLW|CCLW][, NOW|NEXT] packs tool t,
  turret position p (default t) and offset k into T by option 96's layout (COMTAT,
  core/turret.py); a and b are the tool's turret distances, NOW and NEXT its corrective
  move; FRONT and REAR select the turret (TABLEM 29, 30), the index itself is TABLEM(8).
* SELECT/TOOL, n[, OFSETL, k] preselects the next tool: TABLEG(1) and T in a CODE -4 block.

Tool length, LENGTH, l (TOOLEN; PREVTL the last length): on a mill or a lathe a change of
length moves the previous point along the machine's Z (TOOLGM, TOOLL), so the next move
carries it, with the information block 1; on a positioning machine option 86 puts it in
the Z translation (+1: the change since the first tool; +2: less the length; negative:
POSMOV adds the length, core/motion/positioning.py).

On a positioning machine (TOOLGP) the T goes out at once with the cycle-off G code TABLEG(1)
in a CODE -1 block, and the output adds the spindle command to it (option 1 = 1); with option
1 = 2 no block is made: the T waits for the next motion block (core/output/element.py).

A modern control (gecent option 263, docs/modern-controls.md) numbers the tool's offsets:
ADJUST h, OFSETL k or the tool number. A mill (263 = 1) gives it as H with G43 in the first
move after the tool change and as D with CUTCOM; LOADTL LENGTH is accepted, since the control
holds the lengths. A lathe (263 = 2) punches T as station and offset, two digits each.

TURRET on a positioning machine (the manual's TURRET is the contouring lathe's) is not built
and stops the run with an error naming it.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import Diagnostic, InputError, SourcePosition
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
from gecent.core.turret import MACHINE_Z, TurretCorrection, cl_deltas, comtat, shift_previous

TOOL_CHANGE, TURRET_INDEX, FRONT_TURRET, REAR_TURRET = 7, 8, 29, 30
TURN_CLW, TURN_CCLW = 83, 84
_DIRECTIONS = {"CLW": TURN_CLW, "CCLW": TURN_CCLW}
_TURRETS = {"FRONT": FRONT_TURRET, "REAR": REAR_TURRET}
_CORRECTIONS = ("NOW", "NEXT")
TOOL_LENGTH_CHANGE = 1.0  # information block 1: the tool correction (001 L22194-22197)
LENGTH_ZERO = "TOOL LENGTH IS ZERO"  # comment 19 (its text is not in the manual's scan)
PRESELECTED = "PREVIOUSLY SELECTED TOOL WAS NOT LOADED - PRESENT TOOL IS SELECTED"


class ToolElement:
    def __init__(
        self, state: PostState, output: OutputElement, warn: Callable[[Diagnostic], None]
    ) -> None:
        self.state = state
        self.output = output
        self.warn = warn
        self.position: int | None = None  # FFRSTL: where the magazine or turret stands
        self.length_scale: Callable[[float], float] = float  # CL units to the machine's
        self.turret_correction = TurretCorrection(state, output, warn)
        self.first_length: float | None = None  # the first tool's length (FORK, PREVTL)
        self.previous_length: float | None = None  # PREVTL
        self.length_term = 0.0  # option 86 = 1 or 2: the length in the Z translation
        self.selected: int | None = None  # TOLSLC: SELECT/TOOL's tool, not yet loaded

    def statement(self, statement: Statement) -> None:
        """TOOLNO/n[, OFSETL, k][, ADJUST, k][, LENGTH, l][, CLW|CCLW]."""
        offsets = int(self.state.machine.number_option(263))
        allowed = ("OFSETL", "CLW", "CCLW", "LENGTH", "ADJUST")
        tool, words, offset = self._parse(statement, allowed=allowed)
        if not offsets:
            self._manual_load(statement, tool, words, offset)
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

    def _manual_load(
        self, statement: Statement, tool: int, words: list[str], offset: int | None
    ) -> None:
        """TOOLNO as the manual makes it: OFSETL (or APT IV's ADJUST) in T or as option
        96's M code, then the tool-length correction."""
        adjust = _value_after(statement, "ADJUST")
        if adjust is not None and offset is not None:
            raise InputError(f"{statement.major} takes one of OFSETL and ADJUST", statement.where)
        number = adjust if adjust is not None else offset
        length = self._manual_length(statement)
        offset_m = self._offset_m(number)
        t_code = tool if number is None or offset_m is not None else tool * 100 + number
        self._load(statement, tool, t_code, words, index_cell=None, offset_m=offset_m)
        if length is not None:
            self._length_change(statement, length)

    def select_tool(self, statement: Statement) -> None:
        """SELECT/TOOL, n[, OFSETL, k] (SELTUL): the next tool, preselected in a CODE -4
        block of TABLEG(1) and T; a selection not yet loaded is replaced, with a comment."""
        selection = replace(statement, major="SELECT/TOOL", args=statement.args[1:])
        tool, _, offset = self._parse(selection, allowed=("OFSETL",))
        if self.selected is not None:
            self.warn(Diagnostic(PRESELECTED, statement.where))
        self.selected = tool
        machine = self.state.machine
        if machine.registers.formats[13] is None:
            return  # no T register: the selection is the operator's
        offset_m = self._offset_m(offset)
        block = Block(Code.G_ONLY, statement.number)
        cycle_off = machine.g_code(1)
        if cycle_off is not None:
            block.cells[2] = float(cycle_off)
        block.cells[13] = tool if offset is None or offset_m is not None else tool * 100 + offset
        if offset_m is not None:
            self.output.store_m(offset_m)
        self.output.output(block)

    def turret(self, statement: Statement) -> None:
        """TURRET/t[, p[, a, b]][, OFSETL, k][, FRONT|REAR][, CLW|CCLW][, NOW|NEXT]."""
        allowed = ("OFSETL", "CLW", "CCLW", "FRONT", "REAR", *_CORRECTIONS)
        tool, words, offset = self._parse(statement, allowed=allowed, positions=4)
        numbers = _plain_numbers(statement)
        position = int(numbers[1]) if len(numbers) > 1 else tool
        where = statement.where
        if len(numbers) == 3:
            raise InputError("TURRET gives the tool's distances as a pair: t, p, a, b", where)
        when = [w for w in words if w in _CORRECTIONS]
        if len(when) > 1:
            raise InputError("TURRET takes one of NOW and NEXT", where)
        offset_m = None
        if self.state.machine.number_option(263) == LATHE_OFFSETS:
            # a modern lathe: the station, then the offset (OFSETL, else the tool number)
            number = offset if offset is not None else tool
            if position > 99 or number > 99:
                raise InputError(
                    f"TURRET station {position} and offset {number} must be 0-99 each", where
                )
            t_code = position * 100 + number
        else:
            offset_m = self._offset_m(offset)
            t_code = comtat(self.state.machine, tool, position, offset or 0, where)
        for word in words:
            if word in _TURRETS:
                self._store(_TURRETS[word], where)
        self._load(statement, position, t_code, words, index_cell=TURRET_INDEX, offset_m=offset_m)
        distances = (
            (self.length_scale(numbers[2]), self.length_scale(numbers[3]))
            if len(numbers) == 4
            else None
        )
        self.turret_correction.index(where, statement.number, distances, when[0] if when else None)

    def _parse(
        self, statement: Statement, allowed: tuple[str, ...], positions: int = 1
    ) -> tuple[int, list[str], int | None]:
        machine = self.state.machine
        where = statement.where
        words = [a.name for a in statement.args if isinstance(a, Word)]
        for word in words:
            if word not in allowed:
                raise InputError(
                    f"{statement.major} does not take {word}; expected {', '.join(allowed)}",
                    where,
                )
        if "CLW" in words and "CCLW" in words:
            raise InputError(f"{statement.major} takes one of CLW and CCLW", where)
        if machine.number_option(1) != 0 and positions > 1:
            # the manual's TURRET is the contouring lathe's ("the TURRET statement
            # (contouring)", option 96, 001 L25532); a positioning machine turns its
            # turret with ROTATE/TURRET (ROTUR)
            raise InputError(
                f"{statement.major}/tool,position is the contouring lathe's statement (option "
                "96); a positioning machine turns its turret with ROTATE/TURRET",
                where,
            )
        numbers = _plain_numbers(statement)
        offset = _value_after(statement, "OFSETL")
        # a turret's distances a, b may be any length; the tool and position are counts
        counted = numbers[:2] if positions > 1 else numbers
        if not 1 <= len(numbers) <= positions or any(n < 0 or n != int(n) for n in counted):
            expected = (
                "one tool number"
                if positions == 1
                else "a tool, a turret position and the tool's distances a, b"
            )
            raise InputError(
                f"{statement.major} expects {expected}, whole numbers >= 0", statement.where
            )
        return int(numbers[0]), words, offset

    def _offset_m(self, offset: int | None) -> float | None:
        """Option 96 = -K: the offset k as the M code k + K (001 L25564-25568, WE-11)."""
        layout = self.state.machine.number_option(96)
        if offset is None or layout >= 0:
            return None
        return float(offset + abs(int(layout)))

    def _manual_length(self, statement: Statement) -> float | None:
        """LENGTH, l in the machine's units; zero is comment 19, negative bad input."""
        if "LENGTH" not in statement.words():
            return None
        length = statement.value_after("LENGTH")
        if length is None:
            raise InputError(f"{statement.major} LENGTH expects a length", statement.where)
        if length < 0:
            raise InputError(
                f"{statement.major} LENGTH expects a length >= 0, found {length:g}",
                statement.where,
            )
        if length == 0:
            self.warn(Diagnostic(LENGTH_ZERO, statement.where))
        return self.length_scale(length)

    def _length_change(self, statement: Statement, length: float) -> None:
        """TOOLEN and PREVTL: the first length is the reference; a later change corrects
        Z on a contouring machine (TOOLGM, TOOLL) or the Z translation on a positioning
        one (TOOLGP, option 86)."""
        machine = self.state.machine
        self.state.tool.length = length
        if self.first_length is None:
            self.first_length = self.previous_length = length
        change = length - (self.previous_length or 0.0)
        self.previous_length = length
        if machine.number_option(1) != 0:
            self._positioning_length(length)
            return
        if not change or machine.number_option(251) == 1:
            return  # an absolute control holds the lengths itself
        # the gauge point moves up by a longer tool's extra length: the next move carries it
        shift_previous(self.state, cl_deltas(self.output, {MACHINE_Z: change}))
        block = Block(Code.INFORMATION, statement.number)
        block.cells[2] = TOOL_LENGTH_CHANGE
        block.cells[3] = change
        self.output.emit(block)

    def _positioning_length(self, length: float) -> None:
        """Option 86 (001 L25406-25434): +1 adds the change since the first tool to the Z
        translation (TOOLGP's TRANSL(3)), +2 takes the length off Z; 0 and negative values
        leave the translation alone (negative: POSMOV adds the length)."""
        option = self.state.machine.number_option(86)
        assert self.first_length is not None
        term = length - self.first_length if option == 1 else -length if option == 2 else 0.0
        x, y, z = self.state.position.translation
        self.state.position.translation = (x, y, z + term - self.length_term)
        self.length_term = term

    def spindle_turret(
        self,
        statement: Statement,
        station: int,
        directions: list[str],
        offset: int | None,
        length: float | None,
    ) -> None:
        """ROTUR's turn of a positioning machine's spindle turret (core/motion/
        rotary_devices.py turn_spindle_turret): station n comes down as TOOLGP loads a tool,
        in one block with TABLEG(1) and T; ``offset`` and ``length`` (machine units) only with
        option 86 = -2: the length is TOOLEN, which POSMOV adds to Z (option 86 < 0)."""
        if length is not None:  # TOOLEN: POSMOV adds it to Z under option 86 < 0 (L34959)
            self.state.tool.length = length
            if self.first_length is None:
                self.first_length = length
            self.previous_length = length
        machine = self.state.machine
        self.state.tool.number = station
        self.selected = None
        # one block turns the turret: the direction's code (as programmed, else MINMOV's
        # shorter way) or, with neither, the turret-index code
        direction = next((_DIRECTIONS[w] for w in directions), None)
        if direction is None:
            direction = self._shorter_way(station)
        index = machine.m_code(TURRET_INDEX)
        if direction is not None:
            self._store(direction, statement.where)
        elif index is not None:
            self.output.store_m(index)
        offset_m = self._offset_m(offset)
        if offset_m is not None:
            self.output.store_m(offset_m)
        self.position = station
        has_t = machine.registers.formats[13] is not None
        if has_t:
            self.state.remember(T_CODE, station)
        if has_t and machine.number_option(1) == 2:
            self.state.pending.tool = float(station)  # TOOLGP's T waits for the motion
            return
        block = Block(Code.AUX_ONLY, statement.number)
        cycle_off = machine.g_code(1)
        if cycle_off is not None:
            block.cells[2] = float(cycle_off)
        if has_t:
            block.cells[13] = station
        self.output.output(block)

    def _load(
        self,
        statement: Statement,
        station: int,
        t_code: int,
        words: list[str],
        index_cell: int | None,
        offset_m: float | None = None,
    ) -> None:
        machine = self.state.machine
        self.state.tool.number = station
        self.selected = None  # a load takes the preselected tool
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
        if offset_m is not None:
            self.output.store_m(offset_m)
        self.position = station
        if has_t and machine.number_option(1) == 2:
            # TOOLGP makes no block: the T waits for the next motion block (001 L24346-24349)
            self.state.pending.tool = float(t_code)
        elif has_t and machine.number_option(1) != 0:
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
