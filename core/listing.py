"""The Jinja environment the printout plugins render their listings with."""

from __future__ import annotations

from functools import cache
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import jinja2


@cache
def environment() -> jinja2.Environment:
    import jinja2  # only a run that writes a listing pays for it

    return jinja2.Environment(
        loader=jinja2.PackageLoader("gecent.plugins.printouts", "templates"),
        autoescape=False,
        undefined=jinja2.StrictUndefined,
        keep_trailing_newline=True,
        trim_blocks=True,
        lstrip_blocks=True,
    )
