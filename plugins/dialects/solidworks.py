"""SolidWorks CAM / CAMWorks APT (shared/corpus/dialects.md, the two real files of
shared/corpus/solidworks-cam): its words mapped onto the post's.

=====================================  ==================================================
SolidWorks CAM writes                  the post reads
=====================================  ==================================================
``UNIT/MM``                            ``UNITS/MM``
``LOAD/TOOL,n``                        ``LOADTL/n``
``SELECT/TOOL,n`` (the next tool)      nothing (a machine's macros may stage it)
``INSERT/text`` (a note)               ``PPRINT/text``: the listing, not the tape
``CSYS/r11,r12,r13,tx,...`` (3 x 4)    the setup's frame: points go from part to machine
``CYCLE/INIT``                         nothing
``CYCLE/DRILL|DEEP2|...,FEDTO,d,...``  ``CYCLE/DRILL|DEEP,DEPTH,d,CLEAR,r[,STEP,s]...``
``CSI_...``, ``TRNTYP``, ``SETUP``      nothing (CAM notes; said once in the listing)
=====================================  ==================================================

The cycle's pairs: FEDTO the depth below the hole's top, RAPTO the R plane above it, RTRCTO
the retract plane above it (above R: back to the level the cycle started from, G98), DWELL
seconds, 1STPECK and SUBPECK the first and later peck depths (the post pecks SUBPECK each
time: the smaller, never deeper than asked; the listing says so), MMPM/IPM the feed.
"""

from __future__ import annotations

from typing import Any

from gecent.core.cl.records import Statement
from gecent.core.errors import InputError
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.macros import Macros
from gecent.core.macros.dialect import IDENTITY, Dialect, Matrix, ignore_noted, note_once, rigid
from gecent.plugins.dialects.cycle_words import cycle_words, split_cycle

NAME = "solidworks-cam"
TITLE = "SolidWorks CAM"
macros = Macros()

# SolidWorks CAM cycle words and the post's cycles (DEEP2: a peck drill)
CYCLES = {"DRILL": "DRILL", "DEEP": "DEEP", "DEEP2": "DEEP", "TAP": "TAP", "BORE": "BORE",
          "REAM": "REAM", "CSINK": "CSINK", "BRKCHP": "BRKCHP", "FACE": "FACE"}  # fmt: skip
NOTES = ("TRNTYP", "SETUP")


@macros.syntax("UNIT/$P1()")
def unit(ctx: Any) -> None:
    name = ctx.p[1].name
    ctx.cmd("UNITS", {"INCH": "INCHES", "IN": "INCHES"}.get(name, name))


@macros.syntax("LOAD/TOOL,$P1")
def load_tool(ctx: Any) -> None:
    ctx.cmd("LOADTL", ctx.p[1])


ignore_noted(macros, "SELECT/TOOL,?", "THE NEXT TOOL, FOR A CHANGER THAT STAGES IT")


@macros.syntax("INSERT/$P1''")
def insert_note(ctx: Any) -> None:
    ctx.pprint(ctx.p[1])


@macros.syntax("CYCLE/INIT")
def cycle_init(ctx: Any) -> None:
    """Announces the cycle statement that follows."""


@macros.syntax("CYCLE/$P1(DRILL,DEEP,DEEP2,TAP,BORE,REAM,CSINK,BRKCHP,FACE),$P2*")
def cycle(ctx: Any) -> None:
    kind = CYCLES[ctx.p[1].name]
    where = ctx.record.where
    numbers, pairs = split_cycle(ctx.p[2], where)
    if numbers:
        raise InputError(f"CYCLE/{ctx.p[1].name}: expected word, value pairs", where)
    if "FEDTO" not in pairs:
        raise InputError(f"CYCLE/{ctx.p[1].name}: FEDTO (the depth) is missing", where)
    peck = pairs.get("SUBPECK", pairs.get("1STPECK"))
    if kind == "DEEP" and peck and pairs.get("1STPECK") not in (None, peck):
        ctx.warn(f"CYCLE/{ctx.p[1].name}: EVERY PECK IS {peck:g} (FIRST PECK "
                 f"{pairs['1STPECK']:g} NOT KEPT)")  # fmt: skip
    back = pairs.get("RTRCTO", 0.0) > pairs.get("RAPTO", 0.0)  # above R: the start level
    words = cycle_words(kind, abs(pairs["FEDTO"]), pairs.get("RAPTO", 0.0), pairs,
                        peck if kind == "DEEP" else None, back)  # fmt: skip
    ctx.cmd("CYCLE", *words)


@macros.syntax("#2000:*")
def vendor_words(ctx: Any) -> None:
    """CSI_... (CAMWorks' own settings), TRNTYP and SETUP: notes for the CAM system."""
    major = getattr(ctx.record, "major", "")
    if major.startswith("CSI_") or major in NOTES:
        note_once(ctx, major, f"{major} IS A {TITLE.upper()} NOTE; IGNORED")
        return
    ctx.output()


def csys(statement: Statement) -> Matrix:
    """CSYS/r11,r12,r13,tx, r21,r22,r23,ty, r31,r32,r33,tz: the setup's frame, part to
    machine. Only a frame that turns the tool axis moves the points (a flipped setup: the
    points come with the axis 0,0,-1 in part coordinates); a turn about Z alone leaves them,
    which are in the setup's frame already (manufacture3-bottom's three drilling setups
    would otherwise drill one place three times; docs/decisions.md)."""
    values = statement.numbers()
    if len(values) != 12 or len(values) != len(statement.args):
        raise InputError("CSYS expects 12 numbers, a 3 x 4 matrix row by row", statement.where)
    rows = tuple(tuple(values[4 * r : 4 * r + 4]) for r in range(3))
    rigid(statement, rows)  # type: ignore[arg-type]
    if abs(rows[2][2] - 1.0) < 1e-9:  # the tool axis stays +Z
        return IDENTITY
    return rows  # type: ignore[return-value]


def sniff(head: str) -> bool:
    """CAMWorks writes CSI_ settings and CSYS matrices, and UNIT (not UNITS)."""
    return "\nCSI_" in head or ("\nCSYS/" in head and "\nUNIT/" in head)


DIALECT = Dialect(
    NAME,
    TITLE,
    "shared/corpus/dialects.md: SolidWorks CAM / CAMWorks APT",
    sniff,
    tuple(macros.macros),
    {"CSYS": csys},
    priority=20,
    tool_lines=("LOAD/", "UNIT/"),
)


@hookimpl
def register_dialects(register: Register) -> None:
    register(DIALECT)
