"""A machine file's ``[kinematics]`` table checked and built into the chain the run uses
(core/multiaxis/chain.py, docs/five-axis.md); each problem names the table and the axis."""

from __future__ import annotations

from collections.abc import Callable

from gecent.core.machine.definition import ROTARY_CELLS, RegisterSet
from gecent.core.machine.schema import KinematicsSection
from gecent.core.multiaxis.chain import KinematicChain, RotaryAxis, cross, unit

Problem = Callable[[str, str | int | None, str], None]


def chain_from_section(
    section: KinematicsSection, registers: RegisterSet, add: Problem
) -> KinematicChain | None:
    """``[kinematics]``: the two rotary axes of a five-axis machine (core/multiaxis/chain.py),
    each carried in its register (6, then 7) under its own letter."""
    axes: list[RotaryAxis] = []
    for index, given in enumerate(section.axis):
        entry = f"axis {index + 1} ({given.letter})"
        if sum(c * c for c in given.direction) < 1e-12:
            add("kinematics", entry, "direction must not be 0, 0, 0")
            continue
        if given.wrap == "limited" and given.limits is None:
            add("kinematics", entry, 'wrap = "limited" needs limits = [low, high]')
        if given.limits is not None:
            if given.wrap != "limited":
                add("kinematics", entry, f'limits are for wrap = "limited", not {given.wrap!r}')
            if given.limits[0] >= given.limits[1]:
                add("kinematics", entry, "limits must be [low, high] with low < high")
        cell = ROTARY_CELLS[index]
        if registers.letters[cell] != given.letter or registers.formats[cell] is None:
            add(
                "kinematics",
                entry,
                f"axis {index + 1} is output in register {cell}, which must have the letter "
                f"{given.letter!r} and a format (regstr/regfor {cell})",
            )
        axes.append(
            RotaryAxis(
                letter=given.letter,
                carrier=given.carrier,
                direction=unit(given.direction),
                pivot=given.pivot,
                limits=given.limits,
                wrap=given.wrap,
            )
        )
    if len(axes) != 2:
        return None
    if axes[0].letter == axes[1].letter:
        add("kinematics", "axis", "the two rotary axes need two letters")
    across = cross(axes[0].direction, axes[1].direction)
    if sum(c * c for c in across) < 1e-9:
        add("kinematics", "axis", "the two rotary axes are parallel")
    if sum(c * c for c in section.spindle) < 1e-12:
        add("kinematics", "spindle", "the spindle direction must not be 0, 0, 0")
        return None
    return KinematicChain(
        axes=(axes[0], axes[1]),
        spindle=unit(section.spindle),
        prefer=1.0 if section.prefer == "positive" else -1.0,
        pole_zone=section.pole_zone,
        tcp_on=section.tcp_on.strip().upper(),
        tcp_off=section.tcp_off.strip().upper(),
    )
