"""Damaged CL files: inserted, deleted and flipped bytes and truncation give the project's
input error (file, position, what was expected) or a clean read, never anything else."""

from __future__ import annotations

from collections import deque
from pathlib import Path

import pytest
from gecent.core.cl.stream import read_cl
from gecent.core.errors import InputError
from gecent.core.plugins import PluginSet, get_plugins
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from .conftest import SHARED

CORPUS = SHARED / "corpus"
SOURCES = (
    [
        *sorted((CORPUS / "apt4").glob("*.cl3")),
        CORPUS / "creo" / "bohren_1.ncl.8",
        CORPUS / "creo" / "schruppen_1.ncl.1",
    ]
    if CORPUS.is_dir()
    else []
)
# the roughing file is cut to its first 6000 bytes to keep each example fast
SAMPLES = {path.name: path.read_bytes()[:6000] for path in SOURCES}

pytestmark = pytest.mark.skipif(not SAMPLES, reason="shared corpus not present")


@st.composite
def damaged(draw: st.DrawFn) -> tuple[str, bytes]:
    name = draw(st.sampled_from(sorted(SAMPLES)))
    data = bytearray(SAMPLES[name])
    for _ in range(draw(st.integers(1, 4))):
        kind = draw(st.sampled_from(["insert", "delete", "flip", "truncate", "overwrite"]))
        at = draw(st.integers(0, max(len(data) - 1, 0)))
        if kind == "insert":
            data[at:at] = draw(st.binary(min_size=1, max_size=8))
        elif kind == "delete":
            del data[at : at + draw(st.integers(1, 8))]
        elif kind == "flip" and data:
            data[at] ^= 1 << draw(st.integers(0, 7))
        elif kind == "truncate":
            del data[at:]
        elif kind == "overwrite" and data:
            data[at] = draw(st.integers(0, 255))
    return name, bytes(data)


def _read_everything(path: Path, plugins: PluginSet) -> None:
    try:
        deque(read_cl(str(path), plugins), maxlen=0)  # read every record, keep none
    except InputError as exc:
        text = str(exc)
        assert text.startswith(str(path)), text
        assert ": error: " in text


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(case=damaged())
def test_damaged_files_give_input_errors_only(
    case: tuple[str, bytes], tmp_path_factory: pytest.TempPathFactory
) -> None:
    name, data = case
    path = tmp_path_factory.mktemp("fuzz") / name
    path.write_bytes(data)
    _read_everything(path, get_plugins())


@settings(max_examples=200, deadline=None)
@given(data=st.binary(max_size=300))
def test_random_bytes_give_input_errors_only(
    data: bytes, tmp_path_factory: pytest.TempPathFactory
) -> None:
    path = tmp_path_factory.mktemp("noise") / "noise.cl"
    path.write_bytes(data)
    _read_everything(path, get_plugins())


@pytest.mark.parametrize("cut", [20, 30, 100, 957])
def test_truncated_binary_names_offset_and_record(cut: int, tmp_path: Path) -> None:
    path = tmp_path / "cut.cl3"
    path.write_bytes((CORPUS / "apt4" / "test1.cl3").read_bytes()[:cut])
    with pytest.raises(InputError) as caught:
        list(read_cl(str(path), get_plugins()))
    message = str(caught.value)
    assert message.startswith(f"{path}: byte ") and "(record " in message
    assert "truncated record" in message


@pytest.mark.parametrize("cut", [3, 10])
def test_file_cut_before_a_header_is_not_recognised(cut: int, tmp_path: Path) -> None:
    path = tmp_path / "cut.cl3"
    path.write_bytes((CORPUS / "apt4" / "test1.cl3").read_bytes()[:cut])
    with pytest.raises(InputError, match="no CL reader recognises this file"):
        list(read_cl(str(path), get_plugins()))


def test_empty_file_is_an_input_error(tmp_path: Path) -> None:
    path = tmp_path / "empty.cl"
    path.write_bytes(b"")
    with pytest.raises(InputError, match="empty CL file"):
        list(read_cl(str(path), get_plugins()))
