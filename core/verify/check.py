"""One verification: the machine, the CL path, rs274's reading of the tape, the comparison
and its report (docs/verify.md)."""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field

from gecent.core.cl.records import Record, Statement
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.selection import apply_machin_options, first_machin, resolve_machine
from gecent.core.macros.dialect import choose_dialect, read_in_dialect, read_raw
from gecent.core.plugins import PluginSet
from gecent.core.verify.clpath import cl_path
from gecent.core.verify.compare import AXIS_NAMES, Comparison, compare
from gecent.core.verify.fiveaxis import (
    DEFAULT_AXIS_TOLERANCE,
    FiveAxisKinematics,
    FiveAxisVerification,
    compare_poses,
)
from gecent.core.verify.fiveaxis_cl import cl_poses
from gecent.core.verify.rs274 import Interpretation, interpret, offset_words

DEFAULT_TOLERANCE_MM = 0.001


@dataclass
class Verification:
    machine: MachineDefinition
    interpretation: Interpretation
    comparison: Comparison | None  # None when rs274 stopped on the tape
    tolerance: float  # in the tape's units
    unit: str
    tape_lines: list[str]
    unfollowed: list[Statement] = field(default_factory=list)  # CL motion nobody follows
    problem: str | None = None  # the tape cannot be compared at all (its units)

    @property
    def passed(self) -> bool:
        return (
            self.problem is None
            and self.comparison is not None
            and self.comparison.passed
            and not self.unfollowed
        )

    def report(self) -> list[str]:
        unit = self.unit
        if self.problem is not None:
            return [f"verify: FAILED: {self.problem}"]
        if self.comparison is None:
            line = self.interpretation.error_line
            text = self._tape_text(line)
            return [
                "verify: FAILED: rs274 stopped reading the tape"
                + (f" at tape line {line}: {text}" if line else ""),
                f"  rs274: {self.interpretation.error}",
            ]
        result = self.comparison
        deviation = "  ".join(f"{AXIS_NAMES[i]} {result.deviation[i]:.4f}" for i in range(3))
        tools = self.interpretation.tools
        lines = [
            f"verify: {result.moves} tape moves (rs274), {result.targets} CL points, "
            f"{result.arcs} arcs and {result.feeds} feeds checked, tolerance "
            f"{self.tolerance:g} {unit}",
            f"tools: {', '.join(f'T{t}' for t in tools) or 'none'} (diameter and length 0: "
            "the programmed path is compared)",
            f"max deviation ({unit}): {deviation}",
        ]
        if self.unfollowed:
            first = self.unfollowed[0]
            more = len(self.unfollowed) - 1
            lines.append(
                f"verify: FAILED: the CL file moves the tool by {first.major} at {first.where}"
                + (f" (and {more} more such records)" if more else "")
                + ", which the post does not follow: the tape cannot be shown to follow the CL"
            )
            return lines
        mismatch = result.mismatch
        if mismatch is None:
            lines.append("verify: passed: every CL point reached in order")
            return lines
        where = mismatch.target.where
        lines.append(f"verify: FAILED: first mismatch at CL {where}: {mismatch.target.statement}")
        if mismatch.move is not None:
            line = mismatch.move.line
            lines.append(f"  tape line {line}: {self._tape_text(line)}")
            end = ", ".join(f"{v:.4f}" for v in mismatch.move.end)
            lines.append(f"  the tape's {mismatch.move.kind} move ends at ({end})")
        target = ", ".join(f"{v:.4f}" for v in mismatch.target.point)
        lines.append(f"  the CL point is ({target}): {mismatch.reason}")
        return lines

    def _tape_text(self, line: int | None) -> str:
        if line is None or not 1 <= line <= len(self.tape_lines):
            return "?"
        return self.tape_lines[line - 1].strip()


def cl_machine(
    cl_file: str,
    plugins: PluginSet,
    machine_key: str | MachineDefinition | None,
    dialect: str | None = None,
) -> MachineDefinition:
    """The machine a CL file is posted on: --machine, else its MACHIN/GECENT with the
    statement's OPTAB changes and LINEAR/LINCIR, as the post chooses it."""
    request, _ = first_machin(read_raw(cl_file, plugins, choose_dialect(cl_file, plugins, dialect)))
    machine = resolve_machine(plugins, machine_key, request)
    if request is not None:  # the post applies its OPTAB changes to the machine it runs on
        machine = apply_machin_options(machine, request)[0]
    return machine


def cl_as_posted(
    cl_file: str, plugins: PluginSet, machine: MachineDefinition, dialect: str | None = None
) -> Iterator[Record]:
    """A CL file's records as the post reads them for this machine: through its dialect
    (given or detected), in the machine's unit until UNITS says."""
    spoken = choose_dialect(cl_file, plugins, dialect)
    return read_in_dialect(cl_file, plugins, spoken, None, machine.number_option(138) == 1)


def verify_five_axis(
    tape_path: str,
    records: Iterable[Record],
    machine: MachineDefinition,
    tolerance_mm: float,
    axis_tolerance: float = DEFAULT_AXIS_TOLERANCE,
) -> FiveAxisVerification:
    """A five-axis machine by data: the tape's moves carried back to the part through the
    machine's kinematics (core/verify/fiveaxis.py)."""
    chain = machine.kinematics
    assert chain is not None
    try:
        poses, lengths = cl_poses(records, machine)
    except ValueError as exc:
        problem = f"{exc}, which the post does not follow"
        reading = Interpretation([], "MM", None, None)
        return FiveAxisVerification(
            machine, reading, None, tolerance_mm, axis_tolerance, "mm", [], problem
        )
    # rs274 reads a tool-centre-point control's positions as written: G43.4 as G43
    tcp = machine.number_option(265) == 1 and chain.tcp_on
    reading = interpret(tape_path, replace={chain.tcp_on: "G43"} if tcp else None)
    unit = "in" if reading.units == "INCHES" else "mm"
    tolerance = tolerance_mm / 25.4 if unit == "in" else tolerance_mm
    tolerance = max(tolerance, machine.number_option(14) * (0.5 + 1e-9))
    with open(tape_path, encoding="ascii", errors="replace") as tape:
        lines = tape.read().splitlines()
    if reading.error is not None:
        return FiveAxisVerification(machine, reading, None, tolerance, axis_tolerance, unit, lines)
    if chain.needs_tool_length and machine.number_option(265) != 1:
        missing = sorted({m.tool for m in reading.moves if m.tool not in lengths})
        if missing:
            problem = (
                f"the slides are computed for the head's tool, but the CL gives no LENGTH for "
                f"T{missing[0]}"
            )
            return FiveAxisVerification(
                machine, reading, None, tolerance, axis_tolerance, unit, lines, problem
            )
    fmt = machine.registers.formats[11]
    decimals = min(4, fmt.right) if fmt is not None else 4
    kinematics = FiveAxisKinematics(machine, chain, lengths)
    comparison = compare_poses(
        poses, reading.moves, kinematics, tolerance, axis_tolerance, decimals
    )
    return FiveAxisVerification(
        machine, reading, comparison, tolerance, axis_tolerance, unit, lines
    )


def verify(
    tape_path: str,
    cl_file: str,
    plugins: PluginSet,
    machine_key: str | MachineDefinition | None = None,
    tolerance_mm: float = DEFAULT_TOLERANCE_MM,
    dialect: str | None = None,
    axis_tolerance: float = DEFAULT_AXIS_TOLERANCE,
) -> Verification | FiveAxisVerification:
    machine = cl_machine(cl_file, plugins, machine_key, dialect)
    if machine.kinematics is not None:
        records = cl_as_posted(cl_file, plugins, machine, dialect)
        return verify_five_axis(tape_path, records, machine, tolerance_mm, axis_tolerance)
    path = cl_path(cl_as_posted(cl_file, plugins, machine, dialect), machine)
    reading = interpret(tape_path, diameter=machine.number_option(260) == 1)
    unit = "in" if reading.units == "INCHES" else "mm"
    tolerance = tolerance_mm / 25.4 if unit == "in" else tolerance_mm
    # no tape is closer to the CL than half its step: a finer tolerance is raised to that
    # (0.0001 in, the inch pack's step, is 0.00254 mm)
    tolerance = max(tolerance, machine.number_option(14) * (0.5 + 1e-9))
    with open(tape_path, encoding="ascii", errors="replace") as tape:
        lines = tape.read().splitlines()
    if reading.error is not None:
        return Verification(machine, reading, None, tolerance, unit, lines)
    fmt = machine.registers.formats[11]
    decimals = min(4, fmt.right) if fmt is not None else 4
    feed_tolerance = 0.5 * 10.0**-decimals + 1e-9
    machine_unit = "mm" if machine.number_option(138) == 1 else "in"
    if unit != machine_unit:
        problem = (
            f"the tape is in {'inches (G20)' if unit == 'in' else 'millimetres (G21)'}, "
            f"the machine and the CL path in {'millimetres' if machine_unit == 'mm' else 'inches'}"
        )
        return Verification(machine, reading, None, tolerance, unit, lines, [], problem)
    step = machine.number_option(14)
    comparison = compare(
        path,
        reading.moves,
        tolerance,
        feed_tolerance,
        offset_words("\n".join(lines)),
        tolerance + step,
    )
    return Verification(machine, reading, comparison, tolerance, unit, lines, path.unfollowed)
