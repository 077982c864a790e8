"""A motion record with a tool axis (x, y, z, i, j, k: MULTAX, or a CAM system's first
GOTO of a path) on a machine without rotary axes (option 116 = 0, no transform class): when
the tool axis is the spindle's (+Z) it is ordinary three-axis motion; a tilted axis cannot
be reached and is an error naming the line."""

from __future__ import annotations

from math import sqrt

from gecent.core.cl.records import Motion
from gecent.core.errors import InputError, NotYetSupported
from gecent.core.machine.definition import MachineDefinition

AXIS_TOLERANCE = 1e-6  # radians, about: i and j of a unit axis within it count as 0


def three_axis_motion(record: Motion, machine: MachineDefinition) -> Motion:
    """The record with its points cut to x, y, z, or an error."""
    if machine.number_option(116) != 0:
        raise NotYetSupported("multiaxis motion", record.where)
    for point in record.points:
        i, j, k = point[3:6]
        length = sqrt(i * i + j * j + k * k)
        if length == 0.0:
            raise InputError("the tool axis i, j, k is 0, 0, 0", record.where)
        if abs(i) / length > AXIS_TOLERANCE or abs(j) / length > AXIS_TOLERANCE or k < 0:
            raise InputError(
                f"tool axis {i:g},{j:g},{k:g} is not the spindle axis 0,0,1: this machine has "
                "no rotary axes; use a multiaxis machine",
                record.where,
            )
    return Motion(
        record.file,
        record.line,
        record.number,
        record.subtype,
        tuple(point[:3] for point in record.points),
        record.name,
        record.subscript,
        offset=record.offset,
    )
