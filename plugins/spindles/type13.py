"""Spindle type 13: expanded quasi-EIA 3-digit code, for two heads (manual §4.5.14,
001 L15189-15312; TYPE13 L39618-39680).

Like type 4, every range uses the same S code for a row: the EIA "magic three" code of the
actual RPM in range 1 in that row (100 RPM in range 2 of the manual's table is S512, the
code of 12 RPM in its second row). The M code names range and direction, as for type 4:
TABLEM(70 + 2n) CLW and TABLEM(69 + 2n) CCLW for range n.

A machine with more speeds than SRTAB holds stores only the range-1 speeds and, for each
range and head, the multiple of them that the range turns: a range-r speed is the range-1
speed of its row times the factor of range r. SRTAB is laid out so that the usual testing
stays consistent (option 7 = ranges per head, option 8 = 2):

* SRTAB(1 .. 2 x ranges x heads): minimum and maximum of each range, head 1 first;
* SRTAB(M), M = STRTPT = SRTAB(180): N, the number of range-1 speeds;
* SRTAB(M + 1 ...): the factors, range 1 head 1, range 2 head 1, ..., then head 2;
* then the N range-1 speeds (SRTAB(M + 5 ... M + 4 + N) for two ranges and two heads).

The number of heads is what fits before STRTPT: (M - 1) / (2 x option 7). The range is the
lowest whose limits hold the speed (or RANGE,n); the speed is then the range's exact
product, or by option 90 the next lower, closest or next higher one; outside the products
the nearer end, with comment 80 or 63.
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.absent import ABSENT
from gecent.core.errors import MachineDefinitionError
from gecent.core.feed.magic3 import magic3
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.catalogue import STORE_SIZE
from gecent.core.machine.definition import MachineDefinition
from gecent.core.spindle_types import (
    CCLW,
    CLW,
    SpindleRequest,
    SpindleSelection,
    check_ascending,
    choose_speed,
    range_for,
)

STRTPT_CELL = 180  # SRTAB(180) holds the index of STRTPT (001 L15262-15264)

# The manual's two-range, two-head layout with the range-1 speeds of its §4.5.14 table
# (10, 12, 20, 52, 77 RPM). Its range-2 column (88, 100, 200, 300, 450) is no single
# multiple of range 1, which a type-13 table must be; range 2 here is 100/12 of range 1,
# so that 100 RPM in range 2 is the second row, as in the manual's example.
EXAMPLE = """
[machine]
name = "type13-example"
title = "TYPE 13 SPINDLE"
[optab]
7 = 2.0
8 = 2.0
19 = 13.0
[tablem]
4 = "absent"
5 = "absent"
71 = 41
72 = 40
73 = 43
74 = 42
[spindle_table]
speeds = [
  10.0, 77.0, 83.33333333333334, 641.6666666666667,
  20.0, 154.0, 100.0, 770.0,
  5.0,
  1.0, 8.333333333333334, 2.0, 10.0,
  10.0, 12.0, 20.0, 52.0, 77.0,
]
cells = { 180 = 9.0 }
"""


@dataclass(frozen=True, slots=True)
class Layout:
    """A type-13 SRTAB read: per head, the limits and the speeds of each range, and the
    range-1 speeds that give the codes."""

    heads: int
    limits: tuple[tuple[tuple[float, float], ...], ...]
    speeds: tuple[tuple[tuple[float, ...], ...], ...]
    first_range: tuple[tuple[float, ...], ...]


def _cell(machine: MachineDefinition, index: int, what: str) -> float:
    value = machine.srtab(index) if 1 <= index <= STORE_SIZE else ABSENT
    if value is ABSENT:
        raise MachineDefinitionError(
            machine.origin,
            "spindle_table",
            f"SRTAB({index})",
            f"spindle type 13 keeps {what} in SRTAB({index}); it is empty",
        )
    return float(value)


def _reject(machine: MachineDefinition, entry: str, rule: str) -> MachineDefinitionError:
    return MachineDefinitionError(machine.origin, "spindle_table", entry, rule)


def read_layout(machine: MachineDefinition) -> Layout:
    ranges = int(machine.number_option(7))
    if machine.number_option(8) != 2:
        raise MachineDefinitionError(
            machine.origin,
            "optab",
            8,
            "spindle type 13 needs option 8 = 2 (a minimum and a maximum per range); "
            f"found {machine.number_option(8):g}",
        )
    strtpt = _cell(machine, STRTPT_CELL, "the index of STRTPT")
    heads, spare = divmod(int(strtpt) - 1, 2 * ranges)
    if strtpt != int(strtpt) or heads < 1 or spare:
        raise _reject(
            machine,
            f"SRTAB({STRTPT_CELL})",
            "spindle type 13: SRTAB(180) must be the index of STRTPT, just after the "
            f"minimum and maximum of option 7 = {ranges} ranges per head for each head "
            f"(1 + 2 x {ranges} x heads); found {strtpt:g}",
        )
    start = int(strtpt)
    count = _cell(machine, start, "N, the number of range-1 speeds")
    first_speed = start + 1 + heads * ranges
    if count != int(count) or count < 1 or first_speed + int(count) - 1 >= STRTPT_CELL:
        raise _reject(
            machine,
            f"SRTAB({start})",
            "spindle type 13: STRTPT holds the number of range-1 speeds, which must fit "
            f"from SRTAB({first_speed}) up to SRTAB({STRTPT_CELL - 1}); found {count:g}",
        )
    base = tuple(
        _cell(machine, i, f"range-1 speed {i - first_speed + 1}")
        for i in range(first_speed, first_speed + int(count))
    )
    if base[0] <= 0:
        raise _reject(
            machine, f"SRTAB({first_speed})", "spindle type 13: speeds must be above 0 RPM"
        )
    check_ascending(machine, (base,), "spindle type 13 range-1 speeds")
    limits = []
    speeds = []
    first_range = []
    for head in range(heads):
        head_limits = []
        head_speeds = []
        for r in range(ranges):
            slot = head * ranges + r
            low = _cell(machine, 2 * slot + 1, f"the minimum of range {r + 1}, head {head + 1}")
            high = _cell(machine, 2 * slot + 2, f"the maximum of range {r + 1}, head {head + 1}")
            factor = _cell(machine, start + 1 + slot, f"the factor of range {r + 1}")
            if not 0 < low <= high or factor <= 0:
                raise _reject(
                    machine,
                    f"SRTAB({2 * slot + 1})",
                    f"spindle type 13 range {r + 1}, head {head + 1}: needs 0 < minimum <= "
                    f"maximum and a factor above 0; found {low:g}, {high:g} and factor "
                    f"SRTAB({start + 1 + slot}) = {factor:g}",
                )
            head_limits.append((low, high))
            head_speeds.append(tuple(s * factor for s in base))
        limits.append(tuple(head_limits))
        speeds.append(tuple(head_speeds))
        first_range.append(head_speeds[0])
        if magic3(head_speeds[0][0]) is None or magic3(head_speeds[0][-1]) is None:
            raise _reject(
                machine,
                f"SRTAB({first_speed})",
                f"spindle type 13: the range-1 speeds of head {head + 1} must lie within "
                f"magic three's 0.0001 .. 9999; found {head_speeds[0][0]:g} .. "
                f"{head_speeds[0][-1]:g}",
            )
    return Layout(heads, tuple(limits), tuple(speeds), tuple(first_range))


@dataclass(frozen=True)
class ExpandedQuasiEiaSpindle:
    number: int = 13
    name: str = "expanded quasi-EIA 3-digit code (two heads)"
    section: str = "§4.5.14"
    # TYPE13 prints "NO DIRECTION GIVEN IN FIRST SPINDLE STATEMENT" (001 L39664-39667)
    names_missing_direction: bool = True
    manual_example: str = EXAMPLE

    def range_count(self, machine: MachineDefinition) -> int:
        return int(machine.number_option(7))

    def speed_limits(self, machine: MachineDefinition, range_number: int) -> tuple[float, float]:
        return read_layout(machine).limits[0][range_number - 1]

    def table_speeds(
        self, machine: MachineDefinition, range_number: int
    ) -> tuple[float, ...] | None:
        return read_layout(machine).speeds[0][range_number - 1]

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        layout = read_layout(machine)
        if not 1 <= request.head <= layout.heads:
            raise _reject(
                machine,
                f"SRTAB({STRTPT_CELL})",
                f"spindle type 13: head {request.head} has no ranges; the layout holds "
                f"{layout.heads} head(s)",
            )
        head = request.head - 1
        number = range_for(layout.limits[head], request.speed, request.range)
        choice = choose_speed(layout.speeds[head], request.speed, number, machine.number_option(90))
        code = magic3(layout.first_range[head][choice.row])
        assert code is not None  # read_layout keeps range 1 within magic three's span
        return SpindleSelection(
            choice.speed,
            float(code),
            number,
            choice.comments,
            direction_cells={CLW: 70 + 2 * number, CCLW: 69 + 2 * number},
            row=choice.row,
        )


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(ExpandedQuasiEiaSpindle())
