"""Contract: every registered positioning feed type (family "feedtypes", option 78) and
rotary feed type (family "rotaryfeeds", option 141), built-in or third-party.

Each plugin is tried on the machine of its own ``manual_example`` (a machine-file overlay
of the Standard Machine), in every context the machine allows, over feeds swept across
its table (from far below to far above, through every FRTAB value and its multiples by
the spindle speeds tried). In one context:

* snap is idempotent: snapping the snapped feed gives the same feed and row;
* snap never raises the feed, except below the table: then it gives the lowest feed snap
  ever gives in that context, with a comment;
* the command of a feed equals the command of its snapped feed, and the IPM a command
  stands for is a feed snap keeps (so every table value round-trips);
* the command never decreases as the feed rises.

Commands are not compared across contexts: type 2's (and 8's, 9's) ranges overlap (0.04
IPR is in ranges 1 and 2), type 4's range 2 reuses range 1's codes, type 5's XY codes
overlap its Z codes (F21-F35 in both), and type 6's K is 12 in range 1 but 2 in range 2.
No type is exempt within one context.

On the Standard Machine, which has no positioning feed table, a type whose example needs
one raises MachineDefinitionError, and no type raises anything else.
"""

from __future__ import annotations

import math
import re
from dataclasses import fields, is_dataclass
from functools import cache
from itertools import pairwise, product

import pytest
from gecent.core.errors import MachineDefinitionError
from gecent.core.feed.positioning import XY, FeedContext, FeedSnap, FeedType, Z
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.plugins import PluginInfo

from .conftest import registered
from .numbered import check_family_loads, check_numbered_plugin

pytestmark = pytest.mark.contract

FAMILIES = ("feedtypes", "rotaryfeeds")
SELECTING_OPTION = {"feedtypes": 78, "rotaryfeeds": 141}
MACHINE_NAME = re.compile(r"^[a-z0-9][a-z0-9_.-]*$")
SPEEDS = (100.0, None)  # a given spindle speed, and none (the type's own fallback)
CLOSE = 1e-9


def _infos() -> list[PluginInfo]:
    return [info for family in FAMILIES for info in registered(family)]


PLUGINS = {"argvalues": _infos(), "ids": [f"{i.family}-{i.key}" for i in _infos()]}


@cache
def example(info: PluginInfo) -> MachineDefinition:
    return load_machine_text(info.obj.manual_example, f"{info.module}.manual_example")


def contexts(machine: MachineDefinition) -> list[FeedContext]:
    spindle_ranges = range(1, max(1, len(machine.feed_table_ranges())) + 1)
    return [
        FeedContext(
            spindle_speed=speed,
            spindle_range=spindle_range,
            feed_range=feed_range,
            milling=milling,
            axis=axis,
        )
        for speed, spindle_range, feed_range, milling, axis in product(
            SPEEDS, spindle_ranges, (0, 1, 2, 3), (False, True), (XY, Z)
        )
    ]


def sweep(machine: MachineDefinition, context: FeedContext) -> list[float]:
    """Feeds from 1e-5 to 1e4 IPM (10 a decade), with every FRTAB value, 5 times it, and
    both times the spindle speeds in play (the context's and option 27's)."""
    feeds = {10 ** (exponent / 10) for exponent in range(-50, 41)}
    speeds = {1.0, machine.number_option(27)}
    if context.spindle_speed is not None:
        speeds.add(context.spindle_speed)
    for value in machine.feed_table:
        for factor, speed in product((1.0, 5.0), speeds):
            if speed > 0:
                feeds.add(value * factor * speed)
    return sorted(feeds)


def same(a: float, b: float) -> bool:
    return math.isclose(a, b, rel_tol=CLOSE, abs_tol=1e-12)


def test_family_loads() -> None:
    for family in FAMILIES:
        check_family_loads(family)


@pytest.mark.parametrize("info", **PLUGINS)
def test_plugin_contract(info: PluginInfo) -> None:
    check_numbered_plugin(info.family, info)
    plugin = info.obj
    assert isinstance(plugin, FeedType)
    assert is_dataclass(plugin) and plugin.__dataclass_params__.frozen  # type: ignore[attr-defined]
    assert "manual_example" in {f.name for f in fields(plugin)}


@pytest.mark.parametrize("info", **PLUGINS)
def test_manual_example_selects_the_plugin(info: PluginInfo) -> None:
    """The example loads over the Standard Machine and its option selects this type
    (option 78 <= 0 selects type 0)."""
    machine = example(info)
    assert MACHINE_NAME.match(machine.name)
    selector = machine.number_option(SELECTING_OPTION[info.family])
    if info.family == "feedtypes" and info.key == 0:
        assert selector <= 0
    else:
        assert selector == info.key


@pytest.mark.parametrize("info", **PLUGINS)
def test_snap_is_idempotent_and_never_raises_the_feed_but_below_the_table(
    info: PluginInfo,
) -> None:
    plugin, machine = info.obj, example(info)
    for context in contexts(machine):
        feeds = sweep(machine, context)
        snaps = [plugin.snap(machine, feed, context) for feed in feeds]
        assert all(isinstance(s, FeedSnap) for s in snaps)
        lowest = min(s.ipm for s in snaps)
        for feed, snapped in zip(feeds, snaps, strict=True):
            again = plugin.snap(machine, snapped.ipm, context)
            assert same(again.ipm, snapped.ipm) and again.row == snapped.row, (
                feed,
                context,
                snapped,
                again,
            )
            nearest = getattr(plugin, "rounds_to_nearest", False)
            if snapped.ipm > feed * (1 + CLOSE) and not nearest:
                assert snapped.comments and same(snapped.ipm, lowest), (feed, context, snapped)
            if nearest:  # the feed its own command makes: rounding it again changes nothing
                made = plugin.command(machine, feed, context)
                assert same(made.ipm, snapped.ipm), (feed, context, snapped, made)


@pytest.mark.parametrize("info", **PLUGINS)
def test_commands_stand_for_snapped_feeds_and_rise_with_the_feed(info: PluginInfo) -> None:
    plugin, machine = info.obj, example(info)
    for context in contexts(machine):
        commands = []
        for feed in sweep(machine, context):
            snapped = plugin.snap(machine, feed, context)
            command = plugin.command(machine, snapped.ipm, context)
            direct = plugin.command(machine, feed, context)
            assert same(direct.command, command.command), (feed, context, direct, command)
            assert same(direct.ipm, command.ipm), (feed, context, direct, command)
            kept = plugin.snap(machine, command.ipm, context)
            assert same(kept.ipm, command.ipm), (feed, context, command, kept)
            assert same(plugin.command(machine, command.ipm, context).command, command.command)
            commands.append(command.command)
        for low, high in pairwise(commands):
            assert high >= low - CLOSE * max(1.0, abs(low)), (context, low, high)


@pytest.mark.parametrize("info", **PLUGINS)
def test_on_the_standard_machine_only_machine_errors(info: PluginInfo) -> None:
    """The Standard Machine has no positioning FRTAB: a table type (its example has one)
    must say so with MachineDefinitionError; nothing may raise another exception."""
    plugin, machine = info.obj, standard_machine()
    needs_table = bool(example(info).feed_table)
    for context, feed in product(contexts(machine), (0.001, 1.0, 10.0, 1000.0)):
        for call in (plugin.snap, plugin.command):
            try:
                call(machine, feed, context)
            except MachineDefinitionError:
                continue
            assert not needs_table, f"{call.__name__} used the missing feed table"
