"""Every tape, punch, listing and JSON line of the corpus and the example programs, on
eight machines, is byte-identical to what the commit before the streaming kernel wrote
(87acca5; tests/golden/outputs.json holds their SHA-256). A documented fix that changes an
output records the new outputs with ``python tests/golden/make_outputs.py`` and says so in
docs/decisions.md; to see a difference, record the old commit's outputs to another file
(``--commit 87acca5 -o old.json``) or post the case with both trees and diff the files."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from .golden.cases import ROOT, run_case

RECORDED = json.loads((Path(__file__).parent / "golden" / "outputs.json").read_text())


@pytest.mark.parametrize("case", sorted(RECORDED))
def test_outputs_are_as_recorded(case: str) -> None:
    expected = RECORDED[case]
    if not (ROOT / expected["input"]).exists():
        pytest.skip(f"{expected['input']} is not here (the shared corpus is beside the project)")
    found = run_case(expected["input"], expected["machine"])
    for key, value in found.items():
        assert value == expected[key], f"{case}: {key} differs from the recorded output"
