"""Round trips: text -> records -> binary -> records gives equal records, in every layout,
on the corpus and on generated programs; binary corpus files survive records -> binary."""

from __future__ import annotations

import io
import struct
from collections.abc import Iterator
from pathlib import Path

import pytest
from gecent.core.cl.apt_source import AptSourceReader, read_apt_source
from gecent.core.cl.binary_layout import (
    Codec,
    Layout,
    LayoutError,
    detect_layout,
    parse_layout,
)
from gecent.core.cl.binary_reader import read_binary
from gecent.core.cl.binary_writer import write_binary
from gecent.core.cl.records import Record
from gecent.core.cl.vocabulary import vocabulary
from gecent.core.errors import InputError
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from .conftest import SHARED

CORPUS = SHARED / "corpus"
FULL_LAYOUTS = ["apt4", "apt4-be", "manual8", "manual8-be"]
needs_corpus = pytest.mark.skipif(not CORPUS.is_dir(), reason="shared corpus not present")


def through_binary(records: list[Record], layout: Layout, tmp: Path) -> list[Record]:
    buffer = io.BytesIO()
    write_binary(records, buffer, layout)
    path = tmp / f"roundtrip-{layout.name}.cl"
    path.write_bytes(buffer.getvalue())
    assert detect_layout(buffer.getvalue()[:4096]) == layout
    return list(read_binary(str(path)))


@needs_corpus
@pytest.mark.parametrize("layout", FULL_LAYOUTS)
@pytest.mark.parametrize("name", ["creo/schruppen_1.ncl.1", "creo/bohren_1.ncl.8"])
def test_creo_text_round_trips_through_binary(name: str, layout: str, tmp_path: Path) -> None:
    records = list(read_apt_source(str(CORPUS / name)))
    assert through_binary(records, parse_layout(layout), tmp_path) == records


@needs_corpus
@pytest.mark.parametrize("layout", FULL_LAYOUTS)
@pytest.mark.parametrize("path", sorted((CORPUS / "apt4").glob("*.cl3")), ids=lambda p: p.stem)
def test_apt4_binary_round_trips(path: Path, layout: str, tmp_path: Path) -> None:
    records = list(read_binary(str(path)))
    assert through_binary(records, parse_layout(layout), tmp_path) == records


@needs_corpus
def test_apt4_writer_reproduces_the_records_apt_wrote() -> None:
    """Our apt4 writer puts each record's bytes exactly where APT IV put them (the type
    1000 records differ: APT IV writes two blank words, we one)."""
    original = (CORPUS / "apt4" / "test3_ppwords.cl3").read_bytes()
    records = list(read_binary(str(CORPUS / "apt4" / "test3_ppwords.cl3")))
    buffer = io.BytesIO()
    write_binary(records, buffer, parse_layout("apt4"))

    def payloads(data: bytes) -> Iterator[bytes]:
        offset = 0
        while offset < len(data):
            (length,) = struct.unpack_from("<i", data, offset)
            payload = data[offset + 4 : offset + 4 + length]
            if struct.unpack_from("<i", payload, 8)[0] != 1000:
                yield payload
            offset += length + 8

    ours, theirs = list(payloads(buffer.getvalue())), list(payloads(original))
    assert len(ours) == len(theirs) == 26
    for mine, apt in zip(ours, theirs, strict=True):
        if struct.unpack_from("<i", apt, 12)[0] == 1046:  # INSERT: APT leaves junk words
            assert mine[:40] == apt[:40]
        else:
            assert mine == apt


# --- generated programs -------------------------------------------------------------------

_VOCABULARY = vocabulary()
_APT4_TAKEN = set(_VOCABULARY.apt4_major.values())  # FLAME/CORNFD: APT IV writes LINTOL so
_MAJORS = sorted(
    name
    for name, code in _VOCABULARY.major.items()
    if code > 1000
    and code not in _APT4_TAKEN
    and name not in ("PARTNO", "PPRINT", "INSERT")
    and name.isalpha()
)
_MINORS = sorted(name for name in _VOCABULARY.minor if name.isalpha())
_TEXT = st.text(alphabet="ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789 .,-/()=", max_size=60).map(str.strip)
_NUMBER = st.floats(
    min_value=-1e6, max_value=1e6, allow_nan=False, allow_infinity=False, allow_subnormal=False
).map(lambda v: repr(round(v, 7)))
_POINT = st.lists(_NUMBER, min_size=3, max_size=3).map(", ".join)


@st.composite
def statements(draw: st.DrawFn) -> str:
    kind = draw(st.sampled_from(["goto", "from", "godlta", "circle", "pp", "text", "flag", "tol"]))
    if kind in ("goto", "from"):
        return f"{kind.upper()}/{draw(_POINT)}"
    if kind == "godlta":
        return f"GODLTA/{draw(st.one_of(_NUMBER, _POINT))}"
    if kind == "circle":
        values = draw(st.lists(_NUMBER, min_size=7, max_size=7))
        return "CIRCLE/" + ", ".join(values)
    if kind == "text":
        return f"{draw(st.sampled_from(['PARTNO', 'PPRINT', 'INSERT']))} {draw(_TEXT)}"
    if kind == "flag":
        return draw(
            st.sampled_from(
                [
                    *("RAPID", "END", "OPSTOP", "CUT", "DNTCUT", "3DCALC"),
                    *("UNITS/MM", "UNITS/INCHES", "CLPRNT", "CLPRNT/ON", "CLPRNT/OFF"),
                    "MULTAX/OFF",
                ]
            )
        )
    if kind == "tol":
        major = draw(st.sampled_from(["INTOL", "OUTTOL", "CUTTER"]))
        return f"{major}/" + ", ".join(draw(st.lists(_NUMBER, min_size=1, max_size=4)))
    args = draw(st.lists(st.one_of(_NUMBER, st.sampled_from(_MINORS)), max_size=8))
    major = draw(st.sampled_from(_MAJORS))
    return f"{major}/{', '.join(args)}" if args else major


@st.composite
def programs(draw: st.DrawFn) -> list[str]:
    lines = []
    for statement in draw(st.lists(statements(), min_size=1, max_size=25)):
        is_text = statement.split(" ")[0] in ("PARTNO", "PPRINT", "INSERT")
        if draw(st.booleans()) and "," in statement and not is_text:
            cut = statement.index(",") + 1
            lines += [statement[:cut] + " $", "   " + statement[cut:]]
        else:
            lines.append(statement)
        if draw(st.integers(0, 5)) == 0:
            lines.append("$$ " + draw(_TEXT))
    return [*lines, "FINI"]


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program=programs(), layout=st.sampled_from(FULL_LAYOUTS))
def test_generated_programs_round_trip(
    program: list[str], layout: str, tmp_path_factory: pytest.TempPathFactory
) -> None:
    records = list(AptSourceReader("generated.apt").read_lines(program))
    assert records and records[-1].line == len(program)
    tmp = tmp_path_factory.mktemp("gen")
    assert through_binary(records, parse_layout(layout), tmp) == records


_MANUAL4 = [Codec(parse_layout(f"manual4-{order}")) for order in ("le", "be")]


def _writable(value: float) -> bool:
    """The writer refuses the rare float whose bits would read back as a word."""
    try:
        for codec in _MANUAL4:
            codec.pack_float(value)
    except LayoutError:
        return False
    return True


_SINGLE = (  # exact in 32 bits
    st.integers(-(2**20), 2**20).map(lambda n: n / 64).filter(_writable).map(repr)
)


@st.composite
def single_precision_statements(draw: st.DrawFn) -> str:
    kind = draw(st.sampled_from(["goto", "pp", "text", "circle"]))
    if kind == "goto":
        return "GOTO/" + ", ".join(draw(st.lists(_SINGLE, min_size=3, max_size=3)))
    if kind == "circle":
        return "CIRCLE/" + ", ".join(draw(st.lists(_SINGLE, min_size=7, max_size=7)))
    if kind == "text":
        return f"PPRINT {draw(_TEXT)}"
    args = draw(st.lists(st.one_of(_SINGLE, st.sampled_from(_MINORS)), max_size=6))
    return f"{draw(st.sampled_from(_MAJORS))}/{', '.join(args)}" if args else "RAPID"


@settings(max_examples=60, deadline=None)
@given(
    body=st.lists(single_precision_statements(), min_size=1, max_size=15),
    order=st.sampled_from(["le", "be"]),
)
def test_manual4_round_trips_single_precision_programs(
    body: list[str], order: str, tmp_path_factory: pytest.TempPathFactory
) -> None:
    """4-byte words hold 32-bit floats, 4 characters of text per word and 4-character
    names: programs within those limits come back equal."""
    records = list(AptSourceReader("single.apt").read_lines([*body, "$$ note", "FINI"]))
    layout = parse_layout(f"manual4-{order}")
    assert through_binary(records, layout, tmp_path_factory.mktemp("m4")) == records


def test_writer_refuses_what_a_layout_cannot_hold() -> None:
    def write(lines: list[str], layout: str) -> str:
        records = list(AptSourceReader("limits.apt").read_lines(lines))
        with pytest.raises(InputError) as caught:
            write_binary(records, io.BytesIO(), parse_layout(layout))
        return str(caught.value)

    assert write(["MACHIN/UNCX01, 1"], "manual4").endswith(
        "cannot write statement to a manual4-le CL file: word UNCX01 has no vocabulary "
        "code and is longer than 3 characters"
    )
    assert "WIBBLE has no APT major-word code" in write(["WIBBLE/1"], "apt4")
    assert "CORNFD (code 1067) has no APT IV code" in write(["CORNFD"], "apt4")
    assert "1e+300 does not fit a 4-byte word" in write(["GOTO/1e300, 0, 0"], "manual4")
    assert "character 'ä' cannot be written" in write(["PPRINT Gehäuse"], "apt4")
    assert write(["UNITS/FURLONG"], "apt4").endswith("UNITS takes one of MM, CM, INCHES, FEET")
