"""The Standard Machine (manual §5.6.6): every table at its standard value.

Used when a CL file has no MACHIN statement and no --machine is given.
"""

from gecent.core.families import MachinePack
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.loader import STANDARD_RESOURCE


@hookimpl
def register_machines(register: Register) -> None:
    register(MachinePack.from_package(*STANDARD_RESOURCE))
