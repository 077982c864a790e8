"""Readable and JSON views of a resolved machine (``gecent machine show``)."""

from __future__ import annotations

from typing import Any

from gecent.core.absent import ABSENT
from gecent.core.machine.catalogue import REGISTER_COUNT, STORE_SIZE, catalogue
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import standard_machine
from gecent.core.machine.shuffle import decode_shuffle, describe_shuffle

MACHINE_TYPES = {
    0: "lathe",
    1: "mill",
    2: "positioning",
    3: "drafting",
    4: "flame cutter",
    5: "welder",
    6: "filament winder",
    7: "positioning used as contouring",
    8: "positioning with contouring",
}
# option 1: 0 contouring, 3 the 7500's mixed control (core/motion/mixed.py), else positioning
_CONTROLS = {0.0: "contouring", 3.0: "positioning and contouring (7500)"}


def _codes(machine: MachineDefinition, table: str) -> list[dict[str, Any]]:
    cat = catalogue()
    values = machine.tableg if table == "tableg" else machine.tablem
    specs = cat.tableg if table == "tableg" else cat.tablem
    return [
        {
            "location": spec.number,
            "alias": spec.alias,
            "code": values[spec.number],
            "function": spec.function,
        }
        for spec in specs
        if values[spec.number] is not ABSENT
    ]


def _registers(machine: MachineDefinition) -> list[list[dict[str, Any]]]:
    heads = []
    for head in machine.heads:
        heads.append(
            [
                {
                    "location": i,
                    "letter": head.letters[i],
                    "regfor": head.regfor[i],
                    "format": str(head.formats[i]),
                    "alias": catalogue().registers[i - 1].alias,
                }
                for i in range(1, REGISTER_COUNT + 1)
                if head.formats[i] is not None
            ]
        )
    return heads


def machine_as_dict(machine: MachineDefinition) -> dict[str, Any]:
    cat = catalogue()
    return {
        "number": machine.number,
        "name": machine.name,
        "title": machine.title,
        "description": machine.description,
        "source": machine.source,
        "origin": machine.origin,
        "tableg": [{**row, "code": row["code"]} for row in _codes(machine, "tableg")],
        "tablem": _codes(machine, "tablem"),
        "registers": _registers(machine),
        "options": [
            {
                "number": spec.number,
                "alias": spec.alias,
                "value": machine.options[spec.number],
                "standard": spec.default,
                "fixed": spec.fixed,
            }
            for spec in cat.options
        ],
        "spindle_ranges": [list(r) for r in machine.spindle_ranges()],
        "macros": [
            {"name": m.name, "kind": m.kind.value, "phase": m.phase.value, "sdl": m.sdl}
            for m in machine.macros
        ],
        "srtab": {
            i: machine.store[i]
            for i in range(1, machine.srtab_top + 1)
            if machine.store[i] is not ABSENT
        },
        "feed_ranges": [list(r) for r in machine.feed_ranges],
        "output_order": list(machine.output_order) if machine.output_order else None,
        "warnings": list(machine.warnings),
    }


def describe_machine(machine: MachineDefinition, show_all: bool = False) -> str:
    cat = catalogue()
    standard = standard_machine()
    kind = MACHINE_TYPES.get(int(machine.number_option(132)), "?")
    lines = [
        f"machine {machine.label}: {machine.title or '(no title)'}",
        f"  {machine.description}" if machine.description else "",
        f"  type: {kind} (option 132), "
        f"{_CONTROLS.get(machine.number_option(1), 'positioning')} control (option 1), "
        f"spindle type {int(machine.number_option(19))}, GEOUT{int(machine.number_option(164))}",
        f"  axes out: {describe_shuffle(decode_shuffle(machine.number_option(59), 'XYZ'))} "
        f"(option 59), {describe_shuffle(decode_shuffle(machine.number_option(60), 'IJK'))} "
        "(option 60)",
        f"  source: {machine.source or '-'}   file: {machine.origin}",
    ]
    lines = [line for line in lines if line]
    for head_number, head in enumerate(_registers(machine), start=1):
        title = "registers" if len(machine.heads) == 1 else f"registers, head {head_number}"
        lines.append(f"\n{title} (location letter REGFOR = L.R, '-' signed):")
        lines.append(
            "  " + "  ".join(f"{r['location']}:{r['letter']}{r['regfor']:+g}" for r in head)
        )
    if machine.output_order:
        lines.append(f"  output order (IORDER): {list(machine.output_order)}")
    for table in ("tableg", "tablem"):
        prefix = "G" if table == "tableg" else "M"
        lines.append(f"\n{table.upper()} (location alias = code):")
        for row in _codes(machine, table):
            lines.append(f"  {row['location']:>3} {row['alias']:<32} {prefix}{row['code']:02d}")
    lines.append(
        f"\nOPTAB ({'all' if show_all else 'values that differ from the Standard Machine'}):"
    )
    for spec in cat.options:
        value = machine.options[spec.number]
        if show_all or value != standard.options[spec.number]:
            text = f"{value!r}" if isinstance(value, str) else f"{value:g}"
            flag = " (fixed)" if spec.fixed else ""
            lines.append(f"  {spec.number:>3} {spec.alias:<34} = {text}{flag}")
    if machine.macros:
        lines.append("\nmacros in the machine file (docs/macros.md):")
        for macro in machine.macros:
            what = macro.sdl if macro.sdl else f"{macro.kind.value} {macro.phase.value}"
            lines.append(f"  {macro.name}: {what}")
    lines.append("\nSRTAB spindle speeds (option 7 ranges x option 8 speeds):")
    for number, speeds in enumerate(machine.spindle_ranges(), start=1):
        lines.append(f"  range {number}: " + ", ".join(f"{s:g}" for s in speeds))
    extra = [
        i
        for i in range(machine.speed_count + 1, machine.srtab_top + 1)
        if machine.store[i] is not ABSENT
    ]
    if extra:
        lines.append(
            f"  further SRTAB cells {machine.speed_count + 1}..{machine.srtab_top}: "
            f"{len(extra)} values"
        )
    if machine.feed_ranges and machine.number_option(25) < 0:
        # FEDLIM's table: per feed range, the linear slots then the rotary axes (RPM)
        lines.append(f"FRTAB axis feed limits (cells {machine.indfr + 1}..{STORE_SIZE}):")
        rotary = machine.rotary_axes
        names = ["CL x", "CL y", "CL z", "head (RPM)", "table (RPM)", "third (RPM)"][: 3 + rotary]
        for index, (low, high) in enumerate(machine.feed_ranges):
            feed_range, slot = divmod(index, len(names))
            lines.append(f"  range {feed_range + 1} {names[slot]}: {low:g} .. {high:g}")
    elif machine.feed_ranges:
        lines.append(f"FRTAB feed ranges (cells {machine.indfr + 1}..{STORE_SIZE}):")
        for number, (low, high) in enumerate(machine.feed_ranges, start=1):
            lines.append(f"  range {number}: {low:g} .. {high:g}")
    for warning in machine.warnings:
        lines.append(f"warning: {warning}")
    return "\n".join(lines) + "\n"
