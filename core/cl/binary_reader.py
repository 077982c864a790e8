"""Read binary CL files (manual §3.2-3.3, 001 L2666-3656) into the record stream.

The reader is a generator over Fortran records. The ISN of each type-1000 record becomes
the ``line`` of the records that follow it, as the manual keeps the last type-1000 record
to identify the source statement of a diagnostic (001 L2876-2900). A type-1000 record that
holds text becomes a :class:`PartText` (a ``$$`` comment when the text starts so).
"""

from __future__ import annotations

import struct
from collections.abc import Iterator
from typing import BinaryIO

from gecent.core.cl.apt_source import TEXT_MAJORS
from gecent.core.cl.binary_layout import (
    APT4,
    MARKER_BYTES,
    MAX_PAYLOAD,
    RECORD_TYPES,
    Codec,
    Layout,
    detect_layout,
)
from gecent.core.cl.records import (
    Arelem,
    Arg,
    Circle,
    Comment,
    Fini,
    Motion,
    MotionSubtype,
    Multiax,
    Other,
    PartText,
    Record,
    Statement,
    Surface,
    Word,
)
from gecent.core.cl.vocabulary import Vocabulary, vocabulary
from gecent.core.errors import InputError, SourcePosition

TEXT_CODES = frozenset(vocabulary().major[name] for name in TEXT_MAJORS)  # PPRINT, PARTNO, INSERT
READ_BLOCK = 1 << 16
_MOTION_SUBTYPES = {int(kind): kind for kind in MotionSubtype}
CIRCLE_SURFACE = 4
CIRCLE_VALUES = 7
# Statements an APT processor writes as records of other types (APT IV CNVRT3).
STATEMENT_RECORDS = {(9000, 9): "UNITS", (13000, 4): "CLPRNT"}


def _framed(stream: BinaryIO, file: str, order: str) -> Iterator[tuple[int, bytes]]:
    """(byte offset, payload) of each Fortran record; truncation and damage are errors.
    The file is read in blocks, so memory stays at one block whatever the file size."""
    unpack = struct.Struct(order + "i").unpack_from
    buffer = b""
    at = 0  # position of the next record in ``buffer``
    offset = 0  # its byte offset in the file
    count = 0
    while True:
        if len(buffer) - at < MARKER_BYTES:
            buffer = buffer[at:] + stream.read(READ_BLOCK)
            at = 0
            if not buffer:
                return
        count += 1
        if len(buffer) < MARKER_BYTES:
            raise InputError(
                f"truncated record: {len(buffer)} bytes where a 4-byte length was expected",
                SourcePosition(file, record=count, offset=offset),
            )
        (length,) = unpack(buffer, at)
        if length < 0 or length > MAX_PAYLOAD:
            raise InputError(
                f"corrupt record: length {length} (expected 0..{MAX_PAYLOAD} bytes)",
                SourcePosition(file, record=count, offset=offset),
            )
        size = length + 2 * MARKER_BYTES
        while len(buffer) - at < size:
            more = stream.read(max(READ_BLOCK, size))
            if not more:
                found = len(buffer) - at - MARKER_BYTES
                raise InputError(
                    f"truncated record: expected {length + MARKER_BYTES} bytes after the "
                    f"length, found {found}",
                    SourcePosition(file, record=count, offset=offset),
                )
            buffer = buffer[at:] + more
            at = 0
        (trailer,) = unpack(buffer, at + MARKER_BYTES + length)
        if trailer != length:
            raise InputError(
                f"corrupt record: leading length {length} but trailing length {trailer}",
                SourcePosition(file, record=count, offset=offset),
            )
        yield offset, buffer[at + MARKER_BYTES : at + MARKER_BYTES + length]
        at += size
        offset += size


class BinaryDecoder:
    """Turn the payloads of one file into records."""

    def __init__(self, file: str, layout: Layout, words: Vocabulary | None = None) -> None:
        self.file = file
        self.layout = layout
        self.codec = Codec(layout)
        self._header_bytes = layout.header_bytes
        self._word_bytes = layout.word
        self.vocabulary = words or vocabulary()
        self.isn: int | None = None
        self.multiax = False
        self.dialect = (
            {code: name for name, code in self.vocabulary.apt4_major.items()}
            if layout.kind == APT4
            else {}
        )

    def decode(self, offset: int, payload: bytes, count: int) -> Record | None:
        try:
            number, rtype, subtype = self.codec.header(payload)
        except (ValueError, struct.error) as exc:
            raise InputError(
                f"corrupt record header: {exc}",
                SourcePosition(self.file, None, None, count, offset),
            ) from None
        if rtype not in RECORD_TYPES or not 0 <= number < 1 << 31:
            what = f"type {rtype}" if rtype not in RECORD_TYPES else f"record number {number}"
            raise InputError(
                f"corrupt record header: {what} is not valid "
                "(types 1000, 2000, ..., 14000; numbers 0..2**31-1)",
                SourcePosition(self.file, None, None, count, offset),
            )
        start = self._header_bytes
        words = (len(payload) - start) // self._word_bytes
        try:
            return self._record(number, rtype, subtype, payload, start, words, offset)
        except (ValueError, struct.error) as exc:
            where = SourcePosition(self.file, self.isn, None, number, offset)
            raise InputError(f"corrupt type {rtype} record: {exc}", where) from None

    def _record(
        self, number: int, rtype: int, subtype: int, payload: bytes, start: int, words: int, at: int
    ) -> Record | None:
        codec = self.codec
        size = self.layout.word
        if rtype == 1000:
            self.isn = subtype
            if not payload[start:].strip(b" \0"):
                return None
            text = codec.text(payload, start, words, self.layout.text_chars)
            if not text.strip():
                return None
            if text.startswith("$$"):
                return Comment(self.file, subtype, number, text[2:], offset=at)
            return PartText(self.file, subtype, number, text, offset=at)
        line = self.isn
        if rtype == 2000:
            return self._statement(number, subtype, payload, start, words, at)
        if rtype == 3000:
            if words < 5:
                raise ValueError(f"surface record holds {words} words, expected at least 5")
            position = codec.integer(payload, start)
            surface_type = codec.integer(payload, start + size)
            name = codec.text(payload, start + 3 * size, 1, self.layout.name_chars)
            subscript = codec.integer(payload, start + 4 * size)
            values = codec.floats(payload, start + 5 * size, words - 5)
            if surface_type == CIRCLE_SURFACE:
                if len(values) < CIRCLE_VALUES:
                    raise ValueError(f"circle holds {len(values)} values, expected 7")
                return Circle(self.file, line, number, values, name, subscript, position, offset=at)
            return Surface(
                self.file,
                line,
                number,
                surface_type,
                values,
                name,
                subscript,
                position,
                subtype,
                offset=at,
            )
        if rtype == 5000:
            return self._motion(number, subtype, payload, start, words, at)
        if rtype == 6000:
            return Arelem(
                self.file, line, number, subtype, codec.floats(payload, start, words), offset=at
            )
        if rtype == 9000 and subtype == 2:
            self.multiax = words == 0 or codec.floats(payload, start, 1)[0] != 0.0
            return Multiax(self.file, line, number, self.multiax, offset=at)
        if rtype == 14000:
            return Fini(self.file, line, number, offset=at)
        items = self._items(payload, start, words)
        major = STATEMENT_RECORDS.get((rtype, subtype))
        if major == "UNITS" and len(items) == 1 and isinstance(items[0], float):
            names = {value: name for name, value in self.vocabulary.units_value.items()}
            unit = names.get(int(items[0]))
            if unit is not None and items[0] == int(items[0]):
                word = Word(unit, self.vocabulary.minor_code(unit))
                return Statement(self.file, line, number, major, None, (word,), offset=at)
        elif major is not None and all(isinstance(i, float) for i in items) and len(items) < 2:
            flags = tuple(self._word("ON" if i else "OFF") for i in items)
            return Statement(self.file, line, number, major, None, flags, offset=at)
        return Other(self.file, line, number, rtype, subtype, items, offset=at)

    def _statement(
        self, number: int, code: int, payload: bytes, start: int, words: int, at: int
    ) -> Statement:
        major = self.dialect.get(code) or self.vocabulary.major_name(code)
        if major in self.vocabulary.apt4_major and self.dialect:
            code = self.vocabulary.major[major]
        if code in TEXT_CODES:
            text = self.codec.text(payload, start, words, self.layout.text_chars)
            text = text[1:] if text.startswith(" ") else text
            return Statement(self.file, self.isn, number, major, code, (), text, offset=at)
        args = self._items(payload, start, words)
        return Statement(self.file, self.isn, number, major, code, args, offset=at)

    def _word(self, name: str) -> Word:
        return Word(name, self.vocabulary.minor_code(name))

    def _items(self, payload: bytes, start: int, words: int) -> tuple[Arg, ...]:
        codec = self.codec
        args: list[Arg] = []
        for index in range(words):
            at = start + index * self.layout.word
            kind, value = codec.tag(payload, at)
            if kind == "code":
                args.append(self.vocabulary.minor_word(value))
            elif kind == "int":
                args.append(value)
            else:
                name = codec.uncoded_word(payload, at)
                if name is not None:
                    args.append(Word(name, self.vocabulary.minor_code(name)))
                else:
                    args.append(codec.floats(payload, at, 1)[0])
        return tuple(args)

    def _motion(
        self, number: int, subtype: int, payload: bytes, start: int, words: int, at: int
    ) -> Record:
        if subtype not in (3, 4, 5, 6):
            return Other(
                self.file,
                self.isn,
                number,
                5000,
                subtype,
                self._items(payload, start, words),
                offset=at,
            )
        if words < 2:
            raise ValueError(f"motion record holds {words} words, expected a name and a subscript")
        size = self.layout.word
        name = self.codec.text(payload, start, 1, self.layout.name_chars)
        subscript = self.codec.integer(payload, start + size)
        values = self.codec.floats(payload, start + 2 * size, words - 2)
        kind = _MOTION_SUBTYPES[subtype]
        if kind is MotionSubtype.GODLTA:
            if len(values) not in (1, 3):
                raise ValueError(f"GODLTA holds {len(values)} values, expected 1 or 3")
            points: tuple[tuple[float, ...], ...] = (values,)
        else:
            width = 6 if self.multiax else 3
            if not values or len(values) % width:
                raise ValueError(
                    f"motion record holds {len(values)} values, expected a multiple of {width}"
                )
            points = tuple(values[i : i + width] for i in range(0, len(values), width))
        return Motion(self.file, self.isn, number, kind, points, name, subscript, offset=at)


def read_binary(path: str, layout: Layout | None = None) -> Iterator[Record]:
    """Stream the records of a binary CL file; the layout is detected unless given."""
    try:
        with open(path, "rb") as stream:
            if layout is None:
                layout = detect_layout(stream.read(4096))
                stream.seek(0)
                if layout is None:
                    raise InputError(
                        "not a binary CL file: the first record's length markers and header "
                        "match no known layout (apt4, manual4, manual8)",
                        SourcePosition(path, offset=0),
                    )
            decoder = BinaryDecoder(path, layout)
            for count, (offset, payload) in enumerate(_framed(stream, path, layout.order), start=1):
                record = decoder.decode(offset, payload, count)
                if record is not None:
                    yield record
    except OSError as exc:
        raise InputError(f"cannot read CL file: {exc.strerror}", SourcePosition(path)) from None
