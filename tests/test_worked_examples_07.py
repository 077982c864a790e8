"""Worked examples of spec 07 (machine definition, manual §5.5-§5.6) as golden tests:
WE-4 (REGSTR/REGFOR example tables), WE-6 (option 13 tape read time), WE-9 (slide limits of
the engine lathe), WE-10 (option 99), WE-12 (option 141 rotary table feeds), WE-14 (IORDER),
WE-16 (customer options) and WE-20 (information blocks).

WE-11 and WE-19 are in tests/test_tools_manual.py and tests/test_statements_handling.py,
WE-18 in tests/test_macfun_engine.py, WE-1 in tests/test_machin.py, WE-13, WE-15 and WE-17
in tests/test_sample_machines.py, WE-21 in tests/test_catalogue.py.
"""

from __future__ import annotations

import math

import pytest
from gecent.core.absent import ABSENT
from gecent.core.cl.records import Statement, Word
from gecent.core.feed.positioning import FeedContext
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.machine.selection import apply_machin_options, parse_machin, resolve_machine
from gecent.core.output.block import Block, Code
from gecent.core.output.tape import tape_lines
from gecent.core.output.words import WordFormatter
from gecent.core.plugins import get_plugins
from gecent.plugins.feedtypes.rotary1 import GeometricRotaryFeed, rotary_feeds

from tests.test_post_linear import post

# -- WE-4: the REGSTR/REGFOR example tables (001 L24088-24197) --------------------------------

# Example 1: registers N G X Y Z F S T M R (001 L24088-24126), the full table as printed
EXAMPLE_1 = """
[machine]
name = "regfor-example-1"
[regstr]
6 = ""
7 = ""
8 = ""
9 = ""
10 = ""
17 = ""
18 = ""
[regfor]
1 = 30.0
2 = 20.0
3 = -24.0
4 = -24.0
5 = -24.0
6 = 0.0
7 = 0.0
8 = 0.0
9 = 0.0
10 = 0.0
11 = 21.0
12 = 20.0
13 = 10.0
14 = 20.0
16 = -22.0
17 = 0.0
18 = 0.0
[optab]
26 = 1.0  # no I, J, K: no feedrate-number multiplier constant (option 26, 001 L24697-24721)
"""

# Example 2: registers N G X Z I K F S T M W H (001 L24127-24166), the full table. M is
# printed 26.0 (L24159); read as 20.0, the standard, which the manual's own "better way"
# list (L24167-24197) leaves unchanged (docs/decisions.md).
EXAMPLE_2 = """
[machine]
name = "regfor-example-2"
[regstr]
4 = ""
6 = ""
7 = ""
9 = ""
16 = "W"
17 = "H"
18 = ""
[regfor]
1 = 30.0
2 = 20.0
3 = -24.0
4 = 0.0
5 = -24.0
6 = 0.0
7 = 0.0
8 = 24.0
9 = 0.0
10 = 24.0
11 = 31.0
12 = 20.0
13 = 10.0
14 = 20.0
16 = -14.0
17 = 10.0
18 = 0.0
"""

# The manual's "better way" for Example 2: only the deviations from the Standard Machine
# (L24167-24197), with two corrections: REGFOR(5) is printed 24.0 where the full table has
# -24.0, and REGFOR(13) = 10.0 (T), in the full table, is missing from the list.
EXAMPLE_2_DEVIATIONS = """
[machine]
name = "regfor-example-2-deviations"
[regstr]
16 = "W"
17 = "H"
[regfor]
3 = -24.0
4 = 0.0
5 = -24.0
8 = 24.0
9 = 0.0
10 = 24.0
11 = 31.0
12 = 20.0
13 = 10.0
16 = -14.0
17 = 10.0
"""


def _letters_and_formats(machine: MachineDefinition) -> list[tuple[str, float]]:
    registers = machine.registers
    present = registers.present()
    formats = [registers.formats[k] for k in present]
    return [(registers.letters[k], f.regfor) for k, f in zip(present, formats, strict=True) if f]


def test_we4_example_1_registers_ngxyzfstmr() -> None:
    machine = load_machine_text(EXAMPLE_1)
    assert _letters_and_formats(machine) == [
        ("N", 30.0),
        ("G", 20.0),
        ("X", -24.0),
        ("Y", -24.0),
        ("Z", -24.0),
        ("F", 21.0),
        ("S", 20.0),
        ("T", 10.0),
        ("M", 20.0),
        ("R", -22.0),
    ]


def test_we4_example_2_registers_ngxzikfstmwh() -> None:
    machine = load_machine_text(EXAMPLE_2)
    assert _letters_and_formats(machine) == [
        ("N", 30.0),
        ("G", 20.0),
        ("X", -24.0),
        ("Z", -24.0),
        ("I", 24.0),
        ("K", 24.0),
        ("F", 31.0),
        ("S", 20.0),
        ("T", 10.0),
        ("M", 20.0),
        ("W", -14.0),
        ("H", 10.0),
    ]
    x_format = machine.registers.formats[3]
    assert x_format is not None
    assert (x_format.signed, x_format.left, x_format.right) == (True, 2, 4)


def test_we4_example_2_the_better_way_gives_the_same_registers() -> None:
    """Only REGFOR = 0 switches a register off: the deviation list leaves the letters Y, J,
    A, B (REGSTR 4, 9, 6, 7) in place and still gives Example 2's registers."""
    full = load_machine_text(EXAMPLE_2).registers
    deviations = load_machine_text(EXAMPLE_2_DEVIATIONS).registers
    assert deviations.letters[4] == "Y" and deviations.formats[4] is None
    assert deviations.present() == full.present()
    assert [deviations.letters[k] for k in full.present()] == list("NGXZIKFSTMWH")
    assert deviations.regfor[1:19] == full.regfor[1:19]


def test_we4_example_2_posts_x_and_z_in_format_24() -> None:
    """A 1.5-inch X, 0.25-inch Z move: signed, two whole digits and four decimals (trailing
    zeros dropped); FRN = 10 x 10 / 1.5207 = 65.76 in format 31."""
    lines = tape_lines(
        post(["FROM/0,0,0", "FEDRAT/10", "GOTO/1.5,0,.25"], load_machine_text(EXAMPLE_2)).blocks
    )
    assert lines == ["N003G01X+015Z+0025F0658"]


# -- WE-6: option 13, the tape reader's time for a longest block (001 L24515-24541) ----------

# TRS (characters per second) -> minutes, as printed; 62.5 gives the standard 0.012
READ_TIMES = [(62.5, 0.012), (100, 0.0075), (300, 0.0025), (400, 0.001875), (500, 0.0015),
              (1200, 0.000625)]  # fmt: skip

# F in format 50 and option 45 out of the way, so that the FRN shows the reader's limit;
# rapid at 1000 IPM (option 42), faster than a 0.5-inch move read in 0.000625 min (800 IPM)
READER_MACHINE = """
[machine]
name = "tape-reader"
[regfor]
11 = 50.0
[optab]
42 = 1000.0
45 = 99999.0
"""


@pytest.mark.parametrize(("speed", "minutes"), READ_TIMES)
def test_we6_a_short_rapid_waits_for_the_tape_reader(speed: float, minutes: float) -> None:
    """The relation C(MAX)/(60 TRS) with C(MAX) = 45 gives the manual's table; with option
    13 at the table's value a 0.5-inch rapid move takes exactly the read time: its FRN is
    10 / t (GDIMUL 10 for the 1-inch band)."""
    assert 45.0 / (60.0 * speed) == pytest.approx(minutes, rel=1e-12)
    machine = load_machine_text(READER_MACHINE).with_options({13: minutes})
    result = post(["FROM/0,0,0", "FEDRAT/10", "GOTO/1,0,0", "RAPID", "GOTO/1.5,0,0"], machine)
    (rapid,) = [b for b in result.blocks if b.rapid]
    assert rapid.cut_minutes == pytest.approx(minutes, rel=1e-9)
    assert rapid.punch == f"N005X+05F{round(10.0 / minutes):05d}"


def test_we6_the_standard_machine_reads_at_62_5_characters_a_second() -> None:
    assert standard_machine().number_option(13) == pytest.approx(45.0 / (60.0 * 62.5))


# -- WE-9: slide limits of an engine lathe (001 L25843-25861) --------------------------------


def _engine_lathe() -> MachineDefinition:
    """MACH04 (option 59 = +Z-X) with the manual's limits: 20-inch Z from CL X, the 10-inch
    cross slide from CL Y with option 59's minus sign: -8 .. 0; CL Z untested (0, 0)."""
    pack = get_plugins().machine("mach04")
    assert pack is not None
    machine = pack.load()
    assert machine.number_option(59) == 152300.0
    limits = {121: 20.0, 122: 0.0, 123: 0.0, 124: -8.0, 125: 0.0, 126: 0.0}
    return machine.with_options({110: 1.0, **limits})


@pytest.mark.parametrize(
    ("point", "warned"),
    [
        ("20,8,0", []),  # both corners of the first quadrant's window
        ("20.01,8,0", ["X"]),
        ("20,8.01,0", ["Y"]),  # -8.01 below option 124
        ("5,-0.01,0", ["Y"]),  # +0.01 above option 123: Y is signed by option 59
        ("-0.01,1,0", ["X"]),
        ("1,1,-30", []),  # Z: 0/0 is an axis without limits
    ],
)
def test_we9_engine_lathe_limits_in_cl_order(point: str, warned: list[str]) -> None:
    result = post(["FROM/0,0,0", "FEDRAT/10", f"GOTO/{point}"], _engine_lathe())
    texts = [d.text for d in result.diagnostics if "SLIDE LIMIT" in d.text]
    assert texts == [f"{axis} AXIS SLIDE LIMIT HAS BEEN EXCEEDED *** WARNING" for axis in warned]


# -- WE-10: option 99, the S code of SPINDL/NEUTRL (001 L25604-25617) ------------------------


def test_we10_option_99_point_1_punches_s00() -> None:
    """A control whose neutral is S00 (two-digit S, REGFOR(12) = 20): option 99 = 0.1."""
    machine = load_machine_text('[machine]\nname = "s00"\n[regfor]\n12 = 20.0\n')
    lines = tape_lines(post(["SPINDL/NEUTRL"], machine.with_options({99: 0.1})).blocks)
    assert lines == ["N001S00"]


def test_we10_option_99_zero_outputs_no_s_word() -> None:
    assert tape_lines(post(["SPINDL/NEUTRL"], standard_machine()).blocks) == []


# -- WE-12: option 141, the rotary table's feed commands (001 L26063-26074) ------------------

ROTARY_TABLE = """
[machine]
name = "rotary-feed-commands"
[regstr]
16 = "E"
[regfor]
16 = 10.0
[optab]
1 = 1.0
112 = 6.0
139 = 16.0
141 = 1.0
"""


@pytest.mark.parametrize(("command", "rpm"), [(9, 1.2), (8, 0.83916), (7, 0.58683), (1, 0.068627)])
def test_we12_fcom_n_is_option_114_over_1_43_to_the_9_minus_n(command: int, rpm: float) -> None:
    """FCOM(N) = option 114 / 1.43**(9 - N) with the standard option 114 = 1.2 RPM (values
    derived in the digest: 1.43**8 = 17.48591); a feed of that many RPM on the 6-inch table
    (option 112) is commanded by its row N."""
    machine = load_machine_text(ROTARY_TABLE)
    assert machine.number_option(114) == 1.2
    circumference = 2 * math.pi * machine.number_option(112)
    feeds = rotary_feeds(machine)
    assert feeds[command] / circumference == pytest.approx(rpm, rel=5e-5)
    plugin = GeometricRotaryFeed()
    assert plugin.command(machine, feeds[command], FeedContext()).command == float(command)


# -- WE-14: IORDER, the output order of the registers (001 L26978-27009) ----------------------

IORDER_MACHINE = """
[machine]
name = "iorder"
[regfor]
6 = -14.0
7 = -14.0
[output_order]
iorder = [1, 2, 3, 5, 7, 11, 12, 4, 6, 8, 9, 10, 13, 14]
"""


def test_we14_iorder_outputs_n_g_x_i_y_j_z_k_f_s_a_b_t_m() -> None:
    machine = load_machine_text(IORDER_MACHINE)
    block = Block(Code.LINEAR, 1)
    for location in range(1, 15):
        block.cells[location] = 1.0
    words = WordFormatter(machine).words(block, suppress=False, sequence=1)
    assert "".join(letter for _, letter, _, _ in words) == "NGXIYJZKFSABTM"


def test_we14_without_iorder_registers_go_out_in_regstr_order() -> None:
    machine = load_machine_text('[machine]\nname = "ab"\n[regfor]\n6 = -14.0\n7 = -14.0\n')
    assert machine.output_order is None
    block = Block(Code.LINEAR, 1)
    for location in range(1, 15):
        block.cells[location] = 1.0
    words = WordFormatter(machine).words(block, suppress=False, sequence=1)
    assert "".join(letter for _, letter, _, _ in words) == "NGXYZABIJKFSTM"


# -- WE-16: customer options (001 L26771-26830) ----------------------------------------------


def test_we16_machin_sets_the_customer_options_246_and_247() -> None:
    """MACHIN/GECENT,nm,OPTAB,246,100,247,4 reaches the machine: options 246-250 are the
    installation's, never fixed. (No gecent machine builds its SRTAB from them: the manual's
    example prints no speed tables.)"""
    args = ("GECENT", 23, "OPTAB", 246, 100, 247, 4)
    converted = tuple(Word(a, None) if isinstance(a, str) else a for a in args)
    request = parse_machin(Statement("t.apt", 1, 1, "MACHIN", 1015, converted))  # type: ignore[arg-type]
    assert request is not None
    machine = resolve_machine(get_plugins(), None, request)
    assert (machine.option(246), machine.option(247)) == (0.0, 0.0)
    changed, notes = apply_machin_options(machine, request)
    assert (changed.option(246), changed.option(247)) == (100.0, 4.0)
    assert notes == []


# -- WE-20: information blocks, CODE -9 (001 L22151-22258) -----------------------------------


def test_we20_information_blocks_carry_their_data_and_are_never_printed_or_punched() -> None:
    """Type 2 (ORIGIN/X,Y,Z in DBFSEG(3..5)) and type 1 (the tool correction delta T in
    DBFSEG(3)) go to the later passes as CODE -9 blocks and never reach tape or listing."""
    program = [
        "ORIGIN/10,5,2",
        "FROM/0,0,0",
        "LOADTL/1,LENGTH,5",
        "FEDRAT/10",
        "GOTO/1,0,0",
        "LOADTL/2,LENGTH,6.5",
        "GOTO/2,0,0",
    ]
    result = post(program)
    information = [b for b in result.blocks if b.code is Code.INFORMATION]
    assert [b.cells[2] for b in information] == [2.0, 1.0]
    assert [information[0].cells[k] for k in (3, 4, 5)] == [10.0, 5.0, 2.0]
    assert information[1].cells[3] == 1.5
    assert information[1].cells[4] is ABSENT
    assert not any(b.punched or b.printed or b.punch for b in information)
    assert Code.INFORMATION == -9
