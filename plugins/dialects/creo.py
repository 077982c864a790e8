"""PTC Creo (Pro/CLfile; shared/corpus/creo): plain APT but for what Creo puts in its
``$$->`` comments. ``$$-> CUTTER / d`` (the tool's diameter, after LOADTL) is read as the
CUTTER statement, so the tool list and `gecent verify` know the tool; ``$$-> CSYS / ...``
(the NC sequence's coordinate system: the motion is in it already), ``MFGNO``, ``FEATNO``
and ``CUTCOM_GEOMETRY_TYPE`` stay comments.
"""

from __future__ import annotations

from gecent.core.hookspecs import Register, hookimpl
from gecent.core.macros.dialect import Dialect


def sniff(head: str) -> bool:
    """Creo's first line: "$$*  Pro/CLfile  Version ..."."""
    return "Pro/CLfile" in head[:400] or "\n$$-> MFGNO" in head[:2000]


DIALECT = Dialect(
    "creo",
    "PTC Creo",
    "shared/corpus/creo (Pro/CLfile)",
    sniff,
    (),
    priority=30,
    comment_words=frozenset({"CUTTER"}),
    tool_lines=("$$-> CUTTER",),
)


@hookimpl
def register_dialects(register: Register) -> None:
    register(DIALECT)
