"""The bundled drilling program on the sample positioning machine MACH24
(examples/drill_mach24.apt), posted block by block against blocks derived by hand.

MACH24 (001 L27600-27680): absolute X, Y, Z in format -24 with option 59 = 132415 (+X -Y
+Z: Y is punched negated); Z is not output with positions (option 130 = 0); TABLEG(1) =
G80, cycles G81 (DRILL, TABLEG 82), G84 (TAP, 85), G85 (BORE, 86); R register 16 (format
-22); spindle type 8 (S = the row of the speed in its range, option 47 = 0) over three
ranges of eight speeds; feed type 0 with K = 2 (option 78 unset): F = 2 x IPM to the
nearest whole number; rapid: option 45's command, F99; T format 20; TABLEM(4) (spindle
CLW) and TABLEM(3) (end of tape) are absent in the machine as printed.

Hand derivation, the tool at Z 6 throughout (the control's cycle returns it there):

* tool 1 (1060 RPM, range 1 row 7: S07): hole tops 0, DEPTH .15, CLEAR .1: the cycle block
  G81, Z = 6 - (0 - .15) = 6.15, R = 6 - (0 + .1) = 5.9, F = 2 x 4.5 = 9;
* tool 2 (710 RPM, range 1 row 6: S06): Z 6.65, R 5.9, F11; the last hole's top is -.25:
  a new cycle block Z 6.9, R 6.15;
* tool 3 (200 RPM, range 1 row 3: S03), a 1/4-20 tap: 200 / 20 = 10 IPM, F20; Z 6.6, R 5.8;
* tool 4 (530 RPM with RANGE,2: row 4 of range 2, S04; without it range 1 row 5, S05):
  2.25 IPM is F4.5, F5 to the nearest whole command: 2.5 IPM, which the listing prints
  (001 L1160-1168: the printed feedrate is the true value used); Z 6.55, R 5.9.

Each T goes out at once with G80 (TOOLGP) and the running spindle command rides with it
(001 L1165-1166); the new speed follows in its own block.
"""

from __future__ import annotations

from pathlib import Path

from gecent.core.dispatch.post import post
from gecent.core.output.block import Code
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins
from gecent.core.state import RunResult

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "drill_mach24.apt"

EXPECTED = [
    "PLATE2410FOURHOLES",
    "N009G80T01",
    "N010S07",
    "N013G80X+010000Y-010000F99M08",
    "N015G81Z+061500F09R+059",
    "N015X+010000Y-010000",
    "N016X+040000",
    "N017Y-030000",
    "N018X+010000",
    "N021G80S07T02",
    "N022S06",
    "N024G81Z+066500F11R+059",
    "N024X+010000Y-030000",
    "N025Y-010000",
    "N026X+040000",
    "N027Z+069000R+0615",
    "N027Y-030000",
    "N030G80S06T03",
    "N031S03",
    "N033G84Z+066000F20R+058",
    "N033Y-010000",
    "N034X+010000",
    "N037G80S03T04",
    "N038S04",
    "N040G85Z+065500F05R+059",
    "N040Y-030000",
    "N044G80X+000000Y+000000F99M09",
    "(" * 72,  # END's leader (option 168), as the tape image shows a blank-tape run
]


def posted() -> RunResult:
    return post(str(EXAMPLE), get_plugins())


def test_every_block_of_the_drilling_program() -> None:
    assert tape_lines(posted().blocks) == EXPECTED


def test_block_codes_and_printed_feeds() -> None:
    """CODE -16 for the cycle blocks, +16 for positions, -1 for the tool changes; the F-IPM
    column prints the feed each block really makes."""
    result = posted()
    numeric = [b for b in result.blocks if b.punch and b.code is not Code.PARTNO]
    cycle_blocks = [b for b in numeric if b.code is Code.POSITION_Z]
    assert [b.record for b in cycle_blocks] == [15, 24, 27, 33, 40]
    assert [float(b.cells[19]) for b in cycle_blocks] == [4.5, 5.5, 5.5, 10.0, 2.5]  # type: ignore[arg-type]
    tool_changes = [b for b in numeric if b.cells[13] is not None and b.code is Code.AUX_ONLY]
    assert [b.record for b in tool_changes if b.punch and "T" in b.punch] == [9, 21, 30, 37]
    rapid = [b for b in numeric if b.rapid]
    assert [b.record for b in rapid] == [13, 44]


def test_the_machine_s_missing_codes_are_reported() -> None:
    """MACH24 has no spindle-CLW code (TABLEM(4)) and no end-of-tape code (TABLEM(3)):
    comment 22 at the first SPINDL and at END, and the run goes on."""
    result = posted()
    notes = [(d.where.record if d.where else None, d.text) for d in result.diagnostics]
    missing = "REQUESTED MISCELLANEOUS FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE"
    assert notes == [(10, missing), (45, missing)]


def test_the_listing_prints_positions_feeds_and_speeds() -> None:
    """GEOUT1: the absolute columns, F-IPM as made (the bore's 2.5) and S-RPM with each S."""
    result = posted()
    machine = result.machine
    listing = get_plugins().get("printouts", 1).render(machine, result.blocks, result.partno)
    lines = listing.splitlines()
    speeds = [line.split()[-1] for line in lines if line.strip().startswith(("010", "022"))]
    assert speeds == ["1060.", "710."]
    bore = next(line for line in lines if line.strip().startswith("040  85"))
    assert bore.split()[-1] == "2.5" and "+0001.0000" in bore and "+0006.0000" in bore
    origin = next(line for line in lines if line.startswith("FROM"))
    assert origin.split()[1:] == ["+0000.0000", "+0000.0000", "+0006.0000"]  # W9
