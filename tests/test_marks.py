"""LEADER and TMARK (manual §3.5.3.2 CODE -8 and +8, 001 L9298-9324), through the kernel to
the tape image, the punched frames and back."""

from __future__ import annotations

import pytest
from gecent.core.machine.loader import standard_machine
from gecent.core.output.block import Code
from gecent.core.output.marks import leader_cards, leader_inches
from gecent.core.output.punch import punch, unpunch
from gecent.core.output.tape import tape_feet, tape_lines

from tests.test_post_linear import post


@pytest.mark.parametrize(
    ("requested", "cards", "inches"),
    [(6, 1, 6.2), (10, 2, 13.4), (20, 3, 20.6), (24, 4, 27.8), (36, 6, 42.2), (48, 7, 49.4),
     (60, 9, 63.8), (100, 15, 107.0)],
)  # fmt: skip
def test_leader_cards_and_length(requested: float, cards: int, inches: float) -> None:
    """W15 (001 L9313-9320): N = <0.14 L + 1> cards, 7.2 N - 1 inches. The manual's
    "at least this amount" fails for some L (LEADER/7 gives 6.2 in); the formula is kept."""
    assert leader_cards(requested) == cards
    assert leader_inches(requested) == pytest.approx(inches)


def test_w15_leader_48_prints_and_punches_49_4_inches() -> None:
    result = post(["LEADER/48", "FROM/0,0,0", "FEDRAT/10", "GOTO/1,0,0"])
    leader = result.blocks[0]
    assert leader.code is Code.LEADER
    assert leader.text == "49.4 INCHES OF LEADER HERE"
    lines = tape_lines(result.blocks)
    assert lines[0] == "(" * 494  # 49.4 in at 10 frames per inch
    eia = punch(lines, "eia")
    assert eia[:494] == b"\x10" * 494  # option 64: channel 5, no end of block
    assert eia[494:] == punch(lines[1:], "eia")
    assert tape_feet(lines) == pytest.approx((494 + len(lines[1]) + 1) / 120)


def test_tmark_punches_the_end_of_record_code_without_n() -> None:
    result = post(["TMARK", "FROM/0,0,0", "FEDRAT/10", "GOTO/1,0,0"])
    lines = tape_lines(result.blocks)
    assert lines[0] == "="
    assert punch(lines[:1], "eia") == bytes.fromhex("0B80")  # channels 1,2,4 then EOB
    assert punch(lines[:1], "ascii") == bytes.fromhex("A50A")  # "%" rewind stop, LF


def test_option_146_puts_a_dwell_g_in_the_tmark_block() -> None:
    machine = standard_machine().with_options({146: 1.0})
    assert tape_lines(post(["TMARK"], machine).blocks) == ["=G04"]


def test_leader_and_tmark_survive_punching_and_reading_back() -> None:
    program = ["LEADER/10", "TMARK", "FROM/0,0,0", "FEDRAT/10", "GOTO/1,2,0", "LEADER/6"]
    lines = tape_lines(post(program).blocks)
    assert unpunch(punch(lines, "eia"), "eia") == lines
    # ASCII's end of record is the character "%": it reads back as itself
    ascii_lines = ["%" if line == "=" else line for line in lines]
    assert unpunch(punch(lines, "ascii"), "ascii") == ascii_lines
