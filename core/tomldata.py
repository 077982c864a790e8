"""TOML data, parsed once: the option catalogue, the vocabulary, the tape codes and the
machine files are TOML, and tomllib is pure Python (the catalogue alone takes tens of
milliseconds). A parsed file is kept in memory for the process and, in marshal form, in a
cache folder keyed by the SHA-1 of its text, so the next ``gecent`` start reads it back in
a fraction of the time. The folder is ``$GECENT_CACHE_DIR``, else ``$XDG_CACHE_HOME/gecent``
or ``~/.cache/gecent``; ``GECENT_CACHE_DIR=`` (empty) turns the disk cache off. A cache
that cannot be read or written is passed over: the text is parsed as without it.
"""

from __future__ import annotations

import hashlib
import marshal
import os
import tempfile
import tomllib
from pathlib import Path
from typing import Any

_MEMORY: dict[str, dict[str, Any]] = {}
FORMAT = b"gecent-toml-1\n"  # a cache file starts so; another start is not ours


def cache_folder() -> Path | None:
    configured = os.environ.get("GECENT_CACHE_DIR")
    if configured is not None:
        return Path(configured) / "toml" if configured else None
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "gecent" / "toml"


def loads(text: str) -> dict[str, Any]:
    """``tomllib.loads(text)``, from the caches when this text was parsed before; raises
    ``tomllib.TOMLDecodeError`` as tomllib does. Callers must not change the result."""
    key = hashlib.sha1(text.encode("utf-8")).hexdigest()
    found = _MEMORY.get(key)
    if found is not None:
        return found
    folder = cache_folder()
    path = None if folder is None else folder / f"{key}.marshal"
    data = _read(path) if path is not None else None
    if data is None:
        data = tomllib.loads(text)
        if path is not None:
            _write(path, data)
    _MEMORY[key] = data
    return data


def _read(path: Path) -> dict[str, Any] | None:
    try:
        raw = path.read_bytes()
    except OSError:
        return None
    if not raw.startswith(FORMAT):
        return None
    try:
        data = marshal.loads(raw[len(FORMAT) :])
    except (EOFError, ValueError, TypeError):
        return None
    return data if isinstance(data, dict) else None


def _write(path: Path, data: dict[str, Any]) -> None:
    try:
        payload = FORMAT + marshal.dumps(data)
    except ValueError:
        return  # a value marshal cannot keep (a TOML date): parsed each time
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        handle, temporary = tempfile.mkstemp(prefix=".", dir=path.parent)
        with os.fdopen(handle, "wb") as stream:
            stream.write(payload)
        os.replace(temporary, path)
    except OSError:
        return
