"""GEOUT2, the combined printout (manual §3.5.5, 001 L9583-9707): INC, ABS and OPR lines
of a motion block, the INC line alone of a non-motion block (with its ABS line when it
carries a spindle speed), the absolute expansion W9, unit-increasing sequence numbers on
the printout only, and GEOUT1's fall-back to it (001 L9452-9476)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import standard_machine
from gecent.core.output.sinks import PrintoutUnfit
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins
from gecent.plugins.printouts.geout1 import columns
from gecent.plugins.printouts.geout2 import Geout2

from .conftest import MACHINES, ROOT
from .test_post_linear import post

W16 = [
    "PARTNO W16",
    "ORIGIN/10,10,10",
    "FROM/10,0,-20",
    "FEDRAT/20",
    "SPINDL/80",
    "GOTO/13.6,0,-22.6",
    "DELAY/0.4",
    "SPINDL/60",
    "DELAY/0.8",
]


def listing(lines: list[str], machine: MachineDefinition | None = None) -> str:
    machine = machine or standard_machine()
    result = post(lines, machine)
    return Geout2().render(machine, result.blocks, result.partno)


def data_lines(text: str) -> list[str]:
    return [line for line in text.splitlines() if line[:3] in ("INC", "ABS", "OPR")]


def fields(line: str) -> list[str]:
    return line.split()


def test_w16_a_motion_block_prints_inc_abs_and_opr() -> None:
    """W16 (001 L9636-9651): record 6 moves to (13.6, 0, -22.6) at 20 IPM; its ABS line
    carries the CL record number and the absolute point, its OPR line the point less the
    ORIGIN (10, 10, 10), 3.6 -10 -32.6, with the INC line's G and F repeated."""
    rows = data_lines(listing(W16))
    at = next(i for i, row in enumerate(rows) if fields(row)[:3] == ["INC", "002", "01"])
    inc, absolute, operator = rows[at : at + 3]
    assert fields(inc) == ["INC", "002", "01", "+3.6", "-2.6", "045"]
    assert fields(absolute) == ["ABS", "6", "+0013.6000", "+0000.0000", "-0022.6000", "20."]
    assert fields(operator) == ["OPR", "002", "01", "+0003.6000", "-0010.0000", "-0032.6000", "045"]


def test_w16_non_motion_blocks_print_inc_and_abs_only_with_a_speed() -> None:
    """Non-motion records print only their INC line; a block with a spindle speed adds its
    ABS line: the CL record number and the speed in RPM (W16's block 043, ABS 246 60)."""
    rows = [fields(row) for row in data_lines(listing(W16))]
    tags = [row[0] for row in rows]
    # FROM; N005S580M03; the move N006; the dwell N007; N008S560; the dwell N009
    assert tags == [
        "INC",
        "ABS",
        "OPR",
        "INC",
        "ABS",
        "INC",
        "ABS",
        "OPR",
        "INC",
        "INC",
        "ABS",
        "INC",
    ]
    assert rows[-3:] == [["INC", "004", "560"], ["ABS", "8", "60."], ["INC", "005", "04", "+0.08"]]
    assert rows[-4] == ["INC", "003", "04", "+0.04"]


def test_the_three_lines_stand_under_one_register_title() -> None:
    """INC, ABS and OPR share the columns: X's decimal points line up, and the register
    title centres X over its field."""
    text = listing(W16)
    title = next(line for line in text.splitlines() if line.split()[:3] == ["N", "G", "X"])
    rows = data_lines(text)
    at = next(i for i, row in enumerate(rows) if fields(row)[:3] == ["INC", "002", "01"])
    values = ("+3.6", "+0013.6000", "+0003.6000")
    points = {
        row.index(value) + value.index(".")
        for row, value in zip(rows[at : at + 3], values, strict=True)
    }
    assert len(points) == 1
    start = rows[at + 1].index("+0013.6000")
    assert title.index(" X ") + 1 == start + (len("+0013.6000") - 1) // 2


def test_w9_absolute_expansion() -> None:
    """W9 (001 L8945-8960): REGFOR(3) = -24, a FROM at 892.3456 and departures 95.6789,
    10.0010, 90.1111: the incremental X keeps its 6-digit spread, the absolute X has 8
    digits, 0892.3456 0988.0245 0998.0255 1088.1366."""
    from .test_rotary import _all_codes  # X, Y, Z of format -24, G10-G14, option 4 99.9999

    machine = _all_codes()
    program = ["FROM/892.3456,0,0", "FEDRAT/10"]
    program += ["GOTO/988.0245,0,0", "GOTO/998.0255,0,0", "GOTO/1088.1366,0,0"]
    rows = [fields(row) for row in data_lines(listing(program, machine))]
    assert [row[2] for row in rows if row[0] == "ABS"] == [
        "+0892.3456",
        "+0988.0245",
        "+0998.0255",
        "+1088.1366",
    ]
    increments = [row for row in rows if row[0] == "INC" and row[1] != "FROM"]
    assert [next(value for value in row[2:] if "." in value) for row in increments] == [
        "+95.6789",
        "+10.001",
        "+90.1111",
    ]


def test_sequence_numbers_count_up_on_the_printout_and_the_tape_keeps_its_own() -> None:
    """GEOUT2 numbers INC and OPR lines 1, 2, 3 whatever option 143 says; the ABS line
    shows the CL record number; the tape is not changed (docs/decisions.md)."""
    result = post(W16)
    assert tape_lines(result.blocks) == [
        "W16",
        "N005S580M03",
        "N006G01X+36Z-26F045",
        "N007G04X+004",
        "N008S560",
        "N009G04X+008",
    ]
    rows = [row for row in map(fields, data_lines(listing(W16))) if row[1] != "FROM"]
    assert [row[1] for row in rows if row[0] == "INC"] == ["001", "002", "003", "004", "005"]
    assert [row[1] for row in rows if row[0] == "ABS"] == ["5", "6", "8"]
    assert [row[1] for row in rows if row[0] == "OPR"] == ["002"]


def test_a_block_keeps_its_three_lines_on_one_page() -> None:
    machine = standard_machine().with_options({79: 4.0})
    program = ["FROM/0,0,0", "FEDRAT/10"] + [f"GOTO/{n},0,0" for n in range(1, 5)]
    pages = listing(program, machine).split("\f")
    for page in pages:
        tags = [row[:3] for row in data_lines(page)]
        assert len(tags) <= 4
        assert "".join(tags).replace("INCABSOPR", "") == ""  # whole groups only
    assert len(pages) == 5


def test_rotary_positions_print_in_degrees() -> None:
    """ABS line rotary values are degrees (001 L9617-9619): 90 degrees in three departures
    of 0.0833 revolution (option 118 = 0) reach 90.000, and the move after them keeps it."""
    from .test_rotary import _all_codes, _with_a

    machine = _with_a(_all_codes())
    rows = data_lines(
        listing(["FROM/0,0,0", "FEDRAT/10", "ROTATE/HEAD,INCR,90", "GOTO/1,0,0"], machine)
    )
    absolute = [fields(row) for row in rows if row.startswith("ABS")]
    assert [row[5] for row in absolute] == [
        "+0000.000",
        "+0029.988",
        "+0060.012",
        "+0090.000",
        "+0090.000",
    ]


def test_geout2_that_does_not_fit_names_option_160() -> None:
    machine = get_plugins().machine("mach23").load().with_options({160: 90.0})
    with pytest.raises(
        InputError, match=r"GEOUT2 printout's line needs 103 .* option 160 gives 90"
    ):
        Geout2().listing(machine, lambda: "")


def cli(tmp_path: Path, source: Path, machine: str | None = None) -> tuple[int, str, Path, Path]:
    tape, lis = tmp_path / "t.tape", tmp_path / "t.lis"
    arguments = ["post", str(source), "-o", str(tape), "--listing", str(lis)]
    if machine is not None:
        arguments += ["--machine", machine]
    result = CliRunner().invoke(main, arguments)
    return result.exit_code, result.stderr, tape, lis


def machine_file(tmp_path: Path, options: str) -> str:
    """MACH23 with its option 164 line replaced."""
    text = (MACHINES / "mach23.toml").read_text()
    changed = re.sub(r"(?m)^164 = 1\.0.*$", options, text)
    assert changed != text
    path = tmp_path / "mach23-print.toml"
    path.write_text(changed)
    return str(path)


def test_geout1_that_cannot_fit_falls_back_to_geout2(tmp_path: Path) -> None:
    """MACH23's GEOUT1 line needs 120 print positions; with 110 GEOUT1 cannot be used: the
    listing is GEOUT2's, the warning comment at its top and on stderr, the run succeeds and
    the tape is the same (001 L9452-9476, L28989-28992)."""
    narrow = get_plugins().machine("mach23").load().with_options({160: 110.0})
    with pytest.raises(PrintoutUnfit, match=r"GEOUT1 CANNOT BE USED\. .*needs 120 print"):
        columns(narrow)
    source = ROOT / "examples" / "mill_mach23.apt"
    code, err, tape, lis = cli(tmp_path, source, machine_file(tmp_path, "164 = 1.0\n160 = 110.0"))
    assert code == 0
    comment = (
        "GEOUT1 CANNOT BE USED. (GEOUT2 IS USED IN THIS CASE: ITS LINE NEEDS 120 PRINT "
        "POSITIONS, OPTION 160 GIVES 110)"
    )
    assert f"mach23-print.toml: warning: {comment}" in err
    text = lis.read_text()
    assert text.splitlines()[4] == comment  # the first line under the page title
    assert "INC  FROM" in text and "\nOPR " in text
    assert max(len(line) for line in text.splitlines()) <= 111
    (tmp_path / "geout1").mkdir()
    code, _, geout1_tape, _ = cli(tmp_path / "geout1", source)  # MACHIN/GECENT,23: GEOUT1
    assert code == 0 and tape.read_text() == geout1_tape.read_text()


def test_mill_mach23_with_geout2_from_the_command_line(tmp_path: Path) -> None:
    source = ROOT / "examples" / "mill_mach23.apt"
    code, err, tape, lis = cli(tmp_path, source, machine_file(tmp_path, "164 = 2.0"))
    assert code == 0, err
    rows = data_lines(lis.read_text())
    assert {row[:3] for row in rows} == {"INC", "ABS", "OPR"}
    assert "PLATE 2210 HOLES" in lis.read_text()
    assert tape.read_text().splitlines()[1] == "N009G04M03"


def test_mach40_posts_a_three_axis_program_with_its_geout2_listing(tmp_path: Path) -> None:
    """MACH40 (option 164 = 2, 001 L27972) is a class 1 machine (option 116): its points go
    through the class even with the tool along Z (k = 1: C stays 0, A = 90 degrees), so
    part x is machine Y, part y machine -X, and Z is raised by R = option 104 = 4 in
    (core/motion/multiaxis.py); the listing's ABS line has A and C in degrees."""
    source = tmp_path / "t40.apt"
    # (option 110 = 0: machine Z 4 at Y 1 is below MACF40's Z window, its MCHCON 2 test)
    program = ["PARTNO T", "MACHIN/GECENT,40,OPTAB,110,0", "FROM/0,0,5", "FEDRAT/10", "SPINDL/500"]
    source.write_text("\n".join([*program, "GOTO/1,1,0", "GOTO/2,1,0", "FINI"]) + "\n")
    code, err, tape, lis = cli(tmp_path, source)
    assert code == 0, err
    assert tape.read_text().splitlines()[-2:] == ["N006G01X-1Y+1Z-5F00192", "N007Y+1F01000"]
    rows = [fields(row) for row in data_lines(lis.read_text())]
    assert rows[-3:] == [
        ["INC", "003", "+1.", "010.00"],
        ["ABS", "7", "-0001.0000", "+0002.0000", "+0004.0000", "+0090.0000", "+0000.0000", "10."],
        [
            "OPR",
            "003",
            "-0001.0000",
            "+0002.0000",
            "+0004.0000",
            "+0090.0000",
            "+0000.0000",
            "010.00",
        ],
    ]


def test_every_tape_block_is_numbered_whatever_the_tapes_n() -> None:
    """ "A unit increasing number irrespective of the setting of option 143" (001
    L9628-9633): with SEQNO/OFF the tape has no N, the printout still numbers its blocks."""
    rows = data_lines(listing(["SEQNO/OFF", *W16]))
    numbers = [fields(row)[1] for row in rows if row.startswith("INC") and "FROM" not in row]
    assert numbers == ["001", "002", "003", "004", "005"]


def test_w8_print_vectors() -> None:
    """Spec 04 W8 (001 L8880-8889): N (REGFOR 30.), G (20.), X and Y (-24.) laid out two
    blanks apart from column 3: N 3-5, G 8-9, X 12-19, Y 22-29; X and Y signed, 2 + 4
    digits with the point (NPT -6, NPR -104): 8 columns. The layout of every printout
    (CALCPn) spreads the spare print positions equally, so 28 positions give W8's spacing."""
    from dataclasses import replace

    from gecent.core.machine.regformat import decode_regfor
    from gecent.plugins.printouts.layout import Column, format_width, spread

    machine = standard_machine()
    registers = machine.registers
    formats = list(registers.formats)
    for location, regfor in ((1, 30.0), (2, 20.0), (3, -24.0), (4, -24.0)):
        formats[location] = decode_regfor(regfor)
    registers = replace(registers, formats=tuple(formats))
    wanted = [
        Column(str(k), letter, format_width(registers, k))
        for k, letter in ((1, "N"), (2, "G"), (3, "X"), (4, "Y"))
    ]
    placed = spread(wanted, 28)
    assert [(c.start, c.end) for c in placed] == [(3, 5), (8, 9), (12, 19), (22, 29)]


def test_an_insert_is_an_inc_line() -> None:
    """Every line of the tape is tagged (001 L9606-9610): an INSERT's text is punched, so
    it prints as an INC line; PPRINT and comments, not on the tape, stay untagged."""
    text = listing(["PARTNO I", "INSERT G04X1", "PPRINT A NOTE", "FROM/0,0,0"])
    lines = text.splitlines()
    insert = next(line for line in lines if "G04X1" in line)
    assert insert.startswith("INC") and insert.split() == ["INC", "G04X1"]
    assert "A NOTE" in lines
