"""Bad input in a CAM dialect never finds a traceback: the vendor files with lines
dropped, doubled, cut or changed post, or stop with a named error (exit 2 or 3), and
write no tape when they stop."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from .conftest import SHARED

DATA = Path(__file__).resolve().parent / "data"
EXAMPLES = int(os.environ.get("GECENT_FUZZ_EXAMPLES", "25"))
SOURCES = [
    DATA / "dialect_catia.aptsource",
    DATA / "dialect_mastercam.apt",
    DATA / "dialect_fusion.apt",
]
if (SHARED / "corpus" / "dialects.md").is_file():
    import re

    _blocks = re.findall(
        r"```\n(.*?)```", (SHARED / "corpus" / "dialects.md").read_text(encoding="utf-8"), re.S
    )
    SOURCES_TEXT = {f"dialects.md[{i}]": block for i, block in enumerate(_blocks)}
else:
    SOURCES_TEXT = {}
SOURCES_TEXT.update({path.name: path.read_text(encoding="latin-1") for path in SOURCES})

SNIPPETS = st.sampled_from(
    ["", ",", "/", "(", ")", "$", "$$", "1e400", "-0", "NAN", "CIRCLE/", "GOFWD/", "(CIRCLE/ 1,2",
     "KNOT/1,0", "CNTRL/1,2", "NURBS/", "CSYS/1,0,0,0,0,1,0,0,0,0,1", "INDIRV/0,0,0",
     "FEDTO", "1STPECK", "TOOL PATH/", "END-OF-PATH", "LOAD/TOOL", "MOVARC/1,2,3",
     "'", "PARTNO/'", "REMARK", "TPRINT/", "CHANNEL,", "LOADTL/1,0,50"]
)  # fmt: skip


@st.composite
def mutated(draw: st.DrawFn) -> tuple[str, str]:
    name = draw(st.sampled_from(sorted(SOURCES_TEXT)))
    lines = SOURCES_TEXT[name].splitlines(keepends=True)
    for _ in range(draw(st.integers(1, 3))):
        if not lines:
            break
        index = draw(st.integers(0, len(lines) - 1))
        action = draw(st.sampled_from(["drop", "double", "cut", "insert", "replace"]))
        line = lines[index]
        if action == "drop":
            del lines[index]
        elif action == "double":
            lines.insert(index, line)
        elif action == "cut":
            lines[index] = line[: draw(st.integers(0, max(0, len(line) - 1)))] + "\n"
        else:
            at = draw(st.integers(0, len(line)))
            snippet = draw(SNIPPETS)
            cut = at if action == "insert" else min(len(line), at + 4)
            lines[index] = line[:at] + snippet + line[cut:]
    return name, "".join(lines)


@pytest.mark.skipif(not SOURCES_TEXT, reason="no dialect sources")
@settings(
    max_examples=EXAMPLES,
    derandomize=True,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture],
)
@given(case=mutated())
def test_a_mutated_vendor_file_posts_or_stops_by_name(
    case: tuple[str, str], tmp_path_factory: pytest.TempPathFactory
) -> None:
    name, text = case
    folder = tmp_path_factory.mktemp("fuzz")
    source = folder / ("part" + (Path(name).suffix or ".cl"))
    source.write_text(text, encoding="latin-1")
    tape = folder / "part.ngc"
    done = CliRunner().invoke(
        main, ["post", str(source), "--machine", "linuxcnc-mill", "-o", str(tape)]
    )
    assert done.exit_code in (0, 2, 3), f"{name}: exit {done.exit_code}\n{done.output}\n{text}"
    if done.exit_code != 0:
        assert not tape.exists()
        assert "part" in done.output  # the error names the file (and its line)
