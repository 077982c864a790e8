"""Canned cycles expanded on contouring machines without control cycles
(docs/research/cycles.md), from hand-made statements and on the corpus: Creo's peck
drilling on MACH23 and APT IV's CYCLE/DRILL on the Standard Machine."""

from __future__ import annotations

import pytest
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.cl.records import Statement
from gecent.core.dispatch.post import post as post_file
from gecent.core.errors import InputError
from gecent.core.machine.loader import load_machine_text
from gecent.core.motion.cycles import Cycle, cycle_legs, parse_cycle
from gecent.core.output.tape import tape_lines
from gecent.core.plugins import get_plugins

from .conftest import SHARED
from .test_post_linear import post

CORPUS = SHARED / "corpus"
needs_corpus = pytest.mark.skipif(not CORPUS.is_dir(), reason="shared corpus not present")


def statement(text: str) -> Statement:
    record = next(iter(AptSourceReader("c.apt").read_lines([text])))
    assert isinstance(record, Statement)
    return record


def parse(text: str) -> Cycle | None:
    return parse_cycle(statement(text), lambda note: None)


def test_apt_fixed_form_and_creo_couplets_read_alike() -> None:
    fixed = parse("CYCLE/DRILL,0.5,IPM,3.0,0.1")
    couplets = parse("CYCLE/DRILL,DEPTH,0.5,IPM,3.0,CLEAR,0.1")
    assert fixed == couplets
    assert fixed is not None and (fixed.depth, fixed.clearance) == (0.5, 0.1)
    deep = parse("CYCLE/DEEP,DEPTH,3.5,STEP,1.0,MMPM,50.0,CLEAR,1.0")
    assert deep is not None and (deep.kind, deep.step, deep.clearance) == ("DEEP", 1.0, 1.0)
    assert parse("CYCLE/OFF") is None


@pytest.mark.parametrize(
    ("text", "error"),
    [
        ("CYCLE/DRILL,IPM,3", InputError),  # no depth
        ("CYCLE/DRILL,0.5,0.1,7", InputError),  # a value left over
        ("CYCLE/DRILL,DEPTH", InputError),
        ("CYCLE/SPIRAL,1", InputError),  # (not yet supported until wave 7: not a GECENT cycle)
        ("CYCLE/DRILL,1,ORIENT", InputError),
    ],
)
def test_malformed_or_unbuilt_cycles(text: str, error: type[Exception]) -> None:
    with pytest.raises(error):
        parse(text)


def test_peck_drilling_counts_steps_from_the_hole_top() -> None:
    """DEEP, depth 3.5 below a top at 0.5, step 1, clear 1: R = 1.5; pecks to -0.5, -1.5,
    -2.5 and the bottom -3.0, each from R and back to R at rapid."""
    cycle = Cycle("DEEP", 3.5, 1.0, step=1.0)
    legs = cycle_legs(cycle, (0.0, 0.0, 2.0), (0.0, 0.0, 0.5), 2.0)
    assert [(leg.point[2], leg.rapid) for leg in legs] == [
        (1.5, True),
        (-0.5, False),
        (1.5, True),
        (-1.5, False),
        (1.5, True),
        (-2.5, False),
        (1.5, True),
        (-3.0, False),
        (1.5, True),
    ]


def test_tapping_reverses_the_spindle_for_the_way_out() -> None:
    """TAP: feed in, M04 (TABLEM(5)) with the feed out to R, M03 (TABLEM(4)) waiting for
    the next block."""
    program = [
        "SPINDL/100,CLW",
        "FROM/0,0,1",
        "FEDRAT/10",
        "CYCLE/TAP,0.5,IPM,2.0,0.1",
        "GOTO/0,0,0",
        "CYCLE/OFF",
        "GOTO/0,0,1",
    ]
    assert tape_lines(post(program).blocks) == [
        "N001S610M03",
        "N005G01Z-09F500",  # rapid to R = 0.1
        "N005Z-06F033",  # tap to -0.5 at 2 IPM: 10 x 2 / 0.6
        "N005Z+06M04",  # out with the spindle reversed
        "N007Z+09F022M03",  # M03 waits for the next block; the cycle feed stays
    ]


def test_boring_feeds_out_and_face_dwells_at_the_bottom() -> None:
    bore = cycle_legs(Cycle("BORE", 1.0, 0.1), (0.0, 0.0, 0.1), (0.0, 0.0, 0.0), 0.1)
    assert [(leg.point[2], leg.rapid) for leg in bore] == [(0.1, True), (-1.0, False), (0.1, False)]
    face = cycle_legs(Cycle("FACE", 1.0, 0.1, dwell=2.0), (0, 0, 0.1), (0, 0, 0), 0.1)
    assert face[-1].dwell == 2.0 and face[-1].rapid


def test_return_levels() -> None:
    """RETURN absent: R; RETURN,0: the height of the first cycle point; RETURN,e: top + e."""
    at, hole = (0.0, 0.0, 2.0), (1.0, 0.0, 0.0)
    assert cycle_legs(Cycle("DRILL", 1, 0.1), at, hole, 2.0)[-1].point[2] == 0.1
    assert cycle_legs(Cycle("DRILL", 1, 0.1, return_level=0), at, hole, 2.0)[-1].point[2] == 2.0
    assert cycle_legs(Cycle("DRILL", 1, 0.1, return_level=0.5), at, hole, 2.0)[-1].point[2] == 0.5


def test_a_control_with_its_own_drilling_cycle_but_no_r_plane_code_drills_by_moves() -> None:
    # was NotYetSupported (incremental dimensions); wave 9 builds G91's block, and this
    # control, with no G99 (TABLEG(126)), has the cycle drilled by moves
    text = '[machine]\nname = "g81"\ntitle = "G81 MILL"\n[tableg]\n82 = 81\n'
    machine = load_machine_text(text, "g81.toml")
    result = post(["CYCLE/DRILL,0.5,IPM,3,0.1"], machine)
    assert [d.text for d in result.diagnostics] == [
        "CYCLE/DRILL IS DRILLED BY MOVES: NO RETURN CODE TABLEG(126)"
    ]


BOHREN_ON_MACH23 = [
    "MFG0004",
    "N011G04M03",
    "N013G11X-002846Y-009055Z+000787F066",
    "N015G11Z-000196F402",  # rapid to R (+1 mm): a fresh rapid, held by the tape reader
    "N015G11Z-000788F025",  # peck to -0.5 mm at 50 mm/min
    "N015G11Z+000788F400",
    "N015G11Z-001182F017",  # -1.5 mm
    "N015G11Z+001182F400",
    "N015G11Z-001575F012",  # -2.5 mm
    "N015G11Z+001575F381",
    "N015G11Z-001772F011",  # the bottom, -3.0 mm
    "N015G11Z+001772F339",  # back to R
    "N016G11X-00376F160",  # the second hole, at R
    "N016G11Z-000788F025",
    "N016G11Z+000788F400",
    "N016G11Z-001182F017",
    "N016G11Z+001182F400",
    "N016G11Z-001575F012",
    "N016G11Z+001575F381",
    "N016G11Z-001772F011",
    "N016G11Z+001772F339",
    "N019G11Z+000196F402",
    "N020G04M05",
]


@needs_corpus
def test_creo_peck_drilling_on_mach23() -> None:
    """creo/bohren_1.ncl.8: CYCLE/DEEP,DEPTH,3.5,STEP,1,MMPM,50,CLEAR,1 at two holes whose
    tops are at 0.5 mm, in inches on MACH23; hand-derived in docs/research/cycles.md §3.1."""
    plugins = get_plugins()
    result = post_file(str(CORPUS / "creo/bohren_1.ncl.8"), plugins, plugins.machine("23").load())
    assert tape_lines(result.blocks) == BOHREN_ON_MACH23


@needs_corpus
def test_apt4_pp_words_post_on_the_standard_machine() -> None:
    """apt4/test3_ppwords.cl3: every statement of its part program, tool to END."""
    plugins = get_plugins()
    result = post_file(str(CORPUS / "apt4/test3_ppwords.cl3"), plugins)
    assert tape_lines(result.blocks) == [
        "TEST3PPWORDS",
        "N006G04X+05T02",  # LOADTL/2: option-83 dwell carrying T
        "N010S630M03",  # SPINDL/1200: above the table's 300 RPM
        "N016M08",  # COOLNT/ON forced out before FROM
        "N020G01X+1Y+1Z-19F500",  # RAPID to the first hole's clearance
        "N026Z-06F050",  # CYCLE/DRILL,0.5,IPM,3,0.1: 10 x 3 IPM / 0.6 in
        "N026Z+06F500",
        "N028X+1",
        "N028Z-06F050",
        "N028Z+06F500",
        "N030Y+1",
        "N030Z-06F050",
        "N030Z+06F500",
        "N036X-2Y-2Z+19",  # RAPID after CYCLE/OFF, from R
        "N040M09",  # COOLNT/OFF pushed out by SPINDL/OFF's M05
        "N040M05",
        "N042G04X+025",  # DELAY/2.5
        "N044M01",  # OPSTOP
        "N999M00",  # INSERT
        "N010M02",  # SEQNO/10,INCR,5 then END
        "(" * 72,  # option 11 = +1 filler card
    ]
    assert [d.text for d in result.diagnostics] == [
        "MACHIN/MILL names another postprocessor; ignored",
        "SPINDLE SPEED COULD NOT BE FOUND.",
    ]
