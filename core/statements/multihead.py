"""The multihead statements of the first pass (manual §3.4.8.1, 001 L7208-7268, L2214-2300):
COMBIN/n, OP/n and PRFSEQ/ON|OFF. SELECT/HEAD,n is routed by the first pass itself
(core/multihead/first_pass.py): it decides which head's run a record goes to.

OP/n and PRFSEQ make the CODE 17 information blocks the merge pass sequences on. The Part
Programmer's Manual that gives OP's full syntax is not in the seeds; gecent reads
``OP/n[,RPM|SFM,t1,t2][,NONE]`` (docs/decisions.md): t1 is the spindle-speed tolerance and
t2 the feedrate tolerance, in percent, within which the two heads may cut together.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import FatalError, InputError
from gecent.core.output.block import Block, Code
from gecent.core.statements.safety import single_head_safety

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post

# DBFSEG(11) of a CODE 17 block (001 L7236-7240, L7259-7264, L7336-7340)
OP_RESTRICTED, OP_SAFETY, OP_NONE, OP_PREFERRED, OP_SFM = 0, 1, 2, 3, 4
MAX_HEADS = 2  # the merge pass GEMULT reads two scratch tapes (TAPES2, TAPES3)


def _head(run: Post, statement: Statement, what: str) -> int:
    head = run.state.head
    if head == 0:
        raise InputError(
            f"{what} belongs to a multihead program: COMBIN/2 must come first, before the "
            "first motion, on a machine with two heads",
            statement.where,
        )
    return head


def combin(run: Post, statement: Statement) -> None:
    """COMBIN/n (001 L7208-7213): sets MULTHD. The first pass has seen it already (it is
    why there are two heads' runs); a COMBIN any run meets later is the same request."""
    args = statement.args
    if len(args) != 1 or isinstance(args[0], Word) or args[0] != MAX_HEADS:
        raise InputError(
            f"COMBIN expects the number of heads, {MAX_HEADS} (GEMULT merges two)",
            statement.where,
        )
    if run.state.head == 0:
        if len(run.machine.heads) < MAX_HEADS:
            raise InputError(
                f"COMBIN on machine {run.machine.label}, which has one head (its machine "
                "file has no [heads.2] register table)",
                statement.where,
            )
        raise InputError(
            "COMBIN after the first motion record: the multihead environment is set up at "
            "the start of the program (001 L7170-7176)",
            statement.where,
        )


def op(run: Post, statement: Statement) -> None:
    """OP/n (OPCODE, 001 L7218-7250): the operation number the merge pass compares; blocks
    of both heads under equal numbers are cut together."""
    head = _head(run, statement, "OP")
    args = list(statement.args)
    usage = "OP expects OP/n[,RPM|SFM,t1,t2][,NONE] with n a whole number above 0"
    number = args.pop(0) if args else None
    if number is None or isinstance(number, Word) or number != int(number) or number < 1:
        raise InputError(usage, statement.where)
    if number < run.state.multihead_op:
        raise FatalError(
            1020,
            f"OP/{number:g} after OP/{run.state.multihead_op} on head {head}",
            statement.where,
        )
    block = Block(Code.MULTIHEAD_1, statement.number)
    cells = block.cells
    cells[2] = float(number)
    cells[8] = float(head)
    cells[11] = float(OP_RESTRICTED)
    if args and isinstance(args[-1], Word) and args[-1].name == "NONE":
        cells[11] = float(OP_NONE)
        args.pop()
    if args:
        mode = args[0]
        numbers = args[1:]
        if (
            not isinstance(mode, Word)
            or mode.name not in ("RPM", "SFM")
            or len(numbers) != 2
            or any(isinstance(t, Word) or t < 0 for t in numbers)
        ):
            raise InputError(usage + " (tolerances in percent, 0 or more)", statement.where)
        cells[7] = 1.0 if mode.name == "RPM" else 0.0
        spindle, feed = (t for t in numbers if not isinstance(t, Word))
        cells[9], cells[10] = float(spindle), float(feed)
    cells[15] = float(Code.MULTIHEAD_1)
    run.state.multihead_op = int(number)
    run.output.emit(block)


def prfseq(run: Post, statement: Statement) -> None:
    """PRFSEQ/ON|OFF (001 L7251-7268): the head with priority where the heads' shared
    items (spindle speed, feed register) differ: this head (ON) or the other (OFF)."""
    head = _head(run, statement, "PRFSEQ")
    words = statement.words()
    if len(statement.args) != 1 or words not in (("ON",), ("OFF",)):
        raise InputError("PRFSEQ expects ON or OFF", statement.where)
    block = Block(Code.MULTIHEAD_1, statement.number)
    block.cells[2] = float(run.state.multihead_op)
    block.cells[8] = float(head if words == ("ON",) else MAX_HEADS + 1 - head)
    block.cells[11] = float(OP_PREFERRED)
    block.cells[15] = float(Code.MULTIHEAD_1)
    run.output.emit(block)


def safety(run: Post, statement: Statement) -> None:
    """SAFETY/dx,dy,dz on a multihead machine (SAFEGM, 001 L36514-36545; SAFHD1/SAFHD2,
    L7341-7346): the departures that withdraw this head from the work when it is parked,
    in a CODE 17 information block (DBFSEG(11) = 1). A single-head run's SAFETY (the
    lathe's FACE, TURN, BORE; the R register) is core/statements/safety.py's."""
    if run.state.head == 0:
        single_head_safety(run, statement)
        return
    args = statement.args
    if len(args) != 3 or any(isinstance(a, Word) for a in args):
        raise InputError(
            "SAFETY on a multihead program expects the head's withdrawal departures dx, dy, dz",
            statement.where,
        )
    half_step = run.machine.number_option(14) / 2.0
    if all(abs(run.units.length(float(value))) < half_step for value in args):  # type: ignore[arg-type]
        raise InputError(
            "SAFETY does not withdraw the head (its departures are less than a step): give "
            "its departures out of the work",
            statement.where,
        )
    common = int(run.machine.number_option(155))
    if common in (1, 2, 3) and args[common - 1] != 0:
        raise InputError(
            f"SAFETY withdraws head {run.state.head} along the heads' common axis "
            f"({'XYZ'[common - 1]}, option 155), which would move the other head with it",
            statement.where,
        )
    block = Block(Code.MULTIHEAD_1, statement.number)
    block.cells[2] = float(run.state.multihead_op)
    for axis, value in enumerate(args):
        block.cells[3 + axis] = run.units.length(float(value))  # type: ignore[arg-type]
    block.cells[8] = float(run.state.head)
    block.cells[11] = float(OP_SAFETY)
    block.cells[15] = float(Code.MULTIHEAD_1)
    run.output.emit(block)


HANDLERS = {"COMBIN": combin, "OP": op, "PRFSEQ": prfseq, "SAFETY": safety}
