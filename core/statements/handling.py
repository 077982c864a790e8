"""Tool handling at the home position and the positioning mode: GOHOME, LOAD/TOOL (LOADGM,
GEMAXS, 001 L33878-33925), PICKUP (PKUPGP, GEPOS, L34568-34610), UNLOAD (UNLDGP, GEPOS,
L39947-39988) and POSITN (PSTNGP, GEPOS, L34880-34932); spec 08 §2.22, §2.27, §2.29, §2.53.

* **GOHOME** moves the slides to the home position, options 184-190 in machine coordinates
  and CL order (L26455-26500): DEPART, SEGMNT and OUTPUT (L20693-20697, L21659), at the
  feed in force or at rapid after RAPID, never linearity tested (GOHOME calls no LINRTY);
  on a positioning machine a POSMOV to the home positions, with no cycle.
* **LOAD/TOOL, n[, SMALL|LARGE][, LENGTH, l]** on a multiaxis machine: the machine's
  MACFUN first (MCHCON 6, option 133), then GOHOME, then the load G code TABLEG(26-29) of
  the head and gripper with T = n in a CODE -4 block; the loaded tool's R + TL come from
  the class (MAFORK = 0): R options 102-105 by head and gripper, TL the length. On a
  positioning machine LOAD/TOOL, n[, OFSETL, k][, LENGTH, l] is TOOLNO's tool change.
* **PICKUP** and **UNLOAD** on a positioning machine: the tool's load (TABLEG 24, else the
  cycle-off G and TABLEM 32) and unload (TABLEG 26 with T, else the cycle-off G and
  TABLEM 33) codes, with comment 40 when the magazine is not at the tool's pocket.
* **POSITN/OFF** outputs TABLEG(60) (CODE -4) and sets MODPOS 0; FINE, NOBACK, COARSE
  and CORMIL set MODPOS 1-4 and output nothing; TRAV makes the mode in force negative.
  Each later positioning move with no cycle carries the mode's G code (SET12,
  core/motion/positioning.py), which the machine must have.

The readings of the manual these need are in docs/decisions.md ("LOAD, PICKUP, UNLOAD,
GOHOME, POSITN").
"""

from __future__ import annotations

from dataclasses import replace
from math import radians, sqrt
from typing import TYPE_CHECKING, Any, Protocol, runtime_checkable

from gecent.core.cl.records import Motion, MotionSubtype, Statement, Word
from gecent.core.errors import Diagnostic, InputError
from gecent.core.families import HookPoint
from gecent.core.machine.definition import ROTARY_CELLS
from gecent.core.motion.linear import path_length
from gecent.core.motion.mixed import enter_way, is_mixed
from gecent.core.motion.positioning import CORNER_MILLING_G, MODE_G, set12
from gecent.core.motion.rounding import to_steps
from gecent.core.output.block import Block, Code
from gecent.core.statements.spindle_tool import rotate

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post
    from gecent.core.motion.multiaxis import MultiaxisMotion

HOME_LINEAR = (184, 185, 186)  # X, Y, Z (machine coordinates, CL order)
HOME_ROTARY = (187, 188, 189, 190)  # rotary head, rotary table, third rotary, secondary
HOME_AXIS_NAMES = {189: "third rotary axis", 190: "secondary axis"}
CYCLE_OFF = 1  # TABLEG(1)
SELECT_TOOL_G = 24  # TABLEG(24): PICKUP's G code
LOAD_TOOL_G = 26  # TABLEG(26): head 1, small gripper; 27 large; 28, 29 head 2
TOOL_LOAD_M, TOOL_UNLOAD_M = 32, 33  # TABLEM
POSITIONING_OFF_G = 60  # TABLEG(60)
T_REGISTER = 13
WRONG_POCKET = "ATTEMPTING TO UNLOAD TOOL IN WRONG MAGAZINE POCKET."  # comment 40
MODES = {"OFF": 0, "FINE": 1, "NOBACK": 2, "COARSE": 3, "CORMIL": 4}


class _Hooks(Protocol):
    def macfun(self, hook: HookPoint, **fields: Any) -> bool: ...


class _Engine(Protocol):
    """The macro engine's MACFUN call (core/macros/events.py)."""

    @property
    def hooks(self) -> _Hooks: ...


@runtime_checkable
class _Macros(Protocol):
    """A run that may have a macro engine, with the machine's MACFUN (core/run.py's)."""

    @property
    def macros(self) -> _Engine | None: ...


# -- GOHOME ------------------------------------------------------------------------------


def gohome(run: Post, statement: Statement) -> None:
    """GOHOME: the slides to the home position (options 184-190)."""
    if statement.args:
        raise InputError("GOHOME takes no values (options 184-190 give home)", statement.where)
    _go_home(run, statement, None)


def _go_home(run: Post, statement: Statement, target: list[float | None] | None) -> None:
    """The move home; ``target``: the machine point a machine's MACFUN put in DPRESM
    instead (LOAD's change point), X, Y, Z and the class's rotary axes in CL order, None
    for an axis it left where it is."""
    machine = run.machine
    where = statement.where
    if not run.state.position.from_given:
        raise InputError(
            f"{statement.major} before any FROM: the slides' position, which the move home "
            "starts from, is not known",
            where,
        )
    home: list[float | None] = (
        [machine.number_option(n) for n in HOME_LINEAR + HOME_ROTARY]
        if target is None
        else target + [None] * (len(HOME_LINEAR + HOME_ROTARY) - len(target))
    )
    if machine.multiaxis:
        _multiaxis_home(run, run.multiaxis, statement, home)
        return
    devices = _rotary_devices_home(run, statement, home[3:])
    if machine.number_option(1) != 0:
        _positioning_home(run, statement, home)
    else:
        _contouring_home(run, statement, home)
    for device, angle in devices:
        # ROTABL's own turn, as ROTATE/device,ATANGL,angle (the shorter way)
        turn = (Word(device, None), Word("ATANGL", None), angle)
        rotate(run, replace(statement, major="ROTATE", code=None, args=turn))


def _contouring_home(run: Post, statement: Statement, home: list[float | None]) -> None:
    """DEPART-SEGMNT-OUTPUT to home on a machine without a transform class: its machine
    point is the CL point plus TRANS."""
    position = run.state.position
    point = tuple(
        (position.present_part[axis] if value is None else value) - position.translation[axis]
        for axis, value in enumerate(home[:3])
    )
    leg = Motion(statement.file, statement.line, statement.number, MotionSubtype.GOTO, (point,))
    _rapid_if_asked(run, path_length(run.state.position, leg))
    run.motion.record(leg)


def _positioning_home(run: Post, statement: Statement, home: list[float | None]) -> None:
    """POSMOV to the home point: the punched positions are the machine's, so the CL point
    is home less TRANS and less the Z adjustment POSMOV makes (options 140 and 86 < 0).
    The move has no cycle (a hole at home would be drilled) and follows option 130; a
    RAPID before it, or rapid in force, takes it at rapid (POSMOV's own TSTFLG)."""
    motion = run.positioning
    if is_mixed(run.machine):
        enter_way(run.state, motion, True)  # the 7500: home is a positioning move
    position = run.state.position
    point = [
        (position.present_part[axis] if value is None else value) - position.translation[axis]
        for axis, value in enumerate(home[:3])
    ]
    point[2] -= motion._z_shift()  # (its adjustment of Z, undone: home is the machine's)
    leg = Motion(
        statement.file, statement.line, statement.number, MotionSubtype.GOTO, (tuple(point),)
    )
    motion.record(leg, None)


def _rotary_devices_home(
    run: Post, statement: Statement, homes: list[float | None]
) -> list[tuple[str, float]]:
    """The rotary devices GOHOME turns on a machine without a transform class: ROTATE's
    head (option 187) and table (option 188), each whose home the machine file sets (a
    home of 0 is the reading they start at). Options 189 and 190 home the third rotary
    and the secondary axis, which only a transform class has (docs/decisions.md, issue 22 wave 9;
    001 L26478-26500)."""
    machine = run.machine
    for number, value in zip(HOME_ROTARY[2:], homes[2:], strict=False):
        if value:
            raise InputError(
                f"GOHOME: option {number} = {value:g} homes the "
                f"{HOME_AXIS_NAMES[number]}, which machine {machine.label} does not have: "
                "it is an axis of a transform class (option 116 = 0 here; 001 L26490-26500)",
                statement.where,
            )
    devices = [
        (name, float(value))
        for name, value in zip(("HEAD", "TABLE"), homes[:2], strict=False)
        if value
    ]
    formats = machine.registers.formats
    if devices and formats[ROTARY_CELLS[0]] is None and formats[ROTARY_CELLS[1]] is None:
        numbers = ", ".join(f"option {187 if n == 'HEAD' else 188}" for n, _ in devices)
        raise InputError(
            f"GOHOME: {numbers} gives a rotary home, but machine {machine.label} has no "
            "rotary register (DBFSEG 6 or 7) to turn it with (001 L26478-26489)",
            statement.where,
        )
    return devices


def _rapid_if_asked(run: Post, length: float) -> None:
    """TSTFLG: a RAPID given before GOHOME (or rapid in force) takes it at rapid."""
    feed = run.state.feed
    if feed.rapid_requested or feed.rapid_mode:
        run.rapid.motion(length)


def _multiaxis_home(
    run: Post, motion: MultiaxisMotion, statement: Statement, home: list[float | None]
) -> None:
    """DEPART and SEGMNT to the home machine point: the linear axes in steps, each rotary
    axis of the class (head, table, third) the shorter way to its home reading, as GOLINE
    turns them; DPRESP is the home point through the class's inverse (MAFORK = 1)."""
    import numpy as np

    step = run.machine.number_option(14)
    present = run.state.position.present
    linear = [
        present[axis] if value is None else to_steps(value, step)
        for axis, value in enumerate(home[:3])
    ]
    rotary: list[int] = []
    point = np.zeros(6)
    point[0:3] = [steps * step for steps in linear]
    for index, column in enumerate(motion.columns):
        reading = home[3 + index]
        now = motion.angles[index]
        wanted = now if reading is None else reading / motion.per_degree  # degrees
        if column not in motion.limited:
            wanted = now + (wanted - now + 180.0) % 360.0 - 180.0
        motion.angles[index] = wanted
        rotary.append(round(wanted * motion.per_degree / motion.rotary_step))
        point[column] = radians(rotary[-1] * motion.rotary_step / motion.per_degree)
    part = [float(v) for v in motion.transform.inverse(point.reshape(1, 6), motion.kinematics)[0]]
    before = run.state.position.previous_part
    _rapid_if_asked(run, sqrt(sum((part[a] - before[a]) ** 2 for a in range(3))))
    record = Motion(statement.file, statement.line, statement.number, MotionSubtype.GOTO, ())
    # the element's own DEPART-SEGMNT-OUTPUT, for a machine point given, not a CL point
    motion._reach(record, (part[0], part[1], part[2], part[3], part[4], part[5]), linear, rotary)
    motion.machine_raw = point
    motion.machine_previous = point.reshape(1, 6)
    motion.tool_axis = (part[3], part[4], part[5])
    motion.singular = False


# -- LOAD --------------------------------------------------------------------------------


def load(run: Post, statement: Statement) -> None:
    """LOAD/TOOL, n[, SMALL|LARGE][, LENGTH, l] (LOADGM)."""
    machine = run.machine
    where = statement.where
    if not machine.multiaxis and machine.number_option(1) != 0:
        _positioning_load(run, statement)
        return
    if not machine.multiaxis:
        # GECENT's LOAD is LOADGM, the multiaxis one (GEMAXS): the manual restricts it to
        # a machine with a transform class; a contouring tool change is LOADTL or TOOLNO
        raise InputError(
            f"LOAD/TOOL on machine {machine.label}, a contouring machine without a transform "
            'class: LOAD is the multiaxis tool change (LOADGM), and "OPTAB(116) must be set '
            'to a value" (001 L33878-33925, L33922); give the tool change as LOADTL/n or '
            "TOOLNO/n",
            where,
        )
    tool, large, length = _load_arguments(statement)
    if not run.state.position.from_given:
        raise InputError("LOAD/TOOL before any FROM: a FROM must come first", where)
    motion = run.multiaxis
    position = run.state.position
    before = list(position.present)
    engine = run.macros if isinstance(run, _Macros) else None
    if engine is not None and engine.hooks.macfun(
        HookPoint.LOAD, record=statement, values=statement.numbers(), words=statement.words()
    ):
        return  # (RETURN = 1: the machine's own load sequence did it all)
    target: list[float | None] | None = None
    if list(position.present) != before:  # (RETURN = 0 with DPRESM set: the change point)
        step = machine.number_option(14)
        target = [
            None if now == was else now * step
            for now, was in zip(position.present, before, strict=True)
        ]
        position.present[:] = before
    _go_home(run, statement, target)
    head = 2 if run.state.head == 2 else 1
    cell = LOAD_TOOL_G + 2 * (head - 1) + int(large)
    code = machine.g_code(cell)
    if code is None:
        gripper = "large" if large else "small"
        raise InputError(
            f"LOAD/TOOL with head {head}'s {gripper} gripper: machine {machine.label} has no "
            f"load code for it (TABLEG({cell}))",
            where,
        )
    block = Block(Code.G_ONLY, statement.number)
    block.cells[2] = float(code)
    if machine.registers.formats[T_REGISTER] is not None:
        block.cells[T_REGISTER] = float(tool)
    run.output.output(block)
    loaded = run.state.tool
    loaded.number = tool
    loaded.large_gripper = large
    if length is not None:
        loaded.length = run.units.length(length)
    _new_constants(run, motion)


def _positioning_load(run: Post, statement: Statement) -> None:
    """LOAD/TOOL, n[, OFSETL, k][, LENGTH, l] on a positioning machine: the tool change
    TOOLNO makes (TOOLGP), as options 86 and 96 name LOAD/TOOL beside TOOLNO (001
    L25406-25434, L25526-25530); the machine's MACFUN LOAD (MCHCON 6) comes first."""
    args = statement.args
    if not args or not isinstance(args[0], Word) or args[0].name != "TOOL":
        raise InputError(
            "LOAD expects LOAD/TOOL, n[, OFSETL, k][, LENGTH, l] on a positioning machine",
            statement.where,
        )
    engine = run.macros if isinstance(run, _Macros) else None
    if engine is not None and engine.hooks.macfun(
        HookPoint.LOAD, record=statement, values=statement.numbers(), words=statement.words()
    ):
        return  # (RETURN = 1: the machine's own load sequence did it all)
    run.tool.statement(replace(statement, major="LOAD/TOOL", args=args[1:]))


def _load_arguments(statement: Statement) -> tuple[int, bool, float | None]:
    usage = "LOAD expects LOAD/TOOL, n[, SMALL|LARGE][, LENGTH, l] with n a whole number >= 0"
    args = list(statement.args)
    if len(args) < 2 or not isinstance(args[0], Word) or args[0].name != "TOOL":
        raise InputError(usage, statement.where)
    number = args[1]
    if isinstance(number, Word) or number < 0 or number != int(number):
        raise InputError(usage, statement.where)
    large = False
    length: float | None = None
    rest = args[2:]
    while rest:
        word = rest.pop(0)
        if isinstance(word, Word) and word.name in ("SMALL", "LARGE"):
            large = word.name == "LARGE"
        elif isinstance(word, Word) and word.name == "LENGTH" and rest:
            value = rest.pop(0)
            if isinstance(value, Word) or not value > 0:
                raise InputError("LOAD/TOOL LENGTH expects a length > 0", statement.where)
            length = float(value)
        else:
            raise InputError(usage, statement.where)
    return int(number), large, length


def _new_constants(run: Post, motion: MultiaxisMotion) -> None:
    """MAFORK = 0: the loaded tool's R + TL; the tip of the new tool at the home machine
    point gives DPRESP (MAFORK = 1), so the next move's path starts where the tip is."""
    motion.load_constants()
    import numpy as np

    point = np.array(motion.machine_raw, dtype=float).reshape(1, 6)
    part = [float(v) for v in motion.transform.inverse(point, motion.kinematics)[0]]
    position = run.state.position
    position.present_part[:] = part
    position.previous_part[:] = part


# -- PICKUP, UNLOAD ----------------------------------------------------------------------


def _positioning(run: Post, statement: Statement) -> None:
    if run.machine.number_option(1) not in (1.0, 2.0):
        raise InputError(
            f"{statement.major} belongs to a positioning machine (option 1 = 1 or 2)",
            statement.where,
        )


def pickup(run: Post, statement: Statement) -> None:
    """PICKUP (PKUPGP): the tool at the magazine's pocket goes into the spindle."""
    _positioning(run, statement)
    if statement.args:
        raise InputError("PICKUP takes no values", statement.where)
    machine = run.machine
    state = run.state
    code = machine.g_code(SELECT_TOOL_G)
    if code is not None:
        block = Block(Code.G_ONLY, statement.number)
        block.cells[2] = float(code)
    else:
        m_code = machine.m_code(TOOL_LOAD_M)
        if m_code is None:
            raise InputError(
                f"PICKUP: machine {machine.label} has no tool-load code: TABLEM(32) or "
                "TABLEG(24) must be set",
                statement.where,
            )
        block = _cycle_off_block(run, statement)
        run.output.store_m(m_code)
    state.tool.ready_to_unload = int(state.tool.number) if state.tool.number is not None else 0
    run.output.output(block)


def unload(run: Post, statement: Statement) -> None:
    """UNLOAD (UNLDGP): the spindle's tool back into the magazine's pocket."""
    _positioning(run, statement)
    if statement.args:
        raise InputError("UNLOAD takes no values", statement.where)
    machine = run.machine
    tool = run.state.tool
    in_spindle = tool.ready_to_unload or 0
    if in_spindle != (run.tool.position or 0):
        run.warn(Diagnostic(WRONG_POCKET, statement.where))
    code = machine.g_code(LOAD_TOOL_G)
    if code is not None:
        block = Block(Code.G_ONLY, statement.number)
        block.cells[2] = float(code)
        if machine.registers.formats[T_REGISTER] is not None:
            block.cells[T_REGISTER] = float(in_spindle)
    else:
        m_code = machine.m_code(TOOL_UNLOAD_M)
        if m_code is None:
            raise InputError(
                f"UNLOAD: machine {machine.label} has no tool-unload code: TABLEM(33) or "
                "TABLEG(26) must be set",
                statement.where,
            )
        block = _cycle_off_block(run, statement)
        run.output.store_m(m_code)
    tool.ready_to_unload = None
    run.output.output(block)


def _cycle_off_block(run: Post, statement: Statement) -> Block:
    """A CODE -1 block with the cycle-off G code TABLEG(1), when the machine has one."""
    block = Block(Code.AUX_ONLY, statement.number)
    cycle_off = run.machine.g_code(CYCLE_OFF)
    if cycle_off is not None:
        block.cells[2] = float(cycle_off)
    return block


# -- POSITN ------------------------------------------------------------------------------


def positn(run: Post, statement: Statement) -> None:
    """POSITN/OFF|FINE|NOBACK|COARSE|CORMIL|TRAV (PSTNGP): MODPOS."""
    _positioning(run, statement)
    words = statement.words()
    if len(statement.args) != 1 or len(words) != 1 or words[0] not in (*MODES, "TRAV"):
        raise InputError(
            "POSITN expects one of OFF, FINE, NOBACK, COARSE, CORMIL, TRAV", statement.where
        )
    modes = run.state.modes
    mode = words[0]
    if mode == "TRAV":
        modes.positioning = -abs(modes.positioning)
        set12(run.state, statement.where)  # (the machine must have the traverse code)
        return
    if mode != "OFF":
        _require_mode_codes(run, statement, mode)
        modes.positioning = MODES[mode]
        return
    code = run.machine.g_code(POSITIONING_OFF_G)
    if code is None:
        raise InputError(
            f"POSITN/OFF: machine {run.machine.label} has no positioning-off code "
            "(TABLEG(60); TABLEG 52-62 must be set)",
            statement.where,
        )
    modes.positioning = MODES[mode]
    block = Block(Code.G_ONLY, statement.number)
    block.cells[2] = float(code)
    run.output.output(block)


def _require_mode_codes(run: Post, statement: Statement, mode: str) -> None:
    """The codes the mode's moves take ("TABLEG(52-62) must be set", L34929-34932):
    CORMIL's of both feed ranges on a machine with two (option 18)."""
    if mode == "CORMIL":
        ranges = 2 if run.machine.number_option(18) >= 2 else 1
        locations = [CORNER_MILLING_G[r] for r in range(1, ranges + 1)]
    else:
        locations = [MODE_G[MODES[mode]]]
    for location in locations:
        if run.machine.g_code(location) is None:
            raise InputError(
                f"POSITN/{mode}: machine {run.machine.label} has no positioning-mode code "
                f"TABLEG({location}) (POSITN needs TABLEG 52-62)",
                statement.where,
            )


HANDLERS = {
    "GOHOME": gohome,
    "LOAD": load,
    "PICKUP": pickup,
    "UNLOAD": unload,
    "POSITN": positn,
}
