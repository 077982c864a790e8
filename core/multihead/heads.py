"""Each head's view of a multihead machine (manual §3.4.8.1, 001 L7176-7206; TABLEM chart
001 L23165-23245): head 1 posts with the machine's main tables; head 2 with its own
register letters and formats ([heads.2], GMWORD/GMFORM) and its own M codes where the
TABLEM chart has a head-2 cell, so that the first pass's routines (RAPID's gear shifts,
the spindle's SFM codes, the turret) pick "the M code belonging to the head currently
selected" (001 L7270-7278) without knowing about heads.
"""

from __future__ import annotations

from dataclasses import replace

from gecent.core.absent import ABSENT
from gecent.core.machine.definition import MachineDefinition

# head 2's TABLEM cells -> the head-1 cells the first-pass routines read
HEAD_2_M_CELLS = {
    142: 42, 143: 43, 144: 44, 145: 45, 146: 46, 147: 47,  # gear engage, rapid and feed
    156: 154, 157: 155,  # automatic SFM on and off
    67: 66,  # spindle speed change
    166: 83, 167: 84,  # turret CLW and CCLW
}  # fmt: skip


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
    )
