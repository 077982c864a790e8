"""Each head's view of a multihead machine (manual §3.4.8.1, 001 L7176-7206; TABLEM chart
001 L23165-23245): head 1 posts with the machine's main tables; head 2 with its own
register letters and formats ([heads.2], GMWORD/GMFORM) and its own M codes where the
TABLEM chart has a head-2 cell, so that the first pass's routines (RAPID's gear shifts,
the spindle's SFM codes, the turret) pick "the M code belonging to the head currently
selected" (001 L7270-7278) without knowing about heads.

A second S code (option 153 = 2 or 3, 001 L26185-26194) is a spindle register of head 2's
own with its own spindle table: SRTAB holds the tables one after the other, head 1's
first, each of option 7 x option 8 speeds (the layout type 13 gives its two heads' ranges,
001 L15189-15303), and head 2's run reads its own as SRTAB(1 ..). Type 13's one layout
holds both heads already; the types that keep more than the speeds in SRTAB (codes,
factors, generated speeds) have no room for a second table.
"""

from __future__ import annotations

from dataclasses import replace

from gecent.core.absent import ABSENT, Absent
from gecent.core.errors import NotYetSupported
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.rules import GENERATED_TABLE_TYPES, SRTAB_EXTENDED_TYPES

# head 2's TABLEM cells -> the head-1 cells the first-pass routines read
HEAD_2_M_CELLS = {
    142: 42, 143: 43, 144: 44, 145: 45, 146: 46, 147: 47,  # gear engage, rapid and feed
    156: 154, 157: 155,  # automatic SFM on and off
    67: 66,  # spindle speed change
    166: 83, 167: 84,  # turret CLW and CCLW
}  # fmt: skip
# spindle type 13 lays out both heads' ranges in its one SRTAB (001 L15230-15264)
TWO_HEAD_SPINDLE_TYPES = frozenset({13})


def spindle_tables(machine: MachineDefinition) -> int:
    """How many spindle tables SRTAB holds one after the other (option 153: 0 = one)."""
    tables = int(machine.number_option(153))
    return tables if tables in (2, 3) else 1


def head_machine(machine: MachineDefinition, head: int) -> MachineDefinition:
    """The machine as head ``head`` (1 or 2) posts on it in the first pass."""
    if head == 1:
        return machine
    tablem = list(machine.tablem)
    for own, shared in HEAD_2_M_CELLS.items():
        # a head-2 cell the machine leaves absent leaves head 2 without that code
        tablem[shared] = machine.tablem[own] if own < len(tablem) else ABSENT
    return replace(
        machine,
        heads=(machine.heads[head - 1],),
        tablem=tuple(tablem),
        title=f"{machine.title} HEAD {head}",
        store=_own_spindle_table(machine, head),
    )


def _own_spindle_table(machine: MachineDefinition, head: int) -> tuple[float | Absent, ...]:
    """The store as head ``head``'s spindle reads it: its own table at SRTAB(1 ..) when
    the machine has one per head (option 153), else the store as it is."""
    spindle_type = int(machine.number_option(19))
    if spindle_tables(machine) < head or spindle_type in TWO_HEAD_SPINDLE_TYPES:
        return machine.store
    if spindle_type in SRTAB_EXTENDED_TYPES | GENERATED_TABLE_TYPES:
        raise NotYetSupported(
            f"a spindle table per head (option 153) for spindle type {spindle_type}, which "
            "keeps more than its speeds in SRTAB"
        )
    count = machine.speed_count
    first = (head - 1) * count + 1
    store = list(machine.store)
    store[1 : count + 1] = machine.store[first : first + count]
    return tuple(store)
