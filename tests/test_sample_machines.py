"""The five sample machines and the BRACK example load with exactly the manual's values
(spec 07 §10 and §8.6; worked examples WE-13, WE-15, WE-17)."""

from __future__ import annotations

import pytest
from gecent.core.absent import ABSENT
from gecent.core.machine import load_machine_file
from gecent.core.machine.shuffle import decode_shuffle, describe_shuffle

from .conftest import DATA, MACHINES


def load(name: str):  # type: ignore[no-untyped-def]
    return load_machine_file(MACHINES / f"{name}.toml")


def test_mach24_positioning() -> None:
    m = load("mach24")
    assert (m.number, m.title) == (24, "SAMPLE POSITIONING MACHINE")
    assert [m.tableg[i] for i in (1, 82, 83, 84, 85, 86, 87, 88)] == [
        80,
        81,
        82,
        83,
        84,
        85,
        86,
        87,
    ]
    assert [m.tablem[i] for i in (2, 3, 4, 6)] == [ABSENT] * 4
    assert (m.tablem[5], m.tablem[31], m.tablem[102], m.tablem[105]) == (2, 30, 6, 7)
    assert m.registers.regfor[16] == -22.0 and m.registers.letters[16] == "R"
    assert m.option(27) == -1.0 and m.option(59) == 132415.0 and m.option(132) == 2.0
    ranges = m.spindle_ranges()
    assert len(ranges) == 3 and all(len(r) == 8 for r in ranges)  # 3 x 8 = 24 speeds
    assert ranges[0][0] == 70.0 and ranges[2][-1] == 2400.0
    # The one expected validation warning of WE-17: option 23 = 0.
    assert m.warnings == (
        "option 23: assumed feedrate is 0: a motion without FEDRAT will stop the run",
    )


def test_mach04_lathe_we13() -> None:
    m = load("mach04")
    assert (m.tableg[3], m.tableg[4], m.tableg[34]) == (3, 2, 33)
    assert m.registers.formats[4] is None and m.registers.formats[9] is None
    assert m.option(19) == 10.0 and m.option(22) == 101.0
    assert m.spindle_ranges() == ((4.0, 130.0), (18.0, 600.0))  # 2 ranges x 2 = 4
    assert m.indfr == 296
    assert [m.store[i] for i in range(297, 301)] == [0.01, 2.0, 0.1, 20.0]
    assert m.tablem[43] == m.tablem[114] == 41
    assert describe_shuffle(decode_shuffle(m.number_option(59), "XYZ")) == "+Z-X"
    assert describe_shuffle(decode_shuffle(m.number_option(60), "IJK")) == "+K+I"


def test_mach23_mill() -> None:
    m = load("mach23")
    assert [m.tableg[i] for i in (11, 12, 21, 22, 31, 32)] == [10, 11, 20, 21, 30, 31]
    assert m.tablem[3] is ABSENT
    assert m.registers.formats[12] is None and m.registers.formats[13] is None
    assert m.registers.regfor[6] == -6.0  # printed so (001 L27848); kept
    assert m.option(4) == 99.9999 and m.option(164) == 1.0


def test_mach40_multiaxis() -> None:
    m = load("mach40")
    assert m.option(116) == 1.0 and m.option(133) == 1.0 and m.option(10) == -1.0
    assert m.registers.letters[6:8] == ("A", "C")
    assert m.srtab_top == 180 and m.srtab(180) == 9.0
    speeds = [m.srtab(i) for i in range(1, 115)]
    assert speeds[:4] == [10.0, 350.0, 28.3, 991.0]
    assert speeds[16:39] == [float(v) for v in range(16, 61, 2)]
    assert speeds[109:] == [310.0, 320.0, 330.0, 340.0, 350.0]


def test_mach51_multihead() -> None:
    m = load("mach51")
    assert len(m.heads) == 2
    head2 = m.heads[1]
    assert [head2.letters[i] for i in (2, 3, 5, 8, 10, 11)] == ["G", "U", "W", "H", "J", "E"]
    assert head2.regfor[3] == -33.0 and head2.formats[1] is None
    assert len(m.spindle_speeds()) == 100 and m.spindle_speeds()[-1] == 795.0


def test_brack40_example_we15() -> None:
    m = load_machine_file(DATA / "machines" / "brack40.toml")
    assert m.title == "MACHINE 40 BRACK LATHE"
    assert m.spindle_ranges() == ((10.0, 20.0, 30.0), (20.0, 40.0, 60.0))  # 2 x 3 = 6
    assert m.indfr == 296 and m.feed_ranges == ((0.1, 10.0), (7.0, 60.0))
    assert [m.store[i] for i in range(297, 301)] == [0.1, 10.0, 7.0, 60.0]
    assert m.registers.letters[12] == "H" and m.registers.regfor[3] == -23.0


@pytest.mark.parametrize("name", ["mach04", "mach23", "mach24", "mach40", "mach51"])
def test_every_sample_passes_the_checklist(name: str) -> None:
    m = load(name)
    assert m.speed_count == int(m.number_option(7)) * int(m.number_option(8))
    assert 2 * len(m.feed_ranges) == m.number_option(174)
