"""FEDRAT and RAPID (manual §4.1, 001 L31113-31212; §4.1.4, L11809-11910)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import Diagnostic, InputError, NotYetSupported
from gecent.core.spindle import assumed_speed

_FEED_UNITS = ("IPM", "MMPM", "IPR", "MMPR")

if TYPE_CHECKING:
    from gecent.core.run import Run


def fedrat(run: Run, statement: Statement) -> None:
    """FEDRAT/f[,IPM|IPR] or FEDRAT/IPM,f (001 L31113-31212): the feed in machine
    units per minute (per revolution: times the spindle speed), clamped to the
    machine's range (options 48 and 25); the command is made at output. MMPM and MMPR
    are APT IV's; a bare value is in the CL unit and keeps the last mode."""
    numbers = statement.numbers()
    words = [a for a in statement.args if isinstance(a, Word)]
    unbuilt = [w.name for w in words if w.name not in _FEED_UNITS]
    if unbuilt or len(words) > 1:
        raise NotYetSupported(f"FEDRAT/{(unbuilt or [words[1].name])[0]}", statement.where)
    if len(numbers) != 1:
        raise InputError(
            f"FEDRAT expects one feedrate value, found {len(numbers)}", statement.where
        )
    unit = words[0] if words else None
    value = run.units.per_minute(numbers[0], unit)
    if value <= 0:
        raise InputError(f"FEDRAT needs a positive feedrate, found {numbers[0]:g}", statement.where)
    program_feed(run, value, unit, statement, from_fedrat=True)


def program_feed(
    run: Run, value: float, unit: Word | None, statement: Statement, *, from_fedrat: bool = False
) -> None:
    """A programmed feed in machine units (FEDRAT's, or a cycle's): per minute or per
    revolution as its unit word says, or in the last mode without one."""
    feed = run.state.feed
    if unit is not None:
        feed.per_revolution = unit.name in ("IPR", "MMPR")
    if feed.per_revolution:
        feed.per_revolution_value = value
        feed_per_revolution(run, statement, from_fedrat=from_fedrat)
    else:
        set_feed(run, value, statement, from_fedrat=from_fedrat)


def feed_per_revolution(run: Run, statement: Statement, *, from_fedrat: bool = False) -> None:
    """FEDIPM = FEDIPR x the spindle speed, again at every speed change."""
    speed = run.state.spindle.speed
    if speed is None:
        run.warn(Diagnostic("NO SPINDLE SPEED GIVEN FOR IPR MODE.", statement.where))
        speed = run.state.spindle.speed = assumed_speed(run.machine, statement.where)
    set_feed(run, run.state.feed.per_revolution_value * speed, statement, from_fedrat=from_fedrat)


def set_feed(run: Run, feed: float, statement: Statement, *, from_fedrat: bool = False) -> None:
    """FEDIPM within options 48 and 25; only a FEDRAT can ask for rapid by its feed
    (option 109 = +1/+2)."""
    low, high = run.machine.number_option(48), run.machine.number_option(25)
    used = min(max(feed, low), high)
    if from_fedrat and run.rapid.feedrate(feed, high):
        pass  # option 109 = +1/+2: the feed above the range is a rapid request
    elif used != feed:
        per_minute = "MMPM" if run.units.machine_mm == 1.0 else "IPM"
        run.warn(
            Diagnostic(
                f"FEEDRATE {feed:g} {per_minute} IS OUTSIDE THE MACHINE RANGE "
                f"{low:g}-{high:g}; {used:g} {per_minute} USED",
                statement.where,
            )
        )
    run.state.feed.ipm = used
    run.state.feed.programmed = feed


def rapid(run: Run, statement: Statement) -> None:
    """RAPID: the next motion record goes at rapid traverse (option 109)."""
    if statement.args:
        raise NotYetSupported(f"RAPID/{statement.args[0]}", statement.where)
    run.rapid.request()


HANDLERS = {
    "FEDRAT": fedrat,
    "RAPID": rapid,
}
