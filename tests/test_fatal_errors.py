"""Every fatal error a run can reach today (manual §5.7.1, core/errors.py FATAL_ERRORS):
its number and text on stderr, exit status 1, the listing written with what was output
before it and the GEDUMP dump, and no tape file."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main

MILL_WITH_A_BAD_SHUFFLE = """
[machine]
name = "bad-shuffle"
title = "BAD SHUFFLE"
[optab]
59 = 112233.0
"""


def run(tmp_path: Path, lines: list[str], machine: str | None) -> tuple[int, str, Path, Path]:
    source = tmp_path / "part.apt"
    source.write_text("\n".join([*lines, "FINI"]) + "\n")
    tape, listing = tmp_path / "part.tape", tmp_path / "part.lis"
    arguments = ["post", str(source), "-o", str(tape), "--listing", str(listing)]
    if machine:
        arguments += ["--machine", machine]
    result = CliRunner().invoke(main, arguments)
    return result.exit_code, result.stderr, tape, listing


def test_fatal_24_no_initial_spindle_speed(tmp_path: Path) -> None:
    code, err, tape, listing = run(tmp_path, ["MACHIN/GECENT,23,OPTAB,27,-1", "SPINDL/CLW"], None)
    assert code == 1 and not tape.exists()
    assert "fatal error 24 (SPINDL): No initial spindle speed given" in err
    assert "part.apt:2 (record 2)" in err
    dump = listing.read_text()
    assert "*** GEDUMP ***" in dump and "CL RECORD 2" in dump
    assert "SPINDL/ CLW" in dump  # the record as the CL print shows it


def test_fatal_138_no_g_code_for_the_departure(tmp_path: Path) -> None:
    """A mill with G11 only (departures under 1 inch) and option 4 = 9.9999: a 5-inch move
    is not segmented below 1 inch, and no code covers it."""
    machine = tmp_path / "g11only.toml"
    machine.write_text(
        '[machine]\nname = "g11only"\ntitle = "G11 ONLY"\n[tableg]\n2 = "absent"\n12 = 11\n'
    )
    program = ["FROM/0,0,0", "FEDRAT/10", "GOTO/0.5,0,0", "GOTO/5.5,0,0"]
    code, err, tape, listing = run(tmp_path, program, str(machine))
    assert code == 1 and not tape.exists()
    assert "fatal error 138 (SELG): No G code is available for the segment length" in err
    text = listing.read_text()
    assert "G11 ONLY" in text  # the listing of what came before
    assert "CL RECORD 4" in text and "DPREVP (part)    +0.5000 +0.0000 +0.0000" in text


def test_fatal_144_no_circular_code_for_the_radius(tmp_path: Path) -> None:
    """A mill whose circular codes stop at radius 1 (TABLEG 22/32 only): a 2-inch arc has
    no code; the circle passes the option-4 test, so SELGCR's fatal 144 follows."""
    machine = tmp_path / "small-arcs.toml"
    machine.write_text(
        '[machine]\nname = "small-arcs"\ntitle = "SMALL ARCS"\n'
        '[tableg]\n3 = "absent"\n4 = "absent"\n22 = 2\n32 = 3\n'
    )
    program = ["FROM/2,0,0", "FEDRAT/10", "CIRCLE/0,0,0,0,0,1,2", "GOTO/0,2,0"]
    code, err, tape, listing = run(tmp_path, program, str(machine))
    assert code == 1 and not tape.exists()
    assert "fatal error 144 (SELGCR): No G code is available for this radius" in err
    assert "*** GEDUMP ***" in listing.read_text()


def test_fatal_7_option_59_set_up_wrong(tmp_path: Path) -> None:
    machine = tmp_path / "bad.toml"
    machine.write_text(MILL_WITH_A_BAD_SHUFFLE)
    code, err, tape, _ = run(tmp_path, ["FROM/0,0,0", "FEDRAT/10", "GOTO/1,0,0"], str(machine))
    assert code in (1, 2) and not tape.exists()
    assert "59" in err


def test_fatal_999_machine_number_out_of_range(tmp_path: Path) -> None:
    code, err, tape, _ = run(tmp_path, ["MACHIN/GECENT,100"], None)
    assert code == 1 and not tape.exists()
    assert "fatal error 999 (INIT): Given machine number is < 1 or > 99" in err


@pytest.mark.parametrize("option", ["-1", "0"])
def test_fatal_24_also_for_ipr_feeds_without_a_speed(tmp_path: Path, option: str) -> None:
    program = [f"MACHIN/GECENT,23,OPTAB,27,{option}", "FEDRAT/0.1,IPR"]
    code, err, tape, _ = run(tmp_path, program, None)
    assert code == 1 and not tape.exists() and "fatal error 24" in err


def test_fatal_139_and_142_guard_the_segmentation() -> None:
    """SELG's 139 and SELGCR's 142 are the manual's checks that segmentation did its work
    (a departure or a radius beyond option 4 reaching the G-code choice); the motion
    elements segment first and circles beyond option 4 go linear, so no CL input reaches
    them. They are triggered at the selectors themselves: number, text, exit status 1."""
    from gecent.core.errors import FatalError
    from gecent.core.machine.loader import standard_machine
    from gecent.core.motion.gcode import CircularCodes, LinearCodes

    machine = standard_machine()
    with pytest.raises(FatalError) as linear:
        LinearCodes(machine, 0.0001).select(100_000)  # 10 inches > option 4 = 9.9999
    assert linear.value.number == 139 and linear.value.exit_status == 1
    assert "Segment too long; it should have been split" in str(linear.value)
    with pytest.raises(FatalError) as circle:
        CircularCodes(machine).select(12.0, True)
    assert circle.value.number == 142 and circle.value.exit_status == 1
    assert "Circle radius too large" in str(circle.value)


def test_fatal_19_the_from_points_tool_axis_is_not_a_unit_vector(tmp_path: Path) -> None:
    """FROM5 tests the direction cosines of the FROM point: |I² + J² + K² - 1| > e is
    error 19 (001 L28364-28380, L31445-31460). A later point's axis is only warned about."""
    program = ["MACHIN/GECENT,40", "MULTAX", "FROM/-19,48,31.75,0,0,2"]
    code, err, tape, listing = run(tmp_path, [*program, "FEDRAT/10", "GOTO/-18,48,31.75"], None)
    assert code == 1 and not tape.exists()
    assert "fatal error 19 (FROMS): Direction cosines of the FROM point" in err
    assert "|i, j, k| = 2" in err and "part.apt:3 (record 3)" in err
    assert "*** GEDUMP ***" in listing.read_text()
    # (option 110 = 0: these CL points are outside MACF40's machine windows, MCHCON 2)
    unit = ["MACHIN/GECENT,40,OPTAB,110,0", "MULTAX", "FROM/-19,48,31.75,0,0,1", "FEDRAT/10"]
    code, err, tape, _ = run(tmp_path, [*unit, "GOTO/-18,48,31.75,0,0,2"], None)
    assert code == 0 and tape.exists()
    assert "NOT A UNIT VECTOR; THEY ARE NORMALIZED" in err


def test_fatal_39_a_rotary_departure_beyond_option_111() -> None:
    """SELGRO's error 39, "rotary move is greater than maximum departure - it should have
    been segmented" (001 L37125-37135): SEGMNT cuts every turn to option 111 first, so no
    CL input reaches it; it is triggered at the selector, for a line and for a circle."""
    from gecent.core.errors import FatalError
    from gecent.core.machine.loader import load_machine_text
    from gecent.core.motion.gcode import CircularCodes, RotaryCodes, circle_code

    machine = load_machine_text(
        '[machine]\nname = "r"\ntitle = "R"\n[tableg]\n11 = 10\n12 = 11\n13 = 12\n', "r.toml"
    )
    rotmax = machine.number_option(111)  # 35.99964 degrees
    rotary = RotaryCodes(machine, rotmax)
    assert rotary.select(rotmax).code == 10  # at the limit: TABLEG(11)
    with pytest.raises(FatalError) as line:
        rotary.select(40.0)
    assert line.value.number == 39 and line.value.exit_status == 1
    assert "Rotary departure too large; it should have been segmented" in str(line.value)
    with pytest.raises(FatalError) as circle:
        circle_code(CircularCodes(machine), rotary, 0.05, True, 40.0)
    assert circle.value.number == 39
