"""The clearance test between the heads (options 158 and 159, manual §5.6.5, 001
L26239-26257): "clearance between heads on the second (first) axis by CLTAPE order", 0 =
none, N = the clearance in inches.

The write-up of the test is not in the seeds; gecent's reading (docs/decisions.md): the
merge pass knows where both heads stand after every block it puts out (ABS2/ABS3), so it
tests there. The heads come too close when they are nearer than the clearance on every
axis that has one: X (the first CL axis) for option 159, Y (the second) for option 158;
with both options the clearances are a box about one head, which the other may not enter.
Each time the heads enter that box, a postprocessor comment names the block, the heads'
distances and the clearances; the program is not changed (the part programmer moves the
heads apart, or orders the operations so that they are not together there).
"""

from __future__ import annotations

from collections.abc import Callable

from gecent.core.machine.definition import MachineDefinition


class ClearanceTest:
    """Options 158 and 159 in the merge pass: warns when the heads come too close."""

    def __init__(self, machine: MachineDefinition, step: float) -> None:
        self.step = step
        # (CL axis, option, clearance): the first axis by CLTAPE order is X, the second Y
        given = ((0, 159, machine.number_option(159)), (1, 158, machine.number_option(158)))
        self.clearances = tuple(c for c in given if c[2] > 0)
        self.inside = False  # the heads are within the clearances now (warned once)

    @property
    def active(self) -> bool:
        return bool(self.clearances)

    def check(
        self,
        first: tuple[int, ...] | None,
        second: tuple[int, ...] | None,
        record: int | None,
        say: Callable[[str, int | None], None],
    ) -> None:
        """The heads' points (steps, CL axis order) after a block: a comment when they have
        come within the clearances."""
        if not self.clearances or first is None or second is None:
            return
        distances = []
        for axis, option, clearance in self.clearances:
            if axis >= len(first) or axis >= len(second):
                return  # (a machine without the axis: no test)
            distance = abs(first[axis] - second[axis]) * self.step
            if distance >= clearance:
                self.inside = False
                return
            distances.append((axis, option, clearance, distance))
        if self.inside:
            return
        self.inside = True
        words = ", ".join(
            f"{'XYZ'[axis]} {distance:.4f} IN (OPTION {option} = {clearance:g})"
            for axis, option, clearance, distance in distances
        )
        where = f"CL RECORD {record}" if record is not None else "THE MERGE PASS"
        say(f"HEADS 1 AND 2 WITHIN THEIR CLEARANCE AFTER {where}: {words}", record)
