"""Mends found while integrating issue 22's work: each reproduced by a small program."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from gecent.core.cli import main


def test_cycle_off_ends_the_cycle_when_the_macfun_handles_it(tmp_path: Path) -> None:
    """MACH40 with its MACFUN (option 133 = 1): MACF40 handles CYCLE/OFF (its own block),
    and the run's cycle in force must end with it: the point after CYCLE/OFF is a plain
    move, not another hole."""
    source = tmp_path / "c.apt"
    source.write_text(
        # (option 110 = 0: machine Z 14 at Y 0 is below MACF40's Z window, its MCHCON 2 test)
        "PARTNO C\nMACHIN/GECENT,40,OPTAB,133,1,OPTAB,110,0\nFROM/0,0,10,0,0,1\nFEDRAT/10\n"
        "CYCLE/DRILL,1,IPM,5,0.1\nGOTO/1,0,5\nCYCLE/OFF\nGOTO/2,0,5\nFINI\n"
    )
    tape = tmp_path / "c.tap"
    result = CliRunner().invoke(main, ["post", str(source), "-o", str(tape)])
    assert result.exit_code == 0, result.output
    lines = tape.read_text().splitlines()
    assert [line for line in lines if line.startswith("N008")] == ["N008G01Y+1Z-01F00498"]
    assert sum(line.startswith("N006") for line in lines) == 4  # the one hole


def test_a_turret_corrective_move_is_printed(tmp_path: Path) -> None:
    """TURRET/...,NOW on MACH04 (option 106 = 8): the CODE -3 corrective move is punched and
    printed on the listing (it used to stop every printout with "not yet supported")."""
    source = tmp_path / "t.apt"
    source.write_text(
        "PARTNO T\nMACHIN/GECENT,4,OPTAB,106,8\nFROM/0,0,0\nFEDRAT/10\nTURRET/1,1,2,3\n"
        "GOTO/1,1,0\nTURRET/2,2,2.5,1,NOW\nGOTO/2,1,0\nFINI\n"
    )
    tape, listing = tmp_path / "t.tap", tmp_path / "t.lis"
    command = ["post", str(source), "-o", str(tape), "--listing", str(listing)]
    result = CliRunner().invoke(main, command)
    assert result.exit_code == 0, result.output
    assert "N007G01X+2Z-05F04851" in tape.read_text().splitlines()
    printed = [line for line in listing.read_text().splitlines() if line.startswith("  007  01")]
    assert printed and "+2." in printed[0] and "-0.5" in printed[0]
