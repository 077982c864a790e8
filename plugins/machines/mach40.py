"""MACH40: the sample multiaxis mill (manual §5.6.8.4, seed 001 L27867-28177).

Its MACFUN, MACF40, is the plugin gecent.plugins.macfuns.macf40.
"""

from gecent.core.families import MachinePack
from gecent.core.hookspecs import Register, hookimpl


@hookimpl
def register_machines(register: Register) -> None:
    register(MachinePack.from_package(__package__ or __name__, "mach40.toml"))
