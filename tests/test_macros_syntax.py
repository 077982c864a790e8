"""User-defined macros (spec 09 §2, §3, §6): the SDL, matching, precedence, OUTPUT, MATCH,
TERMAC, and the worked examples X12-X16 and X22."""

from __future__ import annotations

import pytest
from gecent.core.cl.records import Word
from gecent.core.errors import InputError
from gecent.core.macros import Kind, Macro, Macros, Phase
from gecent.core.macros.sdl import Form, SdlError, parse_sdl

from .macros_helpers import post, record, warnings

W = lambda name: Word(name, None)  # noqa: E731 - words compare by code, so look them up
HEAD = "PARTNO T\nUNITS/MM\nFROM/0,0,10\n"


def words(values: dict[int, object]) -> dict[int, object]:
    return {n: (v.name if isinstance(v, Word) else v) for n, v in values.items()}


def match(sdl: str, text: str) -> dict[int, object] | None:
    found = parse_sdl(sdl).match(record(text))
    return None if found is None else words(found)


# -- X14: required arguments (002 L1252-1278) -----------------------------------------------


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("SPINDL/400,CLW", {1: 400.0, 2: "CLW"}),
        ("SPINDL/400,CCLW", {1: 400.0, 2: "CCLW"}),
        ("SPINDL/CCLW,400", None),  # $P1 must be numeric
        ("SPINDL/400", None),  # $P2 missing
        ("SPINDL/400,CLW,RANGE,2", None),  # left over and no option takes it (Q12)
    ],
)
def test_x14_required_arguments(text: str, expected: dict[int, object] | None) -> None:
    assert match("SPINDL/$P1,$P2(CLW,CCLW)", text) == expected


# -- X15: optional arguments (002 L1280-1316) -----------------------------------------------

X15 = "SPINDL/$P1,[$P2(SFM,RPM)],[$P3(CLW,CCLW)],[RANGE,$P4]"


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("SPINDL/300,CCLW,RPM,RANGE,3", {1: 300.0, 2: "RPM", 3: "CCLW", 4: 3.0}),
        ("SPINDL/300,RPM,CCLW", {1: 300.0, 2: "RPM", 3: "CCLW", 4: None}),
        ("SPINDL/RPM,CCLW", None),
        ("SPINDL/300", {1: 300.0, 2: None, 3: None, 4: None}),
        ("SPINDL/300,RANGE", None),  # the two-argument option matches only as a unit
        ("SPINDL/300,CLW,CCLW", None),  # an option matches at most once
    ],
)
def test_x15_optional_arguments(text: str, expected: dict[int, object] | None) -> None:
    assert match(X15, text) == expected


# -- X16: the star argument (002 L1318-1350) ------------------------------------------------


def test_x16_star_argument() -> None:
    sdl = "SPINDL/$P1,RANGE,MEDIUM,$P2*"
    assert match(sdl, "SPINDL/200,RANGE,MEDIUM") == {1: 200.0, 2: ()}
    # the manual's continuation: the "$" ends the first line, the next goes on
    found = parse_sdl(sdl).match(record("SPINDL/200,RANGE,MEDIUM,CLW,$\nSFM,MAXRPM,970\n"))
    assert found is not None
    star = found[2]
    assert isinstance(star, tuple) and len(star) == 4  # $FLEN($P2) = 4
    assert [getattr(v, "name", v) for v in star] == ["CLW", "SFM", "MAXRPM", 970.0]


# -- X12, X13: the major word and the argument forms ----------------------------------------


def test_an_sdl_without_arguments_matches_whatever_follows_the_major() -> None:
    assert match("SPINDL", "SPINDL/300,CLW") == {}
    assert match("#*:*", "GOTO/1,2,3") == {}


def test_x12_name_and_class_code_are_one_major() -> None:
    assert parse_sdl("SPINDL").major == parse_sdl("#2000:1031").major == (2000, 1031)
    assert parse_sdl("#2000:*").level == 1 and parse_sdl("#*:*").level == 0
    assert parse_sdl("#*:1031").level == 2 and parse_sdl("SPINDL").level == 3
    assert parse_sdl("GOTO").major == (5000, 5) and parse_sdl("FINI").major == (14000, 0)
    assert parse_sdl("#2000:*").covers((2000, "MYWORD"))


@pytest.mark.parametrize(
    ("sdl", "form", "param"),
    [
        ("X/$P4", Form.NUMBER, 4),
        ("X/$P5()", Form.KEYWORD, 5),
        ("X/$P1(ON,OFF)", Form.KEYWORD, 1),
        ("X/$P3''", Form.STRING, 3),
        ("X/$P12?", Form.ANY_ONE, 12),
        ("X/$P6*", Form.REST, 6),
        ("X/ON", Form.KEYWORD, None),
        ("X/(ON,OFF)", Form.KEYWORD, None),
        ("X/()", Form.KEYWORD, None),
        ("X/''", Form.STRING, None),
        ("X/?", Form.ANY_ONE, None),
        ("X/*", Form.REST, None),
    ],
)
def test_x13_argument_forms(sdl: str, form: Form, param: int | None) -> None:
    item = parse_sdl(sdl).required[0]
    assert (item.form, item.param) == (form, param)


def test_keyword_forms_match_what_they_say() -> None:
    assert match("COOLNT/$P1(ON,OFF)", "COOLNT/ON") == {1: "ON"}
    assert match("COOLNT/$P1(ON,OFF)", "COOLNT/MIST") is None
    assert match("COOLNT/$P1()", "COOLNT/MIST") == {1: "MIST"}
    assert match("COOLNT/$P1()", "COOLNT/3") is None
    assert match("COOLNT/$P1?", "COOLNT/3") == {1: 3.0}
    assert match("PPRINT/$P1''", "PPRINT HELLO THERE") == {1: "HELLO THERE"}
    assert match("GOTO/$P1,$P2,$P3", "GOTO/1,2,3") == {1: 1.0, 2: 2.0, 3: 3.0}
    assert match("MYWORD/$P1", "MYWORD/7") == {1: 7.0}  # a word the post does not know


@pytest.mark.parametrize(
    ("sdl", "column", "message"),
    [
        ("", 1, "empty"),
        ("SPINDL/[$P1", 12, "']'"),
        ("SPINDL/[$P1],$P2", 14, "required argument after an option"),
        ("SPINDL/$P1*,$P2", 1, "last argument"),
        ("SPINDL/$P1,$P1", 12, "named twice"),
        ("SPINDL/$P100", 8, "1 to 99"),
        ("SPINDL/$P1(CLW", 15, "')'"),
        ("/X", 1, "major word"),
    ],
)
def test_a_malformed_sdl_is_refused_with_its_column(sdl: str, column: int, message: str) -> None:
    with pytest.raises(SdlError) as refused:
        parse_sdl(sdl)
    assert f"column {column}:" in str(refused.value) and message in str(refused.value)


def test_a_macro_with_a_bad_sdl_cannot_be_made() -> None:
    with pytest.raises(ValueError, match="SDL"):
        Macro("bad", Kind.SYNTAX, sdl="SPINDL/[")
    with pytest.raises(ValueError, match="startup or shutdown phase"):
        Macro("tc", Kind.TOOL_CHANGE, body=lambda ctx: None)
    with pytest.raises(ValueError, match="takes no phase"):
        Macro("tape", Kind.TAPE, phase=Phase.STARTUP, body=lambda ctx: None)


# -- X22: ignoring and translating ----------------------------------------------------------

X22_INPUT = HEAD.replace("PARTNO T", "PARTNO X22") + (
    "COOLNT/MIST\nCOOLNT/FLOOD\nPENUP\nFEDRAT/100\nGOTO/1,2,3\nFINI\n"
)


def x22_macros() -> Macros:
    macros = Macros(machine="linuxcnc-mill")
    macros.ignore("PENUP")  # no body: every PENUP is ignored, silently

    @macros.syntax("COOLNT/$P1(MIST)")
    def mist_is_flood(ctx):  # type: ignore[no-untyped-def]
        ctx.cmd("COOLNT", "FLOOD")  # no OUTPUT: COOLNT/MIST itself is never processed

    return macros


def test_x22_ignoring_and_translating() -> None:
    tape, result = post(X22_INPUT, x22_macros())
    assert tape == (
        "%\n(X22)\nG17 G21 G90 G94 G40 G49 G80 G54\nN1 G01 X1. Y2. Z3. F100. M08\nN2 M02\n%\n"
    )
    assert warnings(result) == []


def test_x22_without_the_macros_the_post_warns_and_mists() -> None:
    tape, result = post(X22_INPUT, None)
    assert "M07" in tape and any("PENUP" in w for w in warnings(result))


def test_macros_for_another_machine_are_not_used() -> None:
    macros = Macros(machine="fanuc-mill")
    macros.ignore("PENUP")
    _, result = post(X22_INPUT, macros)
    assert any("PENUP" in w for w in warnings(result))


def test_a_translating_macro_does_not_match_its_own_command() -> None:
    """COOLNT/() issuing COOLNT/FLOOD: the macro is active, so the generated record goes to
    built-in processing instead of back into the macro (§6.1, no recursion)."""
    macros = Macros()
    seen: list[str] = []

    @macros.syntax("COOLNT/$P1()")
    def every_coolant(ctx):  # type: ignore[no-untyped-def]
        seen.append(ctx.p[1].name)
        ctx.cmd("COOLNT/FLOOD")

    tape, _ = post(HEAD + "COOLNT/MIST\nGOTO/1,0,0\nFINI\n", macros)
    assert seen == ["MIST"] and "M08" in tape and "M07" not in tape


# -- precedence and OUTPUT chaining (§6.2, §6.7) --------------------------------------------


def test_search_order_and_output_chaining() -> None:
    """Wildcards first (#*:*, #class:*, #*:subclass), then the exact SDL; each OUTPUT hands
    the record to the next inactive match, the last to built-in processing, once."""
    order: list[str] = []
    macros = Macros()
    for sdl in ("SPINDL", "#*:1031", "#2000:*", "#*:*"):  # registered exact first

        def body(ctx, sdl: str = sdl) -> None:  # type: ignore[no-untyped-def]
            if getattr(ctx.record, "major", None) == "SPINDL":
                order.append(sdl)
            ctx.output()

        macros.syntax(sdl, name=sdl)(body)
    tape, _ = post(HEAD + "SPINDL/300\nGOTO/1,0,0\nFINI\n", macros)
    assert order == ["#*:*", "#2000:*", "#*:1031", "SPINDL"]
    assert tape.count("S300") == 1


def test_an_exact_sdl_with_no_match_lets_the_next_one_try() -> None:
    macros = Macros()
    macros.ignore("SPINDL/$P1,CCLW")
    tape, _ = post(HEAD + "SPINDL/300,CLW\nGOTO/1,0,0\nFINI\n", macros)
    assert "S300 M03" in tape


def test_output_with_match_off_goes_straight_to_built_in() -> None:
    outer: list[str] = []
    macros = Macros()

    @macros.syntax("#2000:*", name="a")
    def first(ctx):  # type: ignore[no-untyped-def]
        outer.append("a")
        ctx.match(False)
        ctx.output()

    @macros.syntax("SPINDL", name="b")
    def second(ctx):  # type: ignore[no-untyped-def]
        outer.append("b")

    tape, _ = post(HEAD + "SPINDL/300\nGOTO/1,0,0\nFINI\n", macros)
    assert outer.count("b") == 0 and "S300" in tape


def test_match_off_lets_a_command_bypass_an_inactive_macro() -> None:
    macros = Macros()
    calls: list[str] = []

    @macros.syntax("STOP")
    def stop_means_flood(ctx):  # type: ignore[no-untyped-def]
        calls.append("stop")
        ctx.match(False)
        ctx.cmd("COOLNT/MIST")  # the MIST macro below would translate it

    @macros.syntax("COOLNT/MIST")
    def mist(ctx):  # type: ignore[no-untyped-def]
        calls.append("mist")

    tape, _ = post(HEAD + "STOP\nGOTO/1,0,0\nFINI\n", macros)
    assert calls == ["stop"] and "M07" in tape


def test_match_is_on_again_in_a_nested_macro() -> None:
    macros = Macros()

    @macros.syntax("STOP")
    def stop(ctx):  # type: ignore[no-untyped-def]
        ctx.cmd("OPSTOP")  # matching on: OPSTOP's macro runs

    @macros.syntax("OPSTOP")
    def opstop(ctx):  # type: ignore[no-untyped-def]
        ctx.cmd("COOLNT/MIST")  # its own MATCH starts ON (§2)

    @macros.syntax("COOLNT/MIST")
    def mist(ctx):  # type: ignore[no-untyped-def]
        ctx.cmd("COOLNT/FLOOD")

    tape, _ = post(HEAD + "STOP\nGOTO/1,0,0\nFINI\n", macros)
    assert "M08" in tape and "M07" not in tape and "M00" not in tape and "M01" not in tape


def test_terminate_ends_the_macro() -> None:
    macros = Macros()

    @macros.syntax("COOLNT/$P1()")
    def coolant(ctx):  # type: ignore[no-untyped-def]
        if ctx.p[1].name == "MIST":
            ctx.terminate()  # TERMAC: MIST is dropped
        ctx.output()

    tape, _ = post(HEAD + "COOLNT/MIST\nCOOLNT/FLOOD\nGOTO/1,0,0\nFINI\n", macros)
    assert "M07" not in tape and "M08" in tape


def test_a_macro_gives_meaning_to_a_word_the_post_does_not_know() -> None:
    macros = Macros()

    @macros.syntax("PROBE/$P1,$P2,$P3")
    def probe(ctx):  # type: ignore[no-untyped-def]
        x, y, z = ctx.p[1], ctx.p[2], ctx.p[3]
        ctx.insert(f"G38.2 X{x:g} Y{y:g} Z{z:g} F50")

    tape, result = post(HEAD + "FEDRAT/100\nPROBE/1,2,-5\nGOTO/1,0,0\nFINI\n", macros)
    assert "\nG38.2X1Y2Z-5F50\n" in tape and warnings(result) == []  # INSERT drops blanks


def test_set_p_values_are_the_macros_own() -> None:
    macros = Macros()

    @macros.syntax("SPINDL/$P1,$P2(CLW,CCLW)")
    def halve(ctx):  # type: ignore[no-untyped-def]
        ctx.p[1] = ctx.p[1] / 2
        ctx.cmd("SPINDL", ctx.p[1], ctx.p[2].name)

    tape, _ = post(HEAD + "SPINDL/800,CCLW\nGOTO/1,0,0\nFINI\n", macros)
    assert "S400 M04" in tape


# -- errors a macro makes -------------------------------------------------------------------


def test_output_in_a_tool_change_macro_is_refused_naming_the_macro() -> None:
    macros = Macros()

    @macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
    def before_tool(ctx):  # type: ignore[no-untyped-def]
        ctx.output()

    with pytest.raises(InputError) as refused:
        post(HEAD + "LOADTL/1\nGOTO/1,0,0\nFINI\n", macros)
    assert "*:before_tool" in str(refused.value) and "OUTPUT is not allowed" in str(refused.value)
    assert refused.value.where is not None and refused.value.where.line == 4


def test_a_macro_that_fails_is_named_with_its_record() -> None:
    macros = Macros()

    @macros.syntax("STOP")
    def broken(ctx):  # type: ignore[no-untyped-def]
        return 1 / 0

    with pytest.raises(InputError) as refused:
        post(HEAD + "STOP\nFINI\n", macros)
    assert "macro *:broken failed: ZeroDivisionError" in str(refused.value)
    assert refused.value.where is not None and refused.value.where.line == 4


def test_a_bad_command_from_a_macro_is_named() -> None:
    macros = Macros()

    @macros.syntax("STOP")
    def bad(ctx):  # type: ignore[no-untyped-def]
        ctx.cmd("GOTO/1,,2")

    with pytest.raises(InputError, match=r"macro \*:bad: command 'GOTO/1,,2'"):
        post(HEAD + "STOP\nFINI\n", macros)


def test_read_only_and_unknown_p_are_refused() -> None:
    macros = Macros()

    @macros.event(Kind.DIAGNOSTIC)
    def diag(ctx):  # type: ignore[no-untyped-def]
        ctx.p[4] = 2  # the occurrence count is read-only

    with pytest.raises(
        InputError, match=r"\$P4 \(occurrence\) of the diagnostic macro is read-only"
    ):
        post(HEAD + "PENUP\nFINI\n", macros)
