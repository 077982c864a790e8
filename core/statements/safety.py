"""SAFETY on a single-head machine: the lathe's safety modes (SAFEGL, GELATH) and the
R-register safety code (SAFEGX, GEMAXS). The multihead SAFETY (SAFEGM's withdrawal
record) is core/statements/multihead.py's; it hands a single-head run's SAFETY here.

The routine the run uses is the one the machine's overlay holds (AUXLRY, spec 08 §1.9):

* a lathe (option 132 = 0), SAFEGL: SAFETY/TURN, FACE, BORE or OFF. Its M code is
  TABLEM(37) "Safety Turn", (38) "Safety Face", (39) "Safety Bore" and (40) "Safety Off"
  (001 L23200-23206); the mode is ISAFMD (L17549-17561), and option 21 says whether it is
  modal (1) or one-shot (0: "applies only to first motion statement after a safety
  statement", L24633-24644). SAFEGL calls STOREM (L20949-20951): the code waits for the
  next block, the first motion's, where TSTFLG's SAFETO would put it (L38926-38959).
  One-shot, TSTFLG's SAFETX (called before each motion, as RAPIDX ends a one-shot rapid,
  L11848-11870) stores the off code TABLEM(40) for the second motion: :func:`safety_motion`,
  which core/run.py calls before each motion record (the fast path stays off meanwhile).
* a multiaxis machine (option 116 ≠ 0, which loads GEMAXS, L444), SAFEGX
  (L36554-36611): SAFETY/dx,dy,dz as a three-digit code in DBFSEG(16), one digit per
  axis X, Y, Z: 0 none, 1 +.01 in, 2 -.01, 3 +.10, 4 -.10, 5 +1.0, 6 -1.0, one magnitude
  in a statement; SAFETY/OFF sets DBFSEG(16) to zero "and nothing else is done".

Any other single-head machine (a mill, a positioning machine, ...) has no SAFETY of its
own: its overlay's SAFEGM (GEMILL, "the SAFETY statement for multihead milling machines",
L36514-36545) writes the withdrawal record only the multihead merge pass reads, so there
the statement is bad input pointing to COMBIN/2.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.cl.records import Motion, MotionSubtype, Statement, Word
from gecent.core.errors import InputError, MachineDefinitionError
from gecent.core.output.block import Block, Code

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post

LATHE = 0  # option 132, the machine type (001 L25946-25961)
# TABLEM cells of the lathe's safety codes (001 L23200-23206, spec 07 §4.3)
SAFETY_CELLS = {"TURN": 37, "FACE": 38, "BORE": 39, "OFF": 40}
ONE_SHOT, MODAL = 0, 1  # option 21
# a one-shot SAFETY's motions still to come when the statement is read: the first carries
# the mode's code, the second the off code (Post.safety_motions counts them down)
ONE_SHOT_MOTIONS = 2
R_REGISTER = 16  # SAFEGX: the code goes into DBFSEG(16)
# SAFEGX's table: the magnitude's digit for a plus move; the minus move's is one more
R_DIGITS = {0.01: 1, 0.1: 3, 1.0: 5}
MM_PER_INCH = 25.4


def single_head_safety(run: Post, statement: Statement) -> None:
    """SAFETY where the program is not a multihead one."""
    machine = run.machine
    if machine.number_option(132) == LATHE:
        lathe_safety(run, statement)
    elif machine.multiaxis:
        r_register_safety(run, statement)
    else:
        # the manual defines no single-head SAFETY here: the overlay's SAFEGM writes a
        # record only the multihead merge pass reads (001 L7336-7346, L36514-36545)
        raise InputError(
            f"SAFETY on machine {machine.label}, a single-head machine that is neither a lathe "
            "(option 132 = 0) nor multiaxis (option 116): the manual's SAFETY there is a "
            "multihead program's withdrawal departures (SAFEGM), so COMBIN/2 must come "
            "first, before the first motion, on a machine with two heads",
            statement.where,
        )


def lathe_safety(run: Post, statement: Statement) -> None:
    """SAFEGL: SAFETY/TURN|FACE|BORE|OFF, the mode's M code waiting for the next block."""
    words = statement.words()
    if len(statement.args) != 1 or len(words) != 1 or words[0] not in SAFETY_CELLS:
        raise InputError(
            "SAFETY on a lathe expects one of TURN, FACE, BORE or OFF", statement.where
        )
    mode = words[0]
    machine = run.machine
    kind = machine.number_option(21)
    if kind not in (ONE_SHOT, MODAL):
        raise MachineDefinitionError(
            machine.origin,
            "optab",
            21,
            f"option 21 = {kind:g}: SAFETY is one-shot (0) or modal (1) (001 L24633-24644)",
        )
    code = run.output.store_cell(SAFETY_CELLS[mode], run.warn, statement.where)
    # one-shot: SAFETX's off code at the second motion; a mode whose code the machine
    # lacks (comment 22) was never turned on, and OFF or a new mode ends the count
    armed = mode != "OFF" and kind == ONE_SHOT and code is not None
    run.safety_motions = ONE_SHOT_MOTIONS if armed else 0


def safety_motion(run: Post, record: Motion) -> None:
    """TSTFLG before a motion record while a one-shot SAFETY counts down (SAFETO,
    SAFETX, 001 L38926-38959): the first motion carries the mode's code (STOREM'd by the
    statement); before the second, the safety off code TABLEM(40) is stored to ride it. A
    FROM is no motion here, as for a one-shot rapid."""
    if record.subtype is MotionSubtype.FROM:
        return
    run.safety_motions -= 1
    if run.safety_motions == 0:
        run.output.store_cell(SAFETY_CELLS["OFF"], run.warn, record.where)


def r_register_safety(run: Post, statement: Statement) -> None:
    """SAFEGX: SAFETY/dx,dy,dz as the R code in a block of its own; SAFETY/OFF sets it to
    zero and outputs nothing."""
    machine = run.machine
    where = statement.where
    args = statement.args
    if len(args) == 1 and isinstance(args[0], Word) and args[0].name == "OFF":
        return  # "DBFSEG(16) is set to zero and nothing else is done"
    usage = (
        "SAFETY on a multiaxis machine expects OFF or the moves dx, dy, dz, each 0 or "
        "one of +-.01, +-.1, +-1.0 inch, one size in a statement (SAFEGX)"
    )
    if len(args) != 3 or any(isinstance(a, Word) for a in args):
        raise InputError(usage, where)
    if machine.registers.formats[R_REGISTER] is None:
        raise InputError(
            f"SAFETY: machine {machine.label} has no R register (REGFOR({R_REGISTER})) for "
            "the safety code (SAFEGX is for machines that have it)",
            where,
        )
    inches = [run.units.length(float(a)) * run.units.machine_mm / MM_PER_INCH for a in args]  # type: ignore[arg-type]
    code = r_code(inches)
    if code is None:
        raise InputError(usage, where)
    if code == 0:
        raise InputError("SAFETY/0,0,0 moves no axis: SAFETY/OFF cancels the code", where)
    block = Block(Code.NONMOTION, statement.number)
    block.cells[R_REGISTER] = float(code)
    run.output.output(block)


def r_code(moves: list[float]) -> int | None:
    """SAFEGX's three digits for the moves X, Y, Z in inches (W-4: X +.1, Y 0, Z -.1 ->
    304); None when a move is not in the table or two sizes are mixed."""
    digits = []
    sizes = set()
    for move in moves:
        if abs(move) < 1e-9:
            digits.append(0)
            continue
        size = next((s for s in R_DIGITS if abs(abs(move) - s) < 1e-6), None)
        if size is None:
            return None
        sizes.add(size)
        digits.append(R_DIGITS[size] + (1 if move < 0 else 0))
    if len(sizes) > 1:
        return None  # "only one of the three values given (.01, .1, 1.0)"
    return digits[0] * 100 + digits[1] * 10 + digits[2]
