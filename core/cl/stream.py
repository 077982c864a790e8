"""Open a CL file with the reader whose format it matches."""

from __future__ import annotations

from collections.abc import Iterator

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
    readers: list[ClReader] = [info.obj for info in plugins.family("readers").values()]
    for reader in readers:
        if reader.sniff(head):
            return reader
    names = ", ".join(r.name for r in readers) or "none installed"
    raise InputError(f"no CL reader recognises this file (readers: {names})", SourcePosition(path))


def read_cl(path: str, plugins: PluginSet) -> Iterator[Record]:
    return choose_reader(path, plugins).read(path)
