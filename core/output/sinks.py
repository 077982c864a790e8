"""Sinks: where finished blocks go, as they are made (the streaming shape of the output).

Every block the output element finishes passes through :class:`Sinks`, which works out its
tape line once and hands both to each sink: the tape image, the punched tape, the listing
and the JSON lines. A sink writes at once into a temporary file beside its target; when the
run ends, ``close`` renames it into place (``ok``) or removes it. A fatal error of the
manual's §5.7 keeps the listing, with the GEDUMP dump at its end, and never the tape;
option 110 = +2 after a slide limit, and option 173 = 0 (printed output only), keep the
listing and suppress the tape and punch. The punch puts the readable PARTNO at the head
of each reel; the reels of the BREAK sequence are counted here (core/output/reels.py).
Nothing holds the blocks of the whole run, except the collecting sink that scripts and
tests ask for explicitly.
"""

from __future__ import annotations

import json
import os
from abc import ABC, abstractmethod
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import IO, Protocol

from gecent.core.errors import (
    Diagnostic,
    GecentError,
    InputError,
    NotYetSupported,
    SourcePosition,
)
from gecent.core.machine.definition import MachineDefinition
from gecent.core.output.block import Block
from gecent.core.output.files import AtomicFile
from gecent.core.output.jsonlines import block_record
from gecent.core.output.marks import stand_in
from gecent.core.output.modern import modern_output
from gecent.core.output.punch import Puncher, identification_parity
from gecent.core.output.reels import Reels, tape_reels
from gecent.core.output.tape import tape_line
from gecent.core.plugins import PluginSet


@dataclass(slots=True)
class Ending:
    """How the run ended, for the sinks' ``close``: ``ok`` when it finished; ``dump`` is the
    GEDUMP after a fatal error (the listing keeps it); ``punch_suppressed`` is option
    110 = +2 after a slide limit or option 173 = 0 (no tape, no punch)."""

    ok: bool
    punch_suppressed: bool = False
    dump: list[str] | None = None


class Sink(Protocol):
    def block(self, block: Block, line: str | None) -> None:
        """A finished block and its tape line (None when it is not punched)."""

    def close(self, ending: Ending) -> None: ...


class ListingWriter(Protocol):
    """A printout's page maker (GEOUT1-4): text for each block as pages fill, the rest at
    the end, in pieces (a printout kept in temporary files comes back page by page)."""

    def block(self, block: Block, line: str | None) -> str: ...

    def finish(self) -> Iterator[str]: ...

    def discard(self) -> None:
        """Drop what the pages hold outside memory (temporary files), printing nothing;
        ``finish`` does it too, and both may be called more than once."""


class PrintoutUnfit(NotYetSupported):
    """A printout that cannot lay out the machine's line: GEOUT1 whose line does not fit
    the option-160 print positions (001 L9452-9476). The listing is made by printout
    ``instead`` (GEOUT2), after the warning ``comment``; called directly (a script), it is
    the error it says."""

    def __init__(self, feature: str, comment: str, instead: int) -> None:
        super().__init__(feature)
        self.comment = comment
        self.instead = instead


class LineSink(ABC):
    """A sink of tape lines (the tape image, the punched tape): the fast path hands it the
    line alone; written only when the run finishes with the punch not suppressed."""

    def __init__(self, path: str | Path) -> None:
        self.file = AtomicFile(path)

    def block(self, block: Block, line: str | None) -> None:
        if line is not None:
            self.line(line)

    @abstractmethod
    def line(self, line: str) -> None:
        """Write one tape line."""

    def close(self, ending: Ending) -> None:
        if ending.ok and not ending.punch_suppressed:
            self.file.commit()
        else:
            self.file.discard()


class TapeSink(LineSink):
    """The tape image: one line per punched block, written as it comes."""

    def line(self, line: str) -> None:
        self.file.write((line + "\n").encode("ascii", "replace"))


class PunchSink(LineSink):
    """The punched tape in EIA RS-244 or ASCII RS-358 code, frame by frame; ``parity`` is
    the readable identification's at the head of each reel (None: none is punched)."""

    def __init__(self, path: str | Path, puncher: Puncher, parity: str | None = None) -> None:
        self.puncher = puncher
        self.parity = parity
        super().__init__(path)

    def identify(self, text: str) -> None:
        """The readable PARTNO (and reel number) in letters made of holes (GEPRE, 001
        L9087-9101), bracketed by end-of-block codes; nothing for a blank PARTNO."""
        if self.parity is not None and text.strip():
            self.file.write(self.puncher.readable_partno(text, self.parity))

    def line(self, line: str) -> None:
        frames_of = self.puncher.frames_of
        if line.isprintable():
            self.file.write(frames_of(line))
        else:  # an empty line (a blank card) or a text holding line breaks: as the image reads
            for part in (line + "\n").splitlines():
                self.file.write(frames_of(part))


class ListingSink:
    """The printed listing, page by page; after a fatal error it ends with the dump."""

    def __init__(self, path: str | Path, writer: ListingWriter) -> None:
        self.writer = writer
        self.file = AtomicFile(path)

    def block(self, block: Block, line: str | None) -> None:
        text = self.writer.block(block, line)
        if text:
            self.file.write(text.encode("utf-8"))

    def close(self, ending: Ending) -> None:
        if not ending.ok and ending.dump is None:
            self.writer.discard()
            self.file.discard()  # bad input: no listing either
            return
        try:
            for text in _finished(self.writer):
                self.file.write(text.encode("utf-8"))
        finally:
            self.writer.discard()
        if ending.dump is not None:
            self.file.write(("\n".join(ending.dump) + "\n").encode("utf-8"))
        self.file.commit()


def _finished(writer: ListingWriter) -> Iterator[str]:
    """The rest of the listing; a printout that cannot be finished gives what it gave
    (the dump follows it)."""
    try:
        yield from writer.finish()
    except GecentError:
        return


class JsonSink:
    """``post --json``: each block as one JSON object on a line, as it is made. A reader
    that goes away (``| head``) ends the JSON lines, not the post: the tape is still made."""

    def __init__(self, stream: IO[str], machine: MachineDefinition) -> None:
        self.stream = stream
        self.machine = machine
        self.gone = False

    def block(self, block: Block, line: str | None) -> None:
        if self.gone:
            return
        record = block_record(block, self.machine, line)
        try:
            self.stream.write(json.dumps(record, separators=(",", ":")) + "\n")
        except BrokenPipeError:
            self._reader_gone()

    def close(self, ending: Ending) -> None:
        if self.gone:
            return
        try:
            self.stream.flush()
        except BrokenPipeError:
            self._reader_gone()

    def _reader_gone(self) -> None:
        self.gone = True
        try:  # what is still buffered must not fail again when the process exits
            descriptor = self.stream.fileno()
        except (OSError, ValueError, AttributeError):
            return
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, descriptor)
        os.close(devnull)


@dataclass
class CollectSink:
    """Keeps every block in a list: for scripts and tests that want the blocks themselves
    (memory grows with the run; the command line never uses it)."""

    blocks: list[Block] = field(default_factory=list)

    def block(self, block: Block, line: str | None) -> None:
        self.blocks.append(block)

    def close(self, ending: Ending) -> None:
        """Nothing to write: the blocks stay with the caller."""


class Sinks:
    """The fan-out: each block's tape line is worked out once, then every sink gets both."""

    def __init__(self, sinks: list[Sink] | None = None) -> None:
        self.sinks: list[Sink] = []
        self.line_sinks: list[LineSink] = []  # all of them when the fast path needs no Block
        self.partno = ""  # the first PARTNO's text: the listing's page heading
        # warnings the outputs make before the run (a printout replaced): the run gives
        # them as it gives its own, in the listing and on stderr
        self.notes: list[Diagnostic] = []
        # the characters the punch can carry (None: no punch; the tape image is ASCII)
        self.punch_characters: frozenset[str] | None = None
        self.reels: Reels | None = None  # the BREAK sequence (options 134, 135)
        self.identified = False  # the first reel's readable PARTNO is punched
        self.closed = False
        for sink in sinks or []:
            self.add(sink)

    def add(self, sink: Sink) -> None:
        self.sinks.append(sink)
        if isinstance(sink, LineSink):
            self.line_sinks.append(sink)

    @property
    def lines_only(self) -> bool:
        """Every sink takes tape lines alone (tape, punch): the fast path makes no Block."""
        return len(self.line_sinks) == len(self.sinks)

    def emit(self, block: Block) -> None:
        line = tape_line(block)
        if block.reel:
            self._new_reel(block.reel)
        if line is not None and self.reels is not None:
            self._on_reel(line, block.record)
        for sink in self.sinks:
            sink.block(block, line)

    def emit_known(self, block: Block, line: str) -> None:
        """A block whose tape line is known already (the fast path)."""
        if self.reels is not None:
            self._on_reel(line, block.record)
        for sink in self.sinks:
            sink.block(block, line)

    def emit_line(self, line: str) -> None:
        """A tape line alone, when :attr:`lines_only`."""
        if self.reels is not None:
            self._on_reel(line, None)
        for sink in self.line_sinks:
            sink.line(line)

    def _on_reel(self, line: str, record: int | None) -> None:
        """Count the line on its reel; one that would pass option 134's maximum goes on
        a new reel, after a tape break (core/output/reels.py)."""
        reels = self.reels
        assert reels is not None
        frames = reels.frames_of(line)
        if reels.overflows(frames):
            for block in reels.break_blocks(record, automatic=True):
                self.emit(block)
        reels.count(line, frames)

    def _new_reel(self, number: int) -> None:
        """A reel starts: 1 at the first PARTNO, n at a tape break's heading. The punch
        puts the readable identification there (RDPART and REELNO, 001 L18108-18116)."""
        if number == 1:
            if self.identified:
                return  # (a multihead program's PARTNO, once for each head)
            self.identified = True
        elif self.reels is not None:
            self.reels.new_reel(number)
        text = self.partno if number == 1 else f"{self.partno.strip()} REEL {number}"
        for sink in self.sinks:
            if isinstance(sink, PunchSink):
                sink.identify(text)

    def close(self, ending: Ending) -> None:
        """Close every sink, even when one fails; the first failure is raised after."""
        if self.closed:
            return
        self.closed = True
        failure: BaseException | None = None
        for sink in self.sinks:
            try:
                sink.close(ending if failure is None else Ending(False, dump=ending.dump))
            except BaseException as exc:  # the others must still close (and clean up)
                failure = failure or exc
        if failure is not None:
            raise failure


def output_sinks(
    plugins: PluginSet,
    machine: MachineDefinition,
    tape: Path,
    listing: str | None,
    punch_to: tuple[str, str] | None,
    json_stream: IO[str] | None,
) -> Sinks:
    """The outputs of ``gecent post``: the tape, and the listing, punch and JSON lines when
    asked; what can be refused (the printout, the tape code) is looked at before any file
    is opened, and a failure on the way closes what was opened."""
    sinks = Sinks()
    writer: ListingWriter | None = None
    if listing is not None:
        layout = int(machine.number_option(164))
        printout = plugins.get("printouts", layout)
        where = SourcePosition(machine.origin)  # what the machine asks for: its file
        if printout is None:
            raise NotYetSupported(f"printout GEOUT{layout} (option 164 = {layout})", where)
        try:
            try:
                writer = printout.listing(machine, lambda: sinks.partno)
            except PrintoutUnfit as unfit:  # GEOUT1 cannot be used: GEOUT2, with a warning
                instead = plugins.get("printouts", unfit.instead)
                if instead is None:
                    raise NotYetSupported(
                        f"printout GEOUT{unfit.instead} ({unfit.feature})", where
                    ) from None
                writer = instead.listing(machine, lambda: sinks.partno)
                sinks.notes.append(Diagnostic(unfit.comment, where))
        except (NotYetSupported, InputError) as exc:
            exc.where = exc.where or where
            raise
    puncher = (
        Puncher(
            punch_to[0],
            stand_in(machine, 64),
            stand_in(machine, 65),
            modern=modern_output(machine),
        )
        if punch_to
        else None
    )
    if puncher is not None:
        sinks.punch_characters = puncher.characters
    try:
        sinks.add(TapeSink(tape))
        if writer is not None and listing is not None:
            sinks.add(ListingSink(listing, writer))
        if puncher is not None and punch_to is not None:
            parity = identification_parity(machine, punch_to[0])
            sinks.add(PunchSink(punch_to[1], puncher, parity))
        sinks.reels = tape_reels(machine)
        if json_stream is not None:
            sinks.add(JsonSink(json_stream, machine))
    except BaseException:
        sinks.close(Ending(False))
        if writer is not None:
            writer.discard()  # (when its sink was never made)
        raise
    return sinks
