"""MACF40: the sample multiaxis mill's special functions (manual §5.6.8.4, MACF40, seed 001
L28062-28177; spec 07 §10.4, worked examples WE-18 and WE-19).

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

The slide-limit test (MCHCON 2, with overcentre cutting) needs the A and C axes of
multiaxis motion and is not registered: the standard test runs instead.

Decisions (docs/decisions.md): DATACL(6) and DATACL(7) are the CYCLE statement's first and
second numbers; TLHEAD is 0 (one head) until multihead processing sets it.
"""

from __future__ import annotations

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
            },
            description="the sample multiaxis mill's tool, load, cycle and FROM sequences",
        )
    )
