"""CL units: a metric CL file (UNITS/MM, as Creo writes it) on an inch machine posts
exactly as the same part written in inches (docs/decisions.md, "CL units")."""

from __future__ import annotations

import pytest
from gecent.core.errors import InputError
from gecent.core.plugins import get_plugins
from gecent.core.run import Run

from tests.test_post_linear import post

INCH = [
    "FROM/0,0,1",
    "FEDRAT/10",
    "GOTO/1,0.5,0",
    "GOTO/2,0.5,0",
    "CIRCLE/2,1.5,0,0,0,1,1",
    "GOTO/3,1.5,0",
    "GODLTA/0,0,0.25",
    "GODLTA/-0.25",
]


def metric(lines: list[str]) -> list[str]:
    """The same program with every length in millimetres (the axis vectors stay)."""
    out = []
    for line in lines:
        major, _, args = line.partition("/")
        values = [float(v) for v in args.split(",")]
        if major == "CIRCLE":
            values = [v * 25.4 for v in values[:3]] + values[3:6] + [values[6] * 25.4]
        else:  # points, deltas, and FEDRAT in mm per minute
            values = [v * 25.4 for v in values]
        out.append(f"{major}/{','.join(f'{v:.6f}' for v in values)}")
    return out


def tape(lines: list[str]) -> list[str | None]:
    machine = get_plugins().machine("mach23").load()
    return [b.punch for b in post(lines, machine).blocks if b.punch]


def test_metric_cl_on_an_inch_machine_posts_like_the_inch_cl() -> None:
    inch = tape(["UNITS/INCHES", *INCH])
    assert len(inch) == 5  # the 1-inch arc is one quadrant block
    assert tape(["UNITS/MM", *metric(INCH)]) == inch


@pytest.mark.parametrize("fedrat", ["FEDRAT/254,MMPM", "FEDRAT/10,IPM", "FEDRAT/IPM,10"])
def test_fedrat_units_name_their_own_unit(fedrat: str) -> None:
    """IPM and MMPM say their unit whatever UNITS says; a bare FEDRAT is in the CL unit."""
    program = ["UNITS/MM", *metric(INCH)]
    program[2] = fedrat
    assert tape(program) == tape(["UNITS/INCHES", *INCH])


def test_units_in_centimetres_and_feet() -> None:
    cm = ["UNITS/CM", "FROM/0,0,0", "FEDRAT/25.4", "GOTO/2.54,0,0"]
    feet = ["UNITS/FEET", "FROM/0,0,0", "FEDRAT/10,IPM", "GOTO/0.25,0,0"]
    assert tape(cm) == tape(["UNITS/INCHES", "FROM/0,0,0", "FEDRAT/10", "GOTO/1,0,0"])
    assert tape(feet) == tape(["UNITS/INCHES", "FROM/0,0,0", "FEDRAT/10", "GOTO/3,0,0"])


def test_cutter_and_tolerances_are_converted() -> None:
    run = Run(get_plugins().machine("mach23").load())
    from gecent.core.cl.apt_source import AptSourceReader

    records = AptSourceReader("p.apt").read_lines(
        ["UNITS/MM", "CUTTER/12.7", "INTOL/0.0254", "OUTTOL/0.0508", "FINI"]
    )
    run.process(records)
    tolerances = run.state.tolerances
    assert tolerances.cutter_radius == pytest.approx(0.25)
    assert tolerances.inside == pytest.approx(0.001)
    assert tolerances.outside == pytest.approx(0.002)


def test_unknown_units_is_bad_input() -> None:
    with pytest.raises(InputError, match="UNITS expects one of MM, CM, INCHES, FEET, found"):
        tape(["UNITS/2", "FROM/0,0,0"])
