"""Registers the ACME VMC-1 machine file with gecent."""

from gecent.core.families import MachinePack
from gecent.core.hookspecs import hookimpl


@hookimpl
def register_machines(register):
    register(MachinePack.from_package("acme_mill", "vmc1.toml"))
