"""Options 199 and 200 (manual §5.6.5, 001 L26569-26579): the lower and upper slide limit
of the second rotary head, in degrees as options 149 and 150 give the first head's
(L26154-26166). The second rotary head is the second head axis of a multiaxis class whose
head turns about two (DBFSEG(7)): CLASS 3's A and B, CLASS 6's head A on column B. A move
that passes outside them is warned about, as a slide limit is, and still made."""

from __future__ import annotations

from pathlib import Path

import pytest
from gecent.core.dispatch.post import post
from gecent.core.machine.loader import load_machine_text
from gecent.core.plugins import PluginSet

# the tool tilted 30 degrees about Y: CLASS 6's column B swings 30 degrees, then back
PROGRAM = """PARTNO SECOND HEAD
FROM/0,0,10,0,0,1
FEDRAT/10
GOTO/0,0,10,0.5,0,0.8660254
GOTO/0,0,10,0,0,1
FINI
"""
WARNING = "SECOND HEAD ROTATION LIMIT HAS BEEN EXCEEDED (-10 TO 10 DEGREES, OPTIONS 199, 200)"


def _warnings(plugins: PluginSet, tmp_path: Path, optab: str) -> list[str]:
    pack = plugins.machine("mach40")
    assert pack is not None
    text = f'[machine]\nname = "m40b"\ntitle = "M40 B"\n[tableg]\n11 = 10\n[optab]\n{optab}'
    machine = load_machine_text(text, "m40b.toml", pack.load())
    program = tmp_path / "b.apt"
    program.write_text(PROGRAM)
    result = post(str(program), plugins, machine_override=machine)
    return [str(d) for d in result.diagnostics]


def test_199_200_the_column_beyond_its_limits_is_warned(plugins: PluginSet, tmp_path: Path) -> None:
    """B turns 0 -> 30 (record 4) and 30 -> 0 (record 5, from outside): both warned."""
    notes = _warnings(plugins, tmp_path, "116 = 6.0\n199 = -10.0\n200 = 10.0\n")
    assert [n for n in notes if WARNING in n] == [
        f"{tmp_path}/b.apt:4 (record 4): warning: {WARNING} *** WARNING",
        f"{tmp_path}/b.apt:5 (record 5): warning: {WARNING} *** WARNING",
    ]


@pytest.mark.parametrize(
    "optab",
    [
        "116 = 6.0\n199 = -45.0\n200 = 45.0\n",  # within the limits
        "116 = 6.0\n",  # 0 and 0: no limits
        "199 = -10.0\n200 = 10.0\n",  # CLASS 1 (MACH40): a table C, no second head
    ],
)
def test_199_200_no_warning(plugins: PluginSet, tmp_path: Path, optab: str) -> None:
    assert not any("SECOND HEAD" in n for n in _warnings(plugins, tmp_path, optab))
