"""Command line: parses arguments, calls the core, formats what it returns.

Exit codes: 0 done; 2 the input is wrong (every problem listed, no traceback,
nothing written); 1 an internal error; 130 interrupted (Ctrl-C, nothing
written); 141 the reader of the output went away (``assess simulate --json |
head``), as for any command stopped by a closed pipe.
"""
from __future__ import annotations

import argparse
import contextlib
import os
import signal
import sys
import traceback
from pathlib import Path

from assess import __version__
from assess.errors import InputError, Problem, raise_if_any

EXIT_OK, EXIT_INTERNAL, EXIT_INPUT = 0, 1, 2
#: 128 + the signal's number, as a shell reports a command a signal stopped.
EXIT_INTERRUPTED, EXIT_BROKEN_PIPE = 128 + signal.SIGINT, 128 + 13
EPILOG = ("Exit codes: 0 done; 2 the input is wrong (each problem is named); 1 internal error; "
          "130 interrupted (Ctrl-C).")
FORMATS = ("html", "pdf")
#: What the main job writes besides the CSV files: the report and summary.xlsx.
JOB_FORMATS = ("html", "pdf", "xlsx")

DESCRIPTION = """\
Assess the freestanding equipment of a building under a design earthquake:
which items slide, rock or overturn, how far they slide, and the probability
that sliding exceeds the room each item has (Konstantinidis & Makris 2010).

Reads WORKBOOK (sheets equipment, hazard, settings: see README), assesses every
item under the motions of hazard level LEVEL, and writes summary.csv,
motions.csv, report.html and report.pdf into --out.

Other commands:
  assess simulate ...   one item under one record or pulse (assess simulate --help)
  assess calibrate ...  find what the model lacks from measured tests (assess calibrate --help)
  assess batch ...      a portfolio of buildings, re-running only what changed (assess batch --help)"""

CALIBRATE_DESCRIPTION = """\
Simulate every measured test (MEASURED.xlsx, sheet tests: specimen, motion and
any of sliding_cm, theta_max_over_alpha, overturned) with the model WORKBOOK
declares, then with each effect the model may lack (friction_scale,
interface_elasticity, static_friction, velocity_friction, foot_inset,
restitution, input_scale), fitted to the tests; select the effect that
predicts held-out tests best, or none when no effect earns its parameters.
Writes calibration.json, calibration_tests.csv and report.html/.pdf into --out."""

SIMULATE_DESCRIPTION = """\
Simulate one freestanding item, a rigid block, under one floor motion in one
base direction: sliding, rocking, slide-rock and overturning, with Coulomb
friction and Housner impacts. The motion is an acceleration record (CSV with
time_s,accel_g; one column headed accel_g,dt_s=0.01; or PEER .AT2) or a pulse:
  A: a = ap sin(wp t), B: a = ap cos(wp t), C: Makris Type-C1, rect: a = ap,
  for 0 <= t <= Tp (C: its own length), zero after; wp = 2 pi / Tp.
The floor is at rest after the motion and the item is followed --tail-s longer.
For a pulse the regression's median sliding (Konstantinidis & Makris 2010,
eq. 21) is printed beside the simulation."""


def _formats(text: str, allowed: tuple[str, ...] = FORMATS) -> tuple[str, ...]:
    chosen = tuple(part.strip().lower() for part in text.split(",") if part.strip())
    unknown = [part for part in chosen if part not in allowed]
    if unknown or not chosen:
        raise argparse.ArgumentTypeError(
            f"'{text}' is not a list of formats; use {', '.join(allowed)}, comma-separated (e.g. {','.join(allowed)})")
    return chosen


def _job_formats(text: str) -> tuple[str, ...]:
    return _formats(text, JOB_FORMATS)


def _number(accept, requirement: str):
    """An argparse type: a finite number for which ``accept(value)`` holds."""
    def parse(text: str) -> float:
        try:
            value = float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"'{text}' is not a number") from None
        if not (value < float("inf") and accept(value)):
            raise argparse.ArgumentTypeError(f"'{text}' must be {requirement}")
        return value
    return parse


_positive_number = _number(lambda value: value > 0.0, "a positive number")
_coefficient = _number(lambda value: value >= 0.0, "a number of 0 or more")


def _whole_number(minimum: int):
    """An argparse type: a whole number of at least ``minimum``."""
    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"'{text}' is not a whole number") from None
        if value < minimum:
            raise argparse.ArgumentTypeError(f"'{text}' must be {minimum} or more")
        return value
    return parse


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="assess", description=DESCRIPTION, formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog=EPILOG)
    parser.add_argument("workbook", metavar="WORKBOOK", type=Path, help="the inventory workbook (.xlsx)")
    parser.add_argument("--hazard", metavar="LEVEL[,LEVEL...]", required=True,
                        help="hazard level(s) as the workbook names them, comma-separated; 2in50, 2%%/50yr and "
                             "2475yr are the same level")
    parser.add_argument("--out", metavar="DIR", type=Path,
                        help="output folder (default: reports/<workbook stem>-<LEVEL>/); with several levels, "
                             "one folder per level: DIR/<LEVEL>/ (default reports/<workbook stem>-<LEVEL>/)")
    parser.add_argument("--format", metavar="FORMATS", type=_job_formats, default=JOB_FORMATS,
                        help="what to write besides the CSV files, comma-separated: html, pdf (the report), "
                             "xlsx (summary.xlsx, the summary table for a spreadsheet); default: html,pdf,xlsx")
    parser.add_argument("--units", choices=("si", "us"), default="si",
                        help="us: summary.xlsx also gives every length in inches, beside the centimetres "
                             "(default: si)")
    parser.add_argument("--jobs", metavar="N", type=_whole_number(1),
                        help="threads for the time-history simulation (default: all cores); "
                             "the results do not depend on it")
    parser.add_argument("--seed", metavar="N", type=_whole_number(0), default=0,
                        help="seed of every random draw; the same inputs and seed give the same numbers (default 0)")
    parser.add_argument("--oq-hazard", metavar="CSV", type=Path,
                        help="OpenQuake hazard-curve or hazard-map CSV for the site: the level's motions "
                             "are scaled so that their ground motions match its PGA at LEVEL; a curve also "
                             "gives each item's fragilities (fragility/) and annual rates of failure")
    parser.add_argument("--oq-site", metavar="SITE",
                        help="which site of a multi-site OpenQuake file: a row number (0 = first), a "
                             "custom_site_id, or lon,lat (write --oq-site=-122.5,38.1 when lon is negative)")
    parser.add_argument("--derive-floors", metavar="ROOF_FLOOR", type=_whole_number(1),
                        help="floors without a motion take the ground motions amplified by 1 + 2z/h "
                             "(ASCE 7-16 eq. 13.3-1), z/h = floor / ROOF_FLOOR; such items are flagged "
                             "(default: a floor without a motion is an error)")
    parser.add_argument("--calibration", metavar="CALIBRATION_JSON", type=Path,
                        help="the calibration.json of assess calibrate: its selected effect is applied to the "
                             "items it names (applies_to: its specimens, or all) and the report shows each "
                             "one's risk with and without it (the assessment runs twice)")
    parser.add_argument("--compare-with", metavar="SUMMARY_CSV", type=Path,
                        help="a previous run's summary.csv: also write comparison.csv and a report section "
                             "on which items changed risk class and why (default: the summary.csv already "
                             "in --out, if any)")
    parser.add_argument("--scheduler", metavar="ADDRESS",
                        help="run the simulations on the Dask distributed cluster whose scheduler is at ADDRESS "
                             "(e.g. tcp://10.0.0.5:8786, or tls://... with --tls-*); the numbers do not depend on "
                             "where they ran (default: this machine's cores). " + _SCHEDULER_TRUST)
    _add_tls_options(parser)
    _add_allow_records_outside(parser)
    parser.add_argument("--quiet", action="store_true", help="do not print progress")
    parser.add_argument("--version", action="version", version=f"assess {__version__}")
    return parser


_SCHEDULER_TRUST = ("A scheduler and its workers run code for you and send Python objects that assess opens: "
                    "give only a scheduler you run or trust, as for any Dask client")


def _add_tls_options(parser: argparse.ArgumentParser) -> None:
    for option, what in (("--tls-ca-file", "certificate authority that signed the scheduler's certificate"),
                         ("--tls-cert", "this client's certificate"), ("--tls-key", "this client's private key")):
        parser.add_argument(option, metavar="PEM", help=f"for a tls:// --scheduler: the {what} (default: Dask's "
                            "configuration, distributed.comm.tls.*)")


def _add_allow_records_outside(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--allow-records-outside", action="store_true",
                        help="read record files that lie outside the workbook's folder (default: refused, so "
                             "that a workbook from someone else cannot make assess read other files of this "
                             "machine; records belong in the workbook's folder or its subfolders)")


def build_simulate_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="assess simulate", description=SIMULATE_DESCRIPTION,
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog=EPILOG)
    item = parser.add_argument_group("the item (one base direction)")
    item.add_argument("--height-cm", metavar="H", type=_positive_number, required=True,
                      help="overall height [cm]")
    item.add_argument("--width-cm", metavar="W", type=_positive_number, required=True,
                      help="base dimension in the direction of shaking [cm]")
    item.add_argument("--cg-height-cm", metavar="C", type=_positive_number,
                      help="height of the centre of mass [cm] (default H/2, a uniform block)")
    item.add_argument("--mu", metavar="MU", type=_coefficient, required=True,
                      help="kinetic friction coefficient, item on floor")
    item.add_argument("--mu-static", metavar="MUS", type=_coefficient,
                      help="static friction coefficient (default MU)")
    item.add_argument("--restitution", metavar="E", type=_coefficient,
                      help="coefficient of restitution of rocking impacts "
                           "(default Housner's 1 - (2/kappa) sin^2 alpha)")
    motion = parser.add_argument_group("the motion: --record FILE, or --pulse with --ap-g and --tp-s")
    motion.add_argument("--record", metavar="FILE", type=Path, help="floor acceleration record")
    motion.add_argument("--scale", metavar="S", type=_positive_number, default=1.0,
                        help="factor applied to the record (default 1)")
    motion.add_argument("--pulse", choices=("A", "B", "C", "rect"), help="pulse type")
    motion.add_argument("--ap-g", metavar="A", type=_positive_number, help="pulse amplitude [g]")
    motion.add_argument("--tp-s", metavar="T", type=_positive_number, help="pulse period Tp [s]")
    motion.add_argument("--dt-s", metavar="DT", type=_positive_number,
                        help="sampling step of the pulse [s] (default min(Tp/400, 0.005))")
    run = parser.add_argument_group("the run")
    run.add_argument("--tail-s", metavar="S", type=_coefficient, default=10.0,
                     help="seconds followed after the motion, floor at rest (default 10)")
    run.add_argument("--solver", choices=("auto", "general", "event-driven"), default="auto",
                     help="auto: the fastest solver proved right for the item (default); "
                          "general: Moreau-Jean time stepping; event-driven: the reference solver")
    run.add_argument("--history", metavar="CSV", type=Path,
                     help="also write time_s, floor_accel_g, sliding_cm, theta_over_alpha to CSV")
    run.add_argument("--json", action="store_true", help="print one JSON object (SPEC section 4)")
    return parser


def build_calibrate_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="assess calibrate", description=CALIBRATE_DESCRIPTION,
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog=EPILOG)
    parser.add_argument("workbook", metavar="WORKBOOK", type=Path, help="the inventory workbook (.xlsx)")
    parser.add_argument("--measured", metavar="MEASURED.xlsx", type=Path, required=True,
                        help="the measured tests (sheet tests)")
    parser.add_argument("--out", metavar="DIR", type=Path,
                        help="output folder (default: reports/<workbook stem>-calibration/)")
    parser.add_argument("--format", metavar="FORMATS", type=_formats, default=FORMATS,
                        help="report formats, comma-separated: html, pdf (default: html,pdf)")
    _add_allow_records_outside(parser)
    parser.add_argument("--quiet", action="store_true", help="do not print progress")
    return parser


BATCH_DESCRIPTION = """\
Assess a portfolio of buildings, each with its own workbook, and report what
changed since the previous run. PORTFOLIO is a workbook with a sheet
'buildings' (columns building, workbook, and optionally oq_hazard and level;
paths relative to the portfolio) or a folder of workbooks (each one a building
named by its file name). A building's level is its row's level, else --hazard,
else the one level its workbook defines. Writes into --out one folder per
building (what assess WORKBOOK --hazard LEVEL writes), portfolio.csv and
portfolio.html (items by risk and action per building, cases simulated and
reused) and changes.csv (what changed since the previous run in --out).
Simulations already run for the same item, motion and engine are reused
from --out/.cache, so an edited workbook re-simulates only what it changed."""


def build_batch_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="assess batch", description=BATCH_DESCRIPTION, formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog=EPILOG)
    parser.add_argument("portfolio", metavar="PORTFOLIO", type=Path,
                        help="portfolio workbook (.xlsx, sheet buildings) or a folder of workbooks")
    parser.add_argument("--out", metavar="DIR", type=Path,
                        help="output folder (default: reports/<portfolio stem>/)")
    parser.add_argument("--hazard", metavar="LEVEL",
                        help="level of the buildings whose row gives none (default: the one level of each "
                             "workbook); 2in50, 2%%/50yr and 2475yr are the same level")
    parser.add_argument("--oq-hazard", metavar="CSV", type=Path,
                        help="OpenQuake hazard curve for the buildings whose row gives no oq_hazard: the "
                             "items' fragilities are integrated over it into annual rates (unlike the main "
                             "command's --oq-hazard, it does not rescale the level's motions)")
    parser.add_argument("--scheduler", metavar="ADDRESS",
                        help="run the simulations on the Dask distributed cluster at ADDRESS "
                             "(default: this machine's cores); the numbers do not depend on it. " + _SCHEDULER_TRUST)
    _add_tls_options(parser)
    parser.add_argument("--format", metavar="FORMATS", type=_job_formats, default=JOB_FORMATS,
                        help="what to write into each building's folder besides the CSV files: html, pdf, "
                             "xlsx (default: html,pdf,xlsx)")
    parser.add_argument("--seed", metavar="N", type=_whole_number(0), default=0,
                        help="seed of every random draw (default 0)")
    parser.add_argument("--jobs", metavar="N", type=_whole_number(1),
                        help="threads for the time-history simulation (default: all cores)")
    parser.add_argument("--allow-files-outside", action="store_true",
                        help="read workbooks and hazard curves outside the portfolio's folder, and records "
                             "outside their workbook's folder (default: refused)")
    parser.add_argument("--quiet", action="store_true", help="do not print progress")
    return parser


class _Interrupt:
    """Ctrl-C as the run sees it: whether it came, and whether it may stop the run now.

    The SIGINT handler records the interrupt before raising KeyboardInterrupt,
    so that an interrupt that a library swallows (an exception raised in a
    cffi callback while WeasyPrint draws the PDF is printed and dropped) or
    wraps (numba's threads turn it into a SystemError) is still seen. While
    the output folder is swapped in, it is only recorded, and acted on after.
    """

    received = False
    deferred = False
    written_to: Path | None = None
    unraisable_before = staticmethod(sys.__unraisablehook__)

    @classmethod
    def handler(cls, signum, frame):
        cls.received = True
        if not cls.deferred:
            raise KeyboardInterrupt

    @staticmethod
    def unraisable(unraisable):
        """An interrupt raised where Python can only print it (a weakref callback, a ``__del__``): recorded
        already, so said once by the run's exit (130), not as "Exception ignored in ..."."""
        if not (isinstance(unraisable.exc_value, KeyboardInterrupt) and _Interrupt.received):
            _Interrupt.unraisable_before(unraisable)

    @classmethod
    def stop_if_received(cls):
        if cls.received:
            raise KeyboardInterrupt


@contextlib.contextmanager
def _sigint_recorded():
    """Install :meth:`_Interrupt.handler` for the run (only the main thread may), then restore."""
    _Interrupt.received, _Interrupt.deferred, _Interrupt.written_to = False, False, None
    try:
        previous = signal.signal(signal.SIGINT, _Interrupt.handler)
    except ValueError:  # not the main thread: leave signals alone
        previous = None
    _Interrupt.unraisable_before, sys.unraisablehook = sys.unraisablehook, _Interrupt.unraisable
    try:
        yield
    finally:
        sys.unraisablehook = _Interrupt.unraisable_before
        if previous is not None:
            signal.signal(signal.SIGINT, previous)


def _write_uninterrupted(files: dict[str, bytes], out_dir: Path) -> list[Path]:
    """:func:`assess.output.write_atomically`, Ctrl-C held back until the folder is swapped in."""
    from assess.output import write_atomically
    _Interrupt.stop_if_received()  # an interrupt swallowed while rendering stops the run here
    _Interrupt.deferred = True
    try:
        written = write_atomically(files, out_dir)
        _Interrupt.written_to = Path(out_dir)
    finally:
        _Interrupt.deferred = False
    _Interrupt.stop_if_received()
    return written


def _caused_by(error: BaseException, kind: type) -> bool:
    """Whether ``error`` is ``kind`` or was raised while handling one (``__cause__``/``__context__``)."""
    seen = set()
    while error is not None and id(error) not in seen:
        if isinstance(error, kind):
            return True
        seen.add(id(error))
        error = error.__cause__ or error.__context__
    return False


def _interrupted() -> int:
    if _Interrupt.written_to is not None:
        print(f"assess: interrupted after the outputs were written to {_Interrupt.written_to}.", file=sys.stderr)
    else:
        print("assess: interrupted; nothing was written.", file=sys.stderr)
    return EXIT_INTERRUPTED


def _reader_gone() -> int:
    """stdout's reader closed the pipe: send what is left to /dev/null (Python docs, 'Note on SIGPIPE')."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):
        pass
    return EXIT_BROKEN_PIPE


def main(argv: list[str] | None = None) -> int:
    """Run one command; returns its exit code (module docstring). Ctrl-C anywhere exits 130, in one line."""
    with _sigint_recorded():
        try:
            code = _main(argv)
            sys.stdout.flush()
            return code
        except KeyboardInterrupt:
            return _interrupted()
        except BrokenPipeError:
            return _reader_gone()


def _main(argv: list[str] | None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    if argv and argv[0] == "simulate":
        args, command = build_simulate_parser().parse_args(argv[1:]), _simulate
    elif argv and argv[0] == "calibrate":
        args, command = build_calibrate_parser().parse_args(argv[1:]), _calibrate
    elif argv and argv[0] == "batch":
        args, command = build_batch_parser().parse_args(argv[1:]), _batch
    else:
        args = build_parser().parse_args(argv)  # argparse exits with 2 on a wrong option
        command = _assess
    quiet = command is _simulate or args.quiet

    def say(message: str) -> None:
        """Progress, to stderr; also where an interrupt a library swallowed stops the run."""
        _Interrupt.stop_if_received()
        if not quiet:
            print(f"assess: {message}", file=sys.stderr)

    try:
        return command(args, say)
    except InputError as error:
        print(str(error), file=sys.stderr)
        print("Nothing was written.", file=sys.stderr)
        return EXIT_INPUT
    except Exception as error:  # noqa: BLE001 - the one place that turns a bug into exit code 1
        if _Interrupt.received or _caused_by(error, KeyboardInterrupt):  # e.g. SystemError from numba
            return _interrupted()
        if _caused_by(error, BrokenPipeError):
            return _reader_gone()
        traceback.print_exc()
        print("assess: internal error (a bug, not your input): please report it with the "
              "traceback above. Nothing was written.", file=sys.stderr)
        return EXIT_INTERNAL


def _assess(args: argparse.Namespace, say) -> int:
    from assess.inventory import read_workbook
    from assess.output import check_output_folder, render_outputs
    from assess.pipeline import run_assessment

    levels = _levels(args.hazard)
    if args.jobs is not None:
        import numba
        numba.set_num_threads(min(args.jobs, numba.config.NUMBA_NUM_THREADS))
    out_dirs = [_level_out_dir(args.out, args.workbook, name, several=len(levels) > 1) for name, _ in levels]
    for out_dir in out_dirs:
        check_output_folder(out_dir)
    say(f"reading {args.workbook}")
    inventory = read_workbook(args.workbook)
    raise_if_any(_hazard_problems(inventory, args.allow_records_outside))
    oq_hazard = None
    if args.oq_hazard is not None:
        from assess.hazard.openquake import read_openquake_hazard
        oq_hazard = read_openquake_hazard(args.oq_hazard, site=_oq_site(args.oq_site))
        if oq_hazard.kind != "curve":
            say(f"{args.oq_hazard.name} is a hazard map: the motions are scaled to it; annual rates need a "
                "hazard curve")
    calibration = None
    if args.calibration is not None:
        from assess.calibration.apply import read_calibration
        calibration = read_calibration(args.calibration)
    if args.scheduler is not None:
        say(f"connecting to the Dask scheduler at {args.scheduler}")
    runner = _engine_runner(args.scheduler, args)  # this machine's threads, or a Dask cluster
    results = []
    try:
        for (_, text), out_dir in zip(levels, out_dirs):  # every level computed before any is written
            result = run_assessment(inventory, text, seed=args.seed, progress=say, oq_hazard=oq_hazard,
                                    derive_floors_roof=args.derive_floors, calibration=calibration, runner=runner,
                                    hazard_curve=oq_hazard if oq_hazard is not None and oq_hazard.kind == "curve"
                                    else None)
            results.append(_with_comparison(result, args.compare_with, out_dir / "summary.csv", say))
    finally:
        close = getattr(runner, "close", None)  # a cluster's client
        if close is not None:
            close()
    for result, out_dir in zip(results, out_dirs):
        say(f"rendering {result.level_label}: " + ", ".join(["summary.csv", "motions.csv"] + [
            "summary.xlsx" if f == "xlsx" else f"report.{f}" for f in args.format]
            + (["fragility/"] if result.curve_risk is not None else [])))
        others = tuple(other for other in results if other is not result)
        files = render_outputs(result, args.format, units=args.units, other_levels=others)
        written = _write_uninterrupted(files, out_dir)
        counts = result.risk_counts()
        say(f"{result.level_label}: {counts['high']} high, {counts['moderate']} moderate, {counts['low']} low risk, "
            f"{counts['anchored']} anchored")
        for path in written:
            print(path)
    return EXIT_OK


def _levels(text: str) -> list[tuple[str, str]]:
    """``--hazard`` as (folder name, text) per level, in order; a level given twice is refused."""
    from assess.hazard.levels import parse_level

    levels, seen = [], {}
    for part in [p.strip() for p in str(text).split(",")]:
        try:
            name = parse_level(part).name
        except ValueError as error:
            raise InputError([Problem(file="--hazard", message=str(error))]) from None
        if name in seen:
            raise InputError([Problem(file="--hazard", message=f"'{part}' is the level '{seen[name]}' again.",
                                      fix="give each level once.")])
        seen[name] = part
        levels.append((name, part))
    return levels


def _level_out_dir(out: Path | None, workbook: Path, level_name: str, several: bool) -> Path:
    """Where a level's files go: ``--out`` (one level), ``--out/<LEVEL>`` (several), else the default."""
    if out is None:
        return Path("reports") / f"{workbook.stem}-{level_name}"
    return out / level_name if several else out


def _calibrate(args: argparse.Namespace, say) -> int:
    import json

    from assess.calibration import read_measured, run_calibration
    from assess.inventory import read_workbook
    from assess.output import check_output_folder, csv_text

    out_dir = args.out or Path("reports") / f"{args.workbook.stem}-calibration"
    check_output_folder(out_dir)
    say(f"reading {args.workbook}")
    inventory = read_workbook(args.workbook)
    raise_if_any(_hazard_problems(inventory, args.allow_records_outside))
    measured = read_measured(args.measured, inventory)
    say(f"{len(measured)} measured tests; fitting the effects")
    result = run_calibration(inventory, measured,
                             progress=lambda done, total: say(f"fitted {done} of {total} candidate effects"))
    tests = result.diagnosis.join(result.residuals_before.drop(columns=["specimen", "motion", "direction"])
                                  .add_suffix("_before")).join(
        result.residuals_after.drop(columns=["specimen", "motion", "direction"]).add_suffix("_after"))
    files = {"calibration.json": (json.dumps(result.as_json(), indent=2) + "\n").encode(),
             "calibration_tests.csv": csv_text(tests).encode()}
    if args.format:
        from assess.report import render_pdf
        from assess.report.calibration import render_calibration_html
        html = render_calibration_html(result, args.workbook.name, args.measured.name)
        if "html" in args.format:
            files["report.html"] = html.encode()
        if "pdf" in args.format:
            files["report.pdf"] = render_pdf(html)
    written = _write_uninterrupted(files, out_dir)
    similar = f"; indistinguishable from {', '.join(result.indistinguishable_from)}" \
        if result.indistinguishable_from else ""
    say(f"selected: {result.selected} {result.parameters or ''}{similar}")
    for path in written:
        print(path)
    return EXIT_OK


def _batch(args: argparse.Namespace, say) -> int:
    from assess import batch
    from assess.cache import CachingRunner
    from assess.hazard.levels import parse_level

    if args.hazard is not None:
        try:
            parse_level(args.hazard)
        except ValueError as error:
            raise InputError([Problem(file="--hazard", message=str(error))]) from None
    if args.jobs is not None:
        import numba
        numba.set_num_threads(min(args.jobs, numba.config.NUMBA_NUM_THREADS))
    out_dir = args.out or batch.default_out_dir(args.portfolio)
    batch.check_portfolio_folder(out_dir)
    say(f"reading {args.portfolio}")
    buildings = batch.read_portfolio(args.portfolio, allow_outside=args.allow_files_outside)
    prepared = batch.prepare_buildings(
        buildings, level=args.hazard, oq_hazard=args.oq_hazard,
        hazard_problems=lambda inventory: _hazard_problems(inventory, args.allow_files_outside), say=say)
    runner = CachingRunner(_engine_runner(args.scheduler, args), Path(out_dir) / batch.CACHE_FOLDER)
    say(f"{len(prepared)} buildings; results are reused from {Path(out_dir) / batch.CACHE_FOLDER}")
    try:
        staged = batch.run_portfolio(prepared, out_dir, runner=runner, seed=args.seed, formats=args.format,
                                     say=say)
    finally:
        close = getattr(runner.inner, "close", None)  # a cluster's client
        if close is not None:
            close()
    try:
        _Interrupt.stop_if_received()
        _Interrupt.deferred = True
        try:
            staged.commit()
            _Interrupt.written_to = Path(out_dir)
        finally:
            _Interrupt.deferred = False
    finally:
        staged.discard()
    _Interrupt.stop_if_received()
    for message in runner.write_errors[:3]:
        say(f"could not store results in the cache ({message}); they will be simulated again next time")
    changed = staged.changes["change"].value_counts()
    say(f"{staged.cases_simulated} cases simulated, {staged.cases_reused} reused; changes since the previous "
        f"run: " + (", ".join(f"{n} {kind}" for kind, n in changed.items()) or "none"))
    for name in staged.files:
        print(Path(out_dir) / name)
    return EXIT_OK


def _engine_runner(scheduler, args=None):
    """What simulates the cases the cache does not hold: this machine's threads, or a Dask cluster."""
    from assess.mechanics.runner import LocalRunner
    if scheduler is None:
        return LocalRunner()
    try:
        from assess.mechanics.distributed import DaskRunner
    except ImportError:
        raise InputError([Problem(file="--scheduler", message="this installation of assess cannot run on a Dask "
                                  "cluster.", fix="leave out --scheduler to run on this machine.")]) from None
    return DaskRunner.connect(scheduler, tls_ca_file=getattr(args, "tls_ca_file", None),
                              tls_cert=getattr(args, "tls_cert", None), tls_key=getattr(args, "tls_key", None))


def _with_comparison(result, explicit: Path | None, in_out_dir: Path, say):
    """``result`` with its comparison against a previous summary.

    An explicit ``--compare-with`` file must be a summary (else exit 2); the
    summary.csv already in the output folder is used when it is one, and
    skipped with a note when it is not.
    """
    from dataclasses import replace

    from assess.comparison import compare_summaries, read_previous_summary
    from assess.output import restore_text
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
    return replace(result, comparison=compare_summaries(previous, result.summary))


def _hazard_problems(inventory, allow_records_outside: bool) -> list[Problem]:
    """What in the hazard sheet the run must refuse before reading any record or simulating.

    * a record outside the workbook's folder (:func:`assess.hazard.records.check_record_location`),
      unless ``--allow-records-outside``;
    * ``vp`` = 0: a velocity pulse has a non-zero amplitude (a pulse of
      acceleration ap and period Tp reaches vp = ap Tp / 2 pi for Type B), so a
      0 is a placeholder, not a measurement. Read as "no vp" it would silently
      change how the motion is simulated (its pulse instead of synthetic
      near-fault histories), so it is refused and the user says which is meant.
    """
    import math

    from assess.hazard.records import check_record_location
    workbook = Path(inventory.path)
    problems = []
    for row in inventory.hazard.itertuples(index=False):
        for column in ("record", "record_2"):
            record_path = str(getattr(row, f"{column}_path", "") or "")
            why = check_record_location(record_path, workbook.parent) if record_path else None
            if why and not allow_records_outside:
                problems.append(Problem(file=workbook.name, sheet="hazard", row=int(row.row), column=column,
                                        message=f"motion '{row.motion}': {why}",
                                        fix="copy the record into the workbook's folder (or a subfolder) and "
                                            "give its path relative to the workbook, or run with "
                                            "--allow-records-outside if you trust this workbook."))
        vp = float(row.vp_m_s)
        if not math.isnan(vp) and vp == 0.0:
            problems.append(Problem(file=workbook.name, sheet="hazard", row=int(row.row), column="vp_cm_s",
                                    message=f"motion '{row.motion}': the pulse velocity vp is 0; a velocity "
                                            "pulse has a non-zero amplitude.",
                                    fix="give the pulse's peak velocity (e.g. -75 cm/s for Los Gatos), or "
                                        "leave the cell empty to simulate the motion's pulse from PTA and Tp."))
    return problems


def _oq_site(text):
    """--oq-site as read_openquake_hazard takes it: None, a row index, (lon, lat) or an id."""
    if text is None:
        return None
    if text.strip().isdigit():
        return int(text)
    parts = text.split(",")
    if len(parts) == 2:
        try:
            return (float(parts[0]), float(parts[1]))
        except ValueError:
            pass
    return text


def _simulate(args: argparse.Namespace, say) -> int:
    import json

    from assess.hazard.records import MIN_DURATION_S, pulse_record, read_record
    from assess.mechanics.block import Block
    from assess.simulation import simulate_item

    problems = []
    if (args.record is None) == (args.pulse is None):
        problems.append(Problem(file="command line", message="give the motion either as --record FILE "
                                "or as --pulse with --ap-g and --tp-s (exactly one of them).",
                                fix="e.g. --pulse B --ap-g 0.54 --tp-s 2.1"))
    elif args.pulse is not None and (args.ap_g is None or args.tp_s is None):
        problems.append(Problem(file="command line", message=f"--pulse {args.pulse} needs --ap-g and --tp-s.",
                                fix="add --ap-g (amplitude in g) and --tp-s (period in s)."))
    cg_cm = args.height_cm / 2.0 if args.cg_height_cm is None else args.cg_height_cm
    if cg_cm > args.height_cm:
        problems.append(Problem(file="command line", message=f"--cg-height-cm {cg_cm:g} is above the top "
                                f"of the item (--height-cm {args.height_cm:g}).",
                                fix="give the height of the centre of mass above the floor."))
    mu_static = args.mu if args.mu_static is None else args.mu_static
    if mu_static < args.mu:
        problems.append(Problem(file="command line", message=f"--mu-static {mu_static:g} is below --mu "
                                f"{args.mu:g}; static friction is never below kinetic friction.",
                                fix="give --mu-static of at least --mu, or leave it out."))
    if args.restitution is not None and args.restitution > 1.0:
        problems.append(Problem(file="command line", message=f"--restitution {args.restitution:g} is above 1.",
                                fix="give a coefficient between 0 and 1, or leave it out for Housner's."))
    if args.history is not None and args.history.is_dir():
        problems.append(Problem(file=str(args.history), message="--history names a folder; it takes a file.",
                                fix="give a file name, e.g. --history history.csv."))
    if problems:
        raise InputError(problems)
    block = Block(half_width_m=args.width_cm / 200.0, cg_height_m=cg_cm / 100.0,
                  height_m=args.height_cm / 100.0, mu=args.mu, mu_static=mu_static,
                  restitution=args.restitution)
    if args.record is not None:
        motion, period = read_record(args.record, min_duration_s=MIN_DURATION_S, scale=args.scale), None
    else:
        motion, period = pulse_record(args.pulse, args.ap_g, args.tp_s, args.dt_s), args.tp_s
    run = simulate_item(block, motion, pulse_period_s=period, tail_s=args.tail_s, solver=args.solver,
                        return_history=args.history is not None)
    if args.history is not None:
        from assess.output import write_file_atomically
        _Interrupt.stop_if_received()
        write_file_atomically(args.history, _history_csv(run))
    result = run.as_dict()
    if args.json:
        print(json.dumps(result, indent=2))
    else:
        print(_simulation_text(result))
    return EXIT_OK


def _history_csv(run) -> bytes:
    import io

    import numpy as np
    r = run.response
    floor = np.zeros(r.time_s.size)
    floor[:min(run.motion.accel_g.size, floor.size)] = run.motion.accel_g[:floor.size]
    table = np.column_stack([r.time_s, floor, r.sliding_m * 100.0, r.theta_rad / run.block.alpha_rad])
    buffer = io.StringIO()
    np.savetxt(buffer, table, delimiter=",", fmt="%.9g",
               header="time_s,floor_accel_g,sliding_cm,theta_over_alpha", comments="")
    return buffer.getvalue().encode()


def _simulation_text(result: dict) -> str:
    lines = [
        f"item: alpha {result['alpha_rad']:.4f} rad, p {result['p_rad_s']:.3f} rad/s, b/h "
        f"{result['b_over_h']:.3f}, mu {result['mu']:g} (static {result['mu_static']:g}), "
        f"restitution {result['restitution']:.4f}",
        f"motion: {result['motion']['name']}, PTA {result['motion']['pta_g']:.3f} g, "
        f"{result['motion']['duration_s']:.2f} s at dt {result['motion']['dt_s']:g} s",
        f"mode: {result['mode']} ({' -> '.join(m for _, m in result['mode_sequence'])}; "
        f"solved by the {result['solver']})",
        f"sliding: peak {result['sliding_max_cm']:.2f} cm, residual {result['sliding_residual_cm']:.2f} cm",
        f"rocking: theta_max/alpha {result['theta_max_over_alpha']:.3f}, uplift "
        f"{'yes' if result['uplift'] else 'no'}, overturned {'yes' if result['overturned'] else 'no'}"
        + (f" at {result['overturn_time_s']:.2f} s" if result["overturned"] else ""),
    ]
    if "regression" in result:
        reg = result["regression"]
        lines.append(f"regression (eq. 21): IM {reg['im']:.3f}, median sliding "
                     f"{reg['sliding_median_cm']:.2f} cm")
    return "\n".join(lines)


if __name__ == "__main__":
    sys.exit(main())
