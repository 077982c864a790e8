"""APT vocabulary: major (postprocessor statement) and minor word codes (manual §3.3.2.1-2).

The codes are package data (``data/vocabulary.toml``) with the source of every code.
A word the vocabulary lacks is still a word: readers keep it with ``code = None``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from importlib import resources

from gecent.core import tomldata
from gecent.core.cl.records import Word


@dataclass(frozen=True)
class Vocabulary:
    major: dict[str, int]
    minor: dict[str, int]
    record_words: dict[str, int]
    major_names: dict[int, str]
    minor_names: dict[int, str]
    record_subtype: dict[str, int]
    units_value: dict[str, int]
    apt4_major: dict[str, int]
    gecent_majors: frozenset[str] = frozenset()

    def major_code(self, name: str) -> int | None:
        return self.major.get(name)

    def minor_code(self, name: str) -> int | None:
        return self.minor.get(name)

    def major_name(self, code: int) -> str:
        """The preferred name of a major code; ``#code`` for a code the vocabulary lacks."""
        return self.major_names.get(code, f"#{code}")

    def minor_word(self, code: int) -> Word:
        return Word(self.minor_names.get(code, f"#{code}"), code)


@cache
def vocabulary() -> Vocabulary:
    raw = resources.files("gecent.core.cl").joinpath("data", "vocabulary.toml").read_bytes()
    data = tomldata.loads(raw.decode("utf-8"))
    major = {str(k): int(v) for k, v in data["major"].items()}
    minor = {str(k): int(v) for k, v in data["minor"].items()}
    record_words = {str(k): int(v) for k, v in data.get("record_words", {}).items()}
    major_names: dict[int, str] = {}
    for name, code in major.items():
        major_names.setdefault(code, name)
    minor_names: dict[int, str] = {}
    for name, code in minor.items():
        minor_names.setdefault(code, name)
    return Vocabulary(
        major,
        minor,
        record_words,
        major_names,
        minor_names,
        {str(k): int(v) for k, v in data.get("record_subtype", {}).items()},
        {str(k): int(v) for k, v in data.get("units_value", {}).items()},
        {str(k): int(v) for k, v in data.get("major_apt4", {}).items()},
        frozenset(str(w) for w in data.get("gecent_major", {}).get("words", ())),
    )
