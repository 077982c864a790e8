"""Write output files whole or not at all: a temporary file beside the target, renamed into
place when the run ends well and removed when it does not."""

from __future__ import annotations

import contextlib
import os
import tempfile
from pathlib import Path
from typing import IO

from gecent.core.errors import InputError, SourcePosition


class AtomicFile:
    """A binary file written as it is made into ``.NAME.xxxx`` beside ``path``; ``commit``
    renames it to ``path``, ``discard`` removes it. Nothing of it is ever left half-written
    under the target's name."""

    def __init__(self, path: str | Path, buffering: int = 1 << 16) -> None:
        self.target = Path(path)
        directory = self.target.parent if str(self.target.parent) else Path(".")
        try:
            handle, self.temporary = tempfile.mkstemp(prefix=f".{self.target.name}.", dir=directory)
            os.chmod(self.temporary, 0o666 & ~_umask())  # mkstemp's 0600 is for the temporary only
        except OSError as exc:
            raise _cannot_write(self.target, exc) from None
        self.stream: IO[bytes] = os.fdopen(handle, "wb", buffering=buffering)
        self.closed = False

    def write(self, data: bytes) -> None:
        try:
            self.stream.write(data)
        except OSError as exc:
            self.discard()
            raise _cannot_write(self.target, exc) from None

    def commit(self) -> None:
        if self.closed:
            return
        self.closed = True
        try:
            self.stream.close()
            os.replace(self.temporary, self.target)
        except OSError as exc:
            _unlink(self.temporary)
            raise _cannot_write(self.target, exc) from None

    def discard(self) -> None:
        if self.closed:
            return
        self.closed = True
        with contextlib.suppress(OSError):
            self.stream.close()
        _unlink(self.temporary)


def write_atomically(path: str | Path, data: bytes) -> None:
    output = AtomicFile(path)
    try:
        output.write(data)
    except BaseException:
        output.discard()
        raise
    output.commit()


def _cannot_write(target: Path, exc: OSError) -> InputError:
    return InputError(f"cannot write output: {exc.strerror}", SourcePosition(str(target)))


def _unlink(path: str) -> None:
    with contextlib.suppress(OSError):
        os.unlink(path)


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
