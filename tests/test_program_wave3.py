"""Program-level gaps (issue 22): MACHIN/...,PLAN (GEPLAD, 001 L473-476), the PTONLY/2 run of
a saved CL tape (§3.1.1.1.1, 001 L2538-2565, worked example W14), option 38 = -1 and +2
(001 L24890-24907) and the readable PARTNO punched as hole-pattern letters (options 20,
161, 163, fatal 54; 001 L9087-9098, L26262-26287, L30452-30489, L33577-33610)."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cl.records import Statement, Word
from gecent.core.cli import main
from gecent.core.dispatch.post import post
from gecent.core.errors import FatalError, InputError
from gecent.core.machine.selection import apply_machin_options, parse_machin, ptonly_deck
from gecent.core.output.punch import (
    GLYPHS,
    Puncher,
    read_readable,
    readable_frames,
    readable_parity,
    table,
    unpunch,
)
from gecent.core.plugins import get_plugins

from tests.test_positioning import mach24
from tests.test_positioning import tape as mach24_tape


def machin(*args: object) -> Statement:
    values = tuple(Word(a, None) if isinstance(a, str) else a for a in args)
    return Statement("p.apt", 2, 2, "MACHIN", 1015, values)  # type: ignore[arg-type]


def machine(name: str):  # type: ignore[no-untyped-def]
    return get_plugins().machine(name).load()


# -- MACHIN/...,PLAN -------------------------------------------------------------------------


def test_plan_on_a_contouring_machine_is_ignored_and_said_so(tmp_path: Path) -> None:
    """GEPLAD is called only "if the modifier PLAN is given ... and option 1 is + 1"
    (001 L473-476): MACH23 (option 1 = 0) posts as without PLAN, with the warning."""
    source = tmp_path / "plan.apt"
    lines = ["PARTNO P", "MACHIN/GECENT,23,PLAN", "FROM/0,0,0", "FEDRAT/10", "GOTO/1,0,0"]
    source.write_text("\n".join([*lines, "FINI"]) + "\n")
    result = post(str(source), get_plugins())
    assert [d.text for d in result.diagnostics] == [
        "MACHIN/GECENT,...,PLAN IGNORED: OPTION 1 = 0, NOT +1; GEPLAD PLANS ONLY FOR "
        "POSITIONING MACHINES"
    ]
    assert result.diagnostics[0].where is not None and result.diagnostics[0].where.line == 2


def test_plan_on_a_positioning_machine_is_planned_before_the_run() -> None:
    """(Not yet supported until wave 7 built GEPLAD, core/plan.py, tests/test_geplad.py: the
    run meets a PLAN the pre-pass did not take, and says it is ignored there.)"""
    request = parse_machin(machin("GECENT", 24, "PLAN"))
    assert request is not None
    _, notes = apply_machin_options(machine("mach24"), request)
    assert notes[0].text.startswith("MACHIN/GECENT,...,PLAN IGNORED HERE: GEPLAD PLANS")
    assert notes[0].where is not None and notes[0].where.line == 2


# -- PTONLY/2 --------------------------------------------------------------------------------

SAVED = ["PARTNO W14", "MACHIN/GECENT,23,OPTAB,218,1", "FROM/0,0,0", "FEDRAT/10", "GOTO/1,0,0"]


def _post(tmp_path: Path, *args: str) -> tuple[int, str, str]:
    tape = tmp_path / "out.tape"
    result = CliRunner().invoke(main, ["post", *args, "-o", str(tape), "--listing", "/dev/null"])
    return result.exit_code, tape.read_text() if tape.exists() else "", result.output


def test_w14_ptonly_2_reruns_a_saved_tape_on_the_deck_machine(tmp_path: Path) -> None:
    """W14 (001 L2538-2565): the deck PTONLY/2, MACHIN/GECENT, 4, FINI posts a CL tape saved
    from a run for MACH23 on MACH04; the tape's MACHIN chooses nothing but its OPTAB
    applies. The saved tape is binary (apt4), as APT saved it; the same tape by --machine
    4 gives the same blocks."""
    (tmp_path / "saved.apt").write_text("\n".join([*SAVED, "FINI"]) + "\n")
    made = CliRunner().invoke(
        main,
        ["cl", str(tmp_path / "saved.apt"), "--to", "apt4", "-o", str(tmp_path / "saved.cl")],
    )
    assert made.exit_code == 0, made.output
    deck = tmp_path / "deck.apt"
    deck.write_text("PTONLY/2\nMACHIN/GECENT, 4\nFINI\n")
    status, tape, output = _post(tmp_path, str(tmp_path / "saved.cl"), "--ptonly", str(deck))
    assert status == 0, output
    assert tape == "W14\nN005G01Z+1F100\n"  # MACH04, a lathe: X of the CL is its Z
    assert "THE RUN USES MACHINE 4 (mach04); ONLY THE MACHINE NUMBER IS IGNORED" in output
    by_machine = _post(tmp_path, str(tmp_path / "saved.cl"), "--machine", "4")
    assert by_machine[:2] == (0, tape)


def test_the_deck_names_the_machine_only(tmp_path: Path) -> None:
    """IPOSTP holds the postprocessor and machine number (001 L2456-2521): another
    postprocessor's MACHIN is passed over (W13's BRACK), OPTAB on the deck is ignored."""
    deck = tmp_path / "deck.apt"
    deck.write_text("PTONLY/2\nMACHIN/BRACK,10\nMACHIN/GECENT,24,OPTAB,38,1\nFINI\n")
    from gecent.core.cl.apt_source import read_apt_source

    number, notes = ptonly_deck(read_apt_source(str(deck)))
    assert number == 24
    assert [n.text for n in notes] == [
        "MACHIN/BRACK names another postprocessor; ignored",
        "PTONLY/2: THE DECK'S MACHIN GIVES THE MACHINE NUMBER ONLY; ITS OPTAB AND "
        "MODIFIERS ARE IGNORED (THE TAPE'S MACHIN STATEMENTS CHANGE THE OPTIONS)",
    ]


@pytest.mark.parametrize(
    ("deck", "message"),
    [
        ("PTONLY/1\nMACHIN/GECENT,4\nFINI\n", "only PTONLY/2"),
        ("MACHIN/GECENT,4\nFINI\n", "must begin with PTONLY/2"),
        ("PTONLY/2\nMACHIN/GECENT,4\nMACHIN/GECENT,23\nFINI\n", "once per machine"),
        ("PTONLY/2\nGOTO/1,2,3\nFINI\n", "PTONLY/2, MACHIN and FINI only"),
    ],
)
def test_a_bad_deck_is_bad_input(tmp_path: Path, deck: str, message: str) -> None:
    (tmp_path / "deck.apt").write_text(deck)
    (tmp_path / "saved.apt").write_text("\n".join([*SAVED, "FINI"]) + "\n")
    status, _, output = _post(
        tmp_path, str(tmp_path / "saved.apt"), "--ptonly", str(tmp_path / "deck.apt")
    )
    assert status == 2 and message in output


def test_ptonly_and_machine_together_are_refused(tmp_path: Path) -> None:
    (tmp_path / "deck.apt").write_text("PTONLY/2\nMACHIN/GECENT,4\nFINI\n")
    (tmp_path / "saved.apt").write_text("\n".join([*SAVED, "FINI"]) + "\n")
    status, tape, output = _post(
        tmp_path,
        str(tmp_path / "saved.apt"),
        "--ptonly",
        str(tmp_path / "deck.apt"),
        "--machine",
        "23",
    )
    assert status == 2 and tape == "" and "not both" in output


def test_a_deck_without_a_number_leaves_the_tape_its_machine() -> None:
    deck = [Statement("d", 1, 1, "PTONLY", None, (2.0,)), machin("GECENT")]
    assert ptonly_deck(deck) == (None, [])
    with pytest.raises(InputError, match="must begin"):
        ptonly_deck([])


# -- option 38 = -1 and +2 -------------------------------------------------------------------

PROGRAM = [
    "FROM/0,0,5",
    "AUXFUN/13",
    "CYCLE/DRILL,DEPTH,0.6,IPM,6,CLEAR,0.1",
    "GOTO/1,1,0",
    "AUXFUN/13",
    "GOTO/3,1,0",
    "CYCLE/OFF",
    "GOTO/0,0,5",
    "AUXFUN/13",
    "DELAY/2",
]


def test_option_38_minus_1_fills_with_the_current_cycle_g() -> None:
    """MACH24: before any cycle the control's cycle is off (TABLEG(1) = G80); under DRILL
    the M13 block gets G81; after CYCLE/OFF's G80 block it gets G80 again; +1 gives every
    such block TABLEG(5) = G04. A dwell keeps its own G04."""
    minus = mach24_tape(PROGRAM, mach24("[optab]\n38 = -1.0\n"))
    plus = mach24_tape(PROGRAM, mach24("[optab]\n38 = 1.0\n"))
    assert [line for line in minus if "M13" in line] == ["N002G80M13", "N005G81M13", "N009G80M13"]
    assert [line for line in plus if "M13" in line] == ["N002G04M13", "N005G04M13", "N009G04M13"]
    assert minus[-1] == plus[-1] == "N010G04X+002000"
    # no suppression under -1: each hole repeats G81
    assert minus[2:5] == ["N004G81X+010000Y-010000", "N005G81M13", "N006G81X+030000"]


def test_option_38_minus_1_without_cycle_codes_is_tableg_5() -> None:
    """MACH23 has no cycle codes (TABLEG(1) empty): the fill stays TABLEG(5)."""
    from tests.test_auxiliary import tape

    contour = machine("mach23").with_options({38: -1.0})
    assert tape(["OPSTOP"], contour) == ["N001G04M01"]


def test_option_38_plus_2_suppresses_redundant_g_in_motion_blocks() -> None:
    """+2 suppresses G in motion blocks only; it used to suppress nothing. The M13 blocks
    get no G (no fill under +2)."""
    two = mach24_tape(PROGRAM, mach24("[optab]\n38 = 2.0\n"))
    zero = mach24_tape(PROGRAM, mach24("[optab]\n38 = 0.0\n"))
    assert two == zero
    assert two[2:5] == ["N004X+010000Y-010000", "N005M13", "N006X+030000"]


# -- the readable PARTNO ---------------------------------------------------------------------


def rows(frames: bytes) -> list[str]:
    """Channels 8 (top line) to 1 as dots, one column per frame."""
    return ["".join("o" if f >> (c - 1) & 1 else "." for f in frames) for c in range(8, 0, -1)]


def test_letters_are_five_frames_wide_and_seven_channels_high() -> None:
    """ "HE" with odd parity: H's columns hold 7, 1, 1, 1, 7 dots, all odd; E's 7, 3, 3, 3, 2
    dots, so its last column takes channel 8; a blank frame follows each letter."""
    assert rows(readable_frames("HE", "odd")) == [
        "..........o.",
        "o...o.ooooo.",
        "o...o.o.....",
        "o...o.o.....",
        "ooooo.oooo..",
        "o...o.o.....",
        "o...o.o.....",
        "o...o.ooooo.",
    ]
    even = readable_frames("HE", "even")
    assert all(bin(frame).count("1") % 2 == 0 for frame in even)
    odd = readable_frames("HE", "odd")
    assert all(bin(frame).count("1") % 2 == 1 for frame in odd if frame)


def test_every_letter_reads_back_and_is_never_an_end_of_block() -> None:
    text = "".join(GLYPHS).replace(" ", "")  # (a blank at either end is dropped)
    for parity in ("odd", "even"):
        frames = readable_frames(text, parity)
        assert len(frames) == 6 * len(text)
        assert read_readable(frames) == text
        for code in ("eia", "ascii"):
            assert table(code)["EOB"] not in frames


def test_readable_partno_is_bracketed_by_end_of_block_codes() -> None:
    """DOLLAR (001 L30452-30489): EOB, the letters, EOB; a tape reader passes it over and
    the blocks after it read as before."""
    puncher = Puncher("eia")
    tape = puncher.readable_partno("part 7", "odd") + puncher.frames_of("N001G01X+1")
    assert tape[0] == tape[6 * 6 + 1] == table("eia")["EOB"]
    assert read_readable(tape[1 : 6 * 6 + 1]) == "PART 7"
    assert unpunch(tape, "eia", readable=True) == ["N001G01X+1"]
    with pytest.raises(ValueError):
        unpunch(tape, "eia")


def test_a_character_outside_the_font_is_fatal_error_54() -> None:
    with pytest.raises(FatalError) as caught:
        readable_frames("PART #4", "odd")
    assert caught.value.number == 54 and "'#'" in str(caught.value)


def test_options_20_161_163_choose_the_readable_form() -> None:
    base = machine("mach23")
    assert readable_parity(base, "eia") == "odd"  # option 20 = 0, 163 = 0: IDPART
    assert readable_parity(base, "ascii") == "even"
    assert readable_parity(base.with_options({163: 1.0}), "eia") is None
    assert readable_parity(base.with_options({20: 1.0}), "ascii") == "odd"  # PARNOM
    assert readable_parity(base.with_options({20: 1.0, 161: 1.0}), "eia") == "even"  # PARNEM
    assert readable_parity(base.with_options({20: -1.0}), "eia") is None  # magnetic tape
