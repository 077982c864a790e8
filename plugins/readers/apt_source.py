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
        """Text: no NUL byte, and control characters (other than tab, line and page ends)
        rare; UTF-8 or Latin-1 alike (a stray control character is then an error naming
        its line and column, not an unknown format)."""
        if b"\x00" in head:
            return False
        controls = sum(1 for byte in head if byte < 32 and byte not in (9, 10, 12, 13))
        return controls <= max(1, len(head) // 100)

    def read(self, path: str) -> Iterator[Record]:
        return read_apt_source(path)


@hookimpl
def register_cl_readers(register: Register) -> None:
    register(AptSourceCl())
