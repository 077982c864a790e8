"""Open a CL file with the reader whose format it matches, and look ahead in the stream."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator

from gecent.core.cl.binary_layout import Layout
from gecent.core.cl.records import Record
from gecent.core.errors import InputError, SourcePosition
from gecent.core.families import ClReader
from gecent.core.plugins import PluginSet

SNIFF_BYTES = 4096


def choose_reader(path: str, plugins: PluginSet) -> ClReader:
    try:
        with open(path, "rb") as handle:
            head = handle.read(SNIFF_BYTES)
    except OSError as exc:
        raise InputError(f"cannot read CL file: {exc.strerror}", SourcePosition(path)) from None
    if not head:
        raise InputError(
            "empty CL file: expected CL records ending with FINI", SourcePosition(path, 1)
        )
    readers: list[ClReader] = [info.obj for info in plugins.family("readers").values()]
    for reader in readers:
        if reader.sniff(head):
            return reader
    names = ", ".join(r.name for r in readers) or "none installed"
    raise InputError(
        f"no CL reader recognises this file (readers: {names})", SourcePosition(path, 1)
    )


def read_cl(path: str, plugins: PluginSet, layout: Layout | None = None) -> Iterator[Record]:
    """The records of a CL file; ``layout`` forces a binary layout instead of sniffing."""
    if layout is not None:
        from gecent.core.cl.binary_reader import read_binary

        return read_binary(path, layout)
    return choose_reader(path, plugins).read(path)


class Lookahead:
    """A record stream that can be peeked ahead without consuming it.

    Circular interpolation needs the motion after a circle record, tool look-ahead the next
    LOADTL, macros the next records: each peeks, and memory holds only what was peeked.
    """

    __slots__ = ("_buffer", "_records", "_start")

    def __init__(self, records: Iterable[Record]) -> None:
        self._records = iter(records)
        self._buffer: list[Record] = []
        self._start = 0  # the next record's index in the buffer

    def __iter__(self) -> Lookahead:
        return self

    def __next__(self) -> Record:
        buffer = self._buffer
        if self._start < len(buffer):
            record = buffer[self._start]
            self._start += 1
            if self._start == len(buffer):
                buffer.clear()
                self._start = 0
            elif self._start >= 4096 and 2 * self._start >= len(buffer):
                del buffer[: self._start]  # what was consumed goes (memory stays bounded)
                self._start = 0
            return record
        return next(self._records)

    def _fill(self, count: int) -> bool:
        while len(self._buffer) - self._start < count:
            record = next(self._records, None)
            if record is None:
                return False
            self._buffer.append(record)
        return True

    def peek(self, ahead: int = 1) -> Record | None:
        """The record ``ahead`` places on (1 = the next one), or None past the end."""
        if ahead < 1:
            raise ValueError("peek looks at least one record ahead")
        return self._buffer[self._start + ahead - 1] if self._fill(ahead) else None

    def ahead(self, limit: int | None = None, skip: int = 0) -> Iterator[Record]:
        """The records still to come after the first ``skip``, read (and held) without
        consuming them."""
        ahead = skip + 1
        while limit is None or ahead <= limit + skip:
            record = self.peek(ahead)
            if record is None:
                return
            yield record
            ahead += 1

    def find(self, wanted: Callable[[Record], bool], limit: int | None = None) -> Record | None:
        """The first record ahead that is ``wanted``, looking at most ``limit`` records on."""
        for record in self.ahead(limit):
            if wanted(record):
                return record
        return None
