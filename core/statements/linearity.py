"""LINTOL (manual §3.4.7.3, 001 L6980-7043; spec 03 §15.3): the linearity test of multiaxis
moves. LINTOL/r[,gamma] sets the tolerance sphere's radius r and the cone's half-angle
gamma in degrees (none: no cone test; 0: the cone cancelled); LINTOL/0 cancels the test;
LINTOL/OFF leaves one-point CL records untested, LINTOL/ON tests them again. The test
itself is core/motion/linearity.py."""

from __future__ import annotations

from typing import TYPE_CHECKING

from gecent.core.cl.records import Statement, Word
from gecent.core.errors import InputError

if TYPE_CHECKING:
    from gecent.core.dispatch.context import Post


def lintol(run: Post, statement: Statement) -> None:
    rule = run.state.linearity
    args = statement.args
    usage = "LINTOL expects r[,gamma] (radius and cone half-angle, 0 or more), 0, ON or OFF"
    if len(args) == 1 and isinstance(args[0], Word):
        if args[0].name not in ("ON", "OFF"):
            raise InputError(usage, statement.where)
        rule.one_point_records = args[0].name == "ON"
        return
    if not 1 <= len(args) <= 2 or any(isinstance(a, Word) or a < 0 for a in args):
        raise InputError(usage, statement.where)
    radius = float(args[0])  # type: ignore[arg-type]
    rule.radius = run.units.length(radius)
    rule.one_point_records = True  # LINTOL/r turns one-point testing back on
    # LINTOL/r is the sphere test only (the cone omitted: "need not specify gamma if he does
    # not wish cone testing", 001 L6936-6946); LINTOL/r,0 cancels the cone too
    rule.cone = None
    if radius > 0.0 and len(args) == 2:
        cone = float(args[1])  # type: ignore[arg-type]
        rule.cone = cone if cone > 0.0 else None


HANDLERS = {"LINTOL": lintol}
