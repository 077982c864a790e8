"""Spec 02 (§5.0-5.4.3: the state model and the processing flow): the numeric facts the
range states and the digest's illustrative computations (spec 02 §11), as golden tests.

The range has no worked numeric example of its own (spec 02 §11); these tests hold the
facts it prints (DMBITS, DBFSEG's order, ISPTYP, the Type 6000 capture of flow chart 4)
and the digest's computations that follow from them (§11.2), each with its seed lines.
"""

from __future__ import annotations

import pytest
from gecent.core.absent import ABSENT, DMBITS_VALUE
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.machine.loader import standard_machine
from gecent.core.output.block import Block, Code
from gecent.core.output.tape import tape_lines
from gecent.core.run import Run

from tests.test_post_linear import post


def test_dmbits_is_minus_40404040_and_an_empty_cell_holds_nothing() -> None:
    """DMBITS "equal to -40404040.0" (001 L16920-16922), DPBITS its plus value (L16930-16933):
    a new block's cells hold nothing, and the sentinel refuses to be read as a number."""
    assert DMBITS_VALUE == -40404040.0
    assert -DMBITS_VALUE == 40404040.0
    block = Block(Code.LINEAR, 1)
    assert all(cell is ABSENT for cell in block.cells)
    with pytest.raises(TypeError):
        bool(ABSENT)


def test_dbfseg_cells_are_the_register_order_n_g_x_to_m() -> None:
    """DBFSEG order (001 L16854-16860): 1 N, 2 G, 3 X, 4 Y, 5 Z, 6 A, 7 B, 8 I, 9 J, 10 K,
    11 F, 12 S, 13 T, 14 M; 15 is CODE, which has no letter."""
    letters = standard_machine().registers.letters
    assert letters[1:16] == (*"NGXYZABIJKFSTM", "")


def test_option_19_equal_3_is_spindle_type03() -> None:
    """ISPTYP = "option 19 plus 1" (001 L17598-17601), a 1-based index into TYPE00-TYPE19:
    option 19 = 3 -> ISPTYP 4 -> TYPE03, whose restriction reads OPTAB(19) = 3 (L39282)."""
    run = Run(standard_machine().with_options({19: 3.0}))
    assert type(run.spindle.spindle_type).__module__ == "gecent.plugins.spindles.type03"


def test_a_departure_of_exactly_option_4_is_one_block_one_step_more_is_two() -> None:
    """BIGDEP is option 4 and DMS = BIGDEP - STEP (001 L16703, L16925-16928): on the Standard
    Machine (9.9999, step 0.0001) a move of 9.9999 is one block; 10.0000 is one step too long
    and goes out in two halves (SEGMNT)."""
    machine = standard_machine()
    assert machine.number_option(4) == 9.9999 and machine.number_option(14) == 0.0001
    one = tape_lines(post(["FROM/0,0,0", "FEDRAT/10", "GOTO/9.9999,0,0"]).blocks)
    two = tape_lines(post(["FROM/0,0,0", "FEDRAT/10", "GOTO/10,0,0"]).blocks)
    assert one == ["N003G01X+99999F010"]
    assert two == ["N003G01X+5F020", "N003X+5"]


def test_type_6000_records_give_the_tolerances_and_the_cutter() -> None:
    """Flow chart 4 (001 L19483-19553, L3544-3614): subtype 4 -> TOLIN, 5 -> TOLOUT,
    6 -> CUTRAD = D/2 and CUTTER = 1 (ball tool) when the corner radius is D/2."""
    run = Run(standard_machine())
    program = ["INTOL/0.001", "OUTTOL/0.002", "CUTTER/0.5,0.25", "FINI"]
    run.process(AptSourceReader("part.apt").read_lines(program))
    tolerances = run.state.tolerances
    assert (tolerances.inside, tolerances.outside) == (0.001, 0.002)
    assert tolerances.cutter_radius == 0.25 and tolerances.ball
    flat = Run(standard_machine())
    flat.process(AptSourceReader("part.apt").read_lines(["CUTTER/0.5", "FINI"]))
    assert flat.state.tolerances.cutter_radius == 0.25 and not flat.state.tolerances.ball


def test_opskip_record_240_is_n_minus_240_punched_after_the_skip_code() -> None:
    """Spec 02 §11.2, from SEQCTR (option 143 = 0, 001 L18316) and OPSKIP (FC 8): OPSKIP on,
    CL record 240 -> DBFSEG(1) = -240; the punch writes the skip code, then N240."""
    machine = standard_machine().with_options({30: 1.0})  # the control has block delete
    fillers = ["FEDRAT/10"] * 236  # records 4..239 output nothing
    result = post(["OPSKIP/ON", "FROM/0,0,0", "FEDRAT/10", *fillers, "GOTO/1,0,0"], machine)
    motion = [block for block in result.blocks if block.punch]
    assert [block.cells[1] for block in motion] == [-240.0]
    assert [block.punch for block in motion] == ["/N240G01X+1F100"]
