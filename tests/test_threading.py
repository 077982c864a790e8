"""Threading (manual §4.6, 001 L15648-16023): PITCH, THREAD, COUPLE and the thread blocks
of THREDO on the sample lathe MACH04 (TABLEG 34-36 = G33/G34/G35, TABLEM 51/52 = M50/M51,
I and K in format 14, option 92 = 1 s of coupling dwell in Z)."""

from __future__ import annotations

import pytest
from gecent.core.errors import InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text
from gecent.core.output.block import Code
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post

START = ["FROM/10,0,0", "SPINDL/100,CLW", "COUPLE/ON"]


def lathe() -> MachineDefinition:
    return get_plugins().machine("mach04").load()


def punched(lines: list[str], machine: MachineDefinition | None = None) -> list[str]:
    return [b.punch for b in post(lines, machine or lathe()).blocks if b.punch]


def threads(lines: list[str], machine: MachineDefinition | None = None):  # type: ignore[no-untyped-def]
    result = post(lines, machine or lathe())
    return [b for b in result.blocks if b.code in (Code.THREAD_5, Code.THREAD_6)], result


def test_constant_fine_lead_is_a_six_digit_lead_without_f() -> None:
    """PITCH/16: lead 1/16 = .0625 in, more than 10 threads per inch, so a six-digit lead
    .062500 whose leading zero is passed over: K62500, trailing zeros dropped, CODE -13.
    CL X is the lathe's Z (option 59 +Z-X), the X lead goes to K (option 60 +K+I). A
    constant lead has no F; the printed feed is S x lead = 100 x .0625 = 6.25 IPM; 2 inches
    at 16 threads per inch are 32 turns, 0.32 min at 100 RPM (001 L15672-15714,
    L15975-16010)."""
    blocks, result = threads([*START, "PITCH/16", "THREAD/TURN", "GOTO/8,0,0"])
    assert [b.punch for b in blocks] == ["N006G33Z-2K625"]
    (block,) = blocks
    assert block.code is Code.THREAD_6
    assert block.cells[19] == pytest.approx(6.25)
    assert block.cut_minutes == pytest.approx(0.32)
    assert result.diagnostics == []


def test_coarse_lead_is_a_five_digit_lead() -> None:
    """TH-2: fewer than 10 threads per inch, a five-digit lead: PITCH/4 = .25000 -> K25,
    CODE +13 (001 L15680-15693)."""
    blocks, _ = threads([*START, "PITCH/4", "THREAD/TURN", "GOTO/9,0,0"])
    assert [b.punch for b in blocks] == ["N006G33Z-1K25"]
    assert blocks[0].code is Code.THREAD_5


def test_tapered_thread_lead_components_are_proportional_to_the_departures() -> None:
    """A taper: the lead on the threading axis, the other component |dY x I / dX|: with
    lead .125 (M = 10: 1.25) over dX = -2, dY = -.1: J = .1 x 1.25 / 2 = .0625, in the I
    register (the lathe's X); the printed feed is 100 x .125 x sqrt(1 + (.1/2)^2)."""
    blocks, _ = threads([*START, "PITCH/8", "THREAD/TURN", "GOTO/8,-0.1,0"])
    assert [b.punch for b in blocks] == ["N006G33X+01Z-2I00625K125"]
    assert blocks[0].cells[19] == pytest.approx(12.5 * (1 + 0.05**2) ** 0.5)


def test_variable_lead_f_is_the_threading_rate() -> None:
    """PITCH/8, INCR, 12: the pitch increases, the lead decreases (THMODE -1, TABLEG(36) =
    G35) from .125 to .083333 over the 2-inch path: THRATE = (Lf^2 - Li^2) / (2 s) =
    (.0069444 - .015625) / 4 = -.0021701; F = |THRATE| x M = .021701 in the lead's format
    14: F00217. The turns are (Li - Lf) / |THRATE| = 19.2, 0.192 min at 100 RPM."""
    blocks, _ = threads([*START, "PITCH/8,INCR,12", "THREAD/TURN", "GOTO/8,-0.1,0"])
    assert [b.punch for b in blocks] == ["N006G35X+01Z-2I00625K125F00217"]
    assert blocks[0].cut_minutes == pytest.approx((0.125 - 1 / 12) / (0.0086806 / 4) / 100, 1e-4)


def test_increasing_lead_from_12_to_6_threads_per_inch() -> None:
    """TH-1: 12 -> 6 threads per inch increases the lead (1/12 -> 1/6), so PITCH/12, DECR, 6
    is THMODE +1, TABLEG(35) = G34; the screw length 4 given in PITCH (not the 2-inch path)
    sets THRATE = (1/36 - 1/144) / 8 = .0026042, F = .026042 (M = 10)."""
    blocks, _ = threads([*START, "PITCH/12,DECR,6,4", "THREAD/TURN", "GOTO/8,0,0"])
    assert [b.punch for b in blocks] == ["N006G34Z-2K08333F00260"]


def test_a_segmented_variable_lead_restarts_each_block_at_its_own_lead() -> None:
    """Over DEPMAX (9.9999) the thread is segmented; each block carries the lead at its
    start, L^2 = Li^2 + 2 THRATE x (x along the axis): 12 inches of 1/8 -> 1/4 in lead,
    THRATE = (1/16 - 1/64) / 24; the second block starts at x = 6."""
    blocks, _ = threads(
        ["FROM/30,0,0", "SPINDL/20,CLW", "COUPLE/ON", "PITCH/8,DECR,4", "THREAD/TURN",
         "GOTO/18,0,0"]
    )  # fmt: skip
    rate = (1 / 16 - 1 / 64) / 24
    second = (1 / 64 + 2 * rate * 6) ** 0.5
    assert [float(b.cells[10]) for b in blocks] == pytest.approx([1.25, second * 10])
    assert blocks[0].punch == "N006G34Z-6K125F00195"


def test_thread_is_one_shot() -> None:
    lines = [*START, "PITCH/16", "FEDRAT/10", "THREAD/TURN", "GOTO/8,0,0", "GOTO/6,0,0"]
    result = post(lines, lathe())
    assert [b.code for b in result.blocks if b.punch][-2:] == [Code.THREAD_6, Code.LINEAR]


def test_coupling_dwell_carries_the_encoder_m_code() -> None:
    """COUPLE/ON and OFF: TABLEM(51) = M50, (52) = M51 with option 92's 1-second dwell in Z
    (option 57 = 5, option 56 = 10 -> Z+01)."""
    assert punched(["SPINDL/100,CLW", "COUPLE/ON", "COUPLE/OFF"]) == [
        "N001G04S610M60",
        "N002G04Z+01M50",
        "N003G04Z+01M51",
    ]


def test_negative_option_92_lowers_the_speed_to_couple_then_restores_it() -> None:
    """Option 92 < 0: the spindle drops to the lowest speed of its range (4 RPM in range 1,
    magic three S440) before coupling and comes back up after (001 L15737-15740)."""
    machine = lathe().with_options({92: -1.0})
    assert punched(["SPINDL/100,CLW", "COUPLE/ON"], machine) == [
        "N001G04S610M60",
        "N002G04S440",
        "N002G04Z+01M50",
        "N002G04S610",
    ]


def test_speed_above_option_175_while_coupled_is_reported_and_dropped() -> None:
    """Coupling at 500 RPM over option 175 (300 here) first drops to the lowest speed of the
    range it runs in (18 RPM in range 2, S518, no range change); a later SPINDL over it
    while coupled gets the manual's comment."""
    result = post(["SPINDL/500,CLW", "COUPLE/ON", "SPINDL/550"], lathe().with_options({175: 300}))
    texts = [d.text for d in result.diagnostics]
    assert texts == ["SPINDLE SPEED IS TOO HIGH FOR THREADING"]
    assert [b.punch for b in result.blocks if b.punch] == [
        "N001G04S650M62",
        "N002G04S518",
        "N002G04Z+01M50",
        "N003G04S655",
    ]


def test_thread_without_coupling_warns_and_continues() -> None:
    lines = ["FROM/10,0,0", "SPINDL/100,CLW", "PITCH/16", "THREAD/TURN", "GOTO/8,0,0"]
    result = post(lines, lathe())
    assert [d.text for d in result.diagnostics] == ["THE ENCODER IS NOT COUPLED FOR THREADING."]
    assert [b.punch for b in result.blocks if b.punch][-1] == "N005G33Z-2K625"


def test_rapid_then_thread_cuts_the_thread() -> None:
    lines = [*START, "PITCH/16", "RAPID", "THREAD/TURN", "GOTO/8,0,0", "FEDRAT/10", "GOTO/7,0,0"]
    result = post(lines, lathe())
    assert "RAPID AND THREAD CANNOT BE USED TOGETHER" in result.diagnostics[0].text
    assert [b.punch for b in result.blocks if b.punch][-2:] == ["N007G33Z-2K625", "N009G01Z-1F100"]


def test_facing_thread_leads_along_y() -> None:
    """THREAD/FACE: the lead is on Y (the lathe's X, in I); the other component in K."""
    blocks, _ = threads([*START, "PITCH/10", "THREAD/FACE", "GOTO/10,-2,0"])
    assert [b.punch for b in blocks] == ["N006G33X+2I1"]


def test_spindle_speed_over_the_capability_table_is_reported() -> None:
    """Table 1: normal leads to 600 RPM on a three-range system, 370 on a two-range one
    (option 205 = 1)."""
    lines = ["FROM/10,0,0", "SPINDL/400,CLW", "COUPLE/ON", "PITCH/32", "THREAD/TURN", "GOTO/8,0,0"]
    assert post(lines, lathe()).diagnostics == []
    texts = [d.text for d in post(lines, lathe().with_options({205: 1})).diagnostics]
    assert texts == ["SPINDLE SPEED IS TOO HIGH FOR THREADING"]


MARK_100S = """
[machine]
name = "lathe100s"
[optab]
165 = 1.0
[tableg]
98 = 28
99 = 23
100 = 29
101 = 38
102 = 33
103 = 39
"""


def test_100s_extended_departure_outputs_the_excess_over_ten_inches() -> None:
    """TH-3: on the 100S a thread departure over 9.9999 in along the axis is output as its
    excess over 10 inches, with G23 instead of G33 (001 L15930-15935)."""
    machine = load_machine_text(MARK_100S, base=lathe())
    blocks, _ = threads(["FROM/30,0,0", "SPINDL/100,CLW", "COUPLE/ON", "PITCH/4",
                         "THREAD/TURN", "GOTO/18,0,0"], machine)  # fmt: skip
    assert [b.punch for b in blocks] == ["N006G23Z-2K25"]
    assert blocks[0].steps == (-120000, 0)


def test_100s_extended_lead_outputs_half_the_lead() -> None:
    """TH-4: a lead over .99999 in (here 1.5, PITCH/.6666667) takes G38 and the output
    lead is half of it, .75 -> K75 (001 L15937-15939)."""
    machine = load_machine_text(MARK_100S, base=lathe())
    blocks, _ = threads([*START, "PITCH/0.66666667", "THREAD/TURN", "GOTO/8,0,0"], machine)
    assert [b.punch for b in blocks] == ["N006G38Z-2K75"]


def test_extended_lead_without_its_g_code_is_an_error() -> None:
    with pytest.raises(InputError, match="TABLEG 37"):
        post([*START, "PITCH/0.5", "THREAD/TURN", "GOTO/8,0,0"], lathe())


@pytest.mark.parametrize(
    ("lines", "message"),
    [
        (["THREAD/TURN", "GOTO/8,0,0"], "PITCH statement before"),
        (["PITCH/8,INCR,6"], "final pitch must be above"),
        (["PITCH/0"], "a number > 0"),
        (["THREAD/LEFT"], "THREAD/TURN or THREAD/FACE"),
        (["COUPLE/5"], "COUPLE/ON or COUPLE/OFF"),
        (["PITCH/8", "THREAD/TURN", "GOTO/10,-1,0"], "move along X"),
    ],
)
def test_bad_threading_statements_name_what_was_expected(lines: list[str], message: str) -> None:
    with pytest.raises(InputError, match=message):
        post(["FROM/10,0,0", "SPINDL/100,CLW", *lines], lathe())
