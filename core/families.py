"""What each plugin family registers, and how a family is selected by the machine.

Families and their selectors (manual §2.4, 001 L351-493):

========================  =========================  ===========================
family                    hook                       selected by
========================  =========================  ===========================
machines                  register_machines          MACHIN/GECENT,n or --machine
spindle types             register_spindle_types     option 19
positioning feed types    register_feed_types        option 78
rotary feed types         register_rotary_feed_types option 141
transform classes         register_transform_classes option 116
printouts                 register_printouts         option 164
MACFUN                    register_macfuns           option 133 and the machine
CL readers                register_cl_readers        the input file's content
macros                    register_macros            the machine (spec 09)
dialects                  register_dialects          the CL file's CAM system, or --dialect
========================  =========================  ===========================
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from enum import Enum
from functools import cached_property
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar, Protocol, runtime_checkable

from gecent.core.errors import InputError, SourcePosition

if TYPE_CHECKING:
    from gecent.core.cl.records import Record
    from gecent.core.machine.definition import MachineDefinition


@dataclass(frozen=True)
class FamilySpec:
    """A plugin family: its hook, the attribute that keys its plugins, and the option
    that selects one (with the manual's range of values)."""

    name: str
    hook: str
    key: str
    option: int | None = None
    numbers: frozenset[int] | None = None


def _numbers(first: int, last: int) -> frozenset[int]:
    return frozenset(range(first, last + 1))


# option 19's types 0-19 less type 7, which SPTYPE hands to the machine's MACFUN itself
SPINDLE_TYPES = _numbers(0, 20) - {7}  # 20: gecent, S in RPM (modern controls)

FAMILIES: tuple[FamilySpec, ...] = (
    FamilySpec("machines", "register_machines", "name"),
    FamilySpec("spindles", "register_spindle_types", "number", option=19, numbers=SPINDLE_TYPES),
    FamilySpec("feedtypes", "register_feed_types", "number", option=78, numbers=_numbers(0, 9)),
    FamilySpec(
        "rotaryfeeds", "register_rotary_feed_types", "number", option=141, numbers=_numbers(1, 1)
    ),
    FamilySpec(
        "classes",
        "register_transform_classes",
        "number",
        option=116,
        numbers=_numbers(1, 9),
    ),
    FamilySpec("printouts", "register_printouts", "number", option=164, numbers=_numbers(1, 4)),
    FamilySpec("macfuns", "register_macfuns", "name"),
    FamilySpec("readers", "register_cl_readers", "name"),
    FamilySpec("macros", "register_macros", "key"),
    FamilySpec("dialects", "register_dialects", "name"),
)
FAMILY_BY_NAME = {family.name: family for family in FAMILIES}


@runtime_checkable
class NumberedPlugin(Protocol):
    """Spindle types, feed types, transform classes and printouts: a manual number, a
    name and the manual section the plugin implements."""

    number: int
    name: str
    section: str


@dataclass(frozen=True)
class MachinePack:
    """A machine file shipped by a plugin; parsed fully only when the machine is used."""

    name: str
    number: int | None
    title: str
    origin: str
    text: str = field(repr=False)

    @classmethod
    def from_text(cls, text: str, origin: str) -> MachinePack:
        from gecent.core.machine.loader import read_header

        header = read_header(text, origin).machine
        return cls(
            name=header.name, number=header.number, title=header.title, origin=origin, text=text
        )

    @classmethod
    def from_package(cls, package: str, resource: str) -> MachinePack:
        """A machine file kept as package data beside the registering module."""
        traversable = resources.files(package).joinpath(resource)
        return cls.from_text(traversable.read_text(encoding="utf-8"), str(traversable))

    @classmethod
    def from_path(cls, path: str | Path) -> MachinePack:
        path = Path(path)
        raw = path.read_bytes()
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError as exc:
            line = raw.count(b"\n", 0, exc.start) + 1
            raise InputError(
                f"a machine file is UTF-8 text; byte {exc.start} (line {line}) is not",
                SourcePosition(str(path), line),
            ) from None
        return cls.from_text(text, str(path))

    @cached_property
    def definition(self) -> MachineDefinition:
        from gecent.core.machine.loader import load_machine_text

        return load_machine_text(self.text, self.origin)

    def load(self) -> MachineDefinition:
        return self.definition


class HookPoint(Enum):
    """Where the kernel offers a machine's MACFUN code the chance to act (manual §5.6.7).

    The value is the MCHCON number where the manual confirms it (001 L27406-27568);
    the other hook points are named by their source routine, as the MCHCON list is
    unreadable past the confirmed anchors.
    """

    INIT = 0
    TOOLNO = 1
    SLIDE_LIMITS = 2
    LOAD = 6
    CYCLE = 7
    FROM = 8
    THREAD = 12
    SPINDLE_CODE = "spindle-type-7"
    FEED_RANGE = "fedrat-feed-range-dwell"  # FEDRAT's option 93 < 0 dwell (001 L25507-25511)


class HookResult(Enum):
    """The MACFUN return protocol: RETURN = 0 continue, RETURN = 1 handled."""

    CONTINUE = 0
    HANDLED = 1


MacfunHandler = Callable[[Any], HookResult]


@dataclass(frozen=True)
class Macfun:
    """Special functions of one machine (its MACFUN part), keyed by hook point."""

    name: str
    machine: str
    section: str
    handlers: Mapping[HookPoint, MacfunHandler]
    description: str = ""


@runtime_checkable
class ClReader(Protocol):
    """Turns a CL file into a stream of records (a generator: memory does not grow)."""

    name: str
    description: str

    def sniff(self, head: bytes) -> bool:
        """True when the first bytes of a file look like this reader's format."""
        ...

    def read(self, path: str) -> Iterator[Record]: ...


class Printout(Protocol):
    """A printed listing layout (GEOUT1-4): ``listing`` makes the pages as blocks come
    (a :class:`gecent.core.output.sinks.ListingWriter`), ``render`` a whole list at once."""

    number: int
    name: str
    section: str
    template: ClassVar[str]

    def listing(self, machine: MachineDefinition, partno: Callable[[], str]) -> Any: ...

    def render(self, machine: MachineDefinition, blocks: Iterable[Any], partno: str) -> str: ...


def describe_option(option: int | None) -> str:
    return f"option {option}" if option is not None else ""
