"""MACFUN on the macro engine (manual §5.6.7, spec 07 §9): a machine's special functions,
called at the manual's hook points (MCHCON) when option 133 = 1.

A handler gets a :class:`MacfunContext` and answers ``HookResult.HANDLED`` (RETURN = 1: the
special sequence was done, the source routine skips the rest) or ``CONTINUE`` (RETURN = 0:
carry on, possibly with state the handler changed, as MACF40's LOAD sets the machine
position).

===========  ==========================================  =================================
MCHCON       called                                      HANDLED skips
===========  ==========================================  =================================
0 INIT       once, before the first record                (nothing)
1 TOOLNO     at TOOLNO, LOADTL, TURRET, before the load   the tool change
6 LOAD       after TOOLNO, before the load                the tool change
7 CYCLE      at each CYCLE statement                      the statement
8 FROM       at each FROM record                          the FROM's processing
12 THREAD    at each motion under THREAD                  the thread move
2 LIMITS     each point tested against the slide limits   the standard test
FEED_RANGE   FEDRAT's feed range change, option 93 < 0    (nothing: the dwell is its own)
===========  ==========================================  =================================

FEED_RANGE (MCHCON not legible, 001 L27406-27568) gets ``values`` = (the new range, the
dwell option 93 asks, in seconds); "dwell is output by a special machine function
subroutine" (001 L25507-25511), so the handler outputs it (``MacfunContext.output``), the
range's M code still waiting for the next block.

Spindle type 7's S-code computation (MACSRT from SPTYPE) is called by the spindle element
itself (core/spindle_macfun.py).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from gecent.core.errors import Diagnostic
from gecent.core.families import HookPoint, HookResult, MacfunHandler

if TYPE_CHECKING:
    from gecent.core.cl.records import Record
    from gecent.core.machine.definition import MachineDefinition
    from gecent.core.macros.host import MacroHost
    from gecent.core.output.block import Block
    from gecent.core.plugins import PluginSet
    from gecent.core.state import PostState

ENGINE_POINTS = (
    HookPoint.INIT,
    HookPoint.TOOLNO,
    HookPoint.LOAD,
    HookPoint.CYCLE,
    HookPoint.FROM,
    HookPoint.THREAD,
    HookPoint.SLIDE_LIMITS,
    HookPoint.FEED_RANGE,
)


@dataclass
class MacfunContext:
    """What a MACFUN handler works with. ``point`` is the CL point of a FROM or a motion
    (x, y, z), ``machine_point`` the same with TRANS (the machine's coordinates, DPRESM);
    ``values`` a statement's numbers; ``position`` a slide-limit test's point in steps."""

    hook: HookPoint
    run: MacroHost = field(repr=False)
    record: Record | None = None
    point: tuple[float, ...] = ()
    machine_point: tuple[float, ...] = ()
    values: tuple[float, ...] = ()
    words: tuple[str, ...] = ()
    position: tuple[int, ...] = ()
    data: dict[str, Any] = field(default_factory=dict)

    @property
    def machine(self) -> MachineDefinition:
        return self.run.machine

    @property
    def state(self) -> PostState:
        return self.run.state

    def warn(self, text: str) -> None:
        """A diagnostic in the listing and on stderr, at the record."""
        self.run.warn(Diagnostic(text, self.record.where if self.record is not None else None))

    def output(self, block: Block) -> None:
        """A block through the post's OUTPUT (sequence number, waiting codes)."""
        self.run.output.output(block)


def macfun_handlers(
    plugins: PluginSet, machine: MachineDefinition
) -> dict[HookPoint, MacfunHandler]:
    """The machine's MACFUN handlers at the engine's hook points (option 133 = 1)."""
    if machine.number_option(133) != 1:
        return {}
    handlers: dict[HookPoint, MacfunHandler] = {}
    for info in plugins.family("macfuns").values():
        macfun = info.obj
        if macfun.machine != machine.name:
            continue
        for point, handler in macfun.handlers.items():
            if point in ENGINE_POINTS and point not in handlers:
                handlers[point] = handler
    return handlers


def handled(result: object) -> bool:
    return result is HookResult.HANDLED
