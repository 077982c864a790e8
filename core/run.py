"""One postprocessor run: CL records in, command blocks out (manual §3.1 general flow).

The dispatcher handles each record by its type and, for postprocessor statements, by its
major word. A statement whose handler is not built yet stops the run with a "not yet
supported" error naming the statement and its line; nothing is written then.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass, field

from gecent.core.cl.records import (
    Comment,
    Fini,
    PartText,
    Record,
    Statement,
)
from gecent.core.cl.stream import read_cl
from gecent.core.errors import Diagnostic, InputError, NotYetSupported
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.selection import (
    apply_machin_options,
    first_machin,
    parse_machin,
    resolve_machine,
)
from gecent.core.output.block import Block, Code
from gecent.core.plugins import PluginSet


@dataclass
class RunResult:
    machine: MachineDefinition
    blocks: list[Block] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    partno: str = ""
    records: int = 0


class Run:
    """The state of one run and the record dispatch."""

    def __init__(self, machine: MachineDefinition) -> None:
        self.result = RunResult(machine=machine)
        self.finished = False
        self._statements: dict[str, Callable[[Statement], None]] = {
            "PARTNO": self._partno,
            "PPRINT": self._pprint,
            "INSERT": self._insert,
            "MACHIN": self._machin,
        }

    @property
    def machine(self) -> MachineDefinition:
        return self.result.machine

    def warn(self, diagnostic: Diagnostic) -> None:
        self.result.diagnostics.append(diagnostic)
        self.result.blocks.append(
            Block(
                Code.COMMENT, diagnostic.where.record if diagnostic.where else None, diagnostic.text
            )
        )

    def process(self, records: Iterator[Record]) -> RunResult:
        for record in records:
            self.result.records += 1
            if self.finished:
                raise InputError("record after FINI", record.where)
            if isinstance(record, Statement):
                handler = self._statements.get(record.major)
                if handler is None:
                    raise NotYetSupported(f"{record.major} statement", record.where)
                handler(record)
            elif isinstance(record, Fini):
                self.result.blocks.append(Block(Code.FINI, record.number))
                self.finished = True
            elif isinstance(record, Comment | PartText):
                continue
            else:
                kind = type(record).__name__.upper()
                raise NotYetSupported(
                    f"{kind} record (type {_TYPE_NAMES.get(kind, kind)})", record.where
                )
        if not self.finished:
            self.warn(Diagnostic("NO FINI STATEMENT AT THE END OF THE CL FILE"))
        return self.result

    def _partno(self, statement: Statement) -> None:
        text = statement.text or ""
        if not self.result.partno:
            self.result.partno = text
        self.result.blocks.append(Block(Code.PARTNO, statement.number, text))

    def _pprint(self, statement: Statement) -> None:
        self.result.blocks.append(Block(Code.PPRINT, statement.number, statement.text or ""))

    def _insert(self, statement: Statement) -> None:
        self.result.blocks.append(Block(Code.INSERT, statement.number, statement.text or ""))

    def _machin(self, statement: Statement) -> None:
        request = parse_machin(statement)
        if request is None:
            return  # another postprocessor's MACHIN: reported when the machine was chosen
        if request.number is not None and self.machine.number not in (None, request.number):
            self.warn(
                Diagnostic(
                    f"MACHIN/GECENT,{request.number} IGNORED: "
                    f"THE RUN USES MACHINE {self.machine.label}",
                    statement.where,
                )
            )
        changed, notes = apply_machin_options(self.machine, request)
        self.result.machine = changed
        for note in notes:
            self.warn(note)


_TYPE_NAMES = {"MOTION": "5000", "CIRCLE": "3000", "ARELEM": "6000", "MULTIAX": "9000"}


def post(
    path: str, plugins: PluginSet, machine_override: str | MachineDefinition | None = None
) -> RunResult:
    """Select the machine (first pass up to MACHIN, as GEINIT does), then process the file."""
    request, notes = first_machin(read_cl(path, plugins))
    machine = resolve_machine(plugins, machine_override, request)
    run = Run(machine)
    for note in notes:
        run.warn(note)
    return run.process(read_cl(path, plugins))
