"""The fast path (core/motion/fastpath.py) against the general path, forced by
``--no-fast-path``: the tape, listing, punch, JSON lines, warnings and exit status must be
byte-identical, on every corpus file, the example programs and generated programs, on the
manual's machines and every modern pack."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner
from gecent.core.cli import main
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from .conftest import ROOT
from .golden.cases import inputs

INPUTS = [ROOT / source for source in inputs()]
MACHINES = ["23", "4", "24", "standard", "linuxcnc-mill", "linuxcnc-mill-inch", "fanuc-mill"]
MACHINES += ["fanuc-lathe"]
MODERN = {"linuxcnc-mill", "linuxcnc-mill-inch", "fanuc-mill", "fanuc-lathe"}


def _post(source: Path, machine: str, folder: Path, fast: bool) -> dict[str, object]:
    folder.mkdir(parents=True, exist_ok=True)
    code = "ascii" if machine in MODERN else "eia"
    arguments = ["post", str(source), "--machine", machine, "-o", str(folder / "t.tape")]
    arguments += ["--listing", str(folder / "t.lis"), "--punch", code, str(folder / "t.pun")]
    arguments += ["--json"]
    if not fast:
        arguments.append("--no-fast-path")
    result = CliRunner().invoke(main, arguments)
    outputs: dict[str, object] = {
        "exit": result.exit_code,
        "stdout": result.stdout,
        "stderr": result.stderr,
    }
    for name in ("t.tape", "t.lis", "t.pun"):
        path = folder / name
        outputs[name] = path.read_bytes() if path.exists() else None
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise result.exception
    return outputs


def _same(source: Path, machine: str, folder: Path) -> None:
    fast = _post(source, machine, folder / "fast", True)
    general = _post(source, machine, folder / "general", False)
    for key in general:
        assert fast[key] == general[key], f"{source.name} on {machine}: {key} differs"


@pytest.mark.parametrize("machine", MACHINES)
@pytest.mark.parametrize("source", INPUTS, ids=lambda p: p.name)
def test_fast_and_general_paths_write_the_same(source: Path, machine: str, tmp_path: Path) -> None:
    _same(source, machine, tmp_path)


# -- generated programs ---------------------------------------------------------------------

_COORD = st.one_of(
    st.floats(-9, 9, allow_nan=False).map(lambda v: round(v, 4)),
    st.floats(-9, 9, allow_nan=False),
    st.sampled_from([0.0, 0.00005, -0.00005, 0.0004999, 1.0, 99.99995, 150.0, -250.5]),
)
_POINT = st.tuples(_COORD, _COORD, _COORD).map(lambda p: ", ".join(f"{v:g}" for v in p))


@st.composite
def _statement(draw: st.DrawFn) -> list[str]:
    kind = draw(
        st.sampled_from(
            ["goto"] * 12
            + ["fedrat", "rapid", "circle", "pprint", "trans", "seqno", "opskip", "tool"]
            + ["spindl", "coolnt", "stop", "end", "godlta", "cycle", "units"]
        )
    )
    if kind == "goto":
        return [f"GOTO / {draw(_POINT)}"]
    if kind == "fedrat":
        unit = draw(st.sampled_from(["", ", IPM", ", MMPM", ", IPR"]))
        return [f"FEDRAT / {draw(st.sampled_from([1, 7.5, 20, 150, 1200]))}{unit}"]
    if kind == "rapid":
        return ["RAPID"]
    if kind == "circle":
        x, y = draw(_COORD), draw(_COORD)
        radius = draw(st.sampled_from([0.5, 1.0, 2.5]))
        sense = draw(st.sampled_from([1, -1]))
        return [
            f"CIRCLE / {x:g}, {y:g}, 0, 0, 0, {sense}, {radius:g}",
            f"GOTO / {x + radius:g}, {y:g}, 0",
        ]
    if kind == "pprint":
        return ["PPRINT A NOTE"]
    if kind == "trans":
        return [f"TRANS / {draw(_COORD):g}, {draw(_COORD):g}, 0"]
    if kind == "seqno":
        return [draw(st.sampled_from(["SEQNO / 100, INCR, 5", "SEQNO / OFF", "SEQNO / ON"]))]
    if kind == "opskip":
        return [draw(st.sampled_from(["OPSKIP / ON", "OPSKIP / OFF"]))]
    if kind == "tool":
        return [f"LOADTL / {draw(st.integers(1, 8))}"]
    if kind == "spindl":
        return [draw(st.sampled_from(["SPINDL / 1200, CLW", "SPINDL / OFF", "SPINDL / 300"]))]
    if kind == "coolnt":
        return [draw(st.sampled_from(["COOLNT / ON", "COOLNT / OFF"]))]
    if kind == "stop":
        return ["STOP"]
    if kind == "end":
        return ["END", f"FROM / {draw(_POINT)}"]
    if kind == "godlta":
        return [f"GODLTA / {draw(_COORD):g}"]
    if kind == "units":
        return [draw(st.sampled_from(["UNITS / MM", "UNITS / INCHES"]))]
    return ["CYCLE / DRILL, 1, 10, IPM, 1", f"GOTO / {draw(_POINT)}", "CYCLE / OFF"]


@st.composite
def _program(draw: st.DrawFn) -> str:
    lines = ["PARTNO GENERATED", f"FROM / {draw(_POINT)}"]
    if draw(st.booleans()):
        lines.append("FEDRAT / 20")
    for statement in draw(st.lists(_statement(), min_size=3, max_size=30)):
        lines.extend(statement)
    lines.append("FINI")
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("machine", ["23", "4", "standard", "linuxcnc-mill", "fanuc-lathe"])
@settings(
    max_examples=30, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(program=_program())
def test_generated_programs_post_the_same_by_both_paths(
    machine: str, program: str, tmp_path_factory: pytest.TempPathFactory
) -> None:
    folder = tmp_path_factory.mktemp("generated")
    source = folder / "p.apt"
    source.write_text(program)
    _same(source, machine, folder)


@pytest.mark.parametrize("machine", MACHINES)
def test_the_fast_g_code_choice_is_selg(machine: str) -> None:
    """Bisection over the range limits picks SELG's code for every size up to DEPMAX."""
    from gecent.core.motion.fastpath import _selector
    from gecent.core.motion.gcode import LinearCodes
    from gecent.core.plugins import get_plugins

    pack = get_plugins().machine(machine)
    assert pack is not None
    definition = pack.load()
    codes = LinearCodes(definition, definition.number_option(14))
    select = _selector(codes)
    sizes = {1, codes.depmax}
    for limit in codes.limits:
        sizes |= {int(limit) - 1, int(limit), int(limit) + 1}

    def outcome(choose, size: int) -> object:  # type: ignore[no-untyped-def]
        try:
            return choose(size)
        except Exception as exc:  # the manual's fatal error 138, alike
            return str(exc)

    for size in sorted(s for s in sizes if 0 < s <= codes.depmax):
        assert outcome(select, size) == outcome(codes.select, size), size


def test_a_register_overflow_is_reported_alike_by_both_paths(tmp_path: Path) -> None:
    """A machine whose X holds less than its option 4: the fast path's overflow names the
    record's file and line as the general path's does, and both keep the listing's dump."""
    machine = tmp_path / "small-x.toml"
    machine.write_text(
        '[machine]\nname = "small-x"\ntitle = "SMALL X"\n[regfor]\n3 = -12.0\n[optab]\n4 = 99.0\n'
    )
    source = tmp_path / "p.apt"
    source.write_text("FROM/0,0,0\nFEDRAT/10\nGOTO/1,0,0\nGOTO/10.9951,0,0\nFINI\n")
    _same(source, str(machine), tmp_path)
    general = _post(source, str(machine), tmp_path / "again", False)
    assert general["exit"] == 1
    assert f"{source}:4 (record 4): error: X9.9951 does not fit" in str(general["stderr"])
