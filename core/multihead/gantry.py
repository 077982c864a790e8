"""Common-axis merging (FXMULT, manual §3.4.8.2.1.3, 001 L7897-8402, write-up L31712-31832):
on a machine whose heads share an axis (option 155: 1 X, 2 Y, 3 Z of the CL axes), a
combined block must move both heads alike along it. The heads' lines are paired by their
coordinates on the axis (core/multihead/common_axis.py): the longer path is cut where the
other ends (SEG), a head behind or still on the axis cuts alone first, and a pair whose
component feeds along the axis differ by more than option 157 is cut one head after the
other (FXTOL). Only lines combine (L7992-7994): circles and dwells go out alone. Before a
head cuts alone along the axis the other is parked; a head the axis has moved returns to
its point first (core/multihead/parking.py). This works with one feedrate register or two.
"""

from __future__ import annotations

from collections.abc import Iterator

from gecent.core.absent import ABSENT
from gecent.core.machine.definition import MachineDefinition
from gecent.core.multihead.common_axis import AxisRule, common_axis_step, component_feeds_agree
from gecent.core.multihead.equal_time import HeadMoves
from gecent.core.multihead.gmout import GMOUT
from gecent.core.multihead.split import Move, split_move
from gecent.core.output.block import Block, Code


def merge_common_axis(
    machine: MachineDefinition, moves: list[Iterator[Block]], out: GMOUT, axis: int
) -> list[Block | None] | None:
    """The FXMULT loop over both heads' moves of a combined section; the moves not yet
    output are returned when an OP restriction stops the combined cut."""
    tolerance = machine.number_option(157)
    heads = [
        HeadMoves(converter, blocks) for converter, blocks in zip(out.heads, moves, strict=True)
    ]
    # coordinates on the axis closer than half the tape's smallest value are one: the
    # pieces of a split are cut on that grid, and a CL file may be finer than it
    same = max(h.converter.quanta[axis] * h.step for h in heads) / 2.0
    one_register = machine.number_option(139) == 0
    out.summed = None  # heads cutting alone keep the other waiting: the times add up
    streams = [heads[0].moves(), heads[1].moves()]
    pending: list[Move | None] = [next(streams[0], None), next(streams[1], None)]
    while pending[0] is not None and pending[1] is not None:
        move_1, move_2 = pending
        assert move_1 is not None and move_2 is not None
        if out.restricted(_source(move_1), _source(move_2)):
            return [heads[0].block(move_1), heads[1].block(move_2)]
        lines = [m.arc is None and m.dwell_minutes == 0.0 for m in (move_1, move_2)]
        if not all(lines):
            index = 0 if not lines[0] else 1  # a circle or a dwell: alone, in its turn
            _alone(out, heads[index], pending[index])
            pending[index] = next(streams[index], None)
            continue
        s1, s2 = heads[0].start(move_1, axis), heads[1].start(move_2, axis)
        e1, e2 = s1 + move_1.departures[axis], s2 + move_2.departures[axis]
        step = common_axis_step(s1, e1, s2, e2, same)
        if step.rule is AxisRule.SEPARATE:
            for index in (0, 1):
                _alone(out, heads[index], pending[index])
                pending[index] = next(streams[index], None)
            continue
        if step.rule is AxisRule.CATCH_UP:
            index = (step.head or 1) - 1
            move = pending[index]
            assert move is not None
            rest = None
            if step.at is not None and _worth_splitting(move, step.fraction, axis, same):
                move, rest = split_move(move, step.fraction)
            _alone(out, heads[index], move)
            pending[index] = rest if rest is not None else next(streams[index], None)
            continue
        pieces: list[Move] = [move_1, move_2]
        rests: list[Move | None] = [None, None]
        if step.rule is AxisRule.SEGMENT:
            index = (step.head or 1) - 1
            if _worth_splitting(pieces[index], step.fraction, axis, same):
                pieces[index], rests[index] = split_move(pieces[index], step.fraction)
        if _feeds_agree(pieces[0], pieces[1], axis, tolerance):
            # one feedrate register: the block takes the longer head's time, its F, and
            # the quicker head is slowed to it (as Rule 2 slows, 001 L7570-7596)
            longer = 1 if pieces[0].time >= pieces[1].time else 2
            _together(out, heads, pieces, longer if one_register else None, axis)
        else:  # FXTOL: out of tolerance, each head cuts its piece alone
            for index in (0, 1):
                _alone(out, heads[index], pieces[index])
        for index in (0, 1):
            pending[index] = rests[index] or next(streams[index], None)
    for index in (0, 1):
        while pending[index] is not None:
            _alone(out, heads[index], pending[index])
            pending[index] = next(streams[index], None)
    return None


def _source(move: Move) -> Block:
    assert isinstance(move.source, Block)
    return move.source


def _feeds_agree(first: Move, second: Move, axis: int, tolerance: float) -> bool:
    return component_feeds_agree(
        first.departures[axis],
        first.length,
        first.feed,
        second.departures[axis],
        second.length,
        second.feed,
        tolerance,
    )


def _worth_splitting(move: Move, fraction: float, axis: int, same: float) -> bool:
    """A split leaves two pieces each at least a grid step long on the axis."""
    along = abs(move.departures[axis])
    return same < fraction * along < along - same


def _together(
    out: GMOUT, heads: list[HeadMoves], pieces: list[Move], primary: int | None, axis: int
) -> None:
    first, second = heads[0].block(pieces[0]), heads[1].block(pieces[1])
    if first is not None and second is not None:
        _one_axis_move(first, second, heads[1], axis)
        out.combined(first, second, primary)
        return
    for block in (first, second):
        if block is not None:
            out.alone(block)


def _one_axis_move(first: Block, second: Block, head: HeadMoves, axis: int) -> None:
    """The combined block moves the axis once: head 2's departure along it made head
    1's where rounding has made them differ (CL values finer than the tape would
    otherwise print one word a digit apart from the other)."""
    assert first.steps is not None and second.steps is not None
    if axis >= len(first.steps) or axis >= len(second.steps):
        return
    quantum = head.converter.quanta[axis]
    if round(first.steps[axis] / quantum) == round(second.steps[axis] / quantum):
        return  # (one word on the tape already)
    difference = first.steps[axis] - second.steps[axis]
    # (the pair was made on coordinates equal to half a grid step at each end, each
    # piece cut on the grid: the departures differ by two grid steps at most)
    if abs(difference) > 2 * quantum:
        return
    steps = list(second.steps)
    steps[axis] = first.steps[axis]
    second.steps = tuple(steps)
    second.cells[3 + axis] = steps[axis] * head.step
    if second.position is not None:
        position = list(second.position)
        position[axis] += difference
        second.position = tuple(position)
    ipm = second.cells[19]
    if ipm is not ABSENT and float(ipm) > 0 and second.code is Code.LINEAR:
        head.converter.refinish(second, float(ipm))


def _alone(out: GMOUT, head: HeadMoves, move: Move | None) -> None:
    if move is None:
        return
    block = head.block(move)
    if block is not None:
        out.alone(block)
