"""Choosing the machine for a run and changing its options from the part program
(MACHIN/GECENT, nm [, OPTAB, n, v ...] [, LINEAR | LINCIR | PLAN] [, OFF] and MACHIN/OFF;
manual §5.6, 001 L22352-22366, L24225-24262; the MACHIN subroutine, L33974-34011).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from math import isfinite

from gecent.core.cl.records import Comment, Fini, Motion, Record, Statement, Word
from gecent.core.errors import (
    Diagnostic,
    FatalError,
    InputError,
    SourcePosition,
)
from gecent.core.machine.catalogue import OPTION_COUNT, catalogue
from gecent.core.machine.definition import MachineDefinition, OptionValue
from gecent.core.machine.loader import MachineFileInvalid
from gecent.core.machine.rules import check_definition
from gecent.core.plugins import PluginSet

POSTPROCESSOR_NAME = "GECENT"
# Options that must be given in output units when set by MACHIN (001 L24258-24262).
OUTPUT_UNIT_OPTIONS = frozenset({149, 150})
# Options the non-reassignable list names (001 L24250-24256) that the manual itself tells
# the part programmer to change by MACHIN: the part radius on the rotary table, "changed by
# the MACHIN statement as MACHIN/GECENT, n, OPTAB, 112, r" (001 L10945-10963).
CHANGED_BY_MACHIN_DESPITE_LIST = frozenset({112})
TRANSFORM_CLASS = 116  # option 116: the multiaxis transform class (001 L25771-25777)
MACHINE_TYPE = 132  # option 132: the type of machine, 0..8 (001 L25946-25962)
MACHINE_TYPES = frozenset(float(n) for n in range(9))
OFF = "OFF"


@dataclass
class MachinRequest:
    """What a MACHIN/GECENT statement asks for."""

    number: int | None
    options: list[tuple[int, float, SourcePosition]] = field(default_factory=list)
    modifiers: list[str] = field(default_factory=list)
    where: SourcePosition | None = None  # the statement's place, for what it is told

    @property
    def off(self) -> bool:
        """The OFF modifier (MACHIN/GECENT, nm, ..., OFF)."""
        return OFF in self.modifiers


def is_machin_off(statement: Statement) -> bool:
    """MACHIN/OFF on its own (001 L26678-26687, L33992): it names no postprocessor."""
    args = statement.args
    return len(args) == 1 and isinstance(args[0], Word) and args[0].name == OFF


def parse_machin(statement: Statement) -> MachinRequest | None:
    """Decode MACHIN/GECENT,...; None when it names another postprocessor."""
    args = list(statement.args)
    where = statement.where
    if not args or not isinstance(args[0], Word) or args[0].name != POSTPROCESSOR_NAME:
        return None
    for arg in args:
        if isinstance(arg, float) and not isfinite(arg):
            raise InputError(
                f"MACHIN/GECENT has a value that is not a finite number ({arg})", where
            )
    request = MachinRequest(number=None, where=where)
    position = 1
    if position < len(args) and isinstance(args[position], int | float):
        value = float(args[position])  # type: ignore[arg-type]
        if value != int(value):
            raise InputError(f"MACHIN/GECENT takes a whole machine number, found {value:g}", where)
        request.number = int(value)
        position += 1
    while position < len(args):
        arg = args[position]
        if isinstance(arg, Word) and arg.name == "OPTAB":
            position += 1
            pairs = 0
            while position + 1 < len(args) and all(
                isinstance(a, int | float) for a in args[position : position + 2]
            ):
                option, setting = float(args[position]), float(args[position + 1])  # type: ignore[arg-type]
                if option != int(option):
                    raise InputError(f"OPTAB option number must be whole, found {option:g}", where)
                request.options.append((int(option), setting, where))
                position += 2
                pairs += 1
            if pairs == 0:
                raise InputError("OPTAB must be followed by option number, value pairs", where)
        elif isinstance(arg, Word) and arg.name in ("LINEAR", "LINCIR", "PLAN", OFF):
            request.modifiers.append(arg.name)
            position += 1
        else:
            raise InputError(
                f"MACHIN/GECENT: expected OPTAB, LINEAR, LINCIR, PLAN or OFF, found {arg}", where
            )
    return request


def first_machin(records: Iterable[Record]) -> tuple[MachinRequest | None, list[Diagnostic]]:
    """Read until the first MACHIN/GECENT statement, as GEINIT does (001 L2433-2437), or
    the first motion record: motion is made for the machine known by then."""
    notes: list[Diagnostic] = []
    for record in records:
        if isinstance(record, Motion):
            break
        if isinstance(record, Statement) and record.major == "MACHIN":
            if is_machin_off(record):
                continue  # it selects no machine (the run prints option 218's totals)
            request = parse_machin(record)
            if request is not None:
                return request, notes
            name = record.args[0] if record.args else ""
            notes.append(
                Diagnostic(f"MACHIN/{name} names another postprocessor; ignored", record.where)
            )
    return None, notes


def ptonly_deck(records: Iterable[Record]) -> tuple[int | None, list[Diagnostic]]:
    """The machine of a PTONLY/2 run (manual §3.1.1.1.1, 001 L2538-2565): the deck
    ``PTONLY/2``, ``MACHIN/GECENT, n``, ``FINI`` postprocesses a saved CL tape. Its MACHIN
    fills IPOSTP, the postprocessor's name and machine number (001 L2456-2521), and the run
    takes its machine from there, not from the tape; so the deck's MACHIN gives the machine
    number only, and OPTAB pairs or modifiers on it are said to be ignored (they reach no CL
    tape: the tape's own MACHIN statements change the options, 001 L2563-2565). MACHIN for
    another postprocessor is passed over as on a tape; a second MACHIN/GECENT would post the
    tape once more, for another machine: one post per machine here."""
    notes: list[Diagnostic] = []
    mode_seen = False
    chosen: MachinRequest | None = None
    for record in records:
        if isinstance(record, Fini):
            break
        if isinstance(record, Comment):
            continue
        if not isinstance(record, Statement):
            raise InputError("a PTONLY/2 deck holds PTONLY/2, MACHIN and FINI only", record.where)
        if not mode_seen and record.major != "PTONLY":
            raise InputError("a PTONLY/2 deck must begin with PTONLY/2", record.where)
        if record.major == "PTONLY":
            if record.args != (2.0,):
                shown = ",".join(str(a) for a in record.args)
                raise InputError(
                    f"PTONLY/{shown}: only PTONLY/2 (postprocess a saved CL tape) is a "
                    "postprocessor run",
                    record.where,
                )
            mode_seen = True
        elif record.major == "MACHIN":
            request = parse_machin(record)
            if request is None:
                name = record.args[0] if record.args else ""
                notes.append(
                    Diagnostic(f"MACHIN/{name} names another postprocessor; ignored", record.where)
                )
                continue
            if chosen is not None:
                raise InputError(
                    "a second MACHIN/GECENT in the PTONLY/2 deck: post the tape once per machine",
                    record.where,
                )
            chosen = request
            if request.options or request.modifiers:
                notes.append(
                    Diagnostic(
                        "PTONLY/2: THE DECK'S MACHIN GIVES THE MACHINE NUMBER ONLY; ITS "
                        "OPTAB AND MODIFIERS ARE IGNORED (THE TAPE'S MACHIN STATEMENTS "
                        "CHANGE THE OPTIONS)",
                        record.where,
                    )
                )
        else:
            raise InputError(
                f"{record.major} in a PTONLY/2 deck, which holds PTONLY/2, MACHIN and FINI only",
                record.where,
            )
    if not mode_seen:
        raise InputError("a PTONLY/2 deck must begin with PTONLY/2")
    return (chosen.number if chosen is not None else None), notes


def resolve_machine(
    plugins: PluginSet, override: str | MachineDefinition | None, request: MachinRequest | None
) -> MachineDefinition:
    """--machine wins; then MACHIN/GECENT,nm; then the Standard Machine."""
    if isinstance(override, MachineDefinition):
        return override
    if override is not None:
        pack = plugins.machine(override)
        if pack is None:
            raise InputError(f"machine {override!r} is not installed (see 'gecent machines')")
        return pack.load()
    if request is not None and request.number is not None:
        if not 1 <= request.number <= 99:
            raise FatalError(999, f"MACHIN/GECENT,{request.number}")
        pack = plugins.machine(str(request.number))
        if pack is None:
            raise InputError(
                f"MACHIN/GECENT,{request.number}: machine {request.number} is not installed "
                "(see 'gecent machines')"
            )
        return pack.load()
    pack = plugins.machine("standard")
    if pack is None:
        raise InputError("the Standard Machine is not installed; give --machine")
    return pack.load()


def apply_machin_options(
    machine: MachineDefinition, request: MachinRequest
) -> tuple[MachineDefinition, list[Diagnostic]]:
    """Apply MACHIN/...,OPTAB,n,v pairs and the LINEAR/LINCIR modifiers."""
    notes: list[Diagnostic] = []
    changes: dict[int, OptionValue] = {}
    cat = catalogue()
    for number, value, where in request.options:
        if not 1 <= number <= OPTION_COUNT:
            raise InputError(
                f"MACHIN/GECENT,...,OPTAB: there is no option {number} "
                f"(options are 1..{OPTION_COUNT})",
                where,
            )
        spec = cat.option(number)
        if number == TRANSFORM_CLASS:
            refused = _class_change_refused(machine, value)
            if refused is not None:
                notes.append(Diagnostic(refused, where))
                continue
        if spec.fixed and number not in CHANGED_BY_MACHIN_DESPITE_LIST:
            notes.append(
                Diagnostic(
                    f"OPTION {number} ({spec.alias}) CANNOT BE CHANGED BY MACHIN; VALUE IGNORED",
                    where,
                )
            )
        elif spec.kind == "text":
            notes.append(
                Diagnostic(
                    f"OPTION {number} ({spec.alias}) HOLDS A TAPE CODE AND "
                    "CANNOT BE SET BY MACHIN; VALUE IGNORED",
                    where,
                )
            )
        else:
            if number == MACHINE_TYPE and value not in MACHINE_TYPES:
                _machine_type_fatal(value, where)
            changes[number] = value
    for modifier in request.modifiers:
        if modifier == OFF:
            continue  # no option: the run ends the machine's section (option 218)
        if modifier == "PLAN":
            plan_note = _plan(machine, changes, request)
            if plan_note is not None:
                notes.append(plan_note)
            continue
        changes[28] = 0.0 if modifier == "LINEAR" else 1.0
    if not changes:
        return machine, notes
    changed = machine.with_options(changes)
    errors, _ = check_definition(changed)
    if errors:
        table, entry, rule = errors[0]
        position = request.options[0][2] if request.options else None
        raise InputError(
            f"MACHIN/GECENT,...,OPTAB makes machine {machine.label} invalid: "
            f"[{table}] entry {entry}: {rule}",
            position,
        )
    return changed, notes


def _machine_type_fatal(value: float, where: SourcePosition) -> None:
    """FUNLNK, called by GEMON once the run's machine is known, "interrogate[s] the tables
    of the Machine subroutine and set[s] up a BCD list of function overlays" from option
    132; a type it has no overlays for is "Error 8000: Option 132 is set incorrectly",
    through ERDMP1 (001 L31636-31662, the types L25946-25962). A MACHIN/...,OPTAB,132 the
    run meets is that: fatal (exit 1, the listing and GEDUMP). A machine FILE with a bad
    option 132 is refused when it loads (exit 2), before any run exists."""
    raise FatalError(
        8000,
        f"MACHIN/GECENT,...,OPTAB,132,{value:g}: the machine types are 0..8 (0 lathe, 1 mill, "
        "2 positioning, 3 drafting, 4 flame cutter, 5 welder, 6 filament winder, 7 "
        "positioning used as a contouring, 8 positioning with the contouring option); no "
        "function overlays for this one",
        where,
    )


def _plan(
    machine: MachineDefinition, changes: dict[int, OptionValue], request: MachinRequest
) -> Diagnostic | None:
    """The PLAN modifier: GEMON calls GEPLAD "if the modifier PLAN is given in the MACHIN
    statement and option 1 is + 1" (001 L473-476, IGEFLG L17369-17375), option 1 as this
    MACHIN leaves it; otherwise PLAN asks for nothing and is said to be ignored. GEPLAD runs
    once, before the run, for the first MACHIN/GECENT (core/plan.py), and its planned tape
    carries that MACHIN without PLAN: a PLAN the run meets came later, or on a multihead
    program (planned per head by no one), and is said to be ignored."""
    option_1 = changes.get(1, machine.option(1))
    where = request.where
    if option_1 != 1.0:
        return Diagnostic(
            f"MACHIN/GECENT,...,PLAN IGNORED: OPTION 1 = {float(option_1):g}, NOT +1; "
            "GEPLAD PLANS ONLY FOR POSITIONING MACHINES",
            where,
        )
    return Diagnostic(
        "MACHIN/GECENT,...,PLAN IGNORED HERE: GEPLAD PLANS THE CL TAPE ONCE, BEFORE THE "
        "RUN, FROM THE FIRST MACHIN/GECENT OF A SINGLE-HEAD PROGRAM",
        where,
    )


def _class_change_refused(machine: MachineDefinition, value: float) -> str | None:
    """Why MACHIN may not set option 116 to ``value``, or None. The class is the machine's
    structure: which rotary heads and tables move, with their registers and constants (options
    100-105, 128), all set by the machine subroutine; option 116 is "required only for
    multiaxis machines" (001 L25771-25777). So MACHIN may change one class for another on a
    multiaxis machine, but not make a three-axis machine multiaxis, nor the reverse, nor give
    a class to a five-axis machine described by data (its [kinematics] are its transform)."""
    if machine.kinematics is not None and value != 0:
        return (
            f"OPTION 116 = {value:g} CANNOT BE SET BY MACHIN ON MACHINE {machine.label}: ITS "
            "[kinematics] ARE ITS TRANSFORM; VALUE IGNORED"
        )
    if machine.kinematics is None and (machine.number_option(116) == 0) != (value == 0):
        kind = "A THREE-AXIS MACHINE MULTIAXIS" if value != 0 else "A MULTIAXIS MACHINE THREE-AXIS"
        return (
            f"OPTION 116 = {value:g} (TRANSFORM CLASS) CANNOT MAKE {kind} "
            f"(MACHINE {machine.label}); VALUE IGNORED"
        )
    return None


__all__ = [
    "MachinRequest",
    "MachineFileInvalid",
    "apply_machin_options",
    "first_machin",
    "is_machin_off",
    "parse_machin",
    "ptonly_deck",
    "resolve_machine",
]
