"""The scratch tapes TAPES2 and TAPES3 (manual §3.4.8.1, 001 L7280-7297): each head's
finished command blocks, dumped as the first pass makes them into a temporary file and
read back one at a time by the merge pass, so a long program's blocks never sit in
memory. The file is gecent's own, written and read in one run: pickle is its format.
"""

from __future__ import annotations

import contextlib
import os
import pickle
import tempfile
from collections.abc import Iterator
from typing import BinaryIO

from gecent.core.output.block import Block
from gecent.core.output.sinks import Ending


class ScratchTape:
    """A head's scratch tape: a sink for the first pass, a block reader for the second."""

    def __init__(self, head: int) -> None:
        self.head = head
        handle, self.path = tempfile.mkstemp(prefix=f"gecent-head{head}-", suffix=".tape")
        self.file: BinaryIO | None = os.fdopen(handle, "wb")
        self.blocks = 0

    def block(self, block: Block, line: str | None) -> None:
        block.head = self.head
        assert self.file is not None
        # one pickle per block: a shared pickler's memo would hold every block dumped
        pickle.dump(block, self.file, protocol=pickle.HIGHEST_PROTOCOL)
        self.blocks += 1

    def close(self, ending: Ending) -> None:
        """End of the first pass: the end-of-file mark (the tape is rewound by reading)."""
        if self.file is not None:
            self.file.close()
            self.file = None
        if not ending.ok:
            self.remove()

    def read(self) -> Iterator[Block]:
        """The blocks in the order they were dumped (CREAD)."""
        with open(self.path, "rb") as tape:
            for _ in range(self.blocks):
                yield pickle.load(tape)

    def remove(self) -> None:
        if self.file is not None:
            self.file.close()
            self.file = None
        with contextlib.suppress(FileNotFoundError):
            os.unlink(self.path)
