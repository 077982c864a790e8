"""What macros cost (issue 18): the Creo roughing file posted in-process on linuxcnc-mill
and MACH23 with no macros, with a macro that cannot see GOTOs (the engine's fast path),
with a motion macro (every motion by the general path and the hooks), and with a tool-change
macro reading the next tool (a look-ahead at each tool change); best of ``--repeat``, as a
ratio of the run with no macros timed in the same process. Also the cost of one snapshot
(the copy a look-ahead runs on), and of a next-motion look-ahead at every motion of the
first ``--motions`` motions.

    python benchmarks/bench_macros.py [--copies 5] [--repeat 3]
"""

from __future__ import annotations

import argparse
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from gecent.core.dispatch.post import post
from gecent.core.macros import Kind, Macros, Phase
from gecent.core.macros.table import with_macros
from gecent.core.plugins import PluginSet, get_plugins

ROUGHING = Path(__file__).resolve().parents[2] / "shared/corpus/creo/schruppen_1.ncl.1"


def repeated(copies: int, folder: Path) -> Path:
    lines = ROUGHING.read_text(encoding="latin-1").splitlines(keepends=True)
    first = next(i for i, line in enumerate(lines) if line.startswith(("GOTO", "RAPID")))
    last = max(i for i, line in enumerate(lines) if line.startswith("FINI"))
    body = lines[first:last]
    path = folder / "rough.ncl"
    path.write_text("".join(lines[:first] + body * copies + lines[last:]), encoding="latin-1")
    return path


def scenarios() -> dict[str, Macros | None]:
    fast = Macros()
    fast.ignore("PENUP")
    motion = Macros()

    @motion.event(Kind.MOTION, Phase.STARTUP)
    def every_motion(ctx):  # type: ignore[no-untyped-def]
        return ctx.p.subclass

    tools = Macros()

    @tools.event(Kind.TOOL_CHANGE, Phase.SHUTDOWN)
    def next_tool(ctx):  # type: ignore[no-untyped-def]
        return ctx.next.tool

    return {"no macros": None, "fast path": fast, "motion macro": motion, "next tool": tools}


def best(action: Callable[[], object], repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        action()
        times.append(time.perf_counter() - start)
    return min(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--copies", type=int, default=5)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--motions", type=int, default=200)
    options = parser.parse_args()
    base = get_plugins()
    with tempfile.TemporaryDirectory() as folder:
        path = str(repeated(options.copies, Path(folder)))
        for machine in ("linuxcnc-mill", "23"):
            reference = None
            for name, macros in scenarios().items():
                plugins: PluginSet = base if macros is None else with_macros(base, macros.macros)
                seconds = best(lambda p=plugins, m=machine: post(path, p, m), options.repeat)
                reference = reference or seconds
                ratio = seconds / reference
                print(f"{machine:14s} {name:13s} {seconds:7.3f} s  ratio {ratio:5.2f}")
        snapshot_cost(base, path, options.motions)


def snapshot_cost(base: PluginSet, path: str, motions: int) -> None:
    from gecent.core.macros.lookahead import snapshot

    timing: dict[str, list[float]] = {"snapshot": [], "look": []}
    macros = Macros()

    @macros.event(Kind.MOTION, Phase.STARTUP)
    def look(ctx):  # type: ignore[no-untyped-def]
        if ctx.la.active or len(timing["look"]) >= motions:
            return
        start = time.perf_counter()
        snapshot(ctx._engine.run)
        timing["snapshot"].append(time.perf_counter() - start)
        start = time.perf_counter()
        _ = ctx.next.motion
        timing["look"].append(time.perf_counter() - start)

    post(path, with_macros(base, macros.macros), "linuxcnc-mill")
    for key, values in timing.items():
        values.sort()
        print(f"{key:9s} median {1000 * values[len(values) // 2]:.3f} ms over {len(values)}")


if __name__ == "__main__":
    main()
