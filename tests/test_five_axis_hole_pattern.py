"""A five-axis hole pattern (core/motion/multiaxis_cycles.py): CYCLE/DRILL then one GOTO per
hole, each with its own tool axis, as NX's 5-axis drilling writes it. After a hole the tool
is at R along the old axis; it goes at rapid to the next hole's R point along the new axis
(the chain turning the rotary axes on the way), then drills along the new axis. Three holes
on three tool axes, on both five-axis packs in both modes, verified at a micrometre and a
thousandth of a degree; the second hole's bottom checked by hand on the B head."""

from __future__ import annotations

import itertools
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.dispatch.post import post
from gecent.core.errors import InputError
from gecent.core.plugins import PluginSet
from gecent.core.verify.check import verify

needs_rs274 = pytest.mark.skipif(shutil.which("rs274") is None, reason="rs274 is not installed")

PATTERN = """PARTNO PATTERN
UNITS/MM
MULTAX
LOADTL/1,LENGTH,100
SPINDL/1000,CLW
FROM/0,0,100,0,0,1
RAPID
GOTO/0,0,50,0,0,1
CYCLE/DRILL,DEPTH,5,CLEAR,2,MMPM,100
GOTO/0,0,0,0,0,1
GOTO/20,0,0,0.6,0,0.8
GOTO/0,20,0,0,-0.6,0.8
CYCLE/OFF
FINI
"""

MODES = [
    ("linuxcnc-5axis-ac", 0),
    ("linuxcnc-5axis-ac", 1),
    ("fanuc-5axis-bc", 0),
    ("fanuc-5axis-bc", 1),
]


def post_pattern(tmp_path: Path, machine: str, tcp: int, body: str = PATTERN) -> tuple[Path, Path]:
    number = 86 if machine == "linuxcnc-5axis-ac" else 87
    job = tmp_path / "pattern.apt"
    job.write_text(f"MACHIN/GECENT,{number},OPTAB,265,{tcp}\n" + body)
    tape = tmp_path / "pattern.ngc"
    result = CliRunner().invoke(main, ["post", str(job), "-o", str(tape)])
    assert result.exit_code == 0, result.output
    return job, tape


def blocks(tape: Path) -> list[str]:
    return [line for line in tape.read_text().splitlines() if line.startswith("N")]


@needs_rs274
@pytest.mark.parametrize(("machine", "tcp"), MODES)
def test_three_holes_on_three_tool_axes_pass_verify(
    plugins: PluginSet, tmp_path: Path, machine: str, tcp: int
) -> None:
    job, tape = post_pattern(tmp_path, machine, tcp)
    result = verify(str(tape), str(job), plugins, None, 0.001)
    report = "\n".join(result.report())
    assert result.passed, report
    assert "tolerance 0.001 mm, 0.001 degrees" in report
    # the rapid over the first hole; each hole its R point, bottom and R again (the second
    # and third R points reached by the turning rapid): 1 + 3 x 3
    assert "10 CL points with their tool axes" in report
    assert "3 feeds checked" in report


@pytest.mark.parametrize(("machine", "tcp"), MODES)
def test_the_tool_turns_at_rapid_between_the_holes(tmp_path: Path, machine: str, tcp: int) -> None:
    """Each of the two new tool axes is reached by G00 blocks (a rotary word on them) and
    nothing is cut (G01) between one hole's way out and the next hole's plunge."""
    _, tape = post_pattern(tmp_path, machine, tcp)
    feeds = [index for index, line in enumerate(blocks(tape)) if " G01 " in f" {line} "]
    assert len(feeds) == 3
    rotary = "B" if machine == "fanuc-5axis-bc" else "A"
    for before, plunge in itertools.pairwise(feeds):
        between = blocks(tape)[before + 1 : plunge]
        assert all(" G01" not in line for line in between)
        assert any(f" {rotary}" in line or " C" in line for line in between)


def test_the_second_hole_bottom_by_hand_with_tool_centre_point(tmp_path: Path) -> None:
    """fanuc-5axis-bc, option 265 = 1 (G43.4): X, Y, Z are the tip in the part. The hole's
    top (20, 0, 0), axis (.6, 0, .8), DEPTH 5: bottom (20 - 3, 0, 0 - 4) = (17, 0, -4); its
    R point, CLEAR 2 above the top along the axis: (21.2, 0, 1.6); B = atan2(.6, .8) =
    36.8699 degrees, C = 0 (the axis in the XZ plane, B tilted positive)."""
    _, tape = post_pattern(tmp_path, "fanuc-5axis-bc", 1)
    lines = blocks(tape)
    turn = next(line for line in lines if " B36.87" in line)
    assert turn.split()[1:] == ["X21.2", "Z1.6", "B36.87"]  # G00 modal from the way out
    bottom = lines[lines.index(turn) + 1]
    assert bottom.split()[1:] == ["G01", "X17.", "Z-4."]


def test_the_second_hole_bottom_by_hand_on_the_slides(tmp_path: Path) -> None:
    """fanuc-5axis-bc, option 265 = 0: the slides are the gauge point at B = 0, the pivot
    150 above it (the pack's kinematics) and the tool 100 long, so the pivot is 250 from the
    tip along the axis. Bottom tip (17, 0, -4), axis (.6, 0, .8): pivot (17 + 150, 0, -4 +
    200) = (167, 0, 196), slides (167, 0, 196 - 150) = (167, 0, 46). Its R point (21.2, 0,
    1.6): pivot (171.2, 0, 201.6), slides (171.2, 0, 51.6)."""
    _, tape = post_pattern(tmp_path, "fanuc-5axis-bc", 0)
    lines = blocks(tape)
    turn = next(line for line in lines if " B36.87" in line)
    assert turn.split()[1:] == ["X171.2", "Z51.6", "B36.87"]
    bottom = lines[lines.index(turn) + 1]
    assert bottom.split()[1:] == ["G01", "X167.", "Z46."]


def test_out_on_a_new_tool_axis_from_inside_a_hole_is_bad_input(
    plugins: PluginSet, tmp_path: Path
) -> None:
    """OUT stays at the bottom: the tool would turn inside the hole (bad input since wave 7,
    which built OUT and IN on a new axis: tests/test_last_forms_wave7.py)."""
    job = tmp_path / "out.apt"
    job.write_text(
        "MACHIN/GECENT,87,OPTAB,265,1\n"
        + PATTERN.replace("CYCLE/DRILL,DEPTH,5,CLEAR,2,MMPM,100", "CYCLE/OUT,DEPTH,5,CLEAR,2")
    )
    with pytest.raises(InputError, match="left the tool at the bottom of the hole before"):
        post(str(job), plugins)
