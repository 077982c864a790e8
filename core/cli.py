"""The ``gecent`` command."""

from __future__ import annotations

import io
import json
import os
import shutil
import signal
import sys
import tempfile
import threading
from collections.abc import Callable, Iterable, Iterator
from contextlib import contextmanager
from dataclasses import replace
from functools import wraps
from pathlib import Path
from typing import TYPE_CHECKING, Any, TypeVar

import click
from gecent.core import __version__
from gecent.core.cl.records import Record
from gecent.core.cl.stream import read_cl
from gecent.core.dispatch.post import post as run_post
from gecent.core.errors import (
    EXIT_INTERNAL,
    Diagnostic,
    GecentError,
    InputError,
    InternalError,
    SourcePosition,
)
from gecent.core.families import FAMILIES, MachinePack
from gecent.core.machine.definition import MachineDefinition
from gecent.core.macros.dialect import choose_dialect, in_dialect, read_raw
from gecent.core.macros.files import load_macro_file
from gecent.core.macros.table import with_macros
from gecent.core.motion.guard import DEFAULT_MAX_SEGMENTS
from gecent.core.output.files import write_atomically
from gecent.core.output.modern import modern_output
from gecent.core.output.sinks import Sinks, output_sinks
from gecent.core.plugins import PluginSet, get_plugins

if TYPE_CHECKING:
    from gecent.core.cl.binary_layout import Layout

F = TypeVar("F", bound=Callable[..., Any])


def _reporting_errors(function: F) -> F:
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


_DIALECT_HELP = (
    "The CAM system's dialect the CL file is written in (--list-plugins shows them; none: "
    "plain APT); default: detected from the file."
)


def _plugins() -> PluginSet:
    plugins = get_plugins()
    for failure in plugins.failures:
        click.echo(
            f"gecent: warning: plugin {failure.entry_point} ({failure.distribution}) "
            f"not loaded: {failure.error}",
            err=True,
        )
    return plugins


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
@_reporting_errors
def main(ctx: click.Context, list_plugins: bool, as_json: bool) -> None:
    """gecent: the GECENT III APT postprocessor, re-made as a plugin framework."""
    if list_plugins:
        plugins = _plugins()
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
@_reporting_errors
def machines(as_json: bool) -> None:
    """List the installed machines."""
    plugins = _plugins()
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


def _load_machine(plugins: PluginSet, key: str) -> MachineDefinition:
    if key.endswith(".toml") or os.sep in key:
        return MachinePack.from_path(key).load() if Path(key).exists() else _missing(key)
    pack = plugins.machine(key)
    if pack is None:
        raise InputError(f"machine {key!r} is not installed (see 'gecent machines')")
    return pack.load()


def _override(plugins: PluginSet, key: str | None) -> str | MachineDefinition | None:
    """--machine: a machine file is loaded here, a number or name is resolved by the run."""
    if key is not None and (key.endswith(".toml") or os.sep in key):
        return _load_machine(plugins, key)
    return key


def _missing(key: str) -> MachineDefinition:
    raise InputError(f"machine file {key!r} does not exist")


@machine.command("show")
@click.argument("key", metavar="ID")
@click.option("--all", "show_all", is_flag=True, help="Also list options at their standard value.")
@click.option("--json", "as_json", is_flag=True, help="JSON output.")
@_reporting_errors
def machine_show(key: str, show_all: bool, as_json: bool) -> None:
    """Show a machine's resolved tables and options (ID: number, name or a .toml file)."""
    from gecent.core.machine.describe import describe_machine, machine_as_dict

    definition = _load_machine(_plugins(), key)
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
@click.option("--dialect", metavar="NAME", help=_DIALECT_HELP)
@click.option(
    "--macros",
    "macro_files",
    multiple=True,
    type=click.Path(dir_okay=False),
    metavar="FILE",
    help="Also use the macros of this Python file (docs/macros.md); may be repeated.",
)
@click.option(
    "--no-fast-path",
    "general_path",
    is_flag=True,
    help="Post every record by the general path (for checking the fast path; slower).",
)
@_reporting_errors
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
    general_path: bool,
) -> None:
    """Postprocess a CL file into a tape image and a printed listing.

    Outputs go where they are named; a tape with no -o goes to the current folder as
    INPUT's name with .tape, the listing beside the tape with .lis (on machines whose tape
    is G-code for a modern control, only when --listing asks). Nothing is written into the
    input's folder unless named there. INPUT - reads the CL file from standard input."""
    _terminate_cleanly()
    plugins = _plugins()
    for macro_file in macro_files:
        plugins = with_macros(plugins, load_macro_file(macro_file), f"file {macro_file}")
    override = _override(plugins, machine_key)
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


def _layout(name: str | None) -> Layout | None:
    from gecent.core.cl.binary_layout import LayoutError, parse_layout

    if name is None:
        return None
    try:
        return parse_layout(name)
    except LayoutError as exc:
        raise InputError(str(exc)) from None


@main.command("cl")
@click.argument("input_path", metavar="INPUT", type=click.Path(dir_okay=False))
@click.option("--json", "as_json", is_flag=True, help="JSON lines instead of a CL print.")
@click.option(
    "--layout",
    "in_layout",
    metavar="LAYOUT",
    help="Binary INPUT layout (apt4, manual4, manual8, with -le or -be); default: detected.",
)
@click.option(
    "--to",
    "out_layout",
    metavar="LAYOUT",
    help="Write a binary CL file in this layout (with -o) instead of printing.",
)
@click.option(
    "-o",
    "--output",
    "output_path",
    type=click.Path(dir_okay=False),
    help="Output file (default: standard output; required with --to).",
)
@click.option("--dialect", metavar="NAME", help=_DIALECT_HELP)
@_reporting_errors
def cl_command(
    input_path: str,
    as_json: bool,
    in_layout: str | None,
    out_layout: str | None,
    output_path: str | None,
    dialect: str | None,
) -> None:
    """Print the records of a CL file (text or binary) as the post reads them (through
    its CAM dialect, which is named first), or convert it to binary."""
    from gecent.core.cl.binary_writer import write_binary

    plugins = _plugins()
    spoken = choose_dialect(input_path, plugins, dialect)
    raw = read_cl(input_path, plugins, _layout(in_layout)) if in_layout else None
    records = in_dialect(raw or read_raw(input_path, plugins, spoken), spoken, None)
    heading = None
    if spoken is not None:
        how = "given" if dialect else "detected"
        heading = f"DIALECT {spoken.name} ({spoken.title}), {how}"
        if as_json or out_layout is not None:
            click.echo(heading, err=True)
    if out_layout is not None:
        layout = _layout(out_layout)
        assert layout is not None
        if output_path is None:
            raise InputError("--to needs -o FILE for the binary CL file")
        buffer = io.BytesIO()
        write_binary(records, buffer, layout)
        write_atomically(output_path, buffer.getvalue())
        return
    if output_path is not None:
        lines = io.StringIO()
        _print_records(records, as_json, lines.write, heading)
        write_atomically(output_path, lines.getvalue().encode("utf-8"))
        return
    _print_records(records, as_json, sys.stdout.write, heading)


def _print_records(
    records: Iterable[Record], as_json: bool, write: Callable[[str], Any], heading: str | None
) -> None:
    from gecent.core.cl.clprint import clprint_lines, record_json

    if as_json:
        for record in records:
            write(json.dumps(record_json(record)) + "\n")
        return
    if heading is not None:
        write(heading + "\n")
    write("TAPENO/  ISN\n")
    for record in records:
        for line in clprint_lines(record):
            write(line + "\n")


if __name__ == "__main__":  # pragma: no cover
    main()


@main.command("verify")
@click.argument("tape_path", metavar="TAPE", type=click.Path(dir_okay=False, exists=True))
@click.option(
    "--cl",
    "cl_file",
    required=True,
    type=click.Path(dir_okay=False, exists=True),
    help="The CL file the tape was posted from.",
)
@click.option(
    "--machine",
    "machine_key",
    metavar="ID",
    help="Machine number, name or .toml file (default: MACHIN/GECENT in the CL file).",
)
@click.option(
    "--tolerance",
    type=click.FloatRange(min=0.0, min_open=True),
    default=0.001,
    show_default=True,
    help="Largest deviation allowed, in millimetres.",
)
@click.option("--dialect", metavar="NAME", help=_DIALECT_HELP)
@_reporting_errors
def verify_command(
    tape_path: str, cl_file: str, machine_key: str | None, tolerance: float, dialect: str | None
) -> None:
    """Read TAPE with LinuxCNC's rs274 and compare its tool path with the CL path: exit 0 when
    every CL point is reached in order, 1 at the first mismatch (docs/verify.md)."""
    from gecent.core.verify.check import verify

    plugins = _plugins()
    override = _override(plugins, machine_key)
    result = verify(tape_path, cl_file, plugins, override, tolerance, dialect)
    for line in result.report():
        click.echo(line)
    sys.exit(0 if result.passed else 1)


@main.command("plot")
@click.argument("input_path", metavar="INPUT", type=click.Path(dir_okay=False, exists=True))
@click.option(
    "-o",
    "--output",
    "output",
    required=True,
    type=click.Path(dir_okay=False),
    help="The picture: FILE.png or FILE.svg.",
)
@click.option(
    "--cl",
    "cl_file",
    type=click.Path(dir_okay=False, exists=True),
    help="With a tape: the CL file, drawn under the tape's path.",
)
@click.option(
    "--machine",
    "machine_key",
    metavar="ID",
    help="Machine number, name or .toml file (default: MACHIN/GECENT in the CL file).",
)
@click.option(
    "--plane",
    type=click.Choice(["XY", "XZ", "YZ"]),
    default="XY",
    show_default=True,
    help="The plane drawn (XZ for a lathe: Z across, X up).",
)
@_reporting_errors
def plot_command(
    input_path: str, output: str, cl_file: str | None, machine_key: str | None, plane: str
) -> None:
    """Backplot a tape (read by LinuxCNC's rs274; .ngc, .nc, .tap, .tape) or a CL file:
    rapid moves dashed, feed moves solid, arcs as arcs."""
    from gecent.core.cl.stream import read_cl
    from gecent.core.machine.selection import resolve_machine
    from gecent.core.plot import cl_segments, is_tape, render, tape_segments
    from gecent.core.verify.check import cl_machine
    from gecent.core.verify.clpath import cl_path
    from gecent.core.verify.rs274 import interpret

    plugins = _plugins()
    override = _override(plugins, machine_key)
    cl_source = cl_file if is_tape(input_path) else input_path
    machine = None
    if cl_source is not None:
        machine = cl_machine(cl_source, plugins, override)
    elif override is not None:
        machine = resolve_machine(plugins, override, None)
    unit = "in" if machine is not None and machine.number_option(138) == 0 else "mm"
    overlay = None
    if is_tape(input_path):
        diameter = machine is not None and machine.number_option(260) == 1
        reading = interpret(input_path, diameter=diameter)
        if reading.error is not None:
            click.echo(
                f"warning: rs274 stopped at tape line {reading.error_line}: "
                f"{reading.error}; the path up to there is drawn",
                err=True,
            )
        segments = tape_segments(reading.moves, plane)
        unit = "in" if reading.units == "INCHES" else "mm"
        if cl_file is not None and machine is not None:
            overlay = cl_segments(cl_path(read_cl(cl_file, plugins), machine), plane)
    else:
        assert machine is not None
        segments = cl_segments(cl_path(read_cl(input_path, plugins), machine), plane)
    title = f"{Path(input_path).name} ({plane}, {len(segments)} moves)"
    render(segments, output, plane=plane, title=title, overlay=overlay, unit=unit)
    click.echo(f"plot: {len(segments)} moves drawn to {output}")
