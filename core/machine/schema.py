"""The TOML shape of a machine file, checked by pydantic before any table rule runs.

A machine file lists only its deviations from the Standard Machine, as the manual's
Machine Subroutines did (§5.6.6)::

    [machine]
    number = 23                 # MACHIN/GECENT,23 selects it (1..99)
    name = "mach23"
    title = "SAMPLE MILL"       # TAG: printed on every page, at most 36 characters

    [tableg]                    # TABLEG location = G code, or "absent" (DMBITS)
    11 = 10
    [tablem]                    # TABLEM location = M code, or "absent"
    3 = "absent"
    [regstr]                    # REGSTR location = letter ("" = DBLNKS)
    16 = "R"
    [regfor]                    # REGFOR location = ±(10L + R), 0 = no register
    3 = -24.0
    [optab]                     # option number or alias = value
    4 = 99.9999
    [spindle_table]             # SRTAB, from SRTAB(1) upward; single cells by number
    speeds = [1.0, 300.0]
    cells = { 180 = 9.0 }
    [feed_ranges]               # FRTAB, [min, max] per range, stored from the top of the store
    ranges = [[0.1, 10.0], [7.0, 60.0]]
    [feed_table]                # FRTAB, positioning discrete feeds (option 62 x 63), from the top
    feeds = [0.01, 0.02, 0.03]
    [output_order]              # IORDER: output position of each register location
    iorder = [1, 2, 3, 5, 7, 11, 12, 4, 6, 8, 9, 10, 13, 14]
    [heads.2]                   # multihead: head 2's REGSTR/REGFOR (start from head 1's)
    regstr = { 3 = "U" }
    regfor = { 3 = -33.0 }
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field


class _Section(BaseModel):
    model_config = ConfigDict(extra="forbid")


class MachineHeader(_Section):
    number: int | None = Field(default=None, ge=1, le=99)
    name: str = Field(pattern=r"^[a-z0-9][a-z0-9_.-]*$", max_length=40)
    title: str = Field(default="", max_length=36)
    description: str = ""
    source: str = ""


class SpindleTableSection(_Section):
    speeds: list[float] = Field(default_factory=list)
    cells: dict[int, float] = Field(default_factory=dict)


class FeedRangesSection(_Section):
    ranges: list[tuple[float, float]] = Field(default_factory=list)


class FeedTableSection(_Section):
    feeds: list[float] = Field(default_factory=list)


class OutputOrderSection(_Section):
    iorder: list[int]


class HeadSection(_Section):
    regstr: dict[int, str] = Field(default_factory=dict)
    regfor: dict[int, float] = Field(default_factory=dict)


class MacroSection(_Section):
    """A macro written in the machine file (core/macros/templates.py, docs/macros.md)."""

    name: str = Field(min_length=1, max_length=60)
    sdl: str | None = None
    event: str | None = None
    phase: str | None = None
    body: list[str] = Field(default_factory=list)
    description: str = ""


class KinematicsAxisSection(_Section):
    """One rotary axis of a five-axis machine described by data (core/multiaxis/chain.py)."""

    letter: Literal["A", "B", "C"]
    carrier: Literal["table", "head"]
    direction: tuple[float, float, float]
    pivot: tuple[float, float, float] = (0.0, 0.0, 0.0)
    limits: tuple[float, float] | None = None
    wrap: Literal["limited", "continuous", "rollover"] = "continuous"


class KinematicsSection(_Section):
    """``[kinematics]``: two rotary axes, in register order (6, then 7), table axes from the
    bed outwards, head axes from the column to the spindle (docs/five-axis.md)."""

    spindle: tuple[float, float, float] = (0.0, 0.0, 1.0)
    prefer: Literal["positive", "negative"] = "negative"
    pole_zone: float = Field(default=1.0, ge=0.0, le=45.0)
    # the control's words for its tool-centre-point mode (option 265 = 1): Fanuc "G43.4"
    # (H and the offset follow), "G49" to end it; none for LinuxCNC's TCP kinematics
    tcp_on: str = Field(default="", max_length=20)
    tcp_off: str = Field(default="", max_length=20)
    axis: list[KinematicsAxisSection] = Field(min_length=2, max_length=2)


class MachineFile(_Section):
    machine: MachineHeader
    tableg: dict[int, int | str] = Field(default_factory=dict)
    tablem: dict[int, int | str] = Field(default_factory=dict)
    regstr: dict[int, str] = Field(default_factory=dict)
    regfor: dict[int, float] = Field(default_factory=dict)
    optab: dict[str, float | str] = Field(default_factory=dict)
    spindle_table: SpindleTableSection | None = None
    feed_ranges: FeedRangesSection | None = None
    feed_table: FeedTableSection | None = None
    output_order: OutputOrderSection | None = None
    heads: dict[int, HeadSection] = Field(default_factory=dict)
    macros: list[MacroSection] = Field(default_factory=list)
    kinematics: KinematicsSection | None = None
