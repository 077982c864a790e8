"""GEOUT1's line layout (CALCP1, 001 L9454-9582): every register and the absolute columns
on one line if they fit the option-160 print positions, else S-RPM goes, then F-IPM, else
GEOUT1 cannot be used; the spare positions are shared out equally."""

from __future__ import annotations

from itertools import pairwise

import pytest
from gecent.core.errors import NotYetSupported
from gecent.core.machine.definition import MachineDefinition
from gecent.core.plugins import get_plugins
from gecent.plugins.printouts.geout1 import columns, heading


def mill(positions: float) -> MachineDefinition:
    return get_plugins().machine("mach23").load().with_options({160: positions})


@pytest.mark.parametrize(
    ("positions", "dropped"),
    [(140, []), (132, ["S-RPM"]), (120, ["S-RPM", "F-IPM"])],
)
def test_columns_are_dropped_in_the_manual_order(positions: float, dropped: list[str]) -> None:
    """MACH23 (N G X Y Z A I J K F M, ABS X Y Z A) needs exactly 120 positions without
    the F-IPM and S-RPM columns, 130 with F-IPM and 138 with both."""
    keys = [c.key for c in columns(mill(positions))]
    assert [k for k in ("F-IPM", "S-RPM") if k not in keys] == sorted(dropped)


def test_a_line_that_cannot_fit_rejects_geout1() -> None:
    with pytest.raises(NotYetSupported, match=r"GEOUT1 CANNOT BE USED\. .*needs 120 print"):
        columns(mill(100))


def test_spare_positions_are_shared_out_equally() -> None:
    layout = columns(mill(200))
    gaps = {b.start - (a.start + a.width) for a, b in pairwise(layout)}
    assert len(gaps) == 1
    last = layout[-1]
    assert last.start + last.width - 1 <= 201  # 200 print positions after column 1


def test_titles_are_centred_over_their_fields() -> None:
    machine = mill(120)
    title = heading(machine)
    for column in columns(machine):
        centre = column.start + (column.width - 1) // 2
        first = centre - (len(column.heading) - 1) // 2
        assert title[first - 1 : first - 1 + len(column.heading)] == column.heading


def test_w10_w11_lathe_title_words() -> None:
    """W10/W11 (001 L8976-8982, L9488-9530): a lathe with X and Z only titles its columns
    N G X Z I K F S T M, then ABS-X ABS-Z (OPR- under option 172 = 1) F-IPM S-RPM;
    a metric machine (option 138 = 1) prints F-MPM."""
    lathe = get_plugins().machine("mach04").load()
    words = heading(lathe.with_options({172: 0.0})).split()
    registers = ["N", "G", "X", "Z", "I", "K", "F", "S", "T", "M"]
    assert words == [*registers, "ABS-X", "ABS-Z", "F-IPM", "S-RPM"]
    assert heading(lathe.with_options({172: 1.0})).split()[10:12] == ["OPR-X", "OPR-Z"]
    assert "F-MPM" in heading(lathe.with_options({138: 1.0})).split()
