"""MACH51: the sample multihead lathe (manual §5.6.8.5, seed 001 L28178-28292)."""

from gecent.core.families import MachinePack
from gecent.core.hookspecs import Register, hookimpl


@hookimpl
def register_machines(register: Register) -> None:
    register(MachinePack.from_package(__package__ or __name__, "mach51.toml"))
