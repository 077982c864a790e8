"""The stream API (look-ahead, streaming), the binary layouts and ``gecent cl``."""

from __future__ import annotations

import io
import json
import struct
import tracemalloc
from collections import deque
from collections.abc import Iterator
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cl.apt_source import AptSourceReader, read_apt_source
from gecent.core.cl.binary_layout import Codec, Layout, LayoutError, detect_layout, parse_layout
from gecent.core.cl.binary_reader import read_binary
from gecent.core.cl.binary_writer import write_binary
from gecent.core.cl.records import Circle, Motion, Record, Statement
from gecent.core.cl.stream import Lookahead
from gecent.core.cli import main
from gecent.core.errors import InputError

from .conftest import SHARED

APT4 = SHARED / "corpus" / "apt4"
PROGRAM = ["PARTNO DEMO", "RAPID", "GOTO/0, 0, 5", "CIRCLE/0,0,0,0,0,1,5", "GOTO/5, 0, 0", "FINI"]


def records() -> list[Record]:
    return list(AptSourceReader("demo.apt").read_lines(PROGRAM))


def test_lookahead_peeks_without_consuming() -> None:
    stream = Lookahead(records())
    assert isinstance(stream.peek(), Statement) and stream.peek().major == "PARTNO"  # type: ignore[union-attr]
    assert isinstance(stream.peek(4), Circle)
    assert next(stream).number == 1
    assert stream.peek(3) is not None and stream.peek(3).number == 4  # type: ignore[union-attr]
    circle = stream.find(lambda r: isinstance(r, Circle))
    assert circle is not None and circle.number == 4
    assert stream.find(lambda r: isinstance(r, Circle), limit=1) is None
    assert [r.number for r in stream] == [2, 3, 4, 5, 6]
    assert stream.peek() is None
    with pytest.raises(ValueError):
        stream.peek(0)


def test_lookahead_buffers_only_what_was_peeked() -> None:
    def endless() -> Iterator[Record]:
        number = 0
        while True:
            number += 1
            yield from AptSourceReader("loop.apt").read_lines([f"GOTO/{number}, 0, 0"])

    stream = Lookahead(endless())
    assert stream.peek(50) is not None
    assert len(stream._buffer) == 50
    for _ in range(60):
        next(stream)
    assert len(stream._buffer) == 0


def test_readers_stream_in_constant_memory(tmp_path: Path) -> None:
    """Reading 20 times more lines does not hold 20 times more memory."""

    def peak(lines: int) -> int:
        path = tmp_path / f"long{lines}.apt"
        path.write_text("".join(f"GOTO/{i}.5, 1.25, -3\n" for i in range(lines)) + "FINI\n")
        binary = tmp_path / f"long{lines}.cl"
        with binary.open("wb") as out:
            write_binary(read_apt_source(str(path)), out, parse_layout("apt4"))
        tracemalloc.start()
        deque(read_apt_source(str(path)), maxlen=0)  # stream every record, keep none
        deque(read_binary(str(binary)), maxlen=0)
        peak = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        return peak

    small, large = peak(2_000), peak(40_000)
    assert large < 2 * small + 200_000


@pytest.mark.parametrize(
    "name", ["apt4", "apt4-be", "manual4", "manual4-be", "manual8", "manual8-be"]
)
def test_every_layout_is_detected_from_its_first_record(name: str) -> None:
    layout = parse_layout(name)
    buffer = io.BytesIO()
    write_binary(records(), buffer, layout)
    assert detect_layout(buffer.getvalue()) == layout
    assert layout.name == (name if "-" in name else f"{name}-le")


def test_layout_names_are_checked() -> None:
    with pytest.raises(LayoutError, match="unknown binary CL layout 'manual6'"):
        parse_layout("manual6")
    with pytest.raises(LayoutError, match="unknown byte order 'xe'"):
        parse_layout("apt4-xe")
    with pytest.raises(LayoutError):
        Layout("apt4", "<", 4)


def _corrupt(tmp_path: Path, change: int, value: bytes) -> str:
    data = bytearray((APT4 / "test1.cl3").read_bytes())
    data[change : change + len(value)] = value
    path = tmp_path / "bad.cl3"
    path.write_bytes(bytes(data))
    with pytest.raises(InputError) as caught:
        list(read_binary(str(path), parse_layout("apt4")))
    return str(caught.value).removeprefix(str(path))


@pytest.mark.skipif(not APT4.is_dir(), reason="shared corpus not present")
def test_corrupt_binary_records_name_offset_and_record(tmp_path: Path) -> None:
    # record 2 (PARTNO) starts at byte 40; its payload at 44: NWRDS, number, type, subtype
    assert _corrupt(tmp_path, 44, struct.pack("<i", 99)) == (
        ": byte 40 (record 2): error: corrupt record header: NWRDS says 99 words but the "
        "record holds 25"
    )
    assert _corrupt(tmp_path, 52, struct.pack("<i", 2500)) == (
        ": byte 40 (record 2): error: corrupt record header: type 2500 is not valid "
        "(types 1000, 2000, ..., 14000; numbers 0..2**31-1)"
    )
    assert _corrupt(tmp_path, 148, struct.pack("<i", 96)) == (
        ": byte 40 (record 2): error: corrupt record: leading length 104 but trailing length 96"
    )
    # the FROM record starts at byte 344; its surface name is the slot at payload byte 16
    assert _corrupt(tmp_path, 344 + 4 + 16, b"\x01") == (
        ": byte 344 (record 8, ISN 4): error: corrupt type 5000 record: text word 1 holds "
        "the non-character byte 0x01"
    )


def run(*args: str) -> tuple[int, str, str]:
    result = CliRunner().invoke(main, list(args))
    return result.exit_code, result.stdout, result.stderr


@pytest.mark.skipif(not APT4.is_dir(), reason="shared corpus not present")
def test_cl_command_prints_a_cl_print() -> None:
    code, out, _ = run("cl", str(APT4 / "test3_ppwords.cl3"))
    assert code == 0
    lines = out.splitlines()
    assert lines[0] == "TAPENO/  ISN"
    assert lines[1] == "     2/    1  PARTNO   TEST3 PP WORDS"
    assert "    10/    7  SPINDL/  1200.0000, CLW   " in lines
    assert "    20/   12  GOTO  / NONAME(   0)" in lines
    assert lines[lines.index("    20/   12  GOTO  / NONAME(   0)") + 1].split() == [
        "1.0000000",
        "1.0000000",
        "0.1000000",
    ]
    assert lines[-1] == "    52/   28  FINI"


@pytest.mark.skipif(not APT4.is_dir(), reason="shared corpus not present")
def test_cl_command_json_lines() -> None:
    code, out, _ = run("cl", str(APT4 / "test3_ppwords.cl3"), "--json")
    assert code == 0
    rows = [json.loads(line) for line in out.splitlines()]
    assert rows[4] == {
        "line": 7,
        "record": 10,
        "type": 2000,
        "subtype": 1031,
        "major": "SPINDL",
        "code": 1031,
        "args": [1200.0, "CLW"],
    }
    assert rows[9] == {
        "line": 12,
        "record": 20,
        "type": 5000,
        "subtype": 5,
        "major": "GOTO",
        "name": "NONAME",
        "subscript": 0,
        "points": [[1.0, 1.0, 0.1]],
    }
    assert rows[-1] == {"line": 28, "record": 52, "type": 14000, "major": "FINI"}


def test_cl_command_converts_text_to_binary_and_back(tmp_path: Path) -> None:
    source = tmp_path / "demo.apt"
    source.write_text("\n".join(PROGRAM) + "\n")
    binary = tmp_path / "demo.cl"
    assert run("cl", str(source), "--to", "manual8-be", "-o", str(binary))[0] == 0
    assert detect_layout(binary.read_bytes()) == parse_layout("manual8-be")
    _, text_rows, _ = run("cl", str(source), "--json")
    _, binary_rows, _ = run("cl", str(binary), "--json")
    assert binary_rows == text_rows
    assert isinstance(list(read_binary(str(binary)))[3], Circle)
    assert isinstance(list(read_binary(str(binary)))[2], Motion)


def test_cl_command_errors_exit_2(tmp_path: Path) -> None:
    bad = tmp_path / "bad.apt"
    bad.write_text("GOTO/1, 2, 3\nFEDRAT/10,,IPM\n")
    code, _, err = run("cl", str(bad))
    assert code == 2
    assert err.strip() == f"{bad}:2:11: error: expected a value before ','"
    code, _, err = run("cl", str(bad), "--to", "apt4")
    assert (code, err.strip()) == (2, "error: --to needs -o FILE for the binary CL file")
    code, _, err = run("cl", str(bad), "--layout", "manual9")
    assert code == 2 and "unknown binary CL layout 'manual9'" in err
    out = tmp_path / "out.cl"
    code, _, err = run("cl", str(bad), "--to", "apt4", "-o", str(out))
    assert code == 2 and not out.exists()


def test_storge_left_half_zero_is_an_integer() -> None:
    """Worked example W23 (001 L2770-2790): the double word 00000000 00000004 has a zero
    left half, so it is the integer 4; any non-zero left half makes a floating number."""
    codec = Codec(parse_layout("manual8-be"))
    assert codec.tag(bytes.fromhex("0000000000000004"), 0) == ("code", 4)
    assert codec.tag(bytes.fromhex("3ff0000000000000"), 0) == ("", 0)
    assert codec.floats(bytes.fromhex("3ff0000000000000"), 0, 1) == (1.0,)
    assert codec.integer(bytes.fromhex("0000000000000004"), 0) == 4
