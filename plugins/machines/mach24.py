"""MACH24: the sample positioning machine (drill) (manual §5.6.8.1, seed 001 L27600-27680)."""

from gecent.core.families import MachinePack
from gecent.core.hookspecs import Register, hookimpl


@hookimpl
def register_machines(register: Register) -> None:
    register(MachinePack.from_package(__package__ or __name__, "mach24.toml"))
