"""Whole part programs from examples/, posted block by block against expectations derived by
hand from the machine data and the manual's rules (issue 5's done-when).

MACH23 (the sample mill, 001 L27800-27857): no S or T register, so SPINDL and LOADTL give
M codes only and its tool changes give nothing (no T, no TABLEM(7)); no end-of-program M
(TABLEM(3) absent); inverse-time F (format 3.0) FRN = GDIMUL x F / D, G11 for departures
below 1 inch (GDIMUL 1) and G01 from 1 inch (GDIMUL 10); rapid (option 36 = 0) moves each
axis at its own 60 IPM (options 42-44), command held to option 45 = 500; option 38 = 1 puts
G04 in blocks without a G.
"""

from __future__ import annotations

from pathlib import Path

from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins
from gecent.core.run import post

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"

MILL_ON_MACH23 = [
    "PLATE2210HOLES",  # PARTNO, punched as its coded image
    # LOADTL/1: nothing (no T, no TABLEM(7)); SPINDL/1200,CLW: M03 alone (no S)
    "N009G04M03",
    # CYCLE/DRILL: to hole 1 at rapid, X1 Y1 at 60 IPM each: 10 x 84.85 / 1.414 = 600 -> 500;
    # COOLNT/FLOOD's M08 waits for this first motion
    "N012G01X+01Y+01F500M08",
    "N012G01Z-049F122",  # rapid to R = 0 + .1: 10 x 60 / 4.9 = 122.4
    "N012G11Z-007F009",  # drill to -.6 at 6 IPM: 6 / .7 = 8.57
    "N012G11Z+007F086",  # rapid back to R: 60 / .7 = 85.7
    "N013G01X+02F300",  # hole 2 at rapid: 10 x 60 / 2
    "N013G11Z-007F009",
    "N013G11Z+007F086",
    # COOLNT/OFF (record 15) waits; LOADTL/2 gives nothing; SPINDL/300 (same direction, no
    # S register) outputs its block with the waiting M09
    "N018G04M09",
    # CYCLE/TAP: COOLNT/MIST falls back to M08 (no mist code, option 33); R = 0 + .2
    "N021G01X-02F300M08",
    "N021G11Z+001F500",  # rapid up to R from .1: 60 / .1 = 600 -> 500
    "N021G11Z-007F024",  # tap to -.5 at 16.667 IPM: 16.667 / .7 = 23.8
    "N021G11Z+007M04",  # out at the same feed (F not repeated) with the spindle reversed
    # the M03 that follows the tap rides in SPINDL/800's block (LOADTL/3 gives nothing)
    "N025G04M03",
    # CYCLE/BORE: R = .1; feed in and out
    "N027G01X+02F300",
    "N027G11Z-001F500",  # rapid down to R from .2
    "N027G11Z-0085F005",  # bore to -.75 at 4 IPM: 4 / .85 = 4.7
    "N027G11Z+0085",  # out at the same feed
    # COOLNT/OFF waits and is forced out by SPINDL/OFF's M05 (STOREM), both in record 30
    "N030G04M09",
    "N030G04M05",
    # RAPID home from (3, 1, .1): Z is the slowest axis, 4.9 / 60 min: 10 x 60 / 4.9
    "N032G01X-03Y-01Z+049F122",
    "",  # END: option 11 = 0 is the filler card, 72 blank frames (an empty image line)
]


def test_mill_program_on_mach23_block_by_block() -> None:
    result = post(str(EXAMPLES / "mill_mach23.apt"), get_plugins())
    assert tape_lines(result.blocks) == MILL_ON_MACH23
    # END: MACH23 has no end-of-program M code (TABLEM(3) absent, 001 L27842)
    assert [d.text for d in result.diagnostics] == [
        "REQUESTED MISCELLANEOUS FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE"
    ]
    assert result.diagnostics[0].where is not None
    assert result.diagnostics[0].where.line == 33
