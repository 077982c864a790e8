"""Tape reels and the BREAK sequence (options 134 and 135, 001 L25976-25994; BREAK, CODE -6,
001 L9271-9282; RDPART and REELNO, L18108-18116).

The punched tape is counted reel by reel, as PPUNCH counts it for the footage (every tape
line's frames, the readable identification not included). Once the reel passes option 135's
minimum footage, the next BREAK statement breaks the tape there; a reel that would pass
option 134's maximum with no BREAK is broken before the block that would pass it, with a
warning. The sequence (docs/decisions.md; the manual's §4.7 that tells it is not in it):

* the end-of-record code (option 65) in a block by itself, where the reader stops the old
  reel, as TMARK punches it, and a foot of leader (option 64) after it;
* the new reel's heading: "REEL n" printed, and on the punch the readable PARTNO followed
  by the reel number ("punched into each new tape reel", "printed and punched in readable
  format");
* a foot of leader to start the new reel.

Either option at 0 ignores its part of the sequence: 135 = 0, BREAK never breaks the tape;
134 = 0, no reel is broken for its length.
"""

from __future__ import annotations

from gecent.core.machine.definition import MachineDefinition
from gecent.core.output.block import Block, Code
from gecent.core.output.marks import leader_block, stand_in
from gecent.core.output.modern import modern_output
from gecent.core.output.tape import FRAMES_PER_INCH, line_frames

FRAMES_PER_FOOT = 12 * FRAMES_PER_INCH
BREAK_LEADER_INCHES = 12.0  # trailer of the old reel and lead-in of the new one


def tape_reels(machine: MachineDefinition) -> Reels | None:
    """The reel counting the machine asks for, or None when both options are 0 or the
    tape is a program for a modern control: it is loaded whole into the control, and its
    end-of-record code (ASCII "%") would end the program (docs/decisions.md)."""
    maximum = machine.number_option(134)
    minimum = machine.number_option(135)
    if (maximum <= 0 and minimum <= 0) or modern_output(machine):
        return None
    return Reels(machine, maximum, minimum)


class Reels:
    """The footage of the reel being punched and the blocks of a tape break."""

    def __init__(self, machine: MachineDefinition, maximum: float, minimum: float) -> None:
        self.machine = machine
        self.leader = stand_in(machine, 64)
        self.maximum = round(maximum * FRAMES_PER_FOOT) if maximum > 0 else None
        self.minimum = round(minimum * FRAMES_PER_FOOT) if minimum > 0 else None
        self.reel = 1
        self.frames = 0  # on this reel
        self.holds_blocks = False  # a block of the program is on this reel
        self.ending = False  # a break's blocks are passing: the old reel's end, not its length
        # the automatic breaks, for the run's warnings: the text and the CL record it came at
        self.notes: list[tuple[str, int | None]] = []

    @property
    def feet(self) -> float:
        return self.frames / FRAMES_PER_FOOT

    def frames_of(self, line: str) -> int:
        return line_frames(line, self.leader)

    def count(self, line: str, frames: int) -> None:
        self.frames += frames
        if not self.ending and line and frames > len(line):  # a block (it has its EOB)
            self.holds_blocks = True

    def overflows(self, frames: int) -> bool:
        """A line of ``frames`` would take a reel holding blocks past option 134's
        maximum."""
        return (
            self.maximum is not None
            and not self.ending
            and self.holds_blocks
            and self.frames + frames > self.maximum
        )

    def breakable(self) -> bool:
        """A BREAK statement breaks the tape: the reel has passed option 135's minimum."""
        return self.minimum is not None and not self.ending and self.frames >= self.minimum

    def break_blocks(self, record: int | None, automatic: bool = False) -> list[Block]:
        """The blocks of a tape break (the module's docstring); the count moves to the new
        reel when its heading passes (:meth:`new_reel`)."""
        if automatic:
            self.notes.append(
                (
                    f"TAPE REEL {self.reel} WOULD PASS {self.maximum_feet:g} FEET (OPTION 134) "
                    f"AND NO BREAK STATEMENT BROKE IT: THE TAPE IS BROKEN AT {self.feet:.1f} "
                    f"FEET, REEL {self.reel + 1} FOLLOWS",
                    record,
                )
            )
        self.ending = True
        end = Block(Code.TMARK, record)
        end.cells[15] = float(int(Code.TMARK))
        end.punch = stand_in(self.machine, 65)
        heading = Block(Code.PPRINT, record, f"REEL {self.reel + 1}")
        heading.reel = self.reel + 1
        return [
            end,
            leader_block(self.machine, BREAK_LEADER_INCHES, record, None),
            heading,
            leader_block(self.machine, BREAK_LEADER_INCHES, record, None),
        ]

    def new_reel(self, number: int) -> None:
        self.reel = number
        self.frames = 0
        self.holds_blocks = False
        self.ending = False

    @property
    def maximum_feet(self) -> float:
        return (self.maximum or 0) / FRAMES_PER_FOOT
