"""Postprocessor statements (CL type 2000) by major word: the statement -> handler table of
the manual (spec 08 §2, GEBASE/AUXLRY), one module per group of statements. A handler
takes the run and the statement record; it changes the run's state and outputs blocks
through the run's elements."""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post

Handler = Callable[["Post", Statement], None]


def handlers() -> dict[str, Handler]:
    from gecent.core.feed import accel
    from gecent.core.statements import (
        auxiliary,
        control,
        coordinates,
        cutcom,
        cycle,
        delay,
        feed,
        handling,
        linearity,
        machine,
        multihead,
        select,
        spindle_tool,
        surfaces,
        tape,
        text,
        threading,
    )

    table: dict[str, Handler] = {}
    modules = (
        text,
        machine,
        feed,
        tape,
        spindle_tool,
        delay,
        auxiliary,
        coordinates,
        cycle,
        threading,
        cutcom,
        select,
        multihead,
        linearity,
        handling,
        surfaces,
        control,
        accel,
    )
    for module in modules:
        table.update(module.HANDLERS)
    return table
