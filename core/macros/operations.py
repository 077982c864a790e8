"""Operation variables (spec 09 §9, seed 003): the operation table and the travel, time,
feed and speed a run has made per operation, kept as the blocks go out.

A new operation (a row) starts at every tool change, and at the second and later OPTYPE
between two tool changes unless ``$OPMERGE`` (003 L32-34). Row 1 is the dummy operation
(what came before the first); in ``max``/``min`` row 1 is the whole program to date. After
999 rows the tables stop growing and stop being updated (003 L58, L90-91).

``ctx.ops.tab[8, ctx.ops.oi]`` is ``$OPTAB(8,$OI)``, the start N of the current operation
(X19). Tables index (column, row) from 1; a row that does not exist is an error naming it.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from gecent.core.absent import ABSENT
from gecent.core.macros.model import MacroError
from gecent.core.output.block import Code

if TYPE_CHECKING:
    from gecent.core.output.block import Block
    from gecent.core.output.sinks import Ending
    from gecent.core.state import PostState

MAX_OPS = 999
OPTAB_COLUMNS = 50
AXIS_COLUMNS = 15  # X Y Z, U V W, A' B' C', A B C, quill, N1 N2 (the $TRANS layout)
SUM_COLUMNS = 7
# $OPTAB's built-in columns (003 L59-92)
TOOL, HEAD, OPTYPE, OPARGS, OPNAME, START_TIME, END_TIME, START_N, END_N, SEVERITY = range(1, 11)
LENGTH_OFFSETS, DIAMETER_OFFSETS, FIXTURE_OFFSETS = 11, 12, 13
FEED_TIME, POSITION_TIME, OTHER_TIME, FEED_MIN, FEED_MAX, SPEED_MIN, SPEED_MAX = range(1, 8)
NOT_PROCESSED = -3  # $OPTYPE before any OPTYPE (003 L93-109)


class Table:
    """A (column, row) table, both 1-based; ``writable`` False refuses writes (``$OPSUM``)."""

    def __init__(self, name: str, columns: int, blank: Any, writable: bool = True) -> None:
        self.name = name
        self.columns = columns
        self.blank = blank
        self.writable = writable
        self.rows: list[list[Any]] = []

    def add_row(self) -> None:
        self.rows.append([self.blank] * self.columns)

    def _cell(self, key: tuple[int, int]) -> tuple[int, int]:
        column, row = key
        if not 1 <= row <= len(self.rows):
            raise MacroError(f"${self.name} has rows 1 to {len(self.rows)}, not {row}")
        if not 1 <= column <= self.columns:
            raise MacroError(f"${self.name} has columns 1 to {self.columns}, not {column}")
        return column - 1, row - 1

    def __getitem__(self, key: tuple[int, int]) -> Any:
        column, row = self._cell(key)
        return self.rows[row][column]

    def __setitem__(self, key: tuple[int, int], value: Any) -> None:
        if not self.writable:
            raise MacroError(f"${self.name} is read-only")
        column, row = self._cell(key)
        self.rows[row][column] = value

    def put(self, column: int, row: int, value: Any) -> None:
        """The engine's own write."""
        self.rows[row - 1][column - 1] = value


class Operations:
    def __init__(self) -> None:
        self.tab = Table("OPTAB", OPTAB_COLUMNS, None)
        self.max = Table("OPMAX", AXIS_COLUMNS, None)
        self.min = Table("OPMIN", AXIS_COLUMNS, None)
        self.sum = Table("OPSUM", SUM_COLUMNS, 0.0, writable=False)
        self.oi = 1  # $OI
        self.foi = 0  # $FOI
        self.optype: float = NOT_PROCESSED  # $OPTYPE
        self.opargs: tuple[Any, ...] = ()  # $OPARGS
        self.opname = ""  # $OPNAME
        self.merge = False  # $OPMERGE
        self.full = False
        self._optypes_since_tool = 0
        self._tool: float | None = None
        self._minutes = 0.0  # the run's time so far (feed, positioning and dwell)
        self._add_row()

    @property
    def size(self) -> int:
        """$OPSIZ."""
        return len(self.tab.rows)

    def _add_row(self) -> None:
        if self.size >= MAX_OPS:
            self.full = True
            return
        for table in (self.tab, self.max, self.min, self.sum):
            table.add_row()
        row = self.size
        self.sum.put(FEED_MIN, row, 10000.0)
        self.sum.put(FEED_MAX, row, -1.0)
        self.tab.put(TOOL, row, self._tool)
        self.tab.put(OPTYPE, row, self.optype)
        self.tab.put(OPARGS, row, self.opargs)
        self.tab.put(OPNAME, row, self.opname)
        self.tab.put(START_TIME, row, self._minutes * 60.0)
        self.oi = row
        if self.foi == 0:
            self.foi = row

    def reset_travel(self, row: int) -> None:
        """PPFUN/23,OP,row: the row's travel back to None (003 L12-31)."""
        self.max._cell((1, row))
        for table in (self.max, self.min):
            table.rows[row - 1] = [None] * table.columns

    def tool_change(self, tool: float | None) -> None:
        """A new operation at every tool change; $FOI starts again (003 L3-5)."""
        self._tool = tool
        self.foi = 0
        self._optypes_since_tool = 0
        self._add_row()

    def operation_type(self, optype: float, opargs: tuple[Any, ...]) -> None:
        """OPTYPE, after the OE macro: the new values, and a row from the second OPTYPE
        since the tool change on, unless $OPMERGE (003 L32-34)."""
        self.optype = optype
        self.opargs = opargs
        self._optypes_since_tool += 1
        if self._optypes_since_tool > 1 and not self.merge:
            self._add_row()
        elif not self.full:
            self.tab.put(OPTYPE, self.oi, optype)
            self.tab.put(OPARGS, self.oi, opargs)

    def block(self, block: Block, state: PostState, step: float) -> None:
        """A block on its way out: times, N, travel, feed and speed into the rows."""
        self._minutes += block.cut_minutes + block.dwell_minutes
        if self.full:
            return
        row = self.oi
        rows = (1, row) if row != 1 else (1,)
        sequence = block.cells[1]
        if sequence is not ABSENT:
            if self.tab[START_N, row] is None:
                self.tab.put(START_N, row, float(sequence))
            self.tab.put(END_N, row, float(sequence))
        self.tab.put(END_TIME, row, self._minutes * 60.0)
        if block.code is Code.COMMENT:  # a diagnostic (gecent's are warnings: severity 1)
            self.tab.put(SEVERITY, row, 1.0)
            return
        seconds = block.cut_minutes * 60.0
        summary = self.sum.rows[row - 1]
        summary[(POSITION_TIME if block.rapid else FEED_TIME) - 1] += seconds
        summary[OTHER_TIME - 1] += block.dwell_minutes * 60.0
        if block.position is None or block.steps is None:
            return
        for number in rows:
            for axis, steps in enumerate(block.position[:3]):
                value = steps * step
                low, high = self.min.rows[number - 1], self.max.rows[number - 1]
                low[axis] = value if low[axis] is None else min(low[axis], value)
                high[axis] = value if high[axis] is None else max(high[axis], value)
        if not block.rapid:
            feed = state.feed.ipm
            summary[FEED_MIN - 1] = min(summary[FEED_MIN - 1], feed)
            summary[FEED_MAX - 1] = max(summary[FEED_MAX - 1], feed)
        spindle = state.spindle
        if spindle.on and spindle.speed:
            speed = float(spindle.speed)
            low_speed = summary[SPEED_MIN - 1]
            summary[SPEED_MIN - 1] = speed if low_speed == 0.0 else min(low_speed, speed)
            summary[SPEED_MAX - 1] = max(summary[SPEED_MAX - 1], speed)


class OperationSink:
    """The operation tables' place among the outputs: it sees every block the run emits."""

    def __init__(self, operations: Operations, state: PostState) -> None:
        self.operations = operations
        self.state = state
        self.step = state.machine.number_option(14)

    def block(self, block: Block, line: str | None) -> None:
        self.operations.block(block, self.state, self.step)

    def close(self, ending: Ending) -> None:
        return None
