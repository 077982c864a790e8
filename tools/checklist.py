"""Generate docs/checklist.md: where each feature of the manual lives and what tests it.

Run as ``python tools/checklist.py`` from the project root (``--check`` only compares).

Three tables, from the data file docs/checklist.toml and from the code itself:

* the "Feature checklist" items of the spec digests 01-08 (../shared/spec): each item's
  status (done, partial, missing, no-effect, or unreviewed), the modules that build it and
  the tests that cover it, as docs/checklist.toml records them;
* the option catalogue (core/machine/data/options.toml): the modules that read each option,
  found in the source (``number_option(N)``, ``option(N)``, an alias, ``stand_in(machine,
  N)``, a plugin family's ``option=N``, a constant named ``..._OPTION = N``, or an indirect
  read docs/checklist.toml names), or the option's ``effect`` reason when nothing reads it;
* the manual's fatal errors (core/errors.py FATAL_ERRORS, §5.7.1): where each is raised and
  its test, or why it cannot arise in gecent (docs/decisions.md, "## Fatal errors").

``problems()`` lists every way the data and the tree disagree (a module or test that does
not exist, an item whose text no longer matches its digest, an option neither read nor
explained); the generator refuses to write while there are any, and tests/test_checklist.py
holds the tree to it.
"""

from __future__ import annotations

import re
import sys
import tomllib
from collections import Counter
from dataclasses import dataclass
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
SPEC = ROOT.parent / "shared" / "spec"
DATA = ROOT / "docs" / "checklist.toml"
OUTPUT = ROOT / "docs" / "checklist.md"
OPTIONS = ROOT / "core" / "machine" / "data" / "options.toml"
ERRORS = ROOT / "core" / "errors.py"
DIGESTS = ("01", "02", "03", "04", "05", "06", "07", "08")
STATUSES = ("done", "partial", "missing", "no-effect", "unreviewed")
FATAL_STATUSES = ("raised", "cannot-arise", "pending")
# files that list every option without acting on one (they would count every option read)
NOT_READERS = frozenset({"core/machine/describe.py", "core/machine/catalogue.py"})

_HEADING = re.compile(r"^## (?:\d+\. )?Feature checklist")
_ITEM = re.compile(r"^\s*(?:[-*]|\d+\.) (.*)")
_READS = (
    re.compile(r"\b(?:number_option|option)\(\s*(\d+)\s*\)"),
    re.compile(r"\.options\[\s*(\d+)\s*\]"),
    re.compile(r"\bstand_in\(\s*\w+\s*,\s*(\d+)\s*\)"),
    re.compile(r"\boption=(\d+)\b"),
    re.compile(r"^\s*[A-Z][A-Z0-9_]*OPTION[A-Z0-9_]*\s*=\s*(\d+)\b", re.MULTILINE),
)
# number_option(n) for n in (3, 32, 69) / range(100, 106): a comprehension over numbers
_LOOP_READ = re.compile(
    r"\bnumber_option\((\w+)\)[^\n]*\bfor \1 in (?:\(([\d,\s]+)\)|range\((\d+), (\d+)\))"
)
_ALIAS_READ = re.compile(r"\b(?:number_option|option)\(\s*[\"']([a-z][a-z0-9_]*)[\"']")
_RAISE = re.compile(r"\bFatalError\(\s*(\d+)")


@dataclass(frozen=True, slots=True)
class Item:
    id: str  # "01-17": the digest's number and the item's place in its checklist
    digest: str  # the digest's file name
    text: str


def spec_items(spec: Path = SPEC) -> list[Item]:
    """Every bullet or numbered line of each digest's "Feature checklist" section."""
    items: list[Item] = []
    for number in DIGESTS:
        path = next(spec.glob(f"{number}-*.md"))
        lines = path.read_text(encoding="utf-8").splitlines()
        start = next(i for i, line in enumerate(lines) if _HEADING.match(line))
        count = 0
        for line in lines[start + 1 :]:
            if line.startswith("## "):
                break
            if match := _ITEM.match(line):
                count += 1
                items.append(Item(f"{number}-{count:02d}", path.name, match.group(1).strip()))
    return items


def _python_files(root: Path) -> list[Path]:
    return sorted([*root.glob("core/**/*.py"), *root.glob("plugins/**/*.py")])


def options_catalogue(root: Path = ROOT) -> list[dict[str, Any]]:
    path = root / "core" / "machine" / "data" / "options.toml"
    options: list[dict[str, Any]] = tomllib.loads(path.read_text(encoding="utf-8"))["option"]
    return options


def option_reads(root: Path = ROOT) -> dict[int, set[str]]:
    """Option number -> the modules (paths from the root) whose source reads it."""
    aliases = {option["alias"]: option["number"] for option in options_catalogue(root)}
    reads: dict[int, set[str]] = {}
    for path in _python_files(root):
        name = path.relative_to(root).as_posix()
        if name in NOT_READERS:
            continue
        text = path.read_text(encoding="utf-8")
        numbers = {int(m.group(1)) for pattern in _READS for m in pattern.finditer(text)}
        for loop in _LOOP_READ.finditer(text):
            if loop.group(2):
                numbers |= {int(n) for n in re.findall(r"\d+", loop.group(2))}
            else:
                numbers |= set(range(int(loop.group(3)), int(loop.group(4))))
        numbers |= {
            aliases[m.group(1)] for m in _ALIAS_READ.finditer(text) if m.group(1) in aliases
        }
        for number in numbers:
            reads.setdefault(number, set()).add(name)
    return reads


def fatal_raises(root: Path = ROOT) -> dict[int, set[str]]:
    """Fatal error number -> the modules that raise it (``FatalError(N``)."""
    raises: dict[int, set[str]] = {}
    for path in _python_files(root):
        for match in _RAISE.finditer(path.read_text(encoding="utf-8")):
            raises.setdefault(int(match.group(1)), set()).add(path.relative_to(root).as_posix())
    return raises


def fatal_catalogue(root: Path = ROOT) -> dict[int, tuple[str, str]]:
    """FATAL_ERRORS as core/errors.py writes it (read as text: the tool needs no install)."""
    text = (root / "core" / "errors.py").read_text(encoding="utf-8")
    entry = re.compile(r'^\s*(\d+): \("([A-Z0-9]+)", "([^"]*)"\),$', re.MULTILINE)
    return {int(m.group(1)): (m.group(2), m.group(3)) for m in entry.finditer(text)}


def load_data(path: Path = DATA) -> dict[str, Any]:
    return tomllib.loads(path.read_text(encoding="utf-8"))


def _test_exists(root: Path, test: str) -> bool:
    """``tests/test_x.py`` or ``tests/test_x.py::test_name`` names a file and function."""
    file, _, function = test.partition("::")
    path = root / file
    if not path.is_file():
        return False
    pattern = rf"^def {re.escape(function)}\("
    return not function or re.search(pattern, path.read_text(), re.M) is not None


def problems(root: Path = ROOT, spec: Path = SPEC) -> list[str]:
    """Every disagreement between docs/checklist.toml, options.toml and the tree."""
    data = load_data(root / "docs" / "checklist.toml")
    found: list[str] = []
    items = {item.id: item for item in spec_items(spec)}
    recorded: dict[str, dict[str, Any]] = {}
    for entry in data.get("item", []):
        ident = entry["id"]
        if ident in recorded:
            found.append(f"item {ident}: recorded twice")
        recorded[ident] = entry
        item = items.get(ident)
        if item is None:
            found.append(f"item {ident}: no such checklist item in the digests")
        elif not _normal(item.text).startswith(_normal(entry["text"])):
            found.append(f"item {ident}: the digest now reads {item.text[:60]!r}")
        if entry["status"] not in STATUSES:
            found.append(f"item {ident}: status {entry['status']!r} is not one of {STATUSES}")
        if entry["status"] in ("partial", "missing", "no-effect") and not entry.get("note"):
            found.append(f"item {ident}: a {entry['status']} item needs a note saying why")
        if entry["status"] in ("done", "partial") and not entry.get("tests"):
            found.append(f"item {ident}: a {entry['status']} item needs a test")
        found += _paths(root, f"item {ident}", entry)
    found += [
        f"item {ident}: not in docs/checklist.toml" for ident in items if ident not in recorded
    ]
    found += _option_problems(root, data)
    found += _fatal_problems(root, data)
    return found


def _normal(text: str) -> str:
    return " ".join(text.replace("**", "").replace("`", "").split()).lower()


def _paths(root: Path, what: str, entry: dict[str, Any]) -> list[str]:
    found = [f"{what}: no module {m}" for m in entry.get("modules", []) if not (root / m).exists()]
    found += [f"{what}: no test {t}" for t in entry.get("tests", []) if not _test_exists(root, t)]
    return found


def _option_problems(root: Path, data: dict[str, Any]) -> list[str]:
    reads = option_reads(root)
    indirect = {int(k): v for k, v in data.get("options", {}).get("indirect", {}).items()}
    found: list[str] = []
    for number, module in indirect.items():
        text = (root / module).read_text(encoding="utf-8") if (root / module).is_file() else ""
        if not re.search(rf"\b{number}\b", text):
            found.append(f"option {number}: {module} does not mention it (indirect read)")
    for option in options_catalogue(root):
        number, effect = option["number"], option.get("effect")
        read = number in reads or number in indirect
        if read and effect:
            readers = ", ".join(sorted(reads.get(number, set())) or [indirect[number]])
            found.append(
                f"option {number}: read by {readers} but options.toml says "
                f"effect = {effect!r}: remove the effect line"
            )
        if not read and not effect:
            found.append(
                f"option {number}: nothing reads it and options.toml gives no effect reason"
            )
    return found


def _fatal_problems(root: Path, data: dict[str, Any]) -> list[str]:
    raises = fatal_raises(root)
    recorded = {int(k): v for k, v in data.get("fatal", {}).items()}
    decisions = _fatal_decisions(root)
    found: list[str] = []
    for number in fatal_catalogue(root):
        entry = recorded.get(number)
        if entry is None:
            found.append(f"fatal {number}: not in docs/checklist.toml [fatal]")
            continue
        status = entry["status"]
        if status not in FATAL_STATUSES:
            found.append(f"fatal {number}: status {status!r} is not one of {FATAL_STATUSES}")
        if status == "raised":
            if number not in raises:
                found.append(f"fatal {number}: recorded as raised, but no FatalError({number}")
            if not entry.get("tests"):
                found.append(f"fatal {number}: a raised fatal error needs a test")
        elif number in raises and status != "pending":  # pending: its work is raising it
            found.append(f"fatal {number}: raised by {sorted(raises[number])}: status 'raised'")
        if status == "cannot-arise" and number not in decisions:
            found.append(f"fatal {number}: no line in docs/decisions.md '## Fatal errors' says why")
        if status == "pending" and not entry.get("owner"):
            found.append(f"fatal {number}: a pending fatal error names the work it belongs to")
        found += _paths(root, f"fatal {number}", entry)
    return found


def _fatal_decisions(root: Path) -> set[int]:
    """The fatal error numbers the "## Fatal errors" section of docs/decisions.md names."""
    text = (root / "docs" / "decisions.md").read_text(encoding="utf-8")
    _, _, section = text.partition("\n## Fatal errors\n")
    section = section.split("\n## ", 1)[0]
    numbers: set[int] = set()
    for line in section.splitlines():
        if match := re.match(r"- Fatal errors? ([\d, and]+)", line):
            numbers |= {int(n) for n in re.findall(r"\d+", match.group(1))}
    return numbers


def render(root: Path = ROOT, spec: Path = SPEC) -> str:
    data = load_data(root / "docs" / "checklist.toml")
    lines = [
        "# Feature checklist",
        "",
        "Generated by `python tools/checklist.py` from docs/checklist.toml, the spec digests'",
        '"Feature checklist" sections (../shared/spec/01-08), core/machine/data/options.toml and',
        "the source; do not edit by hand (tests/test_checklist.py checks it is current).",
        "",
    ]
    lines += _items_table(data, spec)
    lines += _options_table(root, data)
    lines += _fatal_table(root, data)
    return "\n".join(lines) + "\n"


def _cell(values: list[str] | str | None) -> str:
    if not values:
        return ""
    text = values if isinstance(values, str) else "<br>".join(values)
    return text.replace("|", "\\|").replace("\n", " ")


def _items_table(data: dict[str, Any], spec: Path) -> list[str]:
    recorded = {entry["id"]: entry for entry in data.get("item", [])}
    items = spec_items(spec)
    counts = Counter(recorded.get(item.id, {}).get("status", "unreviewed") for item in items)
    summary = ", ".join(f"{counts[s]} {s}" for s in STATUSES if counts[s])
    lines = ["## Checklist items", "", f"{len(items)} items: {summary}.", ""]
    digest = ""
    for item in items:
        if item.digest != digest:
            digest = item.digest
            lines += ["", f"### {digest}", "", "| id | item | status | modules | tests | note |"]
            lines.append("|---|---|---|---|---|---|")
        entry = recorded.get(item.id, {})
        lines.append(
            f"| {item.id} | {_cell(item.text)} | {entry.get('status', 'unreviewed')} | "
            f"{_cell(entry.get('modules'))} | {_cell(entry.get('tests'))} | "
            f"{_cell(entry.get('note'))} |"
        )
    return [*lines, ""]


def _options_table(root: Path, data: dict[str, Any]) -> list[str]:
    reads = option_reads(root)
    indirect = {int(k): v for k, v in data.get("options", {}).get("indirect", {}).items()}
    options = options_catalogue(root)
    read = sum(1 for o in options if o["number"] in reads or o["number"] in indirect)
    lines = [
        "## Options",
        "",
        f"{len(options)} options: {read} read by the code, {len(options) - read} with the "
        "reason they have no effect (options.toml `effect`: `none:` by nature, `missing:` "
        "not built yet).",
        "",
        "| option | alias | status | read by | effect |",
        "|---|---|---|---|---|",
    ]
    for option in options:
        number = option["number"]
        modules = sorted(
            reads.get(number, set()) | ({indirect[number]} if number in indirect else set())
        )
        lines.append(
            f"| {number} | {option['alias']} | {option['status']} | {_cell(modules)} | "
            f"{_cell(option.get('effect'))} |"
        )
    return [*lines, ""]


def _fatal_table(root: Path, data: dict[str, Any]) -> list[str]:
    raises = fatal_raises(root)
    recorded = {int(k): v for k, v in data.get("fatal", {}).items()}
    lines = [
        "## Fatal errors (§5.7.1)",
        "",
        "| error | subroutine | reason | status | raised in | tests | note |",
        "|---|---|---|---|---|---|---|",
    ]
    for number, (subroutine, reason) in sorted(fatal_catalogue(root).items()):
        entry = recorded.get(number, {})
        note = entry.get("note", "")
        if entry.get("owner"):
            note = f"{note} (belongs to: {entry['owner']})".strip()
        lines.append(
            f"| {number} | {subroutine} | {_cell(reason)} | {entry.get('status', '')} | "
            f"{_cell(sorted(raises.get(number, set())))} | {_cell(entry.get('tests'))} | "
            f"{_cell(note)} |"
        )
    return [*lines, ""]


def main(argv: list[str]) -> int:
    found = problems()
    if found:
        print("docs/checklist.toml disagrees with the tree:", *found, sep="\n  ", file=sys.stderr)
        return 1
    text = render()
    if "--check" in argv:
        current = OUTPUT.read_text(encoding="utf-8") if OUTPUT.exists() else ""
        if current != text:
            print(
                "docs/checklist.md is out of date: run python tools/checklist.py", file=sys.stderr
            )
            return 1
        return 0
    OUTPUT.write_text(text, encoding="utf-8")
    print(f"wrote {OUTPUT.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
