"""Arcs on the modern packs (issue 16; options 252, 253, 261, 262, docs/modern-controls.md):
any radius, helices, R words and arcs as chords, each posted and, where rs274 is here,
read back by LinuxCNC's interpreter and compared with the CL file."""

from __future__ import annotations

import re
import shutil
from math import atan2, cos, hypot, pi, sin
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.motion.gcode import CircularCodes
from gecent.core.plugins import PluginSet
from gecent.core.verify.check import verify

needs_rs274 = pytest.mark.skipif(
    shutil.which("rs274") is None,
    reason="rs274 (LinuxCNC's interpreter, Debian package linuxcnc-uspace) is not installed",
)
MILLS = ["linuxcnc-mill", "fanuc-mill"]


def program(*body: str, machin: str = "") -> str:
    head = ["PARTNO ARCS", *([machin] if machin else []), "UNITS/MM", "LOADTL/1"]
    head += ["SPINDL/RPM,1000,CLW", "FROM/0,0,50"]
    return "\n".join([*head, *body, "FINI", ""])


def post(tmp_path: Path, text: str, machine: str | None) -> tuple[Path, Path, str]:
    source = tmp_path / "part.apt"
    source.write_text(text)
    tape = tmp_path / "part.ngc"
    command = ["post", str(source), "-o", str(tape)]
    if machine is not None:
        command += ["--machine", machine]
    result = CliRunner().invoke(main, command)
    assert result.exit_code == 0, result.output
    return source, tape, tape.read_text()


def arc(radius: float, z: float = -1.0, end_z: float | None = None) -> tuple[str, ...]:
    """A quarter circle of ``radius`` about the origin, counterclockwise from (r, 0)."""
    end_z = z if end_z is None else end_z
    return (
        "RAPID",
        f"GOTO/{radius},0,{z}",
        "FEDRAT/300,MMPM",
        f"CIRCLE/0,0,{z},0,0,1,{radius}",
        f"GOTO/0,{radius},{end_z}",
    )


def verified(plugins: PluginSet, tape: Path, source: Path, machine: str | None) -> int:
    result = verify(str(tape), str(source), plugins, machine, 0.001)
    assert result.passed, "\n".join(result.report())
    assert result.comparison is not None
    return result.comparison.arcs


@pytest.mark.parametrize("machine", MILLS)
@pytest.mark.parametrize("radius", [99.9, 100.0, 500.0, 4000.0])
def test_an_arc_of_any_radius(tmp_path: Path, machine: str, radius: float) -> None:
    """The manual's radius bands are its controls' hardware; G02/G03 cover every radius."""
    _, _, tape = post(tmp_path, program(*arc(radius)), machine)
    assert re.search(rf"G0?3 X0\. Y{radius:g}\.? I-{radius:g}\.?(?: F300\.)?\n", tape), tape


@needs_rs274
@pytest.mark.parametrize("machine", MILLS)
@pytest.mark.parametrize("radius", [100.0, 500.0])
def test_large_arcs_verify(plugins: PluginSet, tmp_path: Path, machine: str, radius: float) -> None:
    source, tape, _ = post(tmp_path, program(*arc(radius)), machine)
    assert verified(plugins, tape, source, machine) == 1


@pytest.mark.parametrize("machine", [*MILLS, "linuxcnc-mill-inch"])
def test_a_helix_is_one_block_with_the_third_axis(tmp_path: Path, machine: str) -> None:
    """CIRCLE, then a GOTO at another Z: G03 with Z (it was a straight chord)."""
    _, _, tape = post(tmp_path, program(*arc(20.0, z=0.0, end_z=-5.0)), machine)
    if machine.endswith("inch"):  # (the CL is in mm: the inch pack shows inches)
        assert re.search(r"G0?3 X0\. Y0?\.7874 Z-0?\.1969 I-0?\.7874(?: F11\.811)?\n", tape), tape
    else:
        assert re.search(r"G0?3 X0\. Y20\. Z-5\. I-20\.(?: F300\.)?\n", tape), tape


@needs_rs274
@pytest.mark.parametrize("machine", MILLS)
def test_a_helix_verifies(plugins: PluginSet, tmp_path: Path, machine: str) -> None:
    """Three quarters of a turn down 5 mm, then a full turn down 2 mm more."""
    body = (
        *arc(20.0, z=0.0, end_z=-5.0)[:4],
        "GOTO/0,-20,-5",
        "CIRCLE/0,0,-7,0,0,1,20",
        "GOTO/0,-20,-7",
    )
    source, tape, text = post(tmp_path, program(*body), machine)
    assert re.search(r"\d X0\. Y-20\. Z-7\. J20\.\n", text), text  # the full turn (G03 modal)
    assert verified(plugins, tape, source, machine) == 2


def chord_points(tape: str) -> list[tuple[float, float, float]]:
    """The X, Y, Z reached by each block of a tape in G90 (missing words: unchanged)."""
    at = [0.0, 0.0, 50.0]
    points = []
    for line in tape.splitlines():
        words = dict(re.findall(r"([XYZ])(-?[\d.]+)", line))
        if not words:
            continue
        for axis, name in enumerate("XYZ"):
            if name in words:
                at[axis] = float(words[name])
        points.append((at[0], at[1], at[2]))
    return points


def test_a_helix_is_chords_where_the_control_has_no_helix(tmp_path: Path) -> None:
    """Option 261 = 0: straight moves along the helix, each chord within one step of it
    (option 262 = 0), the depth in proportion to the angle, the last point the CL's."""
    machin = "MACHIN/GECENT,80,OPTAB,261,0"
    _, _, tape = post(tmp_path, program(*arc(20.0, z=0.0, end_z=-5.0), machin=machin), None)
    assert "G02" not in tape and "G03" not in tape and " G2 " not in tape
    moves = chord_points(tape)
    start = moves.index((20.0, 0.0, 0.0))
    along = moves[start + 1 :]
    assert along[-1] == (0.0, 20.0, -5.0)
    step = 0.001
    for (x0, y0, _), (x1, y1, _) in zip([moves[start], *along[:-1]], along, strict=True):
        assert abs(hypot(x1, y1) - 20.0) <= step  # ends on the arc
        middle = hypot((x0 + x1) / 2, (y0 + y1) / 2)
        assert 20.0 - middle <= step + step  # the chord's sag: the tolerance, plus rounding
    for x, y, z in along:
        angle = atan2(y, x)
        assert abs(z - (-5.0 * angle / (pi / 2))) <= 0.0011
    # a chord of sag s on radius r spans 2 acos(1 - s/r) = 0.0200 rad: 79 a quarter turn
    assert len(along) == 79


@needs_rs274
def test_arcs_as_chords_verify(plugins: PluginSet, tmp_path: Path) -> None:
    """Option 262 = 0.01: every arc straight moves within 0.01 mm; verify follows them."""
    machin = "MACHIN/GECENT,80,OPTAB,262,0.01"
    body = (*arc(100.0), "CIRCLE/0,0,-1,0,0,1,100", "GOTO/-100,0,-1")
    source, tape, text = post(tmp_path, program(*body, machin=machin), None)
    assert not re.search(r"\bG0?[23]\b", text)
    assert verified(plugins, tape, source, None) == 2
    # 2 acos(1 - 0.01/100) = 0.02828 rad: 56 chords a quarter turn (after the rapid)
    assert len(chord_points(text)) == 1 + 2 * 56


@pytest.mark.parametrize("sweep", [90.0, 180.0, 270.0])
def test_r_words(tmp_path: Path, sweep: float) -> None:
    """Option 252 = 3: R is the radius, negative beyond 180 degrees; I, J are not given."""
    machin = "MACHIN/GECENT,82,OPTAB,252,3"
    end = (50 * cos(sweep * pi / 180), 50 * sin(sweep * pi / 180))
    body = ("RAPID", "GOTO/50,0,-1", "FEDRAT/300,MMPM", "CIRCLE/0,0,-1,0,0,1,50")
    body += (f"GOTO/{end[0]:.6f},{end[1]:.6f},-1",)
    _, _, tape = post(tmp_path, program(*body, machin=machin), None)
    line = next(line for line in tape.splitlines() if " G03 " in line)
    assert " I" not in line and " J" not in line
    assert line.endswith(" R-50." if sweep > 180 else " R50."), line


@needs_rs274
def test_r_words_verify(plugins: PluginSet, tmp_path: Path) -> None:
    machin = "MACHIN/GECENT,80,OPTAB,252,3"
    body = (*arc(100.0), "CIRCLE/0,0,-1,0,0,1,100", "GOTO/100,0,-1")  # 90, then 270 degrees
    source, tape, text = post(tmp_path, program(*body, machin=machin), None)
    assert "R100." in text and "R-100." in text
    assert verified(plugins, tape, source, None) == 2


def test_a_full_circle_in_r_words_takes_i_and_j(tmp_path: Path) -> None:
    machin = "MACHIN/GECENT,82,OPTAB,252,3"
    body = ("RAPID", "GOTO/50,0,-1", "FEDRAT/300,MMPM", "CIRCLE/0,0,-1,0,0,1,50", "GOTO/50,0,-1")
    _, _, tape = post(tmp_path, program(*body, machin=machin), None)
    assert "G03 X50. Y0. I-50. F300.\n" in tape and " R" not in tape


def test_a_fatal_error_of_an_arc_names_the_arc(tmp_path: Path) -> None:
    """The arc goes out when the next record arrives; its fatal error names its own record."""
    machine_file = tmp_path / "narrow.toml"
    pack = Path(__file__).parents[1] / "plugins" / "machines" / "linuxcnc-mill.toml"
    text = pack.read_text().replace('name = "linuxcnc-mill"', 'name = "narrow"')
    text = re.sub(r"^(21|31|44|45|49|50) = \d.*\n", "", text, flags=re.M)
    text = text.replace("number = 80 ", "number = 97 ")
    machine_file.write_text(text)
    source = tmp_path / "part.apt"
    source.write_text(program(*arc(150.0)))
    result = CliRunner().invoke(
        main, ["post", str(source), "--machine", str(machine_file), "-o", str(tmp_path / "t")]
    )
    assert result.exit_code == 1, result.output
    assert "part.apt:10 " in result.output  # the GOTO on the arc, not the FINI after it
    assert "fatal error 144" in result.output


def test_every_whole_arc_pack_has_a_code_for_every_radius(plugins: PluginSet) -> None:
    """A pack with whole arcs (option 253 = 1) is a G-code control: its circular G codes
    cover every radius up to option 4 (fatal 144 was any arc over 100 mm)."""
    packs = [pack.load() for pack in plugins.machines()]
    whole = [machine for machine in packs if machine.number_option(253) == 1]
    assert {"linuxcnc-mill", "fanuc-mill", "fanuc-lathe"} <= {m.name for m in whole}
    for machine in whole:
        codes = CircularCodes(machine)
        largest = machine.number_option(4)
        for radius in (0.001, 0.5, 9.9, 99.9, 100.0, 1000.0, largest * 0.999, largest):
            for clockwise in (True, False):
                assert codes.select(radius, clockwise).code == (2 if clockwise else 3)
