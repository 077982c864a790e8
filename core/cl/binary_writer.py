"""Write records as a binary CL file, the inverse of :mod:`binary_reader`.

It writes what an APT processor writes: a type-1000 record carrying the ISN (the record's
``line``) before the records of each statement, type-2000 statements with vocabulary codes,
circles as 3000/2 records, motion as 5000 records of at most 240 data words (the manual's
NWPR limit of 245, 001 L2666-2707; longer motion continues in subtype-6 records).
Comments travel as type-1000 text starting with ``$$``, so a text -> binary -> records round
trip loses nothing. A word with no vocabulary code is written as a BCD word; a statement
with no code cannot be written and is an error naming it.
"""

from __future__ import annotations

import struct
from collections.abc import Iterable
from typing import BinaryIO

from gecent.core.cl.binary_layout import APT4, TEXT_WORD, Codec, Layout, LayoutError
from gecent.core.cl.binary_reader import CIRCLE_SURFACE, STATEMENT_RECORDS, TEXT_CODES
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
from gecent.core.cl.vocabulary import vocabulary
from gecent.core.errors import InputError

MAX_DATA_WORDS = 240
APT_TEXT_WORDS = 11  # APT IV writes PARTNO, PPRINT and INSERT as 11 six-character words
_RECORD_OF_STATEMENT = {major: key for key, major in STATEMENT_RECORDS.items()}


class BinaryWriter:
    def __init__(self, stream: BinaryIO, layout: Layout) -> None:
        self.stream = stream
        self.layout = layout
        self.codec = Codec(layout)
        self.vocabulary = vocabulary()
        self.isn: int | None = -1  # no statement yet
        self._marker = struct.Struct(layout.order + "i")
        self.dialect = (
            {self.vocabulary.major[name]: code for name, code in self.vocabulary.apt4_major.items()}
            if layout.kind == APT4
            else {}
        )
        self._taken = set(self.dialect.values())

    def write_all(self, records: Iterable[Record]) -> None:
        for record in records:
            self.write(record)

    def write(self, record: Record) -> None:
        try:
            self._write(record)
        except LayoutError as exc:
            raise InputError(
                f"cannot write {type(record).__name__.lower()} to a {self.layout.name} "
                f"CL file: {exc}",
                record.where,
            ) from None

    def _emit(self, number: int, rtype: int, subtype: int, data: bytes) -> None:
        if not 1 <= number < 1 << 31:
            raise LayoutError(f"record number {number} is out of range")
        words = len(data) // self.layout.word
        payload = self.codec.pack_header(number, rtype, subtype, words) + data
        marker = self._marker.pack(len(payload))
        self.stream.write(marker + payload + marker)

    def _statement_text(self, record: Record, text: str) -> None:
        words = self.codec.pack_text(text, self.layout.text_chars)
        self._emit(record.number, 1000, record.line or 0, words)
        self.isn = record.line

    def _write(self, record: Record) -> None:
        codec = self.codec
        if isinstance(record, Comment):
            self._statement_text(record, "$$" + record.text)
            return
        if isinstance(record, PartText):
            self._statement_text(record, record.text)
            return
        if record.line != self.isn:
            self._statement_text(record, "")
        if isinstance(record, Statement):
            self._statement(record)
        elif isinstance(record, Motion):
            self._motion(record)
        elif isinstance(record, Circle | Surface):
            surface = CIRCLE_SURFACE if isinstance(record, Circle) else record.surface_type
            use = 2 if isinstance(record, Circle) else record.use
            data = (
                self._small(record.position)
                + self._small(surface)
                + self._small(len(record.values) + 2)
                + codec.pack_chars(record.name)
                + codec.pack_int(record.subscript)
                + b"".join(codec.pack_float(v) for v in record.values)
            )
            self._emit(record.number, 3000, use, data)
        elif isinstance(record, Arelem):
            data = b"".join(codec.pack_float(v) for v in record.values)
            self._emit(record.number, 6000, record.subtype, data)
        elif isinstance(record, Multiax):
            self._emit(record.number, 9000, 2, codec.pack_float(1.0 if record.on else 0.0))
        elif isinstance(record, Fini):
            self._emit(record.number, 14000, 0, b"")
        elif isinstance(record, Other):
            self._emit(record.number, record.record_type, record.subtype, self._args(record.items))
        else:
            raise LayoutError(f"no binary form for {type(record).__name__} records")

    def _small(self, value: int) -> bytes:
        return bytes(self.layout.word) if value == 0 else self.codec.pack_code(value)

    def _statement(self, record: Statement) -> None:
        if record.code is None:
            key = _RECORD_OF_STATEMENT.get(record.major)
            if key is None:
                raise LayoutError(
                    f"{record.major} has no APT major-word code; add it to the vocabulary"
                )
            self._emit(record.number, key[0], key[1], self._statement_record(record))
            return
        code = self.dialect.get(record.code, record.code)
        if code in self._taken and record.code not in self.dialect:
            raise LayoutError(f"{record.major} (code {record.code}) has no APT IV code")
        if record.code in TEXT_CODES:
            per_word = self.layout.text_chars
            text = " " + (record.text or "")
            if self.layout.kind == APT4:  # APT IV ends the text with a blank word
                text = text.ljust(-(-len(text) // per_word) * per_word + per_word)
            minimum = APT_TEXT_WORDS if self.layout.kind == APT4 else 0
            data = self.codec.pack_text(text, per_word, minimum)
        else:
            data = self._args(record.args)
        self._emit(record.number, 2000, code, data)

    def _statement_record(self, record: Statement) -> bytes:
        """UNITS/x as its unit number; CLPRNT[/ON|OFF] as nothing, 1 or 0 (APT IV CNVRT3)."""
        if record.major == "UNITS":
            units = self.vocabulary.units_value
            if len(record.args) == 1 and isinstance(record.args[0], Word):
                value = units.get(record.args[0].name)
                if value is not None:
                    return self.codec.pack_float(float(value))
            raise LayoutError(f"UNITS takes one of {', '.join(units)}")
        flags = {"ON": 1.0, "OFF": 0.0}
        words = [a.name for a in record.args if isinstance(a, Word)]
        if len(words) != len(record.args) or len(words) > 1 or not set(words) <= set(flags):
            raise LayoutError(f"{record.major} takes ON or OFF")
        return b"".join(self.codec.pack_float(flags[w]) for w in words)

    def _args(self, args: Iterable[Arg]) -> bytes:
        codec = self.codec
        parts: list[bytes] = []
        for arg in args:
            if isinstance(arg, Word):
                if arg.code is not None:
                    parts.append(codec.pack_code(arg.code))
                elif TEXT_WORD.match(arg.name) and len(arg.name) <= self.layout.word_chars:
                    parts.append(codec.pack_chars(arg.name))
                else:
                    raise LayoutError(
                        f"word {arg.name} has no vocabulary code and is longer than "
                        f"{self.layout.word_chars} characters"
                    )
            elif isinstance(arg, int) and self.layout.kind == APT4:
                parts.append(codec.pack_int(arg))
            else:
                parts.append(codec.pack_float(float(arg)))
        return b"".join(parts)

    def _motion(self, record: Motion) -> None:
        codec = self.codec
        head = codec.pack_chars(record.name) + codec.pack_int(record.subscript)
        width = len(record.points[0]) if record.points else 3
        per_record = max(1, MAX_DATA_WORDS // width) if width else 1
        subtype = int(record.subtype)
        for first in range(0, max(len(record.points), 1), per_record):
            points = record.points[first : first + per_record]
            data = b"".join(codec.pack_float(v) for point in points for v in point)
            self._emit(record.number, 5000, subtype, head + data)
            subtype = int(MotionSubtype.CONTINUATION)


def write_binary(records: Iterable[Record], stream: BinaryIO, layout: Layout) -> None:
    BinaryWriter(stream, layout).write_all(records)
