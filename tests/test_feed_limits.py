"""FEDLIM, each axis's own feed limits (option 25 < 0; manual §4.1.5.3, spec 05 §7.2-7.3):
the worked examples E18 (a lathe) and E19 (a multiaxis cone groove), and a post."""

from __future__ import annotations

from dataclasses import replace
from math import pi, sqrt

import pytest
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.feed.limits import limited_feed
from gecent.core.machine import standard_machine
from gecent.core.output.block import Code
from gecent.core.run import Run

from .test_post_linear import post


def test_e18_lathe_axis_limits() -> None:
    """E18 (001 L12087-12215): +Z-X lathe, range 2: Z 0.13..13.5, X 0.36..36 IPM, the Y
    slot zero. F = 100, dX = 2, dZ = 3 (S = 3.61): Fx 55.5 > 36 allows 65, Fz 83.3 > 13.5
    allows 16.2: F = 16.2 IPM (exact 16.225); Fx 9.0, Fz 13.5."""
    path = sqrt(13.0)
    # the slots in the CL axis order, option 59's: Z (CL x), X (CL y), Y (CL z)
    limits = [(0.13, 13.5), (0.36, 36.0), (0.0, 0.0)]
    feed = limited_feed(100.0, [3.0, 2.0, 0.0], path, limits, highest=200.0)
    assert feed == pytest.approx(13.5 * path / 3.0)
    assert round(feed, 1) == 16.2
    assert round(2 * feed / path, 1) == 9.0 and round(3 * feed / path, 1) == 13.5


def test_e19_a_table_axis_limit_on_a_multiaxis_machine() -> None:
    """E19 (001 L12280-12434): a cut vector L = 0.4 in of the CL path; the table turns
    11.46 degrees at option 112's radius 2 in: 0.4 in, FB = 40 IPM at F = 40; its range-1
    maximum 3 RPM allows 2 pi 2 x 3 = 37.7 IPM: F = 37.7 (dY .0318, dZ .00745 in)."""
    table = 2 * pi * 2.0
    turned = 2 * pi * (11.46 / 360.0) * 2.0
    limits = [(0.05, 4.0), (0.1, 6.0), (0.1, 6.0), (0.5 * 2 * pi * 3.0, 2.0 * 2 * pi * 3.0),
              (0.5 * table, 3.0 * table)]  # fmt: skip
    feed = limited_feed(40.0, [0.0, 0.0318, 0.00745, 0.0, turned], 0.4, limits, highest=500.0)
    assert round(feed, 1) == 37.7
    assert round(0.0318 * feed / 0.4, 1) == 3.0 and round(0.00745 * feed / 0.4, 3) == 0.702


def test_a_post_holds_the_feed_to_the_axis_limits() -> None:
    """Option 25 = -200: X may feed 5 IPM at most; FEDRAT/20 along (3, 4) asks 12 IPM of X:
    the feed is 5 x 5 / 3 = 8.333 IPM, with the diagnostic; |option 25| holds the rest."""
    machine = standard_machine().with_options({25: -200.0, 18: 1.0, 174: 6.0})
    machine = replace(machine, feed_ranges=((0.0, 5.0), (0.0, 100.0), (0.0, 100.0)))
    result = post(["FROM/0,0,0", "FEDRAT/20", "GOTO/3,4,0", "GOTO/3,4,5"], machine)
    moves = [b for b in result.blocks if b.code is Code.LINEAR]
    assert float(moves[0].cells[19]) == pytest.approx(25.0 / 3.0)  # type: ignore[arg-type]
    assert float(moves[1].cells[19]) == pytest.approx(20.0)  # type: ignore[arg-type]
    assert any("AXIS FEED LIMITS" in d.text for d in result.diagnostics)


def test_a_multiaxis_move_counts_its_table_turn() -> None:
    """MACH40 (class 1) with option 25 < 0: the table (C, register 7) may turn 0.1 RPM at
    option 112's 16 in, 10.05 IPM; a move turning C 30 degrees over 1 in of CL path at 20
    IPM asks the table for 20 x 8.378 / 1 IPM: the feed falls to 10.05 / 8.378 x 1 IPM."""
    from gecent.core.machine.selection import resolve_machine
    from gecent.core.plugins import get_plugins

    base = resolve_machine(get_plugins(), "40", None)
    machine = base.with_options({25: -999.0, 18: 1.0, 174: 10.0, 111: 360.0})
    pairs = ((0.0, 999.0),) * 3 + ((0.0, 999.0), (0.0, 0.1))
    machine = replace(machine, feed_ranges=pairs)
    tilt = (0.0, 0.6, 0.8)
    turned = (0.6 * 0.5, 0.6 * sqrt(3) / 2, 0.8)  # C from 90 to 60 degrees
    result = post(
        [f"FROM/0,0,10,{','.join(map(str, tilt))}", "FEDRAT/20",
         f"GOTO/1,0,10,{','.join(map(str, turned))}"],
        machine,
    )  # fmt: skip
    move = next(b for b in result.blocks if b.code is Code.LINEAR)
    arc = (pi / 6) * 16.0
    path = 1.0
    expected = 2 * pi * 16.0 * 0.1 * path / arc  # (the turn rounded to option 119's step)
    assert float(move.cells[19]) == pytest.approx(expected, rel=1e-5)  # type: ignore[arg-type]


def test_the_fast_path_leaves_axis_limits_to_the_general_path() -> None:
    """linuxcnc-mill posts by the fast path; with option 25 < 0 its moves go the general
    path, FEDLIM on every one, the F word itself held (F is the feed on a modern control)."""
    from gecent.core.machine.selection import resolve_machine
    from gecent.core.plugins import get_plugins

    base = resolve_machine(get_plugins(), "linuxcnc-mill", None)
    machine = base.with_options({25: -2000.0, 18: 1.0, 174: 6.0})
    machine = replace(machine, feed_ranges=((0.0, 100.0), (0.0, 1000.0), (0.0, 1000.0)))
    lines = ["UNITS/MM", "FROM/0,0,0", "FEDRAT/400", "GOTO/3,4,0", "GOTO/6,8,0", "GOTO/9,12,0"]
    fast, slow = (
        Run(machine, fast=fast).process(AptSourceReader("p.apt").read_lines([*lines, "FINI"]))
        for fast in (True, False)
    )
    tape = [b.punch for b in fast.blocks if b.code is Code.LINEAR]
    assert tape == [b.punch for b in slow.blocks if b.code is Code.LINEAR]
    # X may feed 100 mm/min: 400 along (3, 4) asks 240 of X, so F = 100 x 5 / 3
    assert all(line is not None and line.endswith("F166.667") for line in tape[:1])
    assert all(line is not None and "F" not in line for line in tape[1:])


def test_an_arc_is_held_to_the_axis_limits_too() -> None:
    """SELGCR calls FEDLIM as SELG does (001 L1425-1436): a quarter circle of radius 1
    from (1, 0) to (0, 1) at 20 IPM has chord departures (-1, 1) over an arc of pi/2 in:
    X's mean feed 20 / (pi/2) = 12.7 exceeds its 5 IPM, so F = 5 x (pi/2) / 1 = 7.854."""
    machine = standard_machine().with_options({25: -200.0, 18: 1.0, 174: 6.0})
    machine = replace(machine, feed_ranges=((0.0, 5.0), (0.0, 100.0), (0.0, 100.0)))
    result = post(["FROM/1,0,0", "FEDRAT/20", "CIRCLE/0,0,0,0,0,1,1", "GOTO/0,1,0"], machine)
    arcs = [b for b in result.blocks if b.code in (Code.CIRCLE_XY_CCLW, Code.CIRCLE_XY_CLW)]
    assert arcs
    assert float(arcs[0].cells[19]) == pytest.approx(5.0 * (pi / 2) / 1.0, rel=1e-3)  # type: ignore[arg-type]
