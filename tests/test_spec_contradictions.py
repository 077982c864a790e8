"""Outputs that contradicted the manual (issue 22, part G), each posted as the issue found
it: MACHIN/OFF and option 218 (001 L26678-26687, L33974-34011), option 112 by MACHIN
(L10945-10963), option 171's redundant S words (L26354-26368), GEOUT1's absolute columns
(ABS-A of rotary moves; W9's leading zeros, L8945-8960), end of file before FINI
(L2648-2656), SELGRO's fatal error 39 (L37106-37144), the --machine warning of a MACHIN
with OPTAB (PTONLY/2, L2553-2565), option 116 by MACHIN (L25771-25777), and option 25 < 0
(FEDLIM) held to |option 25|."""

from __future__ import annotations

import re
from dataclasses import replace
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cl.records import Statement, Word
from gecent.core.cli import main
from gecent.core.dispatch.post import post
from gecent.core.errors import FatalError, InputError
from gecent.core.machine import standard_machine
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.machine.selection import apply_machin_options, first_machin, parse_machin
from gecent.core.motion.gcode import RotaryCodes
from gecent.core.output.block import Code
from gecent.core.plugins import get_plugins
from gecent.core.state import RunResult
from gecent.plugins.printouts.layout import expanded_text

from .test_post_linear import post as post_lines


def machine(name: str) -> MachineDefinition:
    pack = get_plugins().machine(name)
    assert pack is not None
    return pack.load()


def cli(tmp_path: Path, lines: list[str], *extra: str) -> tuple[int, str, str, str]:
    """Post a program with the command line: exit code, output, tape and listing."""
    source, tape, listing = tmp_path / "p.apt", tmp_path / "p.tape", tmp_path / "p.lis"
    source.write_text("\n".join(lines) + "\n")
    done = CliRunner().invoke(
        main, ["post", str(source), "-o", str(tape), "--listing", str(listing), *extra]
    )
    read = lambda path: path.read_text() if path.exists() else ""  # noqa: E731
    return done.exit_code, done.output, read(tape), read(listing)


def run_file(tmp_path: Path, lines: list[str], override: str | None = None) -> RunResult:
    source = tmp_path / "p.apt"
    source.write_text("\n".join(lines) + "\n")
    return post(str(source), get_plugins(), machine_override=override)


def machin(*args: object) -> Statement:
    values = tuple(Word(a, None) if isinstance(a, str) else a for a in args)
    return Statement("p.apt", 2, 2, "MACHIN", 1015, values)  # type: ignore[arg-type]


# -- 2. MACHIN/OFF and option 218 --------------------------------------------------------


def test_machin_off_prints_the_totals_and_slews_a_page(tmp_path: Path) -> None:
    """Option 218 = 1: MACHIN/OFF prints the total cut and dwell times so far and the
    listing goes on on a new page; MACHIN/GECENT,23,OFF does the same after its options."""
    program = ["PARTNO OFF", "MACHIN/GECENT,23,OPTAB,218,1", "FROM/0,0,0", "FEDRAT/10"]
    program += ["GOTO/1,0,0", "MACHIN/OFF", "GOTO/2,0,0", "MACHIN/GECENT,23,OFF", "FINI"]
    code, output, tape, listing = cli(tmp_path, program)
    assert code == 0, output
    assert "MACHIN" not in output  # accepted: no warning, no refusal
    totals = re.findall(r"TOTAL CUT TIME ([\d.]+) MIN; TOTAL DWELL TIME 0.00 MIN;", listing)
    assert totals == ["0.10", "0.20"]  # 1 in, then 2 in, at 10 IPM
    assert re.findall(r"PAGE (\d+)", listing) == ["1", "2", "3"]
    first, second = listing.split("\f")[:2]
    assert "TOTAL CUT TIME 0.10" in first and "+0001.0000" in first
    assert "+0002.0000" in second and "TOTAL CUT TIME 0.20" in second
    assert "TOTAL" not in tape


def test_machin_off_without_option_218_prints_nothing(tmp_path: Path) -> None:
    program = ["PARTNO OFF", "MACHIN/GECENT,23", "FROM/0,0,0", "FEDRAT/10", "GOTO/1,0,0"]
    code, output, _, listing = cli(tmp_path, [*program, "MACHIN/OFF", "GOTO/2,0,0", "FINI"])
    assert code == 0 and "MACHIN" not in output
    assert "TOTAL" not in listing and re.findall(r"PAGE (\d+)", listing) == ["1"]


def test_machin_off_chooses_no_machine() -> None:
    """The first pass reads past MACHIN/OFF to the MACHIN/GECENT that names the machine,
    without calling it another postprocessor's."""
    request, notes = first_machin([machin("OFF"), machin("GECENT", 23, "OFF")])
    assert request is not None and request.number == 23 and request.off
    assert notes == []


# -- 3. option 112 by MACHIN ---------------------------------------------------------------


def test_option_112_the_part_radius_is_changed_by_machin() -> None:
    """§4.1.1.1: "the radius can be changed by the MACHIN statement as MACHIN/GECENT, n,
    OPTAB, 112, r" (001 L10959-10961), though §5.6.5 lists 112 as non-reassignable."""
    request = parse_machin(machin("GECENT", 23, "OPTAB", 112, 10, 113, 1))
    assert request is not None
    changed, notes = apply_machin_options(machine("mach23"), request)
    assert changed.number_option(112) == 10.0
    assert [n.text for n in notes] == [
        "OPTION 113 (min_table_feedrate) CANNOT BE CHANGED BY MACHIN; VALUE IGNORED"
    ]


# -- 4. option 171: redundant S words --------------------------------------------------------


LATHE_SPINDLE = ["FROM/0,0,0", "SPINDL/300", "FEDRAT/10", "GOTO/0,0,1", "SPINDL/300"]
LATHE_SPINDLE += ["GOTO/0,0,2", "SPINDL/300,CCLW", "GOTO/0,0,3"]


def test_option_171_drops_redundant_s_words() -> None:
    """MACH04 (S630 for 300 RPM): with option 171 = 1 a SPINDL at the speed the control
    holds outputs no S (and no block when nothing else is in it); the reversal outputs only
    its M. With the standard 0 the S is output again."""
    lathe = machine("mach04")
    dropped = post_lines(LATHE_SPINDLE, lathe.with_options({171: 1.0}))
    kept = post_lines(LATHE_SPINDLE, lathe)
    speeds = lambda r: [b.record for b in r.blocks if b.cells[12] == 630.0]  # noqa: E731
    assert speeds(kept) == [2, 5, 7]
    assert speeds(dropped) == [2]
    reversal = [b for b in dropped.blocks if b.record == 7 and b.code is Code.NONMOTION]
    assert [float(b.cells[14]) for b in reversal] == [63.0]  # type: ignore[arg-type]
    assert not [b for b in dropped.blocks if b.record == 5]


def test_option_171_outputs_s_again_after_a_spindle_off_by_s0() -> None:
    """Option 127 = 1 stops the spindle with S0: the next S is not redundant."""
    lathe = machine("mach04").with_options({171: 1.0, 127: 1.0})
    result = post_lines(["SPINDL/300", "SPINDL/OFF", "SPINDL/300"], lathe)
    assert [b.cells[12] for b in result.blocks if b.code is Code.NONMOTION] == [630.0, 0.0, 630.0]


# -- 5. and 7. GEOUT1's absolute columns -------------------------------------------------


def test_w9_absolute_values_keep_their_leading_zeros() -> None:
    """W9 (001 L8945-8960): REGFOR(3) = -24, from 892.3456 by 95.6789, 10.0010, 90.1111."""
    assert expanded_text(892.3456, 4) == "+0892.3456"
    text = load_machine_text(
        '[machine]\nname = "w9"\ntitle = "W9"\n[regfor]\n3 = -24.0\n'
        "[tableg]\n11 = 10\n[optab]\n4 = 999.9999\n",
        "w9.toml",
    )
    program = ["FROM/892.3456,0,0", "FEDRAT/10", "GOTO/988.0245,0,0", "GOTO/998.0255,0,0"]
    result = post_lines([*program, "GOTO/1088.1366,0,0"], text)
    listing = get_plugins().get("printouts", 1).render(text, result.blocks, "W9")
    rows = [line for line in listing.splitlines() if line.startswith(("FROM", "  00"))]
    absolute_x = [re.findall(r"[+-]\d{4}\.\d{4}", row)[0] for row in rows]
    assert absolute_x == ["+0892.3456", "+0988.0245", "+0998.0255", "+1088.1366"]


def test_the_abs_a_column_follows_the_rotary_table(tmp_path: Path) -> None:
    """MACH23 has an A register: ROTATE/TABLE,INCR,90 and 45 print A at 90 and 135
    degrees (the 90 in three blocks of .0833/.0834/.0833 revolution), and the linear move
    after them keeps 135; the linear axes stay at the point reached."""
    program = ["PARTNO ROT", "MACHIN/GECENT,23", "FROM/0,0,0", "FEDRAT/10", "GOTO/1,1,0"]
    program += ["ROTATE/TABLE,INCR,90", "ROTATE/TABLE,INCR,45", "GOTO/2,2,0", "FINI"]
    code, output, _, listing = cli(tmp_path, program)
    assert code == 0, output
    lines = [line for line in listing.splitlines() if re.match(r"  00[5-8] ", line)]
    assert [line.split()[-1] for line in lines] == [
        "+0000.000000",
        "+0029.988000",
        "+0060.012000",
        "+0090.000000",
        "+0112.500000",
        "+0135.000000",
        "+0135.000000",
    ]
    assert all("+0001.0000 +0001.0000 +0000.0000" in line for line in lines[:-1])


# -- 6. end of file before FINI ------------------------------------------------------------


def test_a_gecent_file_without_fini_is_cut_short(tmp_path: Path) -> None:
    """ "EOF counts as an error" (001 L2648-2656) for a file written for GECENT."""
    with pytest.raises(InputError, match="ends without FINI") as error:
        run_file(tmp_path, ["PARTNO T", "MACHIN/GECENT,23", "FEDRAT/10", "GOTO/1,0,0"])
    assert error.value.where is not None and error.value.where.line == 4
    code, output, tape, _ = cli(tmp_path, ["PARTNO T", "MACHIN/GECENT,23", "GOTO/1,0,0"])
    assert code == 2 and "ends without FINI" in output and tape == ""


def test_a_cam_file_without_fini_still_posts(tmp_path: Path) -> None:
    """A CAM file names no GECENT machine (NX ends with END-OF-PATH): it ends as at FINI."""
    result = run_file(tmp_path, ["PARTNO T", "FEDRAT/10", "GOTO/1,0,0"])
    assert any("NO FINI" in d.text for d in result.diagnostics)
    assert result.blocks[-1].code is Code.FINI


# -- 8. SELGRO's fatal error ---------------------------------------------------------------


def test_selgro_without_a_code_for_the_turn_is_fatal_39() -> None:
    """SELGRO's one diagnostic is ERROR 39 (001 L37106-37144); 138 is SELG's (L36925)."""
    only_g11 = load_machine_text(
        '[machine]\nname = "r"\ntitle = "R"\n[tableg]\n2 = "absent"\n11 = "absent"\n'
        '12 = "absent"\n13 = 11\n',
        "r.toml",
    )
    with pytest.raises(FatalError) as error:
        RotaryCodes(only_g11, 36.0).select(5.0)
    assert error.value.number == 39 and "SELGRO" in str(error.value)


# -- 9. the --machine warning of a MACHIN with OPTAB ----------------------------------------


def test_a_machin_for_another_machine_still_changes_options(tmp_path: Path) -> None:
    """PTONLY/2 "will recognize all of the MACHIN statements for changes to the option
    table" (001 L2563-2565): under --machine only the number is ignored, and said so."""
    program = ["PARTNO W", "MACHIN/GECENT,23,OPTAB,218,1", "FROM/0,0,0", "FINI"]
    result = run_file(tmp_path, program, override="4")
    assert result.machine.number == 4 and result.machine.number_option(218) == 1.0
    assert [d.text for d in result.diagnostics] == [
        "MACHIN/GECENT,23: THE RUN USES MACHINE 4 (mach04); ONLY THE MACHINE NUMBER IS "
        "IGNORED, ITS OPTAB CHANGES APPLY"
    ]


# -- 10. option 116 by MACHIN ---------------------------------------------------------------


def test_a_transform_class_cannot_make_a_three_axis_machine_multiaxis(tmp_path: Path) -> None:
    """MACH23 (a three-axis mill): OPTAB,116,1 is refused with a warning naming option 116
    and the program goes on three-axis; it used to be applied to the machine and then
    ignored by the fast path."""
    program = ["PARTNO C", "MACHIN/GECENT,23,OPTAB,116,1", "FROM/0,0,0", "FEDRAT/10"]
    result = run_file(tmp_path, [*program, "GOTO/1,1,0", "GOTO/2,2,1", "FINI"])
    assert result.machine.number_option(116) == 0.0 and not result.machine.multiaxis
    assert [d.text for d in result.diagnostics] == [
        "OPTION 116 = 1 (TRANSFORM CLASS) CANNOT MAKE A THREE-AXIS MACHINE MULTIAXIS "
        "(MACHINE 23 (mach23)); VALUE IGNORED"
    ]


def test_a_multiaxis_machine_may_change_its_class_but_not_drop_it() -> None:
    mill = machine("mach40")
    request = parse_machin(machin("GECENT", 40, "OPTAB", 116, 2))
    assert request is not None
    changed, notes = apply_machin_options(mill, request)
    assert changed.number_option(116) == 2.0 and notes == []
    request = parse_machin(machin("GECENT", 40, "OPTAB", 116, 0))
    assert request is not None
    changed, notes = apply_machin_options(mill, request)
    assert changed.number_option(116) == mill.number_option(116)
    assert "CANNOT MAKE A MULTIAXIS MACHINE THREE-AXIS" in notes[0].text


# -- option 25 < 0: no negative feed (regression) --------------------------------------------


def test_a_negative_option_25_holds_the_feed_to_its_size() -> None:
    """Option 25 = -300 (FEDLIM): FEDRAT/500 is held to 300 IPM, never "-300 IPM USED"."""
    base = standard_machine().with_options({25: -300.0, 18: 1.0, 174: 6.0})
    limits = replace(base, feed_ranges=((0.0, 1000.0), (0.0, 1000.0), (0.0, 1000.0)))
    result = post_lines(["FROM/0,0,0", "FEDRAT/500", "GOTO/3,4,0"], limits)
    moves = [b for b in result.blocks if b.code is Code.LINEAR]
    assert float(moves[0].cells[19]) == pytest.approx(300.0)  # type: ignore[arg-type]
    assert [d.text for d in result.diagnostics] == [
        "FEEDRATE 500 IPM IS OUTSIDE THE MACHINE RANGE 1-300; 300 IPM USED"
    ]


def test_a_positioning_feed_command_is_held_to_option_24(tmp_path: Path) -> None:
    """POSFED's only test (001 L11214-11216, spec 05 §4): MACH24's feed type 0 makes
    F = 2 x 80 = 160, above option 24's 99: the command is held to 99 and the feed made
    follows it (49.5 IPM), with a warning; it used to stop the run with "F160 does not fit
    register format"."""
    lines = ["MACHIN/GECENT,24,OPTAB,25,100", "FROM/0,0,0", "FEDRAT/80", "GOTO/1,1,0", "FINI"]
    code, output, tape, listing = cli(tmp_path, lines)
    assert code == 0, output
    assert "N004G80X+010000Y-010000F99" in tape
    assert "FEEDRATE COMMAND 160 ABOVE THE MAXIMUM (OPTION 24); 99 USED" in output
    assert "FEEDRATE COMMAND 160 ABOVE THE MAXIMUM (OPTION 24); 99 USED" in listing
