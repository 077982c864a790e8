"""The macro system variables a macro can read or set (spec 09 §4.2, §7.5, §10): the enable
switches, ``$FT``, the look-ahead flags and the machine position.

``ctx.sv.TAPMAC`` and ``ctx.sv["$TAPMAC"]`` are the same variable. A name gecent does not
keep is refused by name (never silently a new variable); read-only ones refuse a write.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from gecent.core.absent import ABSENT
from gecent.core.macros.model import MacroError

if TYPE_CHECKING:
    from gecent.core.macros.context import Engine as MacroEngine

# the enable switches of §4.2: on unless a macro turns them off (decision in docs/decisions.md)
SWITCHES = ("CYCMAC", "MTNMAC", "LCSMAC", "OEMAC", "REGMAC", "TAPMAC", "DIAGMAC")


def _position(axis: int) -> Callable[[MacroEngine], float]:
    def read(engine: MacroEngine) -> float:
        return float(engine.run.state.position.present_part[axis])

    return read


def _cl_position(axis: int) -> Callable[[MacroEngine], float]:
    def read(engine: MacroEngine) -> float:
        position = engine.run.state.position
        return float(position.present_part[axis] - position.translation[axis])

    return read


def _tool(engine: MacroEngine) -> float | None:
    number = engine.run.state.tool.number
    return None if number is None else float(number)


def _axes(engine: MacroEngine) -> str:
    """$AXES: the letters of the active axes, '*' for the rest of six (X21: XYZ***)."""
    return "XYZ***"


# read-only variables computed from the run
COMPUTED: dict[str, Callable[[MacroEngine], Any]] = {
    "XM": _position(0),
    "YM": _position(1),
    "ZM": _position(2),
    "XC": _cl_position(0),
    "YC": _cl_position(1),
    "ZC": _cl_position(2),
    "T": _tool,
    "AXES": _axes,
    "CLN": lambda engine: engine.run.state.sequence,
    "FEDTIM": lambda engine: engine.run.output.cut_minutes,
    "LOOKAH": lambda engine: engine.flags.active,
    "TLOOK": lambda engine: engine.flags.tool,
    "MLOOK": lambda engine: engine.flags.motion,
    "ILOOK": lambda engine: engine.flags.finfo,
    "OELOOK": lambda engine: engine.flags.oe,
    "OI": lambda engine: engine.operations.oi,
    "TLMODE": lambda engine: 0 if engine.run.state.feed.rapid_ipm else 1,  # 0 rapid, 1 feed
    "OPSIZ": lambda engine: engine.operations.size,
}
# read and written through the operation tables (§9.2)
LINKED = {"FOI": "foi", "OPTYPE": "optype", "OPARGS": "opargs", "OPNAME": "opname",
          "OPMERGE": "merge"}  # fmt: skip


class SystemVariables:
    def __init__(self, engine: MacroEngine) -> None:
        object.__setattr__(self, "_engine", engine)
        values: dict[str, Any] = dict.fromkeys(SWITCHES, True)
        values.update(FT=0, REGMATCH=())
        object.__setattr__(self, "_values", values)

    @staticmethod
    def _name(name: str) -> str:
        return re.sub(r"^\$", "", name).upper()

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        return self[name]

    def __setattr__(self, name: str, value: Any) -> None:
        self[name] = value

    def __getitem__(self, name: str) -> Any:
        key = self._name(name)
        if key in COMPUTED:
            return COMPUTED[key](self._engine)
        if key in LINKED:
            return getattr(self._engine.operations, LINKED[key])
        if key in self._values:
            return self._values[key]
        raise MacroError(f"${key} is not a macro system variable gecent keeps")

    def __setitem__(self, name: str, value: Any) -> None:
        key = self._name(name)
        if key == "TLMODE":
            # X20: a motion code INSERTed by hand; the next move states its G again
            self._engine.run.output.words.previous_g = ABSENT
            return
        if key in ("ILOOK", "OELOOK") and not value:
            search = self._engine.search  # a macro ends the $FINFO or OPTYPE look-ahead
            if search is not None and search.kind == ("finfo" if key == "ILOOK" else "oe"):
                search.stop(self._engine.run)
            return
        if key in COMPUTED:
            raise MacroError(f"${key} is read-only")
        if key in LINKED:
            setattr(self._engine.operations, LINKED[key], value)
            return
        if key not in self._values:
            raise MacroError(f"${key} is not a macro system variable gecent keeps")
        if key in SWITCHES:
            value = bool(value)
        if key == "REGMATCH":
            value = (
                () if value is None else tuple(value) if not isinstance(value, str) else (value,)
            )
        self._values[key] = value

    def get(self, key: str) -> Any:
        """The engine's own read of a stored variable (no name handling)."""
        return self._values[key]
