"""CL reader for APT source text, as CAM systems write it (ISO 4343 style; manual §3.3
record types as the APT processor would write them)."""

from __future__ import annotations

from collections.abc import Iterator

from gecent.core.cl.apt_source import read_apt_source
from gecent.core.cl.records import Record
from gecent.core.hookspecs import Register, hookimpl


class AptSourceCl:
    name = "apt-source"
    description = "APT source CL text (GOTO / x, y, z ... FINI), e.g. Creo, CATIA, NX, Mastercam"

    def sniff(self, head: bytes) -> bool:
        if b"\x00" in head:
            return False
        try:
            head.decode("utf-8")
        except UnicodeDecodeError as exc:  # a cut in the middle of a character is still text
            return exc.start >= len(head) - 3
        return True

    def read(self, path: str) -> Iterator[Record]:
        return read_apt_source(path)


@hookimpl
def register_cl_readers(register: Register) -> None:
    register(AptSourceCl())
