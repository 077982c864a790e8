"""Load a machine file: TOML -> schema check -> Standard Machine overrides -> checklist.

Every problem names the file, the table, the entry and the rule broken; all problems of
a file are reported together.
"""

from __future__ import annotations

import re
import tomllib
from collections.abc import Iterable, Mapping
from functools import cache
from importlib import resources
from math import isfinite
from pathlib import Path

from gecent.core import tomldata
from gecent.core.absent import ABSENT, ABSENT_SPELLINGS, Absent
from gecent.core.errors import InputError, MachineDefinitionError, SourcePosition
from gecent.core.machine.catalogue import (
    OPTION_COUNT,
    REGISTER_COUNT,
    STORE_SIZE,
    TABLEG_SIZE,
    TABLEM_SIZE,
    catalogue,
)
from gecent.core.machine.definition import MachineDefinition, OptionValue, RegisterSet
from gecent.core.machine.kinematics import chain_from_section
from gecent.core.machine.regformat import RegisterFormat, decode_regfor
from gecent.core.machine.rules import check_definition
from gecent.core.machine.schema import HeadSection, MachineFile
from gecent.core.macros.model import Macro
from gecent.core.macros.templates import template_macro
from pydantic import ValidationError

_UNION_TAGS = frozenset({"int", "str", "float"})
_LETTERS = re.compile(r"^[A-Z]{0,2}$")
MAX_HEADS = 3
SECOND_G = 24  # REGSTR 24: a second G word, so it shares the G register's letter


class MachineFileInvalid(InputError):
    """A machine file with one or more broken rules."""

    def __init__(self, file: str, problems: list[MachineDefinitionError]) -> None:
        self.file = file
        self.problems = problems
        lines = [f"{file}: error: {p.message}" for p in problems]
        super().__init__("\n".join(lines), None)

    def __str__(self) -> str:
        return self.message


class _Problems:
    def __init__(self, file: str) -> None:
        self.file = file
        self.items: list[MachineDefinitionError] = []

    def add(self, table: str, entry: str | int | None, rule: str) -> None:
        self.items.append(MachineDefinitionError(self.file, table, entry, rule))

    def raise_if_any(self) -> None:
        if self.items:
            raise MachineFileInvalid(self.file, self.items)


def _code_table(
    overrides: Mapping[int, int | str],
    standard: Iterable[int | Absent],
    size: int,
    table: str,
    problems: _Problems,
) -> tuple[int | Absent, ...]:
    values: list[int | Absent] = [ABSENT, *standard]
    for location, value in sorted(overrides.items()):
        if not 1 <= location <= size:
            problems.add(table, location, f"location must be 1..{size}")
            continue
        if isinstance(value, str):
            if value.strip().lower() not in ABSENT_SPELLINGS:
                problems.add(
                    table, location, f'value must be a code number or "absent", not {value!r}'
                )
                continue
            values[location] = ABSENT
        elif value < 0:
            problems.add(table, location, f"code must be 0 or more, not {value}")
        else:
            values[location] = value
    return tuple(values)


def _register_set(
    base: RegisterSet,
    regstr: Mapping[int, str],
    regfor: Mapping[int, float],
    table_prefix: str,
    problems: _Problems,
) -> RegisterSet:
    specs = catalogue().registers
    letters = list(base.letters)
    raw = list(base.regfor)
    for table, entries in ((f"{table_prefix}regstr", regstr), (f"{table_prefix}regfor", regfor)):
        for location, value in sorted(entries.items()):
            if not 1 <= location <= REGISTER_COUNT:
                problems.add(table, location, f"location must be 1..{REGISTER_COUNT}")
            elif not specs[location - 1].usable:
                problems.add(
                    table,
                    location,
                    f"location {location} is reserved ({specs[location - 1].function}) "
                    "and cannot be set",
                )
            elif table.endswith("regstr"):
                letter = str(value).strip()
                if not _LETTERS.match(letter):
                    problems.add(table, location, f"a register letter must be A-Z, not {value!r}")
                else:
                    letters[location] = letter
            else:
                raw[location] = float(value)  # type: ignore[arg-type]  # regfor values
    formats: list[RegisterFormat | None] = [None] * (REGISTER_COUNT + 1)
    for location in range(1, REGISTER_COUNT + 1):
        try:
            formats[location] = decode_regfor(raw[location])
        except ValueError as exc:
            problems.add(f"{table_prefix}regfor", location, f"format must be ±(10·L + R): {exc}")
    seen: dict[str, int] = {}
    for location in range(1, REGISTER_COUNT + 1):
        if formats[location] is None:
            continue
        letter = letters[location]
        if not letter:
            problems.add(
                f"{table_prefix}regstr",
                location,
                f"register has format {raw[location]:g} but no letter (REGSTR is blank); "
                "set a letter or set REGFOR to 0",
            )
        elif letter in seen and not (location == SECOND_G and seen[letter] == 2):
            problems.add(
                f"{table_prefix}regstr",
                location,
                f"letter {letter} is already used by location {seen[letter]}",
            )
        elif letter not in seen:
            seen[letter] = location
    return RegisterSet(letters=tuple(letters), formats=tuple(formats), regfor=tuple(raw))


def _options(
    overrides: Mapping[str, float | str], base: tuple[OptionValue, ...], problems: _Problems
) -> tuple[OptionValue, ...]:
    cat = catalogue()
    values = list(base)
    given: dict[int, str] = {}
    for key, value in overrides.items():
        try:
            number = cat.option_number(key)
        except KeyError:
            problems.add(
                "optab", key, f"unknown option (options are 1..{OPTION_COUNT} or an alias)"
            )
            continue
        if number in given:
            problems.add("optab", key, f"option {number} is also given as {given[number]!r}")
            continue
        given[number] = key
        spec = cat.option(number)
        if spec.kind == "number" and isinstance(value, str):
            problems.add("optab", key, f"option {number} ({spec.alias}) must be a number, not text")
        elif spec.kind == "text" and not isinstance(value, str):
            problems.add("optab", key, f"option {number} ({spec.alias}) holds text (a tape code)")
        elif not isinstance(value, str) and not isfinite(float(value)):
            problems.add("optab", key, f"option {number} must be a finite number; found {value!r}")
        else:
            values[number] = float(value) if not isinstance(value, str) else value
    return tuple(values)


TABLE_SPEED_CELL = 141  # TABSPD: "the table speeds are stored beginning at SRTAB(141)"


def table_speed_cells(options: tuple[OptionValue, ...]) -> range:
    """SRTAB(141 ..): option 179 ranges of option 180 rotary table speeds (001
    L38130-38131, L26428-26439); empty when the options are not whole numbers."""
    ranges, per_range = options[179], options[180]
    if not isinstance(ranges, float) or not isinstance(per_range, float):
        return range(0)
    count = ranges * per_range
    if count != int(count) or not 0 < count <= STORE_SIZE - TABLE_SPEED_CELL + 1:
        return range(0)
    return range(TABLE_SPEED_CELL, TABLE_SPEED_CELL + int(count))


def _store(
    file: MachineFile,
    base: MachineDefinition | None,
    options: tuple[OptionValue, ...],
    problems: _Problems,
) -> tuple[tuple[float | Absent, ...], tuple[tuple[float, float], ...], int, tuple[float, ...]]:
    store: list[float | Absent] = [ABSENT] * (STORE_SIZE + 1)
    feed_ranges: tuple[tuple[float, float], ...] = ()
    srtab_top = 0
    if base is not None:
        store = list(base.store)
        feed_ranges = base.feed_ranges
        srtab_top = base.srtab_top
    table_cells = table_speed_cells(options)
    table_given = False
    if file.spindle_table is not None:
        if file.spindle_table.speeds:
            # A new speed table replaces the standard one; FRTAB words are re-laid below.
            # The rotary table's speeds (SRTAB 141 up, TABSPD) are a table of their own.
            kept = {index: store[index] for index in table_cells}
            store = [ABSENT] * (STORE_SIZE + 1)
            srtab_top = min(len(file.spindle_table.speeds), STORE_SIZE)
            if len(file.spindle_table.speeds) > STORE_SIZE:
                problems.add("spindle_table", "speeds", f"at most {STORE_SIZE} values fit SRTAB")
            for index, speed in enumerate(file.spindle_table.speeds[:STORE_SIZE], start=1):
                store[index] = speed
            for index, value in kept.items():
                if value is not ABSENT:
                    table_given = True
                    store[index] = value if index > srtab_top else store[index]
        for index, value in sorted(file.spindle_table.cells.items()):
            if not 1 <= index <= STORE_SIZE:
                problems.add(
                    "spindle_table", f"cells.{index}", f"SRTAB cell must be 1..{STORE_SIZE}"
                )
            else:
                store[index] = value
                if index in table_cells:  # a table speed is not a spindle speed
                    table_given = True
                else:
                    srtab_top = max(srtab_top, index)
    if table_given and srtab_top >= TABLE_SPEED_CELL:
        problems.add(
            "spindle_table",
            "speeds",
            f"the spindle speeds (SRTAB 1..{srtab_top}) run into the rotary table speeds "
            f"(SRTAB {TABLE_SPEED_CELL} up, options 179 x 180)",
        )
    if file.feed_ranges is not None:
        feed_ranges = tuple((float(lo), float(hi)) for lo, hi in file.feed_ranges.ranges)
    feeds = base.feed_table if base is not None else ()
    if file.feed_table is not None:
        feeds = tuple(float(v) for v in file.feed_table.feeds)
        if file.feed_ranges is None:
            feed_ranges = ()  # one FRTAB: the discrete table replaces inherited range limits
    elif file.feed_ranges is not None:
        feeds = ()
    size = options[174]
    if isinstance(size, float) and size == int(size) and 0 <= size <= STORE_SIZE:
        indfr = STORE_SIZE - int(size)
        if srtab_top > indfr:
            problems.add(
                "spindle_table",
                "speeds",
                f"SRTAB (cells 1..{srtab_top}) and FRTAB (cells {indfr + 1}..{STORE_SIZE}, "
                f"option 174 = {int(size)}) overlap in the shared {STORE_SIZE}-word store",
            )
        if any(store[i] is not ABSENT for i in table_cells if i > indfr):
            problems.add(
                "spindle_table",
                "cells",
                f"the rotary table speeds (SRTAB {TABLE_SPEED_CELL} up, options 179 x 180) and "
                f"FRTAB (cells {indfr + 1}..{STORE_SIZE}, option 174 = {int(size)}) overlap",
            )
        for index in range(indfr + 1, STORE_SIZE + 1):
            store[index] = ABSENT
        for r, (low, high) in enumerate(feed_ranges, start=1):
            for offset, value in ((2 * r - 1, low), (2 * r, high)):
                if indfr + offset <= STORE_SIZE:
                    store[indfr + offset] = value
        if feeds and not feed_ranges:
            # the positioning feed table, FRTAB row r at cell INDFR + 1 + r (001 L27010-27065)
            for row, value in enumerate(feeds[: STORE_SIZE - indfr]):
                store[indfr + 1 + row] = float(value)
    return tuple(store), feed_ranges, srtab_top, feeds


def output_sequence(iorder: list[int], problems: _Problems) -> tuple[int, ...]:
    """IORDER as the manual defines it (001 L26953-27009, WE-14): IORDER(i) is the output
    position of register location i. Kept as the locations in output order (the locations
    it does not give come after, in location order)."""
    if len(iorder) > 30 or len(set(iorder)) != len(iorder) or not all(1 <= p <= 30 for p in iorder):
        problems.add("output_order", "iorder", "IORDER must give distinct output positions 1..30")
        return tuple(range(1, 31))
    listed = sorted(range(1, len(iorder) + 1), key=lambda location: iorder[location - 1])
    return (*listed, *range(len(iorder) + 1, 31))


def build_definition(
    file: MachineFile, origin: str, base: MachineDefinition | None
) -> MachineDefinition:
    """Apply a parsed machine file over ``base`` (the Standard Machine when None)."""
    problems = _Problems(origin)
    cat = catalogue()
    if base is None:
        tableg_std: Iterable[int | Absent] = (spec.standard_code for spec in cat.tableg)
        tablem_std: Iterable[int | Absent] = (spec.standard_code for spec in cat.tablem)
        standard_set = RegisterSet(
            letters=("", *(spec.letter for spec in cat.registers)),
            formats=(None,) * (REGISTER_COUNT + 1),
            regfor=(0.0, *(spec.format for spec in cat.registers)),
        )
        option_base: tuple[OptionValue, ...] = (0.0, *(spec.default for spec in cat.options))
        head_bases: tuple[RegisterSet, ...] = (standard_set,)
    else:
        tableg_std, tablem_std = base.tableg[1:], base.tablem[1:]
        option_base = base.options
        head_bases = base.heads
    tableg = _code_table(file.tableg, tableg_std, TABLEG_SIZE, "tableg", problems)
    tablem = _code_table(file.tablem, tablem_std, TABLEM_SIZE, "tablem", problems)
    head1 = _register_set(head_bases[0], file.regstr, file.regfor, "", problems)
    heads = [head1]
    for number, section in sorted(file.heads.items()):
        if not 2 <= number <= MAX_HEADS:
            problems.add(
                "heads", number, f"head numbers are 2..{MAX_HEADS} (head 1 is the main tables)"
            )
            continue
        if number != len(heads) + 1:
            problems.add(
                "heads", number, f"head {len(heads) + 1} must be defined before head {number}"
            )
            continue
        heads.append(_head(section, head1, number, problems))
    options = _options(file.optab, option_base, problems)
    store, feed_ranges, srtab_top, feed_table = _store(file, base, options, problems)
    order = (
        output_sequence(file.output_order.iorder, problems)
        if file.output_order
        else (base.output_order if base else None)
    )
    header = file.machine
    definition = MachineDefinition(
        number=header.number,
        name=header.name,
        title=header.title,
        description=header.description,
        source=header.source,
        origin=origin,
        tableg=tableg,
        tablem=tablem,
        heads=tuple(heads),
        options=options,
        store=store,
        speed_count=_speed_count(options),
        srtab_top=srtab_top,
        feed_ranges=feed_ranges,
        output_order=order,
        feed_table=feed_table,
        macros=(*(base.macros if base else ()), *_macros(file, problems)),
        kinematics=(
            chain_from_section(file.kinematics, head1, problems.add)
            if file.kinematics is not None
            else (base.kinematics if base else None)
        ),
    )
    problems.raise_if_any()
    errors, warnings = check_definition(definition)
    for table, entry, rule in errors:
        problems.add(table, entry, rule)
    problems.raise_if_any()
    return _with_warnings(definition, warnings)


def _macros(file: MachineFile, problems: _Problems) -> list[Macro]:
    made: list[Macro] = []
    names: set[str] = set()
    for section in file.macros:
        if section.name in names:
            problems.add("macros", section.name, "a second macro of this name")
            continue
        names.add(section.name)
        try:
            made.append(
                template_macro(
                    section.name,
                    file.machine.name,
                    section.body,
                    section.sdl,
                    section.event,
                    section.phase,
                    section.description,
                )
            )
        except ValueError as error:
            problems.add("macros", section.name, str(error))
    return made


def _head(
    section: HeadSection, head1: RegisterSet, number: int, problems: _Problems
) -> RegisterSet:
    return _register_set(head1, section.regstr, section.regfor, f"heads.{number}.", problems)


def _speed_count(options: tuple[OptionValue, ...]) -> int:
    ranges, per_range = options[7], options[8]
    if isinstance(ranges, str) or isinstance(per_range, str):
        return 0
    if not (isfinite(ranges) and isfinite(per_range)):
        return 0  # (the option's own rule reports it)
    return max(0, int(ranges) * int(per_range))


def _with_warnings(definition: MachineDefinition, warnings: list[str]) -> MachineDefinition:
    from dataclasses import replace

    return replace(definition, warnings=tuple(warnings))


def _parse(text: str, origin: str) -> MachineFile:
    try:
        data = tomldata.loads(text)
    except tomllib.TOMLDecodeError as exc:
        # tomllib says "(at line L, column C)" or "(at end of document)": the position
        message = str(exc)
        found = re.search(r"\(at line (\d+), column (\d+)\)$", message)
        if found:
            where = SourcePosition(origin, int(found.group(1)), int(found.group(2)))
        else:
            where = SourcePosition(origin, text.count("\n") + (0 if text.endswith("\n") else 1))
        reason = re.sub(r" \(at (line \d+, column \d+|end of document)\)$", "", message)
        if not found:
            reason += " (at the end of the file)"
        raise InputError(f"not valid TOML: {reason}", where) from None
    try:
        return MachineFile.model_validate(data)
    except ValidationError as exc:
        problems = _Problems(origin)
        reported: set[tuple[str, str | None]] = set()
        for error in exc.errors():
            # Drop the union-member tags pydantic adds ("int", "str") from the location.
            location = [str(part) for part in error["loc"] if part not in _UNION_TAGS]
            table = location[0] if location else "machine file"
            entry = ".".join(location[1:]) or None
            if (table, entry) in reported:
                continue
            reported.add((table, entry))
            message = error["msg"]
            if error["type"] == "extra_forbidden":
                message = "unknown key (not part of a machine file)" if entry else "unknown table"
            elif table in ("tableg", "tablem") and entry is not None:
                message = f'value must be a code number or "absent", not {error["input"]!r}'
            problems.add(table, entry, message)
        raise MachineFileInvalid(origin, problems.items) from None


def load_machine_text(
    text: str, origin: str = "<machine>", base: MachineDefinition | None = None
) -> MachineDefinition:
    """Load a machine file's text over ``base`` (default: the Standard Machine)."""
    parsed = _parse(text, origin)
    return build_definition(parsed, origin, base if base is not None else standard_machine())


def load_machine_file(path: str | Path, base: MachineDefinition | None = None) -> MachineDefinition:
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(f"cannot read machine file: {exc}", SourcePosition(str(path))) from None
    return load_machine_text(text, str(path), base)


def read_header(text: str, origin: str) -> MachineFile:
    """Parse (without table rules) to read the [machine] header of a file."""
    return _parse(text, origin)


STANDARD_RESOURCE = ("gecent.core.machine", "data/standard.toml")


@cache
def standard_machine() -> MachineDefinition:
    """The Standard Machine (§5.6.6): every table at its default value."""
    package, name = STANDARD_RESOURCE
    resource = resources.files(package).joinpath(name)
    text = resource.read_text(encoding="utf-8")
    return build_definition(_parse(text, str(resource)), str(resource), None)
