"""Spindle type 16: type 3 with speed codes that are not unit increasing (manual §4.5.17,
001 L15465-15517; TYPE16 L39784-39815).

Like type 3, the speed is given by an S code and an M code for its range, but the S codes
do not rise by one from row to row, so they are stored: with R = option 7 ranges of
N = option 8 speeds, SRTAB(1..N) holds range 1's speeds, SRTAB(N+1..2N) range 2's, and so
on, and the N speed codes follow the last range, SRTAB(R x N + 1 .. (R + 1) x N). The code of
a row is the same in every range. With the manual's codes 00, 02, 05, 15, 20, 30 and ranges
50-300 and 250-1500 RPM, 750 RPM is S05 with range 2's M code.

The range is the lowest that holds the speed unless RANGE,n is given; option 90 chooses
between table speeds and a speed outside the table gets its nearer end, with comment 80 or
63. The M codes follow type 3 (§4.5.4): when the machine has M03/M04 (TABLEM 4, 5), each
range has one range code (the same code in TABLEM(69 + 2n) and (70 + 2n)), output when it
differs from the last one; when TABLEM 4 and 5 are empty, TABLEM(70 + 2n) and (69 + 2n) are
combined range-and-direction codes (CLW, CCLW) output on a start, a reversal or a range
change.
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.absent import ABSENT
from gecent.core.errors import MachineDefinitionError
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.catalogue import STORE_SIZE
from gecent.core.machine.definition import MachineDefinition
from gecent.core.spindle_types import (
    CCLW,
    CLW,
    SpindleRequest,
    SpindleSelection,
    TableSpindle,
    check_ascending,
    choose_speed,
)

LAST_RANGE_CELL = 82  # TABLEM 71-82: range codes for at most six ranges

EXAMPLE = """
[machine]
name = "type16-example"
title = "TYPE 16 SPINDLE"
[optab]
7 = 2.0
8 = 6.0
19 = 16.0
[tablem]
71 = 41
72 = 41
73 = 42
74 = 42
[spindle_table]
speeds = [
  50.0, 100.0, 150.0, 200.0, 250.0, 300.0,
  250.0, 500.0, 750.0, 1000.0, 1250.0, 1500.0,
  0.0, 2.0, 5.0, 15.0, 20.0, 30.0,
]
"""


def _direction_cells(number: int) -> dict[int, int]:
    return {CLW: 70 + 2 * number, CCLW: 69 + 2 * number}


@dataclass(frozen=True)
class StoredCodeSpindle(TableSpindle):
    number: int = 16
    name: str = "type 3 with non-unit-increasing codes"
    section: str = "§4.5.17"
    # TYPE16 prints "NO DIRECTION GIVEN IN FIRST SPINDLE STATEMENT" (001 L39790-39810)
    names_missing_direction: bool = True
    manual_example: str = EXAMPLE

    def table(
        self, machine: MachineDefinition
    ) -> tuple[tuple[tuple[float, ...], ...], tuple[float, ...]]:
        """The speeds by range and the speed codes stored after the last range."""
        ranges = machine.spindle_ranges()
        count, per_range = int(machine.number_option(7)), int(machine.number_option(8))
        if len(machine.spindle_speeds()) != count * per_range:
            raise MachineDefinitionError(
                machine.origin,
                "spindle_table",
                "speeds",
                f"spindle type 16 needs option 7 x option 8 = {count * per_range} speeds in "
                f"SRTAB before its codes; found {len(machine.spindle_speeds())}",
            )
        check_ascending(machine, ranges, "spindle type 16")
        codes = []
        for index in range(count * per_range + 1, (count + 1) * per_range + 1):
            code = machine.srtab(index) if index <= STORE_SIZE else ABSENT
            if code is ABSENT or float(code) < 0:
                raise MachineDefinitionError(
                    machine.origin,
                    "spindle_table",
                    f"SRTAB({index})",
                    f"spindle type 16 keeps the speed codes after its {count} ranges of "
                    f"{per_range} speeds, in SRTAB({count * per_range + 1}.."
                    f"{(count + 1) * per_range}), each a number >= 0; SRTAB({index}) is "
                    + ("empty" if code is ABSENT else f"{code:g}"),
                )
            codes.append(float(code))
        self._check_m_codes(machine, count)
        return ranges, tuple(codes)

    def _check_m_codes(self, machine: MachineDefinition, count: int) -> None:
        combined = machine.m_code(4) is None and machine.m_code(5) is None
        if not combined and count == 1:
            return  # one range: M03/M04 and no range code are enough
        for number in range(1, count + 1):
            cells = sorted(_direction_cells(number).values())
            have = [c for c in cells if c <= LAST_RANGE_CELL and machine.m_code(c) is not None]
            if (combined and len(have) < 2) or not have:
                raise MachineDefinitionError(
                    machine.origin,
                    "tablem",
                    cells[0],
                    f"spindle type 16 range {number} needs "
                    + (
                        f"its CCLW and CLW range codes in TABLEM({cells[0]}) and "
                        f"TABLEM({cells[1]}) (TABLEM 4 and 5 are empty)"
                        if combined
                        else f"its range code in TABLEM({cells[0]}) and TABLEM({cells[1]})"
                    )
                    + " (TABLEM 71-82 hold six ranges)",
                )

    def ranges(self, machine: MachineDefinition) -> tuple[tuple[float, ...], ...]:
        return self.table(machine)[0]

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        ranges, codes = self.table(machine)
        choice = choose_speed(ranges, request.speed, request.range, machine.number_option(90))
        number = choice.range
        cells = _direction_cells(number)
        combined = machine.m_code(4) is None and machine.m_code(5) is None
        direction_cells = cells if combined else None
        range_cell = None
        if not combined:
            # the range's code sits in both of its slots; a one-range machine may have none
            slots = (cells[request.direction], cells[-request.direction])
            range_cell = next((c for c in slots if machine.m_code(c) is not None), None)
        return SpindleSelection(
            choice.speed,
            codes[choice.row],
            number,
            choice.comments,
            direction_cells=direction_cells,
            range_cell=range_cell,
            row=choice.row,
        )


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(StoredCodeSpindle())
