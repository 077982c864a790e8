"""Blocks as JSON lines (`gecent post --json`), for scripts that read a post's output:
one object per block, in output order, with what the tape and the listing say of it."""

from __future__ import annotations

import json
from collections.abc import Iterable, Iterator

from gecent.core.absent import ABSENT
from gecent.core.machine.definition import MachineDefinition
from gecent.core.output.block import Block
from gecent.core.output.tape import tape_line

STEP_DIGITS = 6


def block_record(
    block: Block, machine: MachineDefinition, line: str | None = None
) -> dict[str, object]:
    """record (CL record number), code (CODE's name and number), text (comments, PPRINT),
    tape (the punched line, None when not punched), words (letter -> printed value),
    position (the machine point reached, in CL axis order and machine units), feed (the
    feed in units per minute the block makes), rpm (the speed its S stands for), rapid,
    cut_minutes and dwell_minutes; on a multihead program the head, and a combined
    block's two halves, each as a block of its own."""
    head = block.head
    letters = machine.heads[head - 1 if 0 < head <= len(machine.heads) else 0].letters
    step = machine.number_option(14)
    feed = block.cells[19]
    rpm = block.cells[20]
    record: dict[str, object] = {
        "record": block.record,
        "code": block.code.name,
        "code_number": int(block.code),
        "text": block.text,
        "tape": line if line is not None else tape_line(block),
        "words": {letters[location]: printed.strip() for location, printed in block.words},
        "position": (
            None
            if block.position is None
            else [round(steps * step, STEP_DIGITS) for steps in block.position]
        ),
        "feed": None if feed is ABSENT else float(feed),
        "rpm": None if rpm is ABSENT else float(rpm),
        "rapid": block.rapid,
        "cut_minutes": block.cut_minutes,
        "dwell_minutes": block.dwell_minutes,
    }
    if head:
        record["head"] = head
    if block.halves is not None:
        record["halves"] = [block_record(half, machine, half.punch) for half in block.halves]
    return record


def json_lines(blocks: Iterable[Block], machine: MachineDefinition) -> Iterator[str]:
    for block in blocks:
        yield json.dumps(block_record(block, machine), separators=(",", ":"))
