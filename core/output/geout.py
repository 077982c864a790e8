"""The end of OUTPUT for a finished block (manual §3.5): its sequence number N (the CL record
number, the SEQNO series, SEQLIM; 001 L9117-9126, L37337-37373), then GEOUT's conversion
into register words and the tape line (flow chart 12, 001 L20074-20192). Mixed into
OutputElement (core/output/element.py)."""

from __future__ import annotations

from collections.abc import Callable

from gecent.core.absent import ABSENT, Absent
from gecent.core.errors import Diagnostic
from gecent.core.output.block import Block, Code
from gecent.core.output.codes import (
    ABSOLUTE_CODES,
    CIRCLE_CODES,
    MOVING_CODES,
    PLACED_CODES,
    UNSHUFFLED,
)
from gecent.core.output.modern import CL_PLANES, ModernControl
from gecent.core.output.words import Word, WordFormatter
from gecent.core.state import PostState


class GeoutConversion:
    """Mixed into OutputElement: what it needs of it is declared here."""

    state: PostState
    modern: ModernControl
    words: WordFormatter
    diagnostics: list[Diagnostic]
    sequence_limit: int
    dump_only: bool
    register_hook: Callable[[Block, list[Word]], list[Word]] | None
    end_code: float | Absent
    separator: str
    rotary_step: float
    emit: Callable[[Block], None]

    def number_and_emit(self, block: Block) -> None:
        """N, then GEOUT: the end of OUTPUT for a block A/D lets go."""
        block.cells[1] = self._sequence_number(block)
        self._emit(block)

    def _sequence_number(self, block: Block) -> float | Absent:
        """N: the CL record number (option 143 = 0), or the SEQNO series, or none after
        SEQNO/OFF; negative under OPSKIP; above SEQLIM, N modulus SEQLIM (001 L9117-9126,
        L37337-37373)."""
        state = self.state
        numbering = state.numbering
        if numbering.off:
            return ABSENT
        if numbering.series is not None and block.punched:
            sequence, increment = numbering.series
            numbering.series = (sequence + increment, increment)
        else:
            sequence = block.record if block.record is not None else state.sequence
        if sequence > self.sequence_limit:
            if self.modern.frame and numbering.series is not None:
                # a program for a modern control never repeats an N: past the register's
                # digits its blocks go on without one
                numbering.off = True
                self.diagnostics.append(
                    Diagnostic(
                        f"BLOCK NUMBERS PASS N{self.sequence_limit}: THE REST OF THE PROGRAM "
                        "HAS NO N WORDS",
                        None,
                    )
                )
                return ABSENT
            sequence %= self.sequence_limit
        if numbering.unrepeated and block.punched:
            if sequence == numbering.last:
                return ABSENT  # option 143 = -1: the redundant N is suppressed
            numbering.last = sequence
        return float(-sequence if state.skipping else sequence)

    def _emit(self, block: Block) -> None:
        if self.dump_only or block.code is Code.FROM:  # FROM: printed, never punched
            self.emit(block)
            return
        self.convert(block)
        self.emit(block)

    def convert(self, block: Block) -> None:
        """GEOUT's conversion: SHUFFL, the register words with their redundancy tests and
        the tape line (flow chart 12)."""
        modern = self.modern
        placed = False
        if modern.absolute and block.position is not None and block.code in PLACED_CODES:
            # a circle states both axes of its CL plane
            keep = (
                () if block.code not in CIRCLE_CODES else CL_PLANES[abs(int(block.code)) - 10][:2]
            )
            modern.place(block, block.position, keep)
            if block.angles is not None:
                modern.place_rotary(block, block.angles, self.rotary_step)
            placed = True
        if block.code not in UNSHUFFLED:
            self.words.shuffle_block(block)
        code = block.code
        motion = code in MOVING_CODES
        words = self.words.words(
            block,
            suppress=motion,
            sequence=self.state.sequence,
            absolute=placed or code in ABSOLUTE_CODES,
        )
        if self.register_hook is not None:
            words = self.register_hook(block, words)
        if modern.active:
            if block.cells[13] is not ABSENT:
                modern.forget()  # a tool change: the next move states every axis
                self.words.previous_g = ABSENT  # and its motion G
            if block.cells[14] is not ABSENT and block.cells[14] == self.end_code:
                modern.ended = True
            elif motion:
                modern.ended = False
        if not motion and block.cells[2] is not ABSENT:
            self.words.previous_g = ABSENT  # a G04 or other G came between: repeat the motion G
        block.words = tuple((location, printed) for location, _, printed, _ in words)
        if block.punched:
            unpunched = self.words.unpunched_g  # option 147: G01/G11 printed, not punched
            punch = self.separator.join(
                letter + punched
                for location, letter, _, punched in words
                if not (location == 2 and unpunched and block.cells[2] in unpunched)
            )
            block.punch = "/" + punch if block.skipped else punch
