"""Modern controls (gecent options 251-260, docs/modern-controls.md): the packs' tapes for
hand-checked programs, block by block, and the option mechanics one at a time."""

from __future__ import annotations

from pathlib import Path

import pytest
from gecent.core.dispatch.post import post
from gecent.core.machine.regformat import decode_regfor
from gecent.core.output.format import RegisterFormatter
from gecent.core.output.modern import machine_planes
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import PluginSet

from .conftest import ROOT

EXAMPLES = ROOT / "examples"


def tape(plugins: PluginSet, tmp_path: Path, text: str, machine: str) -> list[str]:
    source = tmp_path / "part.apt"
    source.write_text(text)
    return tape_lines(post(str(source), plugins, machine).blocks)


@pytest.mark.parametrize(
    ("value", "expected"),
    [
        (12.5, "12.5"),
        (-0.25, "-0.25"),
        (10.0, "10."),
        (0.0, "0."),
        (1193.6631, "1193.663"),
        (-0.0004, "0."),
        (0.0005, "0.001"),
    ],
)
def test_decimal_point_words(value: float, expected: str) -> None:
    fmt = decode_regfor(-53.0)
    assert fmt is not None
    formatter = RegisterFormatter(3, "X", fmt, drop_trailing=True, decimal=True)
    assert formatter.format(value).punched == expected


def test_whole_number_words_lose_leading_zeros_except_codes() -> None:
    fmt = decode_regfor(50.0)
    assert fmt is not None
    assert (
        RegisterFormatter(12, "S", fmt, drop_trailing=False, decimal=True).format(1200).punched
        == "1200"
    )
    two = decode_regfor(20.0)
    assert two is not None
    assert (
        RegisterFormatter(2, "G", two, drop_trailing=False, decimal=True).format(1).punched == "01"
    )


def test_machine_planes_follow_the_shuffle() -> None:
    # a mill: CL planes on the machine's, none mirrored
    assert machine_planes(((3, 1), (4, 1), (5, 1))) == ((18, False), (19, False), (20, False))
    # the lathe: CL x -> Z, CL y -> X: the CL XY plane is ZX (G18), in order
    assert machine_planes(((5, 1), (3, 1), None))[0] == (19, False)
    # MACH04's -X mirrors it
    assert machine_planes(((5, 1), (3, -1), None))[0] == (19, True)


HELLO = """\
PARTNO BRACKET (4711) OP10
PPRINT CLAMP THE PART
UNITS / MM
LOADTL / 3
SPINDL / RPM, 1200.4, CLW
COOLNT / ON
FROM / 0, 0, 50
RAPID
GOTO / 10, 5, 20
FEDRAT / 250, MMPM
GOTO / 10, 5, -1
CIRCLE / 15, 5, -1, 0, 0, -1, 5
GOTO / 20, 5, -1
CIRCLE / 15, 5, -1, 0, 0, 1, 5
GOTO / 20, 5, -1
DELAY / 1.5
FEDRAT / 0.1, MMPR
GOTO / 0, 5, -1
COOLNT / OFF
SPINDL / OFF
FINI
"""


def test_linuxcnc_mill_program(plugins: PluginSet, tmp_path: Path) -> None:
    """Every block checked: % frame, comments with brackets, the start block, T M06, S in
    RPM with M03, G00 without F, absolute words with unchanged axes left out, a half
    circle clockwise and a full circle counterclockwise with signed I, G04 P in seconds,
    G95 for a feed per revolution, M09 M05 and M02 at FINI."""
    assert tape(plugins, tmp_path, HELLO, "linuxcnc-mill") == [
        "%",
        "(BRACKET [4711] OP10)",
        "(CLAMP THE PART)",
        "(T3)",  # the tool list (option 264)
        "G17 G21 G90 G94 G40 G49 G80 G54",
        "N1 T03 M06",
        "N2 S1200 M03",
        "N3 M08",  # forced out by the FROM (001 L31370-31374)
        "N4 G00 G43 X10. Y5. Z20. H3",  # tool length with the first move (option 263)
        "N5 G01 Z-1. F250.",
        "N6 G02 X20. Y5. I5.",
        "N7 G03 X20. Y5. I-5.",
        "N8 G04 P1.5",
        "N9 G95",
        "N10 G01 X0. F0.1",
        "N11 M09",
        "N12 M05",
        "N13 M02",
        "%",
    ]


def test_a_circle_back_to_its_start_is_a_full_circle(plugins: PluginSet, tmp_path: Path) -> None:
    """X and Y are stated although unchanged: LinuxCNC refuses G02/G03 without them."""
    lines = tape(plugins, tmp_path, HELLO, "linuxcnc-mill")
    assert "N7 G03 X20. Y5. I-5." in lines
    # an arc so short that its end rounds onto its start is no move at all
    short = HELLO.replace(
        "CIRCLE / 15, 5, -1, 0, 0, 1, 5\nGOTO / 20, 5, -1",
        ("CIRCLE / 15, 5, -1, 0, 0, 1, 5\nGOTO / 19.99999996, 5.0004, -1"),
    )
    assert not any("I-5." in line for line in tape(plugins, tmp_path, short, "linuxcnc-mill"))


def test_fanuc_mill_frame(plugins: PluginSet, tmp_path: Path) -> None:
    lines = tape(plugins, tmp_path, HELLO, "fanuc-mill")
    assert lines[:2] == ["%", "O1000"]
    assert "N8 G04 P1500" in lines  # milliseconds
    assert lines[-2:] == ["N13 M30", "%"]


def test_fanuc_lathe_example(plugins: PluginSet) -> None:
    """The lathe example: G18, X in diameters, I/K signed radius offsets, G95 feeds,
    G03 for the convex fillet and G02 for the concave one; T0101 from LOADTL/1."""
    lines = tape_lines(post(str(EXAMPLES / "lathe_fanuc.apt"), plugins).blocks)
    assert lines == [
        "%",
        "O2000",
        "(SHAFT END OP10)",
        "(T0101)",
        "G18 G21 G90 G94 G40 G80 G54",
        "N1 T0101",  # station 1, offset 1 (option 263 = 2)
        "N2 S1200 M03",
        "N3 M08",
        "N4 G00 X20. Z2.",
        "N5 G95",
        "N6 G01 Z-20. F0.15",
        "N7 G03 X30. Z-25. K-5.",
        "N8 G01 Z-40.",
        "N9 X40.",
        "N10 G02 X60. Z-50. I10.",
        "N11 G01 Z-60. F0.08",
        "N12 G04 P500",
        "N13 G94",
        "N14 G01 X64. F200.",
        "N15 G00 X120. Z50.",
        "N16 M09",
        "N17 M05",
        "N18 M30",
        "%",
    ]


CYCLES = """\
UNITS / MM
LOADTL / 1
SPINDL / RPM, 900, CLW
FROM / 0, 0, 50
RAPID
GOTO / 10, 10, 5
CYCLE / DEEP, DEPTH, 12, STEP, 4, MMPM, 80, CLEAR, 2
GOTO / 10, 10, 0
GOTO / 30, 10, 0
GOTO / 30, 10, -2
CYCLE / FACE, DEPTH, 1, DWELL, 0.5, MMPM, 60, CLEAR, 2, RETURN, 0
GOTO / 50, 10, 0
CYCLE / OFF
RAPID
GOTO / 0, 0, 50
FINI
"""


def test_control_cycles(plugins: PluginSet, tmp_path: Path) -> None:
    """G99 G83 with Z (the bottom), R (top + CLEAR) and Q; the next hole X Y only; a hole
    with another top gives Z and R again; FACE is G82 with P, RETURN,0 is G98; G80."""
    lines = tape(plugins, tmp_path, CYCLES, "linuxcnc-mill")
    assert lines[lines.index("N3 G00 G43 X10. Y10. Z5. H1") + 1 :] == [
        "N4 G99",
        "N5 G83 X10. Y10. Z-12. F80. R2. Q4.",
        "N6 X30. Y10.",
        "N7 X30. Y10. Z-14. R0. Q4.",
        "N8 G98",
        "N9 G82 X50. Y10. Z-1. F60. R2. P0.5",
        "N10 G80",
        "N11 G00 X0. Y0. Z50.",
        "N12 M02",
        "%",
    ]


def test_cycle_return_to_another_level_is_drilled_by_moves(
    plugins: PluginSet, tmp_path: Path
) -> None:
    """G98/G99 return to the start or R only: RETURN,5 is drilled by moves (issue 22,
    tests/test_cycles_wave3.py), back to 5 above the top."""
    text = CYCLES.replace("RETURN, 0", "RETURN, 5")
    lines = tape(plugins, tmp_path, text, "linuxcnc-mill")
    assert not any("G82" in line for line in lines)
    assert any(line.endswith("G04 P0.5") for line in lines)
    assert lines[lines.index("N8 G80") + 5] == "N13 G00 Z5."
