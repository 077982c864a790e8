"""The OUTPUT element's dwells (manual §4.10, 001 L16296-16373): a dwell block's G and time
word (option 57's register, or the F-register dwell), and the dwells options 98 and 148
put in non-motion blocks. Mixed into OutputElement (core/output/element.py)."""

from __future__ import annotations

from gecent.core.absent import ABSENT, Absent
from gecent.core.motion.gcode import DimensionCode
from gecent.core.output.block import Block, Code
from gecent.core.output.words import WordFormatter
from gecent.core.state import PostState


class Dwells:
    """Mixed into OutputElement: what it needs of it is declared here."""

    state: PostState
    words: WordFormatter
    dwell_g: float | Absent
    dwell_code: DimensionCode | None

    def dwell(self, seconds: float) -> Block:
        """A dwell block (CODE +4, manual §4.10, 001 L16296-16373): G = TABLEG(5) and the
        time divided by option 56 in the option-57 register; or, with option 57 = 11, the
        F-register dwell F = 60 GDIMUL / t under the dwell G or the smallest dimension code
        from G11 up, whose multiplier scales the control's time (001 L16341-16370)."""
        block = Block(Code.DWELL)
        block.dwell_minutes = seconds / 60.0
        self._put_dwell(block, seconds)
        return block

    def put_dwell(self, block: Block, seconds: float) -> None:
        """The dwell's G and time word in the machine's dwell register (option 57)."""
        self._put_dwell(block, seconds)

    def _put_dwell(self, block: Block, seconds: float) -> None:
        machine = self.state.machine
        register = int(machine.number_option(57))
        if self.state.head and machine.option(195) != 0:
            # a multihead head's dwell in the heads' common dwell register (option 195)
            from gecent.core.multihead.registers import shared_dwell_cell

            register = shared_dwell_cell(machine) or register
        if register == 11:
            code = self.dwell_code
            block.cells[2] = ABSENT if code is None else float(code.code)
            multiplier = 1.0 if code is None else max(code.gdimul, 1.0)
            block.cells[11] = 60.0 * multiplier / seconds if seconds else ABSENT
            self.words.previous_f = ABSENT  # the F dwell overwrote the control's feed
            return
        block.cells[2] = self.dwell_g
        block.cells[register] = seconds / (machine.number_option(56) or 1.0)

    def _non_motion_dwell(self, block: Block) -> None:
        """Options 98 and 148 (001 L25585-25602, L26140-26152): an F momentary dwell in
        non-motion blocks (+N: not in dwell blocks; -N: in them too), with G = TABLEG(5);
        or an N-second G04 dwell in every non-motion block (+N) or in STOP/OPSTOP blocks
        only (-N). The manual forbids both at once; option 98 wins."""
        machine = self.state.machine
        momentary = machine.number_option(98)
        if momentary and (block.code is not Code.DWELL or momentary < 0):
            if block.cells[11] is ABSENT:
                block.cells[11] = abs(momentary)
                self.words.previous_f = ABSENT
            if block.cells[2] is ABSENT:
                block.cells[2] = self.dwell_g
            return
        seconds = machine.number_option(148)
        if block.code is Code.DWELL or not seconds or (seconds < 0 and not block.stop):
            return
        self._put_dwell(block, abs(seconds))
        block.dwell_minutes += abs(seconds) / 60.0
