"""Posting throughput against a bare loop, and peak memory (issue 15's measure).

The Creo roughing file is repeated (the set-up statements once, the moves ``--copies``
times, FINI once) and posted by ``gecent post`` in a child process; in the same run a bare
Python loop, also a child process, reads the same file, parses each GOTO and prints a G1
line. Speed is the ratio of the two GOTO rates (this machine is noisy; a ratio measured in
one run means more than absolute times), best of ``--repeat`` runs each. A third child,
``reference_post.py``, is the least a hand-written post of the roughing file must do (a
dict for the state, f-strings, no machine data); its rate is a ceiling for a post written
in Python, and gecent's rate is also given as a ratio of it. Peak RSS is the
child's own (``os.wait4``), on the repeated file and on the file once.

    python benchmarks/bench_throughput.py [--copies 50] [--repeat 3] [--scenario all] [--json]

Scenarios and the targets: ``linuxcnc`` (linuxcnc-mill, tape only) ratio >= 0.5;
``mach23`` (the sample mill, tape, listing and EIA punch) ratio >= 0.3; both peak RSS
<= 80 MB and within 10% of the single file's. ``--check`` exits 1 when a target is missed.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROUGHING = Path(__file__).resolve().parents[2] / "shared/corpus/creo/schruppen_1.ncl.1"
REFERENCE_POST = Path(__file__).resolve().parent / "reference_post.py"


def gecent_command() -> list[str]:
    """The installed ``gecent`` beside this interpreter, else on PATH, else the module."""
    beside = Path(sys.executable).parent / "gecent"
    if beside.exists():
        return [str(beside)]
    found = shutil.which("gecent")
    return [found] if found else [sys.executable, "-m", "gecent.core.cli"]


BARE_LOOP = r"""
import sys
source, target = sys.argv[1], sys.argv[2]
with open(source) as lines, open(target, "w") as out:
    for line in lines:
        if line.startswith("GOTO"):
            x, y, z = line.split("/", 1)[1].split(",")[:3]
            out.write("G1 X%.4f Y%.4f Z%.4f\n" % (float(x), float(y), float(z)))
"""

SCENARIOS = {
    "linuxcnc": (["--machine", "linuxcnc-mill", "-o", "{out}/p.ngc"], 0.5),
    "mach23": (
        [
            *("--machine", "23", "-o", "{out}/p.tape", "--listing", "{out}/p.lis"),
            *("--punch", "eia", "{out}/p.eia"),
        ],
        0.3,
    ),
}
MEMORY_TARGET_MB = 80.0


def repeated(folder: Path, copies: int) -> tuple[Path, int]:
    lines = ROUGHING.read_text().splitlines(keepends=True)
    head, body = lines[:14], lines[14:-1]
    path = folder / f"roughing-{copies}.ncl"
    with path.open("w") as out:
        out.writelines(head)
        for _ in range(copies):
            out.writelines(body)
        out.write(lines[-1])
    gotos = sum(1 for line in path.open() if line.startswith("GOTO"))
    return path, gotos


def child(arguments: list[str]) -> tuple[float, float, int, str]:
    """Wall seconds, peak RSS in MB, exit status and standard error of one child."""
    start = time.perf_counter()
    process = subprocess.Popen(arguments, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    assert process.stderr is not None
    error = process.stderr.read().decode(errors="replace")
    _, status, usage = os.wait4(process.pid, 0)
    elapsed = time.perf_counter() - start
    process.returncode = os.waitstatus_to_exitcode(status)
    return elapsed, usage.ru_maxrss / 1024.0, process.returncode, error


def best(arguments: list[str], repeat: int) -> tuple[float, float, int, str]:
    runs = [child(arguments) for _ in range(repeat)]
    return min(runs, key=lambda run: run[0])


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--copies", type=int, default=50)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--scenario", choices=[*SCENARIOS, "all"], default="all")
    parser.add_argument("--json", action="store_true", help="also print the figures as JSON")
    parser.add_argument("--check", action="store_true", help="exit 1 when a target is missed")
    args = parser.parse_args()
    if not ROUGHING.exists():
        parser.error(f"{ROUGHING} is not here (the shared corpus)")
    names = list(SCENARIOS) if args.scenario == "all" else [args.scenario]
    figures: dict[str, dict[str, object]] = {}
    missed = False
    with tempfile.TemporaryDirectory() as folder:
        tmp = Path(folder)
        source, gotos = repeated(tmp, args.copies)
        single, _ = repeated(tmp, 1)
        bare_seconds, _, _, _ = best(
            [sys.executable, "-c", BARE_LOOP, str(source), str(tmp / "bare.out")], args.repeat
        )
        bare_rate = gotos / bare_seconds
        hand_seconds, _, _, _ = best(
            [sys.executable, str(REFERENCE_POST), str(source), str(tmp / "hand.out")],
            args.repeat,
        )
        hand_rate = gotos / hand_seconds
        print(
            f"{gotos:,} GOTO ({args.copies} copies); bare loop {bare_rate:,.0f} GOTO/s; "
            f"hand-written post {hand_rate:,.0f} GOTO/s (ratio {hand_rate / bare_rate:.3f})"
        )
        for name in names:
            options, target = SCENARIOS[name]
            command = [*gecent_command(), "post"]
            seconds, peak, status, error = best(
                [*command, str(source), *(o.format(out=tmp) for o in options)], args.repeat
            )
            if status != 0:
                print(f"{name}: gecent exited {status}:\n{error}")
                missed = True
                continue
            _, single_peak, _, _ = child(
                [*command, str(single), *(o.format(out=tmp) for o in options)]
            )
            rate = gotos / seconds
            ratio = rate / bare_rate
            flat = peak <= single_peak * 1.10
            passed = ratio >= target and peak <= MEMORY_TARGET_MB and flat
            missed = missed or not passed
            figures[name] = {
                "gotos": gotos,
                "bare_goto_per_s": round(bare_rate),
                "gecent_goto_per_s": round(rate),
                "ratio": round(ratio, 3),
                "hand_written_goto_per_s": round(hand_rate),
                "ratio_to_hand_written": round(rate / hand_rate, 3),
                "target": target,
                "peak_rss_mb": round(peak, 1),
                "peak_rss_single_mb": round(single_peak, 1),
                "passed": passed,
            }
            print(
                f"{name:<9} {rate:>10,.0f} GOTO/s  ratio {ratio:.3f} (target {target}; "
                f"{rate / hand_rate:.3f} of hand-written)  "
                f"peak {peak:.1f} MB (once: {single_peak:.1f} MB)  "
                f"{'PASS' if passed else 'FAIL'}"
            )
    if args.json:
        print(json.dumps(figures, indent=1))
    return 1 if args.check and missed else 0


if __name__ == "__main__":
    sys.exit(main())
