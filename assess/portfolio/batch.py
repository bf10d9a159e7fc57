"""A portfolio of buildings: each one's assessment, a summary across them, and what changed.

``assess batch PORTFOLIO`` reads a portfolio (:func:`read_portfolio`): an
``.xlsx`` with a sheet ``buildings`` (``building``, ``workbook``, optional
``oq_hazard`` and ``level``), or a folder of workbooks. It checks every
building's input before anything runs (:func:`prepare_buildings`), then
assesses each one with the main job (:func:`assess.assessment.pipeline.run_assessment`)
through one :class:`~assess.command.cache.CachingRunner`, so that a case simulated
before (same item, same motion, same engine) is not simulated again, and
writes (:func:`run_portfolio`, :meth:`StagedPortfolio.commit`)::

    <out>/<building>/     what assess WORKBOOK --hazard LEVEL writes (summary.csv, motions.csv, report)
    <out>/portfolio.csv   one row per building: items by risk and by action, cases simulated and reused
    <out>/portfolio.html  the same, and the change report
    <out>/changes.csv     what changed since the previous run in <out>, one row per item and quantity
    <out>/previous/<building>/summary.csv   the summaries this run compared with
    <out>/.cache/         the stored engine results (assess.command.cache)
    <out>/.portfolio.json what each building's folder was made from (to keep it when nothing changed)

A building whose inputs (workbook, records, hazard curve, level, seed,
formats, code) are those of the previous run keeps its folder; the others
are assessed again, their unchanged cases answered by the cache. The tables
and the page across buildings are made in :mod:`assess.portfolio.report`.

Everything is written into a folder beside ``<out>`` that takes its place in
one rename once every building is done, so a run that fails or is
interrupted leaves the previous ``<out>`` as it was (its cache keeps what the
failed run simulated, so the next run reuses it).
"""
from __future__ import annotations

import contextlib
import hashlib
import importlib.metadata
import io
import json
import os
import re
import shutil
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import pandas as pd

import assess
from assess.assessment import pipeline
from assess.assessment.inputs import check_inputs
from assess.assessment.motions import check_level
from assess.command import output
from assess.command.cache import CachingRunner
from assess.report import advice
from assess.command.folders import (OUTPUT_NAMES, existing_folder, folder_mode, machine_refusal, refuse_foreign_files,
                                    refuse_open_office_files, swap_folder, write_files)
from assess.command.job import JOB_FORMATS, Say, open_runner, set_threads
from assess.errors import InputError, Problem, raise_if_any
from assess.hazard.levels import parse_level
from assess.hazard.records import check_record_location
from assess.hazard.usgs import read_hazard_curve_file
from assess.inventory import read_workbook, schema, xlsx
from assess.inventory.schema import Column, SheetSpec
from assess.inventory.workbook import SheetReport, open_book, read_table, same_name_sheets, sheet_cells
from assess.portfolio.report import building_row, changes_between, portfolio_html
from assess.report.tables import declared_csv_text, restore_text

#: The sheet of a portfolio workbook (docs/workbook.md).
BUILDINGS = SheetSpec("buildings", (
    Column("building", "text", required=True, max_chars=80),
    Column("workbook", "text", required=True, max_chars=255),
    Column("oq_hazard", "text", default="", max_chars=255),
    Column("level", "level"),
), subject="a building")
#: Files and folders of a portfolio's output folder besides the buildings' folders.
PORTFOLIO_FILES = ("portfolio.csv", "portfolio.html", "changes.csv")
CACHE_FOLDER, PREVIOUS_FOLDER = ".cache", "previous"
#: What the previous run recorded of each building (its inputs' key, its files), for reusing its folder.
MANIFEST = ".portfolio.json"
#: Files of the package that the outputs depend on (code, templates, packaged data).
_CODE_SUFFIXES = {".py", ".j2", ".css", ".toml", ".csv", ".json"}
_RESERVED = {name.lower() for name in PORTFOLIO_FILES + (CACHE_FOLDER, PREVIOUS_FOLDER, MANIFEST)}
#: What a file browser leaves in a folder it has shown.
_BROWSER_FILES = {".DS_Store", "Thumbs.db", "desktop.ini"}
#: Most buildings in one portfolio (a university campus has some hundreds).
MAX_BUILDINGS = 2_000
#: Bytes of a building name in UTF-8 (it names a folder: 255 bytes at most, less the temporary folders' additions).
MAX_NAME_BYTES = 200
#: A building's name becomes a folder name: letters, digits, space and . _ - ( ) +.
_BUILDING_NAME = re.compile(r"[\w][\w .()+-]*")
#: Largest previous summary.csv read for the change report [bytes].
MAX_PREVIOUS_BYTES = 200 * 2**20


@dataclass(frozen=True)
class Building:
    """One building of a portfolio: its name (its output folder), workbook, level and hazard curve.

    ``level`` and ``oq_hazard`` are None where the portfolio leaves them to
    the defaults (:func:`prepare_buildings`); ``source`` locates the building
    in the portfolio for messages (``portfolio.xlsx, sheet 'buildings', row 3``).
    """

    name: str
    workbook: Path
    level: str | None = None
    oq_hazard: Path | None = None
    source: str = ""
    portfolio: str = ""
    sheet: str | None = None
    row: int | None = None

    def problem(self, message: str, fix: str, column: str | None = None) -> Problem:
        """A problem located at this building's row of the portfolio (its workbook for a folder portfolio)."""
        if self.row is None:
            return Problem(file=str(self.workbook), message=message, fix=fix)
        return Problem(file=self.portfolio, sheet=self.sheet, row=self.row, column=column, message=message, fix=fix)


# ---------------------------------------------------------------- reading the portfolio

def read_portfolio(path, *, allow_outside: bool = False) -> list[Building]:
    """The buildings of a portfolio: an ``.xlsx`` with a sheet ``buildings``, or a folder of workbooks.

    Paths in the sheet are relative to the portfolio's folder and must lie in
    it or below it (once links are followed), as records must lie in their
    workbook's folder, unless ``allow_outside``. A folder portfolio is every
    ``*.xlsx`` directly in the folder (not its subfolders; Excel's ``~$`` lock
    files and hidden files skipped), each building named by its file's stem.

    Raises :class:`~assess.errors.InputError` naming the file, sheet, row and
    cell of every problem.
    """
    given = str(path)
    path = Path(path)
    if path.is_dir():
        return _folder_portfolio(path, given, allow_outside)
    problems: list[Problem] = []
    report = SheetReport(given, None, problems)
    with open_book(path, report) as book:
        same = same_name_sheets(book.sheetnames, BUILDINGS.name)
        if len(same) > 1:
            shown = " and ".join("'" + schema.clip(t, 40) + "'" for t in same[:4])
            report(f"the sheets {shown} all name the {BUILDINGS.name} sheet (sheet names are matched ignoring "
                   "case and spaces around them), so which one holds the table is not clear.",
                   f"keep one sheet named '{BUILDINGS.name}': delete or rename the others.")
            raise InputError(problems)
        title = same[0] if same else None
        if title is None or not book.is_table(title):
            have = ", ".join(f"'{schema.clip(t, 40)}'" for t in book.sheetnames[:20])
            report(f"the portfolio has no sheet '{BUILDINGS.name}'; it has the sheets {have}.",
                   "add a sheet named 'buildings' with the columns building, workbook and, optionally, "
                   "oq_hazard and level (one row per building), or give a folder of workbooks.")
            raise InputError(problems)
        sheet_report = SheetReport(given, title, problems)
        cells = sheet_cells(book, title, sheet_report)
        table = read_table(BUILDINGS, cells, sheet_report) if cells is not None else None
    raise_if_any(problems)
    if len(table.rows) > MAX_BUILDINGS:
        sheet_report(f"the sheet lists {len(table.rows):,} buildings; a portfolio is read up to "
                     f"{MAX_BUILDINGS:,}.", "split it into several portfolios.", row=table.rows[-1].number)
        raise InputError(problems)
    folder = path.parent
    buildings, first_row = [], {}
    for row in table.rows:
        if not row.ok("building", "workbook"):
            continue
        name = str(row.values["building"])
        header = table.headers["building"]
        why = building_name_problem(name)
        if why:
            sheet_report.at(row.number, header, why, "name the building with letters, digits, spaces and "
                            ". _ - ( ) +, starting with a letter or digit (it names its output folder).")
            continue
        if name.lower() in first_row:
            sheet_report.at(row.number, header, f"the building '{name}' is already in row {first_row[name.lower()]} "
                            "(names are compared ignoring case: each names an output folder).",
                            "give every building its own name.")
            continue
        first_row[name.lower()] = row.number
        workbook = _portfolio_file(row, "workbook", table.headers, folder, allow_outside, sheet_report,
                                   (".xlsx", ".xlsm"))
        curve = None
        if row.values.get("oq_hazard"):
            curve = _portfolio_file(row, "oq_hazard", table.headers, folder, allow_outside, sheet_report, None)
        level = None
        if row.ok("level") and row.values.get("level") is not None:
            level = str(row.raw["level"]).strip()
        if workbook is not None and (curve is not None or not row.values.get("oq_hazard")):
            buildings.append(Building(name, workbook, level, curve,
                                      source=f"{given}, sheet '{title}', row {row.number}",
                                      portfolio=given, sheet=title, row=row.number))
    raise_if_any(problems)
    return buildings


def building_name_problem(name: str) -> str | None:
    """Why ``name`` cannot name a building's output folder; None when it can."""
    if not _BUILDING_NAME.fullmatch(name) or name != name.strip() or name.endswith("."):
        return (f"the building name {schema.quote(name)} cannot name a folder: use letters, digits, spaces and "
                ". _ - ( ) +, starting with a letter or digit and not ending with a dot or a space.")
    if name.lower() in _RESERVED:
        return f"the building name {schema.quote(name)} is the name of a file the portfolio writes itself."
    if len(name.encode("utf-8")) > MAX_NAME_BYTES:  # 80 characters may be 320 bytes; file names hold 255
        return (f"the building name is {len(name.encode('utf-8'))} bytes in UTF-8; a folder name may have at most "
                f"{MAX_NAME_BYTES} (letters outside ASCII take 2 to 4 bytes each).")
    return None


def _portfolio_file(row, column: str, headers: dict, folder: Path, allow_outside: bool, report,
                    suffixes: tuple[str, ...] | None) -> Path | None:
    """The file a cell names, relative to the portfolio's folder; None after reporting it at the cell."""
    text = str(row.values[column])
    header = headers.get(column)
    what = "workbook" if column == "workbook" else "hazard curve"
    if any(not c.isprintable() for c in text):
        report.at(row.number, header, f"the {what} path holds control characters.",
                  f"write the {what}'s file name on one line.")
        return None
    try:
        path = (folder / text).resolve()
        exists = path.is_file()
    except (OSError, RuntimeError, ValueError) as error:
        report.at(row.number, header, f"the {what} path {schema.quote(text)} cannot be followed "
                  f"({getattr(error, 'strerror', None) or type(error).__name__}).",
                  f"give the path of the {what} file, relative to the portfolio's folder.")
        return None
    outside = check_record_location(str(path), folder)
    if outside and not allow_outside:
        report.at(row.number, header, f"the {what} {schema.quote(text)} is outside the portfolio's folder "
                  f"{os.path.realpath(folder)}; files are read only from that folder and its subfolders, so "
                  "that a portfolio cannot make assess read other files of this machine.",
                  f"copy the {what} into the portfolio's folder (or a subfolder) and give its path relative to "
                  "the portfolio, or run with --allow-files-outside if you trust this portfolio.")
        return None
    if not exists:
        report.at(row.number, header, f"the {what} {schema.quote(text)} was not found (looked for "
                  f"{schema.clip(str(path), 200)}).",
                  f"correct the path (relative to the portfolio's folder), or put the {what} there.")
        return None
    if suffixes is not None and path.suffix.lower() not in suffixes:
        report.at(row.number, header, f"{schema.quote(text)} is not an Excel workbook (.xlsx).",
                  "give the building's inventory workbook (.xlsx).")
        return None
    return path


def _folder_portfolio(folder: Path, given: str, allow_outside: bool) -> list[Building]:
    """Every ``*.xlsx`` directly in ``folder``, each a building named by its file's stem."""
    problems = []
    try:
        entries = sorted(folder.iterdir(), key=lambda p: p.name)
    except OSError as error:
        raise InputError([Problem(file=given, message=f"the folder cannot be read ({error.strerror}).",
                                  fix="check that you may read it.")]) from None
    workbooks = [p for p in entries if p.suffix.lower() == ".xlsx" and not p.name.startswith(("~$", "."))]
    if not workbooks:
        raise InputError([Problem(file=given, message="the folder holds no workbook (.xlsx).",
                                  fix="give a folder of inventory workbooks, or a portfolio workbook with a "
                                      "sheet 'buildings'.")])
    if len(workbooks) > MAX_BUILDINGS:
        raise InputError([Problem(file=given, message=f"the folder holds {len(workbooks):,} workbooks; a "
                                  f"portfolio is read up to {MAX_BUILDINGS:,}.", fix="split it into several folders.")])
    buildings, seen = [], {}
    for path in workbooks:
        name = path.stem
        why = building_name_problem(name)
        if why is None and name.lower() in seen:
            why = f"the building name '{name}' is also that of {seen[name.lower()]} (names ignore case)."
        outside = check_record_location(str(path), folder)
        if why is None and xlsx.file_problem(path) is not None:  # a link loop, a FIFO: before any resolve or open
            why = xlsx.file_problem(path)
        elif outside and not allow_outside:
            why = (f"{path.name} is a link to a file outside the folder ({os.path.realpath(path)[:200]}); files "
                   "are read only from the portfolio's folder and its subfolders.")
        if why:
            problems.append(Problem(file=str(path), message=why,
                                    fix="rename the workbook (its name, without .xlsx, names the building's "
                                        "output folder), or move it out of the portfolio's folder."))
            continue
        seen[name.lower()] = path.name
        buildings.append(Building(name, path.resolve(), source=str(path)))
    raise_if_any(problems)
    return buildings


# ---------------------------------------------------------------- checking every building first

@dataclass
class PreparedBuilding:
    """A building ready to run: its inventory read and checked, its level and hazard curve chosen."""

    building: Building
    inventory: object
    level: str
    curve: object = None  # an OpenQuakeHazard, or None
    allow_records_outside: bool = False


def prepare_buildings(buildings: list[Building], *, level: str | None = None, oq_hazard=None,
                      allow_records_outside: bool = False,
                      say: Callable[[str], None] = lambda message: None) -> list[PreparedBuilding]:
    """Read every building's workbook and hazard curve and choose its level, before anything runs.

    A building's level is its row's ``level``, else ``level`` (``--hazard``),
    else the one level its hazard sheet defines (a workbook with several, or
    with a site sheet and none, needs one of the other two). A workbook with a
    ``site`` sheet (and a ``building`` sheet) has its ground suite and floor
    motions made as ``assess WORKBOOK`` makes them (:mod:`assess.assessment.floors`);
    a level its site sheet gives no target spectrum for is refused here. A building's curve is its row's ``oq_hazard``,
    else ``oq_hazard`` (``--oq-hazard``: a path, read once for all). What the main command
    refuses in a hazard sheet is refused here too (:func:`assess.assessment.inputs.hazard_problems`:
    records outside the workbook's folder unless ``allow_records_outside``, a vp of 0). Every problem of
    every building is raised together.
    """
    problems: list[Problem] = []
    curves: dict[Path, object] = {}

    def curve_of(path: Path):
        """The curve at ``path``, read once; its problems raised once, for the first building naming it."""
        if path not in curves:
            try:
                curves[path] = read_hazard_curve_file(path)
            except InputError:
                curves[path] = None
                raise
        if curves[path] is None:
            raise InputError([])
        return curves[path]

    prepared = []
    if oq_hazard is not None:  # named on the command line: read even if every row names its own
        try:
            curve_of(Path(oq_hazard))
        except InputError as error:
            problems.extend(error.problems)
    for building in buildings:
        say(f"checking {building.name} ({building.workbook.name})")
        try:
            inventory = read_workbook(building.workbook)
            for warning in inventory.warnings:  # assessed as written; the flags and the report say it too
                say(f"warning: {building.name}: {warning}")
            check_inputs(inventory, allow_records_outside)
            chosen = building.level or level
            if chosen is None:
                levels = list(dict.fromkeys(inventory.hazard["level_label"]))
                if len(levels) != 1:
                    raise InputError([building.problem(_no_level_message(building, inventory, levels),
                        "give the level in the portfolio's 'level' column, or run with --hazard LEVEL.", "level")])
                chosen = str(levels[0])
            try:  # a site sheet gives any level it has a target spectrum for (as the main command)
                check_level(inventory, chosen)
            except InputError as error:  # said at the building's row, where the level was chosen
                raise InputError([building.problem(
                    f"building '{building.name}': {p.message}", p.fix or "",
                    "level" if building.level else None) if building.row is not None or building.level is None
                    else p for p in error.problems]) from None
            curve_path = building.oq_hazard or (Path(oq_hazard) if oq_hazard is not None else None)
            curve = curve_of(curve_path) if curve_path is not None else None
            if curve is not None and curve.kind != "curve":
                raise InputError([building.problem(
                    f"{curve_path.name} is an OpenQuake hazard map; a portfolio integrates the items' "
                    "fragilities over a hazard curve (the map's values at a few probabilities cannot be "
                    "integrated).", "give the site's hazard curve (hazard_curve-mean-PGA.csv), or no curve.",
                    "oq_hazard" if building.oq_hazard else None)])
        except InputError as error:
            problems.extend(error.problems)
            continue
        prepared.append(PreparedBuilding(building, inventory, chosen, curve, allow_records_outside))
    raise_if_any(problems)
    return prepared


def _no_level_message(building: Building, inventory, levels: list) -> str:
    """Why a building whose row and ``--hazard`` give no level has none."""
    named = ", ".join(f"'{schema.clip(v, 40)}'" for v in levels[:10])
    text = f"the building '{building.name}' has no level, and its workbook {building.workbook.name} "
    if inventory.site is None:
        return text + f"defines {len(levels)} ({named})."
    return text + ("has a site sheet, which makes the ground motions of any level it has a target spectrum "
                   "for (DE, MCE_R; a probability such as 2% in 50 years with a 'uhs' file)"
                   + (f", besides the hazard sheet's {len(levels)} ({named})." if levels else "."))


# ---------------------------------------------------------------- the output folder

def check_portfolio_folder(out_dir: Path) -> None:
    """Refuse an output folder the batch may not replace: one holding anything it did not write.

    It may be new, or hold what a batch writes: :data:`PORTFOLIO_FILES`, the
    cache and previous summaries, and building folders holding only what the
    main job writes (:data:`assess.command.folders.OUTPUT_NAMES`).
    """
    out_dir = Path(out_dir)
    if not existing_folder(out_dir, "batch run"):
        return
    foreign = []
    refuse_open_office_files(out_dir, [entry.name for entry in out_dir.iterdir()])
    for entry in sorted(out_dir.iterdir(), key=lambda p: p.name):
        name = entry.name
        if entry.is_dir() and not entry.is_symlink():
            refuse_open_office_files(entry, [child.name for child in entry.iterdir()])
        if name in _BROWSER_FILES or (name in PORTFOLIO_FILES + (MANIFEST,) and entry.is_file()
                                      and not entry.is_symlink()):
            continue
        if name in (CACHE_FOLDER, PREVIOUS_FOLDER) and entry.is_dir() and not entry.is_symlink():
            continue
        if entry.is_dir() and not entry.is_symlink() and not name.startswith(".") \
                and all(child.name in OUTPUT_NAMES for child in entry.iterdir()):
            continue
        foreign.append(name)
    refuse_foreign_files(out_dir, foreign, command="assess batch", run="batch run")


@dataclass
class StagedPortfolio:
    """A finished batch, written into ``staging`` beside ``out_dir``, not yet in its place.

    :meth:`commit` swaps it in (the cache carried over); :meth:`discard` removes it.
    """

    out_dir: Path
    staging: Path | None
    summary: pd.DataFrame
    changes: pd.DataFrame
    files: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    cases_simulated: int = 0
    cases_reused: int = 0

    def commit(self) -> Path:
        """Make ``out_dir`` the staged folder, keeping the cache; on failure leave ``out_dir`` as it was."""
        out_dir, staging = self.out_dir, self.staging
        cache, staged_cache = out_dir / CACHE_FOLDER, staging / CACHE_FOLDER
        moved = False
        aside = None
        try:
            if cache.is_dir():
                os.replace(cache, staged_cache)
                moved = True
            aside = swap_folder(staging, out_dir)
            self.staging = None
        except BaseException as error:
            if moved and staged_cache.is_dir():
                with contextlib.suppress(OSError):
                    os.replace(staged_cache, cache)
            if machine_refusal(error, out_dir) is not None:
                raise machine_refusal(error, out_dir) from None
            raise
        finally:
            if aside is not None:
                shutil.rmtree(aside, ignore_errors=True)
        return out_dir

    def discard(self) -> None:
        if self.staging is not None:
            shutil.rmtree(self.staging, ignore_errors=True)
            self.staging = None


def default_out_dir(portfolio: Path) -> Path:
    """``reports/<portfolio stem>/`` (a folder portfolio: its name)."""
    portfolio = Path(portfolio)
    return Path("reports") / (portfolio.name if portfolio.is_dir() else portfolio.stem)


# ---------------------------------------------------------------- running

def run_portfolio(prepared: list[PreparedBuilding], out_dir: Path, *, runner, seed: int = 0,
                  formats: tuple[str, ...] = ("html", "pdf", "xlsx"), units: str | None = None,
                  say: Callable[[str], None] = lambda message: None, spread=None) -> StagedPortfolio:
    """Assess every building through ``runner`` (a :class:`~assess.command.cache.CachingRunner`), writing into a
    staging folder beside ``out_dir``; returns it staged (:meth:`StagedPortfolio.commit` puts it in place).

    Each building's folder is what ``assess WORKBOOK --hazard LEVEL`` writes.
    A building none of whose inputs changed since the previous run in
    ``out_dir`` (:func:`building_key`: its workbook, records and hazard curve,
    level, seed, formats, the code) keeps its folder as it is, when the folder's
    files are those that run wrote; the others are assessed, their simulations
    reused from the cache where their cases did not change. ``spread`` (a
    :class:`~assess.portfolio.spread.BuildingSpread`, on a cluster) assesses
    them on the cluster's workers, when it applies, with the same files and counts.
    """

    out_dir = Path(out_dir)
    if out_dir.is_symlink():
        out_dir = out_dir.resolve()
    check_portfolio_folder(out_dir)
    previous = _previous_summaries(out_dir)
    before_manifest = _read_manifest(out_dir)
    out_dir.parent.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix=f".{out_dir.name}-new-", dir=out_dir.parent))
    staged = StagedPortfolio(out_dir, staging, pd.DataFrame(), pd.DataFrame())
    try:
        os.chmod(staging, folder_mode(out_dir))
        rows, current, manifest = [], {}, {}
        version = code_version()
        total = len(prepared)
        keys = [building_key(item, seed=seed, formats=formats, units=units, version=version) for item in prepared]
        outcomes = {}
        pending = [] if spread is None else [  # the buildings to assess (their folders are read again below)
            number for number, (item, key) in enumerate(zip(prepared, keys))
            if _unchanged_folder(out_dir / item.building.name, before_manifest.get(item.building.name), key) is None]
        if spread is not None and spread.applies([prepared[k] for k in pending]):
            say(f"on the cluster: {spread.reason}")

            def deliver(number, outcome):  # written as it arrives; only the digests and summary.csv are kept
                files = outcome.files
                write_files(staging / prepared[pending[number]].building.name, files)
                outcome.files = {name: _digest(data) for name, data in files.items()}
                outcome.summary_csv = files["summary.csv"]

            outcomes = dict(zip(pending, spread.assess([prepared[k] for k in pending], seed=seed, formats=formats,
                                                       units=units, say=say, deliver=deliver)))
        elif spread is not None:
            say(f"on the cluster: {spread.reason}")
        for number, item in enumerate(prepared, start=1):
            building = item.building
            tag = f"[{number}/{total}] {building.name}"
            say(f"{tag}: {building.workbook.name} at level {item.level}"
                + (f", hazard curve {Path(item.curve.path).name}" if item.curve is not None else ""))
            started = time.perf_counter()
            key = keys[number - 1]
            kept = None if number - 1 in outcomes else \
                _unchanged_folder(out_dir / building.name, before_manifest.get(building.name), key)
            if number - 1 in outcomes:
                outcome = outcomes[number - 1]  # its files written as it arrived (``deliver``)
                summary, level_label = outcome.summary, outcome.level_label
                simulated, reused = outcome.simulated, outcome.reused
                entry = dict(key=key, cases=simulated + reused, level_label=level_label, files=outcome.files)
                kept = {"summary.csv": outcome.summary_csv}
            elif kept is not None:
                write_files(staging / building.name, kept)
                entry = dict(before_manifest[building.name])
                summary = _restored_summary(kept["summary.csv"])
                simulated, reused, level_label = 0, int(entry["cases"]), str(entry["level_label"])
                say(f"{tag}: unchanged since the previous run (workbook, records, hazard curve, level, code): "
                    f"its folder is kept, {reused} cases reused")
            else:
                before = (runner.cases_simulated, runner.cases_reused)
                # the curve integrates the fragilities into annual rates; it does not rescale the motions
                # (that is the main command's --oq-hazard), so the level's simulations never depend on it
                result = pipeline.run_assessment(item.inventory, item.level, seed=seed, runner=runner,
                                        hazard_curve=item.curve, allow_records_outside=item.allow_records_outside,
                                        progress=lambda message, tag=tag: say(f"{tag}: {message}"))
                result = advice.with_words(result)  # the advice in words, in the report's units
                files = output.render_outputs(result, formats, units=units)
                write_files(staging / building.name, files)
                simulated, reused = runner.cases_simulated - before[0], runner.cases_reused - before[1]
                summary, level_label = result.summary, result.level_label
                entry = dict(key=key, cases=simulated + reused, level_label=level_label,
                             files={name: _digest(data) for name, data in files.items()})
                kept = files
            manifest[building.name] = entry
            current[building.name] = kept["summary.csv"]
            rows.append(building_row(building.name, building.workbook.name, level_label,
                                     Path(item.curve.path).name if item.curve is not None else "", summary,
                                     simulated, reused))
            counts = summary["risk"].value_counts()
            seconds = outcomes[number - 1].seconds if number - 1 in outcomes else time.perf_counter() - started
            where = " on a worker" if number - 1 in outcomes else ""
            say(f"{tag}: {simulated} cases simulated, {reused} reused, {seconds:.1f} s{where}; "
                f"{counts.get('high', 0)} high, {counts.get('moderate', 0)} moderate, {counts.get('low', 0)} low risk")
        staged.summary = pd.DataFrame(rows)
        staged.changes = changes_between(
            {name: data for name, (_, data) in previous.items()},
            {name.lower(): data for name, data in current.items()},
            {name.lower(): name for name in [p[0] for p in previous.values()] + list(current)})
        staged.cases_simulated = int(staged.summary["cases_simulated"].sum()) if rows else 0
        staged.cases_reused = int(staged.summary["cases_reused"].sum()) if rows else 0
        files = {"portfolio.csv": declared_csv_text("portfolio.csv", staged.summary).encode(),
                 "changes.csv": declared_csv_text("changes.csv", staged.changes).encode(),
                 "portfolio.html": portfolio_html(staged, bool(previous)).encode(),
                 MANIFEST: (json.dumps(manifest, indent=1, sort_keys=True) + "\n").encode()}
        for name, data in previous.values():
            files[f"{PREVIOUS_FOLDER}/{name}/summary.csv"] = data
        write_files(staging, files)
        staged.files = sorted(n for n in files if n != MANIFEST) + [f"{name}/" for name in current]
        return staged
    except BaseException as error:
        staged.discard()
        if machine_refusal(error, out_dir) is not None:  # a full disk, a quota: the machine's, not a bug
            raise machine_refusal(error, out_dir) from None
        raise


# ---------------------------------------------------------------- the job of assess batch PORTFOLIO

@dataclass
class BatchJob:
    """``assess batch PORTFOLIO`` and its options (docs/commands.md)."""

    portfolio: Path
    out: Path | None = None
    hazard: str | None = None
    oq_hazard: Path | None = None
    scheduler: str | None = None
    scheduler_tls: dict = field(default_factory=dict)
    formats: tuple[str, ...] = JOB_FORMATS
    seed: int = 0
    jobs: int | None = None
    allow_files_outside: bool = False


def run_batch(job: BatchJob, say: Say = lambda message: None) -> tuple[StagedPortfolio, CachingRunner, Path]:
    """Assess every building of the portfolio, staged beside its output folder (:meth:`StagedPortfolio.commit`
    puts it in place); also returns the caching runner (its counts and the cache's write errors) and the output
    folder as given."""
    if job.hazard is not None:
        try:
            parse_level(job.hazard)
        except ValueError as error:
            raise InputError([Problem(file="--hazard", message=str(error))]) from None
    set_threads(job.jobs)
    out_dir = Path(job.out or default_out_dir(job.portfolio))
    check_portfolio_folder(out_dir)
    say(f"reading {job.portfolio}")
    buildings = read_portfolio(job.portfolio, allow_outside=job.allow_files_outside)
    prepared = prepare_buildings(buildings, level=job.hazard, oq_hazard=job.oq_hazard,
                                 allow_records_outside=job.allow_files_outside, say=say)
    with open_runner(job.scheduler, lambda message: None, out_dir / CACHE_FOLDER,
                     tls=job.scheduler_tls) as runner:
        say(f"{len(prepared)} buildings; results are reused from {out_dir / CACHE_FOLDER}")
        spread = None
        if job.scheduler is not None:
            from assess.portfolio.spread import BuildingSpread
            spread = BuildingSpread(runner, files_of=lambda item: [item.building.workbook, *building_records(item)])
        staged = run_portfolio(prepared, out_dir, runner=runner, seed=job.seed, formats=job.formats, say=say,
                               spread=spread)
    return staged, runner, out_dir


def code_version() -> str:
    """Hash of the code an output folder depends on: every file of the ``assess`` package and the
    report templates, and the versions of the libraries that compute or draw (numpy, numba, pandas,
    matplotlib)."""
    digest = hashlib.blake2b(digest_size=16)
    package = Path(assess.__file__).resolve().parent
    folders = [package, package.parent / "templates"]
    for folder in folders:
        if not folder.is_dir():
            continue
        for path in sorted(folder.rglob("*")):
            if path.is_file() and "__pycache__" not in path.parts and path.suffix in _CODE_SUFFIXES:
                digest.update(str(path.relative_to(folder)).encode() + b"\0" + path.read_bytes() + b"\0")
    for library in ("numpy", "numba", "pandas", "matplotlib", "scipy"):
        with contextlib.suppress(importlib.metadata.PackageNotFoundError):
            digest.update(f"{library}={importlib.metadata.version(library)}\0".encode())
    return digest.hexdigest()


def building_key(item: PreparedBuilding, *, seed: int, formats, units: str, version: str) -> str:
    """Hash of everything a building's folder depends on: the bytes of its workbook, of every record its
    hazard sheet names, of its site sheet's uniform-hazard spectrum and records folder, and of its hazard
    curve; its level, the seed, formats and units; the code."""
    digest = hashlib.blake2b(digest_size=16)
    digest.update(f"{version}|{item.level}|{seed}|{sorted(formats)}|{units}|".encode())
    digest.update(_file_digest(item.building.workbook).encode())
    for record in building_records(item):
        digest.update(f"|{record}|{_file_digest(Path(record))}".encode())
    if item.curve is not None:
        digest.update(f"|curve|{_file_digest(Path(item.curve.path))}".encode())
    return digest.hexdigest()


def building_records(item: PreparedBuilding) -> list[str]:
    """The files besides its workbook that a building's assessment reads: every record its hazard sheet names,
    its site sheet's uniform-hazard spectrum and the records of its records folder."""
    hazard = item.inventory.hazard
    records = sorted({str(p) for column in hazard.columns if column.endswith("_path")  # record_path, and
                      for p in hazard[column] if isinstance(p, str) and p})           # any other record column
    site = item.inventory.site
    if site is not None:
        if site.uhs_path:
            records.append(site.uhs_path)
        if site.records_folder:
            records += sorted(str(p) for p in Path(site.records_folder).rglob("*") if p.is_file())
    return records


def _file_digest(path: Path) -> str:
    digest = hashlib.blake2b(digest_size=16)
    with open(path, "rb") as stream:
        while chunk := stream.read(1 << 20):
            digest.update(chunk)
    return digest.hexdigest()


def _digest(data: bytes) -> str:
    return hashlib.blake2b(data, digest_size=16).hexdigest()


def _read_manifest(out_dir: Path) -> dict:
    """What the previous run recorded of each building (its key, cases, files); {} when unreadable."""
    path = out_dir / MANIFEST
    try:
        if path.is_symlink() or path.stat().st_size > 16 * 2**20:
            return {}
        manifest = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    if not isinstance(manifest, dict):
        return {}
    return {name: entry for name, entry in manifest.items()
            if isinstance(entry, dict) and isinstance(entry.get("key"), str) and isinstance(entry.get("files"), dict)
            and isinstance(entry.get("cases"), int) and isinstance(entry.get("level_label"), str)}


def _unchanged_folder(folder: Path, entry: dict | None, key: str) -> dict[str, bytes] | None:
    """The files of a building's previous folder when its key is ``key`` and the folder holds exactly
    the files that run wrote, byte for byte; else None (the building is assessed again)."""
    if entry is None or entry["key"] != key or not folder.is_dir() or folder.is_symlink():
        return None
    try:
        paths = [p for p in folder.rglob("*") if p.name not in _BROWSER_FILES]
        if any(p.is_symlink() or not (p.is_file() or p.is_dir()) for p in paths):
            return None
        present = sorted(p.relative_to(folder).as_posix() for p in paths if p.is_file())
        if present != sorted(entry["files"]):
            return None
        files = {name: (folder / name).read_bytes() for name in present}
    except OSError:
        return None
    if any(_digest(data) != entry["files"][name] for name, data in files.items()):
        return None
    return files


def _restored_summary(data: bytes) -> pd.DataFrame:
    """summary.csv as the assessment's table: numbers as numbers, text as it was before neutralising."""
    return restore_text(pd.read_csv(io.BytesIO(data), dtype={"id": str, "name": str}, keep_default_na=False,
                                    na_values=[""]))


def _previous_summaries(out_dir: Path) -> dict[str, tuple[str, bytes]]:
    """The previous run's summary.csv of every building folder in ``out_dir``: name (lower case) ->
    (folder name, bytes). A summary too large to be ours is skipped."""
    found = {}
    if not out_dir.is_dir():
        return found
    for entry in sorted(out_dir.iterdir(), key=lambda p: p.name):
        summary = entry / "summary.csv"
        if entry.name.startswith(".") or entry.name in (PREVIOUS_FOLDER,) or not summary.is_file() \
                or summary.is_symlink():
            continue
        with contextlib.suppress(OSError):
            if summary.stat().st_size <= MAX_PREVIOUS_BYTES:
                found[entry.name.lower()] = (entry.name, summary.read_bytes())
    return found
