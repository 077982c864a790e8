"""The turret of a contouring lathe: COMTAT's T word (option 96) and the turret corrective
moves of TURRET/..., NOW and NEXT (manual TURRET 001 L39054-39091, COMTAT L29715-29760,
REFATL/REFBTL L18118-18130, option 96 L25520-25569, option 106 L25666-25680, CODE -3
L9225-9233, information block 7 L22232-22238, fatal 41 L28419-28421).

A tool in the working position has its tip at distance A from the turret centre parallel
to the spindle (the machine's Z) and B across it (the machine's X), as TURRET/t, p, a, b
gives them. When the turret indexes to a tool whose A and B differ from the last tool's,
the turret centre must move by the difference to keep the tip where the part program has
it:

* NOW: at once, a corrective move (CODE -3) processed as a line, segmented within option 4
  (comment "TURRET CORRECTIVE MOVE EXCEEDED MAXIMUM DEPARTURE AND HAS BEEN SEGMENTED"), the
  tool's point unchanged (the Absolute print does not sum it);
* NEXT: in the next move, the previous point (DPREVP, DPREVM) moved back by the correction,
  with the information block 7 carrying it (never printed or punched).

On an absolute control (option 251 = 1) the positions are the tool's point, the new tool's
once its T word has called the offset: NOW is a line to the same point with every axis
stated; NEXT needs nothing more than the shift (the next move's words are the point). The
corrective move is the lathe's (GELATH, 001 L1244-1250): a multiaxis machine (a mill,
GEMAXS, L1598-1604) has none, bad input. On a multihead machine each head's run has its
own correction (its own distances), its CODE -3 blocks go to the head's scratch tape, and
the merge pass pairs one with the other head's motion (CODE +-14, core/multihead/gmout.py).

The tool-length corrections of TOOLNO/LENGTH use the same shift of the previous point
(:func:`shift_previous`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from gecent.core.errors import Diagnostic, FatalError, InputError, SourcePosition
from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.rounding import to_steps
from gecent.core.motion.segments import segment_count, segment_place, segments
from gecent.core.output.block import Block, Code

if TYPE_CHECKING:
    from gecent.core.output.element import OutputElement
    from gecent.core.state import PostState

SEGMENTED = "TURRET CORRECTIVE MOVE EXCEEDED MAXIMUM DEPARTURE AND HAS BEEN SEGMENTED"
MACHINE_X, MACHINE_Z = 3, 5  # DBFSEG cells of the machine's X and Z
TURRET_NEXT = 7.0  # information block 7: the NEXT correction (001 L22232-22238)

# option 96: the T word's fields, first digit first, with their digit counts (001
# L25532-25560). The OCR damaged the type column; 0 and 3-6 are legible, 2 is the sample
# lathe's five-digit layout (MACH04: option 96 = 2, T format 50); 7 and 1 are read in
# docs/decisions.md (7: offset, then the tool position in two digits; 1: the five digits
# split 1-2-2, the split type 2 does not take).
T_LAYOUTS: dict[int, tuple[tuple[str, int], ...]] = {
    0: (("tool", 0),),
    1: (("offset", 1), ("tool", 2), ("position", 2)),
    2: (("offset", 2), ("tool", 2), ("position", 1)),
    3: (("tool", 1), ("position", 1)),
    4: (("tool", 1), ("offset", 1)),
    5: (("offset", 1), ("tool", 1)),
    6: (("offset", 1), ("tool", 1), ("position", 1)),
    7: (("offset", 1), ("position", 2)),
}


def comtat(
    machine: MachineDefinition, tool: int, position: int, offset: int, where: SourcePosition
) -> int:
    """COMTAT: the fields of option 96's layout, packed first digit first. A negative
    option 96 gives the offset as an M code (the caller's), so T is the tool alone."""
    layout_type = int(machine.number_option(96))
    layout = T_LAYOUTS[0] if layout_type < 0 else T_LAYOUTS.get(layout_type)
    if layout is None:
        raise InputError(
            f"option 96 = {layout_type} is no T-word layout (0-7, or negative for an offset "
            "M code)",
            where,
        )
    values = {"tool": tool, "position": position, "offset": offset}
    code = 0
    for field, digits in layout:
        value = values[field]
        if digits and value >= 10**digits:
            raise InputError(
                f"TURRET {field} {value} does not fit the {digits} digit(s) option 96 = "
                f"{layout_type} gives it",
                where,
            )
        code = code * 10**digits + value if digits else value
    return code


def cl_deltas(output: OutputElement, machine_deltas: dict[int, float]) -> list[float]:
    """Distances along the machine's X, Y, Z (cells 3-5) as CL-axis distances, through
    option 59's axes and signs (SHUFFL read backwards)."""
    deltas = [0.0, 0.0, 0.0]
    for axis, target in enumerate(output.words.shuffle[:3]):
        if target is not None and target[0] in machine_deltas:
            cell, sign = target
            deltas[axis] = sign * machine_deltas[cell]
    return deltas


def shift_previous(state: PostState, deltas: list[float]) -> None:
    """DPREVP and DPREVM moved back by a correction, so the next departure carries it; the
    point the next move reaches (the tool's point) is not changed."""
    position = state.position
    step = state.machine.number_option(14)
    for axis, delta in enumerate(deltas):
        if delta:
            position.previous_part[axis] -= delta
            position.previous[axis] -= to_steps(delta, step)  # in place: the fast path's list


class TurretCorrection:
    """REFATL, REFBTL: the distances of the tool in the working position, and the corrective
    move when the next tool's differ."""

    def __init__(
        self, state: PostState, output: OutputElement, warn: Callable[[Diagnostic], None]
    ) -> None:
        self.state = state
        self.output = output
        self.warn = warn
        self.distances: tuple[float, float] | None = None  # (A, B) in machine units

    def index(
        self,
        where: SourcePosition,
        record: int,
        distances: tuple[float, float] | None,
        when: str | None,
    ) -> None:
        """The turret has indexed to a tool with ``distances`` (None: not given);
        ``when`` is NOW, NEXT or None (no corrective move)."""
        if when is not None and distances is None:
            raise InputError(
                f"TURRET/{when} needs the tool's distances: TURRET/t, p, a, b, {when}", where
            )
        if when is not None:
            self._check_machine(when, where)
        previous, self.distances = self.distances, distances or self.distances
        if when is None or previous is None or distances is None:
            return  # the first tool sets the turret's reference: nothing to correct
        machine_deltas = {
            MACHINE_Z: previous[0] - distances[0],
            MACHINE_X: previous[1] - distances[1],
        }
        deltas = cl_deltas(self.output, machine_deltas)
        if not any(deltas):
            return
        if when == "NEXT":
            shift_previous(self.state, deltas)
            block = Block(Code.INFORMATION, record)
            block.cells[2] = TURRET_NEXT
            block.cells[3], block.cells[4] = machine_deltas[MACHINE_X], 0.0
            self.output.emit(block)
        else:
            self._now(where, record, deltas)

    def _check_machine(self, when: str, where: SourcePosition) -> None:
        machine = self.state.machine
        if not machine.number_option(106):
            raise InputError(
                f"TURRET/{when}: the machine has no turret for corrective moves (option 106, "
                "the number of turret positions, is 0)",
                where,
            )
        if machine.multiaxis:
            raise InputError(
                f"TURRET/{when}: a turret corrective move belongs to the lathe program "
                "(GELATH, 001 L1244-1250); a multiaxis machine (option 116) is a milling "
                "machine (GEMAXS, L1598-1604) and has no turret to correct",
                where,
            )

    def _now(self, where: SourcePosition, record: int, deltas: list[float]) -> None:
        """The corrective move in CODE -3 blocks, as lines (G code and feed as CODE 0)."""
        state = self.state
        step = state.machine.number_option(14)
        departures = [to_steps(d, step) for d in deltas]
        if state.machine.number_option(251) == 1:  # absolute positions (modern.py)
            self._absolute_now(where, record, departures, step)
            return
        depmax = max(1, round(state.machine.number_option(4) / step))
        count = segment_count(departures, [depmax] * 3)
        if state.max_segments and count > state.max_segments:
            raise FatalError(41, f"a correction of {count:,} segments", where)
        if count > 1:
            self.warn(Diagnostic(SEGMENTED, where))
        reached = tuple(state.position.previous[:3])
        parts = segments(departures, count) if count > 1 else (tuple(departures),)
        for index, part in enumerate(parts):
            block = Block.motion(Code.LINEAR, record, part, reached, step)
            block.segment = segment_place(index, count)
            try:
                self.output.motion(block)
            except FatalError as error:
                if error.number in (138, 139):
                    raise FatalError(41, error.detail, where) from None
                raise
            block.code = Code.TURRET_CORRECTION
            self.output.output(block)

    def _absolute_now(
        self, where: SourcePosition, record: int, departures: list[int], step: float
    ) -> None:
        """An absolute control (option 251 = 1): its positions are the tool's point, the new
        tool's once the T word has called its offset, so the corrective move is a move to
        the same point, every axis stated; the turret centre moves by the correction. One
        block: the control makes the move, option 4's segments are departures' business.
        It goes out as a line (CODE 0) because only lines take the absolute words (GEOUT's
        placing), and its departure (the correction) gives its G code and feed time."""
        reached = tuple(self.state.position.previous[:3])
        block = Block.motion(Code.LINEAR, record, tuple(departures), reached, step)
        self.output.modern.forget()  # the new tool's positions: every axis is stated
        try:
            self.output.output(block)
        except FatalError as error:
            if error.number in (138, 139):
                raise FatalError(41, error.detail, where) from None
            raise
