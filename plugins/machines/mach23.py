"""MACH23: the sample three-axis mill (manual §5.6.8.3, seed 001 L27800-27866)."""

from gecent.core.families import MachinePack
from gecent.core.hookspecs import Register, hookimpl


@hookimpl
def register_machines(register: Register) -> None:
    register(MachinePack.from_package(__package__ or __name__, "mach23.toml"))
