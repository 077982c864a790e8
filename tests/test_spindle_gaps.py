"""SPINDL/NEUTRL: option 99's S command in command form, the speed and range kept
(manual option 99, 001 L25604-25617)."""

from __future__ import annotations

import pytest
from gecent.core.errors import MachineDefinitionError
from gecent.core.machine.definition import MachineDefinition
from gecent.core.output.block import Code
from gecent.core.plugins import get_plugins

from tests.test_post_linear import post


def _mach24(neutral: float) -> MachineDefinition:
    pack = get_plugins().machine("mach24")
    assert pack is not None
    return pack.load().with_options({99: neutral})


def test_neutral_outputs_option_99_in_command_form() -> None:
    """0.1 stands for S00; the listing's S-RPM shows the command; SPINDL/ON afterwards
    finds the speed in force (300 RPM, MACH24's S03 at 200 RPM)."""
    result = post(["SPINDL/300,CLW", "SPINDL/NEUTRL", "SPINDL/ON"], _mach24(0.1))
    blocks = [b for b in result.blocks if b.punch]
    assert [b.punch for b in blocks] == ["N001S03", "N002S00", "N003S03"]
    assert blocks[1].code is Code.NONMOTION
    assert blocks[1].cells[20] == pytest.approx(0.1)


def test_neutral_with_option_99_zero_outputs_nothing() -> None:
    result = post(["SPINDL/300,CLW", "SPINDL/NEUTRL"], _mach24(0.0))
    assert [b.punch for b in result.blocks if b.punch] == ["N001S03"]


def test_neutral_takes_nothing_else() -> None:
    with pytest.raises(Exception, match="NEUTRL takes nothing else"):
        post(["SPINDL/NEUTRL,300"], _mach24(0.1))


def test_neutral_s_code_needs_an_s_register() -> None:
    pack = get_plugins().machine("mach23")
    assert pack is not None
    with pytest.raises(MachineDefinitionError, match="option 99"):
        post(["SPINDL/NEUTRL"], pack.load().with_options({99: 0.1}))
