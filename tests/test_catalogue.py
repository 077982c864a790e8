"""The catalogue and the Standard Machine (spec 07 §3-§8.1; worked example WE-21)."""

from __future__ import annotations

from gecent.core.absent import ABSENT
from gecent.core.machine import standard_machine
from gecent.core.machine.catalogue import catalogue

NON_REASSIGNABLE = {
    1,
    7,
    8,
    10,
    13,
    14,
    19,
    22,
    33,
    34,
    35,
    69,
    111,
    112,
    113,
    114,
    115,
    118,
    119,
    138,
    165,
    174,
    191,
}


def test_catalogue_has_every_location_once() -> None:
    cat = catalogue()
    # the manual's 250 options and 120 G locations, then gecent's modern-control ones
    assert [o.number for o in cat.options] == list(range(1, 266))
    assert [o.number for o in cat.options if o.status == "gecent"] == list(range(251, 266))
    assert [g.number for g in cat.tableg] == list(range(1, 132))
    assert all(g.seed == "gecent" for g in cat.tableg[120:])
    assert [m.number for m in cat.tablem] == list(range(1, 201))
    assert [r.number for r in cat.registers] == list(range(1, 31))


def test_fixed_options_are_the_manuals_list() -> None:
    assert {o.number for o in catalogue().options if o.fixed} == NON_REASSIGNABLE


def test_standard_machine_we21() -> None:
    m = standard_machine()
    assert m.tableg[2:6] == (1, 2, 3, 4)
    assert m.tableg[18:21] == (17, 18, 19)
    assert m.tableg[1] is ABSENT and m.tableg[34] is ABSENT
    assert m.tablem[1:7] == (0, 1, 2, 3, 4, 5)
    assert (m.tablem[9], m.tablem[10], m.tablem[31]) == (8, 9, 30)
    assert m.tablem[7] is ABSENT and m.tablem[130] is ABSENT
    assert m.registers.regfor[1:15] == (
        30.0,
        20.0,
        -14.0,
        -14.0,
        -14.0,
        0.0,
        0.0,
        14.0,
        14.0,
        14.0,
        30.0,
        30.0,
        20.0,
        20.0,
    )
    assert m.registers.letters[1:15] == tuple("NGXYZABIJKFSTM")
    assert (m.srtab(1), m.srtab(2)) == (1.0, 300.0)
    for spec in catalogue().options:
        assert m.options[spec.number] == spec.default
    assert m.warnings == ()


def test_standard_option_values_from_the_manual() -> None:
    m = standard_machine()
    expected = {
        1: 0.0,
        4: 9.9999,
        5: 0.00005,
        8: 2.0,
        13: 0.012,
        14: 0.0001,
        17: 111.0,
        22: 111.0,
        23: 5.0,
        27: 80.0,
        59: 131415.0,
        60: 161718.0,
        79: 45.0,
        90: -1.0,
        91: 2.0,
        107: 1.0,
        111: 35.99964,
        134: 1100.0,
        135: 900.0,
        160: 120.0,
        164: 1.0,
        175: 600.0,
        64: "((((((",
        65: "=",
        66: "*",
        67: "$",
    }
    for number, value in expected.items():
        assert m.option(number) == value, number


def test_option_aliases_resolve() -> None:
    m = standard_machine()
    assert m.option("step_size") == m.option(14) == 0.0001
    assert m.option("spindle_type") == 1.0
