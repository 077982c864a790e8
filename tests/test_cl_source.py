"""The APT source reader: words, numbers, continuations, comments, text and diagnostics."""

from __future__ import annotations

import pytest
from gecent.core.cl.apt_source import AptSourceReader
from gecent.core.cl.records import (
    Arelem,
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
from gecent.core.errors import InputError


def read(*lines: str) -> list[Record]:
    return list(AptSourceReader("part.apt").read_lines(lines))


def error(*lines: str) -> str:
    with pytest.raises(InputError) as caught:
        read(*lines)
    return str(caught.value)


@pytest.mark.parametrize(
    ("text", "value"),
    [("1.", 1.0), ("-.5", -0.5), ("+2", 2.0), ("1.5E-3", 0.0015), ("7", 7.0), ("2e2", 200.0)],
)
def test_number_spellings(text: str, value: float) -> None:
    (record,) = read(f"FEDRAT/{text}")
    assert isinstance(record, Statement)
    assert record.args == (value,) and isinstance(record.args[0], float)


def test_words_are_case_insensitive_and_keep_their_codes() -> None:
    (record,) = read("spindl / rpm, 1200, clw")
    assert isinstance(record, Statement)
    assert (record.major, record.code) == ("SPINDL", 1031)
    assert record.args == (Word("RPM", 78), 1200.0, Word("CLW", 60))
    assert [a.code for a in record.args if isinstance(a, Word)] == [78, 60]


def test_unknown_words_are_kept_without_a_code() -> None:
    (record,) = read("WIBBLE/FOO, 1")
    assert isinstance(record, Statement)
    assert (record.major, record.code) == ("WIBBLE", None)
    assert record.args == (Word("FOO", None), 1.0)


def test_shared_codes_make_equal_words() -> None:
    assert Word("MMPM", 171) == Word("PREHET", 171)
    assert Word("FOO", None) != Word("BAR", None)


def test_continuation_joins_lines_and_keeps_the_first_line() -> None:
    records = read("GOTO / 1.0, 2.0,  $", "       3.0", "FINI")
    assert records[0] == Motion("part.apt", 1, 1, MotionSubtype.GOTO, ((1.0, 2.0, 3.0),))
    assert isinstance(records[1], Fini) and records[1].line == 3


def test_comments_are_records_and_trailing_comments_follow_their_statement() -> None:
    records = read("$$ first", "RAPID $$ quick", "$$-> CSYS / 1, $", "   2")
    assert [type(r).__name__ for r in records] == ["Comment", "Statement", "Comment", "Comment"]
    assert isinstance(records[1], Comment | Statement)
    assert [r.text for r in records if isinstance(r, Comment)] == [
        "first",
        "quick",
        "-> CSYS / 1, 2",
    ]


def test_text_statements_keep_their_text_verbatim() -> None:
    records = read("PARTNO / MFG0004", "PPRINT  Mind the  CLAMP $", "INSERT N999 M00")
    assert [r.text for r in records if isinstance(r, Statement)] == [
        "MFG0004",
        "Mind the  CLAMP $",
        "N999 M00",
    ]


def test_record_words_become_their_record_types() -> None:
    records = read(
        "CIRCLE/1, 2, 3, 0, 0, 1, 5",
        "INTOL/0.001",
        "CUTTER/10, 2",
        "DNTCUT",
        "MULTAX/ON",
        "GOTO/1, 2, 3, 0, 0, 1",
        "GODLTA/-5",
        "FROM/0, 0, 100, 0, 0, 1",
    )
    assert records[0] == Circle("part.apt", 1, 1, (1.0, 2.0, 3.0, 0.0, 0.0, 1.0, 5.0))
    assert records[1] == Arelem("part.apt", 2, 2, 4, (0.001,))
    assert records[2] == Arelem("part.apt", 3, 3, 6, (10.0, 2.0))
    assert records[3] == Arelem("part.apt", 4, 4, 1, (1.0,))
    assert records[4] == Multiax("part.apt", 5, 5, True)
    assert isinstance(records[5], Motion) and records[5].points == ((1.0, 2.0, 3.0, 0.0, 0.0, 1.0),)
    assert isinstance(records[6], Motion) and records[6].subtype is MotionSubtype.GODLTA


@pytest.mark.parametrize(
    ("lines", "message"),
    [
        (["GOTO/1, 2"], "part.apt:1:1: error: GOTO takes 3 or 6 values, found 2"),
        (["FEDRAT/10,,IPM"], "part.apt:1:11: error: expected a value before ','"),
        (["FEDRAT/10 20"], "part.apt:1:11: error: expected ',' between values"),
        (["FEDRAT/10,"], "part.apt:1:11: error: expected a value after ','"),
        (["FEDRAT 10"], "part.apt:1:8: error: expected '/' after FEDRAT, found '10'"),
        (["P1=POINT/1,2,3"], "part.apt:1:3: error: an assignment is APT part-program geometry"),
        (["GOTO/1, 2, $", "   #"], "part.apt:2:4: error: expected a number or a word, found '#'"),
        (["%"], "part.apt:1:1: error: expected a statement word, found '%'"),
        (["MULTAX/SOMETIMES"], "part.apt:1:1: error: MULTAX takes ON or OFF"),
        (["CIRCLE/1,2,3"], "part.apt:1:1: error: CIRCLE takes 6 or 7 or 11 values, found 3"),
        (["GOTO/1, X, 3"], "part.apt:1:1: error: GOTO takes numbers only, found 1.0, X, 3.0"),
    ],
)
def test_malformed_statements_name_line_column_and_expectation(
    lines: list[str], message: str
) -> None:
    assert error(*lines).startswith(message)


def test_multax_takes_three_or_six_values() -> None:
    """NCL writes FROM/x,y,z under MULTAX/ON (no tool axis): three values are read as
    they are; other counts are refused."""
    assert error("MULTAX/ON", "GOTO/1, 2, 3, 4").startswith(
        "part.apt:2:1: error: GOTO takes 3 or 6 values, found 4"
    )
