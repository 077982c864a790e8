"""Feed, spindle and rotary options of the catalogue (issue 22): 136 (the control restores
spindle and coolant after a stop), 35 (the assumed feed mode), 223 (the circular maximum
departure), 215 (type 5's increment between ranges), 149/150 (the head's rotation limits),
192 (the head's maximum RPM) and 224 (the 100S's metric I, J, K feed command). Seed
lines: 001 L25995-26007, L24823-24831, L26719-26728, L26661-26669, L26154-26166,
L26511-26516, L26729-26738."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import pytest
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.dispatch.post import post as post_file
from gecent.core.errors import MachineDefinitionError
from gecent.core.feed.limits import head_limited_feed
from gecent.core.feed.positioning import XY, FeedContext, Z
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.output.block import Code
from gecent.core.output.tape import tape_line, tape_lines
from gecent.core.plugins import get_plugins
from gecent.core.run import RunResult
from gecent.core.verify.clpath import cl_path

from tests.test_multiaxis_motion import PROGRAM, mach40_g10
from tests.test_post_linear import post
from tests.test_rotary import _all_codes, _with_a

# --- option 136: the control restores spindle and coolant after a stop ------------------

BEFORE_STOP = [
    "TOOLNO/3",
    "SPINDL/200,CLW",
    "COOLNT/ON",
    "FROM/0,0,0",
    "FEDRAT/10",
    "GOTO/1,0,0",
    "STOP",
]
HEAD = ["N001G04X+05T03", "N002S620M03", "N004M08", "N006G01X+1F100", "N007M00"]


def texts(result: RunResult) -> list[str]:
    return [d.text for d in result.diagnostics]


def test_option_136_leaves_spindle_and_coolant_to_the_control() -> None:
    """Option 145 = +1 reinstates tool, spindle and coolant after a stop (§4.7); with option
    136 = 1 the control turns spindle and coolant back on itself (L25995-26007), so only
    the tool comes back: no S/M03 block and no M08."""
    reinstating = standard_machine().with_options({145: 1.0})
    program = [*BEFORE_STOP, "GOTO/2,0,0"]
    assert tape_lines(post(program, reinstating).blocks)[5:] == [
        "N008T03",
        "N008S620M03",
        "N008X+1M08",
    ]
    restoring = reinstating.with_options({136: 1.0})
    assert tape_lines(post(program, restoring).blocks) == [*HEAD, "N008T03", "N008X+1"]


def test_option_136_keeps_the_spindle_turning_through_the_stop() -> None:
    """The spindle is still on after the stop under option 136 = 1, so a SPINDL/...,CCLW
    after it reverses a turning spindle (the warning); at option 136 = 0 the stop turned
    it off and CCLW just starts it. The new statement is output either way (it "takes
    precedence")."""
    program = [*BEFORE_STOP, "SPINDL/200,CCLW", "GOTO/2,0,0"]
    restored = post(program, standard_machine().with_options({136: 1.0}))
    assert tape_lines(restored.blocks)[5:] == ["N008S620M04", "N009X+1"]
    assert texts(restored) == ["WARNING--SPINDLE DIRECTION HAS CHANGED"]
    stopped = post(program, standard_machine())
    assert tape_lines(stopped.blocks)[5:] == ["N008S620M04", "N009X+1"]
    assert texts(stopped) == []


def test_option_136_also_covers_an_optional_stop() -> None:
    """OPSTOP (M01): whether the operator's switch stops there or not, spindle and coolant
    are in their former conditions when the program goes on (docs/decisions.md)."""
    program = [*BEFORE_STOP[:-1], "OPSTOP", "GOTO/2,0,0"]
    machine = standard_machine().with_options({145: 1.0, 136: 1.0})
    assert tape_lines(post(program, machine).blocks)[-2:] == ["N008T03", "N008X+1"]


# --- option 35: the assumed feed mode -----------------------------------------------------

FEEDS = [
    "SPINDL/200,CLW",
    "FROM/0,0,0",
    "FEDRAT/.05",
    "GOTO/1,0,0",
    "FEDRAT/.02",
    "GOTO/2,0,0",
    "FEDRAT/10,IPM",
    "GOTO/3,0,0",
    "FEDRAT/20",
    "GOTO/4,0,0",
]


def test_option_35_1_takes_a_feed_without_a_mode_per_revolution() -> None:
    """Option 35 = 1 (IPR, L24823-24831): FEDRAT/.05 at 200 RPM is 10 IPM (F100 on the
    standard machine, as FEDRAT/10); the next bare feed keeps the mode (.02 x 200 = 4 IPM);
    once IPM is named, bare feeds are per minute."""
    machine = standard_machine().with_options({35: 1.0})
    result = post(FEEDS, machine)
    assert tape_lines(result.blocks) == [
        "N001S620M03",
        "N004G01X+1F100",
        "N006X+1F040",
        "N008X+1F100",
        "N010X+1F200",
    ]
    assert texts(result) == []


def test_option_35_0_takes_it_per_minute() -> None:
    """The standard, 0 = IPM: .05 and .02 IPM are under the machine's lowest feed."""
    result = post(FEEDS, standard_machine())
    assert tape_lines(result.blocks)[1:3] == ["N004G01X+1F010", "N006X+1"]
    assert texts(result) == [
        "FEEDRATE 0.05 IPM IS OUTSIDE THE MACHINE RANGE 1-200; 1 IPM USED",
        "FEEDRATE 0.02 IPM IS OUTSIDE THE MACHINE RANGE 1-200; 1 IPM USED",
    ]


def test_option_35_does_not_touch_the_option_23_feed() -> None:
    """With no FEDRAT at all option 23's feed is assumed, and option 23 is in inches per
    minute (L24674-24679): 5 IPM whatever option 35 says."""
    machine = standard_machine().with_options({35: 1.0})
    result = post(["SPINDL/200,CLW", "FROM/0,0,0", "GOTO/1,0,0"], machine)
    assert tape_lines(result.blocks)[1] == "N003G01X+1F050"
    assert "OPTION FEEDRATE ASSUMED." in texts(result)


# --- option 223: the circular maximum departure ------------------------------------------

ARC = ["FROM/5,0,0", "FEDRAT/10", "CIRCLE/0,0,0,0,0,1,5", "GOTO/3.5355339,3.5355339,0"]
ARC_BLOCK = "N004G03X-14645Y+35355I5F020"
CHORD = "N004G01X-14645Y+35355F026"


@pytest.mark.parametrize(
    ("options", "first"),
    [
        ({}, ARC_BLOCK),  # radius 5 within option 4 = 9.9999
        ({4: 3.9999}, CHORD),  # option 4 bounds both: the arc goes out linear
        ({4: 3.9999, 223: 9.9999}, ARC_BLOCK),  # circles have their own maximum
        ({223: 4.0}, CHORD),  # which may be smaller than the linear one
    ],
)
def test_option_223_bounds_the_radius_of_circular_interpolation(
    options: dict[int, float], first: str
) -> None:
    """§3.4.4 test 4 (spec 03): a radius above the maximum departure cannot be circular;
    option 223 = N makes N that maximum for circles (L26719-26728)."""
    machine = standard_machine().with_options(options)
    assert tape_lines(post(ARC, machine).blocks)[0] == first


# --- option 215: type 5's increment between ranges ---------------------------------------


def type5(options: dict[int, float]) -> tuple[MachineDefinition, Any]:
    plugin = get_plugins().get("feedtypes", 5)
    assert plugin is not None
    machine = load_machine_text(plugin.manual_example, "type5.toml").with_options(options)
    return machine, plugin


def test_option_215_is_type_5s_range_increment() -> None:
    """E10 (L11523-11556), 40 IPM in feed range 2: XY 35.9 at row 27, Z 15.1 at row 20,
    FCOM = row + 6 - 1. The manual's example gives the 6 in option 144; option 215 holds it
    as type 5's own option (L26661-26669) and wins over 144: the same 32 and 25 with option
    144 at 0, and option 144's 3 ignored while 215 = 6."""
    for options in ({144: 0.0, 215: 6.0}, {144: 3.0, 215: 6.0}):
        machine, plugin = type5(options)
        xy = plugin.command(machine, 40.0, FeedContext(feed_range=2, axis=XY))
        z = plugin.command(machine, 40.0, FeedContext(feed_range=2, axis=Z))
        assert (xy.command, xy.ipm) == (32.0, 35.9)
        assert (z.command, z.ipm) == (25.0, 15.1)


def test_option_215_changes_the_codes_of_the_higher_ranges() -> None:
    """Option 215 = 11: range 2 starts 11 codes after range 1's last (F15 -> F26), range 3
    another 11 on (F30 -> F41); range 1 keeps its codes."""
    machine, plugin = type5({215: 11.0})
    first = [
        plugin.command(machine, value, FeedContext(feed_range=r, axis=Z)).command
        for r, value in ((1, 4.2), (2, 10.2), (3, 21.3))
    ]
    assert first == [11.0, 26.0, 41.0]


# --- options 149, 150 and 192: the rotary head -------------------------------------------


def mach40_post(tmp_path: Path, options: dict[int, float]) -> RunResult:
    """The MACH40 program of tests/test_multiaxis_motion.py: its N006 turns the head A
    from 90 to 53.13 degrees (the tool from (0, 0, 1) to (0, .6, .8)) in three segments."""
    program = tmp_path / "m.apt"
    program.write_text(PROGRAM)
    return post_file(
        str(program), get_plugins(), machine_override=mach40_g10().with_options(options)
    )


def lines(result: RunResult) -> list[str]:
    return [line for b in result.blocks if b.code is not Code.PARTNO and (line := tape_line(b))]


HEAD_WARNING = (
    "HEAD ROTATION LIMIT HAS BEEN EXCEEDED (60 TO 120 DEGREES, OPTIONS 149, 150) *** WARNING"
)


def test_options_149_150_warn_when_the_head_turns_past_them(tmp_path: Path) -> None:
    """Head A within 60..120 degrees: the turn to 53.13 passes the lower limit, warned once
    for the record and still made, as the table's options 220, 221 are."""
    plain = mach40_post(tmp_path, {})
    limited = mach40_post(tmp_path, {149: 60.0, 150: 120.0})
    assert lines(limited) == lines(plain)
    warned = [(d.text, d.where.record if d.where else None) for d in limited.diagnostics]
    assert (HEAD_WARNING, 6) in warned
    assert [t for t, _ in warned].count(HEAD_WARNING) == 1
    assert HEAD_WARNING not in texts(mach40_post(tmp_path, {149: 40.0, 150: 120.0}))


def test_options_149_150_on_rotate_head() -> None:
    """ROTATE/HEAD on a rotary machine is tested against them too: 5 then 10 more degrees
    within -10..10: the second turn passes the upper limit."""
    machine = _with_a(_all_codes()).with_options({149: -10.0, 150: 10.0})
    result = post(["FROM/0,0,0", "FEDRAT/10", "ROTATE/HEAD,INCR,5", "ROTATE/HEAD,INCR,10"], machine)
    warned = [(d.text, d.where.record if d.where else None) for d in result.diagnostics]
    text = "HEAD ROTATION LIMIT HAS BEEN EXCEEDED (-10 TO 10 DEGREES, OPTIONS 149, 150) *** WARNING"
    assert warned == [(text, 4)]


def test_option_192_lowers_the_feed_to_the_heads_maximum_rpm(tmp_path: Path) -> None:
    """N006's three segments each turn A 3.4139 hundredths of a turn (12.29 degrees) over
    8.3775 in of turn length at 10 IPM: .0408 RPM. Option 192 = .02 RPM lowers the feed to
    .02 x 360 x 8.3775 / 12.29 = 4.908 IPM: the inverse-time F001194 becomes F000586
    (1194 x 4.908 / 10). 0.05 RPM is not exceeded."""
    limited = mach40_post(tmp_path, {192: 0.02})
    n006 = [line for line in lines(limited) if line.startswith("N006")]
    assert n006[0].endswith("F000586")
    ipm = [round(float(b.cells[19]), 3) for b in limited.blocks if b.code is Code.LINEAR]  # type: ignore[arg-type]
    assert ipm[1:4] == [4.908, 4.908, 4.908]
    note = "FEEDRATE REDUCED TO 4.908 BY THE HEAD'S MAXIMUM OF 0.02 RPM (OPTION 192)"
    assert texts(limited).count(note) == 1
    assert lines(mach40_post(tmp_path, {192: 0.05})) == lines(mach40_post(tmp_path, {}))


def test_option_192_arithmetic() -> None:
    """90 degrees over 2 in at 60 IPM: .25 turn in 1/30 min = 7.5 RPM; a 5 RPM head takes
    40 IPM; 0 sets no limit."""
    machine = standard_machine().with_options({192: 5.0})
    allowed, note = head_limited_feed(machine, 60.0, 90.0, 2.0)
    assert allowed == pytest.approx(40.0)
    assert note is not None
    assert head_limited_feed(machine, 30.0, 90.0, 2.0) == (30.0, None)
    assert head_limited_feed(standard_machine(), 60.0, 90.0, 2.0) == (60.0, None)


# --- option 224: the 100S's metric I, J, K feed command ----------------------------------

LONG_MOVES = ["FROM/0,0,0", "FEDRAT/2", "GOTO/5,0,0", "GOTO/8,6,0", "GOTO/8,6,1"]
MARK_100S_METRIC = {138: 1.0, 165: 1.0, 26: 1.0}


def test_option_224_moves_the_command_of_a_long_move_into_i_j_k() -> None:
    """Option 224 = 4 (L26729-26738; the reading in docs/decisions.md): a linear move whose
    largest departure is over 4 carries its departures over 10^k in I, J, K and the
    command times 10^k, k as large as option 24 (500) allows. X 5 at 2: Fc = 10 x 2 / 5 =
    4, F400 with I.05 (k = 2); X 3 Y 6: Fc = 20 / 6.7082 = 2.9814, F003 without, F298 with
    I.03 J.06, the feed kept to three figures instead of one; Z 1 is not over 4."""
    plain = post(LONG_MOVES, standard_machine().with_options(MARK_100S_METRIC))
    assert tape_lines(plain.blocks) == ["N003G01X+5F004", "N004X+3Y+6F003", "N005Z+1F020"]
    machine = standard_machine().with_options({**MARK_100S_METRIC, 224: 4.0})
    assert tape_lines(post(LONG_MOVES, machine).blocks) == [
        "N003G01X+5I005F400",
        "N004X+3Y+6I003J006F298",
        "N005Z+1F020",
    ]


@pytest.mark.parametrize(
    ("options", "needed"),
    [({}, "165 = 1 (a 100S control)"), ({165: 1.0}, "138 = 1 (the metric system)"),
     ({165: 1.0, 138: 1.0, 26: 0.0}, "26 = 1")],
)  # fmt: skip
def test_option_224_is_for_the_100s_in_metric_with_option_26_1(
    options: dict[int, float], needed: str
) -> None:
    machine = standard_machine().with_options({**options, 224: 4.0})
    with pytest.raises(MachineDefinitionError, match=re.escape(needed)):
        post(LONG_MOVES, machine)


def test_option_35_in_the_verifiers_cl_path() -> None:
    """The verifier follows the CL file as the post does: the first bare feed takes option
    35's mode, a named one its own."""
    records = AptSourceReader("part.apt").read_lines(
        ["FROM/0,0,0", "FEDRAT/.05", "GOTO/1,0,0", "FEDRAT/10,IPM", "GOTO/2,0,0", "FINI"]
    )
    feeds = [t.feed for t in cl_path(records, standard_machine().with_options({35: 1.0})).targets]
    assert (0.05, True) in feeds and (10.0, False) in feeds
    records = AptSourceReader("part.apt").read_lines(["FROM/0,0,0", "FEDRAT/.05", "GOTO/1,0,0"])
    feeds = [t.feed for t in cl_path(records, standard_machine()).targets]
    assert (0.05, False) in feeds
