"""GEOUT1, the summary printout (manual §3.5.4, 001 L9410-9582).

One line per block under a title of the machine's registers, then the absolute (option
172 = 0) or operator (= 1) columns, F-IPM (F-MPM when metric) and S-RPM; cut and dwell
times at the bottom of every page and the tape length on the last one. Pages hold option
79 lines (the title lines not counted).
"""

from __future__ import annotations

from dataclasses import dataclass

from gecent.core.hookspecs import Register, hookimpl
from gecent.core.listing import environment
from gecent.core.machine.definition import MachineDefinition
from gecent.core.output.block import TEXT_CODES, Block
from gecent.core.output.tape import tape_feet, tape_lines

ABSOLUTE_AXES = ((3, "X"), (4, "Y"), (5, "Z"), (6, "A"), (7, "B"), (18, "C"))


def heading(machine: MachineDefinition) -> str:
    registers = machine.registers
    words = [registers.letters[i] for i in registers.present() if i not in (15, 19, 20)]
    prefix = "OPR" if machine.number_option(172) == 1 else "ABS"
    words += [
        f"{prefix}-{letter}" for i, letter in ABSOLUTE_AXES if registers.formats[i] is not None
    ]
    words.append("F-MPM" if machine.number_option(138) == 1 else "F-IPM")
    words.append("S-RPM")
    if machine.number_option(143) == 0:
        words.append("CLREC")
    return " ".join(words)


@dataclass(frozen=True)
class Geout1:
    number: int = 1
    name: str = "GEOUT1"
    section: str = "§3.5.4"
    template: str = "geout1.j2"

    def line(self, block: Block) -> str:
        if block.code in TEXT_CODES:
            return block.text or ""
        raise ValueError(f"GEOUT1 cannot print a CODE {int(block.code)} block yet")

    def render(
        self,
        machine: MachineDefinition,
        blocks: list[Block],
        partno: str,
        cut_minutes: float = 0.0,
        dwell_minutes: float = 0.0,
    ) -> str:
        lines = [self.line(block) for block in blocks if block.printed]
        per_page = max(1, int(machine.number_option(79)))
        pages = [
            {"number": n + 1, "lines": lines[start : start + per_page]}
            for n, start in enumerate(range(0, max(len(lines), 1), per_page))
        ]
        title = machine.title or (
            f"MACHINE {machine.number}" if machine.number else "STANDARD MACHINE"
        )
        return (
            environment()
            .get_template(self.template)
            .render(
                pages=pages,
                title=title,
                partno=partno,
                heading=heading(machine),
                cut_minutes=cut_minutes,
                dwell_minutes=dwell_minutes,
                tape_feet=tape_feet(tape_lines(blocks)),
            )
        )


@hookimpl
def register_printouts(register: Register) -> None:
    register(Geout1())
