"""core/tomldata.py: TOML parsed once, cached on disk, and never trusted blindly."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest
from gecent.core import tomldata

TEXT = '[machine]\nname = "cached"\nnumber = 7\n[optab]\n4 = 9.9999\n'


@pytest.fixture
def cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.setenv("GECENT_CACHE_DIR", str(tmp_path))
    monkeypatch.setattr(tomldata, "_MEMORY", {})
    return tmp_path / "toml"


def test_a_parse_is_cached_and_read_back(cache: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    assert tomldata.loads(TEXT) == tomllib.loads(TEXT)
    [stored] = list(cache.iterdir())
    monkeypatch.setattr(tomldata, "_MEMORY", {})
    monkeypatch.setattr(tomllib, "loads", lambda text: pytest.fail("parsed again"))
    expected = {"machine": {"name": "cached", "number": 7}, "optab": {"4": 9.9999}}
    assert tomldata.loads(TEXT) == expected
    assert stored.exists()


def test_a_damaged_cache_file_is_passed_over(cache: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    tomldata.loads(TEXT)
    [stored] = list(cache.iterdir())
    stored.write_bytes(b"gecent-toml-1\n\x00garbage")
    monkeypatch.setattr(tomldata, "_MEMORY", {})
    assert tomldata.loads(TEXT) == tomllib.loads(TEXT)
    stored.write_bytes(b"somebody else's file")
    monkeypatch.setattr(tomldata, "_MEMORY", {})
    assert tomldata.loads(TEXT) == tomllib.loads(TEXT)


def test_an_empty_cache_setting_turns_the_disk_cache_off(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("GECENT_CACHE_DIR", "")
    monkeypatch.setattr(tomldata, "_MEMORY", {})
    assert tomldata.cache_folder() is None
    assert tomldata.loads(TEXT)["machine"]["number"] == 7


def test_bad_toml_is_still_reported(cache: Path) -> None:
    with pytest.raises(tomllib.TOMLDecodeError):
        tomldata.loads("[machine\n")
