"""What a statement handler may use of the run (the dispatcher's contract).

Handlers (core/statements/, reinstatement) take a :class:`Post`, not the run itself, so the
statements import only what lies below them in the data flow; the run (core/run.py)
satisfies this protocol and dispatches to them.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

from gecent.core.errors import Diagnostic
from gecent.core.feed.positioning import FeedType
from gecent.core.feed.rapid import RapidTraverse
from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.circle import CircularMotion
from gecent.core.motion.control_cycles import ControlCycles
from gecent.core.motion.cycles import Cycle
from gecent.core.motion.linear import LinearMotion
from gecent.core.motion.positioning import PositioningMotion
from gecent.core.motion.rotary import RotaryElement
from gecent.core.output.block import Block
from gecent.core.output.element import OutputElement
from gecent.core.output.sinks import Sinks
from gecent.core.spindle import SpindleElement
from gecent.core.state import PostState, RunResult
from gecent.core.tool import ToolElement
from gecent.core.units import UnitScale

if TYPE_CHECKING:
    from gecent.core.motion.multiaxis import MultiaxisMotion


class Post(Protocol):
    state: PostState
    result: RunResult
    sinks: Sinks
    units: UnitScale
    cycle: Cycle | None  # the canned cycle in force (CYCFLG, ICYTYP)
    cycle_first_z: float | None
    control_cycles: ControlCycles | None  # the control runs the cycle in force
    safety_motions: int  # a one-shot SAFETY's motions to come (core/statements/safety.py)

    @property
    def machine(self) -> MachineDefinition: ...

    @property
    def output(self) -> OutputElement: ...

    @property
    def spindle(self) -> SpindleElement: ...

    @property
    def rapid(self) -> RapidTraverse: ...

    @property
    def tool(self) -> ToolElement: ...

    @property
    def circle(self) -> CircularMotion: ...

    @property
    def rotary(self) -> RotaryElement: ...

    @property
    def motion(self) -> LinearMotion: ...

    @property
    def positioning(self) -> PositioningMotion: ...

    @property
    def multiaxis(self) -> MultiaxisMotion:
        """The multiaxis element (made on first use: it brings numpy)."""

    @property
    def feed_type(self) -> FeedType: ...

    def control_cycle_element(self) -> ControlCycles: ...

    def warn(self, diagnostic: Diagnostic) -> None: ...

    def text_block(self, block: Block) -> None:
        """A text block: bypasses OUTPUT (no N; the pending S and M wait)."""

    def rebuild(self, machine: MachineDefinition) -> None:
        """The machine's options changed (MACHIN mid-run): the elements are made anew."""
