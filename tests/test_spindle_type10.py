"""Spindle type 10 (manual §4.5.11, 001 L15040-15111): range-and-direction M codes, EIA
magic-three S, and protective multiple shifting under a negative option 137."""

from __future__ import annotations

from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post

MANUAL_EXAMPLE = """
[machine]
name = "type10"
title = "TYPE 10 SPINDLE"
[optab]
7 = 3.0
8 = 2.0
19 = 10.0
[tablem]
71 = 61
72 = 60
73 = 63
74 = 62
75 = 65
76 = 64
[spindle_table]
speeds = [1.2, 13.0, 3.1, 31.0, 6.6, 69.0]
"""

SHIFTING = """
[machine]
name = "type10-shift"
title = "TYPE 10 SHIFTING"
[optab]
7 = 2.0
8 = 2.0
19 = 10.0
137 = -0.25
[tablem]
71 = 61
72 = 60
73 = 63
74 = 62
[spindle_table]
speeds = [6.5, 270.0, 28.0, 1200.0]
"""


def tape(lines: list[str], machine: MachineDefinition) -> list[str]:
    return tape_lines(post(lines, machine).blocks)


def test_speed_10_is_s510_with_the_range_and_direction_code() -> None:
    """001 L15060-15070: 10 RPM is S510 with M60 (range 1, CLW) or M63 (range 2, CCLW)."""
    machine = load_machine_text(MANUAL_EXAMPLE, "type10.toml")
    assert tape(["SPINDL/10,CLW"], machine) == ["N001S510M60"]
    assert tape(["SPINDL/10,CCLW,RANGE,2"], machine) == ["N001S510M63"]


def test_protective_shifting_follows_the_manual_rules() -> None:
    """Ranges 6.5-270 and 28-1200, option 137 = -0.25: shift points 67.5 and 300 RPM.
    (1) within a range, direct; (2) 10 -> 1000 RPM from below the shift point, direct;
    (3) 700 RPM in range 2 -> 20 RPM: 300 RPM (S630) with a 6-second dwell, then 20."""
    machine = load_machine_text(SHIFTING, "type10-shift.toml")
    program = ["SPINDL/10,CLW", "SPINDL/200", "SPINDL/10", "SPINDL/1000", "SPINDL/700", "SPINDL/20"]
    assert tape(program, machine) == [
        "N001S510M60",
        "N002S620",  # (1) same range
        "N003S510",
        "N004S710M62",  # (2) 10 RPM is under 67.5: straight to range 2
        "N005S670",
        "N006G04X+06S630",  # (3) the shift point of range 2 with the 6 s dwell
        "N006S520M60",
    ]


def test_mach04_lathe_spindle() -> None:
    """MACH04: ranges 4-130 and 18-600 (option 137 = -0.25), option 89 = 6 s stop on a
    reversal, its dwells in Z (option 57 = 5) and G04 on every block (option 38 = 1)."""
    lathe = get_plugins().machine("mach04").load()
    program = ["SPINDL/10,CLW", "SPINDL/500", "SPINDL/20,CCLW", "SPINDL/OFF"]
    assert tape(program, lathe) == [
        "N001G04S510M60",
        "N002G04S650M62",  # 10 RPM is below 32.5: no protective shift
        "N003G04Z+06M05",  # the reversal: M05 and option 89's 6 s dwell; stopped, so
        "N003G04S520M61",  # no protective shift (500 > 150) is needed
        "N004G04M05",
    ]
