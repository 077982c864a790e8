"""Slide limits (TSTLIM, 001 L38955-39010; options 110 and 121-126, L25720-25734,
L25843-25901): tested on the CL axes with option 59's signs, per option 110."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.errors import RunStopped
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post

LATHE = ["FROM/5,2,0", "FEDRAT/10", "GOTO/63,2,0", "GOTO/63,-1,0", "GOTO/10,-10,0"]


def test_mach04_warns_for_each_point_beyond_a_limit() -> None:
    """MACH04: X (CL x) 0..62, Y (CL y, signed -1 by option 59 = +Z-X) -9..26, Z untested
    (0/0). x = 63 is beyond on records 3 and 4; y = -10 gives +10, within. FEDRAT/10 names
    no range on this two-range lathe: option 91's is assumed (001 L31199)."""
    result = post(LATHE, get_plugins().machine("mach04").load())
    assert [(d.where.record if d.where else None, d.text) for d in result.diagnostics] == [
        (2, "OPTION FEED RATE RANGE ASSUMED."),
        (3, "X AXIS SLIDE LIMIT HAS BEEN EXCEEDED *** WARNING"),
        (4, "X AXIS SLIDE LIMIT HAS BEEN EXCEEDED *** WARNING"),
    ]
    assert not result.punch_suppressed


def test_option_110_minus_1_stops_the_run() -> None:
    machine = get_plugins().machine("mach04").load().with_options({110: -1.0})
    with pytest.raises(RunStopped, match=r"X AXIS SLIDE LIMIT .* \(63 outside 0\.\.62"):
        post(LATHE, machine)


def test_option_110_plus_2_writes_the_listing_but_no_tape(tmp_path: Path) -> None:
    source = tmp_path / "lathe.apt"
    source.write_text("MACHIN/GECENT,4,OPTAB,110,2\n" + "\n".join(LATHE) + "\nFINI\n")
    tape, listing = tmp_path / "lathe.tape", tmp_path / "lathe.lis"
    result = CliRunner().invoke(
        main, ["post", str(source), "-o", str(tape), "--listing", str(listing)]
    )
    assert result.exit_code == 0, result.stderr
    assert "SLIDE LIMITS EXCEEDED: NO PUNCHED OUTPUT (OPTION 110 = 2)" in result.stderr
    assert listing.exists() and not tape.exists()
