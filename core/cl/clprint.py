"""Show records as a CL print (like APT's CLPRNT) or as JSON lines, for ``gecent cl``."""

from __future__ import annotations

from typing import Any

from gecent.core.cl.records import (
    Arelem,
    Arg,
    Circle,
    Comment,
    Fini,
    Motion,
    MotionSubtype,
    Multiax,
    Other,
    PartText,
    Record,
    Statement,
    Surface,
    Word,
)

ARELEM_NAMES = {1: "CUT", 2: "CALC", 4: "INTOL", 5: "OUTTOL", 6: "CUTTER"}
MOTION_NAMES = {
    MotionSubtype.FROM: "FROM",
    MotionSubtype.GODLTA: "GODLTA",
    MotionSubtype.GOTO: "GOTO",
    MotionSubtype.CONTINUATION: "GOTO",
}


def _arg(arg: Arg) -> Any:
    return arg.name if isinstance(arg, Word) else arg


def record_json(record: Record) -> dict[str, Any]:
    """One record as a JSON-ready dict: line, record number, type, subtype, major, data."""
    out: dict[str, Any] = {"line": record.line, "record": record.number}
    if isinstance(record, Motion):
        out |= {"type": 5000, "subtype": int(record.subtype), "major": MOTION_NAMES[record.subtype]}
        if record.name:
            out |= {"name": record.name, "subscript": record.subscript}
        out["points"] = [list(point) for point in record.points]
    elif isinstance(record, Statement):
        out |= {"type": 2000, "subtype": record.code, "major": record.major, "code": record.code}
        if record.text is not None:
            out["text"] = record.text
        else:
            out["args"] = [_arg(a) for a in record.args]
    elif isinstance(record, Circle | Surface):
        out |= {"type": 3000, "subtype": 2 if isinstance(record, Circle) else record.use}
        out["major"] = "CIRCLE" if isinstance(record, Circle) else "SURFACE"
        if isinstance(record, Surface):
            out["surface_type"] = record.surface_type
        if record.name:
            out |= {"name": record.name, "subscript": record.subscript}
        out["values"] = list(record.values)
    elif isinstance(record, Arelem):
        out |= {"type": 6000, "subtype": record.subtype}
        out |= {"major": ARELEM_NAMES.get(record.subtype, "ARELEM"), "values": list(record.values)}
    elif isinstance(record, Multiax):
        out |= {"type": 9000, "subtype": 2, "major": "MULTAX", "on": record.on}
    elif isinstance(record, Fini):
        out |= {"type": 14000, "major": "FINI"}
    elif isinstance(record, Comment):
        out |= {"type": 1000, "major": "$$", "text": record.text}
    elif isinstance(record, PartText):
        out |= {"type": 1000, "text": record.text}
    elif isinstance(record, Other):
        out |= {"type": record.record_type, "subtype": record.subtype}
        out["items"] = [_arg(a) for a in record.items]
    return out


def _value(arg: Arg) -> str:
    if isinstance(arg, Word):
        return f"{arg.name:<6}"
    if isinstance(arg, int):
        return f"{arg:10d}"
    return f"{arg:10.4f}"


def _points(points: tuple[tuple[float, ...], ...]) -> list[str]:
    return [" " * 18 + "".join(f"{v:17.7f}" for v in point) for point in points]


def clprint_lines(record: Record) -> list[str]:
    """The CL print of one record: a line of record number/ISN, major word and data, then a
    line per point for motion, as APT's CLPRNT prints it (TAPENO/ISN)."""
    isn = "" if record.line is None else str(record.line)
    head = f"{record.number:6d}/{isn:>5}  "
    if isinstance(record, Motion):
        major = MOTION_NAMES[record.subtype]
        name = f" {record.name:<6}({record.subscript:4d})" if record.name else ""
        return [f"{head}{major:<6}/{name}", *_points(record.points)]
    if isinstance(record, Statement):
        if record.text is not None:
            return [f"{head}{record.major:<6}   {record.text}"]
        if not record.args:
            return [f"{head}{record.major}"]
        return [f"{head}{record.major:<6}/ " + ", ".join(_value(a) for a in record.args)]
    if isinstance(record, Circle | Surface):
        kind = "CIRCLE" if isinstance(record, Circle) else f"SURFACE TYPE {record.surface_type}"
        name = f" {record.name:<6}({record.subscript:4d}) =" if record.name else ""
        values = "".join(f"{v:11.4f}" for v in record.values)
        return [f"{head}{'DS':<6}/{name} {kind}/{values}"]
    if isinstance(record, Arelem):
        major = ARELEM_NAMES.get(record.subtype, f"ARELEM {record.subtype}")
        return [f"{head}{major:<6}/ " + ", ".join(_value(v) for v in record.values)]
    if isinstance(record, Multiax):
        return [f"{head}MULTAX/ {'ON' if record.on else 'OFF'}"]
    if isinstance(record, Fini):
        return [f"{head}FINI"]
    if isinstance(record, Comment):
        return [f"{head}$$ {record.text}"]
    if isinstance(record, PartText):
        return [f"{head}{record.text}"]
    if isinstance(record, Other):
        items = ", ".join(_value(a) for a in record.items)
        return [f"{head}TYPE {record.record_type}/{record.subtype}  {items}"]
    return [f"{head}{record!r}"]
