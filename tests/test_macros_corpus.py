"""The macro engine on the real CL files: with macros that change nothing, the outputs are
byte for byte those of the post without macros, by the engine's fast path (a macro that
cannot see GOTOs) and by its general path (a motion macro and a tape macro see every
motion and block), and with a look-ahead at every tool change."""

from __future__ import annotations

import pytest
from gecent.core.dispatch.post import post
from gecent.core.macros import Kind, Macros, Phase
from gecent.core.macros.table import with_macros
from gecent.core.output.tape import tape_image
from gecent.core.plugins import get_plugins

from .conftest import SHARED
from .test_corpus_post import FILES

CORPUS = SHARED / "corpus"
pytestmark = pytest.mark.skipif(not CORPUS.is_dir(), reason="shared corpus not present")


def quiet_macros(kind: str) -> Macros:
    macros = Macros(machine="*")
    if kind == "fast":
        macros.ignore("PENUP")  # matches nothing in these files; GOTOs go by the fast path
    else:

        @macros.event(Kind.MOTION, Phase.STARTUP)
        def motion(ctx):  # type: ignore[no-untyped-def]
            assert ctx.p.subclass in (1.0, 3.0, 5.0, 6.0)

        @macros.event(Kind.TAPE)
        def tape(ctx):  # type: ignore[no-untyped-def]
            assert ctx.p.flag == 1

        @macros.syntax("#2000:*")
        def statement(ctx):  # type: ignore[no-untyped-def]
            ctx.output()

        @macros.event(Kind.TOOL_CHANGE, Phase.STARTUP)
        def tool(ctx):  # type: ignore[no-untyped-def]
            ctx.globals.setdefault("next", []).append(ctx.next.tool)

    return macros


@pytest.mark.parametrize("machine", ["23", "linuxcnc-mill"])
@pytest.mark.parametrize("kind", ["fast", "general"])
@pytest.mark.parametrize("name", FILES)
def test_quiet_macros_change_no_output(name: str, kind: str, machine: str) -> None:
    source = str(CORPUS / name)
    plain = post(source, get_plugins(), machine)
    with_engine = post(source, with_macros(get_plugins(), quiet_macros(kind).macros), machine)
    assert tape_image(with_engine.blocks) == tape_image(plain.blocks)
    assert [d.text for d in with_engine.diagnostics] == [d.text for d in plain.diagnostics]
    assert with_engine.cut_minutes == plain.cut_minutes
