"""A motion macro's changed helical component ($P19, spec 09 §5.7, 002 L649-651: "useful if
post-processing for systems that cannot drive a helix").

$P19 is an arc's travel along its axis, in machine units (0 for a planar arc). Changed on
a one-point arc (the CAM form, the only one gecent makes a helix of: core/motion/circle.py),
the arc rises $P19 from its start (0: it stays in its start's plane) and a straight move
at feed takes the tool on to the programmed end, so the path still ends where the CL file
says. On any other motion the change is the macro's error."""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from gecent.core.cl.records import Motion, MotionSubtype
from gecent.core.macros.model import MacroError

NORMAL_AXIS = {0: 2, 1: 1, 2: 0}  # a circle's plane (XY, ZX, YZ): the axis along its normal


def helical_changed(hooks: Any, record: Motion, helical: Any, travel: float) -> None:
    """The arc of ``record`` with its helical component changed from ``travel`` to
    ``helical``; ``hooks`` is the run's EventHooks (its post motion, after MACFUN)."""
    run = hooks.run
    circle = run._circle
    if circle is None or circle.centre is None or record.subtype is not MotionSubtype.GOTO:
        raise MacroError("$P19 (helical) is an arc's: this motion is not one")
    if len(record.points) != 1 or not isinstance(helical, int | float):
        raise MacroError(
            f"$P19 (helical) changes a one-point arc by a number, not {helical!r} on an arc "
            f"of {len(record.points)} points"
        )
    normal = NORMAL_AXIS[circle.plane]
    end = record.points[0]
    raised = list(end)
    raised[normal] = end[normal] - (travel - float(helical)) / run.units.length(1.0)
    hooks._motion_builtin(replace(record, points=(tuple(raised),)))
    if circle.collecting:
        circle.finish()
    circle.centre = None  # the rest is no arc
    hooks._motion_builtin(record)
