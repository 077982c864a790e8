"""What a batch posts: one :class:`Job` per CL file and machine, from files and folders named
on the command line or from a manifest (TOML or CSV), each with its outputs' paths.

Everything a job needs travels with it (the machine file's and macro files' text, and on a
cluster the CL file's bytes), so a worker on another host needs only gecent and the machine
packs installed (docs/batch.md)."""

from __future__ import annotations

import csv
import io
import re
import tomllib
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from gecent.core.errors import InputError, SourcePosition
from gecent.core.motion.guard import DEFAULT_MAX_SEGMENTS

# what a folder's CL files are called: APT source, CL print files, binary CL tapes, Creo's
# numbered .ncl versions, NX's .cls and NCL's .clf
CL_SUFFIXES = (".apt", ".aptsource", ".cl", ".cls", ".cl3", ".clf", ".ncl")
CREO_VERSION = re.compile(r"\.ncl\.\d+$")  # part.ncl.3: Creo's third version
PUNCH_CODES = ("eia", "ascii")
JOB_KEYS = frozenset(
    {
        "input",
        "machine",
        "tape",
        "listing",
        "punch",
        "punch_file",
        "dialect",
        "optab",
        "macros",
        "max_segments",
        "verify",
    }
)


@dataclass(frozen=True)
class Job:
    """One post: a CL file on a machine, and where its outputs go. ``listing`` is a path,
    ``"auto"`` (beside the tape unless the machine's tape is G-code, as ``gecent post``
    does) or None (no listing)."""

    number: int
    input: str
    name: str
    tape: str
    machine: str | None = None
    machine_text: str | None = None  # a machine given as a .toml file: its text
    listing: str | None = "auto"
    punch: tuple[str, str] | None = None
    dialect: str | None = None
    optab: tuple[tuple[int, float], ...] = ()
    macros: tuple[tuple[str, str], ...] = ()  # (the file as named, its Python text)
    max_segments: int = DEFAULT_MAX_SEGMENTS
    verify: bool = False
    input_bytes: bytes | None = field(default=None, repr=False)  # shipped to a cluster
    where: SourcePosition | None = None  # the manifest line that asked for it

    def shipped(self) -> Job:
        """The job with its CL file's bytes, for a worker that may not see this file
        system."""
        return replace(self, input_bytes=Path(self.input).read_bytes())


@dataclass
class JobDefaults:
    """What the command line (or a manifest's ``[defaults]``) gives every job."""

    machines: tuple[str | None, ...] = (None,)
    out: Path = Path("posted")
    suffix: str = ".tape"
    listing: bool | None = None  # None: auto
    punch: str | None = None
    dialect: str | None = None
    optab: tuple[tuple[int, float], ...] = ()
    macros: tuple[str, ...] = ()
    max_segments: int = DEFAULT_MAX_SEGMENTS
    verify: bool = False


def jobs_from_sources(sources: list[str], defaults: JobDefaults) -> list[Job]:
    """Jobs for CL files and folders (every CL file under a folder: :func:`cl_files`), each on
    every machine asked for; outputs mirror the inputs' places under ``defaults.out``, in a
    folder per machine when there are several."""
    found: list[tuple[Path, Path]] = []  # (file, its path under the output folder)
    for source in sources:
        path = Path(source)
        if path.is_dir():
            files = cl_files(path, skip=defaults.out)
            if not files:
                raise InputError(f"no CL files in folder {source} (looked for {_patterns()})")
            found.extend((f, f.relative_to(path)) for f in files)
        elif path.is_file():
            found.append((path, Path(path.name)))
        else:
            raise InputError(f"{source}: no such file or folder")
    if not found:
        raise InputError("no CL files to post: name files, folders or --manifest")
    jobs: list[Job] = []
    for machine in defaults.machines:
        folder = defaults.out
        if len(defaults.machines) > 1:
            folder = folder / _folder_name(machine)
        for path, relative in found:
            tape = folder / relative.parent / (_stem(relative) + defaults.suffix)
            jobs.append(_job(len(jobs) + 1, path, str(relative), tape, machine, defaults, {}))
    return jobs


def cl_files(folder: Path, skip: Path | None = None) -> list[Path]:
    """The CL files under ``folder`` by their names (CL_SUFFIXES, Creo's versions), leaving
    out the folder ``skip`` (the outputs, when they are written inside the inputs)."""
    skipped = skip.resolve() if skip is not None else None
    found = []
    for path in sorted(folder.rglob("*")):
        name = path.name.lower()
        if not (name.endswith(CL_SUFFIXES) or CREO_VERSION.search(name)):
            continue
        if skipped is not None and skipped in path.resolve().parents:
            continue
        if path.is_file():
            found.append(path)
    return found


def jobs_from_manifest(manifest: str, defaults: JobDefaults) -> list[Job]:
    """Jobs from a TOML manifest (``[defaults]`` and ``[[job]]`` tables) or a CSV one (a
    header row naming the columns); paths in it are relative to its folder."""
    path = Path(manifest)
    if not path.is_file():
        raise InputError(f"manifest {manifest}: no such file")
    base = path.parent
    rows: list[tuple[dict[str, Any], SourcePosition]]
    if path.suffix.lower() == ".csv":
        rows = _csv_rows(path)
    else:
        rows, file_defaults = _toml_rows(path)
        if "out" in file_defaults:
            defaults = replace(defaults, out=base / str(file_defaults.pop("out")))
        rows = [({**file_defaults, **row}, at) for row, at in rows]
    if not rows:
        raise InputError("the manifest names no jobs", SourcePosition(manifest))
    jobs: list[Job] = []
    for row, where in rows:
        unknown = sorted(set(row) - JOB_KEYS)
        if unknown:
            raise InputError(
                f"unknown manifest key {unknown[0]!r} (known: {', '.join(sorted(JOB_KEYS))})",
                where,
            )
        if not row.get("input"):
            raise InputError("a job names no input", where)
        for key, value in row.items():
            _check_type(key, value, where)
        source = base / str(row["input"])
        if not source.is_file():
            raise InputError(f"input {row['input']}: no such file", where)
        machine = row.get("machine", defaults.machines[0])
        machine = None if machine in (None, "") else str(machine)
        tape_name = row.get("tape")
        tape = (
            base / str(tape_name)
            if tape_name
            else defaults.out / (_stem(Path(str(row["input"]))) + defaults.suffix)
        )
        jobs.append(
            _job(
                len(jobs) + 1, source, str(row["input"]), tape, machine, defaults, row, where, base
            )
        )
    return jobs


def checked(jobs: list[Job], protected: dict[str, str] | None = None) -> list[Job]:
    """Two jobs writing one file would overwrite each other's output, and an output must
    never be a CL file of the batch, its manifest or its state file (``protected``: path,
    what it is): bad input, before anything is posted."""
    guarded = {str(Path(path).resolve()): what for path, what in (protected or {}).items()}
    for job in jobs:
        guarded.setdefault(str(Path(job.input).resolve()), f"the CL file of job {job.number}")
    owners: dict[str, Job] = {}
    for job in jobs:
        for output in outputs_of(job):
            if not Path(output).name or Path(output).is_dir():
                raise InputError(
                    f"job {job.number} ({job.name}): {output!r} is not a file name",
                    job.where,
                )
            key = str(Path(output).resolve())
            if key in guarded:
                raise InputError(
                    f"job {job.number} ({job.name}) would write {output}, which is "
                    f"{guarded[key]}: give the job another output",
                    job.where,
                )
            other = owners.get(key)
            if other is not None:
                raise InputError(
                    f"jobs {other.number} ({other.name}) and {job.number} ({job.name}) both "
                    f"write {output}: give them different outputs (or --machine one at a time)"
                )
            owners[key] = job
    return jobs


_TYPES: dict[str, tuple[type, ...]] = {
    "input": (str,),
    "machine": (str, int),
    "tape": (str,),
    "listing": (str, bool),
    "punch": (str, bool),
    "punch_file": (str,),
    "dialect": (str,),
    "optab": (str, dict),
    "macros": (str, list),
    "max_segments": (int, str),
    "verify": (bool, str, int),
}


def check_settings(jobs: list[Job], plugins: Any) -> None:
    """What would fail every job it touches is bad batch input, found before anything runs:
    a machine that is not installed, a dialect that is not."""
    dialects = {info.obj.name for info in plugins.family("dialects").values()}
    for job in jobs:
        known = job.machine is None or job.machine_text is not None
        if not known and plugins.machine(job.machine) is None:
            raise InputError(
                f"job {job.number} ({job.name}): machine {job.machine!r} is not installed "
                "(see 'gecent machines')",
                job.where,
            )
        if job.dialect is not None and job.dialect.lower() not in {*dialects, "none", "apt"}:
            raise InputError(
                f"job {job.number} ({job.name}): no dialect {job.dialect!r} (dialects: "
                f"{', '.join(sorted(dialects)) or 'none installed'}, or none)",
                job.where,
            )


def _check_type(key: str, value: Any, where: SourcePosition | None) -> None:
    kinds = _TYPES.get(key)
    if kinds is not None and not isinstance(value, kinds):
        expected = " or ".join(
            {
                str: "text",
                int: "a whole number",
                bool: "true/false",
                dict: "a table",
                list: "a list",
            }[kind]
            for kind in kinds
        )
        raise InputError(f"{key} = {value!r}: expected {expected}", where)
    if key == "macros" and isinstance(value, list) and not all(isinstance(v, str) for v in value):
        raise InputError("macros is a list of file names", where)


def outputs_of(job: Job) -> list[str]:
    """The files a job may write (the listing as "auto" counted beside the tape)."""
    found = [job.tape]
    if job.listing is not None:
        found.append(listing_path(job))
    if job.punch is not None:
        found.append(job.punch[1])
    return found


def listing_path(job: Job) -> str:
    return str(Path(job.tape).with_suffix(".lis")) if job.listing in (None, "auto") else job.listing


def _job(
    number: int,
    source: Path,
    name: str,
    tape: Path,
    machine: str | None,
    defaults: JobDefaults,
    row: dict[str, Any],
    where: SourcePosition | None = None,
    base: Path | None = None,
) -> Job:
    def local(value: Any) -> str:
        return str(base / str(value)) if base is not None else str(value)

    machine_text = None
    if machine is not None and (machine.endswith(".toml") or "/" in machine):
        machine = local(machine) if "machine" in row else machine
        machine_file = Path(machine)
        if not machine_file.is_file():
            raise InputError(f"machine file {machine}: no such file", where)
        machine_text = _read_text(machine_file, "machine file", where)
    listing: str | None = "auto" if defaults.listing is None else None
    if defaults.listing:
        listing = str(tape.with_suffix(".lis"))
    if "listing" in row:
        value = row["listing"]
        word = str(value).strip().lower()
        listing = (
            None
            if value is False or word in ("", "no", "none", "false", "0")
            else "auto"
            if value is True or word in ("auto", "yes", "true", "1")
            else local(value)
        )
    punch_code = row.get("punch", defaults.punch)
    punch: tuple[str, str] | None = None
    if punch_code not in (None, "", False):
        code = str(punch_code).lower()
        if code not in PUNCH_CODES:
            raise InputError(f"punch {punch_code!r}: the punch code is eia or ascii", where)
        punch_file = row.get("punch_file")
        punch = (code, local(punch_file) if punch_file else str(tape.with_suffix(".pch")))
    optab = defaults.optab + _optab(row.get("optab"), where)
    macro_files = [*defaults.macros, *(local(m) for m in _list(row.get("macros")))]
    macros = []
    for macro in macro_files:
        if not Path(macro).is_file():
            raise InputError(f"macro file {macro}: no such file", where)
        macros.append((macro, _read_text(Path(macro), "macro file", where)))
    try:
        max_segments = int(str(row.get("max_segments", defaults.max_segments)))
    except (TypeError, ValueError):
        max_segments = -1
    if max_segments < 0:
        raise InputError("max_segments is a whole number, 0 or more", where)
    return Job(
        number=number,
        input=str(source),
        name=name,
        tape=str(tape),
        machine=machine,
        machine_text=machine_text,
        listing=listing,
        punch=punch,
        dialect=str(row.get("dialect", defaults.dialect) or "") or None,
        optab=optab,
        macros=tuple(macros),
        max_segments=max_segments,
        verify=_flag(row.get("verify", defaults.verify), where),
        where=where,
    )


def parse_optab(text: str, where: SourcePosition | None = None) -> tuple[tuple[int, float], ...]:
    """``23=10;264=1`` (a CSV cell, --optab): option number and value pairs."""
    pairs: dict[str, Any] = {}
    for part in text.replace(",", ";").split(";"):
        if part.strip():
            number, sep, value = part.partition("=")
            if not sep:
                raise InputError(f"optab {part.strip()!r}: expected NUMBER=VALUE", where)
            pairs[number.strip()] = value.strip()
    return _optab(pairs, where)


def _optab(value: Any, where: SourcePosition | None) -> tuple[tuple[int, float], ...]:
    if value in (None, ""):
        return ()
    if isinstance(value, str):
        return parse_optab(value, where)
    if not isinstance(value, dict):
        raise InputError("optab is a table of option numbers and values", where)
    pairs = []
    for number, option_value in value.items():
        try:
            pairs.append((int(number), float(option_value)))
        except (TypeError, ValueError):
            raise InputError(
                f"optab {number} = {option_value!r}: an option number and a number", where
            ) from None
    return tuple(pairs)


def _flag(value: Any, where: SourcePosition | None) -> bool:
    if isinstance(value, bool):
        return value
    text = str(value).strip().lower()
    if text in ("1", "true", "yes"):
        return True
    if text in ("", "0", "false", "no"):
        return False
    raise InputError(f"verify {value!r}: expected true or false", where)


def _list(value: Any) -> list[str]:
    if value in (None, ""):
        return []
    if isinstance(value, str):
        return [part for part in value.replace(",", ";").split(";") if part.strip()]
    return [str(item) for item in value]


def _toml_rows(path: Path) -> tuple[list[tuple[dict[str, Any], SourcePosition]], dict[str, Any]]:
    try:
        data = tomllib.loads(_read_text(path, "manifest", SourcePosition(str(path))))
    except tomllib.TOMLDecodeError as exc:
        raise InputError(
            f"the manifest is not valid TOML: {exc}", SourcePosition(str(path))
        ) from None
    unknown = sorted(set(data) - {"defaults", "job"})
    if unknown:
        raise InputError(
            f"unknown manifest table {unknown[0]!r} (a manifest has [defaults] and [[job]])",
            SourcePosition(str(path)),
        )
    defaults = data.get("defaults", {})
    jobs = data.get("job", [])
    if (
        not isinstance(defaults, dict)
        or not isinstance(jobs, list)
        or not all(isinstance(job, dict) for job in jobs)
    ):
        raise InputError(
            "[defaults] is a table and [[job]] an array of tables", SourcePosition(str(path))
        )
    lines = _job_lines(path)
    return [
        (dict(row), SourcePosition(str(path), lines[i] if i < len(lines) else None))
        for i, row in enumerate(jobs)
    ], dict(defaults)


def _job_lines(path: Path) -> list[int]:
    """The line of each ``[[job]]`` header, so an error names it."""
    return [
        number
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1)
        if line.strip().replace(" ", "") == "[[job]]"
    ]


def _read_text(path: Path, what: str, where: SourcePosition | None) -> str:
    try:
        return path.read_text(encoding="utf-8")
    except UnicodeDecodeError as exc:
        raise InputError(f"{what} {path}: byte {exc.start} is not UTF-8 text", where) from None
    except OSError as exc:
        raise InputError(f"{what} {path}: {exc.strerror}", where) from None


def _csv_rows(path: Path) -> list[tuple[dict[str, Any], SourcePosition]]:
    text = _read_text(path, "manifest", SourcePosition(str(path)))
    with io.StringIO(text.removeprefix("\ufeff"), newline="") as handle:  # (Excel's BOM)
        reader = csv.DictReader(handle)
        if reader.fieldnames is None or "input" not in reader.fieldnames:
            raise InputError(
                "a CSV manifest's header row names an 'input' column", SourcePosition(str(path), 1)
            )
        rows = []
        for row in reader:
            where = SourcePosition(str(path), reader.line_num)
            if None in row:
                raise InputError("more cells than the header has columns", where)
            rows.append(({k.strip(): v.strip() for k, v in row.items() if v and v.strip()}, where))
    return rows


def _stem(path: Path) -> str:
    """The output's name before its suffix: the whole input name, so part.apt and part.cls
    in one folder do not write one tape."""
    return path.name


def _folder_name(machine: str | None) -> str:
    if machine is None:
        return "as-named"
    return Path(machine).stem if machine.endswith(".toml") else machine


def _patterns() -> str:
    return ", ".join(f"*{suffix}" for suffix in CL_SUFFIXES) + ", *.ncl.<n>"
