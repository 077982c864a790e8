"""Issue 22, wave 6: ROTATE/TURRET (docs/decisions.md, "ROTATE/TURRET, wave 6").

ROTATE (RTATGB) sends ROTATE/TURRET to ROTDRF on a drafting machine and to ROTUR
otherwise (001 L36055-36095). ROTUR turns a positioning machine's spindle turret (overlay
GEPOS, L36345-36382): on a contouring machine the statement is bad input naming why (its
turret is the lathe's TURRET statement, option 96, L25532). On the machines that have the
routines they are built (issue 22 wave 7): tests/test_last_forms_wave7.py.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from gecent.core.errors import InputError

from tests.test_multiaxis_rotref import FROM, mach40, moves
from tests.test_multiaxis_rotref import run as post_multiaxis
from tests.test_post_linear import post
from tests.test_rotary_positioning import machine as positioning_table
from tests.test_statements_control import plotter
from tests.test_tools_manual import lathe, positioning


@pytest.mark.parametrize("statement", ["ROTATE/TURRET,1", "ROTATE/TURRET"])
def test_rotate_turret_on_a_contouring_mill_is_bad_input(statement: str) -> None:
    with pytest.raises(InputError, match=r"ROTATE/TURRET.*ROTUR.*contouring machine") as error:
        post(["FROM/0,0,0", statement])
    assert error.value.where is not None and error.value.where.line == 2


def test_rotate_turret_on_the_contouring_lathe_names_its_turret_statement() -> None:
    with pytest.raises(InputError, match=r"indexes its turret with TURRET/ \(option 96\)"):
        post(["FROM/0,0,0", "ROTATE/TURRET,2"], lathe())


def test_rotate_turret_on_a_multiaxis_machine_is_bad_input(tmp_path: Path) -> None:
    with pytest.raises(InputError, match=r"ROTATE/TURRET on a multiaxis machine.*ROTUR"):
        post_multiaxis(tmp_path, [FROM, "ROTATE/TURRET,1"], mach40())


@pytest.mark.parametrize("build", [lambda: positioning(0.0), positioning_table])
def test_rotate_turret_on_a_positioning_machine_is_rotur(build) -> None:  # type: ignore[no-untyped-def]
    """(Not yet supported until issue 22 wave 7 built ROTUR: tests/test_last_forms_wave7.py.)"""
    result = post(["FROM/0,0,0", "ROTATE/TURRET,1"], build())
    assert any(b.cells[13] == 1 for b in result.blocks)


def test_rotate_turret_on_a_drafting_machine_is_rotdrf() -> None:
    """(Not yet supported until wave 7 built ROTDRF: D3, tests/test_last_forms_wave7.py.)"""
    result = post(["FROM/0,0,0", "DRAFT/ON", "ROTATE/TURRET,1"], plotter())
    assert any(b.cells[16] == 3 for b in result.blocks)


def test_a_table_still_turns_beside_the_turret_branch(tmp_path: Path) -> None:
    """ROTATE/TABLE on the multiaxis machine is untouched by the TURRET branch."""
    result = post_multiaxis(tmp_path, [FROM, "FEDRAT/10", "ROTATE/TABLE,INCR,2,CLW"], mach40())
    assert moves(result)
