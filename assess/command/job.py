"""The jobs the commands run: ``assess WORKBOOK`` and ``assess calibrate`` (``assess batch``:
:func:`assess.portfolio.batch.run_batch`).

A job reads its inputs, checks them (every rule before anything runs), runs
the engine through one runner whose life it owns (this machine's threads or a
Dask cluster, closed when the job ends), and returns the files to write, in
memory. The command line (:mod:`assess.cli`) only parses the arguments into a
job, writes what it returns and prints; the commands are described in
docs/commands.md.
"""
from __future__ import annotations

import contextlib
import json
import re
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Callable, Iterator

import numba

from assess import report
from assess.assessment import pipeline
from assess.assessment.alpha_range import alpha_ends
from assess.assessment.comparison import compare_summaries, read_previous_summary
from assess.assessment.inputs import check_inputs
from assess.assessment.motions import check_level
from assess.assessment.result import AssessmentResult
from assess.calibration import read_measured, run_calibration
from assess.calibration.apply import read_calibration
from assess.command import output
from assess.command.cache import CachingRunner
from assess.command.folders import check_output_folder
from assess.command.option_values import JOB_FORMATS
from assess.errors import InputError, Problem
from assess.hazard.levels import parse_level
from assess.hazard.openquake import SITE_FORMS, parse_site_choice
from assess.hazard.usgs import read_hazard_curve_file
from assess.inventory import read_workbook
from assess.mechanics.runner import LocalRunner
from assess.quantity_text import system_of
from assess.report import advice
from assess.report.calibration import render_calibration_html
from assess.report.tables import declared_csv_text, restore_text, summary_text

Say = Callable[[str], None]


# ---------------------------------------------------------------- shared by every job

def set_threads(jobs: int | None) -> None:
    """Use ``jobs`` threads for the engine's cases (None: all cores); the numbers do not depend on it."""
    if jobs is not None:
        numba.set_num_threads(min(jobs, numba.config.NUMBA_NUM_THREADS))


def engine_runner(scheduler: str | None, tls: dict | None = None):
    """What simulates the cases: this machine's threads, or the Dask cluster at ``scheduler`` (``tls``: the
    certificates of a ``tls://`` scheduler, :meth:`assess.mechanics.distributed.DaskRunner.connect`)."""
    if scheduler is None:
        return LocalRunner()
    try:  # Dask is the optional extra assess[cluster]: imported only when a cluster is asked for
        import distributed  # noqa: F401
        from assess.mechanics.distributed import DaskRunner
    except ImportError:
        raise InputError([Problem(file="--scheduler", message="running on a Dask cluster needs Dask, which this "
                                  "installation of assess lacks.",
                                  fix='pip install "assess[cluster]" (here and on the workers), or leave out '
                                      "--scheduler to run on this machine's cores.")]) from None
    return DaskRunner.connect(scheduler, **(tls or {}))


@contextlib.contextmanager
def open_runner(scheduler: str | None, say: Say, cache_folder: Path | None = None,
                tls: dict | None = None) -> Iterator:
    """The job's runner (:func:`engine_runner`, behind a cache in ``cache_folder`` if given), closed at
    the end (a cluster's client)."""
    if scheduler is not None:
        say(f"connecting to the Dask scheduler at {scheduler}")
    engine = engine_runner(scheduler, tls)
    warm_up = getattr(engine, "warm_up", None)  # this machine's runner: on a first run after install, the
    if warm_up is not None:                      # general solver compiles on another core meanwhile
        warm_up()
    try:
        yield engine if cache_folder is None else CachingRunner(engine, cache_folder)
    finally:
        close = getattr(engine, "close", None)  # only a cluster's runner holds a client
        if close is not None:
            close()


def parse_levels(text: str) -> list[tuple[str, str]]:
    """``--hazard`` as (folder name, text) per level, in order; a level given twice is refused."""
    levels, seen = [], {}
    for part in [p.strip() for p in str(text).split(",")]:
        try:
            name = parse_level(part).name
        except ValueError as error:
            raise InputError([Problem(file="--hazard", message=str(error))]) from None
        key = name.casefold()  # one folder on a case-insensitive file system (macOS, Windows): DE and de
        if key in seen:
            raise InputError([Problem(file="--hazard", message=f"'{part}' is the level '{seen[key]}' again.",
                                      fix="give each level once.")])
        seen[key] = part
        levels.append((name, part))
    return levels


def level_out_dir(out: Path | None, workbook: Path, level_name: str, several: bool) -> Path:
    """Where a level's files go: ``--out`` (one level), ``--out/<LEVEL>`` (several), else the default."""
    if out is None:
        return Path("reports") / f"{workbook.stem}-{level_name}"
    return out / level_name if several else out


def oq_site(text: str | None):
    """``--oq-site`` as :func:`~assess.hazard.usgs.read_hazard_curve_file` takes it: None, a row
    index, (lon, lat) or an id (an OpenQuake custom_site_id, an nshmp-haz site name), read as the site
    sheet's ``oq_site`` is (:func:`~assess.hazard.openquake.parse_site_choice`); what starts as a number but
    is neither a row nor a pair is refused."""
    site = parse_site_choice(text)
    if isinstance(site, str) and re.match(r"^[-+(\[]?(\d|\.\d)", site) and not re.fullmatch(r"[\w.:-]+", site):
        raise InputError([Problem(file="--oq-site", message=f"'{text}' is neither a row number, nor lon,lat "
                                  "(two numbers in degrees), nor a site id.",
                                  fix=f"give the site as {SITE_FORMS}, e.g. --oq-site -122.5,38.1.")])
    return site


def with_units(inventory, units: str | None):
    """``inventory`` with its settings' ``units`` set to ``units`` (``--units``), if given: the decisions,
    the report and the tables then write lengths and forces in it (:mod:`assess.quantity_text`)."""
    if units is None:
        return inventory
    return replace(inventory, settings=replace(inventory.settings, units=units))


def with_comparison(result: AssessmentResult, explicit: Path | None, in_out_dir: Path, say: Say) -> AssessmentResult:
    """``result`` with its comparison against a previous summary.

    An explicit ``--compare-with`` file must be a summary (else exit 2); the
    summary.csv already in the output folder is used when it is one, and
    skipped with a note when it is not.
    """
    if explicit is not None:
        previous = read_previous_summary(explicit)
    elif in_out_dir.is_file():
        try:
            previous = read_previous_summary(in_out_dir)
        except InputError as error:
            say(f"not comparing with {in_out_dir}: {error.problems[0].message}")
            return result
    else:
        return result
    previous = restore_text(previous)  # the text summary.csv protects from spreadsheet formulas
    say(f"comparing with the previous run {explicit or in_out_dir}")
    return replace(result, comparison=compare_summaries(previous, summary_text(result.summary),
                                                        system_of(result.settings)))


# ---------------------------------------------------------------- assess WORKBOOK --hazard LEVEL[,LEVEL...]

@dataclass
class AssessmentJob:
    """``assess WORKBOOK --hazard LEVEL[,LEVEL...]`` and its options (docs/commands.md)."""

    workbook: Path
    hazard: str
    out: Path | None = None
    formats: tuple[str, ...] = JOB_FORMATS
    units: str | None = None
    jobs: int | None = None
    seed: int = 0
    oq_hazard: Path | None = None
    oq_site: str | None = None
    derive_floors: int | None = None
    calibration: Path | None = None
    compare_with: Path | None = None
    scheduler: str | None = None
    scheduler_tls: dict = field(default_factory=dict)
    allow_records_outside: bool = False
    #: ``--alpha-range``: None (not asked), () (the ends of the building's system's range) or (low, high).
    alpha_range: tuple | None = None


@dataclass
class LevelOutput:
    """One level's result, its output folder and its files (name -> bytes), not yet written."""

    result: AssessmentResult
    out_dir: Path
    files: dict[str, bytes]


def run_job(job: AssessmentJob, say: Say = lambda message: None,
            warn: Say | None = None) -> Iterator[LevelOutput]:
    """Assess every level of ``job``; yields each level's files, rendered once every level is computed.

    Every input is checked before anything runs: the levels, the output folders, the workbook and its
    hazard sheet's rules, the OpenQuake file and the calibration. ``warn`` (``say`` when not given) hears
    the workbook's plausibility warnings (:mod:`assess.inventory.plausibility`); the run goes on.
    """
    levels = parse_levels(job.hazard)
    set_threads(job.jobs)
    out_dirs = [level_out_dir(job.out, job.workbook, name, several=len(levels) > 1) for name, _ in levels]
    for out_dir in out_dirs:
        check_output_folder(out_dir)
    say(f"reading {job.workbook}")
    inventory = with_units(read_workbook(job.workbook), job.units)
    for warning in inventory.warnings:
        (warn or say)(f"warning: {warning}")
    check_inputs(inventory, job.allow_records_outside)
    for _, text in levels:  # a level the workbook has no motions for, refused before any level runs
        check_level(inventory, text)
    oq_hazard = None
    if job.oq_hazard is not None:
        oq_hazard = read_hazard_curve_file(job.oq_hazard, site=oq_site(job.oq_site))
        if oq_hazard.annual_rates is not None:  # not OpenQuake's: say which format was read, and its notes
            say(f"{job.oq_hazard.name}: a {oq_hazard.source} hazard curve of annual rates, site "
                f"{oq_hazard.site.label()}")
            for note in oq_hazard.notes:
                say(f"note: {note}")
        if oq_hazard.kind != "curve":
            say(f"{job.oq_hazard.name} is a hazard map: the motions are scaled to it; annual rates need a "
                "hazard curve")
    alpha_range = None if job.alpha_range is None else alpha_ends_of(inventory, job.alpha_range)
    calibration = read_calibration(job.calibration) if job.calibration is not None else None
    hazard_curve = oq_hazard if oq_hazard is not None and oq_hazard.kind == "curve" else None
    results = []
    with open_runner(job.scheduler, say, tls=job.scheduler_tls) as runner:
        shared_curve = None  # stripes of ground acceleration through the building: one level's serve all
        for (_, text), out_dir in zip(levels, out_dirs):  # every level computed before any is written
            scale_to = oq_hazard
            if hazard_curve is not None and not parse_level(text).has_probability:
                # a label (DE, MCE_R) has no probability to read the curve at: its motions stay the workbook's
                # (or the code spectrum's), and the curve gives the annual rates only, as in assess batch
                scale_to = None
                say(f"level {text} is a label, not a probability: its motions are kept, and the hazard curve "
                    f"{job.oq_hazard.name} gives the annual rates of failure only")
            result = pipeline.run_assessment(inventory, text, seed=job.seed, progress=say, oq_hazard=scale_to,
                                             derive_floors_roof=job.derive_floors, calibration=calibration,
                                             runner=runner, hazard_curve=hazard_curve,
                                             allow_records_outside=job.allow_records_outside,
                                             curve_risk=shared_curve, alpha_range=alpha_range)
            result = advice.with_words(result)  # the advice in words, in the report's units
            if shared_curve is None and result.curve_risk is not None and result.curve_risk.intensity == "PGA":
                shared_curve = result.curve_risk
            results.append(with_comparison(result, job.compare_with, out_dir / "summary.csv", say))
    for result, out_dir in zip(results, out_dirs):
        say(f"rendering {result.level_label}: " + ", ".join(["summary.csv", "motions.csv", "work_orders.csv"] + [
            "summary.xlsx" if f == "xlsx" else f"report.{f}" for f in job.formats]
            + (["fragility/"] if result.curve_risk is not None else [])))
        others = tuple(other for other in results if other is not result)
        files = output.render_outputs(result, job.formats, other_levels=others)
        yield LevelOutput(result, out_dir, files)


def alpha_ends_of(inventory, given: tuple) -> tuple[float, float]:
    """The two α ``--alpha-range`` runs the level again at (:func:`assess.assessment.alpha_range.alpha_ends`);
    an :class:`~assess.errors.InputError` when the workbook has no building sheet to give α to."""
    if inventory.building is None:
        raise InputError([Problem(
            file=inventory.path.name, sheet="building",
            message="--alpha-range moves the building's lateral stiffness ratio α, and this workbook has no "
                    "building sheet: its floors' motions come from the hazard sheet, which α does not change.",
            fix="add a building sheet (docs/workbook.md, sheet building), or run without --alpha-range.")])
    return alpha_ends(inventory.building, given or None)


# ---------------------------------------------------------------- assess calibrate WORKBOOK --measured TESTS

def run_calibrate(workbook: Path, measured_path: Path, out: Path | None, formats: tuple[str, ...],
                  allow_records_outside: bool, say: Say = lambda message: None):
    """Fit the effects the model may lack to the measured tests (:func:`assess.calibration.run_calibration`);
    returns the result, its files (calibration.json, calibration_tests.csv, the report) and their folder."""
    out_dir = out or Path("reports") / f"{workbook.stem}-calibration"
    check_output_folder(out_dir)
    say(f"reading {workbook}")
    inventory = read_workbook(workbook)
    check_inputs(inventory, allow_records_outside)
    measured = read_measured(measured_path, inventory)
    say(f"{len(measured)} measured tests; fitting the effects")
    result = run_calibration(inventory, measured,
                             progress=lambda done, total: say(f"fitted {done} of {total} candidate effects"))
    tests = result.diagnosis.join(result.residuals_before.drop(columns=["specimen", "motion", "direction"])
                                  .add_suffix("_before")).join(
        result.residuals_after.drop(columns=["specimen", "motion", "direction"]).add_suffix("_after"))
    files = {"calibration.json": (json.dumps(result.as_json(), indent=2) + "\n").encode(),
             "calibration_tests.csv": declared_csv_text("calibration_tests.csv", tests).encode()}
    if formats:
        html = render_calibration_html(result, workbook.name, measured_path.name)
        if "html" in formats:
            files["report.html"] = html.encode()
        if "pdf" in formats:
            files["report.pdf"] = report.render_pdf(html)
    return result, files, out_dir
