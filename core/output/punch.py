"""The punched tape: tape image lines to frames in EIA RS-244 or ASCII RS-358 code
(manual §3.5.3, appendix 7.6-7.7, 001 L8822-8854, L40712-41022).

One byte per frame, bit 0 = channel 1 ... bit 7 = channel 8, parity included (EIA odd in
channel 5, ASCII even in channel 8). Blanks and periods are never punched (001 L8849); each
block ends with the end-of-block code (option 67: EIA channel 8, ASCII LF).

A modern control's tape (decimal-point words, program frame: docs/modern-controls.md) keeps
its periods and blanks, and in EIA its ``%`` lines are the End of Record code.

The readable PARTNO (PARNOM/PARNEM for tape image, IDPART for BCD; options 20, 161, 163;
001 L9087-9098, L26262-26287, L30452-30489, L33577-33610): the first PARTNO's letters made
of holes, bracketed by end-of-block codes. The manual's Hollerith table is not in it: each
letter is 5 frames wide and 7 channels high (channels 7 down to 1, the top row in channel
7), as the period's tape punches lettered a leader, one blank frame between letters, and
channel 8 holds the parity the reader checks (odd or even).
"""

from __future__ import annotations

from collections.abc import Iterable
from functools import cache
from importlib import resources

from gecent.core import tomldata
from gecent.core.errors import FatalError, InputError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.output.modern import modern_output

CODES = ("eia", "ascii")
NOT_PUNCHED = " ."
CARD_FRAMES = 72  # one 72-column card of the tape image


# The readable letters: 5 columns each, bit 0 the top row (the common 5 x 7 dot font); the
# characters are those of the BCD set a 1970 PARTNO could hold (blank, letters, digits and
# the APT punctuation). Another character is fatal error 54 (IDPART, 001 L33603).
GLYPHS = {
    " ": "0000000000", "$": "242a7f2a12", "'": "0005030000", "(": "001c224100",
    ")": "0041221c00", "*": "082a1c2a08", "+": "08083e0808", ",": "0050300000",
    "-": "0808080808", ".": "0060600000", "/": "2010080402", "=": "1414141414",
    "0": "3e5149453e", "1": "00427f4000", "2": "4261514946", "3": "2141454b31",
    "4": "1814127f10", "5": "2745454539", "6": "3c4a494930", "7": "0171090503",
    "8": "3649494936", "9": "064949291e", "A": "7e1111117e", "B": "7f49494936",
    "C": "3e41414122", "D": "7f4141221c", "E": "7f49494941", "F": "7f09090101",
    "G": "3e41415132", "H": "7f0808087f", "I": "00417f4100", "J": "2040413f01",
    "K": "7f08142241", "L": "7f40404040", "M": "7f0204027f", "N": "7f0408107f",
    "O": "3e4141413e", "P": "7f09090906", "Q": "3e4151215e", "R": "7f09192946",
    "S": "4649494931", "T": "01017f0101", "U": "3f4040403f", "V": "1f2040201f",
    "W": "7f2018207f", "X": "6314081463", "Y": "0304780403", "Z": "6151494543",
    "&": "3649552250", ":": "0036360000", "%": "2313086462",
}  # fmt: skip
LETTER_GAP = 1  # blank frames after each letter
PARITY_CHANNEL = 0x80  # channel 8
ODD, EVEN = "odd", "even"


def readable_parity(machine: MachineDefinition, code: str) -> str | None:
    """The parity of the readable PARTNO's frames, or None when none is punched. Option 20
    = 1 (tape image, PUNCHA): option 161 chooses, 0 odd (PARNOM), 1 even (PARNEM); option 20
    = 0 (BCD, PUNCHB): option 163 = 0 punches it (IDPART) with the tape code's own parity
    (EIA odd, ASCII even); option 20 < 0 (magnetic tape) has none (001 L9087-9098)."""
    medium = machine.number_option(20)
    if medium == 1:
        return EVEN if machine.number_option(161) == 1 else ODD
    if medium == 0 and machine.number_option(163) == 0:
        return ODD if code == "eia" else EVEN
    return None


def identification_parity(machine: MachineDefinition, code: str) -> str | None:
    """The parity of the readable PARTNO gecent punches at the head of each reel, or None
    (docs/decisions.md): :func:`readable_parity`'s, with IDPART's restriction "GEOUT1
    only" for BCD output (option 164 = 1, 001 L33577-33610), and never on a modern
    control's tape, whose program frame has no letters made of holes."""
    if modern_output(machine):
        return None
    if machine.number_option(20) == 0 and machine.number_option(164) != 1:
        return None
    return readable_parity(machine, code)


def readable_frames(text: str, parity: str) -> bytes:
    """The frames spelling ``text`` (upper case; blanks at its ends dropped): per letter its
    5 columns, then a blank frame; a column's dots go in channels 7 (top) to 1, and channel 8
    is punched when the dots alone would break the parity. An empty column is blank tape
    (the reader passes over it, whatever its parity)."""
    frames = bytearray()
    for character in text.strip().upper():
        glyph = GLYPHS.get(character)
        if glyph is None:
            raise FatalError(54, f"{character!r} in the PARTNO {text.strip()!r}")
        for column in bytes.fromhex(glyph):
            frame = sum(1 << (6 - row) for row in range(7) if column >> row & 1)
            if frame and (bin(frame).count("1") % 2 == 0) == (parity == ODD):
                frame |= PARITY_CHANNEL
            frames.append(frame)
        frames.extend(bytes(LETTER_GAP))
    return bytes(frames)


def read_readable(frames: bytes) -> str:
    """The letters of readable frames (for tests and for checking a tape): the columns
    between gaps, matched against the font; a blank is the blank glyph's 5 empty columns."""
    columns = {bytes.fromhex(g): c for c, g in GLYPHS.items()}
    letters = []
    width = 5 + LETTER_GAP
    if len(frames) % width:
        raise ValueError(f"{len(frames)} readable frames are not whole letters")
    for start in range(0, len(frames), width):
        dots = bytes(
            sum(1 << (6 - channel) for channel in range(7) if frame >> channel & 1)
            for frame in frames[start : start + 5]
        )
        if dots not in columns or any(frames[start + 5 : start + width]):
            raise ValueError(f"frames {start}-{start + width - 1} are not a readable letter")
        letters.append(columns[dots])
    return "".join(letters)


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

    def readable_partno(self, text: str, parity: str) -> bytes:
        """The readable PARTNO bracketed by end-of-block codes (DOLLAR, 001 L30452-30489)."""
        return self.end_of_block + readable_frames(text, parity) + self.end_of_block

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
    frames: bytes,
    code: str,
    leader: str = "(",
    tmark: str = "=",
    *,
    modern: bool = False,
    readable: bool = False,
) -> list[str]:
    """Read frames back into tape image lines (for tests and for checking a tape).

    A run of leader frames becomes a line of the leader stand-in, each card of blank tape
    an empty line (in ASCII, whose leader is blank tape, blank tape reads as leader); the
    end-of-record code at the start of a block becomes the TMARK stand-in unless it is a
    character of this code (ASCII's rewind stop is "%"). With ``readable`` an
    end-of-block code that ends no block opens a readable PARTNO (the first one, and each
    new reel's after a tape break), passed over to the next one (:func:`read_readable`
    reads its letters)."""
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

    skipping = False
    for frame in frames:
        if skipping:
            skipping = frame != end_of_block
            continue
        if frame in (leader_frame, blank) and not current:
            if run_length and frame != run_frame:
                close_run()
            run_frame = frame
            run_length += 1
            continue
        close_run()
        if frame == end_of_block and readable and not current:
            skipping = True
        elif frame == end_of_block:
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
