"""The statements the event macros wrap (spec 09 §5): TOOLNO, LOADTL and TURRET (tool
change), TRANS (LCS), BREAK, CYCLE (the MACFUN cycle sequence), and OPTYPE and OPNAME,
which only the macro layer gives a meaning. Each takes the run, as the post's own statement
handlers do, so a look-ahead's snapshot of the run carries them unchanged."""

from __future__ import annotations

from typing import Any

from gecent.core.cl.records import Statement, Word
from gecent.core.cl.vocabulary import vocabulary
from gecent.core.errors import Diagnostic
from gecent.core.families import HookPoint
from gecent.core.macros.host import MacroHost
from gecent.core.macros.model import Kind, MacroError, MacroFailure, Phase
from gecent.core.macros.params import LcsParams, NoParams, ToolChangeParams


def tool_change(run: MacroHost, statement: Statement) -> None:
    """TOOLNO, LOADTL and TURRET with the tool change macros around them (§5.4-5.5); the
    first tool change takes the first-tool-change macros when there are any ($FT = 0)."""
    engine = run.macros
    assert engine is not None
    params = _tool_params(statement)
    entry = dict(params.items())  # the values the macro saw first
    if engine.search is not None:
        engine.search.tool_change(run, params.tool_id)
    table = engine.table
    first = engine.sv.get("FT") == 0 and (
        table.event(Kind.FIRST_TOOL_CHANGE, Phase.STARTUP) is not None
        or table.event(Kind.FIRST_TOOL_CHANGE, Phase.SHUTDOWN) is not None
    )
    kind = Kind.FIRST_TOOL_CHANGE if first else Kind.TOOL_CHANGE
    original = run.builtin_statement(statement.major)

    def builtin() -> None:
        try:
            changed = _tool_statement(statement, params, entry)
        except MacroError as error:
            raise _failure(engine, kind, error, statement) from None
        fields = {"record": changed, "values": changed.numbers(), "words": changed.words()}
        hooks = engine.hooks
        if not hooks.macfun(HookPoint.TOOLNO, **fields) and not hooks.macfun(
            HookPoint.LOAD, **fields
        ):
            original(run, changed)
        engine.sv["FT"] = 1  # a tool is in: the shutdown macro may set it to 0 again
        engine.operations.tool_change(params.tool_id)  # a new operation (§9.1)

    engine.event(kind, params, statement, builtin)


def _failure(engine: Any, kind: Kind, error: MacroError, record: Statement) -> MacroFailure:
    """A value the startup macro left that the post cannot take: the macro's error, named."""
    macro = engine.table.event(kind, Phase.STARTUP)
    name = macro.key if macro is not None else kind.value
    return MacroFailure(f"macro {name}: {error}", record.where)


def _tool_params(statement: Statement) -> ToolChangeParams:
    args = statement.args
    numbers = [float(a) for a in args if not isinstance(a, Word)]
    words = statement.words()
    params = ToolChangeParams()
    tool = numbers[0] if numbers else None
    pocket = tool
    if statement.major == "TURRET" and len(args) > 1 and not isinstance(args[1], Word):
        pocket = float(args[1])
    params.set(1, pocket)
    params.set(2, 2.0 if "NEXT" in words else 1.0)
    params.set(3, 2.0)
    params.set(4, 1.0 if "CLW" in words else 2.0 if "CCLW" in words else None)
    params.set(5, statement.value_after("OFSETL"))
    params.set(6, statement.value_after("LENGTH"))
    params.set(7, 2.0 if "LARGE" in words else 1.0 if "SMALL" in words else None)
    params.set(8, 1.0 if "START" in words else None)
    params.set(9, tool)
    params.set(10, statement.value_after("RETAIN"))
    params.set(11, statement.value_after("DIAMET"))
    params.set(12, statement.value_after("TIMES"))
    setool = _after_three(args, "SETOOL")
    for number, value in zip((13, 14, 15), setool, strict=True):
        params.set(number, value)
    params.set(16, statement.value_after("ATANGL"))
    params.set(17, statement.value_after("SETANG"))
    params.set(18, 2.0 if "REAR" in words else 1.0 if "FRONT" in words else None)
    params.set(19, 2.0 if "MILL" in words else 1.0 if "TURN" in words else None)
    return params


def _after_three(args: tuple[Any, ...], name: str) -> tuple[float | None, ...]:
    """SETOOL, x, y, z: the three values after the word (None where absent)."""
    for index, arg in enumerate(args):
        if isinstance(arg, Word) and arg.name == name:
            values = [a for a in args[index + 1 : index + 4] if not isinstance(a, Word)]
            return tuple([float(v) for v in values] + [None] * (3 - len(values)))
    return (None, None, None)


# what the post's own tool change takes from a changed $P (core/tool.py): the tool, the
# turn of the drum, OFSETL, LENGTH; on TURRET also NOW/NEXT and FRONT/REAR
_TAKEN = frozenset({1, 4, 5, 6, 9})
_TURRET_TAKEN = frozenset({2, 18})
# the values with nothing in the post's tool change to receive them: a change is refused
_NOT_TAKEN = {3: "a manual or automatic change", 7: "a gripper size", 8: "START",
              10: "RETAIN", 11: "DIAMET", 12: "TIMES", 13: "SETOOL", 14: "SETOOL",
              15: "SETOOL", 16: "ATANGL", 17: "SETANG", 19: "TURN/MILL",
              20: "a tool name"}  # fmt: skip


def _tool_statement(
    statement: Statement, params: ToolChangeParams, entry: dict[int, Any]
) -> Statement:
    """The statement with what the startup macro changed (§5.5: the changed $P go to the
    post's tool change): the tool ($P9, or $P1 when it alone changed), the offset ($P5),
    the length ($P6), the turn ($P4), and on TURRET the correction's NOW/NEXT ($P2) and the
    turret FRONT/REAR ($P18). A value written back unchanged is no change."""
    changed = {n for n in params.changed if params[n] != entry.get(n)}
    if not changed:
        return statement
    turret = statement.major == "TURRET"
    taken = _TAKEN | (_TURRET_TAKEN if turret else frozenset())
    refused = sorted(changed - taken)
    if refused:
        number = refused[0]
        what = _NOT_TAKEN.get(number) or (
            "NOW/NEXT (TURRET only)" if number == 2 else
            "FRONT/REAR (TURRET only)" if number == 18 else "a head (gecent has no head changer)"
        )  # fmt: skip
        raise MacroError(
            f"$P{number} ({ToolChangeParams.FIELDS[number].name}) changed to "
            f"{params[number]!r}: {statement.major} on this post has no {what}; the post's "
            f"tool change takes $P{', $P'.join(str(n) for n in sorted(taken))}"
        )
    args = list(statement.args)
    tool = params.tool_id if 9 in changed or 1 not in changed else params.pocket
    if turret and 1 in changed and 9 in changed:
        args[1:2] = [float(params.pocket)]
    args[0] = float(tool)
    for number, name in ((5, "OFSETL"), (6, "LENGTH")):
        if number in changed:
            args = _set_after(args, name, params[number])
    for number, words in ((4, {1: "CLW", 3: "CLW", 2: "CCLW", 4: "CCLW"}),
                          (2, {1: "NOW", 2: "NEXT"}), (18, {1: "FRONT", 2: "REAR"})):  # fmt: skip
        if number in changed:
            names = set(words.values())
            args = [a for a in args if not (isinstance(a, Word) and a.name in names)]
            word = words.get(params[number]) if params[number] is not None else None
            if params[number] is not None and word is None:
                raise MacroError(f"$P{number} takes {', '.join(map(str, words))}, not "
                                 f"{params[number]!r}")  # fmt: skip
            if word is not None:
                args.append(_word_of(word))
    return Statement(statement.file, statement.line, statement.number, statement.major,
                     statement.code, tuple(args), statement.text)  # fmt: skip


def _word_of(name: str) -> Word:
    return Word(name, vocabulary().minor_code(name))


def _set_after(args: list[Any], name: str, value: Any) -> list[Any]:
    for index, arg in enumerate(args[:-1]):
        if isinstance(arg, Word) and arg.name == name:
            if value is None:
                return args[:index] + args[index + 2 :]
            return [*args[: index + 1], float(value), *args[index + 2 :]]
    if value is None:
        return args
    return [*args, _word_of(name), float(value)]


NO_LCS_MOTION = -1.0  # $LCSMTN -1: "LCS generated motions are not available"
LCS_MOTION_REFUSED = "LCS MOTION NOT AVAILABLE - TRANS ADJUSTS THE FRAME ONLY"


def trans(run: MacroHost, statement: Statement) -> None:
    """TRANS with the LCS macros around it (§5.8): gecent's immediate LCS change. Its
    $P21 is -1: a translation generates no motion (a macro's other value is warned about
    and the frame is adjusted alone)."""
    engine = run.macros
    assert engine is not None
    original = run.builtin_statement("TRANS")
    numbers = statement.numbers()
    translation = tuple((*(run.units.length(v) for v in numbers), 0.0, 0.0, 0.0)[:3])
    params = LcsParams()
    for number, value in ((1, 1.0), (2, 10.0 if any(translation) else 0.0), (3, 0.0),
                          (4, (1.0, 0.0, 0.0, translation[0], 0.0, 1.0, 0.0, translation[1],
                               0.0, 0.0, 1.0, translation[2])),
                          (5, 0.0), (9, translation), (21, NO_LCS_MOTION)):  # fmt: skip
        params.set(number, value)

    def builtin() -> None:
        if params.motion != NO_LCS_MOTION:
            # $P21 = -1: TRANS only translates, it never turns a rotary axis, so no motion
            # can be asked of it; setting another value gives a diagnostic (004 L512-531)
            run.warn(Diagnostic(f"{LCS_MOTION_REFUSED} ($P21 = {params.motion!r})",
                                statement.where))  # fmt: skip
            params.set(21, NO_LCS_MOTION)
        original(run, statement)

    engine.event(Kind.LCS, params, statement, builtin)


def break_(run: MacroHost, statement: Statement) -> None:
    """BREAK: the break shutdown macro wraps up the old segment, the startup one begins the
    next (§5.3: shutdown first)."""
    engine = run.macros
    assert engine is not None
    original = run.builtin_statement("BREAK")
    shutdown = engine.table.event(Kind.BREAK, Phase.SHUTDOWN)
    startup = engine.table.event(Kind.BREAK, Phase.STARTUP)
    if shutdown is not None:
        engine.run_event(shutdown, NoParams(), statement)
    original(run, statement)
    if startup is not None:
        engine.run_event(startup, NoParams(), statement)


def cycle_statement(run: MacroHost, statement: Statement) -> None:
    """CYCLE: the machine's MACFUN cycle sequence first (MCHCON 7)."""
    engine = run.macros
    if engine.hooks.macfun(
        HookPoint.CYCLE, record=statement, values=statement.numbers(), words=statement.words()
    ):
        if "OFF" in statement.words():
            # the MACFUN ends the cycle on the tape; the run's cycle in force ends with it, or
            # the points after CYCLE/OFF would still be drilled
            run.cycle = None
            run.cycle_first_z = None
        return
    run.builtin_statement("CYCLE")(run, statement)


def optype(run: MacroHost, statement: Statement) -> None:
    """OPTYPE/type[, args]: the operation event (§5.9); a word the post alone does not
    know (without macros it is warned about and disregarded)."""
    run.macros.operation_event(statement)


def opname(run: MacroHost, statement: Statement) -> None:
    """OPNAME/name: $OPNAME and the operation table's name column (§9.2)."""
    name = statement.text or " ".join(str(a) for a in statement.args)
    operations = run.macros.operations
    operations.opname = name
    if not operations.full:
        operations.tab.put(5, operations.oi, name)


STATEMENT_HOOKS = {
    "OPTYPE": optype,
    "OPNAME": opname,
    "CYCLE": cycle_statement,
    "TOOLNO": tool_change,
    "LOADTL": tool_change,
    "TURRET": tool_change,
    "TRANS": trans,
    "BREAK": break_,
}
