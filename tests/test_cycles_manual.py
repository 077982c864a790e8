"""The manual's cycle words beyond the plain types (issue 22 D): BORE's DWELL, DRAG and MANUAL
forms (TABLEG 91-95, 001 L22895-22977), OUT and IN (TABLEG 89/90), INHIBT (CYCLGP's word
list, 001 L30126), the lathe's CYCLEL block (001 L30038-30093), a lathe drilling along its
spindle axis (options 59/60, spec 08 W-13), and the control's dwelling cycles (G82, G89)."""

from __future__ import annotations

from pathlib import Path

import pytest
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.cl.records import Statement
from gecent.core.dispatch.post import post as post_file
from gecent.core.errors import Diagnostic, InputError
from gecent.core.machine.loader import load_machine_text
from gecent.core.machine.selection import resolve_machine
from gecent.core.motion.cycles import Cycle, cycle_legs, parse_cycle
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins

from .test_post_linear import post, tape

SPINDLE_ON = ["SPINDL/100,CLW", "FROM/0,0,1", "FEDRAT/10"]


def parsed(text: str, notes: list[Diagnostic] | None = None) -> Cycle | None:
    record = next(iter(AptSourceReader("c.apt").read_lines([text])))
    assert isinstance(record, Statement)
    return parse_cycle(record, (notes if notes is not None else []).append)


def pack_tape(tmp_path: Path, text: str, machine: object) -> list[str]:
    source = tmp_path / "part.apt"
    source.write_text(text)
    return tape_lines(post_file(str(source), get_plugins(), machine).blocks)  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("text", "kind", "dwell"),
    [
        ("CYCLE/BORE,DRAG,0.5,IPM,2,0.1", "BORE,DRAG", 0.0),
        ("CYCLE/BORE,MANUAL,0.5,IPM,2,0.1", "BORE,MANUAL", 0.0),
        ("CYCLE/BORE,DWELL,DRAG,0.5,IPM,2,0.1", "BORE,DWELL,DRAG", 0.0),
        ("CYCLE/BORE,DRAG,DWELL,0.5,IPM,2,0.1", "BORE,DWELL,DRAG", 0.5),  # DWELL's time
        ("CYCLE/BORE,MANUAL,DEPTH,1,DWELL,2", "BORE,DWELL,MANUAL", 2.0),
        ("CYCLE/BORE,DEPTH,1,DWELL,1.5", "BORE,DWELL", 1.5),  # Creo's DWELL,t too
        ("CYCLE/BORE,DWELL,DEPTH,1,DWELL,3", "BORE,DWELL", 3.0),
        ("CYCLE/OUT,DEPTH,1,CLEAR,0.1", "OUT", 0.0),
        ("CYCLE/IN,CLEAR,0.1", "IN", 0.0),  # a withdrawal needs no depth
    ],
)
def test_bore_forms_out_and_in_are_read(text: str, kind: str, dwell: float) -> None:
    cycle = parsed(text)
    assert cycle is not None and (cycle.kind, cycle.dwell) == (kind, dwell)


@pytest.mark.parametrize(
    "text",
    [
        "CYCLE/BORE,DRAG,MANUAL,DEPTH,1",  # two ways out
        "CYCLE/BORE,DRAG,DRAG,DEPTH,1",
        "CYCLE/DRILL,DRAG,DEPTH,1",  # DRAG belongs to BORE
        "CYCLE/OUT,CLEAR,1",  # OUT goes in: it needs a depth
        "CYCLE/INHIBT,1",
        "CYCLE/BORE,DEPTH,1,DWELL,-1",
    ],
)
def test_malformed_forms_are_input_errors(text: str) -> None:
    with pytest.raises(InputError):
        parsed(text)


def test_inhibt_suspends_the_cycle_as_off_and_says_so() -> None:
    notes: list[Diagnostic] = []
    assert parsed("CYCLE/INHIBT", notes) is None
    assert ["INHIBT" in note.text for note in notes] == [True]


def test_drag_stops_the_spindle_for_the_way_out_and_starts_it_after() -> None:
    """TABLEG 91: feed to Z, stop the spindle, rapid to R; the spindle turns again with the
    next block (as TAP's M03)."""
    legs = cycle_legs(Cycle("BORE,DRAG", 1.0, 0.1), (0.0, 0.0, 0.1), (0.0, 0.0, 0.0), 0.1)
    assert [(leg.point[2], leg.rapid, leg.m_code_cell) for leg in legs] == [
        (0.1, True, None),
        (-1.0, False, None),
        (0.1, True, 6),
        (0.1, True, 4),
    ]
    assert tape(
        [*SPINDLE_ON, "CYCLE/BORE,DRAG,0.5,IPM,2.0,0.1", "GOTO/0,0,0", "CYCLE/OFF", "GOTO/0,0,1"]
    ) == [
        "N001S610M03",
        "N005G01Z-09F500",  # rapid to R = 0.1
        "N005Z-06F033",  # bore to -0.5 at 2 IPM
        "N005Z+06F500M05",  # out at rapid, the spindle stopped
        "N007Z+09F022M03",  # turning again with the next block
    ]


def test_manual_stops_spindle_and_program_in_blocks_of_their_own() -> None:
    """TABLEG 95 (BORE,DWELL,MANUAL): feed to Z, dwell, stop the spindle; M00 lets the operator
    take the tool out; the program then comes out at rapid with the spindle on. The dwell is
    DW-1's (001 L16305-16329): 4 s over option 56 = 10 in the option-57 register X, X04 (the
    Standard Machine's X carries its sign)."""
    lines = tape(
        [
            *SPINDLE_ON,
            "CYCLE/BORE,DWELL,MANUAL,DEPTH,0.5,IPM,2.0,CLEAR,0.1,DWELL,4",
            "GOTO/0,0,0",
            "CYCLE/OFF",
            "GOTO/0,0,1",
        ]
    )
    assert lines == [
        "N001S610M03",
        "N005G01Z-09F500",
        "N005Z-06F033",
        "N005G04X+04",
        "N005M05",
        "N005M00",
        "N005G01Z+06F500M03",
        "N007Z+09F022",
    ]


def test_bore_dwell_feeds_out_after_its_dwell() -> None:
    legs = cycle_legs(Cycle("BORE,DWELL", 1.0, 0.1, dwell=2.0), (0, 0, 0.1), (0, 0, 0), 0.1)
    assert [(leg.point[2], leg.rapid, leg.dwell) for leg in legs][-1] == (0.1, False, 2.0)


def test_out_stays_at_the_bottom_and_in_withdraws_then_moves_across() -> None:
    lines = tape(
        [
            *SPINDLE_ON,
            "CYCLE/OUT,0.5,IPM,2.0,0.1",
            "GOTO/0,0,0",
            "CYCLE/IN,CLEAR,0.1",
            "GOTO/1,0,0",
            "CYCLE/OFF",
            "GOTO/1,0,1",
        ]
    )
    assert lines == [
        "N001S610M03",
        "N005G01Z-09F500",  # rapid to R
        "N005Z-06F033",  # in to -0.5, and stays
        "N007Z+06F500",  # IN: out to R = 0.1 at rapid first
        "N007X+1",  # then across at that level
        "N009Z+09F022",
    ]
    legs = cycle_legs(Cycle("IN", 0.0, 0.1), (0.0, 0.0, 2.0), (0.0, 0.0, 0.0), 2.0)
    assert [leg.point for leg in legs] == [(0.0, 0.0, 2.0)]  # never deeper than it is


def test_a_lathe_drills_along_its_spindle_axis() -> None:
    """MACH04's option 59 is 152300, +Z-X (spec 08 W-13: "a lathe is +Z-X = pairs 15, 23"):
    CL x is the spindle axis. A hole at x = 2 with DEPTH 1, CLEAR 0.1: in to x = 2.1 at rapid,
    to x = 1 at 0.005 IPR (100 RPM: 0.5 IPM), back to 2.1. Before, the expansion drilled
    along CL z, which a lathe does not output, and only moved to x = 2."""
    lines = tape(
        [
            "MACHIN/GECENT,4",
            "SPINDL/100,CLW",
            "FROM/5,0,0",
            "FEDRAT/10",
            "CYCLE/DRILL,DEPTH,1.0,IPR,0.005,CLEAR,0.1",
            "GOTO/2,0,0",
            "CYCLE/OFF",
            "GOTO/5,0,0",
        ],
        resolve_machine(get_plugins(), "mach04", None),
    )
    assert lines == [
        "N002G04S610M60",
        "N006G01Z-29F34483M40",  # rapid 5 -> 2.1
        "N006G01Z-11F00455M41",  # drill to 1.0 at 0.5 IPM
        "N006G01Z+11F750M40",  # back to R
        "N008G01Z+29F00172M41",
    ]


def test_a_lathe_with_the_cycle_code_puts_it_in_a_block_by_itself() -> None:
    """CYCLEL: the G code alone (001 L30049-30072); the points are plain moves for the
    control; CYCLE/OFF is TABLEG(1)."""
    lathe = load_machine_text(
        '[machine]\nname = "g81lathe"\ntitle = "G81 LATHE"\n[tableg]\n1 = 80\n82 = 81\n'
        "[optab]\n132 = 0\n59 = 152300\n60 = 181600\n"
    )
    result = post(
        [
            "SPINDL/100,CLW",
            "FROM/5,0,0",
            "FEDRAT/10",
            "CYCLE/DRILL",
            "GOTO/2,0,0",
            "CYCLE/OFF",
            "GOTO/5,0,0",
        ],
        lathe,
    )
    lines = tape_lines(result.blocks)
    assert lines[1:] == ["N004G81", "N005G01Z-3F033", "N006G80", "N007G01Z+3"]
    notes = post(["FROM/5,0,0", "CYCLE/DRILL,DEPTH,1,CLEAR,0.1", "GOTO/2,0,0"], lathe).diagnostics
    assert any("DEPTH, CLEAR NOT OUTPUT" in note.text for note in notes)


def test_a_cycle_on_a_machine_without_z_is_bad_input() -> None:
    """No axis to drill along: the plunge would go out on no register (issue 22)."""
    flat = load_machine_text('[machine]\nname = "xy"\ntitle = "XY"\n[optab]\n59 = 131400\n')
    with pytest.raises(InputError, match="no Z axis"):
        post(["FROM/0,0,1", "CYCLE/DRILL,1,IPM,2,0.1", "GOTO/0,0,0"], flat)


def test_drag_on_a_machine_without_a_spindle_stop_is_comment_22() -> None:
    # was NotYetSupported; wave 9: STOREM's comment 22 (tests/test_cycles_wave9.py)
    no_stop = load_machine_text('[machine]\nname = "m"\ntitle = "M"\n[tablem]\n6 = "absent"\n')
    result = post(["CYCLE/BORE,DRAG,1,IPM,2,0.1"], no_stop)
    assert [d.text for d in result.diagnostics] == [
        "REQUESTED MISCELLANEOUS FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE"
    ]


BORE_DWELL = (
    "PARTNO T\nUNITS/MM\nFROM/0,0,10\nFEDRAT/100\nSPINDL/1000,CLW\n"
    "CYCLE/BORE,DEPTH,5,CLEAR,2,DWELL,1.5,MMPM,50\nGOTO/1,1,0\nCYCLE/OFF\nFINI\n"
)


def test_a_control_bores_with_a_dwell_by_its_g89(tmp_path: Path) -> None:
    """TABLEG 94, feed to Z, dwell, feed to R: LinuxCNC's and Fanuc's G89, with P in the
    option-57 register (as G82's)."""
    plugins = get_plugins()
    base = resolve_machine(plugins, "linuxcnc-mill", None)
    g89 = load_machine_text(
        '[machine]\nname = "g89"\ntitle = "G89"\n[tableg]\n94 = 89\n', base=base
    )
    lines = pack_tape(tmp_path, BORE_DWELL, g89)
    cycle = next(line for line in lines if "G89" in line)
    assert "Z-5." in cycle and "R2." in cycle and "P1.5" in cycle
    assert any(line.endswith("G80") for line in lines)
    # the pack has no G89: drilled by moves (issue 22, tests/test_cycles_wave3.py)
    lines = pack_tape(tmp_path, BORE_DWELL, "linuxcnc-mill")
    assert "N5 G04 P1.5" in lines and not any("G89" in line for line in lines)


def test_what_the_control_cannot_drill_is_drilled_by_moves(tmp_path: Path) -> None:
    """A DRILL with a DWELL is G82: a control file without it has it drilled by moves; DEEP
    takes no P; OUT has no G-code control counterpart (issue 22: each drilled by moves, no
    cycle G code on the tape)."""
    plugins = get_plugins()
    base = resolve_machine(plugins, "linuxcnc-mill", None)
    no_g82 = load_machine_text(
        '[machine]\nname = "n"\ntitle = "N"\n[tableg]\n83 = "absent"\n', base=base
    )
    drill = BORE_DWELL.replace("CYCLE/BORE", "CYCLE/DRILL")
    deep = BORE_DWELL.replace("CYCLE/BORE", "CYCLE/DEEP")
    out = load_machine_text('[machine]\nname = "o"\ntitle = "O"\n[tableg]\n89 = 89\n', base=base)
    for text, machine in ((drill, no_g82), (deep, "linuxcnc-mill")):
        lines = pack_tape(tmp_path, text, machine)
        assert "N5 G04 P1.5" in lines and not any(" G8" in line for line in lines[3:])
    lines = pack_tape(tmp_path, BORE_DWELL.replace("CYCLE/BORE", "CYCLE/OUT"), out)
    assert lines[lines.index("N4 G01 Z-5. F50.") + 1] == "N5 G04 P1.5"  # and stays there
    assert not any("G89" in line for line in lines)


def test_inhibt_ends_a_control_cycle_with_g80(tmp_path: Path) -> None:
    text = BORE_DWELL.replace("CYCLE/BORE", "CYCLE/DRILL").replace(
        "CYCLE/OFF", "CYCLE/INHIBT\nGOTO/5,5,0"
    )
    lines = pack_tape(tmp_path, text, "linuxcnc-mill")
    index = next(k for k, line in enumerate(lines) if line.endswith("G80"))
    assert "G82" in lines[index - 1] and "Z0." in lines[index + 1]  # then a plain move


def test_positioning_refuses_in_and_a_bore_form_it_lacks() -> None:
    mach24 = resolve_machine(get_plugins(), "mach24", None)
    with pytest.raises(InputError, match="CYCLE/IN on a positioning machine"):
        post(["CYCLE/IN,CLEAR,0.1"], mach24)
    with pytest.raises(InputError, match=r"CYCLE/BORE,DRAG .*TABLEG\(91\)"):
        post(["CYCLE/BORE,DRAG,1,IPM,2,0.1"], mach24)
