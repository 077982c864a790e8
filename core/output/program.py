"""The parts of the OUTPUT element a modern control's program needs (gecent options 251-265,
docs/modern-controls.md, docs/five-axis.md): the start block, the end of the program, G43 H
and the control's tool centre point after a tool change, and F as the feed itself under
G94/G95, or inverse time under G93 for a five-axis move that turns the tool."""

from __future__ import annotations

from collections.abc import Callable

from gecent.core.absent import ABSENT, Absent
from gecent.core.output.block import Block, Code
from gecent.core.output.modern import (
    TOOL_LENGTH_REGISTER,
    ModernControl,
    machine_planes,
)
from gecent.core.output.words import WordFormatter
from gecent.core.state import PostState


class ModernProgram:
    """Mixed into OutputElement: what it needs of it is declared here."""

    state: PostState
    modern: ModernControl
    words: WordFormatter
    separator: str
    tool_length_code: float | Absent
    end_code: float | Absent
    inverse_time_code: bool
    inverse_time_limit: float  # the largest F the register holds: a shorter move is slower
    tcp_on: str
    tcp_off: str
    tcp_active: bool
    emit: Callable[[Block], None]
    _output: Callable[[Block], None]
    flush_m: Callable[[int | None], None]

    def tool_length_block(self, record: int | None) -> None:
        """G43 H in a block of its own (option 263 = 1), when the tool's first move cannot
        carry it (an arc, a cycle) or cutter compensation comes before that move."""
        state = self.state
        state.tool.length_pending = False
        block = Block(Code.G_ONLY, record)
        block.cells[2] = self.tool_length_code
        block.cells[TOOL_LENGTH_REGISTER] = float(state.tool.offset or 0)
        self._output(block)

    def _tcp_block(self, record: int | None) -> None:
        """Option 265 = 1: the control's tool-centre-point mode (Fanuc G43.4) with the
        tool's H, before the first move after a tool change."""
        state = self.state
        state.tool.length_pending = False
        h = next((f for f in self.words.formatters if f.location == TOOL_LENGTH_REGISTER), None)
        words = [self.tcp_on]
        if h is not None:
            words.append(h.letter + h.format(float(state.tool.offset or 0)).punched)
        block = Block(Code.INSERT, record, " ".join(words))
        block.keep_blanks = bool(self.separator)
        self.emit(block)
        self.tcp_active = True

    def _tcp_off(self, record: int | None) -> None:
        self.tcp_active = False
        self.emit(Block(Code.INSERT, record, self.tcp_off))

    def _direct_feed(self, block: Block) -> float:
        """Option 254: F is the feed itself, per revolution under G95 when FEDRAT gave it so;
        a change of mode goes out first in a block of its own. A five-axis move that turns
        a rotary axis is timed (G93, TABLEG 131): F = 1 / its minutes, in every block."""
        feed = self.state.feed
        inverse = block.inverse_time and self.inverse_time_code
        mode = self.modern.feed_mode_code(feed.per_revolution, inverse)
        if mode is not None:
            g_block = Block(Code.G_ONLY, block.record)
            g_block.cells[2] = mode
            self._output(g_block)
            self.words.previous_f = ABSENT  # the control drops F with its feed mode
        if inverse:
            self.words.previous_f = ABSENT  # G93 wants F in every block
            per_minute = feed.ipm / block.feed_length if block.feed_length > 0 else feed.ipm
            return min(per_minute, self.inverse_time_limit)
        return feed.per_revolution_value if feed.per_revolution else feed.ipm

    def _start_block(self, record: int | None) -> None:
        """Option 258: the modal codes the program starts from, before its first block."""
        modern = self.modern
        modern.started = True
        plane: int | None = 18  # TABLEG(18): XY
        if self.state.machine.number_option(252):
            plane = machine_planes(self.words.shuffle[:3])[0][0]
        for comment in self.state.header:  # option 264: the tool list
            text = Block(Code.INSERT, record, comment)
            text.keep_blanks = True
            self.emit(text)
        codes = modern.start_codes(plane)
        g = next((f for f in self.words.formatters if f.location == 2), None)
        if not codes or g is None:
            return
        words = [g.letter + g.format(code).punched for code in codes]
        if self.state.machine.number_option(252) == 2:
            words.append("G90.1")  # arc centres absolute (LinuxCNC; option 252 = 2)
        block = Block(Code.INSERT, record, " ".join(words))
        block.keep_blanks = bool(self.separator)
        self.emit(block)

    def finish_program(self, record: int | None) -> None:
        """Option 258 at FINI: the end-of-program code, unless END has given it since the
        last move."""
        if self.tcp_active and self.tcp_off:
            self._tcp_off(record)
        if not self.modern.frame or self.modern.ended or self.end_code is ABSENT:
            return
        self.flush_m(record)
        self.state.pending.m_code = self.end_code
        self._output(Block(Code.END, record))
