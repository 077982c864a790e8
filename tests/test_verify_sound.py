"""`gecent verify` cannot be fooled (issue 16): rs274 gets a tool table of every tool the
tape names (so T4..T99 load and G41/G42/G43 leave the programmed path alone), and a CL file
with motion the post does not follow (NURBS) fails."""

from __future__ import annotations

import shutil
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from gecent.core.plugins import PluginSet
from gecent.core.verify.check import verify
from gecent.core.verify.rs274 import tool_numbers, tool_table

needs_rs274 = pytest.mark.skipif(
    shutil.which("rs274") is None,
    reason="rs274 (LinuxCNC's interpreter, Debian package linuxcnc-uspace) is not installed",
)


def test_tool_numbers_come_from_t_d_and_h_words() -> None:
    tape = "%\n(T99 IN A COMMENT)\nN1 T04 M06\nN2 G43 H4 Z5.\nN3 G41 D17 X1.\nN4T0101\n%\n"
    assert tool_numbers(tape) == (4, 17, 101)
    assert tool_table((4, 17)) == "T4 P4 D0 Z0 ;gecent verify\nT17 P17 D0 Z0 ;gecent verify\n"


def tools_program(tools: range) -> str:
    lines = ["PARTNO TOOLS", "UNITS/MM", "FROM/0,0,50"]
    for tool in tools:
        x = float(tool)
        lines += [
            "CUTTER/6",
            f"LOADTL/{tool}",
            "SPINDL/RPM,2000,CLW",
            "RAPID",
            f"GOTO/{x},0,5",
            "FEDRAT/400,MMPM",
            "CUTCOM/LEFT",
            f"GOTO/{x},0,-1",
            f"GOTO/{x + 0.5},10,-1",
            "CUTCOM/OFF",
            "RAPID",
            f"GOTO/{x + 0.5},10,50",
        ]
    return "\n".join([*lines, "FINI", ""])


@needs_rs274
@pytest.mark.parametrize("machine", ["linuxcnc-mill", "fanuc-mill"])
def test_tools_1_to_99_with_cutcom_verify(plugins: PluginSet, tmp_path: Path, machine: str) -> None:
    source = tmp_path / "tools.apt"
    source.write_text(tools_program(range(1, 100)))
    tape = tmp_path / "tools.ngc"
    result = CliRunner().invoke(main, ["post", str(source), "--machine", machine, "-o", str(tape)])
    assert result.exit_code == 0, result.output
    checked = verify(str(tape), str(source), plugins, machine, 0.001)
    assert checked.passed, "\n".join(checked.report())
    assert checked.interpretation.tools == tuple(range(1, 100))
    assert "tools: T1, T2, T3" in "\n".join(checked.report())


NURBS = """PARTNO NURBS
UNITS/MM
LOADTL/1
SPINDL/RPM,1000,CLW
FROM/0,0,10
FEDRAT/200,MMPM
GOTO/0,0,-2
NURBS/
KNOT/0,0,0,0.5,1,1,1
CNTRL/0,0,-2
CNTRL/5,8,-2
CNTRL/15,8,-2
CNTRL/20,0,-2
GOTO/20,0,-2
FINI
"""


@needs_rs274
def test_a_file_whose_nurbs_no_dialect_reads_stops_and_nx_reads_it(tmp_path: Path) -> None:
    """NURBS motion is never disregarded: plain APT stops naming the line (exit 3); read as
    NX's, the curve becomes moves within INTOL, and verify passes."""
    source = tmp_path / "nurbs.apt"
    source.write_text(NURBS)
    tape = tmp_path / "nurbs.ngc"
    posted = CliRunner().invoke(
        main, ["post", str(source), "--machine", "linuxcnc-mill", "-o", str(tape)]
    )
    assert posted.exit_code == 3 and "nurbs.apt:8" in posted.output
    assert "--dialect nx" in posted.output and not tape.exists()
    posted = CliRunner().invoke(
        main,
        ["post", str(source), "--machine", "linuxcnc-mill", "-o", str(tape), "--dialect", "nx"],
    )
    assert posted.exit_code == 0, posted.output
    result = CliRunner().invoke(
        main,
        ["verify", str(tape), "--cl", str(source), "--machine", "linuxcnc-mill", "--dialect", "nx"],
    )
    assert result.exit_code == 0, result.output


@needs_rs274
def test_verifications_at_once_do_not_disturb_each_other(
    plugins: PluginSet, tmp_path: Path
) -> None:
    """rs274 maps $HOME/.tool.mmap: each run gets a HOME of its own, so runs in parallel
    (a batch) do not crash each other, and a running LinuxCNC's tool table is left alone."""
    source = tmp_path / "tools.apt"
    source.write_text(tools_program(range(1, 12)))
    tape = tmp_path / "tools.ngc"
    result = CliRunner().invoke(
        main, ["post", str(source), "--machine", "linuxcnc-mill", "-o", str(tape)]
    )
    assert result.exit_code == 0, result.output
    home_table = Path.home() / ".tool.mmap"
    before = home_table.stat().st_mtime_ns if home_table.exists() else None
    with ThreadPoolExecutor(8) as pool:
        runs = list(
            pool.map(
                lambda _: verify(str(tape), str(source), plugins, "linuxcnc-mill", 0.001),
                range(16),
            )
        )
    assert all(run.passed for run in runs), "\n".join(
        next(r for r in runs if not r.passed).report()
    )
    after = home_table.stat().st_mtime_ns if home_table.exists() else None
    assert after == before
