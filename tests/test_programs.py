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

import pytest
from gecent.core.dispatch.post import post
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins

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


# MACH04 (the sample lathe, 001 L27681-27799) with OPTAB 30 = 1 (OPSKIP) and 145 = 1 (full
# reinstatement) from the program's MACHIN: CL x is the lathe's Z, CL y its -X (option 59
# +Z-X); formats 14 for X, Z, I, K; F 3.2 inverse time, G11 below 1 inch (x 1) and G01
# from 1 inch (x 10); rapid at 100 IPM on each machine axis (options 42, 44), command held
# to option 45 = 750; gear codes M40 into rapid (TABLEM 42) and the feed range's own code
# back (range 2: TABLEM(114) = M41); dwells in Z over option 56 = 10; G04 fills every block
# without a G (option 38 = 1).
LATHE_ON_MACH04 = [
    "SHAFT3301OP20",
    # TOOLNO/1,OFSETL,1: T = 1 x 100 + 1, M06, option 83's 2 s dwell (Z+0.2)
    "N010G04Z+02T00101M06",
    # SPINDL/250,CLW: range 2 (18-600), magic three 625, TABLEM(74) = M62
    "N011G04S625M62",
    # COOLNT/ON's M08 waits; the rapid's M40 pushes it out (STOREM)
    "N014G04M08",
    # RAPID (10, 3) -> (8, 1.6): rho = 2 / 100 min, 10 x (2.441 / .02) / 2.441 = 500
    "N014G01X+14Z-2F500M40",
    # FEDRAT/4,IPM,RANGE,2: M41, also the way back from rapid; face 1.6 at 4 IPM: 40 / 1.6
    "N016G01X+16F025M41",
    # RAPID -> (8.1, 1.25): 10 / (1.25 / 100) = 800, held to option 45 = 750
    "N018G01X-125Z+01F750M40",
    # FEDRAT/6: turn 5.1 inches: 60 / 5.1 = 11.76
    "N020G01Z-51F01176M41",
    "N021G11X-035F01714",  # the shoulder, .35 at 6 IPM in G11: 6 / .35
    "N022G04Z+02",  # DELAY/2
    "N023G04M00",  # STOP: M00 in a block by itself; spindle and coolant are off
    # the first motion after the stop reinstates: T in a block, S with its direction M,
    # the feed range's M41 (pushed out by the coolant's M08, which rides in the motion)
    "N024G04T00101",
    "N024G04S625M62",
    "N024G04M41",
    "N024G11Z+01F060M08",  # .1 at 6 IPM: 6 / .1
    # OPSKIP/ON (option 30 = 1): a spring pass the operator may skip
    "/N026G01Z+5F012",
    "/N027G11X+036F01667",
    "/N028G01Z-51F01176",
    # RAPID home (10, 3) from (3, 1.24): 10 x 100 / 7 = 142.86
    "N031G01X-176Z+7F14286M40",
    "N033G04Z+02T00202M06",  # TOOLNO/2,OFSETL,2
    # SPINDL/100: range 1; running 250 > .25 x 600 (option 137 = -.25): the protective
    # shift through 150 RPM (S615) with its 6 s dwell first, then S610 and M60
    "N034G04Z+06S615",
    "N034G04S610M60",
    "N035G04Z+01M50",  # COUPLE/ON: M50 in option 92's 1 s dwell block
    # RAPID (still in rapid) -> (8.5, 1.2): 10 / (1.8 / 100) = 555.56
    "N038G01X+18Z-15F55556",
    # PITCH/8,INCR,10: the lead decreases, G35; .125 x M (10) = K1.25; THRATE =
    # (.1^2 - .125^2) / (2 x 4.5) = -.000625, F = .00625 -> .0063; the thread leaves rapid
    "N040G35Z-45K125F00063M41",
    "N042G11X-04F250M40",  # RAPID up .4: 100 / .4
    "N043G04Z+01M51",  # COUPLE/OFF
    "N045G01X-14Z+6F16667",  # RAPID home: 10 x 100 / 6
    "N047G04M09",  # COOLNT/OFF waits, SPINDL/OFF's M05 pushes it out
    "N047G04M05",
    "N048G04Z+02T00000",  # END: option 97 = 2 s with T0
    "N048G04M02",  # the end code, CODE +5
    "(" * 72,  # option 11 = +1: a card of space codes (the tape image's "(")
]


def test_lathe_program_on_mach04_block_by_block() -> None:
    """Facing, turning, a dwell, a stop with reinstatement, an OPSKIP spring pass, a tool
    change and a variable-lead thread. The dwell time is the DELAY (2 s), the two tool
    changes (2 + 2 s), the coupling (1 + 1 s), the protective shift (6 s) and END's T0
    (2 s): 16 s = 0.27 min."""
    result = post(str(EXAMPLES / "lathe_mach04.apt"), get_plugins())
    assert tape_lines(result.blocks) == LATHE_ON_MACH04
    assert result.diagnostics == []
    assert round(result.dwell_minutes, 4) == round(16 / 60, 4)
    thread = next(b for b in result.blocks if b.cells[2] == 35.0)
    assert thread.cells[19] == 12.5  # 100 RPM x .125 in
    assert thread.cut_minutes == pytest.approx((0.125 - 0.1) / 0.000625 / 100)  # 40 turns


def test_lathe_program_listing_shows_skips_and_times() -> None:
    plugins = get_plugins()
    result = post(str(EXAMPLES / "lathe_mach04.apt"), plugins)
    printout = plugins.get("printouts", 1)
    listing = printout.render(result.machine, result.blocks, result.partno)
    lines = listing.splitlines()
    assert sum(1 for line in lines if line.startswith(" /0")) == 3
    assert "DWELL TIME 0.27 MIN;" in listing
