"""Binary CL file layouts: how records, words, numbers and text sit in the bytes.

Every layout frames records as Fortran unformatted sequential records: a 4-byte length,
the payload, the same length again (in the file's byte order). Two payload layouts:

* ``apt4``: what the APT IV SSV3 processor (gfortran port) writes, corpus/README.md:
  int32 NWRDS, record number, type, subtype, then 8-byte slots. A vocabulary word is the
  int32 pair (0, code); an integer is the pair (0x4E000000, n), the unnormalised IBM
  double that equals n; text is 6 characters and 2 blanks per slot, 4 characters per
  int32 with the first in the most significant byte.
* ``manual``: the record layout of the GECENT III manual (§3.2, 001 L2666-2741), every word
  ``word`` bytes (4 or 8): record number, type, subtype, then the data words. As in the
  manual's STORGE rule, a word whose left half is zero is an integer (a vocabulary code or
  a subscript), stored in its right half; text fills each word from its most significant
  byte, 6 characters and 2 blanks in an 8-byte word, 4 characters in a 4-byte word.

No real CL number is a subnormal float, so the zero left half marks integers without
ambiguity; the writer refuses the rare number whose bits would read back as a word.
"""

from __future__ import annotations

import re
import struct
from dataclasses import dataclass

RECORD_TYPES = frozenset(range(1000, 15000, 1000))
MARKER_BYTES = 4
MAX_PAYLOAD = 1 << 20  # far beyond any CL record (the manual's NWPR is at most 245 words)
TEXT_WORD = re.compile(r"[A-Z][A-Z0-9]*\Z")
IBM_INTEGER = 0x4E000000  # IBM hexadecimal double exponent 0x4E: the fraction is the value
SIGN_BIT = 0x80000000

_PRINTABLE = bytes(range(0x20, 0x7F))
APT4 = "apt4"
MANUAL = "manual"
ORDERS = {"little": "<", "big": ">"}


class LayoutError(ValueError):
    """A value the layout cannot hold (raised by the encoders)."""


@dataclass(frozen=True)
class Layout:
    kind: str  # APT4 or MANUAL
    order: str  # "<" little-endian or ">" big-endian
    word: int = 8  # bytes per data word

    def __post_init__(self) -> None:
        if self.kind not in (APT4, MANUAL):
            raise LayoutError(f"unknown binary CL layout {self.kind!r} (apt4 or manual)")
        if self.order not in ("<", ">"):
            raise LayoutError(f"unknown byte order {self.order!r}")
        if self.word not in (4, 8) or (self.kind == APT4 and self.word != 8):
            raise LayoutError(f"a {self.kind} CL file cannot have {self.word}-byte words")

    @property
    def name(self) -> str:
        size = "" if self.kind == APT4 else str(self.word)
        return f"{self.kind}{size}-{'le' if self.order == '<' else 'be'}"

    @property
    def header_bytes(self) -> int:
        return 16 if self.kind == APT4 else 3 * self.word

    @property
    def text_chars(self) -> int:
        """Characters of part-program text per word (APT's 6-character BCD word)."""
        return 6 if self.word == 8 else 4

    @property
    def name_chars(self) -> int:
        return self.word

    @property
    def word_chars(self) -> int:
        """Longest uncoded word a statement can carry: at least one blank must follow it
        so that it cannot be taken for a number."""
        return 6 if self.word == 8 else 3


def parse_layout(name: str) -> Layout:
    """``apt4``, ``manual4`` or ``manual8``, with an optional ``-le``/``-be`` suffix."""
    base, _, order = name.lower().partition("-")
    order_char = {"": "<", "le": "<", "be": ">"}.get(order)
    if order_char is None:
        raise LayoutError(f"unknown byte order {order!r} in {name!r} (le or be)")
    if base == APT4:
        return Layout(APT4, order_char)
    if base in ("manual4", "manual8"):
        return Layout(MANUAL, order_char, int(base[-1]))
    raise LayoutError(f"unknown binary CL layout {name!r} (apt4, manual4 or manual8)")


def detect_layout(head: bytes) -> Layout | None:
    """The layout whose record markers and header the first record of ``head`` satisfies."""
    for order in ("<", ">"):
        if len(head) < MARKER_BYTES:
            return None
        (length,) = struct.unpack_from(order + "i", head, 0)
        if length < 12 or length > MAX_PAYLOAD or length % 4:
            continue
        end = MARKER_BYTES + length
        if len(head) >= end + MARKER_BYTES:
            (trailer,) = struct.unpack_from(order + "i", head, end)
            if trailer != length:
                continue
        # a file cut inside its first record is still recognised, so that the reader can
        # report the truncation rather than "not a CL file"
        for layout in (Layout(APT4, order), Layout(MANUAL, order, 4), Layout(MANUAL, order, 8)):
            if _first_record_fits(layout, head[MARKER_BYTES:end], length):
                return layout
    return None


class Codec:
    """Encode and decode the words of one layout."""

    def __init__(self, layout: Layout) -> None:
        self.layout = layout
        order = layout.order
        self.order = order
        self.word = layout.word
        if layout.kind == APT4:
            self._header = struct.Struct(order + "4i")
        else:
            self._header = struct.Struct(order + ("3i" if layout.word == 4 else "3q"))
        self._pair = struct.Struct(order + "2i")
        self._unsigned = struct.Struct(order + ("I" if layout.word == 4 else "Q"))
        self._float_code = "f" if layout.word == 4 else "d"
        self._float = struct.Struct(order + self._float_code)
        self._half = 16 if layout.word == 4 else 32
        self._right = (1 << self._half) - 1
        self._floats: dict[int, struct.Struct] = {}
        self._header_bytes = layout.header_bytes
        self._counted = layout.kind == APT4

    # -- header -------------------------------------------------------------------------

    def header(self, payload: bytes, length: int | None = None) -> tuple[int, int, int]:
        """(record number, type, subtype); raises ValueError on an inconsistent header.
        ``length`` is the record length when ``payload`` is only its beginning."""
        length = len(payload) if length is None else length
        header_bytes = self._header_bytes
        if len(payload) < header_bytes:
            raise ValueError(
                f"record of {len(payload)} bytes is shorter than its {header_bytes}-byte header"
            )
        if self._counted:
            words, number, rtype, subtype = self._header.unpack_from(payload, 0)
            if words * 4 != length - 4:
                raise ValueError(f"NWRDS says {words} words but the record holds {length // 4 - 1}")
        else:
            number, rtype, subtype = self._header.unpack_from(payload, 0)
        if (length - header_bytes) % self.word:
            raise ValueError(f"record of {length} bytes is not whole {self.word}-byte words")
        return number, rtype, subtype

    def pack_header(self, number: int, rtype: int, subtype: int, words: int) -> bytes:
        if self.layout.kind == APT4:
            return self._header.pack(3 + 2 * words, number, rtype, subtype)
        return self._header.pack(number, rtype, subtype)

    # -- reading ------------------------------------------------------------------------

    def floats(self, payload: bytes, offset: int, count: int) -> tuple[float, ...]:
        shape = self._floats.get(count)
        if shape is None:
            shape = self._floats[count] = struct.Struct(f"{self.order}{count}{self._float_code}")
        return shape.unpack_from(payload, offset)

    def tag(self, payload: bytes, offset: int) -> tuple[str, int]:
        """("code", n), ("int", n) or ("", 0) for a word that holds a number or text."""
        if self.layout.kind == APT4:
            left, right = self._pair.unpack_from(payload, offset)
            if left == 0 and 0 < right < 0x100000:
                return "code", right
            if left & 0x7FFFFFFF == IBM_INTEGER:
                return "int", -right if left & SIGN_BIT else right
            return "", 0
        (value,) = self._unsigned.unpack_from(payload, offset)
        if value and not value >> self._half:
            return "code", value
        return "", 0

    def integer(self, payload: bytes, offset: int) -> int:
        """A word known to hold an integer (a subscript or a count); 0.0 reads as 0."""
        kind, value = self.tag(payload, offset)
        if kind:
            return value
        number = self.floats(payload, offset, 1)[0]
        if number != int(number):
            raise ValueError(f"expected an integer word, found {number!r}")
        return int(number)

    def chars(self, payload: bytes, offset: int) -> bytes:
        """The characters of one word, first character first."""
        raw = payload[offset : offset + self.word]
        if self.order == ">":
            return raw
        if self.layout.kind == APT4:
            return raw[3::-1] + raw[7:3:-1]
        return raw[::-1]

    def uncoded_word(self, payload: bytes, offset: int) -> str | None:
        """The word spelled by a statement argument, if its bytes spell one."""
        raw = self.chars(payload, offset)
        text = raw.rstrip(b" ")
        if len(text) > self.layout.word_chars or len(text) == len(raw):
            return None
        try:
            word = text.decode("ascii")
        except UnicodeDecodeError:
            return None
        return word if TEXT_WORD.match(word) else None

    def text(self, payload: bytes, offset: int, count: int, per_word: int) -> str:
        """Text spread over ``count`` words, ``per_word`` characters each; an all-zero word
        ends it (APT leaves the unused words of a text record zero)."""
        parts: list[str] = []
        for index in range(count):
            at = offset + index * self.word
            raw = self.chars(payload, at)
            if not any(raw):
                break
            chunk = raw[:per_word].replace(b"\0", b" ")
            if chunk.translate(None, _PRINTABLE):
                bad = chunk.translate(None, _PRINTABLE)[0]
                raise ValueError(f"text word {index + 1} holds the non-character byte {bad:#04x}")
            parts.append(chunk.decode("ascii"))
        return "".join(parts).rstrip()

    # -- writing ------------------------------------------------------------------------

    def pack_float(self, value: float) -> bytes:
        try:
            raw = self._float.pack(value)
        except (OverflowError, struct.error):
            raise LayoutError(f"{value!r} does not fit a {self.word}-byte word") from None
        if value != 0.0 and (self.tag(raw, 0)[0] or self.uncoded_word(raw, 0) is not None):
            raise LayoutError(f"{value!r} cannot be written: its bits would read back as a word")
        return raw

    def pack_code(self, code: int) -> bytes:
        if self.layout.kind == APT4:
            if not 0 < code < 0x100000:
                raise LayoutError(f"vocabulary code {code} is out of range")
            return self._pair.pack(0, code)
        if not 0 < code <= self._right:
            raise LayoutError(f"vocabulary code {code} does not fit a {self.word}-byte word")
        return self._unsigned.pack(code)

    def pack_int(self, value: int) -> bytes:
        """An integer item: the IBM integer of apt4, a left-half-zero word otherwise."""
        if self.layout.kind == APT4:
            if abs(value) > 0x7FFFFFFF:
                raise LayoutError(f"integer {value} does not fit 32 bits")
            return self._pair.pack(IBM_INTEGER | (SIGN_BIT if value < 0 else 0), abs(value))
        if not 0 <= value <= self._right:
            raise LayoutError(f"integer {value} does not fit a {self.word}-byte word")
        return self._unsigned.pack(value)

    def pack_chars(self, text: str) -> bytes:
        """One word of characters, blank-padded, first character most significant."""
        try:
            raw = text.ljust(self.word).encode("ascii")
        except UnicodeEncodeError:
            bad = next(c for c in text if ord(c) > 0x7E)
            raise LayoutError(f"character {bad!r} cannot be written (ASCII only)") from None
        if len(raw) > self.word:
            raise LayoutError(f"{text!r} does not fit a {self.word}-byte word")
        if self.order == ">":
            return raw
        if self.layout.kind == APT4:
            return raw[3::-1] + raw[7:3:-1]
        return raw[::-1]

    def pack_text(self, text: str, per_word: int, minimum_words: int = 0) -> bytes:
        chunks = [text[i : i + per_word] for i in range(0, len(text), per_word)] or [""]
        packed = b"".join(self.pack_chars(chunk) for chunk in chunks)
        missing = minimum_words - len(chunks)
        return packed + bytes(self.word * missing) if missing > 0 else packed


def _first_record_fits(layout: Layout, payload: bytes, length: int) -> bool:
    """Whether ``payload`` reads as a sound first record in ``layout``. Record numbers
    start at 1, so the zero high half of an 8-byte number, or an apt4 NWRDS word read as
    a record number, does not pass for another layout."""
    try:
        number, rtype, subtype = Codec(layout).header(payload, length)
    except (ValueError, struct.error):
        return False
    return rtype in RECORD_TYPES and 1 <= number < 1 << 31 and 0 <= subtype < 1 << 31
