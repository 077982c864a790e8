"""fanuc-5axis-bc: a five-axis machine pack, pure data (fanuc-5axis-bc.toml,
docs/five-axis.md)."""

from gecent.core.families import MachinePack
from gecent.core.hookspecs import Register, hookimpl


@hookimpl
def register_machines(register: Register) -> None:
    register(MachinePack.from_package(__package__ or __name__, "fanuc-5axis-bc.toml"))
