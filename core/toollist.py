"""The tool list of a program's header (gecent option 264, docs/modern-controls.md): one
comment per tool the CL file loads, in the order first loaded, with its CUTTER diameter (one
given after the load and before the tool moves, else the one in force at the load) and the
LENGTH LOADTL gives, in the machine's units.

The list needs the whole file before the first block, so it is read in a pass of its own;
for APT source text only the lines that can matter (LOADTL, TOOLNO, TURRET, CUTTER, UNITS)
are parsed, and a run of moves stands as one, so the pass costs a fraction of the post.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from math import isfinite

from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.cl.records import Arelem, Motion, Record, Statement, Word
from gecent.core.cl.stream import read_cl
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.macros.dialect import Dialect, in_dialect
from gecent.core.plugins import PluginSet
from gecent.core.units import UnitScale

LOADS = ("LOADTL", "TOOLNO", "TURRET")
_MOVES = ("GOTO", "FROM", "GODL")
_MOVED = "GOTO/0,0,0\n"
WANTED = (*LOADS, "CUTTER", "UNITS")
CUTTER = 6  # ARELEM subtype of CUTTER (001 L3544-3615)


@dataclass
class ListedTool:
    number: int  # the T code the load makes (a lathe's station and offset, option 263 = 2)
    diameter: float | None = None
    length: float | None = None
    digits: int = 0  # T's digits as the tape shows them (a lathe's four)

    def comment(self, unit: str) -> str:
        parts = [f"T{self.number:0{self.digits}d}"]
        if self.diameter is not None:
            parts.append(f"DIAMETER {self.diameter:.4g} {unit}")
        if self.length is not None:
            parts.append(f"LENGTH {self.length:.4g} {unit}")
        return "(" + ", ".join(parts) + ")"


def tool_list(
    path: str, plugins: PluginSet, machine: MachineDefinition, dialect: Dialect | None = None
) -> list[str]:
    """The header comments for the tools the CL file at ``path`` loads; a file in a CAM
    dialect has its own tool lines read too, through the dialect."""
    unit = "MM" if machine.number_option(138) == 1 else "IN"
    records = _records(path, plugins, dialect.tool_lines if dialect is not None else ())
    if dialect is not None:
        records = in_dialect(records, dialect, None)
    try:
        return [tool.comment(unit) for tool in listed_tools(records, machine)]
    except InputError:
        return []  # a malformed statement: the post finds it with its line


def listed_tools(records: Iterable[Record], machine: MachineDefinition) -> list[ListedTool]:
    units = UnitScale(machine)
    lathe = machine.number_option(263) == 2
    tools: dict[int, ListedTool] = {}
    cutter: float | None = None
    current: ListedTool | None = None
    described = False  # a CUTTER has followed the current tool's LOADTL
    for record in records:
        if isinstance(record, Motion):
            described = True  # the tool has cut: a later CUTTER is for the next tool
        elif isinstance(record, Statement) and record.major == "UNITS":
            units.set_units(record)
        elif isinstance(record, Arelem) and record.subtype == CUTTER and record.values:
            cutter = units.length(record.values[0])
            if current is not None and not described:
                # a CUTTER after a LOADTL and before any move is that tool's (CAM systems
                # write it after the load; APT before it, which the load then takes)
                current.diameter = cutter
                described = True
        elif isinstance(record, Statement) and record.major in LOADS:
            number = _t_code(record, lathe)
            if number is None:
                continue  # the post reports a LOADTL without a tool
            current = tools.get(number)
            described = current is not None
            if current is None:
                current = tools[number] = ListedTool(number, cutter, None, 4 if lathe else 0)
            length = record.value_after("LENGTH")
            if length is not None:
                current.length = units.length(length)
    return list(tools.values())


def _t_code(statement: Statement, lathe: bool) -> int | None:
    """The tool a load names; on a lathe with station and offset in T (option 263 = 2) the
    T code itself, as core/tool.py makes it (LOADTL/1 and LOADTL/101 are both T0101)."""
    args = statement.args
    plain: list[int] = []
    index = 0
    while index < len(args):
        arg = args[index]
        if isinstance(arg, Word):
            index += 2 if arg.name in ("OFSETL", "ADJUST", "LENGTH") else 1
            continue
        if not isfinite(arg) or abs(arg) > 1e12:
            return None  # the post reports the number at its line
        plain.append(int(arg))
        index += 1
    if not plain:
        return None
    tool = plain[0]
    if not lathe:
        return tool
    adjust, ofsetl = statement.value_after("ADJUST"), statement.value_after("OFSETL")
    for value in (adjust, ofsetl):
        if value is not None and (not isfinite(value) or abs(value) > 1e12):
            return None
    offset = int(adjust if adjust is not None else ofsetl if ofsetl is not None else tool)
    if statement.major == "TURRET":
        station = plain[1] if len(plain) > 1 else tool
        return station * 100 + int(ofsetl if ofsetl is not None else tool)
    return tool if tool > 99 else tool * 100 + offset


def _wanted(line: str, words: tuple[str, ...], initials: str) -> bool:
    """A whole one-line statement beginning with one of the words (a continued statement
    is left to the post, which reads it whole)."""
    text = line.strip()
    if not text or text[0] not in initials or (text.endswith("$") and not text.endswith("$$")):
        return False
    return text.upper().startswith(words)


def _records(path: str, plugins: PluginSet, more: tuple[str, ...] = ()) -> Iterator[Record]:
    """The records that can matter: for APT source only the lines that begin with one of
    the words, parsed by the APT source reader; a binary file whole."""
    try:
        with open(path, "rb") as handle:
            head = handle.read(4096)
    except OSError:
        return iter(())  # the post itself reports the file
    if b"\0" in head:
        return read_cl(path, plugins)
    words = WANTED + more  # with a dialect's own tool lines
    initials = "".join({word[0] + word[0].lower() for word in words})
    try:
        with open(path, encoding="utf-8", errors="replace", newline="") as handle:
            lines: list[str] = []
            for line in handle:
                if _wanted(line, words, initials):
                    lines.append(line)
                elif line.lstrip()[:4].upper() in _MOVES and (not lines or lines[-1] != _MOVED):
                    lines.append(_MOVED)  # one stand-in for a run of moves
    except OSError:
        return iter(())
    try:
        return iter(list(AptSourceReader(path).read_lines(lines)))
    except InputError:
        return iter(())  # a malformed statement: the post finds it with its line
