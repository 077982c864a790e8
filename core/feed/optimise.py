"""Feed optimisation that keeps the programmed feed when a linear block's command would
exceed its maximum (manual §4.1.5, 001 L11898-12529): G-code segmentation (option 170,
TSTFCM) and the feedrate multiplier constant (option 26 = 0); and the 100S's metric
I, J, K feed command for long linear moves (option 224, 001 L26729-26738)."""

from __future__ import annotations

from gecent.core.errors import MachineDefinitionError
from gecent.core.feed.contour import FeedCommand
from gecent.core.machine.definition import MachineDefinition
from gecent.core.motion.gcode import LinearCodes
from gecent.core.motion.segments import segment_place, segments
from gecent.core.output.block import Block, Code


class FeedOptimiser:
    def __init__(
        self,
        machine: MachineDefinition,
        codes: LinearCodes,
        feed: FeedCommand,
        shuffle: tuple[tuple[int, int] | None, ...],
    ) -> None:
        contouring = machine.number_option(1) == 0
        self.step = machine.number_option(14)
        self.codes = codes
        self.feed = feed
        self.shuffle = shuffle
        # option 170 = 1: G-code segmentation of command-limited feed moves (option 10 = 0)
        self.segmenting = (
            machine.number_option(170) == 1 and machine.number_option(10) == 0 and contouring
        )
        # option 26 = 0: the feedrate multiplier constant, on a contouring machine
        self.multiplying = machine.number_option(26) == 0 and contouring
        # option 224 = N: a linear move with a departure over N takes its feed command from
        # I, J, K (the 100S in metric, option 26 = 1)
        self.ijk_minimum = machine.number_option(224)
        if self.ijk_minimum > 0:
            _check_ijk_machine(machine)
        registers = machine.registers
        self.offset_capacity = {
            location: 10**fmt.left - 10**-fmt.right
            for location in (8, 9, 10)
            if (fmt := registers.formats[location]) is not None
        }
        self.offset_places = {
            location: fmt.right
            for location in (8, 9, 10)
            if (fmt := registers.formats[location]) is not None
        }

    def segmented(self, block: Block, ipm: float) -> list[Block] | None:
        """TSTFCM (option 170 = 1, §4.1.5.1, 001 L11920-11987): a linear block whose feed
        command would exceed option 24 is cut into the fewest equal segments that a smaller
        dimension code can carry with a command within it, trying each smaller code in
        turn; None keeps the block whole (and the command is limited as usual)."""
        assert block.steps is not None and block.position is not None
        largest = max(abs(s) for s in block.steps)
        code = self.codes.select(largest)
        length = sum((s * self.step) ** 2 for s in block.steps) ** 0.5
        if code.gdimul * ipm / length <= self.feed.maximum:
            return None
        for candidate, limit in self.codes.smaller(code):
            count = int(largest / limit) + 1  # every departure / count under the limit
            if candidate.gdimul * ipm * count / length > self.feed.maximum:
                continue
            start = [p - s for p, s in zip(block.position, block.steps, strict=True)]
            parts = []
            for index, steps in enumerate(segments(block.steps, count)):
                start = [a + s for a, s in zip(start, steps, strict=True)]
                part = Block.motion(Code.LINEAR, block.record or 0, steps, tuple(start), self.step)
                part.segment = segment_place(index, count, block.segment)
                parts.append(part)
            return parts
        return None

    def multiplied(
        self, block: Block, ipm: float, gdimul: float, length: float, size_class: int
    ) -> tuple[float, float, float | None] | None:
        """Option 26 = 0 (§4.1.5.2, 001 L12440-12529): the command divided by c and the
        departures times c in I, J, K, if every product fits its register; otherwise None
        (the command is limited)."""
        found = self.feed.multiplier(ipm, gdimul, length, size_class)
        if found is None:
            return None
        constant, command, f_format = found
        assert block.steps is not None
        products = {}
        for axis, steps in enumerate(block.steps):
            if steps == 0:
                continue
            target = self.shuffle[3 + axis]
            capacity = self.offset_capacity.get(target[0]) if target is not None else None
            value = abs(steps) * self.step * constant
            if capacity is None or value > capacity:
                return None
            products[8 + axis] = value
        for cell, value in products.items():
            block.cells[cell] = value
        return command, ipm, f_format

    def ijk_command(
        self, block: Block, ipm: float, gdimul: float, length: float, size_class: int
    ) -> tuple[float, float, float | None] | None:
        """Option 224 = N (001 L26729-26738; docs/decisions.md): a linear block whose largest
        departure is over N carries its departures over 10^k in I, J, K (unsigned, as the
        multiplier constant's products) and the command times 10^k, k as large as the
        command's maximum allows and no product smaller than the register's last place.
        None leaves the block as it is (a short move, a command already near its maximum,
        or no I, J, K register for an axis it moves)."""
        assert block.steps is not None
        largest = max(abs(s) for s in block.steps) * self.step
        if largest <= self.ijk_minimum:
            return None
        found = self.feed.decimal_shift(ipm, gdimul, length, size_class)
        if found is None:
            return None
        shift, command, f_format = found
        products = {}
        for axis, steps in enumerate(block.steps):
            if steps == 0:
                continue
            target = self.shuffle[3 + axis]
            places = self.offset_places.get(target[0]) if target is not None else None
            if places is None:
                return None
            value = abs(steps) * self.step / 10**shift
            if value < 10**-places:
                return None  # the direction would be lost in the register's rounding
            products[8 + axis] = value
        for cell, value in products.items():
            block.cells[cell] = value
        return command, ipm, f_format


def _check_ijk_machine(machine: MachineDefinition) -> None:
    """Option 224 is "applicable only to 100S control in the metric system. Option 26 must
    equal 1" (001 L26729-26738)."""
    wanted = {165: (1.0, "a 100S control"), 138: (1.0, "the metric system"), 26: (1.0, "")}
    for number, (value, what) in wanted.items():
        if machine.number_option(number) != value:
            reason = f" ({what})" if what else ""
            raise MachineDefinitionError(
                machine.origin,
                "optab",
                224,
                f"option 224 = {machine.number_option(224):g} needs option {number} = "
                f"{value:g}{reason}, found {machine.number_option(number):g}",
            )
