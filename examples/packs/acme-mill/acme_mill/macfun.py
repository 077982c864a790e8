"""MACFUN of the ACME VMC-1: warn when the FROM point is not the tool-change position."""

from gecent.core.families import HookPoint, HookResult, Macfun
from gecent.core.hookspecs import hookimpl

TOOL_CHANGE_POSITION = (0.0, 0.0, 10.0)


def check_from_point(context):
    point = tuple(context.point[:3])
    if any(abs(a - b) > 1e-4 for a, b in zip(point, TOOL_CHANGE_POSITION, strict=True)):
        context.warn("FROM POINT IS NOT THE TOOL CHANGE POSITION 0,0,10")
    return HookResult.CONTINUE


@hookimpl
def register_macfuns(register):
    register(
        Macfun(
            name="acme-vmc1",
            machine="acme-vmc1",
            section="5.6.7 (MCHCON 8, FROM point test)",
            handlers={HookPoint.FROM: check_from_point},
            description="FROM point must be the tool-change position",
        )
    )
