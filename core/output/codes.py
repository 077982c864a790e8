"""Groups of block CODEs the OUTPUT element and the printouts treat alike (manual §3.2-3.3,
001 L629-823)."""

from __future__ import annotations

from gecent.core.output.block import Code

CIRCLE_CODES = frozenset(
    {
        Code.CIRCLE_XY_CLW,
        Code.CIRCLE_XY_CCLW,
        Code.CIRCLE_ZX_CLW,
        Code.CIRCLE_ZX_CCLW,
        Code.CIRCLE_YZ_CLW,
        Code.CIRCLE_YZ_CCLW,
    }
)
MOTION_CODES = frozenset({Code.LINEAR}) | CIRCLE_CODES
POSITION_CODES = frozenset({Code.POSITION_XY, Code.POSITION_Z})
THREAD_CODES = frozenset({Code.THREAD_5, Code.THREAD_6})
# blocks that move the tool (their G and F are modal) and blocks of absolute positions
MOVING_CODES = MOTION_CODES | POSITION_CODES | {Code.ROTARY_INCREMENTAL, Code.CYCLE}
ABSOLUTE_CODES = POSITION_CODES | {Code.CYCLE}
# blocks whose absolute positions replace their departures under option 251 = 1
PLACED_CODES = MOTION_CODES | THREAD_CODES
# blocks whose cells 3..10 are registers already, not internal axes for SHUFFL
UNSHUFFLED = frozenset({Code.DWELL})
# numeric blocks that get TABLEG(5) when they have no G and option 38 = +-1 (001 L24890-24907)
G_FILLED = frozenset({Code.NONMOTION, Code.AUX_ONLY, Code.END, Code.DWELL, Code.AUX_HEAD_IPM})
