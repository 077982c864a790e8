"""Macros written in a machine file, without Python (docs/macros.md)::

    [[macros]]
    name = "mist-is-flood"
    sdl = "COOLNT/$P1(MIST)"              # a user-defined macro ...
    body = ["COOLNT/FLOOD", "DELAY/2"]

    [[macros]]
    name = "stage-next-tool"
    event = "tool-change"                 # ... or an event macro (spec 09 §5)
    phase = "shutdown"
    body = ["{% if next.tool %}INSERT/T{{ next.tool|int }}{% endif %}"]

Each line of ``body`` is a Jinja template that renders to one APT statement, as a CL file
would have it (``INSERT/...`` for a block punched as written), or to ``OUTPUT`` (the
invoking action, where the kind allows it), or to nothing (skipped). The templates see ``p``
(``p[1]`` is $P1; ``p.tool_id``), ``sv`` (``sv.FT``), ``next`` (``next.tool``,
``next.motion.xm``), ``la``, ``record``, ``machine``, ``globals`` and ``locals``; an
undefined name is an error naming the macro. Templates are compiled when the machine file
is loaded, so a syntax error names the file, the table and the entry.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from typing import TYPE_CHECKING, Any

from gecent.core.macros.model import SINGLE_EVENTS, Kind, Macro, MacroError, Phase

if TYPE_CHECKING:
    import jinja2


@cache
def _environment() -> jinja2.Environment:
    """Jinja, imported only when a machine file has macros (a post starts faster)."""
    import jinja2

    return jinja2.Environment(
        undefined=jinja2.StrictUndefined, autoescape=False, keep_trailing_newline=False
    )


EVENT_NAMES = {kind.value: kind for kind in Kind if kind is not Kind.SYNTAX}


@dataclass(frozen=True)
class TemplateBody:
    """A macro body of APT lines, rendered each time the macro runs."""

    lines: tuple[str, ...]
    templates: tuple[jinja2.Template, ...]

    def __deepcopy__(self, memo: dict[int, Any]) -> TemplateBody:
        return self  # compiled once; a run's snapshot shares it

    def __call__(self, ctx: Any) -> None:
        names = {
            "p": ctx.p,
            "sv": ctx.sv,
            "next": ctx.next,
            "la": ctx.la,
            "record": ctx.record,
            "machine": ctx.machine,
            "globals": ctx.globals,
            "locals": ctx.locals,
        }
        import jinja2

        for source, template in zip(self.lines, self.templates, strict=True):
            try:
                text = template.render(names).strip()
            except jinja2.UndefinedError as error:
                raise MacroError(f"line {source!r}: {error.message}") from None
            except (TypeError, ValueError, ArithmeticError) as error:
                raise MacroError(f"line {source!r}: {error}") from None
            if not text:
                continue
            if text.upper() == "OUTPUT":
                ctx.output()
            else:
                ctx.cmd(text)


def template_macro(
    name: str,
    machine: str,
    body: list[str],
    sdl: str | None = None,
    event: str | None = None,
    phase: str | None = None,
    description: str = "",
) -> Macro:
    """A macro from a machine file's ``[[macros]]`` entry; ValueError says what is wrong."""
    if (sdl is None) == (event is None):
        raise ValueError("a macro has either an sdl (user-defined) or an event, not both")
    import jinja2

    templates = []
    for line in body:
        try:
            templates.append(_environment().from_string(line))
        except jinja2.TemplateSyntaxError as error:
            raise ValueError(f"body line {line!r}: {error.message}") from None
    compiled = TemplateBody(tuple(body), tuple(templates))
    if sdl is not None:
        if phase is not None:
            raise ValueError("a user-defined macro has no phase")
        return Macro(name, Kind.SYNTAX, machine, sdl=sdl, body=compiled if body else None,
                     description=description, section="machine file")  # fmt: skip
    assert event is not None
    kind = EVENT_NAMES.get(event)
    if kind is None:
        raise ValueError(f"event {event!r} is not one of {', '.join(sorted(EVENT_NAMES))}")
    if kind in SINGLE_EVENTS:
        if phase is not None:
            raise ValueError(f"the {event} macro has no phase")
        stage = Phase.EVENT
    elif phase in ("startup", "shutdown"):
        stage = Phase(phase)
    else:
        raise ValueError(f'the {event} macro needs phase = "startup" or "shutdown"')
    if not body:
        raise ValueError("an event macro needs a body")
    return Macro(name, kind, machine, stage, body=compiled, description=description,
                 section="machine file")  # fmt: skip
