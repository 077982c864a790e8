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
        "PARTNO C\nMACHIN/GECENT,40,OPTAB,133,1\nFROM/0,0,10,0,0,1\nFEDRAT/10\n"
        "CYCLE/DRILL,1,IPM,5,0.1\nGOTO/1,0,5\nCYCLE/OFF\nGOTO/2,0,5\nFINI\n"
    )
    tape = tmp_path / "c.tap"
    result = CliRunner().invoke(main, ["post", str(source), "-o", str(tape)])
    assert result.exit_code == 0, result.output
    lines = tape.read_text().splitlines()
    assert [line for line in lines if line.startswith("N008")] == ["N008G01Y+1Z-01F00498"]
    assert sum(line.startswith("N006") for line in lines) == 4  # the one hole
