"""Modern controls (gecent options 251-260, docs/modern-controls.md): what a Fanuc- or
LinuxCNC-style control reads that a 1970 Mark Century tape reader did not.

* option 251: absolute positions under G90 (an axis whose position does not change is left
  out, every axis after a tool change and in the first move), or departures under G91;
* option 254: F is the feed itself, per minute under G94 or per revolution under G95, and
  rapid moves are G00 without F;
* option 258: the start block of modal codes and the end-of-program code at FINI;
* the plane a CL plane lands on after SHUFFL (options 59/60), and whether the shuffle
  mirrors it, so G17/G18/G19 and G02/G03 name the machine's plane and sense.

The manual's own behaviour is untouched when these options are 0.
"""

from __future__ import annotations

from collections.abc import Sequence

from gecent.core.absent import ABSENT
from gecent.core.machine.definition import ROTARY_CELLS, MachineDefinition
from gecent.core.output.block import Block
from gecent.core.state import Numbering

ABSOLUTE, INCREMENTAL_CODED = 1.0, 2.0
# TABLEG locations (gecent's 121-127 and the manual's) used by modern controls
INCH_UNITS, METRIC_UNITS = 121, 122
PER_MINUTE, PER_REVOLUTION = 123, 124
RETURN_INITIAL, RETURN_R_PLANE = 125, 126
RAPID_TRAVERSE = 127
INVERSE_TIME = 131  # G93 (a five-axis move that turns a rotary axis)
TOOL_LENGTH_ON, TOOL_LENGTH_OFF, WORK_OFFSET = 128, 129, 130  # G43, G49, G54
# REGSTR: H (tool length offset), D (cutter radius offset), a second G word (G43 with a move)
TOOL_LENGTH_REGISTER, CUTTER_REGISTER, SECOND_G = 22, 23, 24
MILL_OFFSETS, LATHE_OFFSETS = 1, 2  # option 263
ABSOLUTE_INPUT, INCREMENTAL_INPUT = 96, 97
CUTCOM_OFF, CYCLE_OFF = 40, 1
PLANE_LOCATIONS = {(3, 4): 18, (5, 3): 19, (4, 5): 20}  # machine XY, ZX, YZ: TABLEG 18-20
# (u, v, normal) axis indices of the CL planes XY, ZX, YZ (right-handed: u x v = normal)
CL_PLANES = ((0, 1, 2), (2, 0, 1), (1, 2, 0))


def machine_planes(
    shuffle: Sequence[tuple[int, int] | tuple[int, float] | None],
) -> tuple[tuple[int | None, bool], ...]:
    """For each CL plane (XY, ZX, YZ): the TABLEG location of the machine plane its axes are
    output on (None when an axis is not output), and whether the shuffle mirrors the plane
    (one axis reversed, or the two axes swapped), which turns G02 into G03."""
    planes: list[tuple[int | None, bool]] = []
    for u, v, _ in CL_PLANES:
        first, second = shuffle[u], shuffle[v]
        if first is None or second is None:
            planes.append((None, False))
            continue
        (cu, su), (cv, sv) = first, second
        location = PLANE_LOCATIONS.get((cu, cv))
        swapped = location is None
        if swapped:
            location = PLANE_LOCATIONS.get((cv, cu))
        mirrored = (su * sv < 0) != swapped
        planes.append((location, mirrored))
    return tuple(planes)


class ModernControl:
    """The per-run state of the modern options: the control's position and feed mode."""

    __slots__ = (
        "absolute",
        "at",
        "axes",
        "direct_feed",
        "ended",
        "frame",
        "inverse_time",
        "machine",
        "per_revolution",
        "rapid_code",
        "rollover",
        "rotary_at",
        "started",
        "step",
    )

    def __init__(self, machine: MachineDefinition, step: float, axes: int) -> None:
        self.machine = machine
        self.step = step
        self.axes = axes
        self.absolute = machine.number_option(251) == ABSOLUTE
        self.direct_feed = machine.number_option(254) == 1
        self.frame = machine.number_option(258) == 1
        self.rapid_code = machine.g_code(RAPID_TRAVERSE)
        self.at: list[int] | None = None  # the control's position, CL axis order, steps
        self.per_revolution: bool | None = None  # the G94/G95 mode output last
        self.inverse_time = False  # G93 is in force
        # a five-axis machine's rotary axes: their positions (rotary steps, unwrapped), and
        # which the control takes modulo a turn (rollover)
        self.rotary_at: list[int] | None = None
        chain = machine.kinematics
        self.rollover = tuple(a.wrap == "rollover" for a in chain.axes) if chain else ()
        self.started = False
        self.ended = False

    @property
    def active(self) -> bool:
        return self.absolute or self.direct_feed or self.frame

    def start_codes(self, plane_location: int | None) -> list[float]:
        """The start block's modal G codes, those the machine has, in the usual order: plane,
        units, dimensions, feed mode, G40, G49, G80 and the work offset (G54)."""
        machine = self.machine
        dimension = machine.number_option(251)
        locations = [
            plane_location,
            METRIC_UNITS if machine.number_option(138) == 1 else INCH_UNITS,
            ABSOLUTE_INPUT
            if dimension == ABSOLUTE
            else INCREMENTAL_INPUT
            if dimension == INCREMENTAL_CODED
            else None,
            PER_MINUTE if self.direct_feed else None,
            CUTCOM_OFF,
            TOOL_LENGTH_OFF,
            CYCLE_OFF,
            WORK_OFFSET,
        ]
        codes = [machine.g_code(location) for location in locations if location is not None]
        return [code for code in codes if code is not None]

    def feed_mode_code(self, per_revolution: bool, inverse_time: bool = False) -> float | None:
        """G94, G95 or G93 when the feed mode changes (None: no change, or no such code)."""
        if self.per_revolution is None:
            self.per_revolution = False  # the start block set G94
        if inverse_time:
            if self.inverse_time:
                return None
            self.inverse_time = True
            return self.machine.g_code(INVERSE_TIME)
        if per_revolution == self.per_revolution and not self.inverse_time:
            return None
        self.per_revolution = per_revolution
        self.inverse_time = False
        return self.machine.g_code(PER_REVOLUTION if per_revolution else PER_MINUTE)

    def place_rotary(self, block: Block, angles: tuple[int, ...], step: float) -> None:
        """A five-axis move's absolute angles (rotary steps, unwrapped): an axis the control
        is at already is left out; a rollover axis is given within one turn (0 to 360)."""
        at = self.rotary_at
        for index, steps in enumerate(angles):
            cell = ROTARY_CELLS[index]
            if at is not None and at[index] == steps:
                block.cells[cell] = ABSENT
                continue
            value = steps * step
            if index < len(self.rollover) and self.rollover[index]:
                value %= 360.0
            block.cells[cell] = value
        self.rotary_at = list(angles)

    def place(self, block: Block, reached: tuple[int, ...], keep: tuple[int, ...] = ()) -> None:
        """Absolute words: cells 3.. hold the positions reached, in CL axis order before
        SHUFFL; an axis the control is at already is left out, unless ``keep`` names it (a
        circle states both axes of its plane: LinuxCNC refuses G02 without them)."""
        at = self.at
        for axis in range(self.axes):
            steps = reached[axis]
            if at is not None and at[axis] == steps and axis not in keep:
                block.cells[3 + axis] = ABSENT
            else:
                block.cells[3 + axis] = steps * self.step
        self.at = list(reached[: self.axes])

    def forget(self) -> None:
        """After a tool change the next move states every axis."""
        self.at = None
        self.rotary_at = None


def program_start(machine: MachineDefinition, numbering: Numbering) -> list[str]:
    """Option 258: % opens the program, then the option-259 program number; the program
    numbers its blocks as after SEQNO/ON (option 143; docs/decisions.md)."""
    if machine.number_option(258) != 1:
        return []
    numbering.switch_on(machine.number_option(143))
    number = int(machine.number_option(259))
    return ["%", f"O{number:04d}"] if number > 0 else ["%"]


def program_end(machine: MachineDefinition) -> list[str]:
    """Option 258: % after the end code."""
    return ["%"] if machine.number_option(258) == 1 else []


def modern_output(machine: MachineDefinition) -> bool:
    """The tape is a program for a modern control (decimal-point words, option 255, or the
    %/start/end program frame, option 258): such a machine's listing is written only when
    asked for (docs/decisions.md)."""
    return machine.number_option(255) == 1 or machine.number_option(258) == 1
