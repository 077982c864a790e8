"""What a macro is (spec 09 §1, §13.1): its kind, its phase, the machine it serves and its
body; a user-defined macro also has its syntax definition line.

A pack contributes macros through the ``register_macros`` hook; the run takes, for its
machine, one event macro per (kind, phase) and every user-defined macro, in the order of
:mod:`gecent.core.macros.table`.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from enum import Enum
from typing import Any

from gecent.core.errors import InputError
from gecent.core.macros.sdl import Sdl, parse_sdl


class Kind(Enum):
    DECLARATION = "declaration"
    MACHINE = "machine"
    BREAK = "break"
    FIRST_TOOL_CHANGE = "first-tool-change"
    TOOL_CHANGE = "tool-change"
    CYCLE = "cycle"
    MOTION = "motion"
    LCS = "lcs"
    OPERATION_EVENT = "operation-event"
    REGISTER = "register"
    TAPE = "tape"
    DIAGNOSTIC = "diagnostic"
    SYNTAX = "syntax"  # a user-defined macro, matched by its SDL


class Phase(Enum):
    STARTUP = "startup"
    SHUTDOWN = "shutdown"
    EVENT = "event"  # the single event macros, and user-defined macros


SINGLE_EVENTS = frozenset(
    {Kind.DECLARATION, Kind.OPERATION_EVENT, Kind.REGISTER, Kind.TAPE, Kind.DIAGNOSTIC}
)
# where OUTPUT may be used (§3: the union of the kinds the seed allows it in, Q2)
OUTPUT_ALLOWED = frozenset(
    {
        (Kind.SYNTAX, Phase.EVENT),
        (Kind.CYCLE, Phase.STARTUP),
        (Kind.LCS, Phase.STARTUP),
        (Kind.REGISTER, Phase.EVENT),
        (Kind.TAPE, Phase.EVENT),
        (Kind.DIAGNOSTIC, Phase.EVENT),
    }
)
# kinds whose macros may not issue post-processor commands (§4.3)
NO_COMMANDS = frozenset({Kind.DECLARATION, Kind.REGISTER, Kind.TAPE, Kind.DIAGNOSTIC})

Body = Callable[[Any], Any]  # takes the MacroContext (core/macros/context.py)


class MacroError(Exception):
    """A macro did what its kind does not allow (OUTPUT in a tool change macro, a command
    in a tape macro, a read-only $P written, ...); the run stops naming the macro."""


class MacroFailure(InputError):
    """A macro stopped the run: its own exception, or a rule of its kind it broke. The
    message names the macro; the position is the record it was working on."""


NOT_DONE = "not done"  # a built-in action that has not yet done its event (engine.Action)


class TerminateMacro(BaseException):
    """TERMAC: leave the current macro (caught by the engine). A BaseException, so a
    macro's own ``except Exception`` cannot swallow it."""


class Found(BaseException):
    """A look-ahead found what it searched for (raised inside a snapshot run). A
    BaseException, so a macro's own ``except Exception`` cannot swallow it."""

    def __init__(self, value: Any) -> None:
        super().__init__()
        self.value = value


@dataclass(frozen=True)
class Macro:
    """One macro. ``machine`` is a machine name, or ``"*"`` for every machine. A
    user-defined macro (``Kind.SYNTAX``) without a body ignores what it matches (§6.1)."""

    name: str
    kind: Kind
    machine: str = "*"
    phase: Phase = Phase.EVENT
    sdl: str | None = None
    body: Body | None = field(default=None, compare=False)
    description: str = ""
    section: str = "spec 09"
    parsed: Sdl | None = field(default=None, init=False, compare=False, repr=False)

    def __post_init__(self) -> None:
        if not self.name:
            raise ValueError("a macro needs a name")
        if self.kind is Kind.SYNTAX:
            if self.sdl is None:
                raise ValueError(f"user-defined macro {self.name!r} has no SDL")
            if self.phase is not Phase.EVENT:
                raise ValueError(f"user-defined macro {self.name!r} has no startup or shutdown")
            object.__setattr__(self, "parsed", parse_sdl(self.sdl))
            return
        if self.sdl is not None:
            raise ValueError(f"{self.kind.value} macro {self.name!r}: only user macros have an SDL")
        if self.body is None:
            raise ValueError(f"{self.kind.value} macro {self.name!r} has no body")
        single = self.kind in SINGLE_EVENTS
        if single != (self.phase is Phase.EVENT):
            wanted = "no phase" if single else "a startup or shutdown phase"
            raise ValueError(f"{self.kind.value} macro {self.name!r} takes {wanted}")

    def __deepcopy__(self, memo: dict[int, Any]) -> Macro:
        return self  # immutable: a run's snapshot shares it

    @property
    def key(self) -> str:
        """The id ``--list-plugins`` shows: machine and name."""
        return f"{self.machine}:{self.name}"

    @property
    def slot(self) -> tuple[Kind, Phase]:
        return (self.kind, self.phase)


class Macros:
    """Decorators that build a pack's macros, for its ``register_macros`` hook::

    macros = Macros(machine="acme-vmc1")

    @macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
    def before_tool_change(ctx): ...

    @macros.syntax("COOLNT/$P1(MIST)")
    def mist_is_flood(ctx):
        ctx.cmd("COOLNT/FLOOD")

    @hookimpl
    def register_macros(register):
        macros.register_all(register)
    """

    def __init__(self, machine: str = "*") -> None:
        self.machine = machine
        self.macros: list[Macro] = []

    def event(
        self, kind: Kind, phase: Phase = Phase.EVENT, name: str = ""
    ) -> Callable[[Body], Body]:
        def decorate(body: Body) -> Body:
            self.macros.append(
                Macro(name or body.__name__, kind, self.machine, phase, body=body,
                      description=(body.__doc__ or "").strip().split("\n")[0])
            )  # fmt: skip
            return body

        return decorate

    def syntax(self, sdl: str, name: str = "") -> Callable[[Body], Body]:
        def decorate(body: Body) -> Body:
            self.macros.append(
                Macro(name or body.__name__, Kind.SYNTAX, self.machine, sdl=sdl, body=body,
                      description=(body.__doc__ or "").strip().split("\n")[0])
            )  # fmt: skip
            return body

        return decorate

    def ignore(self, sdl: str, name: str = "") -> None:
        """A user-defined macro with no body: the records it matches are ignored."""
        self.macros.append(Macro(name or f"ignore {sdl}", Kind.SYNTAX, self.machine, sdl=sdl))

    def register_all(self, register: Callable[[Any], None]) -> None:
        for macro in self.macros:
            register(macro)
