"""fanuc-mill: a modern-control machine pack, pure data (fanuc-mill.toml,
docs/modern-controls.md)."""

from gecent.core.families import MachinePack
from gecent.core.hookspecs import Register, hookimpl


@hookimpl
def register_machines(register: Register) -> None:
    register(MachinePack.from_package(__package__ or __name__, "fanuc-mill.toml"))
