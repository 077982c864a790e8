"""Posting speed: the Creo roughing file (metric, 5590 GOTO, 419 CIRCLE, 619 RAPID) repeated
to about a hundred thousand records, posted on the sample mill MACH23 to blocks, tape image,
EIA punch and GEOUT1 listing; each stage timed apart, in CL records per second.

    python benchmarks/bench_post.py [--records 100000] [--profile] [--machine mach24]

With --machine mach24 the same points are posted as absolute positions on the sample drill
(GEPOS, feed type 0).
"""

from __future__ import annotations

import argparse
import cProfile
import pstats
import tempfile
import time
from pathlib import Path

from gecent.core.dispatch.post import post
from gecent.core.output.marks import stand_in
from gecent.core.output.punch import punch
from gecent.core.output.tape import tape_image
from gecent.core.plugins import get_plugins

ROUGHING = Path(__file__).resolve().parent.parent.parent / "shared/corpus/creo/schruppen_1.ncl.1"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--records", type=int, default=100_000)
    parser.add_argument("--profile", action="store_true", help="print the top of a profile")
    parser.add_argument(
        "--machine", default="mach23", help="mach23 (contouring) or mach24 (positioning)"
    )
    args = parser.parse_args()
    lines = ROUGHING.read_text().splitlines(keepends=True)
    head, body = lines[:14], lines[14:-1]  # set-up statements once, then the moves
    copies = max(1, args.records // len(body))
    plugins = get_plugins()
    pack = plugins.machine(args.machine)
    if pack is None:
        parser.error(f"no machine {args.machine}")
    machine = pack.load()
    printout = plugins.get("printouts", 1)
    with tempfile.TemporaryDirectory() as tmp:
        source = Path(tmp) / "roughing.ncl"
        with source.open("w") as out:
            out.writelines(head)
            for _ in range(copies):
                out.writelines(body)
            out.write(lines[-1])
        profiler = cProfile.Profile() if args.profile else None
        start = time.perf_counter()
        if profiler:
            profiler.enable()
        result = post(str(source), plugins, machine)
        if profiler:
            profiler.disable()
        posted = time.perf_counter()
        tape = tape_image(result.blocks)
        taped = time.perf_counter()
        # a modern tape's % has no EIA RS-244 code here: ASCII, as those controls read
        code = "ascii" if result.machine.number_option(258) == 1 else "eia"
        frames = punch(tape.splitlines(), code, stand_in(machine, 64), stand_in(machine, 65))
        punched = time.perf_counter()
        listing = printout.render(machine, result.blocks, result.partno)
        listed = time.perf_counter()
    records = result.records
    print(
        f"{records:,} CL records -> {len(result.blocks):,} blocks, {len(frames):,} frames, "
        f"{listing.count(chr(10)):,} listing lines"
    )
    for label, begin, end in (
        ("post (read, dispatch, motion, output)", start, posted),
        ("tape image", posted, taped),
        (f"{code.upper()} punch", taped, punched),
        ("GEOUT1 listing", punched, listed),
        ("all", start, listed),
    ):
        elapsed = end - begin
        print(f"{label:<40} {elapsed:6.2f} s {records / elapsed:>12,.0f} records/s")
    if profiler:
        pstats.Stats(profiler).sort_stats("cumulative").print_stats(25)


if __name__ == "__main__":
    main()
