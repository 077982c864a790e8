"""Rapid traverse: the option-109 modes and the option-46 gear shift (manual §4.1.4,
001 L11809-11910; option 109 L25698-25719; option 46 L24979-24995; sample printout of rapid
traverse shifting L10362-10383)."""

from __future__ import annotations

from dataclasses import replace

import pytest
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post

PROGRAM = [
    "FROM/0,0,0",
    "FEDRAT/10",
    "GOTO/1,0,0",
    "RAPID",
    "GOTO/2,0,0",
    "GOTO/3,0,0",
    "FEDRAT/100",
    "GOTO/4,0,0",
    "GOTO/5,0,0",
    "FEDRAT/20",
    "GOTO/6,0,0",
]


def rapid_flags(mode: str) -> list[tuple[str, bool]]:
    machine = get_plugins().machine("mach23").load()
    result = post([f"MACHIN/GECENT,23,OPTAB,109,{mode}", *PROGRAM], machine)
    return [(b.punch, b.rapid) for b in result.blocks if b.punch]


@pytest.mark.parametrize(
    ("mode", "rapid_records"),
    [
        ("0", [6]),  # one-shot: only the motion after RAPID
        ("-1", [6, 7]),  # modal until any FEDRAT
        ("1", [6, 9]),  # one-shot, and FEDRAT/100 above option 25 (60) is a RAPID
        ("2", [6, 7, 9, 10]),  # as +1 and modal: FEDRAT/20 within range ends it
    ],
)
def test_option_109_modes(mode: str, rapid_records: list[int]) -> None:
    blocks = rapid_flags(mode)
    assert [int(p[1:4]) for p, rapid in blocks if rapid] == rapid_records
    assert len(blocks) == 6


def test_option_109_plus_one_does_not_warn_about_the_rapid_feedrate() -> None:
    machine = get_plugins().machine("mach23").load()
    clamped = post(["MACHIN/GECENT,23", *PROGRAM], machine).diagnostics
    rapid = post(["MACHIN/GECENT,23,OPTAB,109,1", *PROGRAM], machine).diagnostics
    assert [d.text for d in clamped] == [
        "FEEDRATE 100 IPM IS OUTSIDE THE MACHINE RANGE 0-60; 60 IPM USED"
    ]
    assert rapid == []


LATHE = [
    "FROM/0,0,0",
    "FEDRAT/10",
    "GOTO/1,-1,0",
    "RAPID",
    "GOTO/5,-3,0",
    "GOTO/6,-3,0",
    "RAPID",
    "GOTO/6.01,-3,0",
    "GOTO/6.02,-3,0",
]


def lathe_tape(options: str = "") -> list[str]:
    machine = get_plugins().machine("mach04").load()
    result = post([f"MACHIN/GECENT,4{options}", *LATHE], machine)
    return [b.punch for b in result.blocks if b.punch]


def test_mach04_gear_shift_codes_ride_in_the_motion_blocks() -> None:
    """MACH04: option 46 = -1 (one M code for all axes), TABLEM(42) = M40 into rapid and
    TABLEM(43) = M41 back (001 L27712-27713); its shift dwells (options 16, 81, 82) are 0,
    so STOREM leaves each code pending for the next block. The second RAPID is shorter
    than option 37 (0.18 in): no shift, the feed range's top feed (option 39) instead."""
    assert lathe_tape() == [
        "N004G01X+1Z+1F07071",
        "N006G01X+2Z+4F250M40",
        "N007G01Z+1F100M41",
        "N009G11Z+001F750",
        "N010G11Z+001K002F500",  # 1 * 10 / 0.01 = 1000 > 750: multiplier c = 2, K = 0.02
    ]


def test_gear_shift_with_dwells_follows_the_manual_sample() -> None:
    """With the standard dwells (option 16 = 0.5 s catch-up, 81 = 2 s into rapid, 82 = 1 s
    back) the blocks are those of the manual's sample (L10362-10383): catch-up dwell, then
    the shift dwell carrying the M code, then the move. Dwells go in the option-57 register
    (MACH04: 5, the Z register) divided by option 56 (10): 0.05, 0.2 and 0.1."""
    assert lathe_tape(",OPTAB,16,0.5,81,2,82,1") == [
        "N004G01X+1Z+1F07071",
        "N006G04Z+005",
        "N006G04Z+02M40",
        "N006G01X+2Z+4F250",
        "N007G04Z+005",
        "N007G04Z+01M41",
        "N007G01Z+1F100",
        "N009G11Z+001F750",
        "N010G11Z+001K002F500",  # 1 * 10 / 0.01 = 1000 > 750: multiplier c = 2, K = 0.02
    ]


def test_one_m_code_per_axis_flushes_the_waiting_code() -> None:
    """Option 46 = +1 asks for TABLEM(42), (44), (46): a second code makes STOREM output
    the first in a block of its own, which takes G = TABLEG(5) under option 38 = +1.
    The standard table has no gear-shift codes, so this mill gets M42, M44 and M46."""
    standard = get_plugins().machine("mach23").load()
    tablem = list(standard.tablem)
    tablem[42], tablem[44], tablem[46] = 42, 44, 46
    machine = replace(standard, tablem=tuple(tablem))
    result = post(
        [
            "MACHIN/GECENT,23,OPTAB,46,1,16,0,81,0,82,0",
            "FROM/0,0,0",
            "FEDRAT/10",
            "RAPID",
            "GOTO/2,0,0",
        ],
        machine,
    )
    assert [b.punch for b in result.blocks if b.punch] == [
        "N005G04M42",
        "N005G04M44",
        "N005G01X+02F300M46",
    ]


def test_rapid_rates_follow_the_machine_axes() -> None:
    """Options 42-44 are the machine's X, Y, Z rates: MACH04 sets 43 = 0 (a lathe has no
    Y), so its cross slide (CL y, the lathe's X by option 59) moves at option 42 = 100 IPM.
    (10, 3) -> (8.5, 1.2): rho = max(1.5 / 100, 1.8 / 100) = .018 min, the command
    10 x (2.343 / .018) / 2.343 = 555.56 (not 666.67, as if the cross slide had no rate)."""
    lathe = get_plugins().machine("mach04").load()
    result = post(["FROM/10,3,0", "RAPID", "GOTO/8.5,1.2,0"], lathe)
    (block,) = [b for b in result.blocks if b.rapid]
    assert float(block.cells[11]) == 555.56
