"""Punched tape for the modern packs (issue 16): `--punch eia` and `--punch ascii` on every
pack, periods and blanks kept, EIA's End of Record for `%`, comments in Control Out/In;
comment text held to what the tape can carry, with a warning."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.output.punch import unpunch
from gecent.core.plugins import PluginSet
from gecent.core.statements.text import carried

ROOT = Path(__file__).parents[1]
EXAMPLES = ["hello.apt", "lathe_fanuc.apt", "mill_mach23.apt", "drill_mach24.apt"]
# a five-axis pack does not take canned cycles yet (a named "not yet supported" error)
FIVE_AXIS_EXAMPLES = ["hello.apt", "fiveaxis.apt"]


def modern_packs(plugins: PluginSet) -> list[str]:
    packs = [pack.load() for pack in plugins.machines()]
    return sorted(m.name for m in packs if m.number_option(258) == 1)


@pytest.mark.parametrize("code", ["eia", "ascii"])
def test_every_modern_pack_punches_its_tape(plugins: PluginSet, tmp_path: Path, code: str) -> None:
    packs = modern_packs(plugins)
    assert {"linuxcnc-mill", "fanuc-mill", "fanuc-lathe"} <= set(packs)
    five_axis = {pack.load().name for pack in plugins.machines() if pack.load().kinematics}
    assert {"linuxcnc-5axis-ac", "fanuc-5axis-bc"} <= five_axis
    for machine in packs:
        for example in FIVE_AXIS_EXAMPLES if machine in five_axis else EXAMPLES:
            tape, punched = tmp_path / "p.ngc", tmp_path / f"p.{code}"
            command = ["post", str(ROOT / "examples" / example), "--machine", machine]
            command += ["-o", str(tape), "--punch", code, str(punched)]
            result = CliRunner().invoke(main, command)
            assert result.exit_code == 0, (machine, example, result.output)
            lines = tape.read_text().splitlines()
            assert unpunch(punched.read_bytes(), code, modern=True) == lines, (machine, example)
            assert any("." in line for line in lines)  # the periods are punched


def test_eia_percent_is_end_of_record_and_comments_are_control_out_in(tmp_path: Path) -> None:
    tape, punched = tmp_path / "p.ngc", tmp_path / "p.eia"
    command = ["post", str(ROOT / "examples" / "hello.apt"), "--machine", "fanuc-mill"]
    result = CliRunner().invoke(main, [*command, "-o", str(tape), "--punch", "eia", str(punched)])
    assert result.exit_code == 0, result.output
    frames = punched.read_bytes()
    end_of_record, end_of_block = 0x0B, 0x80
    assert frames[:2] == bytes([end_of_record, end_of_block])
    assert frames[-2:] == bytes([end_of_record, end_of_block])
    assert 0x1A in frames and 0x4A in frames  # ( and )


def test_comment_text_the_tape_cannot_carry_is_replaced_with_a_warning(tmp_path: Path) -> None:
    source = tmp_path / "p.apt"
    source.write_text(
        "PARTNO CAF\u00c9\tOP10\nUNITS/MM\nPPRINT 45\u00b0 Fase (klein)\nFROM/0,0,5\n"
        "FEDRAT/100,MMPM\nGOTO/1,0,0\nFINI\n",
        encoding="utf-8",
    )
    tape = tmp_path / "p.ngc"
    result = CliRunner().invoke(
        main, ["post", str(source), "--machine", "linuxcnc-mill", "-o", str(tape)]
    )
    assert result.exit_code == 0, result.output
    lines = tape.read_text(encoding="ascii").splitlines()
    assert lines[1:3] == ["(CAFE OP10)", "(45  Fase [klein])"]
    assert "p.apt:1 (record 1): warning: PARTNO TEXT: '\u00c9', '\\t' CANNOT GO ON" in result.output
    assert "p.apt:3 (record 3): warning: PPRINT TEXT: '\u00b0' CANNOT GO ON" in result.output
    # with an EIA punch the comment holds only what EIA has: upper case, no brackets
    result = CliRunner().invoke(
        main,
        [
            *("post", str(source), "--machine", "linuxcnc-mill", "-o", str(tape)),
            *("--punch", "eia", str(tmp_path / "p.eia")),
        ],
    )
    assert result.exit_code == 0, result.output
    assert tape.read_text().splitlines()[2] == "(45  FASE  KLEIN )"


def test_carried_keeps_printable_ascii() -> None:
    assert carried("A-Z 0.5 [x] #1", None) == ("A-Z 0.5 [x] #1", [])
    assert carried("Stra\u00dfe", None) == ("Stra e", ["\u00df"])
