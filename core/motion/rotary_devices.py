"""Rotary devices moved by M codes on a positioning machine: ROTATE/INDEXER (ROTIND) and
ROTATE/MAGAZINE (ROTMAG) (manual ROTATE 001 L36055-36095, ROTIND L36126-36160, ROTMAG
L36176-36217, MINMOV L34013-34055; TABLEM 48, 49, 83, 84; option 88).

* ROTATE/INDEXER, n [, RIGHT | LEFT]: n blocks, each with the step M code, TABLEM(48) to
  the right (the default) or TABLEM(49) to the left; STOREM(130) flushes the last one.
* ROTATE/MAGAZINE [, p] [, CLW | CCLW]: the magazine brings pocket p (default: the one in
  the up position) up, turning CLW (TABLEM 83) or CCLW (84), as programmed or the shorter
  way (MINMOV, |option 88| pockets); the pocket number goes in the T register, CODE -1.

Both are positioning-machine routines (restriction "OPTAB(1) must equal 1 or 2").
"""

from __future__ import annotations

from typing import Protocol

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.output.block import Block, Code

INDEX_RIGHT, INDEX_LEFT = 48, 49  # TABLEM cells (001 L36145-36149)
TURN_CLW, TURN_CCLW = 83, 84  # TABLEM cells (001 L36199-36201)
INDEXER_WORDS = ("INDEXER", "INDEXR")
MAGAZINE_WORDS = ("MAGAZINE", "MAGZIN")


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
