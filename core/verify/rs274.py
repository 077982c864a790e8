"""LinuxCNC's stand-alone interpreter ``rs274`` (Debian package linuxcnc-uspace) run on a
tape, and its canonical commands read back as a tool path (docs/research/linuxcnc-rs274.md).

rs274 names each canonical command by the N word of the block it came from, so the tape is
given to it with every block's N replaced by its line number in the tape file: the path then
names the tape line of every move. N is only a label in RS274/NGC; nothing else changes.
A lathe programmed in diameters (option 260) is read in LinuxCNC's diameter mode, G07,
which the copy starts with.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
from dataclasses import dataclass
from pathlib import Path

from gecent.core.errors import GecentError, InputError

Point = tuple[float, float, float]

# SELECT_PLANE: the (first, second, third) axis indices of ARC_FEED's arguments
ARC_AXES = {"XY": (0, 1, 2), "XZ": (2, 0, 1), "YZ": (1, 2, 0)}
_CANON = re.compile(r"^\s*\d+\s+N(\S+)\s+([A-Z_0-9]+)\((.*)\)\s*$")
_N_WORD = re.compile(r"^(/?)\s*[Nn]\s*\d+\s*")


class InterpreterMissing(GecentError):
    """rs274 is not installed: verification cannot run (exit 3, like an unbuilt feature)."""

    exit_status = 3

    def __init__(self) -> None:
        super().__init__(
            "rs274 (LinuxCNC's stand-alone G-code interpreter) is not installed: install the "
            "Debian/Ubuntu package linuxcnc-uspace (apt-get install linuxcnc-uspace), or put "
            "rs274 on PATH"
        )

    def __str__(self) -> str:
        return f"error: {self.args[0]}"


@dataclass(frozen=True, slots=True)
class TapeMove:
    """One move the interpreter makes: rapid, feed or arc, its end, and for an arc its
    centre (x, y, z with the third axis at the end's) and sense (+1 counterclockwise about
    the plane's normal in rs274's axis order, -1 clockwise; more turns for |rotation| > 1)."""

    kind: str  # "rapid", "feed" or "arc"
    end: Point
    line: int  # tape line (1-based)
    feed: float
    per_revolution: bool
    plane: str = "XY"
    centre: Point | None = None
    rotation: int = 0
    # the machine when the move runs: the tool selected (T), the spindle (+1 clockwise,
    # -1 counterclockwise, 0 stopped), cutter compensation ("left", "right" or "")
    tool: int = 0
    spindle: int = 0
    side: str = ""
    # a five-axis tape: the rotary axes A, B, C at the end, and whether F is inverse time
    rotary: Point = (0.0, 0.0, 0.0)
    inverse_time: bool = False


@dataclass
class Interpretation:
    moves: list[TapeMove]
    units: str  # "MM" or "INCHES"
    error: str | None  # rs274's message when it stopped, with the tape line it names
    error_line: int | None
    tools: tuple[int, ...] = ()  # the tool table handed to rs274


def rs274_path() -> str | None:
    return shutil.which("rs274")


def numbered_copy(tape: str, *, diameter: bool, replace: dict[str, str] | None = None) -> str:
    """The tape with N = its line number on every block (comments and % stay as they are);
    ``replace``: words rs274 does not know, each with the word it reads the same way (a
    five-axis control's G43.4, whose tool-tip positions rs274 reads as written)."""
    if replace:
        pattern = re.compile(
            r"(?<![A-Z0-9.])(" + "|".join(re.escape(w) for w in replace) + r")(?![0-9.])"
        )
        tape = pattern.sub(lambda m: replace[m.group(1)], tape)
    lines = []
    inserted = not diameter
    for number, line in enumerate(tape.splitlines(), start=1):
        stripped = line.strip()
        if not inserted and stripped and stripped != "%":
            lines.append("G07")  # LinuxCNC's diameter mode; this line gets no N of its own
            inserted = True
        if not stripped or stripped == "%" or stripped.startswith("(") or stripped.startswith("O"):
            lines.append(line)
            continue
        match = _N_WORD.match(line)
        slash = match.group(1) if match else ("/" if stripped.startswith("/") else "")
        body = line[match.end() :] if match else stripped.lstrip("/")
        lines.append(f"{slash}N{number} {body}")
    return "\n".join(lines) + "\n"


SPINDLE_CALLS = {
    "START_SPINDLE_CLOCKWISE": 1,
    "START_SPINDLE_COUNTERCLOCKWISE": -1,
    "STOP_SPINDLE_TURNING": 0,
}
_COMMENT = re.compile(r"\([^)]*\)|;.*$")
_WORD = re.compile(r"([A-Z])\s*([-+]?[\d.]+)")


@dataclass(frozen=True, slots=True)
class OffsetWords:
    """The offset words in force after a tape line (read from its text: rs274 reports
    offsets by value, which the zero tool table makes 0): H and whether G43 is on, D."""

    h: int | None = None
    length_on: bool = False
    d: int | None = None


def offset_words(tape: str) -> list[OffsetWords]:
    """Per tape line (index 0 = line 1), the offset words in force after it."""
    state = OffsetWords()
    found: list[OffsetWords] = []
    for line in tape.splitlines():
        words = _WORD.findall(_COMMENT.sub("", line).upper())
        h, length_on, d = state.h, state.length_on, state.d
        for letter, value in words:
            if letter == "G" and value in ("43", "43.0"):
                length_on = True
            elif letter == "G" and value in ("49", "49.0"):
                length_on = False
            elif letter == "H":
                h = int(float(value))
            elif letter == "D":
                d = int(float(value))
        state = OffsetWords(h, length_on, d)
        found.append(state)
    return found


_TOOL_WORDS = re.compile(r"(?<![A-Z])[TDH]\s*(\d+)", re.IGNORECASE)


def tool_numbers(tape: str) -> tuple[int, ...]:
    """The tools a tape names in its T, D and H words (comments left out), each once."""
    found: set[int] = set()
    for line in tape.splitlines():
        text = _COMMENT.sub("", line)
        found.update(int(number) for number in _TOOL_WORDS.findall(text))
    found.discard(0)
    return tuple(sorted(found))


def tool_table(tools: tuple[int, ...]) -> str:
    """rs274's tool table: every tool the tape names, diameter and length 0, so that G41/G42
    and G43 leave the programmed path as it is (the CL file gives the tool's centre path:
    the comparison is of the programmed path; docs/decisions.md)."""
    return "".join(f"T{tool} P{tool} D0 Z0 ;gecent verify\n" for tool in tools)


def interpret(
    tape_path: str,
    *,
    diameter: bool = False,
    timeout: float = 600.0,
    replace: dict[str, str] | None = None,
) -> Interpretation:
    program = rs274_path()
    if program is None:
        raise InterpreterMissing()
    try:
        tape = Path(tape_path).read_text(encoding="ascii", errors="replace")
    except OSError as exc:
        raise InputError(f"cannot read the tape: {exc.strerror}", None) from None
    tools = tool_numbers(tape)
    with tempfile.TemporaryDirectory(prefix="gecent-verify-") as folder:
        copy = Path(folder) / "tape.ngc"
        copy.write_text(numbered_copy(tape, diameter=diameter, replace=replace), encoding="ascii")
        table = Path(folder) / "tools.tbl"
        table.write_text(tool_table(tools), encoding="ascii")
        done = subprocess.run(
            [program, "-g", "-t", str(table), str(copy)],
            capture_output=True,
            text=True,
            timeout=timeout,
            check=False,
            stdin=subprocess.DEVNULL,
            # rs274 maps (and truncates) $HOME/.tool.mmap: two at once crash each other
            # (SIGBUS), and a running LinuxCNC's tool table would be lost
            env={**os.environ, "HOME": folder},
        )
    reading = parse_canon(done.stdout + done.stderr, done.returncode)
    reading.tools = tools
    return reading


def _numbers(text: str) -> list[float]:
    return [float(v) for v in text.split(",") if v.strip()]


def parse_canon(output: str, returncode: int = 0) -> Interpretation:
    """The moves of rs274's canonical output, with the feed and plane each runs under."""
    moves: list[TapeMove] = []
    feed, per_revolution, plane, units = 0.0, False, "XY", "MM"
    tool, spindle, side = 0, 0, ""
    inverse_time = False
    tail: list[str] = []
    for text in output.splitlines():
        match = _CANON.match(text)
        if match is None:
            if text.strip() and text.strip() != "executing":
                tail.append(text.strip())
            continue
        label, name, args = match.groups()
        line = int(label) if label.isdigit() else 0
        if name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED"):
            values = _numbers(args)
            x, y, z = values[:3]
            a, b, c = (*values[3:6], 0.0, 0.0, 0.0)[:3]
            kind = "rapid" if name == "STRAIGHT_TRAVERSE" else "feed"
            moves.append(
                TapeMove(
                    kind,
                    (x, y, z),
                    line,
                    feed,
                    per_revolution,
                    plane,
                    None,
                    0,
                    tool,
                    spindle,
                    side,
                    (a, b, c),
                    inverse_time,
                )
            )
        elif name == "ARC_FEED":
            values = _numbers(args)
            first, second, third = ARC_AXES[plane]
            end = [0.0, 0.0, 0.0]
            centre = [0.0, 0.0, 0.0]
            end[first], end[second], end[third] = values[0], values[1], values[5]
            centre[first], centre[second], centre[third] = values[2], values[3], values[5]
            moves.append(
                TapeMove(
                    "arc",
                    (end[0], end[1], end[2]),
                    line,
                    feed,
                    per_revolution,
                    plane,
                    (centre[0], centre[1], centre[2]),
                    int(values[4]),
                    tool,
                    spindle,
                    side,
                )
            )
        elif name == "SELECT_TOOL":
            tool = int(_numbers(args)[0])
        elif name in SPINDLE_CALLS:
            spindle = SPINDLE_CALLS[name]
        elif name == "COMMENT" and "cutter radius compensation" in args:
            side = "left" if "on left" in args else "right" if "on right" in args else ""
        elif name == "SET_FEED_RATE":
            feed = _numbers(args)[0]
        elif name == "SET_FEED_MODE":
            per_revolution = _numbers(args)[-1] == 1.0
        elif name == "COMMENT" and "feed mode set to" in args:
            inverse_time = "inverse time" in args
        elif name == "SELECT_PLANE":
            plane = args.strip().removeprefix("CANON_PLANE_")
        elif name == "USE_LENGTH_UNITS":
            units = args.strip().removeprefix("CANON_UNITS_")
    error = error_line = None
    if returncode != 0:
        error = "; ".join(tail) or f"rs274 exited with status {returncode}"
        found = re.search(r"(?:^|\s)/?N(\d+)\b", tail[-1]) if tail else None
        error_line = int(found.group(1)) if found else None
    return Interpretation(moves, units, error, error_line)
