"""A turret corrective move on the printouts (CODE -3, manual §3.5.3.2, 001 L9225-9233):
"the corrective incremental moves are not summed nor printed on the Absolute Printout,
though they are for the Operator Printout". The Incremental and Operator printouts list
it; the Absolute printout does not (GEOUT2's ABS line, GEOUT3's and GEOUT4's Absolute
printout), and the moves after it are summed without it."""

from __future__ import annotations

from pathlib import Path

from click.testing import CliRunner
from gecent.core.cli import main

from .test_multihead_turret import HEADER

SINGLE_HEAD = """PARTNO TURRET
MACHIN/GECENT,4,OPTAB,106,8,OPTAB,164,2
FROM/6,0,4
FEDRAT/10
TURRET/1,1,2,3
GOTO/5,0,4
TURRET/2,2,2.5,1,NOW
GOTO/4,0,4
FINI
"""

# head 1's correction beside head 2's moves (the heads as tests/test_multihead_turret.py
# sets them up)
TWO_HEADS = (
    HEADER.format(options="")
    + "SELECT/HEAD,1\nOP/3\nTURRET/2,2,2.5,1,NOW\nGOTO/4.5,1.5,0\n"
    + "SELECT/HEAD,2\nOP/3\nGOTO/6,3,0\nGOTO/5,2,0\nFINI\n"
)


def _listing(tmp_path: Path, program: str) -> str:
    source, tape, listing = tmp_path / "p.apt", tmp_path / "p.tape", tmp_path / "p.lis"
    source.write_text(program)
    result = CliRunner().invoke(
        main, ["post", str(source), "-o", str(tape), "--listing", str(listing)]
    )
    assert result.exit_code == 0, result.output
    return listing.read_text()


def test_geout2_a_correction_has_inc_and_opr_lines_only(tmp_path: Path) -> None:
    """MACH04 with GEOUT2: the correction (tool 1 at A = 2, B = 3 to tool 2 at 2.5, 1:
    X +2, Z -0.5) is block 004; it has no ABS line, and the next move's ABS line is the
    programmed point (4, 0, 4), the correction not summed."""
    text = _listing(tmp_path, SINGLE_HEAD)
    lines = [line for line in text.splitlines() if " 004 " in line]
    assert [line[:3] for line in lines] == ["INC", "OPR"]
    assert "+2." in lines[0] and "-0.5" in lines[0]
    abs_lines = [line for line in text.splitlines() if line.startswith("ABS")]
    assert abs_lines[-1].split()[1:4] == ["8", "+0000.0000", "+0004.0000"]


def test_geout3_the_corrective_half_is_not_on_the_absolute_printout(tmp_path: Path) -> None:
    """MACH51 (GEOUT3, option 17 = 111): the +14 block N014 (head 1 corrects beside head
    2's move) prints head 1's half on the Incremental and Operator printouts; on the
    Absolute printout only head 2's half, at its summed point (6, 3)."""
    text = _listing(tmp_path, TWO_HEADS)
    incremental, rest = text.split("*** ABSOLUTE ***")
    absolute, operator = rest.split("*** OPERATOR ***")

    def head_1_014(printout: str) -> list[str]:
        return [line for line in printout.splitlines() if line.startswith("HEAD1  014      01")]

    assert len(head_1_014(incremental)) == 1 and "+002." in head_1_014(incremental)[0]
    assert len(head_1_014(operator)) == 1
    absolute_lines = absolute.splitlines()
    at = next(i for i, line in enumerate(absolute_lines) if line.startswith("HEAD1  014"))
    assert absolute_lines[at].strip() == "HEAD1  014"  # the T word block, no point
    assert absolute_lines[at + 1].split() == ["HEAD2", "+0006.000", "+0003.000", "8."]
    assert absolute_lines[at + 2].split()[:4] == ["HEAD1", "015", "+0004.500", "+0001.500"]
