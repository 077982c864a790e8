"""The multihead options of the option table (manual §5.6.5, 001 L26185-26258,
L26501-26558) on the sample multihead lathe MACH51 (001 L28178-28292): a second S code and
spindle table (153), a second set of M codes (154), the clearance test between the heads
(158, 159), MULTHD without COMBIN (191), a common dwell register (195) and more than two
heads (197)."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest
from gecent.core.absent import ABSENT
from gecent.core.dispatch.post import post
from gecent.core.errors import FatalError, InputError, NotYetSupported
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import MachineFileInvalid, load_machine_file
from gecent.core.output.block import Block, Code
from gecent.core.output.tape import tape_line
from gecent.core.plugins import PluginSet

from .conftest import ROOT

MACH51 = ROOT / "plugins" / "machines" / "mach51.toml"
HEAD_2_LETTERS = '12 = "S", 13 = "T", 14 = "M"'

HEADER = """PARTNO OPTIONS
{combin}SELECT/HEAD,1
FROM/10,10,0
FEDRAT/10
{head_1}SELECT/HEAD,2
FROM/20,10,0
FEDRAT/10
{head_2}"""


def _machine(
    tmp_path: Path, optab: str = "", letters: str = HEAD_2_LETTERS, text: str = ""
) -> MachineDefinition:
    """MACH51 with some options (``optab``: TOML lines), head 2's S, T, M letters and
    more of the file changed."""
    source = MACH51.read_text()
    assert HEAD_2_LETTERS in source
    source = source.replace(HEAD_2_LETTERS, letters).replace("[optab]\n", f"[optab]\n{optab}")
    machine = tmp_path / "m51.toml"
    machine.write_text(source + text)
    return load_machine_file(machine)


def _post(
    plugins: PluginSet,
    tmp_path: Path,
    machine: MachineDefinition,
    body: str,
    head_1: str = "",
    head_2: str = "",
    combin: bool = True,
) -> list[Block]:
    program = tmp_path / "p.apt"
    header = HEADER.format(combin="COMBIN/2\n" if combin else "", head_1=head_1, head_2=head_2)
    program.write_text(header + body + "FINI\n")
    return post(str(program), plugins, machine_override=machine).blocks


def _tape(blocks: list[Block]) -> list[str]:
    return [
        line for b in blocks if b.code is not Code.PARTNO and (line := tape_line(b)) is not None
    ]


def _table_of_two_heads(tmp_path: Path) -> MachineDefinition:
    """Option 153 = 2: SRTAB holds MACH51's 100 speeds for head 1, then head 2's, twice
    head 1's; head 2's S word is V and its M word Q (option 154 = 1)."""
    speeds = load_machine_file(MACH51).spindle_speeds()
    both = ", ".join(f"{s:g}" for s in (*speeds, *(2 * s for s in speeds)))
    source = MACH51.read_text()
    start = source.index("speeds = [")
    end = source.index("]", start)
    machine = tmp_path / "m51.toml"
    text = source[:start] + f"speeds = [{both}" + source[end:]
    machine.write_text(
        text.replace(HEAD_2_LETTERS, '12 = "V", 13 = "T", 14 = "Q"').replace(
            "[optab]\n", "[optab]\n153 = 2.0\n154 = 1.0\n"
        )
    )
    return load_machine_file(machine)


# -- options 153 and 154: head 2's own S and M registers ------------------------------


def test_153_head_2_reads_its_own_spindle_table(plugins: PluginSet, tmp_path: Path) -> None:
    """SPINDL/200 on head 1 is MACH51's 196 RPM, row 48, S47 (type 2: the row number from
    0). Head 2's table is twice head 1's: its 400 RPM is 392, the same row, in its own S
    register V; its M codes go in its own register Q."""
    blocks = _post(
        plugins,
        tmp_path,
        _table_of_two_heads(tmp_path),
        "",
        head_1="SPINDL/200,RPM,CLW\n",
        head_2="SPINDL/400,RPM,CLW\n",
    )
    assert _tape(blocks) == ["N006G04S47M03", "G04V47Q03"]
    assert [b.cells[20] for b in blocks if b.cells[12] is not ABSENT] == [196.0, 392.0]


def test_153_without_it_head_2_shares_head_1s_table(plugins: PluginSet, tmp_path: Path) -> None:
    """MACH51 as the manual gives it (option 153 = 0): 400 RPM is head 1's 400, row 71."""
    blocks = _post(plugins, tmp_path, _machine(tmp_path), "", head_2="SPINDL/400,RPM,CLW\n")
    assert _tape(blocks) == ["G04S70M03"]


def test_154_a_combined_block_carries_both_heads_m_codes(
    plugins: PluginSet, tmp_path: Path
) -> None:
    """With a second set of M codes (option 154 = 1) the coolant of both heads rides in
    the combined block, M08 and Q08; with one M register (MACH51) one M08 serves."""
    body = (
        "SELECT/HEAD,1\nOP/1\nCOOLNT/ON\nGOTO/10,9,0\nSELECT/HEAD,2\nOP/1\nCOOLNT/ON\nGOTO/20,9,0\n"
    )
    own = _tape(_post(plugins, tmp_path, _table_of_two_heads(tmp_path), body))
    assert own == ["N012G01Z-001F0100M08W-001E0100Q08"]
    shared = _tape(_post(plugins, tmp_path, _machine(tmp_path), body))
    assert shared == ["N012G01Z-001F0100M08W-001E0100"]


@pytest.mark.parametrize(
    ("optab", "letters", "message"),
    [
        ("153 = 2.0\n", HEAD_2_LETTERS, "option 153 = 2 asks for a register per head"),
        ("", '12 = "V", 13 = "T", 14 = "M"', "option 153 = 0 asks for one register"),
        ("154 = 1.0\n", HEAD_2_LETTERS, "option 154 = 1 asks for a register per head"),
        ("", '12 = "S", 13 = "T", 14 = "Q"', "option 154 = 0 asks for one register"),
    ],
)
def test_153_154_must_agree_with_head_2s_letters(
    plugins: PluginSet, tmp_path: Path, optab: str, letters: str, message: str
) -> None:
    if "153" in optab:  # (a second table, so that the machine loads; MACH51's head 2)
        machine = _table_of_two_heads(tmp_path).with_options({154: 0.0})
        machine = replace(machine, heads=(machine.heads[0], load_machine_file(MACH51).heads[1]))
    else:
        machine = _machine(tmp_path, optab, letters)
    with pytest.raises(InputError, match=message):
        _post(plugins, tmp_path, machine, "")


def test_153_a_table_per_head_needs_both_tables(tmp_path: Path) -> None:
    """SRTAB must hold option 7 x option 8 speeds per head (checklist 11a)."""
    with pytest.raises(MachineFileInvalid, match="200 speeds, but SRTAB holds only 100"):
        _machine(tmp_path, "153 = 2.0\n", '12 = "V", 13 = "T", 14 = "M"')


def test_153_three_tables_are_a_third_heads(plugins: PluginSet, tmp_path: Path) -> None:
    speeds = load_machine_file(MACH51).spindle_speeds()
    machine = _table_of_two_heads(tmp_path)
    three = list(machine.store)
    for index, speed in enumerate(speeds, start=201):
        three[index] = 3 * speed
    machine = replace(machine.with_options({153: 3.0}), store=tuple(three))
    with pytest.raises(NotYetSupported, match="third spindle table"):
        _post(plugins, tmp_path, machine, "")


# -- options 158 and 159: the clearance between the heads ------------------------------

CLEARANCE_BODY = (
    "SELECT/HEAD,1\nOP/1\nGOTO/15,10,0\nGOTO/15,5,0\n"
    "SELECT/HEAD,2\nOP/1\nGOTO/16,10.5,0\nGOTO/16,20,0\n"
)


def _comments(blocks: list[Block]) -> list[str]:
    return [str(b.text) for b in blocks if b.code is Code.COMMENT]


def test_158_159_heads_within_both_clearances_are_warned(
    plugins: PluginSet, tmp_path: Path
) -> None:
    """Head 1 at (15, 10) and head 2 at (16, 10.5): 1 in apart on X (the first CL axis,
    option 159 = 2) and 0.5 in on Y (the second, option 158 = 1): one comment, though the
    heads stay close for another block; apart again, then close: another."""
    machine = _machine(tmp_path, "158 = 1.0\n159 = 2.0\n")
    blocks = _post(plugins, tmp_path, machine, CLEARANCE_BODY)
    assert _comments(blocks) == [
        "HEADS 1 AND 2 WITHIN THEIR CLEARANCE AFTER CL RECORD 11: "
        "X 1.0000 IN (OPTION 159 = 2), Y 0.5000 IN (OPTION 158 = 1)"
    ]
    back = CLEARANCE_BODY + "GOTO/16,5.5,0\n"  # head 2 on, clear at (16, 20), back close
    blocks = _post(plugins, tmp_path, machine, back)
    assert len(_comments(blocks)) == 2


def test_158_159_a_clearance_kept_on_one_axis_is_no_clash(
    plugins: PluginSet, tmp_path: Path
) -> None:
    """Y 0.5 in apart is within option 158's 1 in, but X 1 in apart keeps option 159's
    0.5 in: the heads are clear. Without the options nothing is tested."""
    machine = _machine(tmp_path, "158 = 1.0\n159 = 0.5\n")
    assert _comments(_post(plugins, tmp_path, machine, CLEARANCE_BODY)) == []
    assert _comments(_post(plugins, tmp_path, _machine(tmp_path), CLEARANCE_BODY)) == []
    only_x = _machine(tmp_path, "159 = 1.5\n")
    (comment,) = _comments(_post(plugins, tmp_path, only_x, CLEARANCE_BODY))
    assert comment.endswith("X 1.0000 IN (OPTION 159 = 1.5)")


# -- option 191: MULTHD without COMBIN --------------------------------------------------


def test_191_sets_multhd_without_combin(plugins: PluginSet, tmp_path: Path) -> None:
    """Option 191 = 1: a program with no COMBIN/ is posted for both heads, as the same
    program with COMBIN/2 on MACH51."""
    body = "SELECT/HEAD,1\nOP/1\nGOTO/10,9,0\nSELECT/HEAD,2\nOP/1\nGOTO/20,9,0\n"
    flagged = _post(plugins, tmp_path, _machine(tmp_path, "191 = 1.0\n"), body, combin=False)
    combined = _post(plugins, tmp_path, _machine(tmp_path), body)
    assert _tape(flagged) == ["N010G01Z-001F0100W-001E0100"]  # (record 10: no COMBIN)
    assert _tape(combined) == ["N011G01Z-001F0100W-001E0100"]


def test_191_on_a_program_of_one_head_is_fatal_7003(plugins: PluginSet, tmp_path: Path) -> None:
    program = tmp_path / "p.apt"
    program.write_text("PARTNO ONE\nFROM/10,10,0\nFEDRAT/10\nGOTO/10,9,0\nFINI\n")
    with pytest.raises(FatalError, match="option 191 sets MULTHD") as raised:
        post(str(program), plugins, machine_override=_machine(tmp_path, "191 = 1.0\n"))
    assert raised.value.number == 7003


def test_191_on_a_machine_of_one_head_is_refused(plugins: PluginSet, tmp_path: Path) -> None:
    machine = tmp_path / "one.toml"
    machine.write_text('[machine]\nname = "one"\ntitle = "ONE"\n[optab]\n191 = 1.0\n')
    program = tmp_path / "p.apt"
    program.write_text("PARTNO ONE\nFROM/10,10,0\nGOTO/10,9,0\nFINI\n")
    with pytest.raises(InputError, match=r"option 191 = 1 .* has one head"):
        post(str(program), plugins, machine_override=load_machine_file(machine))


# -- option 195: a common dwell register ------------------------------------------------


def _dwell_register_machine(tmp_path: Path, head_2_letter: str = "D") -> MachineDefinition:
    """MACH51 with a register D at location 21 (format 3.1, as MACH51's X) on both heads,
    named the common dwell register by option 195."""
    source = MACH51.read_text()
    source = source.replace("[optab]\n", '[optab]\n195 = "D"\n')
    source = source.replace("[regfor]\n", "[regfor]\n21 = 31.0\n")
    source = source.replace("[regstr]\n", '[regstr]\n21 = "D"\n')
    source = source.replace('18 = "" }', f'18 = "", 21 = "{head_2_letter}" }}')
    source = source.replace("18 = 0.0 }", "18 = 0.0, 21 = 31.0 }")
    machine = tmp_path / "m51.toml"
    machine.write_text(source)
    return load_machine_file(machine)


def test_195_the_heads_dwell_in_their_common_register(plugins: PluginSet, tmp_path: Path) -> None:
    """A dwell of head 2 alone goes in D, not in its U (option 57 = 3); both heads'
    dwells cut together are one D word (6 s / option 56 = 10 -> 0.6, format 3.1)."""
    body = "SELECT/HEAD,1\nOP/1\nDELAY/6\nGOTO/10,9,0\nSELECT/HEAD,2\nOP/1\nDELAY/6\nGOTO/20,9,0\n"
    shared = _post(plugins, tmp_path, _dwell_register_machine(tmp_path), body, head_2="DELAY/3\n")
    assert _tape(shared) == ["G04D0003", "N012G04D0006", "N013G01Z-001F0100W-001E0100"]
    own = _post(plugins, tmp_path, _machine(tmp_path), body, head_2="DELAY/3\n")
    assert _tape(own)[:2] == ["G04U+0003", "N012G04X+0006U+0006"]


def test_195_a_dwell_beside_a_move_leaves_no_dwell_word(plugins: PluginSet, tmp_path: Path) -> None:
    """001 L8707-8710: the delay beside the other head's move is a zero move."""
    body = "SELECT/HEAD,1\nOP/1\nGOTO/10,9,0\nSELECT/HEAD,2\nOP/1\nDELAY/6\nGOTO/20,9,0\n"
    machine = _dwell_register_machine(tmp_path).with_options({139: 0.0})
    lines = _tape(_post(plugins, tmp_path, machine, body))
    assert all("D" not in line for line in lines)


def test_195_the_register_is_one_on_both_heads(plugins: PluginSet, tmp_path: Path) -> None:
    machine = _dwell_register_machine(tmp_path, head_2_letter="P")
    with pytest.raises(InputError, match="option 195 names 'D'"):
        _post(plugins, tmp_path, machine, "")
    no_register = _machine(tmp_path, '195 = "Q"\n')
    with pytest.raises(InputError, match="no register location"):
        _post(plugins, tmp_path, no_register, "")


# -- option 197: more than two heads ------------------------------------------------------


@pytest.mark.parametrize("value", [1.0, 2.0, 3.0])
def test_197_more_than_two_heads_are_not_yet_supported(
    plugins: PluginSet, tmp_path: Path, value: float
) -> None:
    """Option 197 describes a machine of three heads; the merge pass reads two tapes."""
    machine = _machine(tmp_path, f"197 = {value}\n")
    with pytest.raises(NotYetSupported, match="more than two heads"):
        _post(plugins, tmp_path, machine, "")


@pytest.mark.parametrize("value", ["4.0", "-1.0", "1.5"])
def test_155_names_x_y_or_z_only(plugins: PluginSet, tmp_path: Path, value: str) -> None:
    """Option 155's values are 0 (none), 1 (X), 2 (Y), 3 (Z) (001 L26207-26217); any other
    is a machine error, not a form to build."""
    with pytest.raises(InputError, match=f"option 155 = {float(value):g}"):
        _post(plugins, tmp_path, _machine(tmp_path, f"155 = {value}\n"), "")


# -- head-specific M codes in RAPID (001 L7270-7278; MACH51's TABLEM, L28232-28235) -------


def test_rapid_shifts_each_heads_gears_with_its_own_m_codes(
    plugins: PluginSet, tmp_path: Path
) -> None:
    """A 40 in rapid (longer than option 37's 35 in) shifts the gears: head 1 by TABLEM
    42/43 (M40 into rapid, M41 back), head 2 by its own cells 142/143 (M44, M45), each
    with option 81's and 82's dwells in its own X or U."""
    body = (
        "SELECT/HEAD,2\nRAPID\nGOTO/60,10,0\nGOTO/60,9,0\n"
        "SELECT/HEAD,1\nRAPID\nGOTO/50,10,0\nGOTO/50,9,0\n"
    )
    lines = _tape(_post(plugins, tmp_path, load_machine_file(MACH51), body))
    assert lines == [
        "N015G04X+0003M40", "N015G10X+040F0500", "N016G04X+00005M41", "N016G01Z-001F0100",
        "G04U+0003M44", "G10U+040E0500", "G04U+00005M45", "G01W-001E0100",
    ]  # fmt: skip
