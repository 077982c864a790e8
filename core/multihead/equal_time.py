"""Single feedrate register merging (manual §3.4.8.2.1.1, 001 L7390-7890): both heads'
moves of a combined section are paired so that every combined block takes one time on
both heads; the longer move is split (SPLIT, CIRSEG), or, below the tape-reader limit
TMAX or within option 151's band, the quicker head is slowed (Rule 2). The arithmetic is
core/multihead/split.py; this module turns command blocks into its moves and its pieces
back into command blocks, in steps that add up exactly to the move split.

A turret corrective move is a line here (001 L7676-7677) and is split as one; its pieces
keep the point the correction leaves the tool at, so that each goes out as a correction
(CODE -3 alone, +-14 beside the other head's move) and none is summed.
"""

from __future__ import annotations

import copy
from collections.abc import Iterator
from math import isclose

from gecent.core.absent import ABSENT, or_zero
from gecent.core.errors import NotYetSupported
from gecent.core.machine.definition import MachineDefinition
from gecent.core.multihead.gmout import GMOUT, HeadConverter
from gecent.core.multihead.split import (
    Move,
    Plane,
    arc_sweep,
    equal_time_merge,
    tape_reader_limit,
)
from gecent.core.output.block import Block, Code
from gecent.core.output.element import CIRCLE_CODES

# CODE 10, 11, 12 (XY, ZX, YZ) -> the plane of split.py
PLANES = {10: Plane.XY, 11: Plane.ZX, 12: Plane.YZ}


def merge_equal_times(
    machine: MachineDefinition, moves: list[Iterator[Block]], out: GMOUT
) -> list[Block | None] | None:
    """The GMLINE/GMCIRL loop over both heads' moves; the moves not yet output (a split's
    rest among them) are returned when a restriction stops the combined cut. With one
    feedrate register the control runs a block at a time: a head's block alone keeps the
    other waiting, so the program's times add up."""
    tmax = tape_reader_limit(machine.number_option(13), machine.number_option(69))
    band = machine.number_option(151)
    heads = [
        HeadMoves(converter, blocks) for converter, blocks in zip(out.heads, moves, strict=True)
    ]
    out.summed = None
    pairs = equal_time_merge(
        heads[0].moves(),
        heads[1].moves(),
        tmax,
        band,
        together=lambda a, b: out.combinable(_source(a), _source(b)),
        stop=lambda a, b: out.restricted(_source(a), _source(b)),
    )
    while True:
        try:
            pair = next(pairs)
        except StopIteration as end:
            left_1, left_2 = end.value
            if left_1 is None and left_2 is None:
                return None
            return [heads[0].block(left_1), heads[1].block(left_2)]
        _out(out, heads[0].block(pair.head_1), heads[1].block(pair.head_2))


def _source(move: Move) -> Block:
    assert isinstance(move.source, Block)
    return move.source


def _out(out: GMOUT, first: Block | None, second: Block | None) -> None:
    """A pair together when the control can cut it so, else each alone."""
    if first is not None and second is not None and out.combinable(first, second):
        out.combined(first, second)
        return
    for block in (first, second):
        if block is not None:
            out.alone(block)


class HeadMoves:
    """One head's blocks as moves, and the pieces the merge makes of them as blocks."""

    def __init__(self, converter: HeadConverter, blocks: Iterator[Block]) -> None:
        self.converter = converter
        self.blocks = blocks
        self.step = converter.element.step
        self.source: Block | None = None
        self.remaining: list[int] = []  # steps of the source not yet output

    def start(self, move: Move, axis: int) -> float:
        """Where ``move`` starts on a CL axis (inches): a split's rest where the pieces
        already output end, a whole move where its block ends less its departure."""
        source = _source(move)
        assert source.position is not None and source.steps is not None
        left = self.remaining if source is self.source else list(source.steps)
        if axis >= len(left) or axis >= len(source.position):
            return 0.0
        return (source.position[axis] - left[axis]) * self.step

    def moves(self) -> Iterator[Move]:
        for block in self.blocks:
            yield self._move(block)

    def _move(self, block: Block) -> Move:
        if block.code is Code.DWELL:
            return Move.dwell(block.dwell_minutes, source=block)
        assert block.steps is not None
        step = self.step
        # (a two-axis machine's blocks have two departures)
        departures = tuple(s * step for s in block.steps[:3]) + (0.0,) * (3 - len(block.steps))
        feed = or_zero(block.cells[19])
        if block.code in CIRCLE_CODES:
            plane = PLANES[abs(int(block.code))]
            clockwise = int(block.code) > 0
            offsets = self._signed_offsets(block, departures, plane, clockwise)
            return Move.circle(departures, offsets, plane, clockwise, feed, source=block)
        return Move.line(departures, feed, source=block)

    def _signed_offsets(
        self,
        block: Block,
        departures: tuple[float, ...],
        plane: Plane,
        clockwise: bool,
    ) -> tuple[float, float, float]:
        """The centre from the start, signed: the manual's offsets are magnitudes (001
        L5300-5330); of the centres they allow, the one on the arc's circle through both
        ends that turns the least in the arc's direction (a quadrant segment)."""
        if self.converter.machine.number_option(252) != 0:
            raise NotYetSupported(
                "merging a circle of a control with signed or absolute centre words "
                "(option 252) on one feedrate register"
            )
        u, v, _ = plane.axes
        magnitudes = [abs(or_zero(block.cells[8 + a])) for a in range(3)]
        radius = block.radius or (magnitudes[u] ** 2 + magnitudes[v] ** 2) ** 0.5
        best: tuple[float, tuple[float, float, float]] | None = None
        for su in (1.0, -1.0):
            for sv in (1.0, -1.0):
                centre = [0.0, 0.0, 0.0]
                centre[u], centre[v] = su * magnitudes[u], sv * magnitudes[v]
                to_end = (
                    (departures[u] - centre[u]) ** 2 + (departures[v] - centre[v]) ** 2
                ) ** 0.5
                if abs(to_end - radius) > 2 * self.step + 1e-9 * radius:
                    continue
                try:
                    sweep = arc_sweep(departures, centre, plane, clockwise)
                except ValueError:
                    continue
                if best is None or sweep < best[0]:
                    best = (sweep, (centre[0], centre[1], centre[2]))
        if best is None:
            # the centre words are the first pass's own, made from the CIRCLE record (the
            # part program gives none): a misfit is gecent's inconsistency, an internal
            # error (core/multihead/post.py), not bad input and not a form to build
            raise RuntimeError(
                f"the centre words of the circle of CL record {block.record} do not fit its "
                "ends (merging it to equal times)"
            )
        return best[1]

    def block(self, move: Move | None) -> Block | None:
        """The command block of a merged piece: the source block itself when the move is
        whole and unslowed, else a copy with its own departures, feed and centre."""
        if move is None:
            return None
        source = move.source
        assert isinstance(source, Block)
        if source is not self.source:
            self.source = source
            self.remaining = list(source.steps or (0, 0, 0))
        if source.code is Code.DWELL:
            if isclose(move.dwell_minutes, source.dwell_minutes):
                return source
            piece = copy.copy(source)
            piece.cells = list(source.cells)
            self.converter.redwell(piece, move.dwell_minutes)
            return piece
        quanta = self.converter.quanta
        steps = [
            round(d / self.step / q) * q for d, q in zip(move.departures, quanta, strict=False)
        ][: len(self.remaining)]
        whole = all(abs(s - r) <= q for s, r, q in zip(steps, self.remaining, quanta, strict=False))
        if whole:
            steps = list(self.remaining)  # the last piece takes what rounding left
        self.remaining = [r - s for r, s in zip(self.remaining, steps, strict=False)]
        feed = or_zero(source.cells[19])
        if steps == list(source.steps or ()) and isclose(move.feed, feed):
            return source
        if not any(steps):
            return None  # a piece within one step: nothing to cut
        piece = copy.copy(source)
        piece.cells = list(source.cells)
        piece.steps = tuple(steps)
        assert source.position is not None
        if source.code is Code.TURRET_CORRECTION:
            # the turret centre moves, the tool's point does not: every piece of a
            # correction keeps it (not summed, 001 L9225-9233)
            piece.position = source.position
        else:
            after = self.remaining + [0] * (len(source.position) - len(self.remaining))
            piece.position = tuple(p - a for p, a in zip(source.position, after, strict=False))
        for axis, count in enumerate(steps):
            piece.cells[3 + axis] = count * self.step
        if move.arc is not None:
            for axis in range(3):
                offset = move.arc.offsets[axis]
                piece.cells[8 + axis] = abs(offset) if abs(offset) > self.step / 2 else ABSENT
            piece.radius = move.arc.radius
        self.converter.refinish(piece, move.feed)
        return piece
