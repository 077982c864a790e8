"""Record the outputs of the golden cases (tests/golden/cases.py) as made by a commit:

    python tests/golden/make_outputs.py --commit 87acca5 [-o tests/golden/outputs.json]

Entries marked "changed" were changed by a documented fix after that commit; recording
anew drops the marks, so keep them (or re-add them) when the change is meant.
The commit is checked out in a temporary git worktree and imported in place of the working
tree (its .typing/gecent links name its core/ and plugins/); with no --commit the working
tree itself is recorded.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]


def record(output: Path) -> None:
    sys.path.insert(0, str(ROOT))
    from tests.golden.cases import case_id, cases, run_case

    results = {case_id(s, m): {"input": s, "machine": m, **run_case(s, m)} for s, m in cases()}
    output.write_text(json.dumps(results, indent=1, sort_keys=True) + "\n")
    print(f"{len(results)} cases recorded in {output}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--commit", help="record this commit's outputs (default: the tree)")
    parser.add_argument("-o", "--output", default=str(HERE / "outputs.json"))
    parser.add_argument("--in-worktree", help=argparse.SUPPRESS)
    args = parser.parse_args()
    output = Path(args.output).resolve()
    if args.commit is None:
        record(output)
        return
    with tempfile.TemporaryDirectory() as folder:
        tree = Path(folder) / "tree"
        subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "-q", str(tree), args.commit],
                       check=True)  # fmt: skip
        try:
            environment = dict(os.environ, PYTHONPATH=str(tree / ".typing"))
            script = (
                f"import sys; sys.path.insert(0, {str(ROOT)!r}); import gecent.core;"
                f"assert gecent.core.__file__.startswith({str(tree)!r}), gecent.core.__file__;"
                "from tests.golden.make_outputs import record; from pathlib import Path;"
                f"record(Path({str(output)!r}))"
            )
            subprocess.run([sys.executable, "-c", script], check=True, env=environment)
        finally:
            subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(tree)],
                           check=False)  # fmt: skip


if __name__ == "__main__":
    main()
