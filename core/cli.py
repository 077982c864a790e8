"""The ``gecent`` command: ``post``, the machine listings and the plugin list; the commands
that only read (``cl``, ``verify``, ``plot``) are in cli_tools.py."""

from __future__ import annotations

import json
import os
import shutil
import signal
import sys
import tempfile
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import replace
from pathlib import Path
from typing import Any

import click
from gecent.core import __version__
from gecent.core.cl.records import Record
from gecent.core.cli_batch import batch_command
from gecent.core.cli_support import (
    DIALECT_HELP,
    installed_plugins,
    load_machine,
    machine_override,
    ptonly_override,
    reporting_errors,
)
from gecent.core.cli_tools import cl_command, plot_command, verify_command
from gecent.core.dispatch.post import post as run_post
from gecent.core.errors import Diagnostic, GecentError, SourcePosition
from gecent.core.families import FAMILIES, MachinePack
from gecent.core.machine.definition import MachineDefinition
from gecent.core.macros.files import load_macro_file
from gecent.core.macros.table import with_macros
from gecent.core.motion.guard import DEFAULT_MAX_SEGMENTS
from gecent.core.output.modern import modern_output
from gecent.core.output.sinks import Sinks, output_sinks
from gecent.core.plugins import PluginSet


def _plugin_rows(plugins: PluginSet) -> list[dict[str, Any]]:
    rows = []
    for family in FAMILIES:
        infos = sorted(
            plugins.family(family.name).values(), key=lambda i: (str(type(i.key)), i.key)
        )
        for info in infos:
            rows.append(
                {
                    "family": family.name,
                    "id": info.key,
                    "name": info.name,
                    "distribution": info.distribution,
                    "version": info.version,
                    "module": info.module,
                }
            )
    return rows


def _print_table(rows: list[dict[str, Any]], columns: list[str]) -> None:
    widths = {c: max([len(c)] + [len(str(r[c])) for r in rows]) for c in columns}
    click.echo("  ".join(c.upper().ljust(widths[c]) for c in columns).rstrip())
    for row in rows:
        click.echo("  ".join(str(row[c]).ljust(widths[c]) for c in columns).rstrip())


@click.group(invoke_without_command=True, context_settings={"help_option_names": ["-h", "--help"]})
@click.option("--list-plugins", is_flag=True, help="List every installed plugin and exit.")
@click.option("--json", "as_json", is_flag=True, help="With --list-plugins: JSON output.")
@click.version_option(__version__, prog_name="gecent")
@click.pass_context
@reporting_errors
def main(ctx: click.Context, list_plugins: bool, as_json: bool) -> None:
    """gecent: the GECENT III APT postprocessor, re-made as a plugin framework."""
    if list_plugins:
        plugins = installed_plugins()
        rows = _plugin_rows(plugins)
        if as_json:
            failures = [vars(f) for f in plugins.failures]
            click.echo(json.dumps({"plugins": rows, "failures": failures}, indent=2))
        else:
            _print_table(rows, ["family", "id", "name", "distribution", "version", "module"])
        ctx.exit(0)
    if ctx.invoked_subcommand is None:
        click.echo(ctx.get_help())


@main.command()
@click.option("--json", "as_json", is_flag=True, help="JSON output.")
@reporting_errors
def machines(as_json: bool) -> None:
    """List the installed machines."""
    plugins = installed_plugins()
    rows = []
    for info in plugins.family("machines").values():
        pack: MachinePack = info.obj
        rows.append(
            {
                "number": "" if pack.number is None else pack.number,
                "name": pack.name,
                "title": pack.title,
                "distribution": info.distribution,
                "origin": pack.origin,
            }
        )
    rows.sort(key=lambda r: (r["number"] == "", r["number"] if r["number"] != "" else 0, r["name"]))
    if as_json:
        click.echo(json.dumps(rows, indent=2))
    else:
        _print_table(rows, ["number", "name", "title", "distribution"])


@main.group()
def machine() -> None:
    """Inspect one machine."""


@machine.command("show")
@click.argument("key", metavar="ID")
@click.option("--all", "show_all", is_flag=True, help="Also list options at their standard value.")
@click.option("--json", "as_json", is_flag=True, help="JSON output.")
@reporting_errors
def machine_show(key: str, show_all: bool, as_json: bool) -> None:
    """Show a machine's resolved tables and options (ID: number, name or a .toml file)."""
    from gecent.core.machine.describe import describe_machine, machine_as_dict

    definition = load_machine(installed_plugins(), key)
    if as_json:
        click.echo(json.dumps(machine_as_dict(definition), indent=2))
    else:
        click.echo(describe_machine(definition, show_all), nl=False)


@main.command()
@click.argument("input_path", metavar="INPUT", type=click.Path(dir_okay=False, allow_dash=True))
@click.option(
    "--machine",
    "machine_key",
    metavar="ID",
    help="Machine number, name or .toml file; overrides MACHIN/GECENT in the CL file.",
)
@click.option(
    "-o",
    "--output",
    "tape_path",
    type=click.Path(dir_okay=False),
    help="Tape image file (default: INPUT's name with .tape, in the current folder; "
    "stdin.tape when INPUT is - for standard input).",
)
@click.option(
    "--listing",
    "listing_path",
    type=click.Path(dir_okay=False),
    help="Printed listing file (default: beside the tape with .lis; on G-code machines "
    "none unless given).",
)
@click.option(
    "--punch",
    "punch_to",
    nargs=2,
    type=(click.Choice(["eia", "ascii"]), click.Path(dir_okay=False)),
    metavar="CODE FILE",
    help="Also write the punched tape, one byte per frame, in EIA RS-244 or ASCII RS-358 code.",
)
@click.option(
    "--json",
    "as_json",
    is_flag=True,
    help="Also print the blocks on standard output as JSON lines, one object per block.",
)
@click.option(
    "--max-segments",
    type=click.IntRange(min=0),
    default=DEFAULT_MAX_SEGMENTS,
    show_default=True,
    help="Most segment blocks one CL move may make (0: no bound); a longer move is refused.",
)
@click.option("--dialect", metavar="NAME", help=DIALECT_HELP)
@click.option(
    "--macros",
    "macro_files",
    multiple=True,
    type=click.Path(dir_okay=False),
    metavar="FILE",
    help="Also use the macros of this Python file (docs/macros.md); may be repeated.",
)
@click.option(
    "--ptonly",
    "ptonly_deck_path",
    type=click.Path(dir_okay=False, exists=True),
    metavar="DECK",
    help="A PTONLY/2 run: INPUT is a saved CL tape and DECK holds PTONLY/2, MACHIN/GECENT,n "
    "and FINI; the machine is the deck's, the tape's MACHIN statements change options only.",
)
@click.option(
    "--no-fast-path",
    "general_path",
    is_flag=True,
    help="Post every record by the general path (for checking the fast path; slower).",
)
@reporting_errors
def post(
    input_path: str,
    machine_key: str | None,
    tape_path: str | None,
    listing_path: str | None,
    punch_to: tuple[str, str] | None,
    as_json: bool,
    max_segments: int,
    dialect: str | None,
    macro_files: tuple[str, ...],
    ptonly_deck_path: str | None,
    general_path: bool,
) -> None:
    """Postprocess a CL file into a tape image and a printed listing.

    Outputs go where they are named; a tape with no -o goes to the current folder as
    INPUT's name with .tape, the listing beside the tape with .lis (on machines whose tape
    is G-code for a modern control, only when --listing asks). Nothing is written into the
    input's folder unless named there. INPUT - reads the CL file from standard input."""
    _terminate_cleanly()
    plugins = installed_plugins()
    for macro_file in macro_files:
        plugins = with_macros(plugins, load_macro_file(macro_file), f"file {macro_file}")
    if ptonly_deck_path is not None:
        machine_key, deck_notes = ptonly_override(ptonly_deck_path, machine_key)
        for note in deck_notes:
            click.echo(str(note), err=True)
    override = machine_override(plugins, machine_key)
    stem = "stdin" if input_path == "-" else Path(input_path).stem
    tape_target = Path(tape_path) if tape_path else Path(stem + ".tape")

    def make_sinks(machine: MachineDefinition) -> Sinks:
        listing = listing_path
        if listing is None and not modern_output(machine):
            listing = str(tape_target.with_suffix(".lis"))
        return output_sinks(
            plugins, machine, tape_target, listing, punch_to, sys.stdout if as_json else None
        )

    with _input_file(input_path) as source:

        def report(diagnostic: Diagnostic) -> None:
            click.echo(
                str(diagnostic).replace(source, "-") if source != input_path else str(diagnostic),
                err=True,
            )

        try:
            run_post(
                source,
                plugins,
                override,
                _progress(source),
                make_sinks,
                report,
                max_segments,
                fast=not general_path,
                dialect=dialect,
            )
        except GecentError as exc:  # standard input is named "-", not its spool
            where = getattr(exc, "where", None)
            if source != input_path and isinstance(where, SourcePosition) and where.file == source:
                exc.where = replace(where, file="-")  # type: ignore[attr-defined]
            raise


@contextmanager
def _input_file(input_path: str) -> Iterator[str]:
    """The CL file to read: the path itself, or for "-" standard input spooled to a
    temporary file (the post reads the CL file twice: the first pass for MACHIN, then the
    run), removed afterwards."""
    if input_path != "-":
        yield input_path
        return
    with tempfile.TemporaryDirectory(prefix="gecent-") as folder:
        spooled = os.path.join(folder, "stdin")
        with open(spooled, "wb") as handle:
            shutil.copyfileobj(sys.stdin.buffer, handle)
        yield spooled


def _terminate_cleanly() -> None:
    """SIGTERM (a job killed by its scheduler, a timeout) unwinds the run like Ctrl-C does,
    so the sinks remove their temporary files."""

    def stop(signum: int, frame: object) -> None:
        raise SystemExit(128 + signum)

    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGTERM, stop)


def _progress(input_path: str) -> Callable[[Iterator[Record]], Iterator[Record]] | None:
    """A progress bar on standard error while a long post runs, only on a terminal: the
    total is the text file's line count (records are at most that), none for binary."""
    if not sys.stderr.isatty():
        return None
    from tqdm import tqdm

    total: int | None = None
    with open(input_path, "rb") as handle:
        head = handle.read(65536)
        if b"\0" not in head:  # a text CL file
            total = head.count(b"\n")
            for chunk in iter(lambda: handle.read(1 << 20), b""):
                total += chunk.count(b"\n")

    def watch(records: Iterator[Record]) -> Iterator[Record]:
        yield from tqdm(records, total=total, unit=" records", leave=False, file=sys.stderr)

    return watch


for _command in (cl_command, verify_command, plot_command, batch_command):
    main.add_command(_command)


if __name__ == "__main__":  # pragma: no cover
    main()
