"""MACH04: the sample lathe (manual §5.6.8.2, seed 001 L27681-27799)."""

from gecent.core.families import MachinePack
from gecent.core.hookspecs import Register, hookimpl


@hookimpl
def register_machines(register: Register) -> None:
    register(MachinePack.from_package(__package__ or __name__, "mach04.toml"))
