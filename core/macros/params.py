"""The $P parameters of each event macro as typed objects with 1-based ``$P`` access
(spec 09 §5, §13.2): ``ctx.p[9]`` and ``ctx.p.tool_id`` are the same value.

``None`` plays ``$NULL``; sequences are tuples. Writing a read-only $P, or a value a
control $P does not take, raises :class:`MacroError` naming both.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any, ClassVar

from gecent.core.macros.model import MacroError


@dataclass(frozen=True)
class P:
    name: str
    writable: bool = True
    allowed: frozenset[float] | None = None  # a control $P: the values it may be set to


class PParams:
    """A macro's $P1..$Pn. Subclasses list their fields in ``FIELDS``."""

    FIELDS: ClassVar[dict[int, P]] = {}
    KIND: ClassVar[str] = "macro"
    _names: ClassVar[dict[str, int]] = {}

    def __init_subclass__(cls) -> None:
        cls._names = {field.name: number for number, field in cls.FIELDS.items()}

    def __init__(self, **values: Any) -> None:
        object.__setattr__(self, "_values", dict.fromkeys(self.FIELDS))
        object.__setattr__(self, "changed", set())
        for name, value in values.items():
            self._values[self._number(name)] = value

    def _number(self, name: str) -> int:
        try:
            return self._names[name]
        except KeyError:
            raise AttributeError(f"{self.KIND} macros have no parameter {name!r}") from None

    def _field(self, number: int) -> P:
        if not isinstance(number, int):
            raise MacroError(f"the {self.KIND} macro has no parameter {number!r}")
        field = self.FIELDS.get(number)
        if field is None:
            raise MacroError(f"$P{number} is not a parameter of the {self.KIND} macro")
        return field

    def __getitem__(self, number: int) -> Any:
        self._field(number)
        return self._values[number]

    def __setitem__(self, number: int, value: Any) -> None:
        field = self._field(number)
        if not field.writable:
            raise MacroError(f"$P{number} ({field.name}) of the {self.KIND} macro is read-only")
        if field.allowed is not None and value not in field.allowed:
            allowed = ", ".join(f"{v:g}" for v in sorted(field.allowed))
            raise MacroError(
                f"$P{number} ({field.name}) of the {self.KIND} macro takes {allowed}, not {value!r}"
            )
        self._values[number] = value
        self.changed.add(number)

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        return self._values[self._number(name)]

    def __setattr__(self, name: str, value: Any) -> None:
        self[self._number(name)] = value

    def set(self, number: int, value: Any) -> None:
        """The engine's own write (no access rules; not a change by the macro)."""
        self._values[number] = value

    def items(self) -> Iterable[tuple[int, Any]]:
        values: dict[int, Any] = self._values
        return values.items()

    def __repr__(self) -> str:
        shown = ", ".join(f"$P{n}={v!r}" for n, v in self._values.items() if v is not None)
        return f"{type(self).__name__}({shown})"


def _fields(*names: str, read_only: Iterable[int] = ()) -> dict[int, P]:
    locked = set(read_only)
    return {
        number: P(name, writable=number not in locked)
        for number, name in enumerate(names, start=1)
        if name
    }


class ToolChangeParams(PParams):
    """Tool change and first tool change (§5.5, 002 L236-339)."""

    KIND = "tool change"
    FIELDS: ClassVar[dict[int, P]] = _fields(
        "pocket", "adjust", "change_type", "drum", "ofsetl", "length", "gripper", "start",
        "tool_id", "retain", "diameter", "times", "setool_x", "setool_y", "setool_z",
        "atangl", "setang", "head_side", "turn_mill", "tool_name", "head_pocket", "head_type",
        "secondary_x", "secondary_y", "secondary_z", "primary_x", "primary_y", "primary_z",
        "load_x", "load_y", "load_z", "head_drum", "atangl_secondary", "atangl_primary",
        "atangl_tool", "setang_secondary", "setang_primary", "setang_tool", "head_change",
        "head_start", "head_id", "head_times", "head_format", "head_name", "tcp_x", "tcp_y",
        "tcp_z",
    )  # fmt: skip


class CycleParams(PParams):
    """CYCLE startup and shutdown (§5.6, 002 L341-499). $P1 on exit: 1 or 2 output the
    cycle, 0 ignores the point, -1 emulates it with motions, -2 does the feed alone."""

    KIND = "cycle"
    FIELDS: ClassVar[dict[int, P]] = {
        **_fields(
            "control", "cl", "machine", "cycle_type", "activating", "alternate",
            "alternate_machine", "feed_out", "feed", "clearance_out", "clearance",
            "depth_out", "depth", "retract_out", "retract", "peck_count", "pecks",
            "peck_number", "axis", "back_out", "back_bottom",
            read_only=(2, 3, 4, 6, 7, 9, 16, 17, 18, 19),
        ),
        1: P("control", allowed=frozenset({1.0, 2.0, 0.0, -1.0, -2.0})),
    }  # fmt: skip


class MotionParams(PParams):
    """Motion startup and shutdown (§5.7, 002 L503-671). $P1: 1 arc, 3 FROM, 5 GOTO,
    6 continuation; set to 0 the motion is suppressed, to 3, 5 or 6 an arc goes as lines."""

    KIND = "motion"
    FIELDS: ClassVar[dict[int, P]] = {
        **_fields(
            "subclass", "cl", "machine", "first_record", "last_record", "alternate",
            "alternate_machine", "points", "direction", "plane", "cl_end", "machine_end",
            "cl_centre", "machine_centre", "cl_axis", "machine_axis", "surface_radius",
            "radius", "helical", "start_angle", "end_angle", "included_angle", "curve_type",
            "start_tangent", "end_tangent",
            read_only=(2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 20, 21, 22,
                       23, 24, 25),
        ),
        1: P("subclass", allowed=frozenset({0.0, 1.0, 3.0, 5.0, 6.0, 9.0, 10.0})),
    }  # fmt: skip


class LcsParams(PParams):
    """LCS startup and shutdown (§5.8, 002 L675-802); TRANS is gecent's LCS change."""

    KIND = "LCS"
    FIELDS: ClassVar[dict[int, P]] = {
        1: P("flag", allowed=frozenset({-1.0, 1.0})),
        2: P("action", writable=False),
        3: P("source", writable=False),
        4: P("matrix", writable=False),
        5: P("angle", writable=False),
        6: P("rotation_axis", writable=False),
        7: P("rotation_order", writable=False),
        8: P("centre", writable=False),
        9: P("translation", writable=False),
        10: P("scale", writable=False),
        11: P("mirror", writable=False),
        21: P("motion"),
        22: P("cl", writable=False),
        23: P("machine", writable=False),
        24: P("base_machine", writable=False),
        25: P("rotary_index", writable=False),
        26: P("rotary_position", writable=False),
    }


class OperationEventParams(PParams):
    """The operation event (§5.9, 002 L804-862)."""

    KIND = "operation event"
    FIELDS: ClassVar[dict[int, P]] = _fields(
        "optype",
        "opargs",
        "first_record",
        "cut_record",
        "positioning_points",
        read_only=(1, 2, 5),
    )


class RegisterParams(PParams):
    """The register macro (§5.10, 002 L866-969)."""

    KIND = "register"
    FIELDS: ClassVar[dict[int, P]] = _fields(
        "flag", "text", "index", "value", "code", read_only=(4, 5)
    )


class TapeParams(PParams):
    """The tape macro (§5.11, 002 L971-1038)."""

    KIND = "tape"
    FIELDS: ClassVar[dict[int, P]] = _fields(
        "flag", "file", "block", "sequence", "rest", read_only=(2, 4, 5)
    )


class DiagnosticParams(PParams):
    """The diagnostic macro (§5.12, 002 L1042-1099)."""

    KIND = "diagnostic"
    FIELDS: ClassVar[dict[int, P]] = _fields(
        "flag", "number", "severity", "occurrence", "message", read_only=(4,)
    )


class NoParams(PParams):
    """Declaration, machine and break macros have no $P."""

    KIND = "event"
    FIELDS: ClassVar[dict[int, P]] = {}


class SyntaxParams(PParams):
    """A user-defined macro's $P1..$P99, as its SDL captured them; all writable."""

    KIND = "user-defined"
    FIELDS: ClassVar[dict[int, P]] = {n: P(f"p{n}") for n in range(1, 100)}
