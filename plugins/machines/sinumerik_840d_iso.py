"""sinumerik-840d-iso: a modern-control machine pack, pure data (sinumerik-840d-iso.toml,
docs/modern-controls.md)."""

from gecent.core.families import MachinePack
from gecent.core.hookspecs import Register, hookimpl


@hookimpl
def register_machines(register: Register) -> None:
    register(MachinePack.from_package(__package__ or __name__, "sinumerik-840d-iso.toml"))
