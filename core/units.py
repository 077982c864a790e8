"""CL units to machine units.

GECENT III (1970) knows one unit system per machine, chosen by option 138 (0 = inch,
1 = metric; 001 L24307-24310, L26026-26033); the CL file was meant to be in the same
units. Modern CAM systems write ``UNITS/MM`` (APT IV: type 9000 subtype 9) and then
every length in that unit, so the dispatcher rescales each record's lengths to the
machine's unit before any element sees it: motion points (not tool-axis vectors),
circle centres and radii, tolerances and the cutter. FEDRAT converts its own value,
because ``IPM`` and ``MMPM`` name their unit whatever UNITS says (decision in
docs/decisions.md, "CL units").
"""

from __future__ import annotations

from dataclasses import replace

from gecent.core.cl.records import Arelem, Circle, Motion, MotionSubtype, Record, Statement, Word
from gecent.core.errors import Diagnostic, InputError, SourcePosition
from gecent.core.machine.definition import MachineDefinition

MILLIMETRES = {"MM": 1.0, "CM": 10.0, "INCHES": 25.4, "FEET": 304.8}
"""The UNITS values of APT IV (vocabulary ``[units_value]``) in millimetres."""

_ARELEM_LENGTHS = {4, 5, 6}  # INTOL, OUTTOL, CUTTER (001 L3544-3615)


class UnitScale:
    """The factor from the CL file's current unit to the machine's (1.0 until UNITS)."""

    __slots__ = ("factor", "machine_mm", "stated")

    def __init__(self, machine: MachineDefinition) -> None:
        self.machine_mm = 1.0 if machine.number_option(138) == 1 else 25.4
        self.factor = 1.0
        self.stated = False  # a UNITS statement has been read

    def set_units(self, statement: Statement) -> None:
        """UNITS/MM|CM|INCHES|FEET: later lengths are in that unit."""
        words = statement.words()
        if len(statement.args) != 1 or len(words) != 1 or words[0] not in MILLIMETRES:
            raise InputError(
                f"UNITS expects one of {', '.join(MILLIMETRES)}, found "
                f"{', '.join(str(a) for a in statement.args) or 'nothing'}",
                statement.where,
            )
        self.factor = MILLIMETRES[words[0]] / self.machine_mm
        self.stated = True

    def unstated(self, where: SourcePosition | None) -> Diagnostic:
        """The first move of a CL file that never said UNITS: its lengths are taken in the
        machine's unit, which a CAM system's file in the other unit makes 25.4 times wrong."""
        unit = "MILLIMETRES" if self.machine_mm == 1.0 else "INCHES"
        return Diagnostic(
            f"NO UNITS STATEMENT BEFORE THE FIRST MOVE: THE CL FILE IS TAKEN IN {unit}, "
            "THE MACHINE'S UNIT",
            where,
        )

    def length(self, value: float) -> float:
        return value * self.factor

    def per_minute(self, value: float, unit: Word | None) -> float:
        """A FEDRAT value in machine units: IPM/IPR are inches, MMPM/MMPR millimetres,
        a bare value is in the CL unit."""
        if unit is None:
            return value * self.factor
        if unit.name in ("IPM", "IPR"):
            return value * 25.4 / self.machine_mm
        return value / self.machine_mm  # MMPM, MMPR

    def record(self, record: Record) -> Record:
        """The record with its lengths in machine units (the same record at factor 1)."""
        factor = self.factor
        if factor == 1.0:
            return record
        if isinstance(record, Motion):
            if record.subtype is MotionSubtype.GODLTA and len(record.points[0]) == 1:
                return replace(record, points=((record.points[0][0] * factor,),))
            points = tuple(
                (p[0] * factor, p[1] * factor, p[2] * factor, *p[3:]) for p in record.points
            )
            # built directly: dataclasses.replace costs more than the scaling on long files
            return Motion(
                record.file,
                record.line,
                record.number,
                record.subtype,
                points,
                record.name,
                record.subscript,
                offset=record.offset,
            )
        if isinstance(record, Circle) and len(record.values) >= 6:
            v = record.values
            radius = (v[6] * factor,) if len(v) > 6 else ()  # (6 values: no radius)
            values = (v[0] * factor, v[1] * factor, v[2] * factor, v[3], v[4], v[5], *radius)
            return replace(record, values=values)
        if isinstance(record, Arelem) and record.subtype in _ARELEM_LENGTHS:
            return replace(record, values=tuple(v * factor for v in record.values))
        return record
