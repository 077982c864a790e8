"""A CAM system's cycle arguments read into the post's CYCLE (not a plugin: the NX,
SolidWorks CAM and Fusion dialects share it): bare numbers in their order, and word, value
pairs (``RAPTO,3``); a word whose value is ``AUTO`` is the post's own default and is left
out (NX's ``RTRCTO,AUTO``)."""

from __future__ import annotations

from typing import Any

from gecent.core.cl.records import Word
from gecent.core.errors import InputError, SourcePosition

FEED_UNITS = ("MMPM", "IPM", "MMPR", "IPR")


def split_cycle(
    items: tuple[Any, ...] | list[Any], where: SourcePosition
) -> tuple[list[float], dict[str, float]]:
    numbers: list[float] = []
    pairs: dict[str, float] = {}
    index = 0
    while index < len(items):
        item = items[index]
        if not isinstance(item, Word):
            numbers.append(float(item))
            index += 1
            continue
        following = items[index + 1] if index + 1 < len(items) else None
        if isinstance(following, Word) and following.name == "AUTO":
            index += 2
            continue
        if following is None or isinstance(following, Word):
            raise InputError(f"CYCLE: {item.name} takes a number", where)
        pairs[item.name] = float(following)
        index += 2
    return numbers, pairs


def cycle_words(
    kind: str,
    depth: float,
    clear: float,
    pairs: dict[str, float],
    step: float | None = None,
    back: bool = False,
) -> list[Any]:
    """CYCLE/kind,DEPTH,d,CLEAR,c[,STEP,s][,DWELL,t][,RETURN,0][,unit,feed]: ``back``
    returns to the level the cycle started from (G98)."""
    words: list[Any] = [kind, "DEPTH", depth, "CLEAR", clear]
    if step:
        words += ["STEP", step]
    if pairs.get("DWELL"):
        words += ["DWELL", pairs["DWELL"]]
    if back:
        words += ["RETURN", 0.0]
    for unit in FEED_UNITS:
        if unit in pairs:
            words += [unit, pairs[unit]]
    return words
