"""The "absent" sentinel: the manual's DMBITS, "no such function / no value established".

G00 and M00 are real codes, so zero can never mean "absent". ``ABSENT`` refuses to be
used as a truth value: code must say ``value is ABSENT``, never ``if value``.
"""

from __future__ import annotations

from enum import Enum
from typing import Final, Literal

# The numeric bit pattern the 1970 tables used; kept so dumps and transcribed data can name it.
DMBITS_VALUE: Final = -40404040.0


class _Absent(Enum):
    ABSENT = "absent"

    def __repr__(self) -> str:
        return "ABSENT"

    def __str__(self) -> str:
        return "absent"

    def __bool__(self) -> bool:
        raise TypeError("ABSENT has no truth value; compare with 'is ABSENT'")


ABSENT: Final = _Absent.ABSENT
Absent = Literal[_Absent.ABSENT]


def or_zero(value: float | Absent) -> float:
    """A cell's number, 0.0 where the cell holds nothing."""
    return 0.0 if value is ABSENT else float(value)


# Spellings accepted in machine files for a deleted table entry.
ABSENT_SPELLINGS: Final = frozenset({"absent", "dmbits"})
