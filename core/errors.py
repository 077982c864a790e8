"""Diagnostics: input errors, the manual's fatal errors and warning comments (manual §5.7).

Exit statuses of the ``gecent`` command:

* 0 - the run finished (warnings may have been printed);
* 1 - a fatal error of the manual's list stopped the run (``FatalError``);
* 2 - the input is malformed: CL file, machine file, option or command line (``InputError``);
* 3 - the input asks for something this version does not build yet (``NotYetSupported``).
"""

from __future__ import annotations

from dataclasses import dataclass

EXIT_FATAL = 1
EXIT_BAD_INPUT = 2
EXIT_NOT_SUPPORTED = 3
EXIT_INTERNAL = 70

# Fatal errors of manual §5.7.1 (001 L28364-28585), with the four numbers that §6 names
# but the list omits (85, 101, 141, 143). 101 is raised by machine-specific code (MACF40).
FATAL_ERRORS: dict[int, tuple[str, str]] = {
    1: ("GEBASE", "Cannot read the CL tape"),
    7: ("DECODE", "Option 59 or 60 is set up incorrectly"),
    14: ("MOTION", "The RETURN flag from subroutine GOLINE is wrong"),
    19: ("FROMS", "Direction cosines of the FROM point are not of unit length"),
    24: ("SPINDL", "No initial spindle speed given (option 27 is negative)"),
    25: ("LINRTY", "No motion from subroutine LINRTY (RETURN flag from DEPART is wrong)"),
    39: ("SELGRO", "Rotary departure too large; it should have been segmented"),
    41: ("TURRET", "Turret corrective move cannot be segmented; turret offsets are probably wrong"),
    54: ("IDPART", "Illegal BCD character in the readable PARTNO"),
    85: ("STOVEC", "A vector element is non-zero where its mask element is absent"),
    101: ("MACFUN", "Machine-specific limit violation"),
    138: ("SELG", "No G code is available for the segment length"),
    139: ("SELG", "Segment too long; it should have been split"),
    141: ("SELGCD", "ICODE has a forbidden value"),
    142: ("SELGCR", "Circle radius too large; it must be less than the maximum departure"),
    143: ("SELGCD", "Linear code number given for a circle"),
    144: ("SELGCR", "No G code is available for this radius"),
    151: ("PROCQD", "DBUFER is absent: subroutine QUADET did not set it up"),
    999: ("INIT", "Given machine number is < 1 or > 99"),
    1020: ("GEMULT", "New n value for code 17 is smaller than the previous n value"),
    1021: ("GEMULT", "Word 11 of CODE 17 is not acceptable"),
    1022: ("GEMULT", "Feedrate for code 17 is not acceptable"),
    1023: ("GEMULT", "ICODE is not acceptable for head 1"),
    1024: ("GEMULT", "n value or feedrate of code 17 is not acceptable on head 1"),
    1025: ("GEMULT", "ICODE is not acceptable for head 2"),
    1026: ("GEMULT", "n value or feedrate of code 17 is not acceptable on head 2"),
    1027: ("GEMULT", "ICODE or JCODE not acceptable"),
    1028: ("GEMULT", "Illegal output: the CODE is not acceptable"),
    3000: ("GEPR01", "GEOUT1 cannot be used for a multihead printout (CODE 17)"),
    7000: ("GMSTOR", "Tape read error"),
    7001: ("WEFREW", "Error opening a scratch file for reading"),
    7002: ("WEFREW", "Error opening a scratch file for writing"),
    7003: ("GEMULT", "Only one head was selected"),
    8000: ("FUNLNK", "Option 132 is set incorrectly"),
    8500: ("OUTPUT", "CODE greater than 18"),
    9000: ("INIT", "CL tape read error or end of file: no MACHIN statement was given"),
    9001: ("OUTPUT", "The IHEAD flag was not set up properly"),
}

# The manual's numbered warning comments (COMENT n) that gecent prints, with the text it
# prints (the module that prints each keeps its own constant; tests/test_macros_wave9.py
# checks they agree): a diagnostic macro's $P2 (spec 09 §5.12). gecent's other warnings
# have no number in the manual ($P2 = $NULL).
WARNING_COMMENTS: dict[int, str] = {
    19: "TOOL LENGTH IS ZERO",  # core/tool.py (text lost in the scan)
    22: "REQUESTED MISCELLANEOUS FUNCTION CODE IS NOT AVAILABLE ON THIS MACHINE",  # L29355
    40: "ATTEMPTING TO UNLOAD TOOL IN WRONG MAGAZINE POCKET.",  # core/statements/handling.py
    47: "END OR RESET HAS NOT BEEN FOLLOWED BY A FROM POINT.",  # L34080
    63: "SPINDLE SPEED COULD NOT BE FOUND.",  # DSRROW, above the range (L14588-14590)
    66: "Z IS BELOW ZERO AFTER THE OPTION 140 ADJUSTMENT",  # core/motion/positioning.py
    80: "LOWEST SPEED IN RANGE IS OUTPUT.",  # DSRROW, below the range (L30766-30777)
}


@dataclass(frozen=True, slots=True)
class SourcePosition:
    """Where something came from: a file, and a line, column or CL record number in it.

    For a binary CL file ``offset`` is the byte offset of the record and ``line`` the ISN
    (source statement number) the APT processor gave it."""

    file: str
    line: int | None = None
    column: int | None = None
    record: int | None = None
    offset: int | None = None

    def __str__(self) -> str:
        if self.offset is not None:
            where = [f"record {self.record}"] if self.record is not None else []
            if self.line is not None:
                where.append(f"ISN {self.line}")
            suffix = f" ({', '.join(where)})" if where else ""
            return f"{self.file}: byte {self.offset}{suffix}"
        parts = [self.file]
        if self.line is not None:
            parts.append(str(self.line))
            if self.column is not None:
                parts.append(str(self.column))
        text = ":".join(parts)
        if self.record is not None:
            text += f" (record {self.record})"
        return text


class GecentError(Exception):
    """Base of every error gecent reports to its user. ``partial`` is what a run had
    produced when a fatal error stopped it (the listing is still written, never the tape)."""

    exit_status = EXIT_INTERNAL
    partial: object | None = None


class InternalError(GecentError):
    """A bug in gecent met while posting: exit 70, naming the record being posted, never
    mistaken for bad input. The original exception is its cause (GECENT_DEBUG=1 shows it)."""

    exit_status = EXIT_INTERNAL

    def __init__(self, error: BaseException, where: SourcePosition | None) -> None:
        super().__init__(f"{type(error).__name__}: {error}")
        self.error = error
        self.where = where

    def __str__(self) -> str:
        prefix = f"{self.where}: " if self.where is not None else ""
        return (
            f"{prefix}gecent: internal error: {self.args[0]} (a bug in gecent, not in the "
            "input: please report it with the input; GECENT_DEBUG=1 shows the traceback)"
        )


class InputError(GecentError):
    """Malformed input: the message names the file, position and what was expected."""

    exit_status = EXIT_BAD_INPUT

    def __init__(self, message: str, where: SourcePosition | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.where = where

    def __str__(self) -> str:
        if self.where is None:
            return f"error: {self.message}"
        return f"{self.where}: error: {self.message}"


class MachineDefinitionError(InputError):
    """A machine file breaks a rule: names the file, the table, the entry and the rule."""

    def __init__(self, file: str, table: str, entry: str | int | None, rule: str) -> None:
        self.file = file
        self.table = table
        self.entry = entry
        self.rule = rule
        where = f"[{table}]" if entry is None else f"[{table}] entry {entry}"
        super().__init__(f"{where}: {rule}", SourcePosition(file))


class NotYetSupported(GecentError):
    """The input uses a feature that this version of gecent does not build yet."""

    exit_status = EXIT_NOT_SUPPORTED

    def __init__(self, feature: str, where: SourcePosition | None = None) -> None:
        super().__init__(feature)
        self.feature = feature
        self.where = where

    def __str__(self) -> str:
        prefix = f"{self.where}: " if self.where is not None else ""
        return f"{prefix}error: not yet supported: {self.feature}"


class RunStopped(GecentError):
    """A condition the machine's options make fatal without a manual error number (for
    example a slide limit under option 110 = -1): processing stops, exit status 1."""

    exit_status = EXIT_FATAL

    def __init__(self, message: str, where: SourcePosition | None = None) -> None:
        super().__init__(message)
        self.message = message
        self.where = where

    def __str__(self) -> str:
        prefix = f"{self.where}: " if self.where is not None else ""
        return f"{prefix}error: {self.message}"


class FatalError(GecentError):
    """One of the manual's fatal errors (§5.7.1): processing stops."""

    exit_status = EXIT_FATAL

    def __init__(self, number: int, detail: str = "", where: SourcePosition | None = None) -> None:
        subroutine, reason = FATAL_ERRORS.get(number, ("MACFUN", "Machine-specific fatal error"))
        self.number = number
        self.subroutine = subroutine
        self.reason = reason
        self.detail = detail
        self.where = where
        super().__init__(str(self))

    def __str__(self) -> str:
        prefix = f"{self.where}: " if self.where is not None else ""
        text = f"{prefix}fatal error {self.number} ({self.subroutine}): {self.reason}"
        return f"{text}: {self.detail}" if self.detail else text


@dataclass(frozen=True, slots=True)
class Diagnostic:
    """A warning comment (manual §5.7): printed in the listing and on stderr; never stops a run."""

    text: str
    where: SourcePosition | None = None

    def __str__(self) -> str:
        prefix = f"{self.where}: " if self.where is not None else ""
        return f"{prefix}warning: {self.text}"
