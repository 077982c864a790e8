"""The tape image: the punched blocks as text, one block per line (manual §3.5.1)."""

from __future__ import annotations

from collections.abc import Iterable

from gecent.core.errors import NotYetSupported
from gecent.core.output.block import TEXT_CODES, Block

FRAMES_PER_INCH = 10  # punched tape: 10 frames per inch (manual §3.5.3.2, LEADER rule)


def tape_lines(blocks: Iterable[Block]) -> list[str]:
    lines: list[str] = []
    for block in blocks:
        if not block.punched:
            continue
        if block.code in TEXT_CODES:
            # Text blocks are already BCD: punched as written (blanks are never punched).
            text = block.text or ""
            text = text.strip() if block.keep_blanks else text.replace(" ", "")
            if text:  # an empty line would be a blank card
                lines.append(text)
        elif block.punch is not None:
            lines.append(block.punch)
        else:
            raise NotYetSupported(f"punching a CODE {int(block.code)} block ({block.code.name})")
    return lines


def tape_image(blocks: Iterable[Block]) -> str:
    lines = tape_lines(blocks)
    return "".join(f"{line}\n" for line in lines)


def tape_feet(lines: Iterable[str], leader: str = "(") -> float:
    """Tape length: one frame per character plus the end-of-block frame (none after
    leader); an empty line is a blank card of 72 frames."""
    frames = sum(
        72 if not line else len(line) + (0 if line.strip(leader) == "" else 1) for line in lines
    )
    return frames / FRAMES_PER_INCH / 12.0
