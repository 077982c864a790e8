"""MACF40: the sample multiaxis mill's special functions (manual §5.6.8.4, MACF40, seed 001
L27984-28177; spec 07 §10.4, worked examples WE-18 and WE-19).

* **TOOLNO (MCHCON 1).** The first call records the loaded tool, later calls the selected
  one, each with its gripper (large when the statement names LARGE, ICLDAT(6) = 7) and its
  length; the T word is suppressed: the tool change is done, nothing is output.
* **LOAD (MCHCON 6).** The tool goes back to the change point: the machine position becomes
  X -19 (-29 with the second head, TLHEAD), Y 48, Z 48.75, A -25, and the normal LOAD goes on.
  (The LOAD statement itself is not built yet: the handler is reached by a run once it is.)
* **CYCLE (MCHCON 7).** The control's cycle codes: G51 + DATACL(6)/2 for CYCLE/OFF, G55 +
  DATACL(6)/2 for TAP, none for OUT and IN; and the feed code 0..9 from the ASFTAB feed
  table in register 17 (H), in a block of its own (CODE -4). Other cycles go on normally.
* **FROM (MCHCON 8).** A FROM point other than the home position (X -19, or -29 with the
  second head; Y 48; Z 31.75; A -25 or 25) is warned about.

* **Slide limits (MCHCON 2).** With option 110 != 0, the machine's slides (DPRESM, the
  transformed point) against MACF40's own windows: X -19..29 (-29..19 with the second head);
  for Y < 0 "overcenter cutting" (the table turned half a revolution) X and Y are mirrored and
  X is tested again; Z by Y's band (Y < 6: Z >= 19; 6 <= Y < 30: Z >= 11.75; 30 <= Y <= 48:
  Z >= 5.625; always Z <= 53.625); Y > 48 is out. A violation is RETURN = 1: with option
  110 > 0 the slide-limit comment (the run's punch withheld under 110 = 2, as TSTLIM's), with
  option 110 < 0 ERROR = 101 through ERDMP1, fatal. No violation: RETURN = 0, the standard test
  of options 121-126 goes on. The head's forbidden A zones (labels 331-338, and the A-only
  test of a CODE 2 block) are not tested: the hook is given the slides, not the A position,
  and the statement after label 338 is lost in the scan.

Decisions (docs/decisions.md): DATACL(6) and DATACL(7) are the CYCLE statement's first and
second numbers; TLHEAD is 0 (one head) until multihead processing sets it.
"""

from __future__ import annotations

from gecent.core.errors import FatalError, SourcePosition
from gecent.core.families import HookPoint, HookResult, Macfun
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.macros.macfun import MacfunContext
from gecent.core.output.block import Block, Code

ASFTAB = (1.0, 1.40, 1.95, 2.75, 3.85, 5.40, 7.50, 10.6, 14.8, 20.7)
FEED_CODE_REGISTER = 17
CYCLE_OFF_G, TAP_G = 51.0, 55.0
EPSILON = 1e-4
FROM_WARNING = "THE FROM POINT IS NOT THE HOME POSITION"


def _memory(context: MacfunContext) -> dict[str, float]:
    """MACF40's own variables (its DATA and COMMON values), kept for the run."""
    return context.data.setdefault("macf40", {})  # type: ignore[no-any-return]


def _head(context: MacfunContext) -> float:
    return float(_memory(context).get("TLHEAD", 0.0))


def tool_sequence(context: MacfunContext) -> HookResult:
    """MCHCON 1 (L28073-28086)."""
    memory = _memory(context)
    tool = context.values[0] if context.values else 0.0
    grip = 1.0 if "LARGE" in context.words else 0.0
    length = float(context.state.tool.offset or 0.0)
    if memory.get("FORK", 0.0) == 0.0:
        memory.update(TOLLOD=tool, GRPLOD=grip, TOLDLN=length, FORK=1.0)
    else:
        memory.update(TOLSLC=tool, GRPSLC=grip, SLTOLN=length)
    return HookResult.HANDLED


def load_sequence(context: MacfunContext) -> HookResult:
    """MCHCON 6 (L28120-28128): back to the change point; the normal LOAD continues."""
    x = -29.0 if _head(context) != 0.0 else -19.0
    position = context.state.position
    step = context.machine.number_option(14)
    for axis, value in enumerate((x, 48.0, 48.75, -25.0)):
        position.present[axis] = round(value / step)
    return HookResult.CONTINUE


def feed_code(feed: float) -> int:
    """DBFSEG(17) = ROW - 1 from ASFTAB (WE-18)."""
    if feed <= ASFTAB[0]:
        return 0
    for index in range(1, len(ASFTAB)):
        if feed == ASFTAB[index]:
            return index  # ROW = I + 1, the code is ROW - 1
        if feed < ASFTAB[index]:
            return index - 1
    return len(ASFTAB) - 1


CYCLE_TYPES = {"OFF": 0, "TAP": 3, "OUT": 7, "IN": 8}


def cycle_sequence(context: MacfunContext) -> HookResult:
    """MCHCON 7 (L28129-28161)."""
    memory = _memory(context)
    values = context.values
    datacl6 = values[0] if values else 0.0
    datacl7 = values[1] if len(values) > 1 else 0.0
    if datacl7 != 0.0:
        memory["CYFED"] = datacl7
    kind = next((CYCLE_TYPES[w] for w in context.words if w in CYCLE_TYPES), None)
    if kind is None:
        return HookResult.CONTINUE  # the other cycles: normal processing
    block = Block(Code.G_ONLY, context.record.number if context.record else None)
    if kind in (0, 3):
        block.cells[2] = (CYCLE_OFF_G if kind == 0 else TAP_G) + datacl6 / 2.0
    block.cells[FEED_CODE_REGISTER] = float(feed_code(memory.get("CYFED", 0.0)))
    context.output(block)
    return HookResult.HANDLED


def from_test(context: MacfunContext) -> HookResult:
    """MCHCON 8 (L28162-28177): the FROM point against the home position."""
    x, y, z = context.machine_point[:3]
    home_x = -29.0 if _head(context) != 0.0 else -19.0
    if any(abs(a - b) > EPSILON for a, b in ((x, home_x), (y, 48.0), (z, 31.75))):
        context.warn(FROM_WARNING)
    return HookResult.CONTINUE


LIMIT_WARNING = "{} AXIS SLIDE LIMIT HAS BEEN EXCEEDED *** WARNING"  # TSTLIM's (001 L38994)
# the Z windows by Y's band (labels 270-330): (Y below, lowest Z)
Z_FLOORS = ((6.0, 19.0), (30.0, 11.75))
Z_FLOOR_TOP_BAND, Z_CEILING, Y_TOP = 5.625, 53.625, 48.0


def _outside(x: float, y: float, z: float, head: float) -> list[tuple[str, str]]:
    """MACF40's limit tests in its order (labels 205-336): (axis, what) of each failure.
    A failure with option 110 > 0 goes on where the Fortran goes on."""
    low, high = (-29.0, 19.0) if head != 0.0 else (-19.0, 29.0)
    found: list[tuple[str, str]] = []

    def x_test(value: float, what: str) -> bool:
        if low - EPSILON <= value <= high + EPSILON:
            return True
        found.append(("X", f"{what}X {value:g} outside {low:g}..{high:g}"))
        return False

    x_test(x, "")  # 230-235: a failure goes on at 260 (the Fortran tests X as it comes too)
    top_band_only = False
    if y < 0.0:  # 261: overcenter cutting, the table turned half a revolution
        x, y = -x, -y
        top_band_only = not x_test(x, "overcenter (mirrored) ")  # 265: on at 320
    if not top_band_only:
        floor = next((z_low for y_below, z_low in Z_FLOORS if y < y_below), None)
        if floor is None and y > Y_TOP + EPSILON:  # 310: Y beyond the column
            found.append(("Y", f"Y {y:g} above {Y_TOP:g}"))
        elif floor is not None:
            if z < floor - EPSILON:  # 280/300 -> 335 (read as 336)
                found.append(("Z", f"Z {z:g} below {floor:g} with Y {y:g}"))
            elif z > Z_CEILING + EPSILON:
                found.append(("Z", f"Z {z:g} above {Z_CEILING:g}"))
            return found
    if z < Z_FLOOR_TOP_BAND - EPSILON:  # 320
        found.append(("Z", f"Z {z:g} below {Z_FLOOR_TOP_BAND:g} with Y {y:g}"))
    elif z > Z_CEILING + EPSILON:  # 330
        found.append(("Z", f"Z {z:g} above {Z_CEILING:g}"))
    return found


def slide_limit_test(context: MacfunContext) -> HookResult:
    """MCHCON 2 (labels 200-338, 001 L28025-28118): RETURN = 1 when a limit is exceeded."""
    action = context.machine.number_option(110)
    if action == 0.0:
        return HookResult.CONTINUE  # 200: no testing
    x, y, z = context.machine_point[:3]
    found = _outside(x, y, z, _head(context))
    if not found:
        return HookResult.CONTINUE  # RETURN = 0: the standard test goes on
    if action < 0.0:  # 240: ERROR = 101, CALL ERDMP1 at the first failure
        raise FatalError(101, f"MACF40: {found[0][1]}", _where(context))
    for axis in dict.fromkeys(axis for axis, _ in found):
        context.warn(LIMIT_WARNING.format(axis))
    context.run.output.slide_limits.exceeded = True  # option 110 = 2: no punched output
    return HookResult.HANDLED


def _where(context: MacfunContext) -> SourcePosition | None:
    return context.record.where if context.record is not None else None


@hookimpl
def register_macfuns(register: Register) -> None:
    register(
        Macfun(
            name="macf40",
            machine="mach40",
            section="§5.6.8.4 MACF40",
            handlers={
                HookPoint.TOOLNO: tool_sequence,
                HookPoint.LOAD: load_sequence,
                HookPoint.CYCLE: cycle_sequence,
                HookPoint.FROM: from_test,
                HookPoint.SLIDE_LIMITS: slide_limit_test,
            },
            description="the sample multiaxis mill's tool, load, cycle, FROM and slide-limit "
            "sequences",
        )
    )
