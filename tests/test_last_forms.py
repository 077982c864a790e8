"""Issue 22, wave 5: the last small "not yet supported" statement forms, each decided from
the manual (docs/decisions.md, "Last statement forms, wave 5"):

* TURRET on a positioning machine: the manual's TURRET is the contouring lathe's ("the
  TURRET statement (contouring)", option 96, 001 L25532); bad input naming ROTATE/TURRET.
* SPINDL/DWELL: the manual names the word and its flag IDWLFL (001 L17348-17352) but no G
  code cell and no time for it; bad input naming why.
* ROTATE/TABLE with both a move and a speed: ROTABL sends a speed to TABSPD (a spinning
  table) and a move to ROTABI/ROTABA (001 L36012-36053); bad input, give two statements.
* ROTATE/TORCH on a multiaxis machine: its rotary axes follow the tool axis (GEMAXS); bad
  input, while a two-axis flame cutter still turns its torch (ROTORC).
"""

from __future__ import annotations

from pathlib import Path

import pytest
from gecent.core.errors import InputError
from gecent.core.output.block import Code

from tests.test_multiaxis_rotref import FROM, mach40, moves
from tests.test_multiaxis_rotref import run as post_multiaxis
from tests.test_post_linear import post
from tests.test_rotary_positioning import machine as positioning_table
from tests.test_rotary_wave3 import flame, torch_values
from tests.test_spindle_wave3 import mach04
from tests.test_tools_manual import lathe, positioning


def test_turret_on_a_positioning_machine_is_bad_input() -> None:
    with pytest.raises(
        InputError, match=r"contouring lathe's statement \(option 96\).*ROTATE/TURRET"
    ):
        post(["FROM/0,0,0", "TURRET/2,2,1,1,NOW"], positioning(0.0))


def test_turret_on_the_lathe_still_indexes() -> None:
    """The same statement on the contouring lathe is the manual's TURRET (no error)."""
    result = post(["FROM/0,0,0", "TURRET/1,1,2,3,NOW"], lathe())
    assert any(b.code is not Code.COMMENT for b in result.blocks)


@pytest.mark.parametrize("statement", ["SPINDL/100,DWELL", "SPINDL/DWELL", "SPINDL/100,CLW,DWELL"])
def test_spindl_dwell_is_bad_input_naming_why(statement: str) -> None:
    with pytest.raises(
        InputError, match=r"SPINDL/DWELL.*IDWLFL.*no G code cell and no time.*DELAY"
    ):
        post([statement], mach04())


def test_spindl_without_dwell_still_turns() -> None:
    result = post(["SPINDL/100,CLW"], mach04())
    assert any(b.cells[12] is not None for b in result.blocks)


@pytest.mark.parametrize(
    "statement",
    [
        "ROTATE/TABLE,INCR,90,CLW,RPM,5",
        "ROTATE/TABLE,ATANGL,45,RANGE,1",
        "ROTATE/TABLE,OFF,INCR,10",
    ],
)
def test_table_move_with_speed_is_bad_input(statement: str) -> None:
    with pytest.raises(InputError, match=r"ROTATE/TABLE takes a move .* or a speed .*not both"):
        post([statement], positioning_table())


def test_table_move_with_speed_is_bad_input_on_a_multiaxis_machine(tmp_path: Path) -> None:
    lines = [FROM, "FEDRAT/10", "ROTATE/TABLE,INCR,2,CLW,RPM,5"]
    with pytest.raises(InputError, match=r"\(RPM with a move\)"):
        post_multiaxis(tmp_path, lines, mach40())


def test_table_move_alone_still_turns(tmp_path: Path) -> None:
    result = post_multiaxis(tmp_path, [FROM, "FEDRAT/10", "ROTATE/TABLE,INCR,2,CLW"], mach40())
    assert moves(result)


def test_torch_on_a_multiaxis_machine_is_bad_input(tmp_path: Path) -> None:
    lines = [FROM, "FEDRAT/10", "ROTATE/TORCH,INCR,10"]
    with pytest.raises(InputError, match=r"ROTATE/TORCH on a multiaxis machine.*tool axis"):
        post_multiaxis(tmp_path, lines, mach40())


def test_torch_on_a_flame_cutter_still_turns() -> None:
    assert torch_values(post(["ROTATE/TORCH,INCR,30"], flame())) == [30.0]
