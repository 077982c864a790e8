"""Memory and speed of a long two-head program (issue 20's measure): both passes of a
multihead post keep each head's blocks in scratch files, so peak memory must stay flat as
the program grows.

A two-head lathe program for MACH51 is generated with ``--sections`` combined operations
of 20 moves per head (each section under its own OP/n, every second one cut by one head
alone first) and posted by ``gecent post`` (tape, listing and EIA punch) in a child
process, at 1x, 4x and 16x the size; the child's peak RSS (``os.wait4``) and its moves
per second are printed. The bare parse-and-print loop of bench_throughput.py reads the
same file in the same run, and the rate is also given as a ratio of it.

    python benchmarks/bench_multihead.py [--sections 250] [--repeat 3] [--json]
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_throughput import BARE_LOOP, child, gecent_command

MOVES = 20  # per head and section


def program(path: Path, sections: int) -> int:
    """The program and its number of GOTOs."""
    lines = [
        "PARTNO LONG TWO-HEAD PROGRAM",
        "MACHIN/GECENT,51",
        "COMBIN/2",
        "SELECT/HEAD,1",
        "FROM/6,4,0",
        "FEDRAT/10",
        "SELECT/HEAD,2",
        "FROM/7,5,0",
        "FEDRAT/8",
    ]
    gotos = 0
    for section in range(1, sections + 1):
        for head, (x0, z0) in ((1, (5.0, 4.0)), (2, (6.0, 5.0))):
            lines.append(f"SELECT/HEAD,{head}")
            # every second operation: head 1 first alone (unequal numbers), then together
            lines.append(f"OP/{2 * section - (1 if head == 1 and section % 2 else 0)}")
            if head == 1 and section % 2:
                lines.append(f"GOTO/{x0:.4f},{z0 + 0.5:.4f},0")
                lines.append(f"OP/{2 * section}")
                gotos += 1
            for move in range(MOVES):
                x = x0 - 0.01 * (move % 10) - 0.003 * head
                z = z0 - 0.05 * (move + 1)
                lines.append(f"GOTO/{x:.4f},{z:.4f},0")
                gotos += 1
            lines.append(f"GOTO/{x0:.4f},{z0:.4f},0")
            gotos += 1
    lines.append("FINI")
    path.write_text("\n".join(lines) + "\n")
    return gotos


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sections", type=int, default=250)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--json", action="store_true")
    options = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        out = Path(folder)
        loop = out / "loop.py"
        loop.write_text(BARE_LOOP)
        for scale in (1, 4, 16):
            source = out / f"p{scale}.apt"
            gotos = program(source, options.sections * scale)
            command = [
                *gecent_command(),
                *("post", str(source), "-o", str(out / "p.tape")),
                *("--listing", str(out / "p.lis"), "--punch", "eia", str(out / "p.eia")),
            ]
            runs = [child(command) for _ in range(options.repeat)]
            elapsed, peak, code, error = min(runs)
            if code != 0:
                print(error, file=sys.stderr)
                return 1
            bare = min(
                child([sys.executable, str(loop), str(source), str(out / "bare.txt")])[0]
                for _ in range(options.repeat)
            )
            rows.append(
                {
                    "gotos": gotos,
                    "seconds": round(elapsed, 3),
                    "gotos_per_second": round(gotos / elapsed),
                    "ratio_to_bare_loop": round(bare / elapsed, 4),
                    "peak_rss_mb": round(peak, 1),
                    "tape_lines": sum(1 for _ in (out / "p.tape").open()),
                }
            )
    if options.json:
        print(json.dumps(rows, indent=2))
    else:
        print(f"{'GOTOs':>8} {'s':>7} {'GOTO/s':>8} {'ratio':>7} {'peak MB':>8} {'tape':>7}")
        for row in rows:
            print(
                f"{row['gotos']:>8} {row['seconds']:>7} {row['gotos_per_second']:>8} "
                f"{row['ratio_to_bare_loop']:>7} {row['peak_rss_mb']:>8} {row['tape_lines']:>7}"
            )
    return 0


if __name__ == "__main__":
    sys.exit(main())
