"""The tape and register macros (spec 09 §5.10, §5.11): each register of a block before it
is placed, and each punched block before tape and listing, with their $P."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Any

from gecent.core.absent import ABSENT
from gecent.core.macros.context import Frame
from gecent.core.macros.host import MacroHost
from gecent.core.macros.model import Kind, MacroFailure, Phase
from gecent.core.macros.params import RegisterParams, TapeParams
from gecent.core.output.block import TEXT_CODES, Block, Code
from gecent.core.output.tape import tape_line

if TYPE_CHECKING:
    from gecent.core.macros.engine import MacroEngine
    from gecent.core.output.words import Word as RegisterWord

_SEQUENCE = re.compile(r"(/?\s*N\d+)\s*(.*)\Z", re.DOTALL)
LAST_REGISTER = 30
TAPE_RESTARTS = 10_000  # a tape macro left in restart mode would loop for ever (§5.11)


def tape_event(engine: MacroEngine, run: MacroHost, block: Block) -> None:
    """§5.11: each punched block goes through the tape macro before tape and listing."""
    line = tape_line(block)
    if line is None:
        run.sinks.emit(block)
        return
    params = TapeParams()
    _tape_block(params, line, 1.0)

    def emit(frame: Frame) -> None:
        text = str(params.block)
        if text:
            run.sinks.emit(_extra_block(block, text))
        _tape_block(params, "", params.flag)

    local: dict[str, Any] = {}  # kept across restarts (§5.11)
    for _ in range(TAPE_RESTARTS):
        frame = engine.single(Kind.TAPE, params, run.current_record, emit, local)
        if frame is None:
            run.sinks.emit(block)
            return
        flag = params.flag
        if flag == 0:
            return
        text = str(params.block)
        if flag == 1:
            if text == line:
                run.sinks.emit(block)
            elif text:
                _retext(block, text)
                run.sinks.emit(block)
            return
        if text:  # restart mode: out it goes, and the macro begins again
            run.sinks.emit(_extra_block(block, text))
        _tape_block(params, "", flag)
    macro = engine.table.event(Kind.TAPE, Phase.EVENT)
    raise MacroFailure(
        f"macro {macro.key if macro else 'tape'}: restarted {TAPE_RESTARTS} times "
        "($P1 never set back to 0 or 1, §5.11)",
        run.current_record.where if run.current_record is not None else None,
    )


def register_event(
    engine: MacroEngine, run: MacroHost, block: Block, words: list[RegisterWord]
) -> list[RegisterWord]:
    """§5.10: each register of a block, before it is placed in the block."""
    placed: list[tuple[float, int, RegisterWord]] = []
    order = 0
    for word in words:
        location, letter, _printed, punched = word
        text = letter + punched
        matching = engine.sv.get("REGMATCH")  # the macro may set it as it goes
        if matching and not _register_matches(matching, location, text, block.code):
            placed.append((location, order, word))
            order += 1
            continue
        params = RegisterParams()
        value = block.cells[location]
        for number, item in ((1, 1.0), (2, text), (3, location),
                             (4, None if value is ABSENT else float(value)),
                             (5, block.code)):  # fmt: skip
            params.set(number, item)

        def put(frame: Frame, params: RegisterParams = params) -> None:
            nonlocal order
            params.changed.clear()
            placed.append((_slot(params.index), order, _word(params)))
            order += 1

        frame = engine.single(Kind.REGISTER, params, run.current_record, put)
        if frame is None:
            placed.append((location, order, word))
        elif params.flag != 0 and (frame.outputs == 0 or params.changed):
            placed.append((_slot(params.index), order, _word(params)))
        order += 1
    placed.sort(key=lambda item: (item[0], item[1]))
    return [word for _, _, word in placed]


def _tape_block(params: TapeParams, line: str, flag: float) -> None:
    params.set(1, flag)
    params.set(2, 1.0)
    params.set(3, line)
    found = _SEQUENCE.match(line)
    params.set(4, found.group(1) if found else "")
    params.set(5, found.group(2) if found else line)
    params.changed.clear()


def _extra_block(like: Block, text: str) -> Block:
    """A block a tape macro adds: punched as written, blanks kept."""
    block = Block(Code.INSERT, like.record, text=text)
    block.keep_blanks = True
    return block


def _retext(block: Block, text: str) -> None:
    if block.code in TEXT_CODES:
        block.text = text
        block.keep_blanks = True
    else:
        block.punch = text


def _register_matches(matching: tuple[Any, ...], location: int, text: str, code: Code) -> bool:
    for item in matching:
        if isinstance(item, Code):
            if item is code:
                return True
        elif isinstance(item, str):
            if re.match(item, text):
                return True
        elif item == location:
            return True
    return False


def _slot(index: Any) -> float:
    number = float(index)
    if number < 1:
        return -1.0  # prefixed to the block
    if number > LAST_REGISTER:
        return LAST_REGISTER + 1.0  # appended
    return number


def _word(params: RegisterParams) -> RegisterWord:
    text = str(params.text)
    return (int(_slot(params.index)), "", text, text)
