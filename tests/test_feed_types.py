"""The positioning feed types (option 78, manual §4.1.2, 001 L11198-11711) and rotary feed
type 1 (option 141, §4.1.3.1, 001 L11713-11808), each on the machine its manual example
describes (the plugin's ``manual_example``): the worked examples E5-E15 of spec 05 §12, then
what the manual leaves open and the machine data a type cannot use."""

from __future__ import annotations

import math
from typing import Any

import pytest
from gecent.core.errors import FatalError, MachineDefinitionError
from gecent.core.feed.positioning import BELOW_TABLE, XY, FeedContext, Z
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.plugins import get_plugins
from gecent.core.statements.feed import RANGE_NOT_AVAILABLE
from gecent.plugins.feedtypes._frtab import SPEED_ASSUMED
from gecent.plugins.feedtypes.type3 import OUTSIDE_MAGIC3


def feed_type(number: int) -> Any:
    plugin = get_plugins().get("feedtypes", number)
    assert plugin is not None, f"feed type {number} is not registered"
    return plugin


def rotary_type(number: int) -> Any:
    plugin = get_plugins().get("rotaryfeeds", number)
    assert plugin is not None, f"rotary feed type {number} is not registered"
    return plugin


def example(plugin: Any) -> MachineDefinition:
    return load_machine_text(plugin.manual_example, f"{plugin.name}.toml")


def snap_then_command(
    plugin: Any, machine: MachineDefinition, feed: float, context: FeedContext
) -> tuple[float, float]:
    """FEDRAT (K = 0) then POSFED (K = 1): the programmed feed and the F command."""
    snapped = plugin.snap(machine, feed, context)
    command = plugin.command(machine, snapped.ipm, context)
    assert command.ipm == pytest.approx(snapped.ipm)
    return snapped.ipm, command.command


# --- feed type 0 -----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("feed", "command"), [(7.123, 21), (18.2694, 55), (1.74, 5), (94.926, 285)]
)
def test_type0_multiplies_by_the_magnitude_of_option_78(feed: float, command: int) -> None:
    """E5, 001 L11252-11264: option 78 = -3, K = 3; the printed "5.0" and "285. 0" are the
    F format of 5 and 285. The feed used is the command over K (F21 is 7 IPM), the true
    value the listing prints (001 L1160-1168; docs/decisions.md)."""
    plugin = feed_type(0)
    used, made = snap_then_command(plugin, example(plugin), feed, FeedContext())
    assert made == command
    assert used == pytest.approx(command / 3)


def test_type0_option_78_zero_means_k_2() -> None:
    """001 L11251: "If option 78 is zero, K = 2" (the option table's ABS(0) would be 0)."""
    plugin = feed_type(0)
    machine = example(plugin).with_options({78: 0.0})
    assert plugin.command(machine, 10.0, FeedContext()).command == 20.0
    assert plugin.command(machine, 7.123, FeedContext()).command == 14.0


def test_type0_rounds_a_half_up() -> None:
    """001 L11242-11244: "rounded to the closest integer"; 0.5 x 5 = 2.5 is F3."""
    plugin = feed_type(0)
    machine = example(plugin).with_options({78: -5.0})
    assert plugin.command(machine, 0.5, FeedContext()).command == 3.0
    assert plugin.command(machine, 0.7, FeedContext()).command == 4.0


# --- feed type 1 -----------------------------------------------------------------------


@pytest.mark.parametrize(("feed", "made"), [(0.1, 0.1), (2.63, 2.6), (35.17, 35.2), (40.0, 40.0)])
def test_type1_the_ipm_is_the_command(feed: float, made: float) -> None:
    """E6, 001 L11274-11284: option 78 = 1; the command is the IPM in REGFOR(11) = 21's
    format: 00.1, 02.6, 35.2, 40.0. That is the feed the control makes, used and printed."""
    plugin = feed_type(1)
    machine = example(plugin)
    assert machine.registers.regfor[11] == 21.0
    assert snap_then_command(plugin, machine, feed, FeedContext()) == (made, made)


# --- feed type 2 -----------------------------------------------------------------------


def test_type2_snaps_to_the_next_lowest_ipr_and_commands_row_plus_option_144() -> None:
    """E7, 001 L11324-11370: 100 RPM, spindle range 2, 7 IPM: 0.07 IPR, next lowest 0.06,
    FIPM = 6 (the new programmed feed); row 6, FCOM = 6 + 11 = 17."""
    plugin = feed_type(2)
    machine = example(plugin)
    context = FeedContext(spindle_speed=100.0, spindle_range=2)
    snapped = plugin.snap(machine, 7.0, context)
    assert snapped.ipm == pytest.approx(6.0)
    assert snapped.row == 6
    assert plugin.command(machine, snapped.ipm, context).command == 17.0


def test_type2_scans_only_the_spindle_ranges_segment() -> None:
    """001 L11360-11368: range 2 of FRTAB "since spindle range is 2"; 0.10 IPR is in
    ranges 2 and 3 at rows 8 and 10."""
    plugin = feed_type(2)
    machine = example(plugin)
    for spindle_range, row in ((2, 8), (3, 10)):
        context = FeedContext(spindle_speed=100.0, spindle_range=spindle_range)
        assert plugin.command(machine, 10.0, context).command == row + 11


def test_type2_every_table_value_is_its_own_row() -> None:
    """001 L11331-11339: each IPR of each range, times the speed, keeps its row and FCOM."""
    plugin = feed_type(2)
    machine = example(plugin)
    for spindle_range, values in enumerate(machine.feed_table_ranges(), start=1):
        context = FeedContext(spindle_speed=250.0, spindle_range=spindle_range)
        for index, ipr in enumerate(values):
            row = (spindle_range - 1) * 5 + index
            snapped = plugin.snap(machine, ipr * 250.0, context)
            assert (snapped.ipm, snapped.row, snapped.comments) == (ipr * 250.0, row, ())
            assert plugin.command(machine, ipr * 250.0, context).command == row + 11


def test_type2_without_a_spindle_speed_assumes_option_27() -> None:
    """No speed given: option 27 (standard 80 RPM) with the manual's comment, as SPINDL
    and FEDRAT/IPR do (001 L28310-28314, L24722-24727): 6.4 IPM is 0.08 IPR. The comment
    comes with FEDRAT's snap, not again in every block's command."""
    plugin = feed_type(2)
    machine = example(plugin)
    context = FeedContext(spindle_range=2)
    snapped = plugin.snap(machine, 6.4, context)
    assert snapped.ipm == pytest.approx(6.4)
    assert snapped.row == 7
    assert snapped.comments == (SPEED_ASSUMED,)
    command = plugin.command(machine, snapped.ipm, context)
    assert (command.command, command.comments) == (18.0, ())


def test_type2_without_a_speed_and_option_27_negative_is_fatal_24() -> None:
    """001 L24722-24727: a negative option 27 means "error if no initial spindle speed"."""
    plugin = feed_type(2)
    machine = example(plugin).with_options({27: -1.0})
    with pytest.raises(FatalError) as raised:
        plugin.snap(machine, 6.0, FeedContext(spindle_range=2))
    assert raised.value.number == 24


def test_type2_below_the_table_takes_the_lowest_with_the_comment() -> None:
    """Below range 1's 0.01 IPR (the manual is silent): the lowest, with a comment."""
    plugin = feed_type(2)
    machine = example(plugin)
    context = FeedContext(spindle_speed=100.0, spindle_range=1)
    snapped = plugin.snap(machine, 0.5, context)
    assert (snapped.ipm, snapped.row, snapped.comments) == (1.0, 0, (BELOW_TABLE,))


def test_type2_a_spindle_range_beyond_the_table_is_a_machine_error() -> None:
    """A fourth spindle range on a three-range FRTAB: the table cannot serve it."""
    plugin = feed_type(2)
    with pytest.raises(MachineDefinitionError) as raised:
        plugin.snap(example(plugin), 7.0, FeedContext(spindle_speed=100.0, spindle_range=4))
    assert (raised.value.table, raised.value.entry) == ("feed_table", "feeds")


# --- feed type 3 -----------------------------------------------------------------------


@pytest.mark.parametrize(("feed", "command"), [(40.0, 540), (2.0, 420), (0.1, 310)])
def test_type3_is_the_magic_3_code_of_the_ipm(feed: float, command: int) -> None:
    """E8, 001 L11380-11384: 40 -> 540 and 2 -> 420 as printed. The printed 0.1 -> 210 is a
    manual slip: appendix 7.1's rule (001 L40132-40175; first digit 3 - no zeros after the
    point) gives 310, like its own .153 -> 315, so 310 is tested."""
    plugin = feed_type(3)
    assert snap_then_command(plugin, example(plugin), feed, FeedContext()) == (feed, command)


def test_type3_the_feed_used_is_the_one_the_code_stands_for() -> None:
    """Two significant digits (appendix 7.1): 7.82 IPM is F478, 7.8 IPM made and printed."""
    plugin = feed_type(3)
    made = plugin.command(example(plugin), 7.82, FeedContext())
    assert (made.command, made.ipm) == (478.0, pytest.approx(7.8))


def test_type3_outside_the_magic_3_span_takes_the_limit_with_a_comment() -> None:
    """Appendix 7.1 (001 L40132-40175) codes 0.0001 to 9999 only; 9999 rounds to two
    digits as 10000, code 810."""
    plugin = feed_type(3)
    machine = example(plugin)
    high = plugin.command(machine, 20000.0, FeedContext())
    assert (high.command, high.ipm, high.comments) == (810.0, 10000.0, (OUTSIDE_MAGIC3,))
    low = plugin.snap(machine, 0.00001, FeedContext())
    assert (low.ipm, low.comments) == (0.0001, (OUTSIDE_MAGIC3,))


# --- feed type 4 -----------------------------------------------------------------------


def test_type4_range_1() -> None:
    """E9 example 1, 001 L11422-11432: 0.2 IPM at 100 RPM in feed range 1 is 0.002 IPR,
    row 1, FCOM = 1 + 0 = 1."""
    plugin = feed_type(4)
    context = FeedContext(spindle_speed=100.0, feed_range=1)
    assert snap_then_command(plugin, example(plugin), 0.2, context) == (0.2, 1.0)


def test_type4_range_2_is_five_times_range_1() -> None:
    """E9 example 2, 001 L11434-11442: 4 IPM at 200 RPM in feed range 2 is 0.02 IPR, found
    at row 3 of .005, .010, .015, .020, .030, .045; FCOM = 3 + 0 = 3."""
    plugin = feed_type(4)
    context = FeedContext(spindle_speed=200.0, feed_range=2)
    ipm, command = snap_then_command(plugin, example(plugin), 4.0, context)
    assert (ipm, command) == (pytest.approx(4.0), 3.0)


def test_type4_range_2_rows_and_option_144() -> None:
    """001 L11404-11411: the same row codes F0-F5 in both ranges; option 144 is added."""
    plugin = feed_type(4)
    machine = example(plugin).with_options({144: 10.0})
    context = FeedContext(spindle_speed=100.0, feed_range=2)
    for row, ipr in enumerate((0.005, 0.010, 0.015, 0.020, 0.030, 0.045)):
        snapped = plugin.snap(machine, ipr * 100.0, context)
        assert snapped.ipm == pytest.approx(ipr * 100.0)
        assert plugin.command(machine, snapped.ipm, context).command == row + 10


def test_type4_uses_the_feed_range_not_the_spindle_range() -> None:
    """001 L11422, L11434: "Feed Range = 1/2"; without FEDRAT/RANGE, range 1. Feed range 3
    is not available: range 2, with FEDRAT's comment."""
    plugin = feed_type(4)
    machine = example(plugin)
    none_given = plugin.snap(machine, 0.5, FeedContext(spindle_speed=100.0, spindle_range=2))
    assert (none_given.ipm, none_given.row) == (pytest.approx(0.4), 3)
    third_range = FeedContext(spindle_speed=100.0, feed_range=3)
    third = plugin.snap(machine, 2.0, third_range)
    assert (third.ipm, third.row, third.comments) == (
        pytest.approx(2.0),
        3,
        (RANGE_NOT_AVAILABLE,),
    )
    assert plugin.command(machine, third.ipm, third_range).comments == ()


def test_type4_stores_only_range_1() -> None:
    """001 L11413-11420: option 62 = 1 even with two ranges; a second stored range is
    machine data the type cannot use."""
    plugin = feed_type(4)
    machine = load_machine_text(
        plugin.manual_example.replace("62 = 1.0", "62 = 2.0")
        .replace("63 = 6.0", "63 = 3.0")
        .replace('name = "feed-type-4-example"', 'name = "feed-type-4-two-stored"'),
        "two-stored.toml",
    )
    with pytest.raises(MachineDefinitionError) as raised:
        plugin.snap(machine, 0.2, FeedContext(spindle_speed=100.0))
    assert (raised.value.table, raised.value.entry) == ("optab", 62)


# --- feed type 5 -----------------------------------------------------------------------


def test_type5_xy_and_z_moves_of_feed_range_2() -> None:
    """E10, 001 L11523-11556: 40 IPM in feed range 2. XY: next lowest 35.9, row 27,
    FCOM = 27 + 6 - 1 = 32. Z: 15.1, row 20, FCOM = 20 + 6 - 1 = 25 (printed "~")."""
    plugin = feed_type(5)
    machine = example(plugin)
    xy = plugin.command(machine, 40.0, FeedContext(feed_range=2, axis=XY))
    z = plugin.command(machine, 40.0, FeedContext(feed_range=2, axis=Z))
    assert (xy.command, xy.ipm) == (32.0, 35.9)
    assert (z.command, z.ipm) == (25.0, 15.1)


def test_type5_keeps_the_programmed_feed_at_fedrat() -> None:
    """One feed serves both tables (001 L11523-11556 finds 35.9 for XY and 15.1 for Z from
    the same 40 IPM), so FEDRAT keeps 40 and each block finds its own."""
    plugin = feed_type(5)
    snapped = plugin.snap(example(plugin), 40.0, FeedContext(feed_range=2))
    assert (snapped.ipm, snapped.row, snapped.comments) == (40.0, None, ())


def test_type5_codes_of_every_range() -> None:
    """001 L11478-11489: Z F11-F15, F21-F25, F31-F35 and XY F21-F25, F31-F35, each code for
    its table value."""
    plugin = feed_type(5)
    machine = example(plugin)
    ranges = machine.feed_table_ranges()
    groups = [(Z, r, ranges[r - 1], 11) for r in (1, 2, 3)]
    groups += [(XY, r, ranges[2 + r], 21) for r in (1, 2)]
    for axis, range_number, values, start in groups:
        for entry, value in enumerate(values):
            command = plugin.command(
                machine, value, FeedContext(feed_range=range_number, axis=axis)
            )
            assert (command.command, command.ipm) == (
                start + 10 * (range_number - 1) + entry,
                value,
            )


def test_type5_range_3_for_z_is_range_2_for_xy() -> None:
    """001 L11555-11556: "When Range 3 is programmed for Z, Range 2 is used for XY"."""
    plugin = feed_type(5)
    machine = example(plugin)
    z = plugin.command(machine, 30.0, FeedContext(feed_range=3, axis=Z))
    xy = plugin.command(machine, 30.0, FeedContext(feed_range=3, axis=XY))
    assert (z.command, z.ipm, z.comments) == (33.0, 28.9, ())
    assert (xy.command, xy.ipm, xy.comments) == (31.0, 28.6, ())
    beyond = FeedContext(feed_range=4, axis=Z)
    assert plugin.snap(machine, 30.0, beyond).comments == (RANGE_NOT_AVAILABLE,)
    assert plugin.command(machine, 30.0, beyond).command == 33.0


def test_type5_below_the_range_takes_its_lowest_with_the_comment() -> None:
    """12 IPM under XY range 2 (28.6 ... 65.2, 001 L11481-11489): the manual is silent;
    the lowest, F31, with a comment."""
    plugin = feed_type(5)
    command = plugin.command(example(plugin), 12.0, FeedContext(feed_range=2, axis=XY))
    assert (command.command, command.ipm, command.comments) == (31.0, 28.6, (BELOW_TABLE,))


def test_type5_needs_z_and_xy_ranges() -> None:
    """Option 201 (the Z ranges) must leave XY ranges in option 62 (001 L11464-11474)."""
    plugin = feed_type(5)
    machine = example(plugin).with_options({201: 5.0})
    for call in (plugin.snap, plugin.command):
        with pytest.raises(MachineDefinitionError) as raised:
            call(machine, 40.0, FeedContext(feed_range=2))
        assert (raised.value.table, raised.value.entry) == ("optab", 201)


# --- feed type 6 -----------------------------------------------------------------------


def test_type6_milling_range_1_is_12_times_the_feed() -> None:
    """E11 example 1, 001 L11607-11614: 3.6 IPM, feed range 1, CYCLE/MILL (ICTYP = 6): no
    exact value, next lowest 3.5, FCOM = 12 x 3.5 = 42."""
    plugin = feed_type(6)
    context = FeedContext(feed_range=1, milling=True)
    assert snap_then_command(plugin, example(plugin), 3.6, context) == (3.5, 42.0)


def test_type6_range_2_is_2_times_the_feed() -> None:
    """E11 example 2, 001 L11616-11619: 7.9 IPM in feed range 2: 7 IPM, FCOM = 2 x 7 = 14."""
    plugin = feed_type(6)
    context = FeedContext(feed_range=2)
    assert snap_then_command(plugin, example(plugin), 7.9, context) == (7.0, 14.0)


def test_type6_range_1_only_when_milling() -> None:
    """001 L11563-11569: range 1 needs CYCLE/MILL and FEDRAT/RANGE,1; otherwise range 2 is
    always in force (FEDRAT/RANGE,1 without milling, or milling without a range)."""
    plugin = feed_type(6)
    machine = example(plugin)
    for context in (FeedContext(feed_range=1), FeedContext(milling=True)):
        assert snap_then_command(plugin, machine, 3.6, context) == (3.0, 6.0)


def test_type6_commands_of_the_manual_table() -> None:
    """001 L11591-11600: F6..F60 for the low range and F4..F24 for the high range."""
    plugin = feed_type(6)
    machine = example(plugin)
    low, high = machine.feed_table_ranges()
    milling = FeedContext(feed_range=1, milling=True)
    assert [plugin.command(machine, v, milling).command for v in low] == [
        6.0 * n for n in range(1, 11)
    ]
    assert [plugin.command(machine, v, FeedContext()).command for v in high] == [
        4.0,
        6.0,
        8.0,
        10.0,
        12.0,
        14.0,
        16.0,
        18.0,
        20.0,
        24.0,
    ]


def test_type6_needs_two_ranges() -> None:
    """A low and a high range (001 L11561-11562, option 62 = 2 at L11604): four ranges
    cannot be served."""
    plugin = feed_type(6)
    machine = example(plugin).with_options({62: 4.0, 63: 5.0})
    with pytest.raises(MachineDefinitionError) as raised:
        plugin.snap(machine, 3.6, FeedContext())
    assert (raised.value.table, raised.value.entry) == ("optab", 62)


# --- feed type 7 -----------------------------------------------------------------------


def test_type7_outputs_the_fedrat_value() -> None:
    """E12, 001 L11630-11634: FEDRAT/1 (potentiometer 1) gives FCOM = 1; the code stays the
    programmed feed."""
    plugin = feed_type(7)
    assert snap_then_command(plugin, example(plugin), 1.0, FeedContext()) == (1.0, 1.0)
    assert snap_then_command(plugin, example(plugin), 12.0, FeedContext()) == (12.0, 12.0)


# --- feed type 8 -----------------------------------------------------------------------


def test_type8_is_the_magic_3_code_of_the_snapped_ipr() -> None:
    """E13, 001 L11655-11663, with the OCR corrected: the printed "FIPM = 1" and
    "7/100 = 0. 01" are 7 IPM and 0.07 IPR (0.06 IPR and FIPM = 6 follow from them only).
    Range 2 gives 0.06 IPR, FIPM = 6, FCOM = magic 3 of 0.06 = 260."""
    plugin = feed_type(8)
    context = FeedContext(spindle_speed=100.0, spindle_range=2)
    ipm, command = snap_then_command(plugin, example(plugin), 7.0, context)
    assert (ipm, command) == (pytest.approx(6.0), 260.0)


def test_type8_codes_every_ipr_of_the_table() -> None:
    """Type 2's table (001 L11331-11339) as magic 3 codes, e.g. 0.01 -> 210, 0.26 -> 326."""
    plugin = feed_type(8)
    machine = example(plugin)
    codes = [
        plugin.command(
            machine, ipr * 100.0, FeedContext(spindle_speed=100.0, spindle_range=r)
        ).command
        for r, values in enumerate(machine.feed_table_ranges(), start=1)
        for ipr in values
    ]
    assert codes == [210, 220, 230, 240, 250, 240, 260, 280, 310, 312, 310, 314, 318, 322, 326]


def test_type8_an_ipr_without_a_magic_3_code_is_a_machine_error() -> None:
    """0.00001 IPR has no code: appendix 7.1 (001 L40132-40175) codes 0.0001 to 9999."""
    plugin = feed_type(8)
    machine = load_machine_text(
        plugin.manual_example.replace("0.01, 0.02", "0.00001, 0.02").replace(
            'name = "feed-type-8-example"', 'name = "feed-type-8-tiny"'
        ),
        "tiny.toml",
    )
    with pytest.raises(MachineDefinitionError) as raised:
        plugin.command(machine, 0.001, FeedContext(spindle_speed=100.0, spindle_range=1))
    assert (raised.value.table, raised.value.entry) == ("feed_table", "feeds")


# --- feed type 9 -----------------------------------------------------------------------


def test_type9_snaps_in_the_ipm_table_and_commands_row_plus_option_144() -> None:
    """E14, 001 L11701-11707: 45 IPM in spindle range 2 (14, 18, 26, 30, 40): 40 IPM,
    row 9, FCOM = 9 + 11 = 20 (the printed row "1" of 26 IPM is row 7)."""
    plugin = feed_type(9)
    context = FeedContext(spindle_range=2)
    machine = example(plugin)
    assert snap_then_command(plugin, machine, 45.0, context) == (40.0, 20.0)
    assert plugin.snap(machine, 26.0, context).row == 7


def test_type9_needs_no_spindle_speed() -> None:
    """001 L11671-11674: the values are IPM; no IPR conversion, so no speed comment."""
    plugin = feed_type(9)
    machine = example(plugin).with_options({27: -1.0})
    snapped = plugin.snap(machine, 75.0, FeedContext(spindle_range=3))
    assert (snapped.ipm, snapped.row, snapped.comments) == (70.0, 12, ())


# --- the machine data a table type cannot use -------------------------------------------


@pytest.mark.parametrize("number", [2, 4, 5, 6, 8, 9])
def test_a_table_type_on_a_machine_without_a_feed_table(number: int) -> None:
    """The Standard Machine has no positioning FRTAB (001 L26831-26925)."""
    plugin = feed_type(number)
    context = FeedContext(spindle_speed=100.0, feed_range=1)
    with pytest.raises(MachineDefinitionError) as raised:
        plugin.command(standard_machine(), 10.0, context)
    assert (raised.value.table, raised.value.entry) == ("feed_table", "feeds")


@pytest.mark.parametrize("number", [2, 4, 5, 6, 8, 9])
def test_a_table_type_whose_counts_no_longer_match(number: int) -> None:
    """Option 63 changed after loading (MACHIN/OPTAB): option 62 x option 63 is no longer
    the number of feeds in FRTAB."""
    plugin = feed_type(number)
    machine = example(plugin)
    changed = machine.with_options({63: machine.number_option(63) + 1})
    with pytest.raises(MachineDefinitionError) as raised:
        plugin.command(changed, 10.0, FeedContext(spindle_speed=100.0, feed_range=1))
    assert (raised.value.table, raised.value.entry) == ("feed_table", "feeds")


# --- rotary feed type 1 ----------------------------------------------------------------

PRINTED_ROTARY_IPM = (
    0.754,
    1.0801,
    1.5419,
    2.2009,
    3.1479,
    4.5051,
    6.4476,
    9.1986,
    13.1570,
    18.8496,
)


def test_rotary1_programmed_7_ipm_is_e6() -> None:
    """E15, 001 L11796-11807: the printed "1 IPM" is 7 ("no feedrate exactly equal to 7");
    the next lowest is 6.4476 (6.4460 by the formula), row 6: the rotary command is 6."""
    plugin = rotary_type(1)
    machine = example(plugin)
    snapped = plugin.snap(machine, 7.0, FeedContext())
    assert snapped.row == 6
    assert snapped.ipm == pytest.approx(6.4476, rel=0.005)
    assert plugin.command(machine, snapped.ipm, FeedContext()).command == 6.0


def test_rotary1_table_matches_the_printed_one_within_half_a_percent() -> None:
    """001 L11784-11793 with options 112 = 6 and 114 = 0.5: 2 pi x 6 x 0.5 / 1.43**(9 - n),
    rows 0-9. The printed IPM are 37.699 x RPM values rounded to 3-4 figures (.0409 x
    37.699 = 1.5419, .349 x 37.699 = 13.157), hence differences up to 0.21 %; row 9 is
    exact, 6 pi."""
    plugin = rotary_type(1)
    machine = example(plugin)
    generated = [2 * math.pi * 6.0 * 0.5 / 1.43 ** (9 - n) for n in range(10)]
    for printed, value in zip(PRINTED_ROTARY_IPM, generated, strict=True):
        assert value == pytest.approx(printed, rel=0.005)
    for row, value in enumerate(generated):
        snapped = plugin.snap(machine, value, FeedContext())
        assert (snapped.row, snapped.ipm) == (row, pytest.approx(value, rel=1e-12))
        assert plugin.command(machine, value, FeedContext()).command == row
    assert generated[9] == pytest.approx(6 * math.pi)


def test_rotary1_below_the_table() -> None:
    """Below row 0 (0.7538 IPM, 001 L11784): the lowest row, with a comment."""
    plugin = rotary_type(1)
    snapped = plugin.snap(example(plugin), 0.5, FeedContext())
    assert (snapped.row, snapped.comments) == (0, (BELOW_TABLE,))


@pytest.mark.parametrize("option", [112, 114])
def test_rotary1_needs_a_radius_and_a_maximum(option: int) -> None:
    """Options 112 and 114 build the table (001 L11771-11776)."""
    plugin = rotary_type(1)
    machine = example(plugin).with_options({option: 0.0})
    with pytest.raises(MachineDefinitionError) as raised:
        plugin.snap(machine, 7.0, FeedContext())
    assert (raised.value.table, raised.value.entry) == ("optab", option)
