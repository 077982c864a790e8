"""What the ``gecent`` commands share: their error reporting, the installed plugins, the
machine a --machine names and a binary CL layout."""

from __future__ import annotations

import os
import sys
from collections.abc import Callable
from functools import wraps
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

import click
from gecent.core.errors import (
    EXIT_INTERNAL,
    Diagnostic,
    GecentError,
    InputError,
    InternalError,
)
from gecent.core.families import MachinePack
from gecent.core.machine.definition import MachineDefinition
from gecent.core.plugins import PluginSet, get_plugins

if TYPE_CHECKING:
    from gecent.core.cl.binary_layout import Layout

F = TypeVar("F", bound=Callable[..., Any])


def reporting_errors(function: F) -> F:
    """Report gecent errors as one clear message and an exit status; never a traceback."""

    @wraps(function)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return function(*args, **kwargs)
        except GecentError as exc:
            if isinstance(exc, InternalError) and os.environ.get("GECENT_DEBUG"):
                raise
            click.echo(str(exc), err=True)
            sys.exit(exc.exit_status)
        except click.exceptions.Exit:
            raise
        except BrokenPipeError:
            # the reader of our output (head, less) has gone: stop quietly, as cat does
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
            sys.exit(0)
        except Exception as exc:
            if os.environ.get("GECENT_DEBUG"):
                raise
            click.echo(
                f"gecent: internal error: {type(exc).__name__}: {exc} "
                "(set GECENT_DEBUG=1 for the traceback)",
                err=True,
            )
            sys.exit(EXIT_INTERNAL)

    return wrapper  # type: ignore[return-value]


DIALECT_HELP = (
    "The CAM system's dialect the CL file is written in (--list-plugins shows them; none: "
    "plain APT); default: detected from the file."
)


def installed_plugins() -> PluginSet:
    plugins = get_plugins()
    for failure in plugins.failures:
        click.echo(
            f"gecent: warning: plugin {failure.entry_point} ({failure.distribution}) "
            f"not loaded: {failure.error}",
            err=True,
        )
    return plugins


def load_machine(plugins: PluginSet, key: str) -> MachineDefinition:
    if key.endswith(".toml") or os.sep in key:
        return MachinePack.from_path(key).load() if Path(key).exists() else _missing(key)
    pack = plugins.machine(key)
    if pack is None:
        raise InputError(f"machine {key!r} is not installed (see 'gecent machines')")
    return pack.load()


def machine_override(plugins: PluginSet, key: str | None) -> str | MachineDefinition | None:
    """--machine: a machine file is loaded here, a number or name is resolved by the run."""
    if key is not None and (key.endswith(".toml") or os.sep in key):
        return load_machine(plugins, key)
    return key


def ptonly_override(deck: str, machine_key: str | None) -> tuple[str | None, list[Diagnostic]]:
    """--ptonly DECK: the machine a PTONLY/2 deck names (core/machine/selection.py), as the
    --machine it stands for; none when its MACHIN gives no number (the tape's own then)."""
    from gecent.core.cl.apt_source import read_apt_source
    from gecent.core.machine.selection import ptonly_deck

    if machine_key is not None:
        raise InputError("give --machine or --ptonly, not both: the deck names the machine")
    number, notes = ptonly_deck(read_apt_source(deck))
    return (None if number is None else str(number)), notes


def _missing(key: str) -> MachineDefinition:
    raise InputError(f"machine file {key!r} does not exist")


def binary_layout(name: str | None) -> Layout | None:
    from gecent.core.cl.binary_layout import LayoutError, parse_layout

    if name is None:
        return None
    try:
        return parse_layout(name)
    except LayoutError as exc:
        raise InputError(str(exc)) from None
