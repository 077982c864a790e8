"""Macros from a Python file named on the command line (``gecent post --macros FILE``):
a shop's macros tried out before they go into a pack.

The file is imported as a module of its own. Its macros are what its ``register_macros``
hook registers (as in a pack), else the :class:`Macros` objects it defines at module level.
They form the user layer: they come before the machine's pack and gecent's own."""

from __future__ import annotations

import importlib.util
from pathlib import Path

from gecent.core.errors import InputError, SourcePosition
from gecent.core.macros.model import Macro, Macros


def load_macro_file(path: str | Path) -> list[Macro]:
    path = Path(path)
    where = SourcePosition(str(path))
    if not path.is_file():
        raise InputError("no such macro file", where)
    name = f"gecent_macros_{abs(hash(str(path.resolve())))}"
    spec = importlib.util.spec_from_file_location(name, path)
    if spec is None or spec.loader is None:
        raise InputError("a macro file is a Python file (.py)", where)
    module = importlib.util.module_from_spec(spec)
    try:
        spec.loader.exec_module(module)
    except SyntaxError as error:
        raise InputError(
            f"the macro file is not valid Python: {error.msg}",
            SourcePosition(str(path), error.lineno, error.offset),
        ) from None
    except Exception as error:  # the file's own fault: named, with what it raised
        line = _line_in(error, path)
        raise InputError(
            f"the macro file failed to load: {type(error).__name__}: {error}",
            SourcePosition(str(path), line),
        ) from None
    found: list[Macro] = []
    hook = getattr(module, "register_macros", None)
    try:
        if callable(hook):
            hook(found.append)
        else:
            for value in vars(module).values():
                if isinstance(value, Macros):
                    found.extend(value.macros)
    except Exception as error:
        raise InputError(
            f"register_macros failed: {type(error).__name__}: {error}", where
        ) from None
    bad = [m for m in found if not isinstance(m, Macro)]
    if bad:
        raise InputError(f"register_macros registered {bad[0]!r}, not a Macro", where)
    if not found:
        raise InputError("the macro file registers no macro (no register_macros, no Macros)", where)
    return found


def _line_in(error: BaseException, path: Path) -> int | None:
    trace = error.__traceback__
    line = None
    while trace is not None:
        if Path(trace.tb_frame.f_code.co_filename) == path:
            line = trace.tb_lineno
        trace = trace.tb_next
    return line
