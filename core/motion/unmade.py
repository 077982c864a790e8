"""Motion the manual's overlays never make, refused as bad input naming why: threading is
the lathe's THREAD/THREDO (GELATH) and the mill's THREDM (GEMILL), SFMO is the lathe's, and
GEMAXS drives a contouring control (docs/decisions.md, "The last not-yet-supported forms",
issue 22 wave 7)."""

from __future__ import annotations

from gecent.core.cl.records import Motion
from gecent.core.errors import InputError
from gecent.core.state import PostState

THREAD_POSITIONING = (
    "THREAD on a positioning machine: threading is the lathe's THREAD/THREDO (GELATH) and "
    "the mill's THREDM (GEMILL); the positioning overlay GEPOS has no thread (001 "
    "L38323-38380)"
)
THREAD_MULTIAXIS = (
    "THREAD on a multiaxis machine: threading is the lathe's THREAD/THREDO (GELATH) and the "
    "mill's THREDM (GEMILL), whose lead is along the machine's slides; the multiaxis "
    "overlay GEMAXS (option 116) has no thread (001 L38323-38380, L443-444)"
)
SFM_MULTIAXIS = (
    "SFM on a multiaxis machine: SFMO (GELATH) keeps the surface speed by the radius of a "
    "CL coordinate about the spindle's centre line; under GEMAXS (option 116) the transform "
    "turns the part, so that radius is not the cut's (001 L37415-37420, L443-444)"
)
MULTIAXIS_POSITIONING = (
    "multiaxis motion on a positioning machine: GEMAXS's transforms (option 116) make a "
    "contouring control's moves (the manual's multiaxis machine has option 1 = 0, 001 "
    "L443-444, L550-566); a positioning machine turns its table with ROTATE/TABLE (ROTABA)"
)


def refuse_on_positioning(state: PostState, record: Motion) -> None:
    if state.threading.armed:
        raise InputError(THREAD_POSITIONING, record.where)


def refuse_on_multiaxis(state: PostState, record: Motion, positioning: bool) -> None:
    """What a multiaxis machine's motion cannot do."""
    if positioning:
        raise InputError(MULTIAXIS_POSITIONING, record.where)
    if state.threading.armed:
        raise InputError(THREAD_MULTIAXIS, record.where)
    if state.sfm.active:
        raise InputError(SFM_MULTIAXIS, record.where)
