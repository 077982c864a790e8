"""The Machine Subroutine checklist (manual §5.6.6.4, 001 L27081-27161) and the option
rules whose breach the manual makes fatal (§5.7), applied to a resolved definition.

Each rule returns ``(table, entry, rule text)``; the loader adds the file name.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from itertools import pairwise
from math import isfinite

from gecent.core.absent import ABSENT
from gecent.core.machine.catalogue import STORE_SIZE
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.shuffle import decode_shuffle

Problem = tuple[str, str | int | None, str]

# Spindle types whose SRTAB holds more than the option 7 x option 8 speed table
# (commands, factors or generation parameters after it; manual §4.5.11, .13, .15, .16,
# .18), and type 7 whose layout belongs to the machine's own MACFUN code.
SRTAB_EXTENDED_TYPES = frozenset({7, 11, 13, 15, 16, 18})
# types whose SRTAB holds the parameters the speeds are generated from, not the speeds:
# type 18's highest speed and change between speeds per range (manual §4.5.19)
GENERATED_TABLE_TYPES = frozenset({18})

# Allowed values of the options that select modules or encodings.
_CHOICES: dict[int, tuple[set[float], str]] = {
    1: ({-1.0, 0.0, 1.0, 2.0, 3.0}, "control mode must be -1, 0, 1, 2 or 3"),
    10: ({0.0, 1.0, -1.0, -2.0, -3.0, -4.0}, "feedrate command format must be 0, +1 or -1..-4"),
    20: ({-2.0, -1.0, 0.0, 1.0}, "punched output type must be -2, -1, 0 or 1"),
    132: (
        {float(n) for n in range(9)},
        "machine type must be 0..8 (a wrong value is fatal error 8000)",
    ),
    164: ({1.0, 2.0, 3.0, 4.0}, "printout layout must be 1..4 (GEOUT1-GEOUT4)"),
}


def _whole(value: float | str) -> bool:
    return isinstance(value, float) and isfinite(value) and value == int(value)


def _number(machine: MachineDefinition, number: int) -> float:
    """The option's number (0 for text, and for a value that is not finite, which its own
    rule reports, so that the other rules can still be checked)."""
    value = machine.options[number]
    return value if isinstance(value, float) and isfinite(value) else 0.0


def _option_values(machine: MachineDefinition) -> Iterator[Problem]:
    for number, (allowed, rule) in _CHOICES.items():
        if machine.options[number] not in allowed:
            yield "optab", number, f"{rule}; found {machine.options[number]!r}"
    for number, low, high, what in (
        (19, 0, 20, "spindle type"),  # 20: gecent, S in RPM
        (116, 0, 9, "geometry class"),
        (7, 1, 300, "number of spindle ranges"),
        (8, 1, 300, "speeds per range"),
        (18, 0, 7, "number of feedrate ranges"),
        (174, 0, STORE_SIZE, "FRTAB size"),
        (57, 1, 30, "dwell register location (REGSTR 1..30)"),
        (164, 1, 4, "printout (GEOUT1..GEOUT4)"),
        (96, 0, 9, "T-word layout type"),
        (252, 0, 3, "arc centre words"),
        (263, 0, 2, "tool offset numbering"),
        (259, 0, 99999, "program number"),
        (160, 1, 1000, "printout width"),
    ):
        value = machine.options[number]
        if not _whole(value) or not low <= float(value) <= high:
            yield "optab", number, f"{what} must be a whole number {low}..{high}; found {value!r}"
    if not machine.feed_table and _whole(machine.options[174]) and int(_number(machine, 174)) % 2:
        yield "optab", 174, "FRTAB size must be even (a minimum and a maximum per range)"
    for number, value in enumerate(machine.options):
        if isinstance(value, float) and not isfinite(value):
            yield "optab", number, f"must be a finite number; found {value!r}"
    if _number(machine, 14) <= 0:
        yield "optab", 14, "step size must be greater than 0"
    if _number(machine, 4) <= 0:
        yield "optab", 4, "the largest departure must be greater than 0 (segments divide by it)"
    if _number(machine, 45) == 0:
        yield "optab", 45, "the largest rapid command must not be 0 (negative: no rapid F)"
    if _number(machine, 5) < 0:
        yield "optab", 5, "equality tolerance must not be negative"
    axes = machine.options[22]
    if not _whole(axes) or not set(f"{int(float(axes)):03d}") <= {"0", "1"} or axes in (0.0,):
        yield "optab", 22, f"axes present must be a sum of 100 (X), 10 (Y), 1 (Z); found {axes!r}"
    for number, letters in ((59, "XYZ"), (60, "IJK")):
        try:
            decode_shuffle(_number(machine, number), letters)
        except ValueError as exc:
            yield "optab", number, f"badly formed (fatal error 7, DECODE): {exc}"


def _spindle_table(machine: MachineDefinition) -> Iterator[Problem]:
    count = machine.speed_count
    spindle_type = int(_number(machine, 19))
    if spindle_type in GENERATED_TABLE_TYPES:
        cells = 2 * int(_number(machine, 7))
        empty = [i for i in range(1, cells + 1) if machine.store[i] is ABSENT]
        if empty:
            yield (
                "spindle_table",
                "speeds",
                f"spindle type {spindle_type} keeps the highest speed and the change between "
                f"speeds of each of the option 7 ranges in SRTAB(1..{cells}); "
                f"SRTAB({empty[0]}) is empty",
            )
        return
    tables = int(_number(machine, 153))
    product = "option 7 x option 8"
    if tables in (2, 3) and spindle_type not in SRTAB_EXTENDED_TYPES:
        count *= tables  # a table per head, one after the other (option 153, core/multihead)
        product += " x option 153"
    if count >= len(machine.store):
        yield (
            "spindle_table",
            "speeds",
            f"{product} = {count} speeds, more than the store holds ({len(machine.store) - 1})",
        )
        return
    missing = [i for i in range(1, count + 1) if machine.store[i] is ABSENT]
    if missing:
        yield (
            "spindle_table",
            "speeds",
            f"{product} = {count} speeds, but SRTAB holds only {count - len(missing)} "
            "(checklist 11a: their product must equal the number of speeds)",
        )
    elif spindle_type not in SRTAB_EXTENDED_TYPES and machine.srtab_top > count:
        yield (
            "spindle_table",
            "speeds",
            f"{product} = {count} speeds, but SRTAB holds {machine.srtab_top} values "
            f"(checklist 11a; spindle type {spindle_type} keeps only speeds in SRTAB)",
        )
    if not missing:
        for range_number, speeds in enumerate(machine.spindle_ranges(), start=1):
            if any(b < a for a, b in pairwise(speeds)):
                yield (
                    "spindle_table",
                    "speeds",
                    f"range {range_number} speeds must be in ascending order: {list(speeds)}",
                )
            if any(s < 0 for s in speeds):
                yield "spindle_table", "speeds", f"range {range_number} has a negative speed"
            if not all(isfinite(s) for s in speeds):
                yield (
                    "spindle_table",
                    "speeds",
                    f"range {range_number} has a speed that is not a finite number",
                )
    if spindle_type == 7 and _number(machine, 133) != 1:
        yield "optab", 133, "spindle type 7 computes S in the machine's MACFUN: set option 133 = 1"


def _feed_table(machine: MachineDefinition) -> Iterator[Problem]:
    ranges = machine.feed_ranges
    size = int(_number(machine, 174))
    if machine.feed_table:
        yield from _positioning_feed_table(machine, size)
        return
    per_axis = _number(machine, 25) < 0
    if per_axis:
        # FEDLIM (001 L11988-12439): per feed range, a pair for each of the three linear
        # slots (a two-axis machine's third may be zero), then one per rotary axis of a
        # multiaxis machine (head, table, third; in RPM)
        rotary = machine.rotary_axes
        count = max(1, int(_number(machine, 18)))
        expected = (3 + rotary) * count
        why = (
            f"option 25 < 0: one [min, max] per axis (3 linear + {rotary} rotary) per feed "
            f"range ({count})"
        )
    else:
        count = int(_number(machine, 18))
        expected, why = count, f"option 18 = {count} feedrate ranges"
    if len(ranges) != expected:
        yield "feed_ranges", "ranges", f"{why}, but FRTAB lists {len(ranges)} (checklist 11c)"
    if size != 2 * len(ranges):
        yield (
            "optab",
            174,
            f"FRTAB size must be 2 x {len(ranges)} ranges = {2 * len(ranges)}; found {size} "
            "(checklist 11c)",
        )
    for number, (low, high) in enumerate(ranges, start=1):
        if not 0 <= low <= high:
            yield "feed_ranges", f"ranges.{number}", f"minimum {low} must be 0..maximum {high}"
    if not per_axis and any(b[1] < a[1] for a, b in pairwise(ranges)):
        yield "feed_ranges", "ranges", "feed ranges must be in ascending order of range"


def _positioning_feed_table(machine: MachineDefinition, size: int) -> Iterator[Problem]:
    """The discrete feeds of the positioning feed types (001 L11198-11236, L27010-27065)."""
    feeds = machine.feed_table
    if machine.feed_ranges:
        yield (
            "feed_table",
            "feeds",
            "FRTAB holds either feed-range limits or a feed table, not both",
        )
    count = int(_number(machine, 62)) * int(_number(machine, 63))
    if len(feeds) != count:
        yield (
            "feed_table",
            "feeds",
            f"option 62 x option 63 = {count} feeds, but the table lists {len(feeds)}",
        )
    if size != len(feeds):
        yield "optab", 174, f"FRTAB size must be the {len(feeds)} feeds of the table; found {size}"
    if any(v < 0 for v in feeds):
        yield "feed_table", "feeds", "feeds must not be negative"


def _code_tables(machine: MachineDefinition) -> Iterator[Problem]:
    if machine.tablem[130] is not ABSENT:
        yield "tablem", 130, "location 130 must stay absent (STOREM uses it to clear VALUEM)"
    ranges = int(_number(machine, 18))
    default_range = machine.tablem[43]
    if ranges > 1 and default_range is not ABSENT:
        range_codes = [machine.tablem[113 + i] for i in range(ranges)]
        if default_range not in range_codes:
            yield (
                "tablem",
                43,
                f"the default feed-range M code {default_range} must be one of the feed-range "
                f"codes TABLEM(113..{112 + ranges}) = {[str(c) for c in range_codes]}",
            )
    circular = [machine.tableg[i] for i in (3, 4, 7, 8, 21, 22, 23, 31, 32, 33, 44, 45, 49, 50)]
    if _number(machine, 9) == 1 and all(code is ABSENT for code in circular):
        yield "optab", 9, "circular interpolation is on but TABLEG has no circular G code"


def _feed_format(machine: MachineDefinition) -> Iterator[Problem]:
    if _number(machine, 10) == 1:
        if machine.registers.regfor[11] != 30.0:
            yield "regfor", 11, "option 10 = +1 (EIA magic 3 feed) needs REGFOR(11) = 30"
        if _number(machine, 26) == 0:
            yield (
                "optab",
                26,
                "option 10 = +1 cannot use the feedrate multiplier: set option 26 = 1",
            )
    ijk = [machine.registers.formats[i] for i in (8, 9, 10)]
    if _number(machine, 1) in (0, 3) and _number(machine, 26) == 0 and all(f is None for f in ijk):
        yield "optab", 26, "option 26 = 0 (feedrate multiplier) needs I, J or K registers"


def _departure_capacity(machine: MachineDefinition) -> Iterator[Problem]:
    """The X, Y and Z formats must hold the largest departure, option 4 (DEPMAX), since
    moves are segmented to it (001 L4318-4333); under option 41 <= 0 the long departures
    of G10 blocks use format 23 or 24 and the others stay under 10 (§4.8, 001 L16144-16269)."""
    if _number(machine, 1) not in (0, 3):  # (3: the 7500's contouring departures too)
        return
    depmax = _number(machine, 4)
    variable = _number(machine, 41)
    for location in (3, 4, 5):
        fmt = machine.registers.formats[location]
        if fmt is None:
            continue
        capacity = 10**fmt.left - 10**-fmt.right
        if variable <= 0:
            long_capacity = 100 - 10 ** -(4 if variable == -2 else 3)
            if depmax > long_capacity + 1e-9 or capacity + 1e-9 < 9.9999:
                yield (
                    "regfor",
                    location,
                    f"option 41 = {variable:g} needs this format to hold 9.9999 and option 4 "
                    f"({depmax:g}) to be at most {long_capacity:g}",
                )
        elif depmax > capacity + 10**-fmt.right:  # MACH51: 999.9999 in format 33 passes
            yield (
                "regfor",
                location,
                f"format {fmt.regfor:g} holds at most {capacity:g}, less than the largest "
                f"departure option 4 = {depmax:g}",
            )


def _output_order(machine: MachineDefinition) -> Iterator[Problem]:
    order = machine.output_order
    if order is None:
        return
    if len(order) > 30 or len(set(order)) != len(order) or not all(1 <= p <= 30 for p in order):
        yield "output_order", "iorder", "IORDER must give distinct output positions 1..30"


def _positioning_control_kinds(machine: MachineDefinition) -> Iterator[Problem]:
    """Option 1 = 3, the 7500's positioning and contouring control (001 L24352-24356,
    core/motion/mixed.py), and option 213 = 1, a contouring machine with a positioning
    control (L26636-26649): a positioning move then ends where a contour goes on from,
    so its Z cannot be left to the operator (option 130 = 0, L25932-25941); the 7500
    tells the two ways apart by the block's G code, so it needs the positioning G
    TABLEG(1) and the linear one TABLEG(2) (docs/decisions.md, issue 22 wave 8)."""
    control, cuts = _number(machine, 1), machine.number_option(213)  # (a number: the schema)
    if cuts not in (0, 1):
        yield "optab", 213, f"contouring machine with a positioning control is 0 or 1; found {cuts}"
    if cuts == 1 and control == 0:
        yield (
            "optab",
            213,
            "option 213 = 1 (a contouring machine with a positioning control) needs a "
            "positioning control: option 1 = 1, -1, 2 or 3, not 0",
        )
    if (control == 3 or cuts == 1) and _number(machine, 130) == 0:
        why = "option 1 = 3 (positioning with contouring)" if control == 3 else "option 213 = 1"
        yield (
            "optab",
            130,
            f"{why} cuts from where a positioning move ends: option 130 = 0 would leave "
            "its Z to the operator; set +1 (Z block) or -1 (Z in the XY block)",
        )
    if control == 3:
        for location, what in ((1, "positioning (cycle-off)"), (2, "linear interpolation")):
            if machine.g_code(location) is None:
                yield (
                    "tableg",
                    location,
                    f"option 1 = 3 (positioning with contouring) needs the {what} G code: "
                    "the block's G code tells the 7500 which way it reads the block",
                )
    if _number(machine, 132) == 8 and control != 3:
        yield (
            "optab",
            132,
            f"option 132 = 8 (positioning machine with the 7500's contouring option) needs "
            f"option 1 = 3; found option 1 = {control:g}",
        )


RULES: tuple[Callable[[MachineDefinition], Iterator[Problem]], ...] = (
    _option_values,
    _positioning_control_kinds,
    _spindle_table,
    _feed_table,
    _code_tables,
    _feed_format,
    _output_order,
)

# Options the manual says must never be 0 ("processing stops"); they are only used when the
# part program is silent, so a zero is reported at load and is fatal only when needed.
_NEVER_ZERO = {
    23: "assumed feedrate is 0: a motion without FEDRAT will stop the run",
    27: "assumed spindle speed is 0: a SPINDL without a speed will stop the run",
    34: "initial spindle direction is 0: a SPINDL without a direction will stop the run",
    85: "assumed saddle feed mode is 0: a saddle feed without a mode will stop the run",
}


def check_definition(machine: MachineDefinition) -> tuple[list[Problem], list[str]]:
    errors = [problem for rule in RULES for problem in rule(machine)]
    warnings = [
        f"option {number}: {text}"
        for number, text in _NEVER_ZERO.items()
        if machine.options[number] == 0.0
    ]
    # a format too small for option 4 only matters to a move that long (the manual's own
    # option-change example sets option 4 = 20 on MACH40's format 14), so it is a warning
    warnings += [
        f"[{table}] entry {entry}: {text}" for table, entry, text in _departure_capacity(machine)
    ]
    printouts = machine.options[17]
    if machine.options[143] == 1.0 and isinstance(printouts, float) and "2" in f"{printouts:g}":
        # option 143's own table: "+1 = unit increasing (option 17 must not be 2)"
        # (001 L26079-26090): a segmented departure's middle blocks would be numbered and
        # then left out of the printout
        warnings.append(
            f"option 143 = 1 (unit-increasing numbers) with option 17 = {printouts:g}: "
            "option 17 must not have a digit 2"
        )
    return errors, warnings
