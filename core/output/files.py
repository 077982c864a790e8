"""Write output files whole or not at all: a temporary file renamed into place."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

from gecent.core.errors import InputError, SourcePosition


def write_atomically(path: str | Path, data: bytes) -> None:
    target = Path(path)
    try:
        directory = target.parent if str(target.parent) else Path(".")
        handle, temporary = tempfile.mkstemp(prefix=f".{target.name}.", dir=directory)
        try:
            os.chmod(temporary, 0o666 & ~_umask())  # mkstemp's 0600 is for the temporary only
            with os.fdopen(handle, "wb") as stream:
                stream.write(data)
            os.replace(temporary, target)
        except BaseException:
            os.unlink(temporary)
            raise
    except OSError as exc:
        raise InputError(
            f"cannot write output: {exc.strerror}", SourcePosition(str(target))
        ) from None


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
