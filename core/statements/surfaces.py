"""The clearance surface and the positioning words around it, and the values kept for later
processing: CLRSRF (CLRSGP, 001 L29442-29470), RETRCT (RTRCGP, L35647-35692), XOFSET
(XOFSET, L40092-40130) and OVRCNT (OVRCNT, L34364-34400). (MCHTOL, the A/D tolerance, is
A/D's own: core/feed/accel.py.)

CLRSRF and OVRCNT only keep a value (CLERP, OVCVAL); RETRCT raises the tool to the CLRSRF
height in a Z-only block (CODE -16), at rapid when RAPIDO allows it; XOFSET puts an
X-offset number in a cycle-off block (CODE +1). RETRCT and XOFSET are routines of the
positioning overlay (GEPOS): a contouring machine refuses them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.absent import ABSENT
from gecent.core.cl.records import Statement, Word
from gecent.core.errors import InputError
from gecent.core.motion.rounding import to_steps
from gecent.core.output.block import Block, Code

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post

Z = 2
Z_REGISTER = 5
X_OFFSET_REGISTER = 17  # DBFSEG(17): "the X offset number" (001 L40097-40105)
# the words of an APT plane CLRSRF/a,b,c,d (the plane a x + b y + c z = d)
PLANE_VALUES = 4


def positioning_machine(run: Post) -> bool:
    """GEPOS is loaded for option 1 = 1, 2 or -1 (positioning; 001 L385-389, L24300)."""
    return run.machine.number_option(1) in (1.0, 2.0, -1.0)


def require_positioning(run: Post, statement: Statement, routine: str) -> None:
    if not positioning_machine(run):
        raise InputError(
            f"{statement.major} is a positioning-machine statement ({routine}, overlay GEPOS: "
            f"option 1 = 1 or 2); this machine has option 1 = "
            f"{run.machine.number_option(1):g}",
            statement.where,
        )


def clrsrf(run: Post, statement: Statement) -> None:
    """CLRSRF/z, or the plane CLRSRF/a,b,c,d of a Z level (a = b = 0): CLERP, the height
    RETRCT goes to. Nothing is output."""
    numbers = statement.numbers()
    if len(numbers) != len(statement.args) or len(numbers) not in (1, PLANE_VALUES):
        raise InputError(
            "CLRSRF expects the clearance height z, or a plane a,b,c,d normal to Z",
            statement.where,
        )
    if len(numbers) == 1:
        height = numbers[0]
    else:
        a, b, c, d = numbers
        if a != 0 or b != 0 or c == 0:
            raise InputError(
                "CLRSRF: the clearance surface must be a plane normal to Z (RETRCT moves Z only)",
                statement.where,
            )
        height = d / c
    run.state.clearance_plane = run.units.length(height)


def retrct(run: Post, statement: Statement) -> None:
    """RETRCT: Z = CLRSRF + TRANS z in a block by itself (CODE -16), at rapid (RAPFLG,
    RAPIDO) unless the move is too short for a rapid, then at option 39's feed. The present
    point's Z becomes the clearance height (DPREVP(3), CURNTZ)."""
    if statement.args:
        raise InputError("RETRCT takes no arguments", statement.where)
    require_positioning(run, statement, "RTRCGP")
    state = run.state
    if state.clearance_plane is None:
        raise InputError("RETRCT needs a CLRSRF statement before it", statement.where)
    machine = run.machine
    if machine.registers.formats[Z_REGISTER] is None or machine.number_option(130) == 0:
        raise InputError(
            "RETRCT needs a programmable Z (a Z register, and option 130 = +1 or -1)",
            statement.where,
        )
    step = machine.number_option(14)
    position = state.position
    # the CL height as POSMOV makes it: TRANS added, option 140's inversion taken off
    height = state.clearance_plane + position.translation[Z] - machine.number_option(140)
    target = to_steps(height, step)
    departure = target - position.previous[Z]
    run.rapid.request()  # RAPFLG = 1, then RAPIDO for this move (TSTFLG's part)
    run.rapid.motion(abs(departure) * step)
    block = Block(Code.POSITION_Z, statement.number)
    block.cells[Z_REGISTER] = target * step
    reached = (position.previous[0], position.previous[1], target)
    block.position = reached
    block.steps = (0, 0, departure)
    block.rapid = bool(state.feed.rapid_ipm)
    position.previous[Z] = position.present[Z] = target
    position.previous_part[Z] = position.present_part[Z] = height
    _control_holds_z(run, target)
    run.output.output(block)


def _control_holds_z(run: Post, target: int) -> None:
    """The positioning element leaves out a Z the control already holds; after RETRCT the
    control holds the clearance height, so a move back down must output its Z."""
    element = getattr(run, "positioning", None)  # (the run's POSMOV; not part of Post)
    if element is not None:
        element.held[Z] = target


def xofset(run: Post, statement: Statement) -> None:
    """XOFSET/n: a cycle-off block (G = TABLEG(1)) with the offset number n in DBFSEG(17),
    output as a CODE +1 block. The machine needs a register for it."""
    numbers = statement.numbers()
    if len(statement.args) != 1 or len(numbers) != 1:
        raise InputError("XOFSET expects one offset number", statement.where)
    number = numbers[0]
    if number != int(number) or number < 0:
        raise InputError("XOFSET expects a whole offset number >= 0", statement.where)
    require_positioning(run, statement, "XOFSET")
    if run.machine.registers.formats[X_OFFSET_REGISTER] is None:
        raise InputError(
            "XOFSET: this machine has no register for the X offset number (REGSTR 17)",
            statement.where,
        )
    block = Block(Code.NONMOTION, statement.number)
    cycle_off = run.machine.g_code(1)
    block.cells[2] = ABSENT if cycle_off is None else float(cycle_off)
    block.cells[X_OFFSET_REGISTER] = number
    run.output.output(block)


def ovrcnt(run: Post, statement: Statement) -> None:
    """OVRCNT/n | ON | OFF: OVCVAL = n; OFF sets it to 0; ON puts the last n back."""
    args = statement.args
    state = run.state
    if len(args) == 1 and isinstance(args[0], Word) and args[0].name in ("ON", "OFF"):
        state.overcenter = state.overcenter_given if args[0].name == "ON" else 0.0
        return
    if len(args) != 1 or isinstance(args[0], Word):
        raise InputError("OVRCNT expects a value n, ON or OFF", statement.where)
    state.overcenter = state.overcenter_given = run.units.length(float(args[0]))


HANDLERS = {
    "CLRSRF": clrsrf,
    "RETRCT": retrct,
    "XOFSET": xofset,
    "OVRCNT": ovrcnt,
}
