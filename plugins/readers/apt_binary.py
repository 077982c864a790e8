"""CL reader for binary CL files (manual §3.2-3.3, 001 L2666-3656): the APT IV layout that
APT processors write today and the manual's own record layout, in 4- or 8-byte words and
either byte order, told apart by the first record's length markers and header."""

from __future__ import annotations

from collections.abc import Iterator

from gecent.core.cl.binary_layout import detect_layout
from gecent.core.cl.records import Record
from gecent.core.hookspecs import Register, hookimpl


class BinaryCl:
    name = "binary"
    description = "binary CL file: APT IV (gfortran) or the manual's layout, 4/8-byte words"

    def sniff(self, head: bytes) -> bool:
        return detect_layout(head) is not None

    def read(self, path: str) -> Iterator[Record]:
        from gecent.core.cl.binary_reader import read_binary  # only for binary files

        return read_binary(path)


@hookimpl
def register_cl_readers(register: Register) -> None:
    register(BinaryCl())
