"""The punched tape: tape image lines to frames in EIA RS-244 or ASCII RS-358 code
(manual §3.5.3, appendix 7.6-7.7, 001 L8822-8854, L40712-41022).

One byte per frame, bit 0 = channel 1 ... bit 7 = channel 8, parity included (EIA odd in
channel 5, ASCII even in channel 8). Blanks and periods are never punched (001 L8849); each
block ends with the end-of-block code (option 67: EIA channel 8, ASCII LF).

A modern control's tape (decimal-point words, program frame: docs/modern-controls.md) keeps
its periods and blanks, and in EIA its ``%`` lines are the End of Record code.
"""

from __future__ import annotations

from collections.abc import Iterable
from functools import cache
from importlib import resources

from gecent.core import tomldata
from gecent.core.errors import InputError

CODES = ("eia", "ascii")
NOT_PUNCHED = " ."
CARD_FRAMES = 72  # one 72-column card of the tape image


@cache
def table(code: str) -> dict[str, int]:
    raw = resources.files("gecent.core.output").joinpath("data", "tape_codes.toml").read_bytes()
    return {str(k): int(v) for k, v in tomldata.loads(raw.decode("utf-8"))[code].items()}


class Puncher:
    """Tape image lines to frames, one line at a time, by table translation.

    Two stand-ins of the machine's options 64 and 65 are punched as control codes: a line
    made only of the leader stand-in is leader (no end of block), and the TMARK stand-in at
    the start of a line is the end-of-record (rewind stop) code. An empty line is a blank
    card: 72 frames of blank tape (feed holes only), the option-11 filler after END."""

    def __init__(
        self, code: str, leader: str = "(", tmark: str = "=", *, modern: bool = False
    ) -> None:
        if code not in CODES:
            raise InputError(f"unknown tape code {code!r} (eia or ascii)")
        codes = table(code)
        self.code = code
        self.leader = leader
        self.tmark = tmark
        self.end_of_block = bytes([codes["EOB"]])
        self.blank_card = bytes([codes["BLANK_TAPE"]]) * CARD_FRAMES
        self.leader_frame = bytes([codes["LEADER"]])
        self.rewind_stop = bytes([codes["REWIND_STOP"]])
        characters = {k: v for k, v in codes.items() if len(k) == 1 and ord(k) < 256}
        self.not_punched = NOT_PUNCHED
        if modern:
            characters[" "] = codes["SPACE"]
            characters.setdefault("%", codes["REWIND_STOP"])  # EIA: End of Record
            self.not_punched = ""
        self.characters = frozenset(characters)
        frames = bytearray(range(256))
        for character, frame in characters.items():
            frames[ord(character)] = frame
        self.frames = bytes(frames)
        # deleting every punchable character leaves exactly the ones that have no code
        self.unpunchable = str.maketrans("", "", "".join(characters) + self.not_punched)
        self.lines = 0

    def frames_of(self, line: str) -> bytes:
        self.lines += 1
        if not line:
            return self.blank_card
        if line.strip(self.leader) == "":
            return self.leader_frame * len(line)
        prefix = b""
        if line.startswith(self.tmark):
            prefix = self.rewind_stop
            line = line[1:]
        missing = line.translate(self.unpunchable)
        if missing:
            raise InputError(
                f"tape block {self.lines} ({line!r}): {missing[0]!r} has no "
                f"{self.code.upper()} code"
            )
        body = line.encode("latin-1").translate(self.frames, self.not_punched.encode("ascii"))
        return prefix + body + self.end_of_block


def punch(lines: Iterable[str], code: str, leader: str = "(", tmark: str = "=") -> bytes:
    """The frames of a tape image; a character the code cannot punch is an error naming it
    (see :class:`Puncher`)."""
    puncher = Puncher(code, leader, tmark)
    return b"".join(puncher.frames_of(line) for line in lines)


def unpunch(
    frames: bytes, code: str, leader: str = "(", tmark: str = "=", *, modern: bool = False
) -> list[str]:
    """Read frames back into tape image lines (for tests and for checking a tape).

    A run of leader frames becomes a line of the leader stand-in, each card of blank tape
    an empty line (in ASCII, whose leader is blank tape, blank tape reads as leader); the
    end-of-record code at the start of a block becomes the TMARK stand-in unless it is a
    character of this code (ASCII's rewind stop is "%")."""
    codes = table(code)
    characters = {v: k for k, v in reversed(list(codes.items())) if len(k) == 1}
    if modern:  # blanks between words, and EIA's End of Record for "%"
        characters.setdefault(codes["SPACE"], " ")
        characters.setdefault(codes["REWIND_STOP"], "%")
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
