"""The punched tape: tape image lines to frames in EIA RS-244 or ASCII RS-358 code
(manual §3.5.3, appendix 7.6-7.7, 001 L8822-8854, L40712-41022).

One byte per frame, bit 0 = channel 1 ... bit 7 = channel 8, parity included (EIA odd in
channel 5, ASCII even in channel 8). Blanks and periods are never punched (001 L8849); each
block ends with the end-of-block code (option 67: EIA channel 8, ASCII LF).
"""

from __future__ import annotations

import tomllib
from collections.abc import Iterable
from functools import cache
from importlib import resources

from gecent.core.errors import InputError

CODES = ("eia", "ascii")
NOT_PUNCHED = " ."
CARD_FRAMES = 72  # one 72-column card of the tape image


@cache
def table(code: str) -> dict[str, int]:
    raw = resources.files("gecent.core.output").joinpath("data", "tape_codes.toml").read_bytes()
    return {str(k): int(v) for k, v in tomllib.loads(raw.decode("utf-8"))[code].items()}


def punch(lines: Iterable[str], code: str, leader: str = "(", tmark: str = "=") -> bytes:
    """The frames of a tape image; a character the code cannot punch is an error naming it.

    Two stand-ins of the machine's options 64 and 65 are punched as control codes: a line
    made only of the leader stand-in is leader (no end of block), and the TMARK stand-in at
    the start of a line is the end-of-record (rewind stop) code. An empty line is a blank
    card: 72 frames of blank tape (feed holes only), the option-11 filler after END."""
    if code not in CODES:
        raise InputError(f"unknown tape code {code!r} (eia or ascii)")
    codes = table(code)
    end_of_block = codes["EOB"]
    frames = bytearray()
    for number, line in enumerate(lines, start=1):
        if not line:
            frames.extend(bytes([codes["BLANK_TAPE"]]) * CARD_FRAMES)
            continue
        if line.strip(leader) == "":
            frames.extend(bytes([codes["LEADER"]]) * len(line))
            continue
        if line.startswith(tmark):
            frames.append(codes["REWIND_STOP"])
            line = line[1:]
        for character in line:
            if character in NOT_PUNCHED:
                continue
            frame = codes.get(character)
            if frame is None:
                raise InputError(
                    f"tape block {number} ({line!r}): {character!r} has no {code.upper()} code"
                )
            frames.append(frame)
        frames.append(end_of_block)
    return bytes(frames)


def unpunch(frames: bytes, code: str, leader: str = "(", tmark: str = "=") -> list[str]:
    """Read frames back into tape image lines (for tests and for checking a tape).

    A run of leader frames becomes a line of the leader stand-in, each card of blank tape
    an empty line (in ASCII, whose leader is blank tape, blank tape reads as leader); the
    end-of-record code at the start of a block becomes the TMARK stand-in unless it is a
    character of this code (ASCII's rewind stop is "%")."""
    codes = table(code)
    characters = {v: k for k, v in reversed(list(codes.items())) if len(k) == 1}
    end_of_block, leader_frame = codes["EOB"], codes["LEADER"]
    blank, rewind_stop = codes["BLANK_TAPE"], codes["REWIND_STOP"]
    lines: list[str] = []
    current: list[str] = []
    run_frame, run_length = -1, 0

    def close_run() -> None:
        nonlocal run_length
        if run_length and run_frame == leader_frame:
            lines.append(leader * run_length)
        elif run_length:
            if run_length % CARD_FRAMES:
                raise ValueError(f"{run_length} frames of blank tape are not whole cards")
            lines.extend([""] * (run_length // CARD_FRAMES))
        run_length = 0

    for frame in frames:
        if frame in (leader_frame, blank) and not current:
            if run_length and frame != run_frame:
                close_run()
            run_frame = frame
            run_length += 1
            continue
        close_run()
        if frame == end_of_block:
            lines.append("".join(current))
            current = []
        elif frame == rewind_stop and not current and frame not in characters:
            current.append(tmark)
        elif frame in characters:
            current.append(characters[frame])
        else:
            raise ValueError(f"frame {frame:#04x} is not a {code.upper()} character")
    close_run()
    if current:
        raise ValueError("the tape ends inside a block (no end-of-block code)")
    return lines
