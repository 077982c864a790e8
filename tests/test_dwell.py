"""DELAY, the dwell methods, OPSKIP and the cut/dwell times (manual §4.10-4.12; readings in
docs/research/dwell-times.md)."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post


def punched(lines: list[str], machine: MachineDefinition | None = None) -> list[str | None]:
    return [b.punch for b in post(lines, machine).blocks if b.punch]


def test_dw1_delay_in_the_x_register_over_option_56() -> None:
    """DW-1 (001 L16305-16330): DELAY/4 on the Standard Machine is G04 X0.4 (X04), which
    the control reads as 4 s; the dwell time counts the real 4 s."""
    result = post(["DELAY/4"])
    assert [b.punch for b in result.blocks if b.punch] == ["N001G04X+04"]
    assert result.dwell_minutes == pytest.approx(4 / 60)


def test_delay_in_revolutions_follows_the_spindle() -> None:
    """DELAY/2,REV at 85 RPM is 2 x 60 / 85 = 1.41176 s: X 0.1412, as the manual's sample
    printout shows it (001 L10270, L10282, L10407)."""
    lines = ["SPINDL/85,CLW", "DELAY/2,REV"]
    assert punched(lines) == ["N001S585M03", "N002G04X+01412"]


def test_delay_in_revolutions_without_a_speed_is_taken_as_seconds() -> None:
    result = post(["DELAY/2,REV"])
    assert [b.punch for b in result.blocks if b.punch] == ["N001G04X+02"]
    assert [d.text for d in result.diagnostics] == [
        "DELAY TIME FOR REV NOT CORRECT SINCE NO SPEED IS GIVEN."
    ]


def test_delay_zero_is_a_bare_block() -> None:
    assert punched(["DELAY/0"]) == ["N001"]


def test_preset_timer_when_there_is_no_dwell_g_code() -> None:
    """TABLEG(5) absent: DELAY outputs TABLEM(18) in a block by itself (001 L30311-30342)."""
    text = '[machine]\nname = "timer"\ntitle = "PRESET TIMER"\n'
    text += '[tableg]\n5 = "absent"\n[tablem]\n18 = 31\n'
    machine = load_machine_text(text, "timer.toml")
    assert punched(["DELAY/1"], machine) == ["N001M31"]


def test_dw3_dw4_f_register_dwell_on_mach40() -> None:
    """MACH40 (option 57 = 11, no TABLEG(5)): F = 60 / t under G11, the smallest code from
    GDIMUL 1 up (001 L16341-16370): DELAY/40 -> G11 F1.5 (F0015), DELAY/3 -> F20."""
    machine = get_plugins().machine("mach40").load()
    assert punched(["DELAY/40", "DELAY/3"], machine) == ["N001G11F0015", "N002G11F020"]


def test_opskip_marks_every_block_until_off() -> None:
    """§4.11 (001 L16375-16398): the N is stored negative and "/" goes before it."""
    machine = standard_machine().with_options({30: 1.0})
    lines = ["OPSKIP/ON", "FROM/0,0,0", "FEDRAT/10", "GOTO/1,0,0", "OPSKIP/OFF", "GOTO/2,0,0"]
    assert punched(lines, machine) == ["/N004G01X+1F100", "N006X+1"]


def test_opskip_on_a_machine_without_block_delete_is_ignored() -> None:
    result = post(["OPSKIP/ON", "FROM/0,0,0", "FEDRAT/10", "GOTO/1,0,0"])
    assert [b.punch for b in result.blocks if b.punch] == ["N004G01X+1F100"]
    assert "OPSKIP NOT AVAILABLE" in result.diagnostics[0].text


def test_option_148_dwells_in_every_non_motion_block() -> None:
    """Option 148 = 2: a 2-second G04 in the SPINDL block; dwell blocks keep their own."""
    result = post(["SPINDL/100,CLW", "DELAY/1"], standard_machine().with_options({148: 2.0}))
    assert [b.punch for b in result.blocks if b.punch] == ["N001G04X+02S610M03", "N002G04X+01"]
    assert result.dwell_minutes == pytest.approx(3 / 60)


def test_option_98_puts_a_momentary_f_in_non_motion_blocks() -> None:
    """Option 98 = +200: F200 with G = TABLEG(5) in non-motion blocks, not in dwell blocks;
    the next feed block repeats its F (the control's F was overwritten)."""
    machine = standard_machine().with_options({98: 200.0})
    lines = ["FROM/0,0,0", "FEDRAT/10", "GOTO/1,0,0", "SPINDL/100,CLW", "GOTO/2,0,0"]
    assert punched(lines, machine) == ["N003G01X+1F100", "N004G04F200S610M03", "N005G01X+1F100"]


def test_listing_footer_has_running_cut_and_dwell_times(tmp_path: Path) -> None:
    source = tmp_path / "p.apt"
    source.write_text("FROM/0,0,0\nFEDRAT/10\nGOTO/5,0,0\nDELAY/6\nFINI\n")
    listing = tmp_path / "p.lis"
    result = CliRunner().invoke(
        main, ["post", str(source), "-o", str(tmp_path / "p.tape"), "--listing", str(listing)]
    )
    assert result.exit_code == 0, result.stderr
    text = listing.read_text()
    assert "CUT TIME 0.50 MIN; DWELL TIME 0.10 MIN;" in text
    assert text.rstrip().endswith("TAPE FOOTAGE 1")
