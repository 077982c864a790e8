"""ROTATE/TURRET on the machines that have a routine for it (ROTATE (RTATGB), 001
L36055-36095): ROTUR turns a positioning machine's spindle turret (GEPOS, L36345-36382) and
ROTDRF indexes a drafting machine's turret (GEDRAF, L36097-36124). On a contouring machine
the statement is bad input (core/motion/rotary_devices.py ``rotate_turret``). The forms and
codes the manual leaves open are decided in docs/decisions.md ("issue 22 wave 7").
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import Diagnostic, InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.rotary_devices import DRAFTING, DeviceOutput
from gecent.core.output.block import Block, Code
from gecent.core.state import PostState

TURRET_INDEX_D = 3.0  # ROTDRF's D code: the one DRAFT's pen codes 1, 2, 4, 5 leave free
D_REGISTER, T_REGISTER = 16, 13  # DBFSEG cells (DRAFT, 001 L30545-30560; the T word)
TURRET_INDEXED_PEN_DOWN = "WARNING -- TURRET INDEXED WHILE PEN IS DOWN -- WARNING"  # L36112
TOOL_CORRECTED_ON_TURRET = -2.0  # option 86: "... on a ROTATE/TURET statement" (L25424)


class SpindleTurret(Protocol):
    """What ROTUR uses of the tool element (core/tool.py): its load of a turret station."""

    state: PostState
    warn: Callable[[Diagnostic], None]
    length_scale: Callable[[float], float]

    def spindle_turret(
        self,
        statement: Statement,
        station: int,
        directions: list[str],
        offset: int | None,
        length: float | None,
    ) -> None: ...


def turret_routine(machine: MachineDefinition) -> str | None:
    """The routine ROTATE (RTATGB) gives ROTATE/TURRET (001 L36055-36095): ROTDRF on a
    drafting machine (option 132 = 3), ROTUR on a positioning one (GEPOS), else None."""
    if machine.number_option(132) == DRAFTING:
        return "ROTDRF"
    if machine.number_option(1) != 0:
        return "ROTUR"
    return None


def index_drafting_turret(
    statement: Statement,
    machine: MachineDefinition,
    out: DeviceOutput,
    pen_down: bool,
    warn: Callable[[Diagnostic], None],
) -> None:
    """ROTDRF: "a command block which rotates the turret", with the warning when the pen is
    down (001 L36097-36124). The drafting machine's codes go in its D register (DRAFT,
    L30529-30578), whose pen codes are 1, 2, 4 and 5: the index is D3, the one they leave
    free. ROTATE/TURRET indexes to the next station; ROTATE/TURRET, n names the station
    in the T register (docs/decisions.md, issue 22 wave 7)."""
    words = [a.name for a in statement.args[1:] if isinstance(a, Word)]
    numbers = statement.numbers()
    where = statement.where
    if words or len(numbers) > 1:
        raise InputError("ROTATE/TURRET on a drafting machine takes at most a station", where)
    if machine.registers.formats[D_REGISTER] is None:
        raise InputError(
            "ROTATE/TURRET: this drafting machine has no D register for its codes (REGSTR 16)",
            where,
        )
    block = Block(Code.NONMOTION, statement.number)
    block.cells[D_REGISTER] = TURRET_INDEX_D
    if numbers:
        station = numbers[0]
        if station != int(station) or station < 1:
            raise InputError(f"ROTATE/TURRET expects a station >= 1, found {station:g}", where)
        if machine.registers.formats[T_REGISTER] is None:
            raise InputError(
                f"ROTATE/TURRET,{station:g}: machine {machine.label} has no T register for "
                "the station; ROTATE/TURRET alone indexes to the next one",
                where,
            )
        block.cells[T_REGISTER] = station
    if pen_down:
        warn(Diagnostic(TURRET_INDEXED_PEN_DOWN, where))
    out.output(block)


def turn_spindle_turret(statement: Statement, tool: SpindleTurret) -> None:
    """ROTUR: "rotate the spindle turret into position for tool pickup or tool unload, and
    ... move the spindle into machining position" (001 L36345-36382), as TOOLGP loads a
    tool (core/tool.py): ROTATE/TURRET, n [, CLW | CCLW] [, OFSETL, k] [, LENGTH, l] brings
    station n down (TOOLDN) by the turret-index M code TABLEM(8), T n and the cycle-off
    TABLEG(1) in one block, turning as programmed or the shorter way (MINMOV, option 88 =
    -N). With option 86 = -2 ("make the tool correction and insert tool offset (if any) on
    a ROTATE/TURET statement", L25424) LENGTH is the tool length POSMOV adds to Z (option
    86 < 0, L34956-34961) and OFSETL's M code (option 96 = -K) goes out, after the turn's
    (one M register: a block each); with another option 86 they are said to be ignored
    (docs/decisions.md, issue 22 wave 7)."""
    where = statement.where
    station: int | None = None
    values: dict[str, float] = {}
    directions: list[str] = []
    args = statement.args[1:]
    index = 0
    while index < len(args):
        arg = args[index]
        following = args[index + 1] if index + 1 < len(args) else None
        if isinstance(arg, Word) and arg.name in ("OFSETL", "LENGTH"):
            if following is None or isinstance(following, Word) or arg.name in values:
                raise InputError(f"ROTATE/TURRET: {arg.name} expects one value", where)
            values[arg.name] = float(following)
            index += 2
            continue
        if isinstance(arg, Word) and arg.name in ("CLW", "CCLW") and not directions:
            directions.append(arg.name)
        elif not isinstance(arg, Word) and station is None and float(arg) == int(arg) >= 1:
            station = int(arg)
        else:
            raise InputError(
                "ROTATE/TURRET on a positioning machine expects a station >= 1, at most one "
                f"of CLW, CCLW, and OFSETL, k and LENGTH, l (found {arg})",
                where,
            )
        index += 1
    if station is None:
        raise InputError("ROTATE/TURRET on a positioning machine expects a station", where)
    machine = tool.state.machine
    offset = values.get("OFSETL")
    length = values.get("LENGTH")
    if offset is not None and (offset != int(offset) or offset < 0):
        raise InputError(f"ROTATE/TURRET: OFSETL expects a whole number, found {offset:g}", where)
    if length is not None and length < 0:
        raise InputError(f"ROTATE/TURRET: LENGTH expects a length >= 0, found {length:g}", where)
    correcting = machine.number_option(86) == TOOL_CORRECTED_ON_TURRET
    if not correcting and values:
        tool.warn(
            Diagnostic(
                "ROTATE/TURRET: OFSETL AND LENGTH ARE USED WITH OPTION 86 = -2 ONLY; IGNORED",
                where,
            )
        )
    tool.spindle_turret(
        statement,
        station,
        directions,
        int(offset) if correcting and offset is not None else None,
        tool.length_scale(length) if correcting and length is not None else None,
    )
