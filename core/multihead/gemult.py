"""The merge pass GEMULT (manual §3.4.8.2, 001 L7298-7359, L2214-2300): the two scratch
tapes are read back block by block; a head's blocks go out alone until both heads stand at
an OP/n block; equal operation numbers start a combined section, in which the heads' moves
are cut together, unequal ones send the head with the lower number on alone.

Inside a section (§3.4.8.2.1) lines, dwells and circles merge; any other block goes out
alone as it is met. With a feedrate register per head (option 139 != 0, 001 L2040-2075)
nothing is split: both heads' first moves go out together, then each head's moves alone,
always the head that has cut the shorter time, and together again where the two heads'
summed times meet. With one feedrate register every combined block needs equal times on
both heads: the longer move is split (core/multihead/split.py, SPLIT and CIRSEG).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass

from gecent.core.errors import Diagnostic, InputError, NotYetSupported, SourcePosition
from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.linear import TWO_AXIS
from gecent.core.multihead.dump import ScratchTape
from gecent.core.multihead.equal_time import merge_equal_times
from gecent.core.multihead.gantry import merge_common_axis
from gecent.core.multihead.gmout import GMOUT, mergeable
from gecent.core.output.block import Block, Code
from gecent.core.output.sinks import Sinks
from gecent.core.statements.multihead import OP_PREFERRED, OP_SAFETY, OP_SFM

TIME_EPSILON = 1e-9  # minutes: summed times closer than this have met


@dataclass
class HeadTape:
    """One head's scratch tape being read (CREAD into AS2/AS3). A head's END waits there
    until the other head has come to its own END or its FINI: the ENDs close the program,
    head 1's first (the manual's example, steps O and P, 001 L2263-2300)."""

    head: int
    blocks: Iterator[Block]
    waiting_op: int | None = None  # the OP/n it stopped at (IS23 / IS33)
    op: Block | None = None  # that OP block: its restrictions (RPM/SFM, IPM, NONE)
    finished: bool = False  # its FINI (CODE 18) has been read
    fini: Block | None = None
    held: Block | None = None  # read ahead and put back (the next OP, or the END)
    released: bool = False  # its END may go out

    def next(self) -> Block | None:
        held = self.held
        if held is not None:
            if self.at_end:
                return None
            self.held = None
            return held
        if self.finished:
            return None
        block = next(self.blocks, None)
        if block is None or block.code is Code.FINI:
            self.finished = True
            self.fini = block
            return None
        if block.code is Code.END and not self.released:
            self.held = block
            return None
        return block

    def put_back(self, block: Block) -> None:
        self.held = block

    @property
    def at_end(self) -> bool:
        return self.held is not None and self.held.code is Code.END and not self.released

    @property
    def done(self) -> bool:
        return self.finished and self.held is None

    @property
    def stopped(self) -> bool:
        """Nothing more comes from it until the other head has come to its end."""
        return self.done or self.at_end


class MergePass:
    """GEMULT: sequences the two tapes by OP/n and merges the combined sections."""

    def __init__(
        self,
        machine: MachineDefinition,
        tapes: list[ScratchTape],
        sinks: Sinks,
        warn: Callable[[Diagnostic], None],
    ) -> None:
        value = machine.number_option(155)
        if value not in (0, 1, 2, 3):
            # the option table knows only X, Y and Z (001 L26207-26217): a machine error
            raise InputError(
                f"option 155 = {value:g}: the heads' common axis is 0 (none), 1 (X), 2 (Y) "
                "or 3 (Z)",
                SourcePosition(machine.origin),
            )
        common = int(value)
        self.common_axis = common - 1 if common else None
        if self.common_axis == 2 and machine.number_option(22) in TWO_AXIS:
            raise InputError(
                "option 155 = 3 makes Z the heads' common axis, but the machine has two axes "
                "(option 22)",
                SourcePosition(machine.origin),
            )
        self.machine = machine
        self.tapes = [HeadTape(tape.head, tape.read()) for tape in tapes]
        self.out = GMOUT(machine, sinks, warn)
        self.two_feed_registers = machine.number_option(139) != 0

    def run(self) -> None:
        tapes = self.tapes
        if self.common_axis is not None:
            self._prelude()
        current = tapes[0]
        while not all(t.done for t in tapes):
            other = tapes[2 - current.head]
            if current.stopped:
                if other.stopped:  # both at their ends: the ENDs go out, head 1's first
                    for tape in tapes:
                        tape.released = True
                    current = tapes[0] if not tapes[0].done else tapes[1]
                else:
                    current = other
                continue
            block = current.next()
            if block is None:
                continue
            if block.code is not Code.MULTIHEAD_1:
                self.out.alone(block)
                continue
            if self._information(block):
                continue
            current.waiting_op = int(block.cells[2])  # type: ignore[arg-type]
            current.op = block
            if other.stopped:
                current.waiting_op = None  # nothing to cut with: go on alone
                continue
            if other.waiting_op is None:
                current = other  # read the other tape up to its OP block
                continue
            if current.waiting_op == other.waiting_op:
                self._section()
                current = tapes[0]
                continue
            # unequal: the head with the lower operation number goes on alone
            assert current.waiting_op is not None and other.waiting_op is not None
            current = current if current.waiting_op < other.waiting_op else other
            current.waiting_op = None
        self.out.finish([t.fini for t in tapes])

    def _prelude(self) -> None:
        """On a common axis every move of one head moves the other: both heads' FROM and
        SAFETY are read before the first move goes out (each tape up to its first move or
        OP block), so that the axis knows where both heads stand."""
        for tape in self.tapes:
            while True:
                block = tape.next()
                if block is None:
                    break
                if block.code is Code.MULTIHEAD_1 and self._information(block):
                    continue
                if block.code is Code.MULTIHEAD_1 or (
                    block.steps is not None and block.code is not Code.FROM
                ):
                    tape.put_back(block)
                    break
                self.out.alone(block)

    def _information(self, block: Block) -> bool:
        """SAFETY, SFM and PRFSEQ blocks set their conditions; False for an OP block."""
        kind = int(block.cells[11])  # type: ignore[arg-type]
        if kind == OP_PREFERRED:
            self.out.preferred = int(block.cells[8])  # type: ignore[arg-type]
            return True
        if kind in (OP_SAFETY, OP_SFM):
            self.out.information(block)
            return True
        return False

    def _section(self) -> None:
        """A combined section: both heads at the same OP/n (001 L7318-7330)."""
        first, second = self.tapes
        assert first.op is not None and second.op is not None
        self.out.start_section(first.op, second.op)
        for tape in self.tapes:
            tape.waiting_op = None
        moves = [self._moves(tape) for tape in self.tapes]
        if self.common_axis is not None:
            left = merge_common_axis(self.machine, moves, self.out, self.common_axis)
        elif self.two_feed_registers:
            left = self._by_summed_times(moves)
        else:
            left = merge_equal_times(self.machine, moves, self.out)
        if left is not None:
            self._one_after_the_other(left, moves)
        self.out.end_section()

    def _moves(self, tape: HeadTape) -> Iterator[Block]:
        """A head's mergeable blocks up to its next OP block (or FINI); the others go out
        alone as they are met (001 L7649-7660)."""
        while True:
            block = tape.next()
            if block is None:
                return
            if block.code is Code.MULTIHEAD_1:
                if self._information(block):
                    continue
                tape.put_back(block)  # the next OP: the sequencing reads it again
                return
            if mergeable(block):
                if block.code is Code.TURRET_CORRECTION and self.common_axis is not None:
                    raise NotYetSupported(
                        "a turret corrective move (CODE +-14) in a combined section on heads "
                        f"that share a common axis (option 155), CL record {block.record}"
                    )
                yield block
            else:
                self.out.alone(block)

    def _by_summed_times(self, moves: list[Iterator[Block]]) -> list[Block | None] | None:
        """Two feedrate registers (001 L2040-2075): the first moves together, then always
        the head with the smaller summed time, together again where the sums meet. The
        moves not yet output when a restriction stops the combined cut are returned."""
        pending = [next(m, None) for m in moves]
        summed = [0.0, 0.0]
        while pending[0] is not None or pending[1] is not None:
            first, second = pending
            if first is not None and second is not None and self.out.restricted(first, second):
                return pending
            if (
                first is not None
                and second is not None
                and abs(summed[0] - summed[1]) <= TIME_EPSILON
                and self.out.combinable(first, second)
            ):
                summed[0] += first.cut_minutes + first.dwell_minutes
                summed[1] += second.cut_minutes + second.dwell_minutes
                self.out.combined(first, second)
                pending = [next(moves[0], None), next(moves[1], None)]
                continue
            index = 0 if second is None or (first is not None and summed[0] <= summed[1]) else 1
            block = pending[index]
            assert block is not None
            summed[index] += block.cut_minutes + block.dwell_minutes
            self.out.alone(block)
            pending[index] = next(moves[index], None)
        return None

    def _one_after_the_other(
        self, pending: list[Block | None], moves: list[Iterator[Block]]
    ) -> None:
        """A restriction is broken (001 L7640-7645): the other head is withdrawn while the
        preferred head finishes its part of the section; then it returns and finishes
        its own. The times add up: the heads no longer cut at once."""
        out = self.out
        out.summed = None
        keep = out.preferred
        parked = 3 - keep
        record = next((b.record for b in pending if b is not None), None)
        out.parking.park(parked, record)
        for head in (keep, parked):
            if head == parked and self.common_axis is None:
                # (on a common axis the head comes back by the axis first, before its
                # next move: GMOUT's parking returns it there)
                out.parking.unpark(parked, record)
            block = pending[head - 1]
            if block is not None:
                out.alone(block)
            for block in moves[head - 1]:
                out.alone(block)
