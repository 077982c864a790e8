"""The fixed meaning of every table location and option (manual §5.6.1-5.6.5).

The catalogue is package data (``data/*.toml``): each TABLEG/TABLEM location, register
location and option keeps its manual number, gains a readable alias, and carries its
Standard Machine value. Machine files override those standard values.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from importlib import resources
from typing import Any, Literal, TypeVar

from gecent.core import tomldata
from gecent.core.absent import ABSENT, ABSENT_SPELLINGS, Absent
from pydantic import BaseModel, ConfigDict, Field, ValidationError

OPTION_COUNT = 265  # the manual's 1-250 and gecent's 251-265 (docs/modern-controls.md)
MANUAL_OPTION_COUNT = 250
TABLEG_SIZE = 131  # the manual's 1-120 and gecent's 121-131
TABLEM_SIZE = 200
REGISTER_COUNT = 30
STORE_SIZE = 300

Applies = Literal["", "P", "C", "MA", "MH"]
Unit = Literal[
    "",
    "length",
    "feed",
    "seconds",
    "minutes",
    "rpm",
    "degrees",
    "feet",
    "percent",
    "fraction",
    "count",
    "text",
]


class _Frozen(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")


class OptionSpec(_Frozen):
    """One OPTAB entry: its manual number, readable alias and Standard Machine value."""

    number: int = Field(ge=1, le=OPTION_COUNT)
    alias: str = Field(pattern=r"^[a-z][a-z0-9_]*$")
    applies: Applies
    unit: Unit
    kind: Literal["number", "text", "number_or_text"]
    default: float | str
    fixed: bool
    status: Literal["active", "untested", "open", "reserved", "customer", "gecent"]
    meaning: str
    values: str
    seed: str
    # why nothing reads the option: "none: ..." (no effect in a post-processor) or
    # "missing: ..." (its feature is not built); docs/checklist.md lists both
    effect: str | None = Field(default=None, pattern=r"^(none|missing): \S")


class LocationSpec(_Frozen):
    """One TABLEG or TABLEM location: a fixed function whose value is the machine's code."""

    number: int = Field(ge=1)
    alias: str = Field(pattern=r"^[a-z][a-z0-9_]*$")
    standard: int | str
    function: str
    confidence: Literal["A", "B", "C"]
    seed: str

    @property
    def standard_code(self) -> int | Absent:
        if isinstance(self.standard, str):
            if self.standard.lower() not in ABSENT_SPELLINGS:
                raise ValueError(f"location {self.number}: standard {self.standard!r}")
            return ABSENT
        return self.standard


class RegisterSpec(_Frozen):
    """One REGSTR/REGFOR location (a DBFSEG cell) and its standard letter and format."""

    number: int = Field(ge=1, le=REGISTER_COUNT)
    alias: str = Field(pattern=r"^[a-z][a-z0-9_]*$")
    letter: str = Field(max_length=2)
    format: float
    ndp: bool
    usable: bool
    function: str


@dataclass(frozen=True, slots=True)
class Catalogue:
    options: tuple[OptionSpec, ...]
    tableg: tuple[LocationSpec, ...]
    tablem: tuple[LocationSpec, ...]
    registers: tuple[RegisterSpec, ...]
    option_numbers: dict[str, int]
    tableg_numbers: dict[str, int]
    tablem_numbers: dict[str, int]

    def option(self, number: int) -> OptionSpec:
        return self.options[number - 1]

    def option_number(self, key: int | str) -> int:
        """Resolve an option number or alias; raises KeyError for an unknown one."""
        if isinstance(key, int):
            if not 1 <= key <= OPTION_COUNT:
                raise KeyError(key)
            return key
        text = key.strip()
        if text.isdigit():
            return self.option_number(int(text))
        return self.option_numbers[text]


def _read(name: str) -> dict[str, object]:
    data = resources.files("gecent.core.machine").joinpath("data", name).read_bytes()
    return tomldata.loads(data.decode("utf-8"))


SpecT = TypeVar("SpecT", OptionSpec, LocationSpec, RegisterSpec)


def _numbered(items: Any, model: type[SpecT], count: int, name: str) -> tuple[SpecT, ...]:
    try:
        specs = tuple(model.model_validate(item) for item in items)
    except ValidationError as exc:  # a broken catalogue is a packaging bug, not user input
        raise RuntimeError(f"catalogue {name} is invalid: {exc}") from exc
    if [spec.number for spec in specs] != list(range(1, count + 1)):
        raise RuntimeError(f"catalogue {name} must list locations 1..{count} in order")
    aliases = [spec.alias for spec in specs]
    if len(set(aliases)) != len(aliases):
        raise RuntimeError(f"catalogue {name} has duplicate aliases")
    return specs


@cache
def catalogue() -> Catalogue:
    options = _numbered(_read("options.toml")["option"], OptionSpec, OPTION_COUNT, "options.toml")
    tableg = _numbered(_read("tableg.toml")["location"], LocationSpec, TABLEG_SIZE, "tableg.toml")
    tablem = _numbered(_read("tablem.toml")["location"], LocationSpec, TABLEM_SIZE, "tablem.toml")
    registers = _numbered(
        _read("registers.toml")["register"], RegisterSpec, REGISTER_COUNT, "registers.toml"
    )
    return Catalogue(
        options=options,
        tableg=tableg,
        tablem=tablem,
        registers=registers,
        option_numbers={spec.alias: spec.number for spec in options},
        tableg_numbers={spec.alias: spec.number for spec in tableg},
        tablem_numbers={spec.alias: spec.number for spec in tablem},
    )
