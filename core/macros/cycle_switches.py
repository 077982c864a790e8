"""A cycle macro's output switches and its feed alone (spec 09 §5.6, 002 L341-499), on a
control that runs the cycle (core/motion/control_cycles.py).

$P8, $P10, $P12 and $P14 set $FALSE leave out the cycle block's F, R, Z and G98/G99; set
$TRUE (even to the value the macro was given) they force them out although modal. $P5
$TRUE on a later hole states the whole cycle definition again; $FALSE on the hole that
activates it is the macro's error (the control would have no cycle). gecent has no
BORE-BACK cycle ($P4 is never 8): $P20 $TRUE or a $P21 is the macro's error. $P1 = -2
puts the feed alone in a block of its own (X23). GENER "does not adjust timing or tool
positions for such changes", and neither does gecent."""

from __future__ import annotations

from gecent.core.cl.records import Motion
from gecent.core.macros.host import MacroHost
from gecent.core.macros.model import MacroError
from gecent.core.macros.params import CycleParams
from gecent.core.output.block import Block, Code

# $P -> the name ControlCycles.hole takes the switch by
SWITCHES = {5: "activate", 8: "feed", 10: "clearance", 12: "depth", 14: "retract", 20: "back_out"}


def cycle_switches(params: CycleParams, activating: bool) -> dict[str, bool]:
    """The switches the macro wrote, for ControlCycles.hole; a write is a switch even when
    it writes the value the macro was given (§5.6: $TRUE forces the output)."""
    switches = {
        name: bool(params[number]) for number, name in SWITCHES.items() if number in params.changed
    }
    activate = switches.pop("activate", None)
    if activate is False and activating:
        raise MacroError(
            "$P5 (activating) cannot be $FALSE at the hole that activates the control's "
            "cycle: the control would have no cycle to run"
        )
    if activate and not activating:
        switches["activate"] = True  # the whole definition stated again, its F too
        switches.setdefault("feed", True)
    if switches.pop("back_out", False) or 21 in params.changed:
        raise MacroError(
            "$P20/$P21: gecent's cycles have no BORE-BACK bottom plane to output ($P4 is never 8)"
        )
    return switches


def feed_alone(run: MacroHost, record: Motion, params: CycleParams) -> None:
    """$P1 = -2: the cycle's feed-rate processing alone, its F in a block of its own (after
    a G94/G95 block when the feed mode changes) when the control needs it (F is modal:
    not when the same F is in force, unless $P8 forces it); the cycle block that follows
    does not repeat it. A control whose cycle blocks carry no F (option 254 = 0) has none
    to put out; $P8 $FALSE leaves it out."""
    output = run.output
    forced = bool(params.feed_out) if 8 in params.changed else None
    if not output.modern.direct_feed or forced is False:
        return
    block = Block(Code.G_ONLY, record.number)
    feed = output._direct_feed(block)
    if feed == output.words.previous_f and not forced:
        return
    block.cells[11] = feed
    block.switched = {11: True}
    output.output(block)
    output.words.previous_f = feed
