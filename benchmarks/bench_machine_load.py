"""Machine files loaded and validated per second (each run loads the Standard Machine and
the five samples from TOML through the full checklist).

    python benchmarks/bench_machine_load.py
"""

from __future__ import annotations

import time
from pathlib import Path

from gecent.core.machine import load_machine_text

MACHINES = Path(__file__).resolve().parent.parent / "plugins" / "machines"


def main(rounds: int = 200) -> None:
    texts = [(p.read_text(), str(p)) for p in sorted(MACHINES.glob("*.toml"))]
    start = time.perf_counter()
    for _ in range(rounds):
        for text, origin in texts:
            load_machine_text(text, origin)
    elapsed = time.perf_counter() - start
    loads = rounds * len(texts)
    print(f"{loads} machine loads in {elapsed:.2f} s: {loads / elapsed:.0f} machines/s")


if __name__ == "__main__":
    main()
