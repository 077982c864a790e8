"""Spindle type 9: associated speed code related to tool number (manual §4.5.10,
001 L15010-15039; TYPE09 L39426-39460).

Like type 8 (§4.5.9), the speed code is the row of the speed in its range plus option 47,
independent of the range; but the range is given by the tool in use. The manual's table
is headed "Range 1 = Tools 1 & 4, Range 2 = Tools 2 & 5, Range 3 = Tools 3 & 6", and its
example agrees: speed 50 is S04 with tool 1 (range 1, row 4) and S01 with tool 5 (range 2,
row 1). Tools cycle through the ranges in that order however many tools (option 88) and
ranges (option 7) there are: tool t turns in range ((t - 1) mod ranges) + 1. (The text
after the example and TYPE09 list the reverse order, tools 1, 4, 7 in range 3, which
contradicts the example; docs/decisions.md.)

A programmed RANGE,n cannot move the spindle out of the tool's range: the tool's range is
used, with a comment when they differ. With no tool in use the programmed range is used,
else the lowest range that holds the speed, with the manual's comment "LOWEST RANGE THAT
SPINDLE SPEED FALLS IN IS ASSUMED".
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.core.spindle_types import SpindleRequest, SpindleSelection, choose_speed
from gecent.plugins.spindles.type08 import RangeFreeSpeedCodeSpindle

LOWEST_RANGE_ASSUMED = "LOWEST RANGE THAT SPINDLE SPEED FALLS IN IS ASSUMED"

# The §4.5.10 table: three ranges of five speeds, codes 0..4 (001 L15016-15026).
MANUAL_EXAMPLE = """
[machine]
name = "spindle-type09"
title = "TYPE 9 SPINDLE (4.5.10)"
[optab]
7 = 3.0
8 = 5.0
19 = 9.0
47 = 0.0
88 = 6.0
[regfor]
12 = 20.0
[spindle_table]
speeds = [
  10.0, 20.0, 30.0, 40.0, 50.0,
  40.0, 50.0, 60.0, 70.0, 80.0,
  70.0, 80.0, 90.0, 100.0, 110.0,
]
"""


def range_not_used(programmed: int, tool: int, used: int) -> str:
    return f"RANGE {programmed} IS NOT USED, TOOL {tool} TURNS IN RANGE {used}"


@dataclass(frozen=True)
class ToolRangeSpeedCodeSpindle(RangeFreeSpeedCodeSpindle):
    number: int = 9
    name: str = "associated speed code related to tool number"
    section: str = "§4.5.10"
    manual_example: str = MANUAL_EXAMPLE

    def tool_range(self, ranges: int, tool: int) -> int:
        """The range tool ``tool`` (>= 1) turns in: the tools cycle through the ranges."""
        return (tool - 1) % ranges + 1

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        ranges = self.ranges(machine)
        comments: tuple[str, ...] = ()
        number = request.range
        tool = request.tool
        if tool is not None and tool >= 1:
            number = self.tool_range(len(ranges), tool)
            if request.range is not None and request.range != number:
                comments = (range_not_used(request.range, tool, number),)
        elif number is None:
            comments = (LOWEST_RANGE_ASSUMED,)  # choose_speed takes the lowest range (LOCRNG)
        choice = choose_speed(ranges, request.speed, number, machine.number_option(90))
        return SpindleSelection(
            choice.speed,
            self.row_code(machine, choice.row),
            choice.range,
            comments + choice.comments,
            row=choice.row,
        )


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(ToolRangeSpeedCodeSpindle())
