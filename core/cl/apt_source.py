"""Read CL data written as APT source text (ISO 4343 style), as CAM systems write it.

Rules (decisions with seed lines in docs/decisions.md):

* case-insensitive words; blanks are insignificant except inside PARTNO/PPRINT/INSERT text;
* a trailing ``$`` continues the statement on the next line;
* ``$$`` starts a comment, kept as a :class:`Comment` record; a comment line that ends in a
  single ``$`` continues on the next line (Creo writes multi-line ``$$->`` comments so);
* PARTNO, PPRINT and INSERT keep the rest of the line verbatim (a leading ``/`` dropped);
  REMARK lines are comments;
* a major word may be several: hyphened (``END-OF-PATH``) or blank-separated before its slash
  (NX's ``TOOL PATH/``, read as ``TOOL_PATH``);
* FROM/GOTO take 3 values (6 after MULTAX/ON), GODLTA 1 or 3; CIRCLE takes the canonical
  7 values xc, yc, zc, i, j, k, r, or 6 (no radius) or 11 (NX: the 7 and four more, dropped);
  a word may begin with digits (SolidWorks CAM's 1STPECK); INTOL, OUTTOL and CUTTER become
  type-6000 records and MULTAX a type-9000 record, as an APT processor writes them.

The reader is a generator: memory does not grow with the file.
"""

from __future__ import annotations

import codecs
import re
from collections.abc import Iterable, Iterator

from gecent.core.cl.records import (
    Arelem,
    Arg,
    Circle,
    Comment,
    Fini,
    Motion,
    MotionSubtype,
    Multiax,
    Record,
    Statement,
    Word,
)
from gecent.core.cl.vocabulary import vocabulary
from gecent.core.errors import InputError, SourcePosition

TEXT_MAJORS = frozenset({"PARTNO", "PPRINT", "INSERT"})
# the rest of the line is text: REMARK a comment, TPRINT a tool's name (CATIA, Mastercam)
TEXT_LINES = TEXT_MAJORS | {"REMARK", "TPRINT"}
_MOTION = {"FROM": MotionSubtype.FROM, "GOTO": MotionSubtype.GOTO, "GODLTA": MotionSubtype.GODLTA}
_ARELEM = {"INTOL": 4, "OUTTOL": 5, "CUTTER": 6}
# Flag words an APT processor turns into type-6000 records (001 L3569-3576): subtype, item 4.
_ARELEM_FLAGS = {
    "CUT": (1, 0.0),
    "DNTCUT": (1, 1.0),
    "2DCALC": (2, 0.0),
    "3DCALC": (2, 1.0),
    "NDTEST": (2, 2.0),
}
_TOKEN = re.compile(
    r"\s*(?:(?P<number>[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)(?![A-Za-z0-9_])"
    r"|(?P<word>[0-9]*[A-Za-z][A-Za-z0-9_]*)|(?P<comma>,)|(?P<end>$))",
    re.ASCII,  # blanks are ASCII blanks: float() takes no other (a \x1c is an error)
)
_NUMBER_ITEM = r"\s*[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?\s*"
_NUMBER_LIST = re.compile(rf"{_NUMBER_ITEM}(?:,{_NUMBER_ITEM})*\Z", re.ASCII)
_MAJOR = re.compile(r"\s*((?:[A-Za-z]|\d+[A-Za-z])[A-Za-z0-9_]*)", re.ASCII)
# TLON,GOFWD/: words joined by commas up to the slash
_LEADING = re.compile(r"((?:\s*,\s*[A-Za-z][A-Za-z0-9_]*)+)\s*/", re.ASCII)
# a major word of several: END-OF-PATH (hyphens), TOOL PATH/ (a blank, before the slash)
_MORE_MAJOR = re.compile(
    r"(?:-([A-Za-z][A-Za-z0-9_]*))|(?:[ \t]+([A-Za-z][A-Za-z0-9_]*)(?=\s*/))", re.ASCII
)
# the reader's fast path: a whole one-line "GOTO / x, y, z" (no continuation, no comment)
_ONE_LINE_GOTO = re.compile(
    rf"\s*GOTO\s*/({_NUMBER_ITEM}),({_NUMBER_ITEM}),({_NUMBER_ITEM})[\r\n]*\Z", re.ASCII
)


class _Line:
    """One logical statement: the joined text and where each part came from."""

    __slots__ = ("line", "parts", "text")

    def __init__(self, line: int) -> None:
        self.line = line
        self.text = ""
        self.parts: list[tuple[int, int, int]] = []  # (offset in text, line, column base)

    def add(self, text: str, line: int, column: int) -> None:
        self.parts.append((len(self.text), line, column))
        self.text += text

    def position(self, file: str, offset: int) -> SourcePosition:
        start, line, column = self.parts[0]
        for part in self.parts:
            if part[0] > offset:
                break
            start, line, column = part
        return SourcePosition(file, line, column + offset - start)


class AptSourceReader:
    """Parse one APT source CL file into records."""

    def __init__(self, file: str, columns: int | None = None) -> None:
        self.file = file
        self.columns = columns  # CATIA: columns past 72 hold sequence tags, not data
        self.multiax = False
        self.number = 0
        self._vocabulary = vocabulary()

    def read_lines(self, lines: Iterable[str]) -> Iterator[Record]:
        """The records of the lines, continuations joined; a whole one-line GOTO of three
        numbers (no continuation, no comment, not under MULTAX) is read straight off."""
        file = self.file
        goto = MotionSubtype.GOTO
        one_line_goto = _ONE_LINE_GOTO.match
        pending: _Line | None = None
        pending_kind = "statement"
        columns = self.columns
        for number, raw in enumerate(lines, start=1):
            if columns is not None and len(raw.rstrip("\r\n")) > columns:
                if raw[columns - 1] not in " \t" and raw[columns] not in " \t":
                    raise InputError(
                        f"a value runs past column {columns}, where this CAM system's lines "
                        "end (sequence tags follow)",
                        SourcePosition(file, number, columns + 1),
                    )
                raw = raw[:columns] + "\n"
            if pending is None and (found := one_line_goto(raw)) is not None and not self.multiax:
                x, y, z = found.groups()
                self.number += 1
                yield Motion(file, number, self.number, goto, ((float(x), float(y), float(z)),))
                continue
            line = raw.rstrip("\r\n")
            if pending is not None and pending_kind == "comment":
                stripped = line.rstrip()
                continues = stripped.endswith("$") and not stripped.endswith("$$")
                pending.add(" " + (stripped[:-1] if continues else stripped).strip(), number, 1)
                if not continues:
                    yield self._comment(pending)
                    pending = None
                continue
            comment_at = line.find("$$")
            head = line if comment_at < 0 else line[:comment_at]
            if pending is None and not head.strip():
                if comment_at >= 0:
                    comment = _Line(number)
                    body = line[comment_at + 2 :].rstrip()
                    if body.endswith("$") and not body.endswith("$$"):
                        comment.add(body[:-1].rstrip(), number, comment_at + 3)
                        pending, pending_kind = comment, "comment"
                    else:
                        comment.add(body, number, comment_at + 3)
                        yield self._comment(comment)
                continue
            if pending is None:
                pending, pending_kind = _Line(number), "statement"
            stripped = head.rstrip()
            first_word = _MAJOR.match(pending.text or stripped)
            is_text = first_word is not None and first_word.group(1).upper() in TEXT_LINES
            if not is_text and stripped.endswith("$"):
                pending.add(stripped[:-1], number, 1)
                continue
            pending.add(line.rstrip() if is_text else stripped, number, 1)
            record = self._statement(pending)
            if record is not None:
                yield record
            pending = None
            if comment_at >= 0 and not is_text:
                trailing = _Line(number)
                trailing.add(line[comment_at + 2 :].rstrip(), number, comment_at + 3)
                yield self._comment(trailing)
        if pending is not None:
            if pending_kind == "comment":
                yield self._comment(pending)
            else:
                record = self._statement(pending)
                if record is not None:
                    yield record

    def _comment(self, logical: _Line) -> Comment:
        self.number += 1
        return Comment(self.file, logical.line, self.number, logical.text.strip())

    def _error(self, logical: _Line, offset: int, message: str) -> InputError:
        return InputError(message, logical.position(self.file, offset))

    def _statement(self, logical: _Line) -> Record | None:
        text = logical.text
        match = _MAJOR.match(text)
        if match is None:
            if not text.strip():
                return None
            offset = len(text) - len(text.lstrip())
            raise self._error(
                logical, offset, f"expected a statement word, found {text.strip()[:20]!r}"
            )
        major = match.group(1).upper()
        rest_at = match.end()
        if major not in TEXT_LINES:
            while (more := _MORE_MAJOR.match(text, rest_at)) is not None:
                joined, spaced = more.groups()
                major += f"-{joined.upper()}" if joined else f"_{spaced.upper()}"
                rest_at = more.end()
        self.number += 1
        line = logical.line
        if major == "REMARK":  # an APT comment statement
            return Comment(self.file, line, self.number, text[rest_at:].strip())
        if major in TEXT_LINES:
            body = text[rest_at:].strip()
            if body.startswith("/"):
                body = body[1:].strip()
            return Statement(
                self.file, line, self.number, major, self._vocabulary.major_code(major), (), body
            )
        rest = text[rest_at:]
        stripped = rest.lstrip()
        if stripped.startswith("="):
            raise self._error(
                logical, rest_at, "an assignment is APT part-program geometry, not CL data"
            )
        args: list[Arg] = []
        if stripped.startswith(","):
            # CATIA's CHANNEL,1 (no slash) and TLON,GOFWD/ (the last word is the major, the
            # ones before lead its arguments)
            found = _LEADING.match(stripped)
            if found is not None:
                leading = [major, *found.group(1).replace(" ", "").upper().split(",")[1:-1]]
                major = found.group(1).replace(" ", "").upper().split(",")[-1]
                start = rest_at + len(rest) - len(stripped) + found.end()
                words: list[Arg] = [Word(w, self._vocabulary.minor_code(w)) for w in leading]
                if "(" in text[start:]:  # nested geometry: kept as text for a dialect
                    return Statement(
                        self.file, logical.line, self.number, major,
                        self._vocabulary.major_code(major), tuple(words), text[start:].strip(),
                    )  # fmt: skip
                return self._record(logical, major, [*words, *self._arguments(logical, start)])
            args = self._arguments(logical, rest_at + len(rest) - len(stripped) + 1)
            return self._record(logical, major, args)
        if stripped:
            if not stripped.startswith("/"):
                raise self._error(
                    logical,
                    rest_at + len(rest) - len(stripped),
                    f"expected '/' after {major}, found {stripped[:12]!r}",
                )
            args = self._arguments(logical, rest_at + len(rest) - len(stripped) + 1)
        return self._record(logical, major, args)

    def _arguments(self, logical: _Line, start: int) -> list[Arg]:
        text = logical.text
        if _NUMBER_LIST.match(text, start):  # most records: numbers only (GOTO, FEDRAT)
            return [float(item) for item in text[start:].split(",")]
        args: list[Arg] = []
        position = start
        expect_value = True
        while True:
            token = _TOKEN.match(text, position)
            if token is None:
                raise self._error(
                    logical,
                    position + len(text[position:]) - len(text[position:].lstrip()),
                    f"expected a number or a word, found {text[position:].strip()[:12]!r}",
                )
            kind = token.lastgroup
            assert kind is not None  # every alternative of _TOKEN is a named group
            if kind == "end":
                if expect_value and args:
                    raise self._error(logical, position, "expected a value after ','")
                return args
            if kind == "comma":
                if expect_value:
                    raise self._error(logical, token.start(kind), "expected a value before ','")
                expect_value = True
            else:
                if not expect_value:
                    raise self._error(logical, token.start(kind), "expected ',' between values")
                value = token.group(kind)
                if kind == "number":
                    args.append(float(value))
                else:
                    name = value.upper()
                    args.append(Word(name, self._vocabulary.minor_code(name)))
                expect_value = False
            position = token.end()

    def _numbers(
        self, logical: _Line, major: str, args: list[Arg], counts: tuple[int, ...]
    ) -> tuple[float, ...]:
        if any(isinstance(a, Word) for a in args):
            raise self._error(
                logical, 0, f"{major} takes numbers only, found {', '.join(map(str, args))}"
            )
        if len(args) not in counts:
            expected = " or ".join(str(c) for c in counts)
            raise self._error(logical, 0, f"{major} takes {expected} values, found {len(args)}")
        return tuple(float(a) for a in args if not isinstance(a, Word))

    def _record(self, logical: _Line, major: str, args: list[Arg]) -> Record:
        file, line, number = self.file, logical.line, self.number
        if major in _MOTION:
            subtype = _MOTION[major]
            if subtype is MotionSubtype.GODLTA:
                counts: tuple[int, ...] = (1, 3)
            else:
                counts = (3, 6)  # (NCL writes FROM/x,y,z under MULTAX/ON: no tool axis)
            values = self._numbers(logical, major, args, counts)
            return Motion(file, line, number, subtype, (values,))
        if major == "CIRCLE":
            # 7 values (centre, axis, radius); 6 without the radius (SolidWorks CAM: it comes
            # from the points); 11 with NX's tolerance and tool data after the radius
            values = self._numbers(logical, major, args, (6, 7, 11))
            return Circle(file, line, number, values[:7])
        if major == "FINI":
            return Fini(file, line, number)
        if major in _ARELEM_FLAGS:
            if args:
                raise self._error(logical, 0, f"{major} takes no values")
            flag_subtype, flag = _ARELEM_FLAGS[major]
            return Arelem(file, line, number, flag_subtype, (flag,))
        if major in _ARELEM:
            values = self._numbers(logical, major, args, tuple(range(1, 8)))
            return Arelem(file, line, number, _ARELEM[major], values)
        if major == "MULTAX":
            words = [a.name for a in args if isinstance(a, Word)]
            if words not in (["ON"], ["OFF"], []) or len(args) != len(words):
                raise self._error(logical, 0, "MULTAX takes ON or OFF")
            self.multiax = words != ["OFF"]
            return Multiax(file, line, number, self.multiax)
        return Statement(file, line, number, major, self._vocabulary.major_code(major), tuple(args))


def text_encoding(path: str) -> str:
    """UTF-8 (with or without a byte-order mark) when the whole file decodes so, else
    Latin-1, which every byte does: CAM systems write both (German PPRINT umlauts)."""
    decoder = codecs.getincrementaldecoder("utf-8")()
    with open(path, "rb") as handle:
        first = handle.read(1 << 16)
        bom = first.startswith(codecs.BOM_UTF8)
        chunk = first
        try:
            while chunk:
                decoder.decode(chunk)
                chunk = handle.read(1 << 20)
            decoder.decode(b"", final=True)
        except UnicodeDecodeError:
            return "latin-1"
    return "utf-8-sig" if bom else "utf-8"


def read_apt_source(path: str, columns: int | None = None) -> Iterator[Record]:
    """Stream the records of an APT source CL file (``columns``: read no further along a
    line, for sequence tags past column 72)."""
    reader = AptSourceReader(path, columns)
    try:
        encoding = text_encoding(path)
        with open(path, encoding=encoding, errors="strict", newline="") as handle:
            yield from reader.read_lines(handle)
    except OSError as exc:
        raise InputError(f"cannot read CL file: {exc.strerror}", SourcePosition(path)) from None
