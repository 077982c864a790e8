"""Issue 22, wave 7: the last "not yet supported" statement forms, built to the manual or, where
it defines nothing, as decided in docs/decisions.md (issue 22, wave 7).

* ROTATE/TURRET on a positioning machine (ROTUR, 001 L36345-36382): station n comes down as
  TOOLGP loads a tool: TABLEG(1), T n and the turret-index M code TABLEM(8) in one block,
  turned CLW/CCLW (TABLEM 83/84) as programmed or the shorter way (option 88 = -N); option
  86 = -2 corrects Z by LENGTH and puts out OFSETL's M code (L25424).
* ROTATE/TURRET on a drafting machine (ROTDRF, L36097-36124): D3, the D code DRAFT's pen
  codes 1, 2, 4, 5 leave free (L30529-30578), with the pen-down warning.
"""

from __future__ import annotations

import shutil
from math import cos, pi, radians, sin
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.dispatch.post import post as post_path
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.output.block import Code
from gecent.core.output.sinks import output_sinks
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins
from gecent.core.verify.check import verify

from tests.test_multiaxis_circle import CIRCLES, punched
from tests.test_multiaxis_circle import mach40 as mach40_circles
from tests.test_multiaxis_circle import run as run_mach40
from tests.test_post_linear import post
from tests.test_statements_control import plotter

TURRET_DRILL = """
[tablem]
8 = 55
83 = 61
84 = 62
[optab]
88 = -6.0
130 = -1.0
"""


def turret_drill(extra: str = "") -> MachineDefinition:
    """MACH24 with a six-spindle turret: index M55, CLW M61, CCLW M62, offset M codes 40+k."""
    base = get_plugins().machine("mach24").load()
    text = f'[machine]\nname = "turret-drill"\n{TURRET_DRILL}{extra}'
    # option 96 = -K (the offset M code k + K, 001 L25564-25568) is set past the file
    # rules, which read 96 as the lathe's T layout only (as tests/test_tools_manual.py does)
    return load_machine_text(text, "test.toml", base=base).with_options({96: -40.0})


def tape(lines: list[str], machine: MachineDefinition) -> list[str]:
    return tape_lines(post(lines, machine).blocks)


def test_rotur_brings_the_station_down_the_shorter_way() -> None:
    """From station 1 (the first turn has no known start: index only) to 2 is CLW, to 6
    the shorter way is CCLW; CLW as programmed wins."""
    assert tape(
        [
            "FROM/0,0,5",
            "ROTATE/TURRET,1",
            "ROTATE/TURRET,2",
            "ROTATE/TURRET,6",
            "ROTATE/TURRET,5,CLW",
        ],
        turret_drill(),
    ) == ["N002G80T01M55", "N003G80T02M61", "N004G80T06M62", "N005G80T05M61"]


def test_rotur_sets_the_length_and_puts_out_the_offset_under_option_86_minus_2() -> None:
    """Option 86 = -2: LENGTH is the tool length POSMOV adds to Z (option 86 < 0): the
    moves at 5 go out at Z 7.5 with the 2.5 tool and 8.0 with the 3.0 one; OFSETL 3 is M43
    (option 96 = -40), after the turn's M61 (one M register: a block each)."""
    assert tape(
        [
            "FROM/0,0,5",
            "ROTATE/TURRET,1,LENGTH,2.5",
            "RAPID",
            "GOTO/1,0,5",
            "ROTATE/TURRET,2,OFSETL,3,LENGTH,3.0",
            "RAPID",
            "GOTO/2,0,5",
        ],
        turret_drill("86 = -2.0\n"),
    ) == [
        "N002G80T01M55",
        "N004G80X+010000Y+000000Z+075000F99",
        "N005M61",
        "N005G80T02M43",
        "N007G80X+020000Z+080000",
    ]


def test_rotur_without_option_86_minus_2_ignores_length_and_offset() -> None:
    result = post(["FROM/0,0,5", "ROTATE/TURRET,1,OFSETL,3,LENGTH,3"], turret_drill())
    assert tape_lines(result.blocks) == ["N002G80T01M55"]
    assert "ROTATE/TURRET: OFSETL AND LENGTH ARE USED WITH OPTION 86 = -2 ONLY; IGNORED" in [
        d.text for d in result.diagnostics
    ]


@pytest.mark.parametrize(
    "statement",
    ["ROTATE/TURRET", "ROTATE/TURRET,0", "ROTATE/TURRET,1.5", "ROTATE/TURRET,1,CLW,CCLW",
     "ROTATE/TURRET,1,LENGTH", "ROTATE/TURRET,1,2", "ROTATE/TURRET,1,NOW"],
)  # fmt: skip
def test_rotur_bad_forms_are_input_errors(statement: str) -> None:
    with pytest.raises(InputError, match="ROTATE/TURRET") as error:
        post(["FROM/0,0,5", statement], turret_drill())
    assert error.value.where is not None and error.value.where.line == 2


def test_rotdrf_indexes_by_d3_and_warns_with_the_pen_down() -> None:
    result = post(
        ["FROM/0,0,0", "DRAFT/ON", "ROTATE/TURRET", "DRAFT/OFF", "ROTATE/TURRET"], plotter()
    )
    assert tape_lines(result.blocks) == ["N002D1", "N003D3", "N004D2", "N005D3"]
    assert [d.text for d in result.diagnostics] == [
        "WARNING -- TURRET INDEXED WHILE PEN IS DOWN -- WARNING"
    ]


def test_rotdrf_station_goes_in_t_or_is_refused_without_a_t_register() -> None:
    assert tape(["FROM/0,0,0", "ROTATE/TURRET,2"], plotter()) == ["N002T02D3"]
    no_t = load_machine_text(
        '[machine]\nname = "pens"\n[regfor]\n13 = 0.0\n', "test.toml", base=plotter()
    )
    with pytest.raises(InputError, match="no T register for the station"):
        post(["FROM/0,0,0", "ROTATE/TURRET,2"], no_t)
    assert tape(["FROM/0,0,0", "ROTATE/TURRET"], no_t) == ["N002D3"]


OUT_IN = """PARTNO OUTIN
UNITS/MM
MULTAX
LOADTL/1,LENGTH,100
SPINDL/1000,CLW
FROM/0,0,100,0,0,1
RAPID
GOTO/0,0,50,0,0,1
CYCLE/OUT,DEPTH,5,CLEAR,2
GOTO/0,0,0,0,0,1
CYCLE/IN,DEPTH,5,CLEAR,2
GOTO/20,0,0,0.6,0,0.8
CYCLE/OUT,DEPTH,5,CLEAR,2
GOTO/20,0,0,0.6,0,0.8
CYCLE/IN,DEPTH,5,CLEAR,2
GOTO/0,20,0,0,-0.6,0.8
CYCLE/OFF
FINI
"""


def test_in_withdraws_along_the_old_axis_then_turns_to_the_new_point(tmp_path: Path) -> None:
    """The B-C five-axis pack (tool centre point): OUT drills the first hole and stays at
    Z-5; IN on the tilted axis withdraws along Z to R (Z2, the first hole's top + CLEAR),
    then goes at rapid to the new point's R point along its axis, (20,0,0) + 2 (0.6,0,0.8)
    = (21.2, 0, 1.6), B turning to 36.87; OUT drills that hole along its axis, 5 deep to
    (17, 0, -4), and stays; IN withdraws along that axis to (21.2, 0, 1.6), then goes to
    (0, 20, 0) + 2 (0, -0.6, 0.8) = (0, 18.8, 1.6) with C at 90."""
    job = tmp_path / "outin.apt"
    job.write_text("MACHIN/GECENT,87,OPTAB,265,1\n" + OUT_IN)
    tape = tmp_path / "outin.ngc"
    result = CliRunner().invoke(main, ["post", str(job), "-o", str(tape)])
    assert result.exit_code == 0, result.output
    lines = [line.split(" ", 1)[1] for line in tape.read_text().splitlines() if line[:1] == "N"]
    assert lines[2:9] == [
        "G00 X0. Y0. Z50. B0. C0.",
        "Z2.",
        "G01 Z-5. F100.",
        "G00 Z2.",
        "X21.2 Z1.6 B36.87",
        "G01 X17. Z-4.",
        "G00 X21.2 Z1.6",
    ]
    assert lines[9] == "X0. Y18.8 C90."
    if shutil.which("rs274") is not None:  # the tape's path is the CL path, hole by hole
        verified = verify(str(tape), str(job), get_plugins(), None, 0.001)
        assert verified.passed, "\n".join(verified.report())


def test_out_on_a_new_axis_from_outside_a_hole_goes_to_its_r_point(tmp_path: Path) -> None:
    """The tool at R of a drilled hole (DRILL's way out, Z2), OUT on a tilted axis goes at
    rapid to the new hole's R point along its axis (21.2, 0, 1.6), drills 5 deep along it
    to (17, 0, -4) and stays there."""
    head = OUT_IN.split("CYCLE/OUT")[0]
    body = (
        "CYCLE/DRILL,DEPTH,5,CLEAR,2,MMPM,100\nGOTO/0,0,0,0,0,1\n"
        "CYCLE/OUT,DEPTH,5,CLEAR,2\nGOTO/20,0,0,0.6,0,0.8\nCYCLE/OFF\nFINI\n"
    )
    job = tmp_path / "out.apt"
    job.write_text("MACHIN/GECENT,87,OPTAB,265,1\n" + head + body)
    tape = tmp_path / "out.ngc"
    result = CliRunner().invoke(main, ["post", str(job), "-o", str(tape)])
    assert result.exit_code == 0, result.output
    lines = [line.split(" ", 1)[1] for line in tape.read_text().splitlines() if line[:1] == "N"]
    assert lines[-4:-1] == ["G00 Z2.", "X21.2 Z1.6 B36.87", "G01 X17. Z-4."]


@pytest.mark.parametrize(
    ("statement", "message"),
    [
        ("CYCLE/SPIRAL,1", r"CYCLE/SPIRAL is not a GECENT III cycle; the cycles are DRILL, FACE"),
        ("CYCLE/DRILL,1,ORIENT", r"CYCLE/DRILL does not take ORIENT; it takes DEPTH, STEP"),
        ("CYCLE/BORE,1,ORIENT", r"CYCLE/BORE does not take ORIENT; .*DWELL, DRAG, MANUAL"),
    ],
)
def test_a_cycle_word_outside_cyclgp_s_list_is_bad_input(statement: str, message: str) -> None:
    """CYCLGP's minor words (001 L30106-30130) are the cycles; any other is bad input."""
    with pytest.raises(InputError, match=message) as error:
        post(["FROM/0,0,5", statement])
    assert error.value.where is not None and error.value.where.line == 2


def multiaxis(options: dict[int, float] | None = None) -> MachineDefinition:
    machine = get_plugins().machine("mach40").load()
    return machine.with_options(options) if options else machine


@pytest.mark.parametrize(
    ("lines", "build", "message"),
    [
        (
            ["FROM/0,0,5", "PITCH/16", "THREAD/TURN", "FEDRAT/5", "GOTO/1,0,5"],
            lambda: get_plugins().machine("mach24").load(),
            r"THREAD on a positioning machine: .*GEPOS has no thread \(001 L38323-38380\)",
        ),
        (
            ["FROM/1,2,3,0,0.6,0.8", "PITCH/16", "THREAD/TURN", "FEDRAT/5", "GOTO/1,2,2,0,0.6,0.8"],
            multiaxis,
            r"THREAD on a multiaxis machine: .*GEMAXS \(option 116\) has no thread",
        ),
        (
            ["FROM/1,2,3,0,0.6,0.8", "SPINDL/20,SFM,CLW", "FEDRAT/5", "GOTO/1,2,2,0,0.6,0.8"],
            multiaxis,
            r"SFM on a multiaxis machine: SFMO \(GELATH\)",
        ),
        (
            ["FROM/1,2,3,0,0.6,0.8", "FEDRAT/5", "GOTO/1,2,2,0,0.6,0.8"],
            lambda: multiaxis({1: 1.0}),
            r"multiaxis motion on a positioning machine: GEMAXS's transforms",
        ),
    ],
)
def test_combinations_no_overlay_makes_are_bad_input(lines, build, message) -> None:  # type: ignore[no-untyped-def]
    """(Not yet supported until issue 22 wave 7: the manual's overlays do not make them.)"""
    with pytest.raises(InputError, match=message) as error:
        post(lines, build())
    assert error.value.where is not None and error.value.where.line == len(lines)


# -- the saddle: CODE +15 and SFM (SADDLE, 001 L36448-36512) --------------------------------


def saddle_lathe() -> MachineDefinition:
    """MACH04 with a signed saddle register R (REGFOR(16) = -32), as
    tests/test_statement_forms.py lays it over the sample lathe."""
    base = get_plugins().machine("mach04").load()
    text = '[machine]\nname = "saddle"\n[regfor]\n16 = -32.0\n[tablem]\n25 = 25\n'
    return load_machine_text(text, "test.toml", base=base)


def test_a_saddle_move_in_ipm_is_code_15_and_an_ipr_or_rapid_one_is_not() -> None:
    """CODE +15, "an auxiliary head motion having its feed command in IPM": the F stays the
    IPM given (5 IPM: F005, no feed command), with option 38's G04 as any block without a
    G; IPR (SADMOD = -1) and TRAV moves are plain non-motion blocks."""
    result = post(
        ["SELECT/HED,SADDLE,2.5,5,IPM", "SELECT/HED,SADDLE,1,0.01,IPR", "SELECT/HED,SADDLE,1,TRAV"],
        saddle_lathe(),
    )
    moved = [b for b in result.blocks if b.cells[16] is not None and b.punch]
    assert [(b.code, b.punch) for b in moved] == [
        (Code.AUX_HEAD_IPM, "N001G04F005R+0025"),
        (Code.NONMOTION, "N002G04F00001R+001"),
        (Code.NONMOTION, "N003G04M25R+001"),
    ]


def test_a_code_15_block_is_printed_on_the_listing(tmp_path: Path) -> None:
    """The printouts lay a CODE +15 block out as a non-motion one (GEOUT1 here)."""
    job = tmp_path / "saddle.apt"
    job.write_text("PARTNO SADDLE\nFROM/1,0,0\nSELECT/HED,SADDLE,2.5,5,IPM\nFINI\n")
    plugins = get_plugins()
    listing = tmp_path / "saddle.lis"
    tape_file = tmp_path / "saddle.tape"
    post_path(
        str(job),
        plugins,
        machine_override=saddle_lathe(),
        sinks=lambda m: output_sinks(plugins, m, tape_file, str(listing), None, None),
    )
    assert tape_file.read_text().splitlines()[-1] == "N003G04F005R+0025"
    assert any(line.split()[:2] == ["003", "04"] for line in listing.read_text().splitlines())


def test_a_saddle_move_under_sfm_keeps_the_speed_in_force() -> None:
    """SADDLE calls SFMO under SFM (SADSFM, 001 L36474-36478): the SFM radius is a CL
    coordinate or a fixed one, which the saddle moves neither of, so the sequence ends at
    once (a constant radius) and the move goes out at the speed in force, S unrepeated."""
    lines = tape(
        ["FROM/2,0,0", "SPINDL/100,SFM", "FEDRAT/5", "GOTO/1,0,0", "SELECT/HED,SADDLE,1,5,IPM"],
        saddle_lathe(),
    )
    assert lines[0].startswith("N002G04S660") and lines[-1] == "N005G04F005R+001"


# -- multiaxis circles: the supplementary constants D, E (001 L1830-1842) -------------------


def test_a_circle_that_turns_the_table_carries_its_supplementary_constant(tmp_path: Path) -> None:
    """tests/test_multiaxis_circle.py's W24-like arc on MACH40 given registers 16 = D and
    17 = E (format 24): the tip sweeps 6 degrees about the table's axis while the table
    (MACH40's second rotary, DBFSEG 7, letter C) turns 3, so the machine circle sweeps 3
    degrees = pi/60 rad and C turns .8333 hundredths of a revolution: E = .8333 / (pi/60)
    = 15.9149 (unsigned, as J), the rotary axis's "radius"; A does not turn, so no D."""
    end = (5 * cos(radians(6)), 5 * sin(radians(6)))
    lines = [
        "FROM/5,0,1,1,0,0",
        "FEDRAT/10",
        "CIRCLE/0,0,1,0,0,1,5",
        f"GOTO/{end[0]:.8f},{end[1]:.8f},1,{cos(radians(3)):.8f},{sin(radians(3)):.8f},0",
    ]
    registers = CIRCLES.replace("[regfor]\n", "[regfor]\n16 = 24.0\n17 = 24.0\n")
    machine = mach40_circles(registers + '[regstr]\n16 = "D"\n17 = "E"\n')
    result = run_mach40(tmp_path, lines, machine)
    assert punched(result) == [(-10, "N005G03X-02617Y-00069C+08333J5F00200E159149")]
    assert round(0.8333 / (pi / 60), 4) == 15.9149
