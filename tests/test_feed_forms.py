"""Golden tests: contouring feed forms (spec 05 §3, appendix 7.1 magic three)."""

from __future__ import annotations

import pytest
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
