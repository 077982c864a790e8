"""haas-mill: a modern-control machine pack, pure data (haas-mill.toml,
docs/modern-controls.md)."""

from gecent.core.families import MachinePack
from gecent.core.hookspecs import Register, hookimpl


@hookimpl
def register_machines(register: Register) -> None:
    register(MachinePack.from_package(__package__ or __name__, "haas-mill.toml"))
