"""GEOUT3, the multiple printout of a multihead machine (manual §3.5.6), and the two-head
lathe example program posted block by block on MACH51 from the command line."""

from __future__ import annotations

import json
from pathlib import Path

from click.testing import CliRunner
from gecent.core.cli import main

from .conftest import ROOT

EXAMPLE = ROOT / "examples" / "twohead_mach51.apt"

# Worked by hand from the program: FRN = 10 F / L (option 10 = 0, GDIMUL 10 under G01),
# head 1 feeds 10 IPM, head 2 8 IPM; MACH51's head 2 has U, W, the feed register E and
# no N (001 L28193-28201); each head's first pass in its own scratch file, the operations
# sequenced by OP/n and cut together under equal numbers (two feedrate registers: the
# first moves together, then the head that has cut the shorter time).
TAPE = [
    "TWO-HEADLATHEEXAMPLE",  # the PARTNO of each tape (001 L2214-2300)
    "N007G04S47M03",  # head 1's spindle, 200 RPM -> 196, S47
    "TWO-HEADLATHEEXAMPLE",
    "G04S47M03",  # head 2's
    "N014G01X-001F0100",  # OP/1, head 1 alone: 1 in at 10 IPM, FRN 100
    "N015G01Z-001",
    "G01U-001E0080",  # OP/2, head 2 alone: FRN 10 x 8 / 1 = 80
    "N021G01X-0005F0200W-002E0040",  # OP/3: both first moves in one block (CODE +17)
    "N022G01Z-0015F0067",  # head 1: 0.05 min < head 2's 0.25
    "N024G18",  # PREPHD: circular interpolation on head 1 (TABLEG(16))
    "N024G31X+0005Z-0005I0005F0020",  # the quarter circle, R 0.5
    "G01U-001W-001E0057",  # head 2: 0.2785 > 0.25
    "N025G11X+0005",
    "G01U+002E0040",  # head 1 has finished OP/3: head 2's rest alone
    "N033G01X+0005Z+003F0033W+003E0027",  # OP/4: both again
]


def test_the_two_head_example_posts_block_by_block(tmp_path: Path) -> None:
    tape, listing = tmp_path / "p.tape", tmp_path / "p.lis"
    result = CliRunner().invoke(
        main, ["post", str(EXAMPLE), "-o", str(tape), "--listing", str(listing)]
    )
    assert result.exit_code == 0, result.output
    assert tape.read_text().splitlines() == TAPE
    text = listing.read_text()
    for kind in ("INCREMENTAL", "ABSOLUTE", "OPERATOR"):  # option 17 = 111
        assert f"*** {kind} ***" in text
    incremental = text.split("*** ABSOLUTE ***")[0].splitlines()
    assert incremental[3] == "TWO-HEAD LATHE EXAMPLE"  # the PARTNO heads every page
    # a title line per head, in each head's letters, head 2's registers under head 1's
    # (W17, 001 L9751-9757): head 2 has no N, its U under X, W under Z, E under F
    first, second = incremental[4], incremental[5]
    assert first.split() == ["N", "G", "X", "Z", "I", "K", "F", "S", "T", "M"]
    assert second.split() == ["G", "U", "W", "H", "J", "E", "S", "T", "M"]
    for one, two in (("G", "G"), ("X", "U"), ("Z", "W"), ("I", "H"), ("F", "E")):
        assert first.index(f" {one}") == second.index(f" {two}")
    combined = [line.split() for line in incremental if line.startswith("HEAD")][7:9]
    # N021's two halves: one tape block, two lines
    assert combined == [["HEAD1", "021", "01", "-000.5", "0200"], ["HEAD2", "-002.", "0040"]]
    absolute = text.split("*** ABSOLUTE ***")[1].split("*** OPERATOR ***")[0]
    last = [line.split() for line in absolute.splitlines() if line.startswith("HEAD2")][-1]
    assert last == ["HEAD2", "+0007.000", "+0005.000", "8."]  # head 2's last point, 8 IPM
    # 0.2 (OP/1) + 0.125 (OP/2) + max(0.3285, 0.6768) (OP/3) + max(0.3041, 0.375) (OP/4)
    assert "CUT TIME 1.38 MIN; DWELL TIME 0.00 MIN;" in text


def test_four_printouts_are_listed() -> None:
    result = CliRunner().invoke(main, ["--list-plugins", "--json"])
    assert result.exit_code == 0
    plugins = json.loads(result.output)["plugins"]
    names = sorted(p["name"] for p in plugins if p["family"] == "printouts")
    assert names == ["GEOUT1", "GEOUT2", "GEOUT3", "GEOUT4"]


def test_mach40_posts_with_its_geout2(tmp_path: Path) -> None:
    program = tmp_path / "t40.apt"
    program.write_text(
        "PARTNO T\nMACHIN/GECENT,40\nFROM/0,0,5\nFEDRAT/10\nSPINDL/500\n"
        "GOTO/1,1,0\nGOTO/2,1,0\nFINI\n"
    )
    listing = tmp_path / "t40.lis"
    result = CliRunner().invoke(
        main, ["post", str(program), "-o", str(tmp_path / "t.tape"), "--listing", str(listing)]
    )
    assert result.exit_code == 0, result.output
    lines = listing.read_text().splitlines()
    assert any(line.startswith("INC") for line in lines)
    assert any(line.startswith("ABS") for line in lines)
    assert any(line.startswith("OPR") for line in lines)


def test_each_head_has_its_own_origin(tmp_path: Path) -> None:
    """The Operator printout is each head's summed values less its own ORIGIN (OPRVAL
    and OPRVL2, 001 L9812-9882): head 1's ORIGIN/1,1,0 moves head 1's lines only."""
    program = tmp_path / "p.apt"
    program.write_text(
        EXAMPLE.read_text().replace(
            "SELECT/HEAD,1\nFROM/6,4,0", "SELECT/HEAD,1\nORIGIN/1,1,0\nFROM/6,4,0"
        )
    )
    listing = tmp_path / "p.lis"
    result = CliRunner().invoke(
        main, ["post", str(program), "-o", str(tmp_path / "p.tape"), "--listing", str(listing)]
    )
    assert result.exit_code == 0, result.output
    operator = listing.read_text().split("*** OPERATOR ***")[1]
    froms = [line.split() for line in operator.splitlines() if "FROM" in line]
    assert froms == [
        ["HEAD1", "FROM", "+0005.000", "+0003.000"],  # (6, 4) less (1, 1)
        ["HEAD2", "FROM", "+0007.000", "+0005.000"],  # no ORIGIN of its own
    ]


def test_the_first_machin_chooses_the_printout(tmp_path: Path) -> None:
    """MACHIN/GECENT,23,OPTAB,164,4 in the CL file, as the manual's GEOUT4 sample chooses
    its printout (001 L10011): the listing is GEOUT4's."""
    program = tmp_path / "p.apt"
    program.write_text(
        "PARTNO P\nMACHIN/GECENT,23,OPTAB,164,4\nFROM/0,0,1\nFEDRAT/20\nGOTO/1,1,0\nFINI\n"
    )
    listing = tmp_path / "p.lis"
    result = CliRunner().invoke(
        main, ["post", str(program), "-o", str(tmp_path / "p.tape"), "--listing", str(listing)]
    )
    assert result.exit_code == 0, result.output
    assert "*** INCREMENTAL ***" in listing.read_text()
