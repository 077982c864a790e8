"""Parking the heads (FXPARK with PARK, RETHD and DRETHD, manual §3.4.8.2.1.3, 001
L7971-7992, L8026-8033, L31834-31915; §2.4.5.1, L2117-2130).

A head is parked by moving it by the departures of its SAFETY statement (SAFHD1, SAFHD2)
at rapid; the other head is withdrawn with it and brought back, so that neither mars the
work, and a comment is printed. A parked head returns to the point it is to cut from.

On a machine whose heads share a common axis (option 155, a gantry) every move of one head
along that axis moves the other with it ("once parked, only the common axis value changes
for the head", L7986-7990): before a head moves along the axis alone the other is parked,
and a head whose axis value has been moved returns to its own point before it cuts again.
The write-ups of PARK, RETHD and DRETHD are not in the seeds (only their call lists,
L20771-20784); the comments' texts are gecent's (docs/decisions.md).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol

from gecent.core.errors import Diagnostic
from gecent.core.machine.definition import MachineDefinition
from gecent.core.output.block import Block, Code


class HeadOutput(Protocol):
    """A head's converter, as parking uses it (core/multihead/gmout.py HeadConverter)."""

    @property
    def step(self) -> float: ...

    @property
    def quanta(self) -> list[int]: ...

    def rapid_move(
        self, departures: tuple[float, ...], at: tuple[int, ...], record: int | None
    ) -> tuple[list[Block], Block, list[Block]]: ...


class Output(Protocol):
    """GMOUT, as parking uses it."""

    machine: MachineDefinition
    positions: dict[int, tuple[int, ...] | None]

    @property
    def head_outputs(self) -> Sequence[HeadOutput]: ...

    def warn(self, diagnostic: Diagnostic) -> None: ...

    def text(self, text: str, record: int | None) -> None: ...

    def alone(self, block: Block) -> None: ...

    def combined(self, first: Block, second: Block) -> None: ...


class Parking:
    def __init__(self, out: Output) -> None:
        self.out = out
        self.safety: dict[int, tuple[float, ...] | None] = {1: None, 2: None}
        self.parked = {1: False, 2: False}
        option = int(out.machine.number_option(155))
        self.axis: int | None = option - 1 if option in (1, 2, 3) else None
        self.making = 0  # > 0 while parking or returning moves are made (no nesting)
        # each head's last point of its own program (steps): where it cuts on from
        self.cl_points: dict[int, tuple[int, ...] | None] = {1: None, 2: None}
        self.dragged_warned = {1: False, 2: False}

    def safety_given(self, head: int, departures: tuple[float, ...]) -> None:
        """A SAFETY information block (DBFSEG(11) = 1): SAFHD1 or SAFHD2."""
        self.safety[head] = departures  # (SAFETY refuses a departure along a common axis)

    # -- parking and returning ------------------------------------------------------

    def park(self, head: int, record: int | None) -> None:
        """PARK: withdraw ``head`` by its SAFETY departures at rapid, the other head
        withdrawn with it and brought back, and the comment; a head with no SAFETY stays
        where it is, with a diagnostic."""
        out = self.out
        departures = self.safety[head]
        if departures is None or out.positions[head] is None:
            out.warn(Diagnostic(f"HEAD {head} NOT PARKED: NO SAFETY WAS GIVEN FOR IT", None))
            return
        other = 3 - head
        self.parked[head] = True
        out.text(f"HEAD {head} PARKED", record)
        withdrawn = self.safety[other]
        self.making += 1
        try:
            if withdrawn is None or out.positions[other] is None or self.parked[other]:
                self._rapid(head, departures, record)
                return
            moves = {head: departures, other: withdrawn}
            blocks = [self._rapid_blocks(h, moves[h], record) for h in (1, 2)]
            for before, _, _ in blocks:
                for block in before:
                    out.alone(block)
            out.combined(blocks[0][1], blocks[1][1])
            for _, _, after in blocks:
                for block in after:
                    out.alone(block)
            self._rapid(other, tuple(-d for d in withdrawn), record)
        finally:
            self.making -= 1

    def unpark(self, head: int, record: int | None) -> None:
        """RETHD: the parked head back to where it was withdrawn from, with the comment."""
        departures = self.safety[head]
        if not self.parked[head] or departures is None:
            return
        self.parked[head] = False
        self.out.text(f"HEAD {head} RETURNED TO THE WORK", record)
        self.making += 1
        try:
            self._rapid(head, tuple(-d for d in departures), record)
        finally:
            self.making -= 1

    def _rapid(self, head: int, departures: tuple[float, ...], record: int | None) -> None:
        step = self.out.head_outputs[head - 1].step
        if all(round(d / step) == 0 for d in departures):
            return  # (within a step: no move to make)
        before, move, after = self._rapid_blocks(head, departures, record)
        for block in (*before, move, *after):
            self.out.alone(block)

    def _rapid_blocks(
        self, head: int, departures: tuple[float, ...], record: int | None
    ) -> tuple[list[Block], Block, list[Block]]:
        at = self.out.positions[head]
        assert at is not None
        return self.out.head_outputs[head - 1].rapid_move(departures, at, record)

    # -- the common axis ------------------------------------------------------------

    def placed(self, head: int, block: Block) -> None:
        """A head's FROM. On a common axis both heads' FROMs name the one coordinate of the
        axis: the later one is where the axis stands, for both heads (a FROM that differs
        is warned about; the other head returns to its own point before it cuts)."""
        positions = self.out.positions
        assert block.position is not None
        positions[head] = block.position
        self.cl_points[head] = block.position
        axis = self.axis
        other = positions[3 - head]
        if axis is None or other is None or axis >= len(other):
            return
        if other[axis] != block.position[axis]:
            self.out.warn(
                Diagnostic(
                    f"THE HEADS' FROM POINTS DIFFER ON THE COMMON AXIS {'XYZ'[axis]}: IT IS ONE "
                    "COORDINATE FOR BOTH HEADS, AND MOVES FROM ONE TO THE OTHER",
                    None,
                )
            )
            self._drag(3 - head, block.position[axis])

    def moved(self, head: int, block: Block) -> None:
        """A head's move went out: where it stands (and, for a move of its program, the CL
        point it has reached), and on a common axis where the other head now stands."""
        assert block.position is not None
        self.out.positions[head] = block.position
        if not self.making:
            self.cl_points[head] = block.position
        axis = self.axis
        if axis is not None and axis < len(block.position):
            self._drag(3 - head, block.position[axis])

    def _drag(self, head: int, coordinate: int) -> None:
        positions = self.out.positions
        at = positions[head]
        if at is not None and self.axis is not None and at[self.axis] != coordinate:
            changed = list(at)
            changed[self.axis] = coordinate
            positions[head] = tuple(changed)

    def before_alone(self, block: Block) -> None:
        """On a common axis: a head's move starts from its own point (a return first when
        the axis has moved it, or it is parked), and the other head is parked before this
        one moves along the axis; a dwell is made where the head's program left it."""
        if self.axis is None or self.making or block.code is Code.FROM:
            return
        head = block.head or 1
        if block.steps is None or block.position is None:
            if block.code is Code.DWELL and self.cl_points[head] is not None:
                self._to_start(head, self.cl_points[head], block.record)  # type: ignore[arg-type]
            return
        start = _start(block)
        at = self.out.positions[head]
        quantum = self.out.head_outputs[head - 1].quanta[self.axis]
        if block.steps[self.axis] != 0 or (
            at is not None and abs(at[self.axis] - start[self.axis]) >= quantum
        ):
            self._clear_way(3 - head, block.record)
        self._to_start(head, start, block.record)

    def before_combined(self, first: Block, second: Block) -> None:
        """On a common axis: both heads at their own points before they cut together."""
        if self.axis is None or self.making:
            return
        for _ in range(2):  # (a return along the axis parks the other head: once more)
            for block in (first, second):
                if block.steps is not None and block.position is not None:
                    self._to_start(block.head or 1, _start(block), block.record)

    def _to_start(self, head: int, start: tuple[int, ...], record: int | None) -> None:
        """RETHD/DRETHD: the head back to ``start``: withdrawn first if it is in the work,
        the other head parked first when the way back moves the common axis, along the
        axis at the parked level, then into the work by its SAFETY (001 L7980-7990)."""
        out = self.out
        at = out.positions[head]
        quanta = out.head_outputs[head - 1].quanta
        if at is None or (not self.parked[head] and _near(at, start, quanta)):
            return
        axis = self.axis
        assert axis is not None
        if axis < len(at) and abs(at[axis] - start[axis]) >= quanta[axis]:
            self._clear_way(3 - head, record)
        if not self.parked[head] and self.safety[head] is not None:
            self.park(head, record)  # (a head in the work leaves it before it moves away)
        at = out.positions[head]
        assert at is not None
        step = out.head_outputs[head - 1].step
        safety = self.safety[head]
        steps = [round(d / step) for d in safety] if safety is not None else []
        parked_at = list(start)
        if self.parked[head] and steps:
            for index, count in enumerate(steps[: len(parked_at)]):
                parked_at[index] += count
        if self.parked[head]:
            self.parked[head] = False
            out.text(f"HEAD {head} RETURNED TO THE WORK", record)
        self.making += 1
        try:
            over = [p - a for p, a in zip(parked_at, at, strict=False)]
            if any(over):
                self._rapid(head, tuple(d * step for d in over), record)
            at = out.positions[head]
            assert at is not None
            down = [s - a for s, a in zip(start, at, strict=False)]
            if any(down):
                self._rapid(head, tuple(d * step for d in down), record)
        finally:
            self.making -= 1

    def _clear_way(self, head: int, record: int | None) -> None:
        """The head is parked before the other moves the common axis under it; with no
        SAFETY it rides along in the work, with a diagnostic once."""
        if self.parked[head] or self.out.positions[head] is None:
            return
        if self.safety[head] is None:
            if not self.dragged_warned[head]:
                self.dragged_warned[head] = True
                self.out.warn(
                    Diagnostic(
                        f"HEAD {head} MOVES WITH THE COMMON AXIS IN THE WORK: NO SAFETY WAS "
                        "GIVEN TO PARK IT",
                        None,
                    )
                )
            return
        self.park(head, record)


def _near(at: tuple[int, ...], point: tuple[int, ...], quanta: list[int]) -> bool:
    """Within the tape's smallest value of ``point`` on every axis: no move to make."""
    return all(abs(a - p) < q for a, p, q in zip(at, point, quanta, strict=False))


def _start(block: Block) -> tuple[int, ...]:
    """The point a move starts from (steps): where it ends less its departures."""
    assert block.position is not None and block.steps is not None
    steps = block.steps + (0,) * (len(block.position) - len(block.steps))
    return tuple(p - s for p, s in zip(block.position, steps, strict=True))
