"""The tape image: the punched blocks as text, one block per line (manual §3.5.1)."""

from __future__ import annotations

from collections.abc import Iterable

from gecent.core.errors import NotYetSupported
from gecent.core.output.block import NOT_PUNCHED, TEXT_CODES, Block

FRAMES_PER_INCH = 10  # punched tape: 10 frames per inch (manual §3.5.3.2, LEADER rule)
CARD_FRAMES = 72  # an empty line is a blank card: 72 frames


def tape_line(block: Block) -> str | None:
    """The block's line of the tape image, or None when the block is not punched (or is a
    text block left empty: an empty line would be a blank card)."""
    if block.code in NOT_PUNCHED:
        return None
    if block.code in TEXT_CODES:
        # Text blocks are already BCD: punched as written (blanks are never punched).
        text = block.text or ""
        text = text.strip() if block.keep_blanks else text.replace(" ", "")
        return text or None
    if block.punch is not None:
        return block.punch
    raise NotYetSupported(f"punching a CODE {int(block.code)} block ({block.code.name})")


def tape_lines(blocks: Iterable[Block]) -> list[str]:
    return [line for line in map(tape_line, blocks) if line is not None]


def tape_image(blocks: Iterable[Block]) -> str:
    lines = tape_lines(blocks)
    return "".join(f"{line}\n" for line in lines)


def line_frames(line: str, leader: str = "(") -> int:
    """The frames a tape line takes: one per character plus the end-of-block frame (none
    after leader); an empty line is a blank card."""
    if not line:
        return CARD_FRAMES
    return len(line) + (0 if line.strip(leader) == "" else 1)


def tape_feet(lines: Iterable[str], leader: str = "(") -> float:
    """Tape length in feet."""
    return frames_to_feet(sum(line_frames(line, leader) for line in lines))


def frames_to_feet(frames: int) -> float:
    return frames / FRAMES_PER_INCH / 12.0
