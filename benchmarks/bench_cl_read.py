"""CL reading speed: the Creo roughing file repeated to about a million lines, read by the
APT source reader, written as an APT IV binary CL file and read back by the binary reader,
against a bare loop that only splits each line on '/' and ',' and converts the numbers.

    python benchmarks/bench_cl_read.py [--lines 1000000]
"""

from __future__ import annotations

import argparse
import re
import tempfile
import time
from pathlib import Path

from gecent.core.cl.apt_source import read_apt_source
from gecent.core.cl.binary_layout import parse_layout
from gecent.core.cl.binary_reader import read_binary
from gecent.core.cl.binary_writer import write_binary

ROUGHING = Path(__file__).resolve().parent.parent.parent / "shared/corpus/creo/schruppen_1.ncl.1"
_NUMBER = re.compile(r"^\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*$")


def bare_loop(path: Path) -> int:
    """The floor: split on '/' and ',' and float() what looks like a number."""
    count = 0
    with path.open() as handle:
        for line in handle:
            _, _, rest = line.partition("/")
            for item in rest.split(","):
                if _NUMBER.match(item):
                    float(item)
            count += 1
    return count


def timed(label: str, units: str, run: object) -> float:
    start = time.perf_counter()
    count = run()  # type: ignore[operator]
    elapsed = time.perf_counter() - start
    rate = count / elapsed
    print(f"{label:<34} {count:>9} {units} in {elapsed:6.2f} s: {rate:>10,.0f} {units}/s")
    return rate


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--lines", type=int, default=1_000_000)
    args = parser.parse_args()
    lines = ROUGHING.read_text().splitlines(keepends=True)
    body = lines[:-1]  # without FINI, so that the copies make one program
    copies = max(1, args.lines // len(body))
    with tempfile.TemporaryDirectory() as tmp:
        text = Path(tmp) / "roughing.ncl"
        with text.open("w") as out:
            for _ in range(copies):
                out.writelines(body)
            out.write(lines[-1])
        total = copies * len(body) + 1
        print(f"input: {ROUGHING.name} x {copies} = {total:,} lines")
        bare = timed("bare split/float loop", "lines", lambda: bare_loop(text))
        source = timed(
            "APT source reader",
            "lines",
            lambda: sum(1 for _ in read_apt_source(str(text))) and total,
        )
        binary = Path(tmp) / "roughing.cl3"
        with binary.open("wb") as out:
            write_binary(read_apt_source(str(text)), out, parse_layout("apt4"))
        records = timed(
            "binary reader (APT IV layout)",
            "records",
            lambda: sum(1 for _ in read_binary(str(binary))),
        )
        print(f"APT source reader / bare loop: {source / bare:.2f}")
        print(f"binary file: {binary.stat().st_size:,} bytes, {records:,.0f} records/s")


if __name__ == "__main__":
    main()
