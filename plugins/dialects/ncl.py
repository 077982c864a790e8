"""NCCS NCL APT source (shared/corpus/dialects.md): REMARK lines are comments (the reader
reads them so for every file), MULTAX/ON gives each point a tool axis (three-axis motion
when it is the spindle's; a tilted one stops the run on a three-axis machine, naming the
line); no UNITS and no FEDRAT are common: the post warns and takes its defaults. NCL needs
no word of its own mapped: the dialect is named so that `gecent cl` says what the file is.
"""

from __future__ import annotations

from gecent.core.hookspecs import Register, hookimpl
from gecent.core.macros.dialect import Dialect


def sniff(head: str) -> bool:
    """NCL files begin with REMARK lines."""
    return head.lstrip().upper().startswith("REMARK")


DIALECT = Dialect("ncl", "NCCS NCL APT", "shared/corpus/dialects.md: NCCS NCL APT source",
                  sniff, (), priority=60)  # fmt: skip


@hookimpl
def register_dialects(register: Register) -> None:
    register(DIALECT)
