"""Feed type 8: type 2's IPR table, with the EIA "magic 3" code of the IPR as the command
(manual §4.1.2.9, 001 L11641-11665; appendix 7.1, L40132-40175; options 62, 63, 78).

This type is selected by setting option 78 to +8. The feeds are generated as for feed type
2 (subroutine FTYPE2): discrete IPR values in ranges, the range named by the current
spindle range, and the exact or next lowest IPR taken, its IPM becoming the programmed
feed. The selected IPR value is then converted to its EIA "magic 3" code, which is the
feedrate command (the text's "Section 6.1" is the appendix's 7.1).

Example, with the type 2 tables: 7 IPM at 100 RPM in spindle range 2 is 0.07 IPR; range 2
gives 0.06 IPR, so FIPM = 6 and FCOM = 260. The printed "FIPM = 1" and "7/100 = 0.01" are
OCR slips for 7 and 0.07 (the division and the result 0.06 need them).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from gecent.core.errors import MachineDefinitionError
from gecent.core.feed.magic3 import magic3
from gecent.core.feed.positioning import FeedCommand, FeedContext, FeedSnap
from gecent.core.hookspecs import Register, hookimpl
from gecent.core.machine.definition import MachineDefinition
from gecent.plugins.feedtypes._frtab import ftype2_lookup

KIND = "feed type 8"

# The manual's example uses feed type 2's table (001 L11655-11663); a magic-3 code needs
# F format 30 (001 L11189-11191).
MANUAL_EXAMPLE = """
[machine]
name = "feed-type-8-example"
title = "FEED TYPE 8 (IPR TABLE, MAGIC 3)"
description = "Manual 4.1.2.9: IPR feeds by spindle range, FCOM = magic 3 of the IPR"
source = "001 L11641-11665"

[regfor]
11 = 30.0

[optab]
1 = 1.0
78 = 8.0
62 = 3.0
63 = 5.0
174 = 15.0

[feed_table]
feeds = [
    0.01, 0.02, 0.03, 0.04, 0.05,
    0.04, 0.06, 0.08, 0.10, 0.12,
    0.10, 0.14, 0.18, 0.22, 0.26,
]
"""


@dataclass(frozen=True)
class IprTableMagicThreeFeed:
    number: int = 8
    name: str = "IPR table by spindle range, EIA magic 3 of the IPR"
    section: str = "§4.1.2.9"
    manual_example: str = field(default=MANUAL_EXAMPLE, repr=False)

    def snap(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedSnap:
        hit = ftype2_lookup(machine, feed, context, KIND, per_revolution=True)
        return FeedSnap(hit.ipm, hit.row, hit.speed_comments + hit.comments)

    def command(self, machine: MachineDefinition, feed: float, context: FeedContext) -> FeedCommand:
        hit = ftype2_lookup(machine, feed, context, KIND, per_revolution=True)
        code = magic3(hit.value)
        if code is None:
            raise MachineDefinitionError(
                machine.origin,
                "feed_table",
                "feeds",
                f"{KIND}: the IPR feed {hit.value:g} (row {hit.row}) has no EIA magic 3 code; "
                "the code exists for 0.0001 to 9999",
            )
        return FeedCommand(float(code), hit.ipm, hit.comments)


@hookimpl
def register_feed_types(register: Register) -> None:
    register(IprTableMagicThreeFeed())
