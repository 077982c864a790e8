"""Multiaxis linear motion (manual §3.4.7; spec 03 §12, spec 05 §3.1.4): points with tool
axes through the machine's transform class, departures with ROTMOV, segments, feed by the
part path."""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np
import pytest
from gecent.core.cl.records import Motion, MotionSubtype
from gecent.core.dispatch.post import post
from gecent.core.errors import InputError
from gecent.core.machine import standard_machine
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.motion.multiaxis import MultiaxisMotion
from gecent.core.multiaxis.transform import B, Kinematics, MachinePoints, Points, as_points
from gecent.core.output.block import Block, Code
from gecent.core.output.tape import tape_line
from gecent.core.plugins import PluginSet, get_plugins
from gecent.core.state import PostState

PROGRAM = """PARTNO MULTIAXIS
MACHIN/GECENT,40
FROM/0,0,10,0,0,1
FEDRAT/10
GOTO/1,0,10,0,0,1
GOTO/1,0,10,0,0.6,0.8
GOTO/2,1,10,0.6,0,0.8
GOTO/2,1,9
FINI
"""


def mach40_g10() -> MachineDefinition:
    """MACH40 with a TABLEG(11) (G10): as transcribed it has G11 and G01 only, so SELGRO has
    no code for a rotary departure of ROTMAX / 10 (3.6 degrees) or more and stops with fatal
    138 (W22, 001 L6261-6282; docs/decisions.md); the manual's examples assume every code
    available (L6127-6128)."""
    pack = get_plugins().machine("mach40")
    assert pack is not None
    text = '[machine]\nname = "mach40x"\ntitle = "MACH40 TEST"\n[tableg]\n11 = 10\n'
    return load_machine_text(text, "mach40x.toml", pack.load())


def test_mach40_posts_a_multiaxis_program(plugins: PluginSet, tmp_path: Path) -> None:
    """MACH40 is class 1 (table C about Z, head A about X), R + TL = option 104 = 4 in,
    rotary output in hundredths of a revolution (option 118 = -1), ROTMAX 35.99964 degrees
    (option 111) = 9.9999 units. Worked by hand from class 1's equations:

    * FROM along Z (k = 1, singular): C stays 0, A = 90, Z = 10 + 4 = 14;
    * (1, 0, 10) along Z: X = x sin C - y cos C = 0, Y = x cos C + y sin C = 1: Y+1;
    * tool (0, .6, .8): C = 90, A = 53.13; X = 1, Y = 4 x .6 = 2.4, Z = 10 + 3.2 = 13.2;
      C turns 25 units (90 degrees) and A -10.2417 (-36.87): three segments of ROTMAX;
    * (2, 1, 10) with (.6, 0, .8): C back to 0 (the shorter way), X = -1, Y = 2 + 2.4:
      X -2, Y +2 in three segments;
    * a 3-value point keeps the tool axis: Z-1.

    SELGRO (W22, 001 L6261-6282): a segment of ROTMAX turns C 8.3333 units, above ROTMAX /
    10 (.99999), which needs the 36-359.9999 degree code, TABLEG(11). MACH40 as transcribed
    has none, so SEGMNT cuts its turns to the largest range it has a code for, ROTMAX / 10
    (TABLEG(2), G01; docs/decisions.md): 25 units in 26 blocks, each within .99999. With a
    G10 they go out in three segments under it (changed from G11 by the manual's rule), and
    the inverse time command takes the G10 row (format 33, at most 9.999, 001 L24453):
    F001194, and N007's 21.2 held to F009999 (4.71 IPM)."""
    program = tmp_path / "m.apt"
    program.write_text(PROGRAM)
    as_transcribed = post(str(program), plugins)
    lines = [tape_line(b) for b in as_transcribed.blocks if b.code is not Code.PARTNO]
    lines = [line for line in lines if line]
    assert [line[:4] for line in lines].count("N006") == 26
    assert [line[:4] for line in lines].count("N007") == 26
    assert lines[1] == "N006X+00385Y+00538Z-00308A-03939C+09615F01035"
    turns = [int(line.split("C")[1][:6]) for line in lines if line.startswith("N006")]
    assert sum(turns) == 250000 and max(abs(t) for t in turns) <= 9999
    result = post(str(program), plugins, machine_override=mach40_g10())
    lines = [tape_line(b) for b in result.blocks if b.code is not Code.PARTNO]
    assert [line for line in lines if line] == [
        "N005G01Y+1F01000",
        "N006G10X+03333Y+04667Z-02667A-34139C+83333F001194",
        "N006X+03334Y+04666Z-02666A-34138C+83334",
        "N006X+03333Y+04667Z-02667A-34139C+83333",
        "N007X-06667Y+06667C-83333F009999",
        "N007X-06666Y+06666C-83334",
        "N007X-06667Y+06667C-83333",
        "N008G01Z-1F01000",
    ]


@dataclass(frozen=True)
class GivenPoints:
    """A transform class giving the machine points a worked example states (the manual's
    W5 and E2 name no class): part x picks the machine point."""

    points: dict[float, tuple[float, ...]]
    number: int = 1
    name: str = "GIVEN"
    section: str = "§4.2"
    structure: str = "5(3,0,2)"
    rotary: tuple[int, ...] = (3, B)

    def direct(
        self, part: Points, kinematics: Kinematics, previous: Points | None = None
    ) -> MachinePoints:
        rows = [self.points[float(x)] for x in as_points(part)[:, 0]]
        axes = np.array([[*row[:3], np.radians(row[3]), np.radians(row[4]), 0.0] for row in rows])
        return MachinePoints(axes, np.zeros(len(rows), dtype=bool))

    def inverse(self, machine: Points, kinematics: Kinematics) -> Points:
        raise AssertionError("not used")


def _moves(given: GivenPoints, points: list[tuple[float, ...]]) -> list[Block]:
    machine = standard_machine().with_options({118: 1.0, 111: 999.0, 119: 0.0001, 4: 99.9999})
    registers = machine.registers
    formats = list(registers.formats)
    letters = list(registers.letters)
    formats[6] = formats[7] = formats[3]
    letters[6], letters[7] = "A", "B"
    machine = replace(
        machine, heads=(replace(registers, formats=tuple(formats), letters=tuple(letters)),)
    )
    blocks: list[Block] = []
    motion = MultiaxisMotion(PostState(machine), blocks.append, given, lambda d: None)
    for number, point in enumerate(points, start=1):
        subtype = MotionSubtype.FROM if number == 1 else MotionSubtype.GOTO
        motion.record(Motion("t", number, number, subtype, (point,)))
    return blocks


def test_w5_multiaxis_departures() -> None:
    """Spec 03 W5 (001 L4243-4255): present less previous: dX 11.5730 = 22.6841 - 11.1111,
    dY 3.3699 = 3.2466 - (-0.1233), dZ 0, dA 25 = 50 - 25, dB -25 = -25 - 0."""
    given = GivenPoints(
        {1.0: (11.1111, -0.1233, -1.0, 25.0, 0.0), 2.0: (22.6841, 3.2466, -1.0, 50.0, -25.0)}
    )
    _, move = _moves(given, [(1.0, 0, 0, 0, 0, 1), (2.0, 0, 0, 0, 0, 1)])
    assert [round(float(move.cells[k]), 4) for k in (3, 4, 5, 6, 7)] == [
        11.573,
        3.3699,
        0.0,
        25.0,
        -25.0,
    ]


def test_e2_the_feed_goes_by_the_part_path() -> None:
    """Spec 05 E2 (001 L10985-11038): P1 (0, 1, 2) to P2 (3, 5, 2): S = 5 in part
    coordinates; the machine's departures (6, 8, 3, B 90) are not used."""
    given = GivenPoints({0.0: (0.0, 0.0, 9.0, 0.0, 90.0), 3.0: (6.0, 8.0, 12.0, 0.0, 180.0)})
    _, move = _moves(given, [(0.0, 1, 2, 0, 0, 1), (3.0, 5, 2, 0, 1, 0)])
    assert move.feed_length == pytest.approx(5.0)
    assert float(move.cells[7]) == pytest.approx(90.0)


def test_a_tool_axis_not_of_length_one_is_warned(plugins: PluginSet, tmp_path: Path) -> None:
    """FROM5 (001 L6290-6300): the direction cosines' length is tested."""
    program = tmp_path / "m.apt"
    program.write_text(PROGRAM.replace("GOTO/1,0,10,0,0.6,0.8", "GOTO/1,0,10,0,0.6,0.9"))
    result = post(str(program), plugins, machine_override=mach40_g10())
    assert any("NOT A UNIT VECTOR" in d.text for d in result.diagnostics)


@pytest.mark.parametrize(
    ("line", "feature"),
    [
        # OUT on a hole along another tool axis than the one the tool stands at (issue 22;
        # DRILL's five-axis hole pattern is built, tests/test_five_axis_hole_pattern.py)
        ("CYCLE/OUT,DEPTH,1,CLEAR,0.1\nGOTO/2,1,9,0,0,1", "turn at the bottom of a hole"),
    ],
)
def test_what_multiaxis_motion_did_not_do_is_built(
    plugins: PluginSet, tmp_path: Path, line: str, feature: str
) -> None:
    """(Not yet supported until wave 7: OUT from outside a hole goes to the new hole's R point
    along its axis, tests/test_last_forms_wave7.py.)"""
    program = tmp_path / "m.apt"
    program.write_text(PROGRAM.replace("GOTO/2,1,9", f"{line}\nGOTO/2,1,9"))
    result = post(str(program), plugins, machine_override=mach40_g10())
    assert not any(feature in d.text for d in result.diagnostics)


def test_linrty_leaves_every_piece_within_the_sphere() -> None:
    """LINRTY (spec 03 §15.5): each piece it outputs has its machine midpoint, carried back
    to the part, within r of the part midpoint (the tolerance sphere), and within the cone;
    the pieces end at the move's end."""
    from gecent.core.motion.linearity import LinearityTest, _midpoint
    from gecent.core.state import Linearity
    from gecent.plugins.classes.class1 import Class1

    transform, kinematics = Class1(), Kinematics(reach=4.0)
    test = LinearityTest(transform, kinematics)
    rule = Linearity(radius=0.001, cone=0.5)
    start = (0.0, 0.0, 10.0, 0.0, 0.6, 0.8)
    end = (2.0, 0.0, 10.0, 0.6, 0.0, 0.8)
    machine = transform.direct(np.array([start]), kinematics).axes[0]
    points, met = test.points(start, machine, end, rule, 100_000)
    assert met and len(points) > 3 and points[-1] == end
    at, at_machine = start, machine
    for point in points:
        point_machine = test.machine(point, at_machine)
        back = transform.inverse(((at_machine + point_machine) / 2).reshape(1, 6), kinematics)[0]
        half = _midpoint(at, point)
        assert np.linalg.norm(back[:3] - np.array(half[:3])) <= rule.radius
        at, at_machine = point, point_machine


def _lintol_program(tmp_path: Path, lintol: str) -> list[str]:
    program = tmp_path / "l.apt"
    program.write_text(
        "PARTNO L\nMACHIN/GECENT,40\nFROM/0,0,10,0,0.6,0.8\nFEDRAT/10\n"
        f"{lintol}\nGOTO/2,0,10,0.6,0,0.8\nFINI\n"
    )
    result = post(str(program), get_plugins(), machine_override=mach40_g10())
    lines = [line for b in result.blocks if b.code is Code.LINEAR and (line := tape_line(b))]
    return [line[4:] if line.startswith("N") else line for line in lines]  # (N aside)


def test_lintol_cuts_a_move_that_leaves_the_tolerance(tmp_path: Path) -> None:
    """LINTOL/r (001 L6980-7043): no test before it (ROTMAX's three segments), many pieces
    with it; LINTOL/0 cancels it; LINTOL/OFF leaves a one-point record untested."""
    untested = _lintol_program(tmp_path, "PPRINT NO LINTOL")
    assert len(untested) == 3  # C turns 90 degrees: three ROTMAX segments
    assert len(_lintol_program(tmp_path, "LINTOL/0.001")) > 20
    assert _lintol_program(tmp_path, "LINTOL/0.001\nLINTOL/0") == untested
    assert _lintol_program(tmp_path, "LINTOL/0.001\nLINTOL/OFF") == untested


def test_lintol_forms_are_checked(tmp_path: Path) -> None:
    from gecent.core.errors import InputError

    program = tmp_path / "l.apt"
    program.write_text("PARTNO L\nMACHIN/GECENT,40\nLINTOL/-1\nFINI\n")
    with pytest.raises(InputError, match="LINTOL expects"):
        post(str(program), get_plugins())


def test_a_three_axis_post_never_loads_numpy(tmp_path: Path) -> None:
    """The transform classes load with the plugins, numpy only when one computes: a
    three-axis run stays as light as it was (peak memory, start-up)."""
    import subprocess
    import sys

    from .conftest import ROOT

    script = (
        "import sys\n"
        "from gecent.core.dispatch.post import post\n"
        "from gecent.core.plugins import get_plugins\n"
        f"post({str(ROOT / 'examples' / 'hello.apt')!r}, get_plugins())\n"
        "print('numpy' in sys.modules)\n"
    )
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "False"


def test_linrty_says_when_the_tolerance_cannot_be_met(tmp_path: Path) -> None:
    """A tool axis turning from (.6, 0, .8) to (-.6, 0, .8) passes +Z at its midpoint,
    class 1's singular axis: no halving can follow it, and the run says so (spec 03 open
    question 18's guard) instead of punching it as tested; a LINTOL so fine it asks for
    more pieces than --max-segments is refused."""
    program = tmp_path / "p.apt"
    program.write_text(
        "PARTNO P\nMACHIN/GECENT,40\nFROM/5,0,10,0.6,0,0.8\nFEDRAT/10\nLINTOL/0.001\n"
        "GOTO/5,0,10,-0.6,0,0.8\nFINI\n"
    )
    result = post(str(program), get_plugins(), machine_override=mach40_g10())
    assert any("LINEARITY TOLERANCE CANNOT BE MET" in d.text for d in result.diagnostics)
    program.write_text(
        program.read_text().replace("GOTO/5,0,10,-0.6,0,0.8", "GOTO/5,0,10,0,0.6,0.8")
    )
    program.write_text(program.read_text().replace("LINTOL/0.001", "LINTOL/0.000000000001"))
    with pytest.raises(InputError, match="segment"):
        post(str(program), get_plugins(), machine_override=mach40_g10(), max_segments=50)


def test_lintol_r_alone_drops_the_cone() -> None:
    """LINTOL/r: the sphere test only (001 L6936-6946)."""
    from gecent.core.cl.apt_source import AptSourceReader
    from gecent.core.run import Run

    run = Run(standard_machine())
    run.process(AptSourceReader("p.apt").read_lines(["LINTOL/0.01,0.5", "LINTOL/0.02", "FINI"]))
    assert (run.state.linearity.radius, run.state.linearity.cone) == (0.02, None)
