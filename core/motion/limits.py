"""Slide limits (TSTLIM, 001 L38955-39010; options 110 and 121-126, L25720-25734,
L25843-25901): every point reached, on the CL axes with option 59's signs, against each
axis's limits. A 0/0 pair is an axis without limits.

Option 80 (pallet height "used for clearance checking", 001 L25356-25366; multiaxis
machines): the part's frame sits on the pallet's top, the limits are the machine's,
measured from the table; so Z is tested raised by the pallet's height. An incremental
tape is the same either way: the absolute checks are where the pallet shows
(docs/decisions.md, "Options 80, 222 and positioning cycles"). A machine's own MACFUN test
(``hook``) gets the position unraised: it knows its own fixtures."""

from __future__ import annotations

from collections.abc import Callable

from gecent.core.errors import Diagnostic, RunStopped
from gecent.core.machine.definition import MachineDefinition


class SlideLimits:
    def __init__(
        self, machine: MachineDefinition, shuffle: tuple[tuple[int, int] | None, ...]
    ) -> None:
        self.step = machine.number_option(14)
        self.action = machine.number_option(110)
        self.exceeded = False
        # the machine's MACFUN limit test (MCHCON 2): True when it did the test itself
        self.hook: Callable[[tuple[int, ...]], bool] | None = None
        self.limits: tuple[tuple[float, float, int], ...] = ()
        self.pallet = machine.number_option(80) if machine.multiaxis else 0.0
        if self.action != 0:
            signs = [1 if target is None else target[1] for target in shuffle[:3]]
            self.limits = tuple(
                (machine.number_option(lower), machine.number_option(upper), signs[axis])
                for axis, (upper, lower) in enumerate(((121, 122), (123, 124), (125, 126)))
            )

    def test(self, position: tuple[int, ...]) -> list[Diagnostic]:
        """The warnings for a point in steps; option 110 = -1 stops the run instead."""
        if self.hook is not None and self.hook(position):
            return []
        notes = []
        for axis, (low, high, sign) in enumerate(self.limits):
            if axis >= len(position) or (low == 0 and high == 0):
                continue
            value = sign * (position[axis] * self.step + (self.pallet if axis == 2 else 0.0))
            if low - 1e-9 <= value <= high + 1e-9:
                continue
            text = f"{'XYZ'[axis]} AXIS SLIDE LIMIT HAS BEEN EXCEEDED *** WARNING"
            if self.action == -1:
                raise RunStopped(f"{text} ({value:g} outside {low:g}..{high:g}; option 110 = -1)")
            notes.append(Diagnostic(text))
            self.exceeded = True
        return notes
