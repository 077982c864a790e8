"""The real CL files posted on the manual's sample mill MACH23, checked from the outputs:
the punched tapes read back to the tape image, the tape's departures add up to the CL
points (to within one step, with no pulse lost), and the listing has a line per block.

Creo's roughing file is metric (UNITS/MM) and names another postprocessor (MACHIN/UNCX01),
so MACH23 is chosen with --machine and every length is converted to inches."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cl.records import Motion, MotionSubtype, Statement
from gecent.core.cl.stream import read_cl
from gecent.core.cli import main
from gecent.core.dispatch.post import post
from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.rounding import to_steps
from gecent.core.output.block import Code
from gecent.core.output.punch import unpunch
from gecent.core.plugins import get_plugins

from .conftest import SHARED
from .test_post_linear import decode

CORPUS = SHARED / "corpus"
FILES = ["creo/schruppen_1.ncl.1", "apt4/test2_contour_tlrgt.cl3", "apt4/test2d_finetol.cl3"]

pytestmark = pytest.mark.skipif(not CORPUS.is_dir(), reason="shared corpus not present")


def cl_end_points(path: Path) -> dict[int, tuple[float, float, float]]:
    """Each motion record's last point, in inches, by CL record number; a continuation
    record's points belong to the record it continues."""
    scale = 1.0
    points: dict[int, tuple[float, float, float]] = {}
    head = 0
    for record in read_cl(str(path), get_plugins()):
        if isinstance(record, Statement) and record.major == "UNITS":
            scale = 1 / 25.4 if record.words() == ("MM",) else 1.0
        elif isinstance(record, Motion):
            if record.subtype is MotionSubtype.GODLTA:
                raise AssertionError("no GODLTA in these files")
            if record.subtype is not MotionSubtype.CONTINUATION:
                head = record.number
            x, y, z = record.points[-1][:3]
            points[head] = (x * scale, y * scale, z * scale)
    return points


@pytest.mark.parametrize("name", FILES)
def test_mach23_posts_the_corpus_file(name: str, tmp_path: Path) -> None:
    source = CORPUS / name
    tape, listing = tmp_path / "p.tape", tmp_path / "p.lis"
    eia, ascii_ = tmp_path / "p.eia", tmp_path / "p.ascii"
    arguments = ["post", str(source), "--machine", "23", "-o", str(tape), "--listing"]
    runner = CliRunner()
    result = runner.invoke(main, [*arguments, str(listing), "--punch", "eia", str(eia)])
    assert result.exit_code == 0, result.stderr
    result = runner.invoke(main, [*arguments, str(listing), "--punch", "ascii", str(ascii_)])
    assert result.exit_code == 0, result.stderr
    image = tape.read_text().splitlines()
    # (MACH23 punches the readable PARTNO at the head of each reel: readable=True skips it)
    assert unpunch(eia.read_bytes(), "eia", readable=True) == image
    # a tape break's end-of-record mark (=) is ASCII's rewind stop, which reads back as "%"
    ascii_image = ["%" + line[1:] if line.startswith("=") else line for line in image]
    assert unpunch(ascii_.read_bytes(), "ascii", readable=True) == ascii_image
    text = listing.read_text()
    assert text.startswith("***GENERAL ELECTRIC GECENT III POSTPROCESSOR***\nSAMPLE MILL")
    motion_lines = [line for line in image if line.startswith("N") and "X" in line]
    assert len(motion_lines) > 5


@pytest.mark.parametrize("name", FILES)
def test_tape_departures_add_up_to_the_cl_points(name: str) -> None:
    """Appendix 7.2 on real input: the punched departures, read back from each tape line,
    add up to every CL end point within one step per axis, and to the rounded point
    exactly (no pulse lost), record by record."""
    plugins = get_plugins()
    machine: MachineDefinition = plugins.machine("mach23").load()
    result = post(str(CORPUS / name), plugins, machine)
    step = machine.number_option(14)
    ends = cl_end_points(CORPUS / name)
    total = [0, 0, 0]
    reached: dict[int, tuple[int, ...]] = {}
    checked = 0
    for block in result.blocks:
        if block.code is Code.FROM:
            assert block.position is not None and block.record is not None
            total = list(block.position[:3])
            reached[block.record] = tuple(total)
        if block.punch is None or block.steps is None:
            continue
        words = decode(block.punch, machine)
        for axis, letter in enumerate("XYZ"):
            total[axis] += round(words.get(letter, 0.0) / step)
        assert tuple(total) == block.position[:3]  # type: ignore[index]
        assert block.record is not None
        reached[block.record] = tuple(total)
    for record, point in ends.items():
        if record not in reached:
            continue  # a move of no whole step outputs nothing
        rounded = tuple(to_steps(v, step) for v in point)
        assert reached[record] == rounded
        assert all(abs(r * step - v) <= step for r, v in zip(reached[record], point, strict=True))
        checked += 1
    assert checked > 0.9 * len(ends)


def test_creo_drilling_file_on_the_positioning_machine_mach24() -> None:
    """Creo's metric peck-drilling file (UNITS/MM, CYCLE/DEEP with STEP) on the sample drill:
    9000 RPM is above the table, so the top speed 2400 RPM (range 3, row 7: S07) with the
    manual's comment; the holes are absolute positions in inches (Y negated by option 59 =
    132415); the cycle block is G83 (TABLEG(84)) with Z = the plunge from the 2 mm height
    to 0.5 - 3.5 mm, 5 mm = .1969 in, R = 2 - (0.5 + 1) = .5 mm = .02 in, and F = 2 x 50
    MMPM in IPM (1.9685 x 2 = 3.94: F4, 2 IPM made); STEP is left to the control."""
    result = post(str(CORPUS / "creo/bohren_1.ncl.8"), get_plugins(), "24")
    punched = [b.punch for b in result.blocks if b.punch and b.code is not Code.PARTNO]
    assert punched == [
        "N008G80T01",
        "N011S07",
        "N013G80X-002846Y+009055F99",
        "N015G83Z+001969F04R+0002",
        "N015X-002846Y+009055",
        "N016X-006606",
    ]
    notes = [d.text for d in result.diagnostics]
    assert "SPINDLE SPEED COULD NOT BE FOUND." in notes
    assert "CYCLE STEP NOT OUTPUT: THE CONTROL'S OWN CYCLE DOES IT" in notes
