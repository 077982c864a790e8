"""The run's elements (spec 02 §7's subroutine groups as objects), each made when first
used and made anew when a MACHIN changes the machine's options: output, motion, circle,
rapid, spindle, tool, thread, rotary, positioning, the control's canned cycles."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from typing import TYPE_CHECKING, Any

from gecent.core.errors import Diagnostic, NotYetSupported
from gecent.core.feed.positioning import FeedType
from gecent.core.feed.rapid import RapidTraverse
from gecent.core.machine.definition import MachineDefinition
from gecent.core.macros.macfun import macfun_handlers
from gecent.core.motion.circle import CircularMotion
from gecent.core.motion.control_cycles import ControlCycles
from gecent.core.motion.fastpath import FastLinear
from gecent.core.motion.guard import CoordinateGuard
from gecent.core.motion.linear import LinearMotion
from gecent.core.motion.positioning import PositioningMotion
from gecent.core.motion.rotary import RotaryElement
from gecent.core.motion.thread import ThreadElement
from gecent.core.output.element import OutputElement
from gecent.core.output.sinks import Sinks
from gecent.core.plugins import PluginSet, get_plugins, macfun_handler
from gecent.core.spindle import SpindleElement
from gecent.core.state import PostState, RunResult
from gecent.core.tool import ToolElement
from gecent.core.units import UnitScale

if TYPE_CHECKING:
    from gecent.core.motion.multiaxis import MultiaxisMotion
    from gecent.core.multiaxis.transform import TransformClass


class Elements:
    """The element part of :class:`gecent.core.run.Run`."""

    plugins: PluginSet | None
    result: RunResult
    state: PostState
    sinks: Sinks
    units: UnitScale
    macros: Any
    fast_allowed: bool
    use_fast_path: bool
    warn: Callable[[Diagnostic], None]
    _output: OutputElement | None
    _motion: LinearMotion | None
    _multiaxis: MultiaxisMotion | None
    _circle: CircularMotion | None
    _rapid_traverse: RapidTraverse | None
    _spindle: SpindleElement | None
    _tool_element: ToolElement | None
    _rotary: RotaryElement | None
    _thread: ThreadElement | None
    _positioning: PositioningMotion | None
    _control_cycles: ControlCycles | None
    _guard: CoordinateGuard | None
    _fast: FastLinear | None

    @property
    def machine(self) -> MachineDefinition:
        return self.result.machine

    @property
    def output(self) -> OutputElement:
        if self._output is None:
            self._output = OutputElement(self.state)
            self._output.emit = self.sinks.emit
            if self.macros is not None:
                self.macros.hooks.output_element(self._output)
            if self.machine.number_option(1) != 0:
                self._output.positioning_feed = self.feed_type
        return self._output

    def control_cycle_element(self) -> ControlCycles:
        if self._control_cycles is None:
            self._control_cycles = ControlCycles(self.state, self.output.output)
        return self._control_cycles

    @property
    def feed_type(self) -> FeedType:
        """The positioning feed type of option 78 (0 or negative: type 0)."""
        number = max(0, int(self.machine.number_option(78)))
        plugins = self.plugins or get_plugins()
        found = plugins.get("feedtypes", number)
        if found is None:
            raise NotYetSupported(f"positioning feed type {number} (option 78): not installed")
        return found  # type: ignore[no-any-return]

    @property
    def positioning(self) -> PositioningMotion:
        if self._positioning is None:
            output = self.output
            self._positioning = PositioningMotion(
                self.state,
                output.output,
                self.warn,
                self.rapid.motion,
                output.store_m,
                output.dwell,
            )
            if self.macros is not None:
                self.macros.hooks.positioning_element(self._positioning)
        return self._positioning

    @property
    def motion(self) -> LinearMotion:
        if self._motion is None:
            self._motion = LinearMotion(self.state, self.output.output)
        return self._motion

    @property
    def multiaxis(self) -> MultiaxisMotion:
        """GOLINE on a multiaxis machine, through its transform class (option 116)."""
        if self._multiaxis is None:
            # (numpy comes with the multiaxis element: a three-axis run never loads it)
            from gecent.core.motion.multiaxis import MultiaxisMotion

            number = int(self.machine.number_option(116))
            chain = self.machine.kinematics
            if chain is not None:  # a five-axis machine by data (docs/five-axis.md)
                tcp = self.machine.number_option(265) == 1
                transform: TransformClass | None = replace(chain, tool_centre_point=tcp)
            else:
                transform = (self.plugins or get_plugins()).get("classes", number)
            if transform is None:
                raise NotYetSupported(f"transform class {number} (option 116 = {number})")
            self._multiaxis = MultiaxisMotion(self.state, self.output.output, transform, self.warn)
        return self._multiaxis

    @property
    def circle(self) -> CircularMotion:
        if self._circle is None:
            self._circle = CircularMotion(self.state, self.output.output, self.warn)
        return self._circle

    @property
    def rapid(self) -> RapidTraverse:
        if self._rapid_traverse is None:
            output = self.output
            self._rapid_traverse = RapidTraverse(
                self.state, output.output, output.store_m, output.dwell
            )
        return self._rapid_traverse

    @property
    def spindle(self) -> SpindleElement:
        if self._spindle is None:
            plugins = self.plugins or get_plugins()
            self._spindle = SpindleElement(
                self.state,
                self.output,
                lambda n: plugins.get("spindles", n),
                self.warn,
                lambda point: macfun_handler(plugins, self.machine, point),
                length=self.units.length,
            )
        return self._spindle

    @property
    def thread(self) -> ThreadElement:
        if self._thread is None:
            self._thread = ThreadElement(
                self.state, self.output.output, self.motion, self.warn, self.units.machine_mm
            )
        return self._thread

    @property
    def rotary(self) -> RotaryElement:
        if self._rotary is None:
            self._rotary = RotaryElement(self.state, self.output.output, self.warn)
        return self._rotary

    def rebuild(self, machine: MachineDefinition) -> None:
        """The elements precompute from the machine: made anew, keeping the times so far
        (the sinks and what they wrote stay)."""
        self._macfun_check(machine)
        self.result.machine = self.state.machine = machine
        previous = self._output
        self._output = self._motion = self._circle = self._multiaxis = None
        self._rapid_traverse = self._spindle = self._tool_element = self._rotary = None
        self._guard = None
        self._fast = None
        self.use_fast_path = self.fast_allowed
        if previous is not None:
            self.output.cut_minutes = previous.cut_minutes
            self.output.dwell_minutes = previous.dwell_minutes

    def _macfun_check(self, machine: MachineDefinition) -> None:
        """MACHIN may turn the machine's MACFUN (option 133) on or off: the engine's hook
        points follow; a MACFUN turned on with no engine running is not built."""
        handlers = macfun_handlers(self.plugins or get_plugins(), machine)
        if self.macros is not None:
            self.macros.macfuns = handlers  # (the engine's own: a snapshot's stays its own)
        elif handlers:
            raise NotYetSupported("MACFUN turned on by MACHIN (option 133) after the start")

    @property
    def tool(self) -> ToolElement:
        if self._tool_element is None:
            self._tool_element = ToolElement(self.state, self.output, self.warn)
            self._tool_element.length_scale = self.units.length
        return self._tool_element
