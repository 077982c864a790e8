"""Spindle type 6: discrete EIA 3-digit code number, selective search (manual §4.5.7,
001 L14965-14979).

The machine control searches its own spindle table for the next lower EIA-coded speed it
has. The postprocessor nevertheless treats this type exactly as type 5 (§4.5.6): it finds
the exact table speed itself, which is simpler, and essential under SFM, which must step
through the machine's real speeds. So the S code is the EIA "magic three" of the next
lower speed in the single range of SRTAB.
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.hookspecs import Register, hookimpl
from gecent.plugins.spindles.type05 import DiscreteEiaSpindle

# The §4.5.6 table serves here too: the manual gives type 6 no table of its own.
MANUAL_EXAMPLE = """
[machine]
name = "spindle-type06"
title = "TYPE 6 SPINDLE (4.5.7)"
[optab]
7 = 1.0
8 = 23.0
19 = 6.0
[spindle_table]
speeds = [
  2.0, 3.0, 5.0, 7.0, 10.0, 12.0, 15.0, 17.0,
  20.0, 25.0, 30.0, 40.0, 50.0, 60.0, 80.0, 100.0, 120.0, 150.0, 170.0, 190.0,
  193.0, 197.0, 200.0,
]
"""


@dataclass(frozen=True)
class SelectiveSearchEiaSpindle(DiscreteEiaSpindle):
    number: int = 6
    name: str = "discrete EIA 3-digit code number, selective search"
    section: str = "§4.5.7"
    manual_example: str = MANUAL_EXAMPLE


@hookimpl
def register_spindle_types(register: Register) -> None:
    register(SelectiveSearchEiaSpindle())
