"""Which registers the heads of a multihead machine have of their own and which they share
(options 153, 154 and 195 of the option table, manual §5.6.5, 001 L26185-26204,
L26531-26539).

A second S code (option 153) or a second set of M codes (option 154) is a register of head
2's own, under a letter of its own, as option 152's second set of preparatory codes is
("assigned a letter other than G", 001 L26175-26184); without it both heads use head 1's
register, one letter ([heads.2] names it as head 1 does). The merge pass then carries one
value of it in a combined block (core/multihead/gmout.py).

A common dwell register (option 195 = its letter) is the register both heads' dwells go
in, in place of option 57's register (X for head 1, U for head 2 on MACH51): the register
location both heads' REGSTR give that letter, with its format (docs/decisions.md).
"""

from __future__ import annotations

from gecent.core.errors import InputError, NotYetSupported, SourcePosition
from gecent.core.machine.definition import MachineDefinition


def check_own_registers(machine: MachineDefinition) -> None:
    """Options 153 and 154 agree with head 2's letters: a register of its own has a
    letter of its own, a shared one head 1's letter. Three spindle tables (153 = 3) and
    register sets shared among more than two heads (197) are for a third head, which the
    merge pass (two tapes, TAPES2 and TAPES3) does not have."""
    if machine.number_option(197) != 0:
        raise NotYetSupported(
            f"a machine of more than two heads (option 197 = {machine.number_option(197):g}, "
            "heads sharing a register set): GEMULT merges two heads, one scratch tape each"
        )
    if int(machine.number_option(153)) == 3:
        raise NotYetSupported(
            "a third spindle table (option 153 = 3): it is a third head's, and GEMULT merges "
            "two heads"
        )
    first, second = (head.letters for head in machine.heads[:2])
    # (DBFSEG cell, option, does head 2 have that register of its own?, the word)
    registers = (
        (12, 153, machine.number_option(153) != 0, "spindle speed (S)"),
        (14, 154, machine.number_option(154) != 0, "miscellaneous (M)"),
    )
    for cell, option, own, what in registers:
        if cell >= len(first) or cell >= len(second) or not (first[cell] or second[cell]):
            continue
        if own == (first[cell] == second[cell]):
            says = "a register per head" if own else "one register for both heads"
            raise InputError(
                f"option {option} = {machine.number_option(option):g} asks for {says} for the "
                f"{what} word, but head 2's letter is {second[cell] or 'blank'!r} and head 1's "
                f"{first[cell] or 'blank'!r} ([heads.2] regstr {cell})",
                SourcePosition(machine.origin),
            )


def dwell_letter(machine: MachineDefinition) -> str | None:
    """Option 195's letter, or None when the heads have no common dwell register."""
    value = machine.option(195)
    if isinstance(value, str) and value.strip():
        return value.strip()
    if value == 0:
        return None
    raise InputError(
        f"option 195 is the letter of the heads' common dwell register (or 0), not {value!r}",
        SourcePosition(machine.origin),
    )


def shared_dwell_cell(machine: MachineDefinition) -> int | None:
    """The register location (DBFSEG cell) of the heads' common dwell register in this
    machine's (or head's) REGSTR; None without one."""
    letter = dwell_letter(machine)
    if letter is None:
        return None
    letters = machine.registers.letters
    for cell in range(1, len(letters)):
        if letters[cell] == letter and machine.registers.formats[cell] is not None:
            return cell
    raise InputError(
        f"option 195 names {letter!r} the heads' common dwell register, but no register "
        "location with a format has that letter (REGSTR/REGFOR)",
        SourcePosition(machine.origin),
    )


def check_dwell_register(machine: MachineDefinition) -> int | None:
    """The common dwell register's location, the same on both heads (one register)."""
    from gecent.core.multihead.heads import head_machine

    cells = [shared_dwell_cell(head_machine(machine, head)) for head in (1, 2)]
    if cells[0] != cells[1]:
        raise InputError(
            f"option 195 names the heads' common dwell register, but head 1 has it at REGSTR "
            f"location {cells[0]} and head 2 at {cells[1]}: one register has one location",
            SourcePosition(machine.origin),
        )
    return cells[0]
