"""Output options of issue 22 (manual option table, 001 L25976-26388; §3.5.3, L9087-9101,
L9271-9282): printed output only (173), G01/G11 left off the tape (147), the readable
PARTNO at the head of the punched tape (20, 161, 163, 164) and the PARTNO image left off
(169), and the tape reels of the BREAK sequence (134, 135).

The manual gives no worked example for any of them: the tests post small programs."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.absent import ABSENT
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.cli import main
from gecent.core.errors import InputError
from gecent.core.machine.loader import standard_machine
from gecent.core.output.block import Block, Code
from gecent.core.output.punch import (
    identification_parity,
    read_readable,
    readable_frames,
    table,
    unpunch,
)
from gecent.core.output.reels import FRAMES_PER_FOOT, tape_reels
from gecent.core.output.sinks import CollectSink, Sinks
from gecent.core.output.tape import line_frames, tape_lines
from gecent.core.plugins import get_plugins
from gecent.core.run import PRINTED_ONLY, Run

from tests.test_post_linear import post

MOVES = ["FROM/0,0,0", "FEDRAT/10", "GOTO/1,0,0", "GOTO/1,1,0", "GOTO/1.5,1,0"]


def machine(name: str):  # type: ignore[no-untyped-def]
    return get_plugins().machine(name).load()


def posted(
    tmp_path: Path, lines: list[str], *, code: str = "eia", machine_key: str | None = None
) -> tuple[int, str, Path, Path, Path]:
    """Post through the command line: exit code, stderr, and the tape, listing and punch
    paths (which may not exist)."""
    source = tmp_path / "part.apt"
    source.write_text("\n".join([*lines, "FINI"]) + "\n")
    tape, listing, punched = tmp_path / "t.tape", tmp_path / "t.lis", tmp_path / "t.pun"
    arguments = ["post", str(source), "-o", str(tape), "--listing", str(listing)]
    arguments += ["--punch", code, str(punched)]
    if machine_key is not None:
        arguments += ["--machine", machine_key]
    result = CliRunner().invoke(main, arguments)
    return result.exit_code, result.stderr, tape, listing, punched


# -- option 173: printed output only ---------------------------------------------------------


def test_option_173_standard_is_read_as_punching() -> None:
    """The printed standard 0.0 ("printed output only") is read as 1.0: every sample
    machine, none of which sets 173, makes its tape (docs/decisions.md)."""
    assert standard_machine().number_option(173) == 1.0
    assert not post(MOVES).punch_suppressed


def test_option_173_0_writes_the_listing_and_no_tape(tmp_path: Path) -> None:
    program = ["PARTNO PRINTED ONLY", "MACHIN/GECENT,23,OPTAB,173,0", *MOVES]
    exit_code, stderr, tape, listing, punched = posted(tmp_path, program)
    assert exit_code == 0, stderr
    assert PRINTED_ONLY in stderr
    assert listing.exists() and not tape.exists() and not punched.exists()
    assert PRINTED_ONLY in listing.read_text()


def test_option_173_1_punches(tmp_path: Path) -> None:
    exit_code, stderr, tape, listing, punched = posted(
        tmp_path, ["MACHIN/GECENT,23,OPTAB,173,1", *MOVES]
    )
    assert exit_code == 0, stderr
    assert PRINTED_ONLY not in stderr
    assert tape.exists() and listing.exists() and punched.exists()


# -- option 147: G01 and G11 left off the punched tape -----------------------------------------


def test_option_147_leaves_g01_and_g11_off_the_tape_but_not_the_listing() -> None:
    """MACH23: G01 for departures to 9.9999, G11 (TABLEG(12)) for the short one."""
    mach23 = machine("mach23")
    assert tape_lines(post(MOVES, mach23).blocks) == [
        "N003G01X+01F100",
        "N004G01Y+01",
        "N005G11X+005F020",
    ]
    result = post(MOVES, mach23.with_options({147: 1.0}))
    assert tape_lines(result.blocks) == ["N003X+01F100", "N004Y+01", "N005X+005F020"]
    g_printed = [dict(block.words).get(2) for block in result.blocks if block.words]
    assert g_printed == ["01", "01", "11"]


def test_option_147_keeps_other_g_codes() -> None:
    """A dwell's G04 stays on the tape."""
    mach23 = machine("mach23").with_options({147: 1.0})
    lines = tape_lines(post([*MOVES, "DELAY/2"], mach23).blocks)
    assert lines[-1].startswith("N") and "G04" in lines[-1]


def test_option_147_general_and_fast_paths_agree() -> None:
    mach23 = machine("mach23").with_options({147: 1.0})
    program = [*MOVES, *(f"GOTO/{x},{x % 3},0" for x in range(2, 30)), "FINI"]

    def lines(fast: bool) -> list[str]:
        run = Run(mach23, fast=fast)
        return tape_lines(run.process(AptSourceReader("p.apt").read_lines(program)).blocks)

    assert lines(True) == lines(False)
    assert not any("G01" in line for line in lines(True))


def test_option_147_is_refused_on_a_modern_control() -> None:
    """A modern control leaves G00 only on a G01: the option is bad input there."""
    with pytest.raises(InputError, match="option 147 = 1"):
        post(MOVES, machine("linuxcnc-mill").with_options({147: 1.0}))


# -- the readable PARTNO and option 169 ----------------------------------------------------


def test_the_readable_partno_heads_the_punched_tape(tmp_path: Path) -> None:
    """MACH23 (options 20 = 0, 163 = 0, 164 = 1: IDPART): EOB, the letters in EIA's odd
    parity, EOB, then the tape as the tape image has it."""
    program = ["PARTNO BRACKET 12", "MACHIN/GECENT,23", *MOVES]
    exit_code, stderr, tape, _, punched = posted(tmp_path, program)
    assert exit_code == 0, stderr
    frames = punched.read_bytes()
    eob = table("eia")["EOB"]
    width = 6 * len("BRACKET 12")
    assert frames[0] == frames[width + 1] == eob
    assert frames[1 : width + 1] == readable_frames("BRACKET 12", "odd")
    assert read_readable(frames[1 : width + 1]) == "BRACKET 12"
    assert unpunch(frames, "eia", readable=True) == tape.read_text().splitlines()
    assert tape.read_text().splitlines()[0] == "BRACKET12"  # the non-readable image


def test_option_163_1_punches_no_readable_partno(tmp_path: Path) -> None:
    program = ["PARTNO BRACKET 12", "MACHIN/GECENT,23,OPTAB,163,1", *MOVES]
    exit_code, stderr, tape, _, punched = posted(tmp_path, program)
    assert exit_code == 0, stderr
    assert unpunch(punched.read_bytes(), "eia") == tape.read_text().splitlines()


def test_option_169_1_leaves_the_partno_image_off_the_tape(tmp_path: Path) -> None:
    """The PARTNO is printed, not punched; the readable PARTNO is still punched (the
    option "does not pertain to the readable PARTNO", 001 L26336)."""
    mach23 = machine("mach23").with_options({169: 1.0})
    result = post(["PARTNO LEFT OFF", *MOVES], mach23)
    assert result.blocks[0].code is Code.PPRINT and result.blocks[0].text == "LEFT OFF"
    assert tape_lines(result.blocks)[0] == "N004G01X+01F100"
    # (an option MACHIN sets applies from MACHIN on: here before the PARTNO)
    program = ["MACHIN/GECENT,23,OPTAB,169,1", "PARTNO LEFT OFF", *MOVES]
    exit_code, stderr, tape, listing, punched = posted(tmp_path, program)
    assert exit_code == 0, stderr
    assert "LEFTOFF" not in tape.read_text()
    assert "LEFT OFF" in listing.read_text()
    frames = punched.read_bytes()
    assert read_readable(frames[1 : 1 + 6 * len("LEFT OFF")]) == "LEFT OFF"
    assert unpunch(frames, "eia", readable=True) == tape.read_text().splitlines()


@pytest.mark.parametrize(
    ("options", "code", "parity"),
    [
        ({}, "eia", "odd"),  # IDPART: the tape code's own parity
        ({}, "ascii", "even"),
        ({163: 1.0}, "eia", None),
        ({164: 2.0}, "eia", None),  # IDPART is GEOUT1's only (001 L33608)
        ({20: 1.0, 164: 2.0}, "eia", "odd"),  # PARNOM
        ({20: 1.0, 161: 1.0}, "eia", "even"),  # PARNEM
        ({20: -1.0}, "eia", None),  # magnetic tape
    ],
)
def test_which_option_values_punch_the_readable_partno(
    options: dict[int, float], code: str, parity: str | None
) -> None:
    assert identification_parity(machine("mach23").with_options(options), code) == parity


def test_no_readable_partno_on_a_modern_control(tmp_path: Path) -> None:
    assert identification_parity(machine("linuxcnc-mill"), "ascii") is None
    exit_code, stderr, _, _, punched = posted(
        tmp_path, ["PARTNO MODERN", *MOVES], code="ascii", machine_key="linuxcnc-mill"
    )
    assert exit_code == 0, stderr
    assert unpunch(punched.read_bytes(), "ascii", modern=True)[0] == "%"


def test_the_footage_does_not_count_the_readable_partno(tmp_path: Path) -> None:
    """PPUNCH counts the blocks' characters; IDPART punches by PUNCHB directly."""
    with_id = posted(tmp_path, ["PARTNO FOOTAGE", "MACHIN/GECENT,23", *MOVES])[3].read_text()
    without = posted(tmp_path, ["PARTNO FOOTAGE", "MACHIN/GECENT,23,OPTAB,163,1", *MOVES])[
        3
    ].read_text()
    assert with_id == without


# -- options 134 and 135: the BREAK sequence ---------------------------------------------------


def long_program(breaks: set[int], moves: int = 60) -> list[str]:
    lines = ["PARTNO REELS", "MACHIN/GECENT,23,OPTAB,134,2,OPTAB,135,1", "FROM/0,0,0", "FEDRAT/10"]
    for i in range(1, moves):
        lines.append(f"GOTO/{i % 7 + 1},{i % 5},0")
        if i in breaks:
            lines.append("BREAK")
    return lines


def reels_of(lines: list[str]) -> list[list[str]]:
    """The tape image cut at its end-of-record marks."""
    reels: list[list[str]] = [[]]
    for line in lines:
        reels[-1].append(line)
        if line == "=":
            reels.append([])
    return reels


def test_a_break_before_the_minimum_footage_is_an_optional_stop_only(tmp_path: Path) -> None:
    exit_code, stderr, tape, _, _ = posted(tmp_path, long_program({3}, moves=8))
    assert exit_code == 0, stderr
    lines = tape.read_text().splitlines()
    assert "=" not in lines
    assert any(line.endswith("M01") for line in lines)


def test_a_break_after_the_minimum_footage_breaks_the_tape(tmp_path: Path) -> None:
    """Option 135 = 1 ft: the BREAK after the eleventh move (reel past 120 frames) gives
    the optional stop, the end-of-record mark, a foot of leader (13.4 in: two cards),
    "REEL 2" printed and, on the punch, the readable "REELS REEL 2", and leader again."""
    program = long_program({11}, moves=13)
    exit_code, stderr, tape, listing, punched = posted(tmp_path, program)
    assert exit_code == 0, stderr
    lines = tape.read_text().splitlines()
    at = lines.index("=")
    assert lines[at - 1].endswith("M01")
    assert sum(line_frames(line) for line in lines[:at]) >= FRAMES_PER_FOOT
    assert lines[at + 1 : at + 3] == ["(" * 134, "(" * 134]
    assert lines[at + 3].startswith("N")
    printed = listing.read_text().splitlines()
    mark = printed.index("TMARK")
    assert printed[mark + 1 : mark + 4] == [
        "13.4 INCHES OF LEADER HERE",
        "REEL 2",
        "13.4 INCHES OF LEADER HERE",
    ]
    frames = punched.read_bytes()
    assert unpunch(frames, "eia", readable=True) == lines
    heading = readable_frames("REELS REEL 2", "odd")
    assert frames.count(heading) == 1
    assert frames.index(heading) > frames.index(bytes([table("eia")["REWIND_STOP"]]))


def test_a_reel_never_passes_the_maximum(tmp_path: Path) -> None:
    """Option 134 = 2 ft with no BREAK: each reel is broken before the block that would
    take it past 240 frames, with a warning; the blocks all stay on the tape."""
    exit_code, stderr, tape, _, punched = posted(tmp_path, long_program(set()))
    assert exit_code == 0, stderr
    lines = tape.read_text().splitlines()
    reels = reels_of(lines)
    assert len(reels) > 3
    for number, reel in enumerate(reels[:-1]):
        # a reel: after the trailer of the one before it, up to its end-of-record mark
        on_reel = reel[:-1] if number == 0 else reel[1:-1]
        assert sum(line_frames(line) for line in on_reel) <= 2 * FRAMES_PER_FOOT
    assert stderr.count("(OPTION 134) AND NO BREAK STATEMENT BROKE IT") == len(reels) - 1
    assert "REEL 2 FOLLOWS" in stderr
    assert sum(line.startswith("N") for line in lines) == 59  # every move
    assert unpunch(punched.read_bytes(), "eia", readable=True) == lines


def test_options_134_and_135_at_0_ignore_their_part(tmp_path: Path) -> None:
    no_maximum = [line.replace("134,2", "134,0") for line in long_program({11})]
    exit_code, stderr, tape, _, _ = posted(tmp_path, no_maximum)
    assert exit_code == 0, stderr
    assert tape.read_text().splitlines().count("=") == 1  # the BREAK's alone
    no_minimum = [
        line.replace("135,1", "135,0").replace("134,2", "134,100")
        for line in long_program({11}, moves=13)
    ]
    exit_code, stderr, tape, _, _ = posted(tmp_path, no_minimum)
    assert exit_code == 0, stderr
    assert "=" not in tape.read_text().splitlines()


def test_the_standard_reel_and_a_modern_control() -> None:
    """The standard: 1100 ft at most, BREAK looked for after 900 ft (120 frames a foot);
    a modern control's program is not cut into reels."""
    reels = tape_reels(standard_machine())
    assert reels is not None
    assert (reels.maximum, reels.minimum) == (132000, 108000)
    assert tape_reels(standard_machine().with_options({134: 0.0, 135: 0.0})) is None
    assert tape_reels(machine("linuxcnc-mill")) is None


def test_a_break_without_an_optional_stop_code_still_breaks_the_tape() -> None:
    """TABLEM(2) = DMBITS: the BREAK block is disregarded (001 L9278-9280), but the tape
    is still broken: the end-of-record mark needs no stop code."""
    base = machine("mach23").with_options({134: 2.0, 135: 1.0})
    tablem = list(base.tablem)
    tablem[2] = ABSENT
    no_opstop = replace(base, tablem=tuple(tablem))
    blocks: list[Block] = []
    sinks = Sinks([CollectSink(blocks)])
    sinks.reels = tape_reels(no_opstop)
    program = long_program({11}, moves=13)[2:]  # (the options are set on the machine)
    Run(no_opstop, sinks=sinks).process(AptSourceReader("p.apt").read_lines([*program, "FINI"]))
    lines = tape_lines(blocks)
    at = lines.index("=")
    assert not any(line.endswith("M01") for line in lines)
    assert lines[at - 1].startswith("N") and lines[at + 3].startswith("N")
    assert [b.text for b in blocks if b.reel] == ["REEL 2"]


def test_a_partno_character_outside_the_font_is_fatal_error_54(tmp_path: Path) -> None:
    """IDPART's error 54 (001 L33603): a run stopped with the listing and its dump."""
    exit_code, stderr, tape, listing, punched = posted(
        tmp_path, ["PARTNO PART #4", "MACHIN/GECENT,23", *MOVES]
    )
    assert exit_code == 1
    assert "54" in stderr and "'#'" in stderr
    assert listing.exists() and not tape.exists() and not punched.exists()


def test_option_173_0_on_a_multihead_machine_keeps_the_tape_back(tmp_path: Path) -> None:
    """The manual's multihead sequencing example (COMBIN/2 on MACH51): both passes run,
    the listing is written, the tape is not."""
    sequencing = Path(__file__).parent / "data" / "multihead" / "sequencing.apt"
    program = sequencing.read_text().replace("MACHIN/GECENT,51", "MACHIN/GECENT,51,OPTAB,173,0")
    lines = program.splitlines()[:-1]  # (posted adds the FINI)
    exit_code, stderr, tape, listing, _ = posted(tmp_path, lines)
    assert exit_code == 0, stderr
    assert PRINTED_ONLY in stderr
    assert listing.exists() and not tape.exists()


def test_a_multihead_tape_has_one_readable_partno_and_is_cut_at_the_maximum(
    tmp_path: Path,
) -> None:
    """The sequencing example on MACH51 with tape-image output (option 20 = 1, PARNOM):
    the PARTNO goes to both heads, its readable form once; option 134 cuts the merged
    tape, with the warnings."""
    sequencing = Path(__file__).parent / "data" / "multihead" / "sequencing.apt"
    program = sequencing.read_text().replace(
        "MACHIN/GECENT,51", "MACHIN/GECENT,51,OPTAB,20,1,OPTAB,134,1.5,OPTAB,135,1"
    )
    exit_code, stderr, tape, _, punched = posted(tmp_path, program.splitlines()[:-1])
    assert exit_code == 0, stderr
    frames = punched.read_bytes()
    eob = bytes([table("eia")["EOB"]])
    letters = readable_frames("SEQUENCING EXAMPLE OF MANUAL 2.4.5.2", "odd")
    assert frames.count(eob + letters + eob) == 1  # (each new reel's adds " REEL n")
    assert "REEL 2 FOLLOWS" in stderr
    assert "=" in tape.read_text().splitlines()
