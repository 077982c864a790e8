"""`gecent verify` of canned cycles on the five-axis packs (issue 22; docs/five-axis.md):
the holes are followed as the post drills them, along the tool axis
(core/motion/multiaxis_cycles.py's tool_axis_legs), each leg a CL point with the tool axis
in force; a vertical DRILL and a DEEP along a tool axis tilted 45 degrees (RETURN,0), on
both packs in both modes, verified at a micrometre and a thousandth of a degree, and a tape
with one hole's depth changed fails."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.plugins import PluginSet
from gecent.core.verify.check import verify

from .test_cycles_wave3 import FIVE_AXIS_HOLES

needs_rs274 = pytest.mark.skipif(shutil.which("rs274") is None, reason="rs274 is not installed")

HOLES = FIVE_AXIS_HOLES  # the program tests/test_cycles_wave3.py posts and checks by hand

MODES = [
    ("linuxcnc-5axis-ac", 0),
    ("linuxcnc-5axis-ac", 1),
    ("fanuc-5axis-bc", 0),
    ("fanuc-5axis-bc", 1),
]


def post_holes(tmp_path: Path, machine: str, tcp: int) -> tuple[Path, Path]:
    number = 86 if machine == "linuxcnc-5axis-ac" else 87
    job = tmp_path / "holes.apt"
    job.write_text(f"MACHIN/GECENT,{number},OPTAB,265,{tcp}\n" + HOLES)
    tape = tmp_path / "holes.ngc"
    result = CliRunner().invoke(main, ["post", str(job), "-o", str(tape)])
    assert result.exit_code == 0, result.output
    return job, tape


@needs_rs274
@pytest.mark.parametrize(("machine", "tcp"), MODES)
def test_vertical_and_tilted_holes_pass_verify_at_a_micrometre_and_a_thousandth_of_a_degree(
    plugins: PluginSet, tmp_path: Path, machine: str, tcp: int
) -> None:
    job, tape = post_holes(tmp_path, machine, tcp)
    result = verify(str(tape), str(job), plugins, None, 0.001)
    report = "\n".join(result.report())
    assert result.passed, report
    assert "tolerance 0.001 mm, 0.001 degrees" in report
    # the rapid over the first hole; its R plane, bottom and R again; the second hole
    # across at R (its R plane the same point), bottom, R; the rapid onto the tilted axis;
    # each DEEP hole across at the start level, R, two pecks each back to R, the bottom
    # and RETURN,0: 1 + 3 + 3 + 1 + 8 + 8
    assert "24 CL points with their tool axes" in report
    assert "8 feeds checked" in report  # 2 vertical bottoms, 2 x 3 pecks and bottoms


def shifted(line: str, word: str, by: float) -> str:
    """The line with the word's value moved by ``by``."""
    match = re.search(rf"{word}(-?[\d.]+)", line)
    assert match is not None, line
    value = float(match.group(1)) + by
    return line[: match.start()] + f"{word}{value:.3f}" + line[match.end() :]


def feed_lines(tape: Path) -> list[str]:
    return [line for line in tape.read_text().splitlines() if " G01 " in f" {line} "]


@needs_rs274
@pytest.mark.parametrize(("machine", "tcp"), MODES)
@pytest.mark.parametrize(
    ("which", "deeper", "reason"),
    [
        (0, 0.5, "off the CL line"),  # the first vertical hole 0.5 deeper
        (1, -0.5, "a rapid move where the CL cuts"),  # the second 0.5 shallower
        (4, 0.5, "off the CL line"),  # the first tilted hole's bottom 0.5 deeper
        (7, -0.5, "a rapid move where the CL cuts"),  # the second's 0.5 shallower
    ],
)
def test_a_hole_drilled_to_another_depth_fails(
    plugins: PluginSet,
    tmp_path: Path,
    machine: str,
    tcp: int,
    which: int,
    deeper: float,
    reason: str,
) -> None:
    """The feed moves are the two vertical bottoms, then each tilted hole's pecks at 2 and 4
    and its bottom at 6 (indices 4 and 7 the bottoms). A tilted hole deepens along
    (.7071, 0, .7071): in X and Z, except where the trunnion has turned it onto the
    machine's Z (slides computed on the A/C table)."""
    job, tape = post_holes(tmp_path, machine, tcp)
    line = feed_lines(tape)[which]
    if " X" in line:
        edited = shifted(shifted(line, "X", -deeper * 0.70711), "Z", -deeper * 0.70711)
    else:
        edited = shifted(line, "Z", -deeper)
    text = tape.read_text()
    assert text.count(line + "\n") == 1
    tampered = tmp_path / "tampered.ngc"
    tampered.write_text(text.replace(line + "\n", edited + "\n"))
    result = verify(str(tampered), str(job), plugins, None, 0.001)
    report = "\n".join(result.report())
    assert not result.passed, report
    assert reason in report, report
