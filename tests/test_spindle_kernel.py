"""The spindle kernel shared by every spindle type (core/spindle.py): LOCRNG's fallback,
DSRROW's option 90, the empty-table check, and SPINDL/OFF on a machine without M05."""

from __future__ import annotations

import pytest
from gecent.core.errors import MachineDefinitionError
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins
from gecent.core.spindle_types import (
    LOWEST_OUTPUT,
    NOT_FOUND,
    check_ascending,
    choose_speed,
    range_for,
)

from tests.test_post_linear import post

RANGES = ((10.0, 20.0, 30.0), (40.0, 80.0, 120.0))


def test_a_speed_in_a_gap_between_ranges_takes_the_nearer_range() -> None:
    """Outside every range, "the maximum or minimum speed, whichever is nearer" (001
    L14588-14590): 33 RPM is nearer range 1's 30, 38 nearer range 2's 40."""
    assert range_for(RANGES, 33.0, None) == 1
    assert range_for(RANGES, 38.0, None) == 2
    assert range_for(RANGES, 5.0, None) == 1
    assert range_for(RANGES, 500.0, None) == 2
    assert range_for(RANGES, 30.0, None) == 1  # lowest range wins (LOCRNG)


@pytest.mark.parametrize(("rule", "speed"), [(-1.0, 80.0), (0.0, 80.0), (1.0, 120.0)])
def test_option_90_chooses_lower_closest_or_higher(rule: float, speed: float) -> None:
    assert choose_speed(RANGES, 95.0, None, rule).speed == speed


def test_closest_takes_the_lower_speed_on_a_tie() -> None:
    assert choose_speed(RANGES, 100.0, None, 0.0).speed == 80.0


def test_outside_a_range_its_end_with_the_manual_s_comments() -> None:
    low = choose_speed(RANGES, 35.0, 2, -1.0)
    high = choose_speed(RANGES, 35.0, 1, -1.0)
    assert (low.speed, low.row, low.comments) == (40.0, 0, (LOWEST_OUTPUT,))
    assert (high.speed, high.row, high.comments) == (30.0, 2, (NOT_FOUND,))


def test_no_table_is_a_machine_file_error() -> None:
    with pytest.raises(MachineDefinitionError, match="needs a table of speeds"):
        check_ascending(standard_machine(), (), "spindle type 8")


def test_spindle_off_without_m05_is_a_comment_and_no_empty_block() -> None:
    """MACH24 has no TABLEM(6): comment 22 and nothing on the tape."""
    machine = get_plugins().machine("mach24").load()
    result = post(["SPINDL/200", "SPINDL/OFF"], machine)
    assert tape_lines(result.blocks) == ["N001S03"]
    assert [d.text for d in result.diagnostics][-1].startswith("REQUESTED MISCELLANEOUS")


def test_sfm_on_a_circle_in_one_block_is_built() -> None:
    """SFM on quadrant circles is built (tests/test_spindle_wave3.py); a control taking the
    whole arc in one block (option 253) takes it as whole arcs between the shift points
    (tests/test_modern_forms_wave9.py): the quarter circle turns pi / 2 in all."""
    base = get_plugins().machine("mach04").load()
    machine = load_machine_text('[machine]\nname = "m"\n[optab]\n253 = 1.0\n', "m.toml", base=base)
    result = post(
        ["FROM/5,2,0", "FEDRAT/10,RANGE,1", "SPINDL/100,SFM", "CIRCLE/5,0,0,0,0,1,2", "GOTO/3,0,0"],
        machine,
    )
    sweeps = [b.sweep or 0.0 for b in result.blocks if abs(int(b.code)) == 10]
    assert len(sweeps) > 1 and sum(sweeps) == pytest.approx(1.5707963267948966)  # pi / 2
