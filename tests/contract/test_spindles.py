"""Contract: every registered spindle type (option 19), built-in or third-party.

Each spindle-type plugin declares ``manual_example``: a machine overlay in TOML, read over
the Standard Machine, holding its manual section's example table. On that machine:

* ``range_count``, ``speed_limits`` and ``table_speeds`` agree with one another (a discrete
  range ascends from its lowest speed to its highest);
* every table speed of every range round-trips (SPINDL/s,RANGE,r selects speed s in range
  r); a variable type's range limits do the same within the type's rounding;
* a sweep of speeds across each range selects non-decreasing speeds with finite commands,
  in the programmed range, each a speed of the table, and names only M codes the machine has;
* a broken table (emptied; range 1 out of order, or, for a type whose SRTAB holds the
  parameters its speeds are generated from, those parameters negated) and the Standard
  Machine's own table under the type's option 19 give a MachineDefinitionError or a
  selection, never any other exception.

(Type 7 is not a plugin: SPTYPE hands it to the machine's MACFUN, core/spindle_macfun.py.)
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace
from itertools import pairwise
from typing import Any

import pytest
from gecent.core.absent import ABSENT
from gecent.core.errors import MachineDefinitionError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.loader import load_machine_text, standard_machine
from gecent.core.plugins import PluginInfo
from gecent.core.spindle_types import CLW, SpindleRequest, SpindleSelection, SpindleType

from .conftest import plugin_params
from .numbered import check_family_loads, check_numbered_plugin

pytestmark = pytest.mark.contract

SPINDLES = plugin_params("spindles")
_SAME = 1e-6  # RPM


def test_family_loads() -> None:
    check_family_loads("spindles")


@pytest.mark.parametrize("info", **SPINDLES)
def test_plugin_contract(info: PluginInfo) -> None:
    check_numbered_plugin("spindles", info)
    assert isinstance(info.obj, SpindleType)
    assert getattr(info.obj, "manual_example", None), (
        "a spindle type declares manual_example, a TOML machine overlay with its table"
    )


def example(info: PluginInfo) -> tuple[Any, MachineDefinition]:
    plugin = info.obj
    text = plugin.manual_example
    machine = load_machine_text(text, f"spindle-type{plugin.number:02d}-example.toml")
    assert machine.number_option(19) == plugin.number, "the example selects its own type"
    return plugin, machine


def ranges_of(plugin: Any, machine: MachineDefinition) -> list[tuple[int, float, float, Any]]:
    """(range, lowest, highest, table speeds or None) for every range the type offers. A
    range number it does not offer (type 14's unused ranges below its second mode) has an
    empty table or answers speed_limits with a MachineDefinitionError; at least one range
    must be offered."""
    count = plugin.range_count(machine)
    assert isinstance(count, int) and count >= 1
    offered = []
    for r in range(1, count + 1):
        try:
            low, high = plugin.speed_limits(machine, r)
        except MachineDefinitionError:
            continue
        speeds = plugin.table_speeds(machine, r)
        if speeds is None or len(speeds) > 0:
            offered.append((r, low, high, speeds))
    assert offered, "the example offers at least one range"
    return offered


def select(
    plugin: Any, machine: MachineDefinition, speed: float, r: int | None
) -> SpindleSelection:
    selection = plugin.select(machine, SpindleRequest(speed, r, CLW))
    assert isinstance(selection, SpindleSelection)
    assert math.isfinite(selection.command) and selection.command >= 0, selection
    assert math.isfinite(selection.speed) and selection.speed >= 0, selection
    assert all(isinstance(c, str) and c for c in selection.comments)
    return selection


@pytest.mark.parametrize("info", **SPINDLES)
def test_limits_and_table_agree(info: PluginInfo) -> None:
    plugin, machine = example(info)
    for r, low, high, speeds in ranges_of(plugin, machine):
        assert math.isfinite(low) and math.isfinite(high) and 0 <= low <= high, (r, low, high)
        if speeds is None:
            continue  # variable in SFM: only its limits
        assert all(b >= a for a, b in pairwise(speeds)), (r, speeds)
        assert speeds[0] == pytest.approx(low) and speeds[-1] == pytest.approx(high)


@pytest.mark.parametrize("info", **SPINDLES)
def test_every_table_speed_round_trips(info: PluginInfo) -> None:
    plugin, machine = example(info)
    for r, low, high, speeds in ranges_of(plugin, machine):
        if speeds is None:
            # a variable type may round to what the machine can be commanded
            slack = max(1.0, 0.02 * high)
            for limit in (low, high):
                selection = select(plugin, machine, limit, r)
                assert selection.range == r
                assert abs(selection.speed - limit) <= slack, (r, limit, selection)
            continue
        for speed in speeds:
            selection = select(plugin, machine, speed, r)
            assert (selection.range, selection.speed) == (r, pytest.approx(speed)), (
                f"SPINDL/{speed:g},RANGE,{r}: {selection}"
            )


def sweep(low: float, high: float, speeds: tuple[float, ...] | None) -> list[float]:
    steps = 40
    points = {low * 0.5, high * 1.5, *(low + (high - low) * i / steps for i in range(steps + 1))}
    if speeds is not None:
        table = list(speeds)[:400]
        points.update(table)
        points.update((a + b) / 2 for a, b in pairwise(table))
    return sorted(points)


@pytest.mark.parametrize("info", **SPINDLES)
def test_speed_sweep_is_monotonic_and_in_the_table(info: PluginInfo) -> None:
    plugin, machine = example(info)
    table = ranges_of(plugin, machine)
    count = plugin.range_count(machine)
    for r, low, high, speeds in table:
        selected: list[float] = []
        for speed in sweep(low, high, speeds):
            selection = select(plugin, machine, speed, r)
            assert selection.range == r, (speed, r, selection)
            if speeds is not None:
                assert any(abs(selection.speed - s) <= _SAME for s in speeds), selection
                if selection.row is not None:
                    assert speeds[selection.row] == pytest.approx(selection.speed), selection
            check_codes_exist(machine, selection)
            selected.append(selection.speed)
        assert selected == sorted(selected), f"range {r}: {selected}"
        for speed in sweep(low, high, None):
            selection = select(plugin, machine, speed, None)  # the type chooses the range
            assert 1 <= selection.range <= count, selection
            check_codes_exist(machine, selection)


def check_codes_exist(machine: MachineDefinition, selection: SpindleSelection) -> None:
    cells = [*(selection.direction_cells or {}).values()]
    cells += [c for c in (selection.range_cell, selection.stop_cell) if c is not None]
    for cell in cells:
        assert machine.m_code(cell) is not None, f"TABLEM({cell}) is absent: {selection}"


def definition_error_or_value(call: Callable[[], object]) -> MachineDefinitionError | None:
    """A broken table may be reported by any method, but only as MachineDefinitionError."""
    try:
        call()
    except MachineDefinitionError as error:
        assert error.table and error.rule, "the error names the table and the rule"
        return error
    return None


def every_call(plugin: Any, machine: MachineDefinition, speed: float) -> list[object]:
    calls: list[Callable[[], object]] = [
        lambda: plugin.range_count(machine),
        lambda: plugin.speed_limits(machine, 1),
        lambda: plugin.table_speeds(machine, 1),
        lambda: plugin.select(machine, SpindleRequest(speed, None, CLW)),
        lambda: plugin.select(machine, SpindleRequest(speed, 1, CLW)),
    ]
    return [definition_error_or_value(call) for call in calls]


@pytest.mark.parametrize("info", **SPINDLES)
def test_an_empty_table_is_a_machine_definition_error(info: PluginInfo) -> None:
    plugin, machine = example(info)
    _, low, _, _ = ranges_of(plugin, machine)[0]
    empty = replace(machine, store=(ABSENT,) * len(machine.store), srtab_top=0)
    outcomes = every_call(plugin, empty, low)
    assert outcomes[3] is not None and outcomes[4] is not None, "select reports the empty table"


def out_of_order(machine: MachineDefinition, values: tuple[float, ...]) -> MachineDefinition | None:
    """The machine with ``values``, found as a run in SRTAB, stored in reverse."""
    store = list(machine.store)
    size = len(values)
    for start in range(1, len(store) - size + 1):
        window = store[start : start + size]
        if all(
            v is not ABSENT and abs(float(v) - s) <= _SAME
            for v, s in zip(window, values, strict=True)
        ):
            store[start : start + size] = list(reversed(window))
            return replace(machine, store=tuple(store))
    return None


@pytest.mark.parametrize("info", **SPINDLES)
def test_a_range_out_of_order_is_a_machine_definition_error(info: PluginInfo) -> None:
    plugin, machine = example(info)
    _, low, high, speeds = ranges_of(plugin, machine)[0]
    broken = None
    for run in (speeds, (low, high)):
        if run is not None and len(run) > 1 and run[0] != run[-1]:
            broken = out_of_order(machine, tuple(run))
            if broken is not None:
                break
    if broken is None:  # SRTAB holds generation parameters (type 18): negate them
        store = [
            v if v is ABSENT or not 1 <= k <= machine.srtab_top else -float(v)
            for k, v in enumerate(machine.store)
        ]
        broken = replace(machine, store=tuple(store))
    outcomes = every_call(plugin, broken, (low + high) / 2)
    assert outcomes[4] is not None, "SPINDL/s,RANGE,1 reports range 1 out of order"


@pytest.mark.parametrize("info", **SPINDLES)
def test_the_standard_table_is_usable_or_reported(info: PluginInfo) -> None:
    """The Standard Machine (one range, 1-300 RPM, no range codes) under the type's option
    19: the type either works with it or says why it cannot, as a machine-file error."""
    plugin, _ = example(info)
    machine = standard_machine().with_options({19: float(plugin.number)})
    every_call(plugin, machine, 100.0)
