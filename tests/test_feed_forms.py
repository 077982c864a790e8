"""Golden tests: contouring feed forms (spec 05 §3, appendix 7.1 magic three)."""

from __future__ import annotations

import pytest
from gecent.core.absent import ABSENT
from gecent.core.errors import InputError
from gecent.core.feed.contour import INVERSE_TIME
from gecent.core.feed.magic3 import decode, magic3
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text

from .test_post_linear import post, tape


@pytest.mark.parametrize(
    ("value", "code"),
    [
        (1728, 717),
        (150, 615),
        (15.2, 515),
        (7.82, 478),
        (0.153, 315),
        (0.0126, 213),
        (0.00875, 188),  # 87.5 rounds half up
        (0.000462, 46),  # punched "046"
        (40, 540),  # 001 L11183-11185
        (2, 420),  # 001 L11382
        (0.06, 260),  # 001 L11661-11662
        # 001 L11384 prints "0.1 -> 210"; the rule gives 310 for 0.1 and 210 for 0.01: the
        # scan shows "0. 1" with a gap, a lost "0". The corrected values are tested.
        (0.1, 310),
        (0.01, 210),
        (1, 410),
        (10, 510),
        (100, 610),
        (9.96, 510),  # rounds to 10.0: the next decade
        (0.125, 313),  # half up, not Python's half-even
    ],
)
def test_appendix_7_1_magic_three(value: float, code: int) -> None:
    """The 8 examples of appendix 7.1 (001 L40150-40166) and the others the manual gives."""
    assert magic3(value) == code


def test_magic_three_range_and_decoding() -> None:
    assert magic3(0.00009) is None and magic3(10000) is None
    assert magic3(0) == 0
    assert decode(540) == 40.0 and decode(46) == pytest.approx(0.00046)


WIDE = {3: -24.0, 4: -24.0, 5: -24.0}  # X, Y, Z up to 99.9999, as option 4 allows


def _machine(optab: dict[int, float], regfor: dict[int, float] | None = None) -> MachineDefinition:
    text = '[machine]\nnumber = 87\nname = "feeds"\ntitle = "FEED TEST"\n'
    text += "[tableg]\n11 = 10\n12 = 11\n"
    text += "[optab]\n" + "".join(f"{k} = {v}\n" for k, v in optab.items())
    if regfor:
        text += "[regfor]\n" + "".join(f"{k} = {v}\n" for k, v in regfor.items())
    return load_machine_text(text, "feeds.toml")


def test_e1_feedrate_number() -> None:
    """E1 (001 L10841-10873): dX 4, dY 3, dZ 2 at 40 IPM, G01 (GDIMUL 10): S = 5.3852,
    Fc = 400 / 5.3852 = 74.28 -> 74.3 in format 31. The manual prints 74.8, an OCR 3 -> 8
    (even its rounded S = 5.39 gives 74.21)."""
    machine = _machine({}, {11: 31.0})
    lines = tape(["FROM/0,0,0", "FEDRAT/40", "GOTO/4,3,2"], machine)
    assert lines == ["N003G01X+4Y+3Z+2F0743"]


def test_feedrate_number_clamp_gives_back_the_real_feed() -> None:
    """001 L11922-11943: dX 30, dY 40 at 300 IPM; largest departure 40 -> GDIMUL 100:
    Fc = 100 * 300 / 50 = 600 -> option 24 = 500, and the feed is then 500 * 50 / 100 = 250."""
    machine = _machine({4: 99.9999, 25: 400.0}, WIDE)
    result = post(["FROM/0,0,0", "FEDRAT/300", "GOTO/30,40,0"], machine)
    block = next(b for b in result.blocks if b.punch and "X" in b.punch)
    assert block.punch == "N003G10X+30Y+40F500"
    assert block.cells[19] == 250.0


def test_e21_rapid_vector_optimisation() -> None:
    """E21 (001 L12540-12627): dX 3, dY 4 (S = 5), options 42 = 43 = 100, D = 10:
    rho = max(3/100, 4/100) = 0.04, command 10 / 0.04 = 250, vector feed 5 / 0.04 = 125 IPM."""
    machine = _machine({42: 100.0, 43: 100.0, 44: 100.0})
    result = post(["FROM/0,0,0", "RAPID", "GOTO/3,4,0"], machine)
    block = next(b for b in result.blocks if b.punch and "X" in b.punch)
    assert block.punch == "N003G01X+3Y+4F250"
    assert block.cells[19] == pytest.approx(125.0)


def test_e4_magic_three_feed() -> None:
    """E4 (001 L11183-11197): option 10 = +1, 40 IPM -> F540 (REGFOR(11) = 30, option 26 = 1)."""
    machine = _machine({10: 1.0, 26: 1.0})
    assert tape(["FROM/0,0,0", "FEDRAT/40", "GOTO/1,0,0"], machine) == ["N003G01X+1F540"]


def test_magic_three_needs_its_machine_settings() -> None:
    """The machine file itself is refused (001 L11189-11197, L24246-24249)."""
    with pytest.raises(InputError, match="option 10 = \\+1"):
        _machine({10: 1.0})


def test_e3_inverse_time_switches_the_f_format_by_g_code() -> None:
    """E3 (001 L11167-11172): option 10 = -2, a G10 block (10 <= departure < 100) whose
    command is 8.76 punches F00876 in format 32 (the row -2/G10: 0.01 .. 9.99); a G01 block
    takes format 31 and the row 0.1 .. 99.9."""
    machine = _machine({10: -2.0, 4: 99.9999, 25: 500.0}, WIDE)
    lines = tape(["FROM/0,0,0", "FEDRAT/438", "GOTO/30,40,0", "FEDRAT/20", "GOTO/32,40,0"], machine)
    assert lines == ["N003G10X+30Y+40F00876", "N005G01X+02F0100"]


def test_inverse_time_rows_cover_the_manual_table() -> None:
    assert len(INVERSE_TIME) == 16
    assert INVERSE_TIME[(-3, 13)] == (40.0, 1.0, 9999.0)
    assert INVERSE_TIME[(-4, 15)] == (47.0, 0.00001, 0.0999999)


def test_e17_g_code_segmentation_keeps_the_programmed_feed() -> None:
    """E17 (001 L11920-11970): dX 30, dY 40 at 300 IPM needs G10 (D = 100): Fc = 600 > 500.
    Without option 170 the command is held to 500 and the feed drops to 250 IPM; with it
    the move is cut into 5 segments of (6, 8) for G01 (D = 10): Fc = 300, the full 300 IPM
    (4 segments would give exactly 10, not under it)."""
    program = ["FROM/0,0,0", "FEDRAT/300", "GOTO/30,40,0"]
    base = {4: 99.9999, 25: 500.0, 26: 1.0}
    clamped = post(program, _machine(base, WIDE))
    motion = [b for b in clamped.blocks if b.punch]
    assert [b.punch for b in motion] == ["N003G10X+30Y+40F500"]
    assert motion[0].cells[19] == pytest.approx(250.0)
    segmented = post(program, _machine({**base, 170: 1.0}, WIDE))
    motion = [b for b in segmented.blocks if b.punch]
    assert [b.punch for b in motion] == ["N003G01X+06Y+08F300"] + ["N003X+06Y+08"] * 4
    assert {b.cells[19] for b in motion} == {300.0}


def test_e20_feedrate_multiplier_constant_in_inverse_time() -> None:
    """E20 (001 L12481-12511): inverse time, dX = dY = 0.01 at 30 IPM in a G11 block (row
    -1/G11, FCOMAX 999.9): FCOM = 30 / 0.014142 = 2121.3 > 999.9. The manual "adopts" c = 5
    (FCOM 424, I = J = 0.05) and calls c arbitrary; gecent takes the smallest whole c that
    brings the command to the maximum or below, c = 3: FCOM 707.1, I = J = 0.03 (the
    relations of the example hold: FCOM x c = 2121.3, I = dX x c)."""
    machine = _machine({10: -1.0}, {11: 33.0})
    result = post(["FROM/0,0,0", "FEDRAT/30", "GOTO/0.01,0.01,0"], machine)
    motion = next(b for b in result.blocks if b.punch)
    assert motion.cells[11] == pytest.approx(707.1)
    assert (motion.cells[8], motion.cells[9]) == (pytest.approx(0.03), pytest.approx(0.03))
    assert motion.cells[19] == 30.0  # the programmed feed is kept
    assert float(motion.cells[11]) * 3 == pytest.approx(30 / (2 * 0.01**2) ** 0.5, abs=0.2)
    assert motion.punch == "N003G11X+001Y+001I003J003F7071"


def test_multiplier_products_that_do_not_fit_fall_back_to_the_clamp() -> None:
    """I, J, K must hold the departures times c (001 L12512-12529): 9 in x c = 2 exceeds
    the standard I format 14 (9.9999), so the command is limited instead."""
    machine = _machine({4: 99.9999, 25: 500.0}, WIDE)
    result = post(["FROM/0,0,0", "FEDRAT/500", "GOTO/9,0,0"], machine)
    motion = next(b for b in result.blocks if b.punch)
    assert motion.cells[8] is ABSENT
    assert motion.punch == "N003G01X+09F500"  # 10 x 500 / 9 = 555.6 -> 500


def test_inverse_time_on_an_arc_takes_the_row_of_its_radius_band() -> None:
    """An arc's radius band is a size class like a linear range: radius 2 is the G01 class,
    row -1/G01 (format 32): F = 10 IPM / 2 in = 5.00 -> F00500."""
    machine = _machine({10: -1.0}, {11: 33.0})
    lines = tape(["FROM/2,0,0", "FEDRAT/10", "CIRCLE/0,0,0,0,0,1,2", "GOTO/0,2,0"], machine)
    assert lines == ["N004G03X-2Y+2I2F00500"]
