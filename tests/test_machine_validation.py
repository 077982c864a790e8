"""Bad machine files are rejected with the file, table, entry and rule (spec 07 §8.5)."""

from __future__ import annotations

from pathlib import Path

import pytest
from gecent.core.errors import InputError
from gecent.core.machine import load_machine_file
from gecent.core.machine.loader import MachineFileInvalid

HEADER = '[machine]\nname = "bad"\nnumber = 88\n'


def problems(tmp_path: Path, body: str) -> list[str]:
    path = tmp_path / "bad.toml"
    path.write_text(HEADER + body)
    with pytest.raises(MachineFileInvalid) as caught:
        load_machine_file(path)
    assert all(p.file == str(path) for p in caught.value.problems)
    assert str(path) in str(caught.value)
    return [f"[{p.table}] {p.entry}: {p.rule}" for p in caught.value.problems]


def test_wrong_table_entries(tmp_path: Path) -> None:
    found = problems(tmp_path, '[tableg]\n132 = 5\n3 = "maybe"\n[tablem]\n4 = -3\n')
    assert any(p.startswith("[tableg] 132: location must be 1..131") for p in found)
    assert any(p.startswith('[tableg] 3: value must be a code number or "absent"') for p in found)
    assert any(p.startswith("[tablem] 4: code must be 0 or more") for p in found)


def test_tablem_130_must_stay_absent(tmp_path: Path) -> None:
    found = problems(tmp_path, "[tablem]\n130 = 7\n")
    assert any(p.startswith("[tablem] 130: location 130 must stay absent") for p in found)


def test_register_rules(tmp_path: Path) -> None:
    found = problems(
        tmp_path, '[regstr]\n15 = "Q"\n16 = "X"\n[regfor]\n16 = -14.0\n17 = 10.0\n9 = 14.5\n'
    )
    assert any(p.startswith("[regstr] 15: location 15 is reserved") for p in found)
    assert any(p.startswith("[regstr] 16: letter X is already used by location 3") for p in found)
    assert any(p.startswith("[regstr] 17: register has format 10 but no letter") for p in found)
    assert any(p.startswith("[regfor] 9: format must be") for p in found)


def test_unknown_option_number_and_alias(tmp_path: Path) -> None:
    found = problems(tmp_path, "[optab]\n266 = 1.0\nno_such_option = 2.0\n64 = 3.0\n")
    assert "[optab] 266: unknown option (options are 1..265 or an alias)" in found
    assert "[optab] no_such_option: unknown option (options are 1..265 or an alias)" in found
    assert any(p.startswith("[optab] 64: option 64 (") and "holds text" in p for p in found)


def test_option_given_twice(tmp_path: Path) -> None:
    found = problems(tmp_path, "[optab]\n14 = 0.001\nstep_size = 0.0001\n")
    assert any("is also given as" in p for p in found)


def test_spindle_table_count_must_match_options_7_and_8(tmp_path: Path) -> None:
    found = problems(
        tmp_path,
        "[optab]\n7 = 2.0\n8 = 3.0\n19 = 2.0\n[spindle_table]\nspeeds = [10.0, 20.0, 30.0, 40.0]\n",
    )
    assert any(
        p.startswith(
            "[spindle_table] speeds: option 7 x option 8 = 6 speeds, but SRTAB holds only 4"
        )
        for p in found
    )


def test_spindle_table_with_extra_values_for_a_plain_type(tmp_path: Path) -> None:
    found = problems(tmp_path, "[optab]\n19 = 2.0\n[spindle_table]\nspeeds = [10.0, 20.0, 30.0]\n")
    assert any("but SRTAB holds 3 values" in p for p in found)


def test_speeds_must_ascend_within_a_range(tmp_path: Path) -> None:
    found = problems(tmp_path, "[spindle_table]\nspeeds = [300.0, 1.0]\n")
    assert any("range 1 speeds must be in ascending order" in p for p in found)


def test_feed_range_count_must_match_options_18_and_174(tmp_path: Path) -> None:
    found = problems(
        tmp_path,
        "[optab]\n18 = 3.0\n174 = 4.0\n[feed_ranges]\nranges = [[0.1, 10.0], [7.0, 60.0]]\n",
    )
    assert (
        "[feed_ranges] ranges: option 18 = 3 feedrate ranges, but FRTAB lists 2 (checklist 11c)"
        in found
    )


def test_frtab_size_must_be_twice_the_ranges(tmp_path: Path) -> None:
    found = problems(
        tmp_path,
        "[optab]\n18 = 2.0\n174 = 6.0\n[feed_ranges]\nranges = [[0.1, 10.0], [7.0, 60.0]]\n",
    )
    assert any(
        p.startswith("[optab] 174: FRTAB size must be 2 x 2 ranges = 4; found 6") for p in found
    )


def test_srtab_and_frtab_must_not_overlap(tmp_path: Path) -> None:
    speeds = ", ".join(str(float(i)) for i in range(1, 299))
    found = problems(
        tmp_path,
        f"[optab]\n7 = 1.0\n8 = 298.0\n18 = 2.0\n174 = 4.0\n"
        f"[spindle_table]\nspeeds = [{speeds}]\n"
        "[feed_ranges]\nranges = [[0.1, 10.0], [7.0, 60.0]]\n",
    )
    assert any("overlap in the shared 300-word store" in p for p in found)


def test_default_feed_range_code_must_be_a_range_code(tmp_path: Path) -> None:
    found = problems(
        tmp_path,
        "[tablem]\n113 = 10\n114 = 20\n43 = 30\n[optab]\n18 = 2.0\n174 = 4.0\n"
        "[feed_ranges]\nranges = [[0.1, 10.0], [7.0, 60.0]]\n",
    )
    assert any(p.startswith("[tablem] 43: the default feed-range M code 30") for p in found)


def test_option_rules_of_the_fatal_errors(tmp_path: Path) -> None:
    found = problems(tmp_path, "[optab]\n59 = 191415.0\n132 = 9.0\n19 = 7.0\n")
    assert any(p.startswith("[optab] 59: badly formed (fatal error 7, DECODE)") for p in found)
    assert any(p.startswith("[optab] 132: machine type must be 0..8") for p in found)
    assert any(p.startswith("[optab] 133: spindle type 7") for p in found)


def test_magic_three_feed_needs_regfor_30(tmp_path: Path) -> None:
    found = problems(tmp_path, "[optab]\n10 = 1.0\n[regfor]\n11 = 40.0\n")
    assert "[regfor] 11: option 10 = +1 (EIA magic 3 feed) needs REGFOR(11) = 30" in found


def test_schema_errors_name_table_and_entry(tmp_path: Path) -> None:
    found = problems(tmp_path, "[tableg]\n2 = 1.5\n[frobs]\nx = 1\n")
    assert any(p.startswith("[tableg] 2:") for p in found)
    assert any(p.startswith("[frobs] None: unknown table") for p in found)


def test_broken_toml_is_an_input_error(tmp_path: Path) -> None:
    path = tmp_path / "broken.toml"
    path.write_text("[machine\nname=")
    with pytest.raises(InputError, match="not valid TOML"):
        load_machine_file(path)


def test_title_longer_than_tag(tmp_path: Path) -> None:
    path = tmp_path / "t.toml"
    path.write_text('[machine]\nname = "t"\ntitle = "' + "X" * 37 + '"\n')
    with pytest.raises(MachineFileInvalid, match=r"\[machine\] entry title"):
        load_machine_file(path)
