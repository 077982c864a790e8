"""Punched tape in EIA RS-244 and ASCII RS-358 code (appendix 7.6-7.7)."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.errors import InputError
from gecent.core.output.punch import punch, table, unpunch


def test_every_eia_code_has_odd_parity_and_every_ascii_code_even() -> None:
    for character, frame in table("eia").items():
        if character != "BLANK_TAPE":
            assert bin(frame).count("1") % 2 == 1, character
    for character, frame in table("ascii").items():
        assert bin(frame).count("1") % 2 == 0, character


def test_option_64_to_67_channels() -> None:
    """001 L25212-25237: space/leader channel 5, end of record 1,2,4, tab 2,3,4,5,6, EOB 8."""
    eia = table("eia")
    assert (eia["SPACE"], eia["EOR"], eia["TAB"], eia["EOB"]) == (0x10, 0x0B, 0x3E, 0x80)


def test_p1_one_register_word() -> None:
    """X -3.2468 in format -24 punches X-032468 (001 L8835-8848), then end of block."""
    assert punch(["X-032468"], "eia") == bytes.fromhex("374020130204160880")
    assert punch(["X-032468"], "ascii") == bytes.fromhex("D82D3033B2B436B80A")


def test_p6_block_delete_slash_leads_the_block() -> None:
    eia = punch(["/N012G01X-032468"], "eia")
    assert eia == bytes.fromhex("3145200102672001374020130204160880")


def test_blanks_and_periods_are_never_punched() -> None:
    assert punch(["N1 2.3"], "ascii") == punch(["N123"], "ascii")


@pytest.mark.parametrize("code", ["eia", "ascii"])
def test_tapes_read_back_to_their_image(code: str) -> None:
    image = ["TEST1", "N012G01X+1Z-1F071", "/N014Y+1F100", "N016X-1"]
    assert unpunch(punch(image, code), code) == image


def test_characters_without_a_code_are_named() -> None:
    with pytest.raises(InputError, match=r"tape block 2 \('M00%'\): '%' has no EIA code"):
        punch(["N1", "M00%"], "eia")


def test_post_writes_the_punched_tape(tmp_path: Path) -> None:
    source = tmp_path / "part.apt"
    source.write_text("PARTNO DEMO\nFROM/0,0,0\nFEDRAT/10\nGOTO/1,0,0\nFINI\n")
    tape, listing, eia = tmp_path / "p.tape", tmp_path / "p.lis", tmp_path / "p.eia"
    arguments = ["post", str(source), "-o", str(tape), "--listing", str(listing)]
    result = CliRunner().invoke(main, [*arguments, "--punch", "eia", str(eia)])
    assert result.exit_code == 0, result.stderr
    assert tape.read_text() == "DEMO\nN004G01X+1F100\n"
    # (the readable PARTNO heads the punch on the Standard Machine: option 20 = 0, 163 = 0)
    assert unpunch(eia.read_bytes(), "eia", readable=True) == tape.read_text().splitlines()
    again = tmp_path / "again.eia"
    CliRunner().invoke(main, [*arguments, "--punch", "eia", str(again)])
    assert again.read_bytes() == eia.read_bytes()  # deterministic
