"""A plugin whose registration hook raises, and one that registers a bad spindle type."""

from gecent.core.hookspecs import hookimpl


class BadSpindle:
    number = 42
    name = "type 42"
    section = "§4.5"


@hookimpl
def register_printouts(register):
    raise RuntimeError("printout template missing")


@hookimpl
def register_spindle_types(register):
    register(BadSpindle())
