"""The resolved machine definition: the Standard Machine with one machine's overrides applied.

Tables keep the manual's 1-based location numbers (index 0 is unused), so
``machine.tableg[4]`` is always the CCLW circular G code, as in the manual. Everything is
immutable tuples: a run reads it in its hot loop without pydantic or dict lookups.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

from gecent.core.absent import ABSENT, Absent
from gecent.core.machine.catalogue import STORE_SIZE, catalogue
from gecent.core.machine.regformat import RegisterFormat

if TYPE_CHECKING:
    from gecent.core.multiaxis.chain import KinematicChain

OptionValue = float | str

# DBFSEG's rotary departures: head, table, a third rotary axis (001 L6330-6345)
ROTARY_CELLS = (6, 7, 18)
# REGFOR locations printed without a decimal point (NDP, 001 L24057-24062).
NDP_LOCATIONS = frozenset({1, 2, 12, 13, 14, 17})


@dataclass(frozen=True, slots=True)
class RegisterSet:
    """REGSTR letters and decoded REGFOR formats of one head (locations 1..30)."""

    letters: tuple[str, ...]
    formats: tuple[RegisterFormat | None, ...]
    regfor: tuple[float, ...]

    def present(self) -> tuple[int, ...]:
        """Locations with a register (REGFOR != 0), in location order."""
        return tuple(i for i in range(1, len(self.formats)) if self.formats[i] is not None)


@dataclass(frozen=True, slots=True)
class MachineDefinition:
    """One machine, fully resolved. Build it with :mod:`gecent.core.machine.loader`."""

    number: int | None
    name: str
    title: str
    description: str
    source: str
    origin: str
    tableg: tuple[int | Absent, ...]
    tablem: tuple[int | Absent, ...]
    heads: tuple[RegisterSet, ...]
    options: tuple[OptionValue, ...]
    store: tuple[float | Absent, ...]
    speed_count: int
    srtab_top: int
    feed_ranges: tuple[tuple[float, float], ...]
    output_order: tuple[int, ...] | None
    warnings: tuple[str, ...] = field(default=())
    # the positioning feed table (FRTAB rows 0.., option 62 ranges x option 63 feeds)
    feed_table: tuple[float, ...] = field(default=())
    # macros written in the machine file (core/macros/templates.py): Macro objects
    macros: tuple[Any, ...] = field(default=())
    # a five-axis machine described by data (``[kinematics]``, core/multiaxis/chain.py)
    kinematics: KinematicChain | None = None

    @property
    def registers(self) -> RegisterSet:
        """Head 1's register set (the only one on a single-head machine)."""
        return self.heads[0]

    @property
    def multiaxis(self) -> bool:
        """A multiaxis machine: a transform class (option 116) or ``[kinematics]``."""
        return self.kinematics is not None or self.number_option(116) != 0

    @property
    def rotary_axes(self) -> int:
        """The rotary registers a multiaxis machine (option 116, or ``[kinematics]``) drives
        through its transform, head, table and third (0 on any other machine)."""
        if self.kinematics is not None:
            return len(self.kinematics.axes)
        if self.number_option(116) == 0:
            return 0
        return sum(1 for cell in ROTARY_CELLS if self.registers.formats[cell] is not None)

    @property
    def label(self) -> str:
        return f"{self.number} ({self.name})" if self.number is not None else self.name

    def option(self, key: int | str) -> OptionValue:
        """An option's value by manual number or alias (KeyError for an unknown key)."""
        return self.options[catalogue().option_number(key)]

    def number_option(self, key: int | str) -> float:
        """A numeric option's value by number or alias (a number indexes the tuple directly:
        the kernel asks by number in its loops)."""
        if type(key) is int and 0 < key < len(self.options):
            value = self.options[key]
        else:
            value = self.option(key)
        if isinstance(value, str):
            raise TypeError(f"option {key} holds text {value!r}, not a number")
        return value

    @property
    def indfr(self) -> int:
        """INDFR = 300 - option 174: FRTAB(INDFR + i) is the i-th feed-range word."""
        return STORE_SIZE - int(self.number_option(174))

    def srtab(self, index: int) -> float | Absent:
        """SRTAB(index), 1-based, from the shared 300-word store."""
        return self.store[index]

    def spindle_speeds(self) -> tuple[float, ...]:
        """The speed table SRTAB(1 .. option 7 x option 8)."""
        return tuple(float(v) for v in self.store[1 : self.speed_count + 1] if v is not ABSENT)

    def feed_table_ranges(self) -> tuple[tuple[float, ...], ...]:
        """The positioning feed table by range: option 62 ranges of option 63 feeds."""
        per_range = max(1, int(self.number_option(63)))
        table = self.feed_table
        return tuple(table[i : i + per_range] for i in range(0, len(table), per_range))

    def spindle_ranges(self) -> tuple[tuple[float, ...], ...]:
        per_range = max(1, int(self.number_option(8)))  # (option 8's own rule reports 0)
        speeds = self.spindle_speeds()
        return tuple(speeds[i : i + per_range] for i in range(0, len(speeds), per_range))

    def with_options(self, changes: Mapping[int, OptionValue]) -> MachineDefinition:
        """A copy with some options changed (no validation: see loader.revalidate)."""
        options = list(self.options)
        for number, value in changes.items():
            options[number] = value
        return replace(self, options=tuple(options))

    def g_code(self, location: int) -> float | None:
        """TABLEG(location) as a number; None where the machine has no such code (DMBITS)."""
        value = self.tableg[location]
        return None if value is ABSENT else float(value)

    def m_code(self, location: int) -> float | None:
        """TABLEM(location) as a number; None where the machine has no such code (DMBITS)."""
        value = self.tablem[location]
        return None if value is ABSENT else float(value)

    def describe_code(self, table: str, location: int) -> str:
        value = (self.tableg if table == "tableg" else self.tablem)[location]
        return "absent" if value is ABSENT else f"{table[-1].upper()}{value:02d}"
