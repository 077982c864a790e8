"""A diagnostic macro's number and severity (spec 09 §5.12, 002 L1042-1099).

gecent's diagnostics are text. $P2 is the manual's comment number where the diagnostic is
one of its numbered warning comments (the catalogue ``WARNING_COMMENTS`` of
core/errors.py), else $NULL. A macro that changes $P2 to another catalogued number puts
out that comment instead ("changing it outputs a different diagnostic"), with its text
unless the macro also wrote $P5; a number outside the catalogue is the macro's error.

$P3, the severity, is 1 (a warning: listed, on stderr, counted) on entry. The macro may
set 0, a message: listed in the listing and on the tape as any warning comment, but not
reported nor counted; or 2, an error: the run stops with the message (exit status 1, as
the machine's own stops without a manual number).
"""

from __future__ import annotations

from gecent.core.errors import WARNING_COMMENTS, Diagnostic, RunStopped, SourcePosition
from gecent.core.macros.host import MacroHost
from gecent.core.macros.model import MacroError
from gecent.core.macros.params import DiagnosticParams
from gecent.core.output.block import Block, Code

MESSAGE, WARNING, ERROR = 0.0, 1.0, 2.0
SEVERITIES = {MESSAGE: "a message", WARNING: "a warning", ERROR: "an error (the run stops)"}


def comment_number(text: str) -> float | None:
    """The manual's comment number of a diagnostic's text, None when it has none."""
    for number, comment in WARNING_COMMENTS.items():
        if text == comment or text.startswith(comment):
            return float(number)
    return None


def message_of(params: DiagnosticParams, entry_number: float | None) -> str:
    """The text to put out: the new comment's when $P2 changed and $P5 did not."""
    number = params.number
    if 2 in params.changed and number != entry_number and number is not None:
        comment = WARNING_COMMENTS.get(int(number)) if float(number).is_integer() else None
        if comment is None:
            known = ", ".join(str(n) for n in WARNING_COMMENTS)
            raise MacroError(
                f"$P2 (number) {number!r} is none of the manual's numbered comments gecent "
                f"prints ({known})"
            )
        if 5 not in params.changed:
            return comment
    return str(params.message)


def deliver(
    run: MacroHost,
    params: DiagnosticParams,
    entry_number: float | None,
    where: SourcePosition | None,
) -> None:
    """The diagnostic the $P describe, at its severity."""
    message = message_of(params, entry_number)
    severity = params.severity
    if severity not in SEVERITIES:
        levels = ", ".join(f"{value:g} {name}" for value, name in SEVERITIES.items())
        raise MacroError(f"$P3 (severity) takes {levels}; not {severity!r}")
    if severity == ERROR:
        raise RunStopped(message, where)
    if severity == MESSAGE:
        run.text_block(Block(Code.COMMENT, where.record if where else None, message))
        return
    run.warn_builtin(Diagnostic(message, where))
