"""What the macro layer uses of the run, and what macro bodies reach through ``ctx``: the
run (core/run.py) and the engine satisfy these protocols, so core/macros imports neither."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any, Protocol

from gecent.core.dispatch.context import Post

if TYPE_CHECKING:
    from gecent.core.cl.records import Motion, Record
    from gecent.core.errors import Diagnostic
    from gecent.core.motion.circle import CircularMotion
    from gecent.core.plugins import PluginSet
    from gecent.core.statements import Handler


class MacroHost(Post, Protocol):
    """The run, as the macro engine sees it."""

    finished: bool
    plugins: PluginSet | None
    report: Callable[[Diagnostic], None] | None
    macros: Any  # the run's MacroEngine
    _circle: CircularMotion | None
    _statements: dict[str, Handler]  # the statement table the hooks take places in
    _motion_record: Callable[[Motion], None]

    @property
    def current_record(self) -> Record | None: ...

    def builtin(self, record: Record) -> None: ...

    def builtin_statement(self, major: str) -> Handler: ...

    def motion_builtin(self, record: Motion) -> None: ...

    def simulated_hole(
        self, record: Motion, at: tuple[float, float, float], hole: tuple[float, float, float]
    ) -> None: ...

    def warn_builtin(self, diagnostic: Diagnostic) -> None: ...

    def feed(
        self, records: Iterable[Record], fast_ok: bool, dispatch: Callable[[Record], None]
    ) -> None: ...

    def end_of_input(self) -> Any: ...
