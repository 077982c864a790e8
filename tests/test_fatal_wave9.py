"""The last fatal errors of §5.7.1 (issue 22 wave 9), each raised where the manual raises it:

* 41, TURRET: a turret corrective move that cannot be segmented (001 L39074-39078,
  L28419-28421; core/turret.py);
* 101, MACFUN: MACF40's slide-limit test, MCHCON 2, under option 110 < 0 (001
  L28025-28118; plugins/macfuns/macf40.py), and the same test's warnings under 110 > 0;
* 8000, FUNLNK: option 132 set to no machine type by MACHIN/...,OPTAB (001 L31636-31662,
  L25946-25962; core/machine/selection.py), while a machine file stays a load error.

A fatal error is exit 1 with its number and text on stderr, the listing written with the
GEDUMP and no tape (docs/decisions.md). The manual has no worked example for these errors:
the cases are built from the routines' own tests.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.errors import FatalError
from gecent.core.families import HookPoint, HookResult
from gecent.core.macros.macfun import MacfunContext
from gecent.core.plugins import get_plugins
from gecent.core.run import Run
from gecent.plugins.macfuns import macf40

from .macros_helpers import records


def post_cli(
    tmp_path: Path, lines: list[str], machine: str | None = None
) -> tuple[int, str, Path, Path]:
    source = tmp_path / "part.apt"
    source.write_text("\n".join([*lines, "FINI"]) + "\n")
    tape, listing = tmp_path / "part.tape", tmp_path / "part.lis"
    arguments = ["post", str(source), "-o", str(tape), "--listing", str(listing)]
    if machine:
        arguments += ["--machine", machine]
    result = CliRunner().invoke(main, arguments)
    return result.exit_code, result.stderr, tape, listing


def assert_fatal(code: int, tape: Path, listing: Path, record: int) -> None:
    assert code == 1 and not tape.exists()
    dump = listing.read_text()
    assert "*** GEDUMP ***" in dump and f"CL RECORD {record} " in dump


# -- 41: TURRET ------------------------------------------------------------------------------

# MACH04 (the sample lathe) with an 8-position turret; the first tool sets the reference
TURRET_PROGRAM = [
    "FROM/0,0,0",
    "FEDRAT/10",
    "TURRET/1,1,2,3",
    "GOTO/1,1,0",
    "TURRET/2,2,2,-9000,NOW",
    "GOTO/2,1,0",
]


def test_fatal_41_a_correction_too_large_to_segment(tmp_path: Path) -> None:
    """B 3 -> -9000: a 9003-inch correction in 0.01-inch pieces (option 4) is 900,301
    segments, past the segment bound: "much too large; the turret tool offsets are
    probably wrong"."""
    program = ["MACHIN/GECENT,4,OPTAB,106,8,OPTAB,4,0.01", *TURRET_PROGRAM]
    code, err, tape, listing = post_cli(tmp_path, program)
    assert_fatal(code, tape, listing, 6)
    assert (
        "part.apt:6 (record 6): fatal error 41 (TURRET): Turret corrective move cannot be "
        "segmented; turret offsets are probably wrong: a correction of 900,301 segments"
    ) in err


def test_fatal_41_a_correction_no_g_code_covers(tmp_path: Path) -> None:
    """Option 4 = 9999 leaves the correction whole; no G code takes a 9003-inch departure
    (SELG's 138, reported as TURRET's 41)."""
    program = ["MACHIN/GECENT,4,OPTAB,106,8,OPTAB,4,9999", *TURRET_PROGRAM]
    code, err, tape, listing = post_cli(tmp_path, program)
    assert_fatal(code, tape, listing, 6)
    assert "fatal error 41 (TURRET)" in err and "no TABLEG code covers a departure" in err


def test_a_correction_that_can_be_segmented_is_not_fatal(tmp_path: Path) -> None:
    program = ["MACHIN/GECENT,4,OPTAB,106,8,OPTAB,4,1", *TURRET_PROGRAM[:4]]
    program += ["TURRET/2,2,2,-3,NOW", "GOTO/2,1,0"]
    code, err, tape, _ = post_cli(tmp_path, program)
    assert code == 0 and tape.exists()
    assert "TURRET CORRECTIVE MOVE EXCEEDED MAXIMUM DEPARTURE AND HAS BEEN SEGMENTED" in err


# -- 101: MACF40's slide limits ----------------------------------------------------------------

HEAD_RADIUS = 4.0  # option 104: R, head 1 with the small gripper


def cl_point(x: float, y: float, z: float) -> str:
    """The CL point MACH40's class 1 takes to machine slides (x, y, z) with the tool along
    Z and the table at C = 0 (machine X = -y, Y = x, Z = z + R)."""
    return f"{y:g},{-x:g},{z - HEAD_RADIUS:g}"


def post_mach40(target: tuple[float, float, float], option_110: float | None = None) -> Run:
    machine = get_plugins().machine("mach40")
    assert machine is not None
    definition = machine.load()
    if option_110 is not None:
        definition = definition.with_options({110: option_110})
    run = Run(definition, get_plugins())
    start = cl_point(0.0, 20.0, 30.0)
    text = f"PARTNO T\nFROM/{start}\nFEDRAT/10\nGOTO/{cl_point(*target)}\nFINI\n"
    run.process(iter(records(text)))
    return run


def limit_warnings(run: Run) -> list[str]:
    return [d.text for d in run.result.diagnostics if "SLIDE LIMIT" in d.text]


@pytest.mark.parametrize(
    ("target", "axis"),
    [
        ((32.0, 20.0, 30.0), "X"),  # X -19..29
        ((-20.0, 20.0, 30.0), "X"),
        ((0.0, 50.0, 30.0), "Y"),  # Y beyond 48
        ((0.0, 2.0, 15.0), "Z"),  # Y < 6: Z >= 19
        ((0.0, 10.0, 11.0), "Z"),  # 6 <= Y < 30: Z >= 11.75
        ((0.0, 40.0, 5.0), "Z"),  # 30 <= Y <= 48: Z >= 5.625
        ((0.0, 20.0, 55.0), "Z"),  # Z <= 53.625
        ((10.0, -10.0, 10.0), "Z"),  # overcenter: |Y| = 10 wants Z >= 11.75
        ((22.0, -10.0, 20.0), "X"),  # overcenter: X mirrored to -22, outside -19..29
    ],
)
def test_macf40_warns_of_its_own_limits_under_option_110_2(
    target: tuple[float, float, float], axis: str
) -> None:
    """MACH40's option 110 = 2: the comment naming the axis and no punched output."""
    run = post_mach40(target)
    assert set(limit_warnings(run)) >= {f"{axis} AXIS SLIDE LIMIT HAS BEEN EXCEEDED *** WARNING"}
    assert run.result.punch_suppressed


@pytest.mark.parametrize(
    "target",
    [
        (0.0, 20.0, 30.0),
        (29.0, 2.0, 19.0),  # the corners of the windows hold
        (-19.0, 48.0, 5.625),
        (0.0, 6.0, 53.625),
        (10.0, -10.0, 20.0),  # overcenter: X mirrored to -10, |Y| = 10, Z >= 11.75
    ],
)
def test_macf40_points_inside_its_windows_pass(target: tuple[float, float, float]) -> None:
    run = post_mach40(target)
    assert limit_warnings(run) == [] and not run.result.punch_suppressed


def test_fatal_101_under_option_110_minus_1() -> None:
    """ERROR = 101.0, CALL ERDMP1 (label 240): the first violation stops the run."""
    with pytest.raises(FatalError) as raised:
        post_mach40((32.0, 20.0, 30.0), option_110=-1.0)
    assert raised.value.number == 101 and raised.value.subroutine == "MACFUN"
    assert raised.value.detail == "MACF40: X 32 outside -19..29"
    assert raised.value.where is not None and raised.value.where.line == 4


def test_fatal_101_on_the_cli(tmp_path: Path) -> None:
    start, outside = cl_point(0.0, 20.0, 30.0), cl_point(0.0, 50.0, 30.0)
    program = ["MACHIN/GECENT,40,OPTAB,110,-1", f"FROM/{start}", "FEDRAT/10", f"GOTO/{outside}"]
    code, err, tape, listing = post_cli(tmp_path, program)
    assert_fatal(code, tape, listing, 4)
    assert (
        "part.apt:4 (record 4): fatal error 101 (MACFUN): Machine-specific limit violation: "
        "MACF40: Y 50 above 48"
    ) in err


def test_no_limit_test_under_option_110_0() -> None:
    """Label 200: option 110 = 0 is no testing, MACF40's or the standard one."""
    run = post_mach40((32.0, 50.0, 60.0), option_110=0.0)
    assert limit_warnings(run) == [] and not run.result.punch_suppressed


@pytest.mark.parametrize(
    ("head", "result"), [(0.0, HookResult.HANDLED), (1.0, HookResult.CONTINUE)]
)
def test_the_second_head_has_its_own_x_window(head: float, result: HookResult) -> None:
    """TLHEAD != 0: X -29..19 (labels 205-220); X = -25 is outside head 1's -19..29."""
    run = post_mach40((0.0, 20.0, 30.0))
    context = MacfunContext(
        HookPoint.SLIDE_LIMITS,
        run,
        machine_point=(-25.0, 20.0, 30.0),
        data={"macf40": {"TLHEAD": head}},
    )
    assert macf40.slide_limit_test(context) is result


# -- 8000: FUNLNK ----------------------------------------------------------------------------


@pytest.mark.parametrize("value", ["9", "-1", "2.5"])
def test_fatal_8000_machin_sets_option_132_to_no_machine_type(tmp_path: Path, value: str) -> None:
    code, err, tape, listing = post_cli(
        tmp_path, [f"MACHIN/GECENT,23,OPTAB,132,{value}", "FROM/0,0,0", "GOTO/1,1,0"]
    )
    assert_fatal(code, tape, listing, 1)
    assert (
        "part.apt:1 (record 1): fatal error 8000 (FUNLNK): Option 132 is set incorrectly: "
        f"MACHIN/GECENT,...,OPTAB,132,{float(value):g}: the machine types are 0..8"
    ) in err


def test_fatal_8000_at_a_later_machin(tmp_path: Path) -> None:
    program = ["MACHIN/GECENT,23", "FROM/0,0,0", "MACHIN/GECENT,23,OPTAB,132,12", "GOTO/1,1,0"]
    code, err, tape, listing = post_cli(tmp_path, program)
    assert_fatal(code, tape, listing, 3)
    assert "part.apt:3 (record 3): fatal error 8000 (FUNLNK)" in err


def test_a_machine_type_machin_may_set_is_not_fatal(tmp_path: Path) -> None:
    code, err, tape, _ = post_cli(
        tmp_path, ["MACHIN/GECENT,23,OPTAB,132,1", "FROM/0,0,0", "GOTO/1,1,0"]
    )
    assert code == 0 and tape.exists(), err


def test_a_machine_file_with_a_bad_option_132_stays_a_load_error(tmp_path: Path) -> None:
    """No run, no overlay list yet: the file is refused when it loads (exit 2)."""
    machine = tmp_path / "bad132.toml"
    machine.write_text('[machine]\nname = "bad132"\ntitle = "BAD TYPE"\n[optab]\n132 = 9.0\n')
    code, err, tape, _ = post_cli(tmp_path, ["FROM/0,0,0", "GOTO/1,1,0"], str(machine))
    assert code == 2 and not tape.exists()
    assert "bad132.toml" in err and "machine type must be 0..8" in err
    assert "fatal error 8000 (FUNLNK)" not in err  # (the rule's text names it)


def test_option_132_8_without_the_7500_control_stays_an_input_error(tmp_path: Path) -> None:
    """Type 8 has its overlays; option 1 = 3 missing is the machine's inconsistency."""
    code, err, tape, _ = post_cli(
        tmp_path, ["MACHIN/GECENT,23,OPTAB,132,8", "FROM/0,0,0", "GOTO/1,1,0"]
    )
    assert code == 2 and not tape.exists()
    assert "option 132 = 8" in err and "fatal error" not in err


@pytest.mark.parametrize(
    "point", [(-19.0, 48.0, 31.75), (-19.0, 48.0, 48.75), (-29.0, 48.0, 31.75)]
)
def test_macf40s_home_and_change_point_lie_inside_its_windows(
    point: tuple[float, float, float],
) -> None:
    """The home (FROM test) and the change point (LOAD, WE-19) are DPRESM in the frame the
    limit test reads: X at its low end for its head, Y at the top, Z below the ceiling."""
    run = post_mach40((0.0, 20.0, 30.0))
    head = 1.0 if point[0] == -29.0 else 0.0
    context = MacfunContext(
        HookPoint.SLIDE_LIMITS, run, machine_point=point, data={"macf40": {"TLHEAD": head}}
    )
    assert macf40.slide_limit_test(context) is HookResult.CONTINUE
