"""CUTCOM (CTCMGB, manual 001 L30025-30060): the cutter-compensation G code in a block by
itself (CODE -4, which the output stage never drops as a redundant G, L9241-9250).

The manual does not list CUTCOM's modifiers; they come from TABLEG's cutter-compensation
functions: 40 off, 41 left, 42 right (L22628-22691), 46 plus, 47 minus.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement
from gecent.core.errors import Diagnostic, InputError
from gecent.core.output.block import Block, Code
from gecent.core.output.modern import CUTTER_REGISTER, MILL_OFFSETS

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post

CUTCOM_CELLS = {"OFF": 40, "LEFT": 41, "RIGHT": 42, "PLUS": 46, "MINUS": 47}
# comment 22's wording (001 L29355-29358), for a G code: the manual has no comment of its own
G_NOT_AVAILABLE = "REQUESTED PREPARATORY FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE"


PLANES = ("XYPLAN", "YZPLAN", "ZXPLAN")  # APT IV's plane of the compensation


def cutcom(run: Post, statement: Statement) -> None:
    """CUTCOM/LEFT|RIGHT|OFF|PLUS|MINUS[, XYPLAN|YZPLAN|ZXPLAN][, n]: TABLEG(40, 41, 42, 46,
    47) in a G-only block; a code the machine lacks is reported and nothing is output. On
    a modern mill (option 263 = 1) G41/G42 carry D: n, or the loaded tool's offset number;
    the control is put in the plane word's plane (XY without one) first, as for an arc."""
    words = statement.words()
    numbers = statement.numbers()
    side = [w for w in words if w in CUTCOM_CELLS]
    planes = [w for w in words if w in PLANES]
    if (
        len(side) != 1
        or len(planes) > 1
        or len(side) + len(planes) != len(words)
        or len(numbers) > 1
        or (numbers and side[0] not in ("LEFT", "RIGHT"))
    ):
        raise InputError(
            "CUTCOM expects LEFT or RIGHT [,XYPLAN|YZPLAN|ZXPLAN][,offset number], or OFF, "
            f"PLUS or MINUS; found {', '.join(str(a) for a in statement.args) or 'nothing'}",
            statement.where,
        )
    code = run.machine.g_code(CUTCOM_CELLS[side[0]])
    if code is None:
        run.warn(Diagnostic(G_NOT_AVAILABLE, statement.where))
        return
    modes = run.state.modes
    modern = run.machine.number_option(263) == MILL_OFFSETS
    if modern and side[0] in ("LEFT", "RIGHT"):
        if modes.compensation and modes.compensation != side[0]:
            # a control changes sides through G40 (LinuxCNC refuses G42 under G41)
            run.warn(
                Diagnostic(
                    f"CUTCOM/{side[0]} WHILE {modes.compensation} IS ON: G40 FIRST", statement.where
                )
            )
            compensation_off(run, statement.number)
        tool = run.state.tool
        if tool.length_pending:
            # the tool length goes on before compensation (no G43 under G41/G42)
            run.output.tool_length_block(statement.number)
    modes.compensation = "" if side[0] == "OFF" else side[0]
    if side[0] in ("LEFT", "RIGHT") and run.machine.number_option(9) == 1:
        # compensation works in a plane: the control is put in it first (XY unless named)
        plane = {"XYPLAN": 0, "ZXPLAN": 1, "YZPLAN": 2}[planes[0] if planes else "XYPLAN"]
        run.circle.select_plane(plane, statement.number)
    block = Block(Code.G_ONLY, statement.number)
    block.cells[2] = code
    if side[0] in ("LEFT", "RIGHT") and run.machine.number_option(263) == MILL_OFFSETS:
        offset = numbers[0] if numbers else run.state.tool.offset
        if offset is not None and run.machine.registers.formats[CUTTER_REGISTER] is not None:
            if offset < 0 or offset != int(offset):
                raise InputError(
                    f"CUTCOM expects a whole offset number, found {offset:g}", statement.where
                )
            block.cells[CUTTER_REGISTER] = float(offset)
    run.output.output(block)


HANDLERS = {"CUTCOM": cutcom}


def compensation_off(run: Post, record: int) -> None:
    """G40 in a block of its own (TABLEG 40)."""
    code = run.machine.g_code(CUTCOM_CELLS["OFF"])
    run.state.modes.compensation = ""
    if code is None:
        return
    block = Block(Code.G_ONLY, record)
    block.cells[2] = code
    run.output.output(block)
