"""The ``gecent`` commands that read a CL file or a tape without posting it: ``cl`` (print
or convert the records), ``verify`` (the tape read back by LinuxCNC's rs274) and ``plot``."""

from __future__ import annotations

import io
import json
import sys
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any

import click
from gecent.core.cl.records import Record
from gecent.core.cl.stream import read_cl
from gecent.core.cli_support import (
    DIALECT_HELP,
    binary_layout,
    installed_plugins,
    machine_override,
    reporting_errors,
)
from gecent.core.errors import InputError
from gecent.core.macros.dialect import choose_dialect, in_dialect, read_raw
from gecent.core.output.files import write_atomically

if TYPE_CHECKING:
    from gecent.core.machine.definition import MachineDefinition
    from gecent.core.plugins import PluginSet


@click.command("cl")
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
@click.option("--dialect", metavar="NAME", help=DIALECT_HELP)
@reporting_errors
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

    plugins = installed_plugins()
    spoken = choose_dialect(input_path, plugins, dialect)
    raw = read_cl(input_path, plugins, binary_layout(in_layout)) if in_layout else None
    records = in_dialect(raw or read_raw(input_path, plugins, spoken), spoken, None)
    heading = None
    if spoken is not None:
        how = "given" if dialect else "detected"
        heading = f"DIALECT {spoken.name} ({spoken.title}), {how}"
        if as_json or out_layout is not None:
            click.echo(heading, err=True)
    if out_layout is not None:
        layout = binary_layout(out_layout)
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


@click.command("verify")
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
@click.option(
    "--axis-tolerance",
    "axis_tolerance",
    type=click.FloatRange(min=0.0, min_open=True),
    default=0.001,
    show_default=True,
    help="A five-axis machine: the largest tool-axis deviation allowed, in degrees.",
)
@click.option("--dialect", metavar="NAME", help=DIALECT_HELP)
@reporting_errors
def verify_command(
    tape_path: str,
    cl_file: str,
    machine_key: str | None,
    tolerance: float,
    axis_tolerance: float,
    dialect: str | None,
) -> None:
    """Read TAPE with LinuxCNC's rs274 and compare its tool path with the CL path: exit 0 when
    every CL point is reached in order, 1 at the first mismatch (docs/verify.md)."""
    from gecent.core.verify.check import verify

    plugins = installed_plugins()
    override = machine_override(plugins, machine_key)
    result = verify(tape_path, cl_file, plugins, override, tolerance, dialect, axis_tolerance)
    for line in result.report():
        click.echo(line)
    sys.exit(0 if result.passed else 1)


@click.command("plot")
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
@click.option("--dialect", metavar="NAME", help=DIALECT_HELP)
@click.option(
    "--axis-every",
    "axis_every",
    type=int,
    default=10,
    show_default=True,
    help="A five-axis machine: draw the tool axis at every Nth point.",
)
@click.option(
    "--axis-length",
    "axis_length",
    type=float,
    default=10.0,
    show_default=True,
    help="A five-axis machine: the length of each tool-axis line drawn.",
)
@reporting_errors
def plot_command(
    input_path: str,
    output: str,
    cl_file: str | None,
    machine_key: str | None,
    plane: str,
    dialect: str | None,
    axis_every: int,
    axis_length: float,
) -> None:
    """Backplot a tape (read by LinuxCNC's rs274; .ngc, .nc, .tap, .tape) or a CL file:
    rapid moves dashed, feed moves solid, arcs as arcs. On a five-axis machine by data the
    picture is 3-D: the tool tip's path in the part and the tool axis every N points."""
    from gecent.core.machine.selection import resolve_machine
    from gecent.core.plot import cl_segments, is_tape, render, tape_segments
    from gecent.core.verify.check import cl_as_posted, cl_machine
    from gecent.core.verify.clpath import cl_path
    from gecent.core.verify.rs274 import interpret

    plugins = installed_plugins()
    override = machine_override(plugins, machine_key)
    cl_source = cl_file if is_tape(input_path) else input_path
    machine = None
    if cl_source is not None:
        machine = cl_machine(cl_source, plugins, override, dialect)
    elif override is not None:
        machine = resolve_machine(plugins, override, None)
    unit = "in" if machine is not None and machine.number_option(138) == 0 else "mm"
    if machine is not None and machine.kinematics is not None:
        drawn = plot_five_axis(
            input_path, cl_file, plugins, machine, dialect, output, axis_every, axis_length
        )
        click.echo(f"plot: {drawn} points drawn in 3-D to {output}")
        return
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
            overlay = cl_segments(
                cl_path(cl_as_posted(cl_file, plugins, machine, dialect), machine), plane
            )
    else:
        assert machine is not None
        segments = cl_segments(
            cl_path(cl_as_posted(input_path, plugins, machine, dialect), machine), plane
        )
    title = f"{Path(input_path).name} ({plane}, {len(segments)} moves)"
    render(segments, output, plane=plane, title=title, overlay=overlay, unit=unit)
    click.echo(f"plot: {len(segments)} moves drawn to {output}")


def plot_five_axis(
    input_path: str,
    cl_file: str | None,
    plugins: PluginSet,
    machine: MachineDefinition,
    dialect: str | None,
    output: str,
    every: int,
    length: float,
) -> int:
    """The 3-D plot of a five-axis tape or CL file (core/plot5.py); the points drawn."""
    from gecent.core.plot import is_tape
    from gecent.core.plot5 import cl_path, render_five_axis, tape_path
    from gecent.core.verify.check import cl_as_posted
    from gecent.core.verify.fiveaxis import FiveAxisKinematics
    from gecent.core.verify.fiveaxis_cl import cl_poses
    from gecent.core.verify.rs274 import interpret

    chain = machine.kinematics
    assert chain is not None
    source = cl_file if is_tape(input_path) else input_path
    poses, lengths = (
        cl_poses(cl_as_posted(source, plugins, machine, dialect), machine)
        if source is not None
        else ([], {})
    )
    overlay = cl_path(poses) if poses and is_tape(input_path) else None
    if is_tape(input_path):
        tcp = machine.number_option(265) == 1 and chain.tcp_on
        reading = interpret(input_path, replace={chain.tcp_on: "G43"} if tcp else None)
        if reading.error is not None:
            click.echo(
                f"warning: rs274 stopped at tape line {reading.error_line}: "
                f"{reading.error}; the path up to there is drawn",
                err=True,
            )
        path = tape_path(reading.moves, FiveAxisKinematics(machine, chain, lengths))
    else:
        path = cl_path(poses)
    title = f"{Path(input_path).name} (tool tip in the part, {len(path)} points)"
    render_five_axis(path, output, title=title, overlay=overlay, every=every, axis_length=length)
    return len(path)
