"""GEPLAD, the planning pre-pass of MACHIN/GECENT,n,PLAN on a positioning machine (manual
§2.2.2 C, 001 L473-476; the overlay list, 001 L311-318; core/plan.py; docs/decisions.md
"issue 22 wave 7"): the holes of each cycle run in nearest-neighbour order, the tool setups and the
table travel as notes, the planned tape numbered afresh."""

from __future__ import annotations

from pathlib import Path

from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.cl.records import Motion, Statement
from gecent.core.dispatch.post import post
from gecent.core.output.tape import tape_lines
from gecent.core.plan import geplad
from gecent.core.plugins import get_plugins

HOLES = [
    "FROM/0,0,5",
    "LOADTL/3",
    "CYCLE/DRILL,DEPTH,0.6,IPM,6,CLEAR,0.1",
    "GOTO/5,0,0",
    "GOTO/1,0,0",
    "GOTO/4,0,0",
    "GOTO/2,0,0",
    "GOTO/3,0,0",
    "CYCLE/OFF",
    "GOTO/0,0,5",
]


def posted(tmp_path: Path, machin: str, body: list[str]) -> tuple[list[str], list[str]]:
    source = tmp_path / "p.apt"
    source.write_text("\n".join(["PARTNO PLAN", machin, *body, "FINI"]) + "\n")
    result = post(str(source), get_plugins())
    return tape_lines(result.blocks), [d.text for d in result.diagnostics]


def test_plan_puts_the_holes_in_nearest_order_and_numbers_them_afresh(tmp_path: Path) -> None:
    """MACH24 (option 1 = +1): the five holes along X go out 1, 2, 3, 4, 5 from the table at
    0, with the N words climbing; the travel falls from 15 (5+4+3+2+1) to 5."""
    tape, notes = posted(tmp_path, "MACHIN/GECENT,24,PLAN", HOLES)
    assert tape[tape.index("N006G81Z+056000F12R+049") :] == [
        "N006G81Z+056000F12R+049",
        "N006X+010000Y+000000",
        "N007X+020000",
        "N008X+030000",
        "N009X+040000",
        "N010X+050000",
        "N012G80X+000000",
    ]
    assert "GEPLAD TOOL SETUP 1: LOADTL/3, 5 HOLES" in notes
    assert "GEPLAD: TABLE TRAVEL BETWEEN HOLES 15.0000 AS PROGRAMMED, 5.0000 AS PLANNED" in notes


def test_without_plan_the_holes_keep_their_programmed_order(tmp_path: Path) -> None:
    tape, notes = posted(tmp_path, "MACHIN/GECENT,24", HOLES)
    first = tape.index("N006G81Z+056000F12R+049")
    assert tape[first + 1 : first + 6] == ["N006X+050000Y+000000", "N007X+010000", "N008X+040000",
                       "N009X+020000", "N010X+030000"]  # fmt: skip
    assert not any("GEPLAD" in n for n in notes)


def test_plan_on_a_contouring_machine_is_ignored_with_a_note(tmp_path: Path) -> None:
    _, notes = posted(tmp_path, "MACHIN/GECENT,23,PLAN", ["FROM/0,0,0", "GOTO/1,0,0"])
    assert any("PLAN IGNORED: OPTION 1 = 0, NOT +1" in n for n in notes)


def test_a_later_plan_is_ignored_here(tmp_path: Path) -> None:
    """GEMON asks for GEPLAD once, before the run (IGEFLG, 001 L17369-17375)."""
    _, notes = posted(tmp_path, "MACHIN/GECENT,24", ["FROM/0,0,5", "MACHIN/GECENT,24,PLAN"])
    assert any("PLAN IGNORED HERE: GEPLAD PLANS THE CL TAPE ONCE" in n for n in notes)


def records(lines: list[str]) -> list:
    return list(AptSourceReader("part.apt").read_lines([*lines, "FINI"]))


def test_only_holes_at_one_height_under_a_cycle_are_reordered() -> None:
    """A new hole-top height, a statement or CYCLE/OFF ends a run; moves outside a cycle
    and the statements keep their places; a hole's comment goes with it."""
    tape = geplad(
        records(
            [
                "MACHIN/GECENT,24,PLAN",
                "FROM/0,0,5",
                "GOTO/9,9,5",
                "GOTO/0,0,5",
                "CYCLE/DRILL,DEPTH,1,IPM,6",
                "GOTO/3,0,0",
                "$$ THE FAR ONE",
                "GOTO/2,0,0",
                "GOTO/8,0,-1",
                "GOTO/7,0,-1",
                "FEDRAT/4",
                "GOTO/0,1,-1",
                "GOTO/1,0,-1",
                "CYCLE/OFF",
            ]
        )
    )
    motions = [r.points[0] for r in tape.records if isinstance(r, Motion)]
    assert [p[:2] for p in motions] == [
        (0, 0), (9, 9), (0, 0), (2, 0), (3, 0), (7, 0), (8, 0), (1, 0), (0, 1)
    ]  # fmt: skip
    machin = tape.records[0]
    assert isinstance(machin, Statement) and machin.words() == ("GECENT",)
    numbers = [r.number for r in tape.records]
    assert numbers == sorted(numbers)
    lines = [r.line for r in tape.records]
    assert lines.index(7) == lines.index(8) - 1  # the comment (line 7) before its hole (8)
    # as programmed from 0,0: 3, 2 | 8, 7 | (0,1), 1; as planned: 2, 3 | 7, 8 | 1, (0,1)
    assert tape.travel_programmed == 3 + 1 + 6 + 1 + 50**0.5 + 2**0.5
    assert tape.travel_planned == 2 + 1 + 4 + 1 + 7 + 2**0.5
