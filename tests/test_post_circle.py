"""Circular interpolation: the manual's worked examples, the APT IV corpus circles, SELGCR."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.cl.records import Motion, MotionSubtype, Record
from gecent.core.cli import main
from gecent.core.errors import FatalError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import standard_machine
from gecent.core.motion.gcode import CircularCodes
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins
from gecent.core.run import Run, RunResult

from .conftest import SHARED
from .test_post_linear import tape

APT4 = SHARED / "corpus" / "apt4"


def post_apt(lines: list[str], machine: MachineDefinition | None = None) -> RunResult:
    """Post APT-style records: a ``POINTS/x,y,z,x,y,z,...`` line is one GOTO record with
    several points, as an APT processor writes a circle's cut vectors."""
    records: list[Record] = []
    reader = AptSourceReader("apt.cl")
    for number, line in enumerate([*lines, "FINI"], start=1):
        if line.startswith("POINTS/"):
            values = [float(v) for v in line[7:].split(",")]
            points = tuple(tuple(values[i : i + 3]) for i in range(0, len(values), 3))
            records.append(Motion("apt.cl", number, number, MotionSubtype.GOTO, points))
        else:
            (record,) = reader.read_lines([line])
            records.append(replace(record, line=number, number=number))
    return Run(machine or standard_machine()).process(iter(records))


def punched(result: RunResult) -> list[str]:
    return tape_lines(result.blocks)


def test_w10_clockwise_circle_from_quadrant_2_to_4() -> None:
    """W10 (001 L4852-5149), numbered: centre (0,0), r = 2, CLW from (-1.2, 1.6) to
    (1.2, -1.6) crosses at A = (0, 2) and B = (2, 0): three CODE +10 blocks, I/J unsigned
    from each block's start; F = 10 * 10 IPM / 2."""
    lines = punched(
        post_apt(
            ["FROM/-1.2,1.6,0", "FEDRAT/10", "CIRCLE/0,0,0,0,0,1,2", "POINTS/1.6,1.2,0,1.2,-1.6,0"]
        )
    )
    assert lines == [
        "N004G02X+12Y+04I12J16F050",
        "N004X+2Y-2J2",
        "N004X-08Y-16I2",
    ]


def test_w11_points_on_the_axes_make_one_quadrant() -> None:
    """W11 diagram C (001 L4917-4948): CCLW from (2, 0) to (0, 2), both on axes: QA = QB = 1,
    one CODE -10 block."""
    result = post_apt(
        ["FROM/2,0,0", "FEDRAT/10", "CIRCLE/0,0,0,0,0,1,2", "POINTS/1.4142136,1.4142136,0,0,2,0"]
    )
    circles = [b for b in result.blocks if b.punch and "G03" in b.punch]
    assert [b.punch for b in circles] == ["N004G03X-2Y+2I2F050"]
    assert int(circles[0].code) == -10


def test_w12_zero_departure_at_the_start_goes_linear() -> None:
    """W12 (001 L5236-5263): P1 = (-0.002, 2.99999) rounds to (-0.002, 3); the first segment
    to (0, 3) has no Y departure, so it is a linear block (CODE 0, no I/J)."""
    lines = punched(
        post_apt(
            [
                "FROM/-0.002,2.99999,0",
                "FEDRAT/10",
                "CIRCLE/0,0,0,0,0,1,3",
                "POINTS/2.1213203,2.1213203,0,2.4,-1.8,0",
            ]
        )
    )
    assert lines == [
        "N004G01X+0002I02F500",
        "N004G02X+3Y-3J3F033",
        "N004X-06Y-18I3",
    ]


def test_a_full_circle_is_four_quadrants() -> None:
    lines = punched(
        post_apt(
            [
                "FROM/2,0.5,0",
                "FEDRAT/10",
                "CIRCLE/0,0.5,0,0,0,1,2",
                "POINTS/0,2.5,0,-2,0.5,0,2,0.5,0",
            ]
        )
    )
    assert lines == [
        "N004G03X-2Y+2I2F050",
        "N004X-2Y-2J2",
        "N004X+2Y-2I2",
        "N004X+2Y+2J2",
    ]


@pytest.mark.parametrize(
    ("setup", "why"),
    [
        (["MACHIN/GECENT,1,LINEAR"], "LINEAR mode (option 28 = 0)"),
        ([], "points off the plane"),
    ],
)
def test_circles_fall_back_to_linear(setup: list[str], why: str) -> None:
    z = "0.01" if why == "points off the plane" else "0"
    result = post_apt(
        [*setup, "FROM/2,0,0", "FEDRAT/10", "CIRCLE/0,0,0,0,0,1,2", f"POINTS/0,2,{z},-2,0,0"]
    )
    punched = [b.punch for b in result.blocks if b.punch and b.punch.startswith("N")]
    assert punched and all("G02" not in p and "G03" not in p for p in punched), why
    assert len(punched) == 2


def test_radius_beyond_option_4_goes_linear() -> None:
    lines = punched(
        post_apt(["FROM/12,0,0", "FEDRAT/10", "CIRCLE/0,0,0,0,0,1,12", "POINTS/0,12,0,-12,0,0"])
    )
    assert not any("G02" in line or "G03" in line for line in lines)


def test_w23_circular_g_selection() -> None:
    """W23 (001 L6130-6146): with every code present, radius 0.08 CLW -> TABLEG(23), GDIMUL
    0.1; radius 40 CCLW -> TABLEG(31), GDIMUL 100. MACH23 lacks (23): the next band's G21."""
    machine = standard_machine().with_options({4: 99.9999})
    every = CircularCodes(
        replace(
            machine,
            tableg=tuple(
                loc if loc in (21, 22, 23, 31, 32, 33, 44, 45, 49, 50) else value
                for loc, value in enumerate(machine.tableg)
            ),
        )
    )
    small, large = every.select(0.08, True), every.select(40.0, False)
    assert (small.location, small.gdimul) == (23, 0.1)
    assert (large.location, large.gdimul) == (31, 100.0)
    mach23 = CircularCodes(get_plugins().machine("mach23").load())
    assert (mach23.select(0.08, True).code, mach23.select(0.08, True).gdimul) == (21, 1.0)
    assert mach23.select(40.0, False).code == 30
    with pytest.raises(FatalError) as caught:
        mach23.select(120.0, True)
    assert caught.value.number == 142


@pytest.mark.skipif(not APT4.is_dir(), reason="shared corpus not present")
@pytest.mark.parametrize("stem", ["test2_contour_tlrgt", "test2d_finetol"])
def test_apt4_contour_circle_posts_as_two_quadrant_blocks(stem: str, tmp_path: Path) -> None:
    """The corpus circle C1 (centre 4,2; part radius 2) is driven by the tool centre at
    R = 2.25 (cutter 0.5); its 54 points (test2d: 6 records of up to 63) go CCLW from
    (4, -0.25) to (4, 4.25): two quadrant blocks of G03, I/J 2.25, F = 10 * 20 / 2.25."""
    tape_file = tmp_path / "t.tape"
    result = CliRunner().invoke(
        main,
        [
            "post",
            str(APT4 / f"{stem}.cl3"),
            "-o",
            str(tape_file),
            "--listing",
            str(tmp_path / "t.lis"),
        ],
    )
    assert result.exit_code == 0, result.stderr
    lines = tape_file.read_text().splitlines()
    circle = 21
    after = 23 if stem == "test2_contour_tlrgt" else 28
    assert lines[1:] == [
        "N016G01X+075Y+075Z-1F137",
        "N018X+425F047",
        f"N0{circle}G03X+225Y+225J225F089",
        f"N0{circle}X-225Y+225I225",
        f"N0{after}G01X-425F047",
        f"N0{after + 2}X-075Y-525Z+1F037",
    ]


def test_cam_circle_with_one_point_takes_its_sense_from_the_axis() -> None:
    """Creo writes CIRCLE then one GOTO, the arc's end: counterclockwise about the axis."""
    ccw = tape(["FROM/2,0,0", "FEDRAT/10", "CIRCLE/0,0,0,0,0,1,2", "GOTO/0,2,0"])
    cw = tape(["FROM/2,0,0", "FEDRAT/10", "CIRCLE/0,0,0,0,0,-1,2", "GOTO/0,2,0"])
    assert ccw == ["N004G03X-2Y+2I2F050"]
    # clockwise about -z from (2, 0) to (0, 2) is the long way round: three quadrants
    assert cw == ["N004G02X-2Y-2I2F050", "N004X-2Y+2J2", "N004X+2Y+2I2"]


def test_mach04_lathe_profile_is_shuffled_onto_z_and_x() -> None:
    """MACH04 (option 59 = 152300, 60 = 181600; 001 L27763-27764): CL x goes out as +Z, CL y
    as -X, I as K and J as I; the lathe's G codes are its own (G11 under 1 inch, G21 for a
    small CCLW arc, 001 L27694-27699)."""
    machine = get_plugins().machine("mach04").load()
    lines = tape(
        [
            "FROM/5,2,0",
            "FEDRAT/10",
            "GOTO/0,2,0",
            "GOTO/0,1.5,0",
            "CIRCLE/-0.5,1.5,0,0,0,-1,0.5",
            "GOTO/-0.5,1,0",
            "GOTO/-3,1,0",
        ],
        machine,
    )
    assert lines == [
        "N003G01Z-5F020",
        "N004G11X+05",
        "N006G31X+05Z-05K05",
        "N007G01Z-25F040",
    ]
