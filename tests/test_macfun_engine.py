"""MACFUN on the macro engine (manual §5.6.7; spec 07 §9): the hook points are called at
their places, HANDLED skips the source routine's rest; MACF40, the sample multiaxis mill's
MACFUN, with the worked examples WE-18 (cycle feed code) and WE-19 (LOAD hook)."""

from __future__ import annotations

import pytest
from gecent.core.absent import ABSENT
from gecent.core.families import HookPoint, HookResult, Macfun
from gecent.core.macros.macfun import MacfunContext
from gecent.core.output.block import Code
from gecent.core.plugins import PluginInfo, PluginSet, get_plugins
from gecent.core.run import Run
from gecent.plugins.macfuns import macf40

from .macros_helpers import records

HOME = "FROM/-19,48,31.75\n"


def run_on(machine: str, text: str, plugins: PluginSet | None = None) -> Run:
    plugins = plugins or get_plugins()
    pack = plugins.machine(machine)
    assert pack is not None
    run = Run(pack.load(), plugins)
    run.process(iter(records(text)))
    return run


def with_macfun(macfun: Macfun) -> PluginSet:
    base = get_plugins()
    plugins = base.copy()
    plugins.family("macfuns")[f"test-{macfun.machine}"] = PluginInfo(
        "macfuns", macfun.name, macfun.name, "(test)", "", "tests", macfun
    )
    return plugins


def texts(run: Run) -> list[str]:
    return [d.text for d in run.result.diagnostics]


# -- WE-18: MACF40's cycle feed code ---------------------------------------------------------


@pytest.mark.parametrize(
    ("feed", "code"),
    [(0.5, 0), (1.0, 0), (1.2, 0), (1.40, 1), (5.0, 4), (5.40, 5), (15.0, 8), (25.0, 9)],
)
def test_we18_cycle_feed_code(feed: float, code: int) -> None:
    assert macf40.feed_code(feed) == code


def test_we18_cycle_blocks_on_mach40() -> None:
    run = run_on(
        "mach40",
        "PARTNO T\n" + HOME + "FEDRAT/10\nCYCLE/TAP,4,IPM,5.4\nGOTO/-18,48,31\n"
        "CYCLE/OFF,2\nCYCLE/OUT\nFINI\n",
    )
    blocks = [(b.cells[2], b.cells[17]) for b in run.result.blocks if b.code is Code.G_ONLY]
    # TAP with DATACL(6) = 4: G55 + 2 = G57; OFF with 2: G51 + 1 = G52; OUT: the feed code
    # alone; the feed 5.4 (ASFTAB's 6th) stays for the later cycles: code 5
    assert [(float(g), float(h)) for g, h in blocks[:2]] == [
        (57.0, 5.0),
        (52.0, 5.0),
    ]
    assert float(blocks[2][1]) == 5.0 and blocks[2][0] is ABSENT  # no G for OUT
    assert run.cycle is None  # HANDLED: the built-in CYCLE never ran
    # HOME is a CL point: class 1 (k = 1, C = 0) takes it to machine X -48, outside MACF40's
    # X window (its slide-limit test, MCHCON 2), which is all it is warned of
    assert [t for t in texts(run) if "SLIDE LIMIT" not in t] == []


# -- WE-19: MACF40's LOAD hook ---------------------------------------------------------------


@pytest.mark.parametrize(("head", "x"), [(0.0, -19.0), (1.0, -29.0)])
def test_we19_load_returns_the_tool_to_the_change_point(head: float, x: float) -> None:
    run = run_on("mach40", "PARTNO T\n" + HOME + "FINI\n")
    context = MacfunContext(HookPoint.LOAD, run, data={"macf40": {"TLHEAD": head}})
    assert macf40.load_sequence(context) is HookResult.CONTINUE  # RETURN = 0: LOAD goes on
    step = run.machine.number_option(14)
    reached = tuple(s * step for s in run.state.position.present[:4])
    assert reached == pytest.approx((x, 48.0, 48.75, -25.0), abs=step)


def test_macf40_toolno_records_the_tools_and_suppresses_t() -> None:
    run = run_on(
        "mach40",
        "PARTNO T\n" + HOME + "TOOLNO/3,LARGE\nTOOLNO/4\nFEDRAT/10\nGOTO/-18,48,31\nFINI\n",
    )
    memory = run.macros.macfun_data["macf40"]  # type: ignore[union-attr]
    assert (memory["TOLLOD"], memory["GRPLOD"], memory["TOLSLC"], memory["GRPSLC"]) == (
        3.0,
        1.0,
        4.0,
        0.0,
    )
    assert all(b.cells[13] is ABSENT for b in run.result.blocks)  # no T word at all


def test_macf40_from_point_test() -> None:
    assert texts(run_on("mach40", "PARTNO T\n" + HOME + "FINI\n")) == []
    away = run_on("mach40", "PARTNO T\nFROM/0,0,0\nFINI\n")
    assert texts(away) == [macf40.FROM_WARNING]


# -- the hook points and their places --------------------------------------------------------


def test_a_third_party_from_hook_runs() -> None:
    """The acme pack's FROM test (registered and never called before the macro engine)."""
    calls: list[tuple[float, ...]] = []

    def check(context: MacfunContext) -> HookResult:
        calls.append(context.point)
        context.warn("NOT THE CHANGE POSITION")
        return HookResult.CONTINUE

    plugins = with_macfun(Macfun("mine", "mach40", "test", {HookPoint.FROM: check}))
    # MACF40 is registered first and keeps the FROM point; mine serves the other points
    run = run_on("mach40", "PARTNO T\nFROM/1,2,3\nFINI\n", plugins)
    assert calls == [] and texts(run) == [macf40.FROM_WARNING]


def test_init_thread_and_slide_limit_points_are_called() -> None:
    seen: list[HookPoint] = []

    def note(context: MacfunContext) -> HookResult:
        seen.append(context.hook)
        return HookResult.HANDLED if context.hook is HookPoint.SLIDE_LIMITS else HookResult.CONTINUE

    plugins = with_macfun(
        Macfun(
            "mine",
            "mach40",
            "test",
            {HookPoint.INIT: note, HookPoint.SLIDE_LIMITS: note, HookPoint.THREAD: note},
        )
    )
    del plugins.family("macfuns")["macf40"]  # MACF40 would keep its own limit point
    run = run_on("mach40", "PARTNO T\n" + HOME + "FEDRAT/10\nGOTO/500,48,31\nFINI\n", plugins)
    assert seen[0] is HookPoint.INIT and seen.count(HookPoint.INIT) == 1
    assert HookPoint.SLIDE_LIMITS in seen
    # the machine did its own limit test: no standard slide-limit warning
    assert not any("SLIDE LIMIT" in t for t in texts(run))


def test_a_macfun_is_not_called_without_option_133() -> None:
    calls: list[int] = []

    def check(context: MacfunContext) -> HookResult:
        calls.append(1)
        return HookResult.HANDLED

    plugins = with_macfun(Macfun("mine", "linuxcnc-mill", "test", {HookPoint.FROM: check}))
    run = run_on("linuxcnc-mill", "PARTNO T\nUNITS/MM\nFROM/0,0,10\nFINI\n", plugins)
    assert calls == [] and run.macros is None


def test_machin_turning_macfun_off_mid_run_stops_its_hooks() -> None:
    on = run_on("mach40", "PARTNO T\nFROM/0,0,0\nFINI\n")
    off = run_on("mach40", "PARTNO T\nMACHIN/GECENT,40,OPTAB,133,0\nFROM/0,0,0\nFINI\n")
    assert macf40.FROM_WARNING in texts(on)
    assert macf40.FROM_WARNING not in texts(off)


def test_machin_turning_macfun_on_mid_run_is_not_built() -> None:
    def check(context: MacfunContext) -> HookResult:
        return HookResult.CONTINUE

    plugins = with_macfun(Macfun("mine", "mach23", "test", {HookPoint.FROM: check}))
    assert run_on("mach23", "PARTNO T\nFROM/0,0,0\nFINI\n", plugins).macros is None
    with pytest.raises(Exception, match="MACFUN turned on by MACHIN"):
        run_on("mach23", "PARTNO T\nMACHIN/GECENT,23,OPTAB,133,1\nFINI\n", plugins)
