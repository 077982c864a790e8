"""The syntax definition line (SDL) of a user-defined macro, and matching a record against it
(spec 09 §6.2-§6.7, seed 002 L1133-1350).

::

    sdl   := major [ "/" arg ("," arg)* ]           required items first, then options
    major := NAME | "#" (INT | "*") ":" (INT | "*")
    arg   := item | "[" item ("," item)* "]"       an option: matches as a unit or not at all
    item  := "$P" N [ "()" | "(" kws ")" | "''" | "?" | "*" ]
           | NAME | "(" [kws] ")" | "''" | "?" | "*"

A bare ``$Pn`` matches a number, ``()`` any keyword, ``(K1,K2)`` one of the keywords, ``''``
a string, ``?`` any one argument and ``*`` everything left (a tuple, empty when nothing is
left). An SDL is parsed once, when its macro is registered; a malformed one is refused with
the column of the fault.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from enum import Enum

from gecent.core.cl.records import (
    Arelem,
    Circle,
    Fini,
    Motion,
    Multiax,
    Other,
    PartText,
    Record,
    Statement,
    Surface,
    Word,
)
from gecent.core.cl.vocabulary import vocabulary

STATEMENT_CLASS = 2000
ANY = "*"
Key = tuple[int, int | str]  # (class, subclass): the subclass of an unknown word is its name


class SdlError(ValueError):
    """A syntax definition line that cannot be parsed (column counted from 1)."""

    def __init__(self, sdl: str, column: int, message: str) -> None:
        super().__init__(f"SDL {sdl!r}, column {column}: {message}")


class Form(Enum):
    NUMBER = "number"
    KEYWORD = "keyword"  # one of ``words``, or any keyword when ``words`` is empty
    STRING = "string"
    ANY_ONE = "?"
    REST = "*"


@dataclass(frozen=True)
class Item:
    form: Form
    words: tuple[Word, ...] = ()
    param: int | None = None  # n of $Pn; None when the item does not capture

    def accepts(self, value: object) -> bool:
        form = self.form
        if form is Form.NUMBER:
            return isinstance(value, int | float) and not isinstance(value, bool)
        if form is Form.KEYWORD:
            return isinstance(value, Word) and (not self.words or value in self.words)
        if form is Form.STRING:
            return isinstance(value, str)
        return True  # ANY_ONE (REST is handled by the sequence matcher)


@dataclass(frozen=True)
class Sdl:
    text: str
    major: tuple[int | str, int | str]  # (class or "*", subclass or "*")
    required: tuple[Item, ...] = ()
    options: tuple[tuple[Item, ...], ...] = ()
    params: tuple[int, ...] = field(default=())  # every $Pn the SDL names, in order
    # no "/": the major alone, whatever the arguments (#*:* "matches any record", §6.2)
    bare: bool = False

    @property
    def level(self) -> int:
        """The search order of §6.2: #*:* (0), #class:* (1), #*:subclass (2), exact (3)."""
        cls, sub = self.major
        if cls == ANY and sub == ANY:
            return 0
        if sub == ANY:
            return 1
        if cls == ANY:
            return 2
        return 3

    def covers(self, key: Key) -> bool:
        cls, sub = self.major
        return (cls == ANY or cls == key[0]) and (sub == ANY or sub == key[1])

    def match(self, record: Record) -> dict[int, object] | None:
        """The $P values when the record matches (None for an option that did not), else
        None. Leftover arguments that no unused option takes mean no match (Q12)."""
        key = record_key(record)
        if key is None or not self.covers(key):
            return None
        if self.bare:
            return {}
        args = record_arguments(record)
        values: dict[int, object] = dict.fromkeys(self.params)
        at = _match_sequence(self.required, args, 0, values)
        if at is None:
            return None
        unused = list(self.options)
        while at < len(args):
            for option in unused:
                trial = dict(values)
                end = _match_sequence(option, args, at, trial)
                if end is not None and end > at:
                    values = trial
                    unused.remove(option)
                    at = end
                    break
            else:
                return None
        return values


def _match_sequence(
    items: tuple[Item, ...], args: tuple[object, ...], at: int, values: dict[int, object]
) -> int | None:
    for item in items:
        if item.form is Form.REST:
            if item.param is not None:
                values[item.param] = tuple(args[at:])
            at = len(args)
            continue
        if at >= len(args) or not item.accepts(args[at]):
            return None
        if item.param is not None:
            values[item.param] = args[at]
        at += 1
    return at


def record_key(record: Record) -> Key | None:
    """A record's (class, subclass) as an SDL major sees it; comments have none."""
    if type(record) is Motion:
        return (5000, int(record.subtype))
    if isinstance(record, Statement):
        return (STATEMENT_CLASS, record.code if record.code is not None else record.major)
    if isinstance(record, Circle):
        return (3000, 4)
    if isinstance(record, Surface):
        return (3000, record.surface_type)
    if isinstance(record, Arelem):
        return (6000, record.subtype)
    if isinstance(record, Multiax):
        return (9000, 2 if record.on else 0)
    if isinstance(record, Fini):
        return (14000, 0)
    if isinstance(record, PartText):
        return (1000, 0)
    if isinstance(record, Other):
        return (record.record_type, record.subtype)
    return None


def record_arguments(record: Record) -> tuple[object, ...]:
    """The items an SDL's arguments are matched against: a statement's words and numbers
    (its text as one string), the values of a motion's points, a circle's canonical form."""
    if isinstance(record, Statement):
        return record.args if record.text is None else (*record.args, record.text)
    if isinstance(record, Motion):
        return tuple(value for point in record.points for value in point)
    if isinstance(record, Circle | Surface | Arelem):
        return tuple(record.values)
    if isinstance(record, Other):
        return record.items
    return ()


_NAME = re.compile(r"[A-Za-z0-9][A-Za-z0-9_-]*")
_CLASS = re.compile(r"#\s*(\*|\d+)\s*:\s*(\*|\d+|[A-Za-z][A-Za-z0-9_]*)")
_PARAM = re.compile(r"\$P(\d+)", re.IGNORECASE)


class _Parser:
    def __init__(self, text: str) -> None:
        self.text = text
        self.at = 0
        self.params: list[int] = []

    def fail(self, message: str) -> SdlError:
        return SdlError(self.text, self.at + 1, message)

    def blank(self) -> None:
        while self.at < len(self.text) and self.text[self.at] in " \t":
            self.at += 1

    def peek(self) -> str:
        self.blank()
        return self.text[self.at] if self.at < len(self.text) else ""

    def take(self, char: str) -> bool:
        if self.peek() == char:
            self.at += 1
            return True
        return False

    def parse(self) -> Sdl:
        major = self.major()
        required: list[Item] = []
        options: list[tuple[Item, ...]] = []
        bare = not self.take("/")
        if not bare:
            while True:
                if self.peek() == "[":
                    self.at += 1
                    items = [self.item()]
                    while self.take(","):
                        items.append(self.item())
                    if not self.take("]"):
                        raise self.fail("expected ']' to close the option")
                    options.append(tuple(items))
                else:
                    if options:
                        raise self.fail("a required argument after an option")
                    required.append(self.item())
                if not self.take(","):
                    break
        if self.peek():
            raise self.fail(f"unexpected {self.text[self.at :][:10]!r}")
        for index, item in enumerate(required):
            if item.form is Form.REST and (index != len(required) - 1 or options):
                raise SdlError(self.text, 1, "'*' may only be the last argument (Q14)")
        for option in options:
            if any(item.form is Form.REST for item in option[:-1]):
                raise SdlError(self.text, 1, "'*' may only end an option")
        return Sdl(self.text, major, tuple(required), tuple(options), tuple(self.params), bare)

    def major(self) -> tuple[int | str, int | str]:
        self.blank()
        found = _CLASS.match(self.text, self.at)
        if found is not None:
            self.at = found.end()
            cls_text, sub_text = found.groups()
            cls: int | str = ANY if cls_text == ANY else int(cls_text)
            sub: int | str
            if sub_text == ANY:
                sub = ANY
            elif sub_text.isdigit():
                sub = int(sub_text)
            else:
                sub = sub_text.upper()
            return cls, sub
        found = _NAME.match(self.text, self.at)
        if found is None:
            raise self.fail("expected a major word or #class:subclass")
        self.at = found.end()
        return major_key(found.group(0).upper())

    def item(self) -> Item:
        self.blank()
        param = None
        found = _PARAM.match(self.text, self.at)
        if found is not None:
            param = int(found.group(1))
            if not 1 <= param <= 99:
                raise self.fail("$P numbers run from 1 to 99")
            if param in self.params:
                raise self.fail(f"$P{param} is named twice")
            self.params.append(param)
            self.at = found.end()
            if self.at >= len(self.text) or self.text[self.at] not in "(?*'":
                return Item(Form.NUMBER, param=param)
        char = self.text[self.at] if self.at < len(self.text) else ""
        if char == "(":
            self.at += 1
            words: list[Word] = []
            if not self.take(")"):
                words.append(self.word())
                while self.take(","):
                    words.append(self.word())
                if not self.take(")"):
                    raise self.fail("expected ')' to close the keyword list")
            return Item(Form.KEYWORD, tuple(words), param)
        if self.text.startswith("''", self.at):
            self.at += 2
            return Item(Form.STRING, param=param)
        if char == "?":
            self.at += 1
            return Item(Form.ANY_ONE, param=param)
        if char == "*":
            self.at += 1
            return Item(Form.REST, param=param)
        return Item(Form.KEYWORD, (self.word(),))

    def word(self) -> Word:
        self.blank()
        found = _NAME.match(self.text, self.at)
        if found is None:
            raise self.fail("expected a keyword")
        self.at = found.end()
        name = found.group(0).upper()
        return Word(name, vocabulary().minor_code(name))


def major_key(name: str) -> tuple[int, int | str]:
    """A major word's (class, subclass): motion words are class 5000, FINI 14000, the
    circle 3000:4, every other word a postprocessor statement (known or not)."""
    motion = {"FROM": 3, "GODLTA": 4, "GOTO": 5}
    if name in motion:
        return (5000, motion[name])
    if name == "FINI":
        return (14000, 0)
    if name == "CIRCLE":
        return (3000, 4)
    code = vocabulary().major_code(name)
    return (STATEMENT_CLASS, code if code is not None else name)


def parse_sdl(text: str) -> Sdl:
    if not text.strip():
        raise SdlError(text, 1, "an empty SDL")
    return _Parser(text).parse()
