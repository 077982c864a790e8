"""The GEOUT conversion of a finished block into register words (manual §3.5.3, flow
chart 12, 001 L20074-20192): SHUFFL, the register formats (fixed, varied by G code under
option 41 or inverse time, leading zeros under option 51 = -2), redundant G and F words,
and the option-51 rule for zero values."""

from __future__ import annotations

from gecent.core.absent import ABSENT, Absent
from gecent.core.errors import FatalError, InputError, SourcePosition
from gecent.core.machine.definition import MachineDefinition
from gecent.core.machine.regformat import decode_regfor
from gecent.core.machine.shuffle import cell_map
from gecent.core.output.block import Block, Code
from gecent.core.output.format import FormatOverflow, RegisterFormatter
from gecent.core.output.modern import modern_output

NEVER_OUTPUT = frozenset({15, 19, 20})  # CODE, feed in IPM, speed in RPM: not registers
ZERO_RULE_CELLS = frozenset({3, 4, 5, 6, 7, 8, 9, 10, 16})  # option 51 (001 L25024-25049)

Word = tuple[int, str, str, str]  # location, letter, printed, punched


def unpunched_g_codes(machine: MachineDefinition) -> frozenset[float]:
    """Option 147 = 1 on a contouring machine: G01 and G11 are left off the punched tape
    (the listing keeps them; 001 L26131-26139). The codes are the ones the option names,
    whichever TABLEG cells hold them. A modern control needs its G01 after a G00, so the
    option is bad input there."""
    if machine.number_option(147) != 1 or machine.number_option(1) != 0:
        return frozenset()
    if modern_output(machine):
        raise InputError(
            "option 147 = 1 leaves G01 and G11 off the tape, which a modern control "
            "(option 255 or 258 = 1) needs to leave rapid",
            SourcePosition(machine.origin),
        )
    return frozenset({1.0, 11.0})


class WordFormatter:
    def __init__(self, machine: MachineDefinition) -> None:
        self.machine = machine
        registers = machine.registers
        contouring = machine.number_option(1) == 0
        # option 1 = 3 (the 7500, core/motion/mixed.py): departures drop X, Y, Z's trailing
        # zeros as on a contouring control, absolute positions keep them (absolute_xyz)
        mixed = machine.number_option(1) == 3
        order = [k for k in (machine.output_order or ()) if k not in NEVER_OUTPUT] or [
            k for k in range(1, 31) if k not in NEVER_OUTPUT
        ]
        self.decimal = machine.number_option(255) == 1
        self.formatters: list[RegisterFormatter] = []
        for location in order:
            fmt = registers.formats[location]
            if fmt is None:
                continue
            drop = contouring or mixed or location not in (3, 4, 5)
            self.formatters.append(
                RegisterFormatter(
                    location,
                    registers.letters[location],
                    fmt,
                    drop_trailing=drop,
                    decimal=self.decimal,
                )
            )
        self.absolute_xyz = {
            f.location: RegisterFormatter(
                f.location, f.letter, f.fmt, drop_trailing=False, decimal=self.decimal
            )
            for f in self.formatters
            if mixed and f.location in (3, 4, 5)
        }
        try:
            self.shuffle = cell_map(machine.number_option(59), "XYZ") + cell_map(
                machine.number_option(60), "IJK"
            )
        except ValueError as exc:
            raise FatalError(7, str(exc)) from None
        self.signed_centre = machine.number_option(252) != 0
        self.diameter = machine.number_option(260) == 1
        self.absolute_centre = machine.number_option(252) == 2
        self.zero_rule = machine.number_option(51)
        self.unpunched_g = unpunched_g_codes(machine)
        # option 38 = 0 or +2: a G code equal to the last one output is left out; only in
        # blocks that move (``suppress``) both ways: 0's non-motion G is the block's command
        self.suppress_g = machine.number_option(38) in (0.0, 2.0)
        self.suppress_f = machine.number_option(107) in (1.0, 2.0)
        self.previous_g: float | Absent = ABSENT
        self.previous_f: float | Absent = ABSENT
        self._f_formats: dict[float, RegisterFormatter] = {}
        self.long_formatters = self._long_departure_formatters()
        long_code = machine.tableg[11]
        self.long_code = None if long_code is ABSENT else float(long_code)
        self.leading_zero_codes = {
            float(code): extra
            for location, extra in ((12, 0), (13, 1))
            if (code := machine.tableg[location]) is not ABSENT
        }

    def _long_departure_formatters(self) -> dict[int, RegisterFormatter]:
        """Option 41 <= 0 (§4.8, 001 L16144-16269): in a G10 block (TABLEG(11)) X, Y and Z
        take format 23 (24 under -2), with the sign rule of their own format."""
        machine = self.machine
        variable = machine.number_option(41)
        if variable > 0 or machine.tableg[11] is ABSENT:
            return {}
        size = 24.0 if variable == -2 else 23.0
        formatters = {}
        for location in (3, 4, 5):
            regfor = machine.registers.regfor[location]
            if regfor:
                fmt = decode_regfor(-size if regfor < 0 else size)
                assert fmt is not None
                formatters[location] = RegisterFormatter(
                    location,
                    machine.registers.letters[location],
                    fmt,
                    drop_trailing=True,
                    decimal=self.decimal,
                )
        return formatters

    def _leading_zero_rule(self, block: Block) -> dict[int, int] | None:
        """Option 51 = -2 (100M, §4.9): in G11 (TABLEG(12)) blocks X, Y, Z lose their
        leading zeros left of the point, in G12 (TABLEG(13)) one zero right of it too."""
        if self.zero_rule != -2 or block.code is not Code.LINEAR or block.cells[2] is ABSENT:
            return None
        extra = self.leading_zero_codes.get(float(block.cells[2]))
        return None if extra is None else {3: extra, 4: extra, 5: extra}

    def f_formatter(self, regfor: float) -> RegisterFormatter:
        """FVARGO: inverse time changes the F format with the block's G code."""
        formatter = self._f_formats.get(regfor)
        if formatter is None:
            fmt = decode_regfor(regfor)
            assert fmt is not None
            letter = self.machine.registers.letters[11]
            formatter = self._f_formats[regfor] = RegisterFormatter(
                11, letter, fmt, drop_trailing=False, decimal=self.decimal
            )
        return formatter

    def shuffle_block(self, block: Block) -> None:
        """SHUFFL (001 L37532-37564): options 59/60 put the internal X, Y, Z and I, J, K on
        the machine's axes with their signs, for every block at output."""
        cells = block.cells
        internal = [cells[k] for k in (3, 4, 5, 8, 9, 10)]
        for k in (3, 4, 5, 8, 9, 10):
            cells[k] = ABSENT
        for value, target in zip(internal, self.shuffle, strict=True):
            if target is not None and value is not ABSENT:
                cell, sign = target
                signed = cell < 8 or self.signed_centre
                cells[cell] = sign * float(value) if signed else float(value)
        if self.diameter:  # option 260: X is a diameter (and an absolute centre's I)
            for cell in (3, 8) if self.absolute_centre else (3,):
                radius = cells[cell]
                if radius is not ABSENT:
                    cells[cell] = 2 * float(radius)

    def words(
        self, block: Block, *, suppress: bool, sequence: int, absolute: bool = False
    ) -> list[Word]:
        """(location, letter, printed, punched) of each register the block outputs. In an
        absolute positioning block a zero X, Y, Z, A or B is a position, so option 51's
        deletion of zero words (meant for departures) does not touch it."""
        words: list[Word] = []
        long_departure = (
            self.long_formatters
            and block.code is Code.LINEAR
            and block.cells[2] is not ABSENT
            and float(block.cells[2]) == self.long_code
        )
        leading = self._leading_zero_rule(block)
        cycle = block.code is Code.CYCLE  # its R is a level too: R0 is a position
        for formatter in self.formatters:
            location = formatter.location
            if long_departure and location in self.long_formatters:
                formatter = self.long_formatters[location]
            if absolute and location in self.absolute_xyz:
                formatter = self.absolute_xyz[location]
            value = block.cells[location]
            if value is ABSENT:
                continue
            forced = block.switched.get(location) if block.switched else None
            if forced is False:
                continue  # a cycle macro inhibited it: the modal value stays as it was
            number = float(value)
            if location == 1:
                number = abs(number)
            if suppress and location == 2:
                if self.suppress_g and number == self.previous_g and not forced:
                    continue
                self.previous_g = number
            if suppress and location == 11:
                if self.suppress_f and number == self.previous_f and not forced:
                    continue
                self.previous_f = number
            if location == 11 and block.f_format is not None:
                formatter = self.f_formatter(block.f_format)
            try:
                text = formatter.format(
                    number,
                    leading.get(location) if leading is not None else None,
                )
            except FormatOverflow as overflow:
                record = block.record if block.record is not None else sequence
                overflow.where = SourcePosition("", None, None, record)
                raise
            if (
                location in ZERO_RULE_CELLS
                and not (absolute and (location <= 7 or (location == 16 and cycle)))
                and not (self.absolute_centre and 8 <= location <= 10)  # a centre at 0
                and text.punched.strip("+-0.") == ""
            ):
                if self.zero_rule in (0, -2):  # delete value and address (standard)
                    continue
                if self.zero_rule == 1:  # the address alone
                    words.append((location, formatter.letter, text.printed, ""))
                    continue
            words.append((location, formatter.letter, text.printed, text.punched))
        return words
