"""GEOUT4, the multiple printout (manual §3.5.7, 001 L9883-9936): separate Incremental,
Absolute and Operator printouts chosen by option 17 (001 L24571-24591), each with its
title, page numbers, times and tape footage; the second and third kept in temporary files
until the run ends, and never left behind."""

from __future__ import annotations

import os
import re
import tempfile
from collections.abc import Callable
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import standard_machine
from gecent.core.output.block import Block
from gecent.core.output.sinks import Ending, ListingSink
from gecent.core.output.tape import tape_line
from gecent.plugins.printouts import multiple
from gecent.plugins.printouts.geout4 import Geout4
from gecent.plugins.printouts.multiple import HeadLayout, MultiplePrintout

from .conftest import MACHINES, ROOT
from .test_post_linear import post

TITLE = re.compile(r"^\*\*\* (\w+) \*\*\*$", re.MULTILINE)
PROGRAM = ["PARTNO SPLIT", "FROM/0,0,0", "FEDRAT/10", "PPRINT LONG MOVE", "GOTO/30,0,0"]


def machine(option_17: float, **options: float) -> MachineDefinition:
    changes = {17: option_17, 164: 4.0} | {int(k[1:]): v for k, v in options.items()}
    return standard_machine().with_options(changes)


def listing(lines: list[str], machine: MachineDefinition) -> str:
    result = post(lines, machine)
    return Geout4().render(machine, result.blocks, result.partno)


def printouts(text: str) -> dict[str, str]:
    """Each printout's text (its pages) by its title."""
    parts = TITLE.split(text)
    found: dict[str, str] = {}
    for kind, page in zip(parts[1::2], parts[2::2], strict=True):
        found[kind] = found.get(kind, "") + page
    return found


def rows(text: str) -> list[list[str]]:
    """The numbered lines (N, then the values)."""
    return [line.split() for line in text.splitlines() if re.match(r"^  \d{3}( |$)", line)]


@pytest.mark.parametrize(
    ("option", "titles"),
    [
        (111, ["INCREMENTAL", "ABSOLUTE", "OPERATOR"]),
        (100, ["INCREMENTAL"]),
        (10, ["ABSOLUTE"]),
        (1, ["OPERATOR"]),
        (110, ["INCREMENTAL", "ABSOLUTE"]),
    ],
)
def test_option_17_chooses_the_printouts(option: float, titles: list[str]) -> None:
    """Each printout complete and separate, in the order incremental, absolute, operator,
    each with its page numbers from 1 and its times and tape footage at its end."""
    text = listing(PROGRAM, machine(option))
    assert TITLE.findall(text) == titles
    assert text.count("PAGE 1\n") == len(titles) and "PAGE 2" not in text
    assert text.count("TAPE FOOTAGE 1\n") == len(titles)
    assert text.count("\f") == len(titles) - 1  # each printout starts a page
    assert not text.startswith("\f")


def test_the_printouts_show_the_same_blocks_their_own_way() -> None:
    """The N of each block on all three; the Incremental the tape's words, the Absolute the
    point and the feed in IPM, the Operator the point less the ORIGIN with the words."""
    program = ["ORIGIN/1,2,3", "FROM/0,0,0", "FEDRAT/10", "GOTO/3,4,0"]
    found = printouts(listing(program, machine(111)))
    assert rows(found["INCREMENTAL"]) == [["004", "01", "+3.", "+4.", "020"]]
    assert rows(found["ABSOLUTE"]) == [["004", "+0003.0000", "+0004.0000", "+0000.0000", "10."]]
    assert rows(found["OPERATOR"]) == [
        ["004", "01", "+0002.0000", "+0002.0000", "-0003.0000", "020"]
    ]
    for text in found.values():
        assert "  FROM " in text


def test_digit_2_prints_only_the_first_and_last_segments() -> None:
    """GOTO/30 on the Standard Machine (departures up to 9.9999) is four segments; a digit
    2 keeps the first and the last on its printout (001 L24587-24590). The segmenter marks
    them on the blocks; the times stay the run's."""
    blocks = post(PROGRAM, machine(111)).blocks
    assert [b.segment for b in blocks if b.steps] == [
        (True, False),
        (False, False),
        (False, False),
        (False, True),
    ]
    found = printouts(listing(PROGRAM, machine(211)))
    assert [len(rows(found[kind])) for kind in ("INCREMENTAL", "ABSOLUTE", "OPERATOR")] == [2, 4, 4]
    assert [row[-1] for row in rows(found["INCREMENTAL"])] == ["013", "+7.5"]  # G01 X F, X
    found = printouts(listing(PROGRAM, machine(222)))
    assert [row[1] for row in rows(found["ABSOLUTE"])] == ["+0007.5000", "+0030.0000"]
    cuts = {line for text in found.values() for line in text.splitlines() if "CUT TIME" in line}
    assert cuts == {"CUT TIME 3.00 MIN; DWELL TIME 0.00 MIN;"}


def test_comments_only_on_the_incremental_printout() -> None:
    """Comments (CODE +9) are printed on the Incremental printout only; PPRINT and the
    PARTNO on all three (001 L9330-9334)."""
    found = printouts(listing([*PROGRAM, "SELCTL/3"], machine(111)))
    comment = "SELCTL IS NOT A GECENT III POSTPROCESSOR WORD; STATEMENT DISREGARDED"
    assert [comment in text for text in found.values()] == [True, False, False]
    assert all("\nLONG MOVE\n" in text and "\nSPLIT\n" in text for text in found.values())


@pytest.mark.parametrize("option", [0.0])
def test_option_17_zero_prints_nothing(option: float) -> None:
    assert listing(PROGRAM, machine(option)) == ""


@pytest.mark.parametrize("option", [3.0, 130.0, 11.5, -1.0, 1000.0])
def test_a_bad_option_17_is_refused(option: float) -> None:
    with pytest.raises(InputError, match=rf"option 17 = {option:g}: its digits"):
        Geout4().listing(machine(option), lambda: "")


def test_pages_of_a_kept_printout_end_with_the_times_to_their_last_line() -> None:
    """A kept printout's page shows the cut time to its last line, not the run's."""
    program = ["FROM/0,0,0", "FEDRAT/60"] + [f"GOTO/{n},0,0" for n in range(1, 9)]
    text = listing(program, machine(10, o79=3))
    assert TITLE.findall(text) == ["ABSOLUTE"] * 3
    times = re.findall(r"CUT TIME (\S+) MIN", text)
    assert times == ["0.03", "0.08", "0.13"]  # a minute a foot: 2, 5 and 8 inches


def test_a_multiple_printout_takes_heads_with_prefixes() -> None:
    """GEOUT3's shape (001 L9708-9770): a register title per head, each line prefixed by
    its head; here both heads print the same block."""

    class TwoHeads(MultiplePrintout):
        number, name, section, template = 3, "TWO HEADS", "§3.5.6", multiple.PAGE_TEMPLATE

        def layouts(self, machine: MachineDefinition) -> list[HeadLayout]:
            return [HeadLayout("HEAD1", machine.registers), HeadLayout("HEAD2", machine.registers)]

        def parts(self, block: Block) -> tuple[tuple[int, Block], ...]:
            return ((0, block), (1, block))

    blocks = post([*PROGRAM[1:3], "GOTO/1,0,0"], machine(100)).blocks
    text = TwoHeads().render(machine(100), blocks, "")
    lines = text.splitlines()
    at = next(i for i, line in enumerate(lines) if line.split()[:3] == ["N", "G", "X"])
    assert lines[at + 1].split()[:3] == ["N", "G", "X"]  # a title line per head
    assert [line.split()[:2] for line in lines if line.startswith("HEAD")] == [
        ["HEAD1", "FROM"],
        ["HEAD2", "FROM"],
        ["HEAD1", "003"],
        ["HEAD2", "003"],
    ]


def cli(tmp_path: Path, program: list[str], machine_text: str) -> tuple[int, str, Path, Path]:
    source = tmp_path / "part.apt"
    source.write_text("\n".join([*program, "FINI"]) + "\n")
    machine_path = tmp_path / "machine.toml"
    machine_path.write_text(machine_text)
    tape, lis = tmp_path / "part.tape", tmp_path / "part.lis"
    arguments = ["post", str(source), "-o", str(tape), "--listing", str(lis)]
    result = CliRunner().invoke(main, [*arguments, "--machine", str(machine_path)])
    return result.exit_code, result.stderr, tape, lis


@pytest.fixture
def spools(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> Callable[[], None]:
    """Every spool the printout makes, in a folder of its own; the first removal of each
    fails (as on a system that cannot remove an open file), so a spool is seen on disk
    until it is closed. The check: nothing left, every spool closed, one used at least."""
    made: list[multiple.Spool] = []

    class Tracked(multiple.Spool):
        def __init__(self) -> None:
            super().__init__()
            made.append(self)

    folder = tmp_path / "spool"
    folder.mkdir()
    monkeypatch.setattr(multiple, "Spool", Tracked)
    monkeypatch.setattr(tempfile, "tempdir", str(folder))
    refused: set[str] = set()
    unlink = os.unlink

    def held_open(path: str | os.PathLike[str], *args: object, **kwargs: object) -> None:
        if str(path).startswith(str(folder)) and str(path) not in refused:
            refused.add(str(path))
            raise PermissionError(path)
        unlink(path)

    monkeypatch.setattr(os, "unlink", held_open)

    def check() -> None:
        assert list(folder.iterdir()) == []
        assert made and all(spool.closed for spool in made)
        assert refused  # the files were there while the run went on

    return check


GEOUT4_MILL = '[machine]\nname = "geout4-mill"\n[optab]\n164 = 4.0\n'


def test_no_temporary_file_after_a_run(tmp_path: Path, spools: Callable[[], None]) -> None:
    code, err, tape, lis = cli(tmp_path, PROGRAM, GEOUT4_MILL)
    assert code == 0 and tape.exists(), err
    assert TITLE.findall(lis.read_text()) == ["INCREMENTAL", "ABSOLUTE", "OPERATOR"]
    spools()


def test_no_temporary_file_after_bad_input(tmp_path: Path, spools: Callable[[], None]) -> None:
    code, _, tape, lis = cli(tmp_path, [*PROGRAM, "TRANS/1,2,3,4"], GEOUT4_MILL)
    assert code == 2 and not tape.exists() and not lis.exists()
    spools()


def test_no_temporary_file_after_a_fatal_error(tmp_path: Path, spools: Callable[[], None]) -> None:
    """Fatal 138 (a mill with G11 only): the listing keeps the three printouts of what was
    output, then the dump."""
    text = GEOUT4_MILL + '[tableg]\n2 = "absent"\n12 = 11\n'
    program = ["FROM/0,0,0", "FEDRAT/10", "GOTO/0.5,0,0", "GOTO/5.5,0,0"]
    code, _, tape, lis = cli(tmp_path, program, text)
    assert code == 1 and not tape.exists()
    listed = lis.read_text()
    assert TITLE.findall(listed) == ["INCREMENTAL", "ABSOLUTE", "OPERATOR", "GEDUMP"]
    spools()


def test_a_failed_run_drops_the_spools(tmp_path: Path) -> None:
    """The listing sink of a run that failed on bad input prints nothing and closes the
    temporary files (ListingSink.close calls the writer's discard)."""
    machine_ = machine(111)
    pages = Geout4().listing(machine_, lambda: "")
    sink = ListingSink(tmp_path / "part.lis", pages)
    for block in post(PROGRAM, machine_).blocks:
        sink.block(block, tape_line(block))
    kept = [printed.spool for printed in pages.printed if printed.spool is not None]
    assert len(kept) == 2 and not any(spool.closed for spool in kept)
    sink.close(Ending(False))
    assert all(spool.closed for spool in kept) and list(tmp_path.iterdir()) == []


def test_mill_mach23_with_geout4_from_the_command_line(tmp_path: Path) -> None:
    text = (MACHINES / "mach23.toml").read_text()
    changed = re.sub(r"(?m)^164 = 1\.0.*$", "164 = 4.0", text)
    program = (ROOT / "examples" / "mill_mach23.apt").read_text().splitlines()
    code, err, tape, lis = cli(tmp_path, [line for line in program if line != "FINI"], changed)
    assert code == 0, err
    listed = lis.read_text()
    assert TITLE.findall(listed) == ["INCREMENTAL", "ABSOLUTE", "OPERATOR"]
    found = printouts(listed)
    assert [len(rows(found[kind])) for kind in found] == [21, 21, 21]
    warning = "REQUESTED MISCELLANEOUS FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE"
    assert [warning in found[kind] for kind in found] == [True, False, False]
    assert tape.read_text().splitlines()[1] == "N009G04M03"


def test_option_143_unit_numbers_with_option_17_digit_2_is_warned() -> None:
    """Option 143's table: "+1 = unit increasing (option 17 must not be 2)" (001
    L26079-26090)."""
    from gecent.core.machine.loader import standard_machine
    from gecent.core.machine.rules import check_definition

    warned = check_definition(standard_machine().with_options({143: 1.0, 17: 212.0}))[1]
    assert any("option 17 must not have a digit 2" in w for w in warned)
    quiet = check_definition(standard_machine().with_options({143: 1.0, 17: 111.0}))[1]
    assert not any("option 17" in w for w in quiet)
