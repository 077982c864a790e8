"""Machine definitions (manual §5.6): tables TABLEG, TABLEM, REGSTR, REGFOR, OPTAB,
the shared SRTAB/FRTAB store and TAG, loaded from TOML and validated once at load time."""

from gecent.core.machine.definition import MachineDefinition, RegisterSet
from gecent.core.machine.loader import load_machine_file, load_machine_text, standard_machine

__all__ = [
    "MachineDefinition",
    "RegisterSet",
    "load_machine_file",
    "load_machine_text",
    "standard_machine",
]
