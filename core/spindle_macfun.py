"""Spindle type 7: the machine's own S-code computation (manual §4.5.8, 001 L14980-14981;
option 19 note L24608-24616; SPTYPE L37748-37752).

§4.5.8 reads "TYPE 7: (PRESENTLY UNDEFINED)": GECENT III has no standard type 7, and no
TYPE07 routine: SPTYPE itself branches to MACSRT. So type 7 is a kernel branch, not one of
the nineteen spindle-type plugins (option 19 = 7 never looks for a plugin). The
option table completes the picture: "If option(19) = 7.0, then set option(133) = 1.0", and
SPTYPE branches to the machine subroutine (MACSRT) "for s-code calculation". So a type-7
machine computes its S command in its own MACFUN code, at the hook point
``HookPoint.SPINDLE_CODE``. As in SPTYPE, the usual table testing has been done first and
is offered to that code: :meth:`SpindleCodeContext.table_choice` is DSRROW's range, row and
speed from SRTAB (option 7 ranges of option 8 speeds, option 90). The old GECENT II type 7
is GECENT III's type 19.

The handler receives a :class:`SpindleCodeContext` and puts its answer, a
:class:`~gecent.core.spindle.SpindleSelection`, into ``context.selection``.
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.errors import MachineDefinitionError
from gecent.core.families import HookPoint, HookResult
from gecent.core.machine.definition import MachineDefinition
from gecent.core.spindle_types import (
    SpindleRequest,
    SpindleSelection,
    TableChoice,
    check_ascending,
    choose_speed,
)


def _speed_table(machine: MachineDefinition) -> tuple[tuple[float, ...], ...]:
    count = int(machine.number_option(7)) * int(machine.number_option(8))
    if len(machine.spindle_speeds()) != count:
        raise MachineDefinitionError(
            machine.origin,
            "spindle_table",
            "speeds",
            f"spindle type 7's table testing needs option 7 x option 8 = {count} speeds in "
            f"SRTAB; found {len(machine.spindle_speeds())}",
        )
    ranges = machine.spindle_ranges()
    check_ascending(machine, ranges, "spindle type 7")
    return ranges


@dataclass
class SpindleCodeContext:
    """What a type-7 MACFUN handler works with: the request, the machine, and the
    selection the handler fills in."""

    request: SpindleRequest
    machine: MachineDefinition
    selection: SpindleSelection | None = None

    def table_choice(self) -> TableChoice:
        """SPTYPE's LOCRNG and DSRROW on the machine's speed table (option 7 ranges of
        option 8 speeds, selection by option 90), as done before MACSRT is called."""
        ranges = _speed_table(self.machine)
        return choose_speed(
            ranges, self.request.speed, self.request.range, self.machine.number_option(90)
        )


MACFUN_TYPE = 7


@dataclass(frozen=True)
class MachineComputedSpindle:
    number: int = MACFUN_TYPE
    name: str = "machine-computed S code (MACFUN)"
    section: str = "§4.5.8"

    def range_count(self, machine: MachineDefinition) -> int:
        return int(machine.number_option(7))

    def speed_limits(self, machine: MachineDefinition, range_number: int) -> tuple[float, float]:
        speeds = self._ranges(machine)[range_number - 1]
        return speeds[0], speeds[-1]

    def table_speeds(
        self, machine: MachineDefinition, range_number: int
    ) -> tuple[float, ...] | None:
        return self._ranges(machine)[range_number - 1]

    def select(self, machine: MachineDefinition, request: SpindleRequest) -> SpindleSelection:
        handler = request.macfun(HookPoint.SPINDLE_CODE) if request.macfun else None
        if handler is None:
            raise MachineDefinitionError(
                machine.origin,
                "optab",
                19,
                "spindle type 7 computes S in the machine's own MACFUN: the machine needs a "
                f"MACFUN providing {HookPoint.SPINDLE_CODE.value} (and option 133 = 1)",
            )
        context = SpindleCodeContext(request, machine)
        result = handler(context)
        if result is not HookResult.HANDLED or context.selection is None:
            raise MachineDefinitionError(
                machine.origin,
                "macfun",
                HookPoint.SPINDLE_CODE.value,
                "the machine's spindle-type-7 code must fill context.selection and return "
                f"HookResult.HANDLED; it returned {result!r} with selection "
                f"{context.selection!r}",
            )
        return context.selection

    def _ranges(self, machine: MachineDefinition) -> tuple[tuple[float, ...], ...]:
        return _speed_table(machine)
