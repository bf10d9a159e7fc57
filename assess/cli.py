"""Command line: parses arguments, calls the core, formats what it returns.

Exit codes: 0 done; 2 the input is wrong (every problem listed, no traceback,
nothing written); 1 an internal error; 130 interrupted (Ctrl-C, nothing
written); 141 the reader of the output went away (``assess simulate --json |
head``), as for any command stopped by a closed pipe.
"""
from __future__ import annotations

import argparse
import json
import sys
import traceback
from pathlib import Path

from assess import __version__, startup
from assess.command.folders import write_file_atomically
from assess.command.interrupts import (Interrupt, caused_by, held_back, interrupted, reader_gone, sigint_recorded,
                                       write_uninterrupted)
from assess.command.option_values import (FORMATS, JOB_FORMATS, alpha_range_value, coefficient, formats,
                                          job_formats, positive_number, whole_number)
from assess.command.site_option import joined_oq_site
from assess.errors import InputError, Problem, printable

EXIT_OK, EXIT_INTERNAL, EXIT_INPUT = 0, 1, 2
EPILOG = ("Exit codes: 0 done; 2 the input is wrong (each problem is named); 1 internal error; "
          "130 interrupted (Ctrl-C).")

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
    parser.add_argument("--format", metavar="FORMATS", type=job_formats, default=JOB_FORMATS,
                        help="what to write besides the CSV files, comma-separated: html, pdf (the report), "
                             "xlsx (summary.xlsx, the summary table for a spreadsheet); default: html,pdf,xlsx")
    parser.add_argument("--units", choices=("si", "us"),
                        help="the units of the report, its advice and summary.xlsx: si (cm, kN, kg; A4) or us "
                             "(in, lb, kip; letter paper; summary.csv adds _in and _kip columns beside its SI "
                             "ones); default: the settings' units, else us when the workbook's lengths are in "
                             "inches or feet, else si")
    parser.add_argument("--jobs", metavar="N", type=whole_number(1),
                        help="threads for the time-history simulation (default: all cores); "
                             "the results do not depend on it")
    parser.add_argument("--seed", metavar="N", type=whole_number(0), default=0,
                        help="seed of every random draw; the same inputs and seed give the same numbers (default 0)")
    parser.add_argument("--oq-hazard", metavar="CSV", type=Path,
                        help="the site's PGA hazard: an OpenQuake hazard-curve or hazard-map CSV, or a USGS "
                             "nshmp-haz curve (hazout/PGA/curves.csv, annual rates), told apart by the header: the "
                             "level's motions are scaled so that their ground motions match its PGA at LEVEL; a "
                             "curve also gives each item's fragilities (fragility/) and annual rates of failure")
    parser.add_argument("--oq-site", metavar="SITE",
                        help="which site of a multi-site hazard file: a row number (0 = first), an OpenQuake "
                             "custom_site_id or nshmp-haz site name, or lon,lat in degrees (e.g. --oq-site "
                             "-122.5,38.1)")
    parser.add_argument("--derive-floors", metavar="ROOF_FLOOR", type=whole_number(1),
                        help="floors without a motion take the ground motions amplified by 1 + 2z/h "
                             "(ASCE 7-16 eq. 13.3-1), z/h = floor / ROOF_FLOOR; such items are flagged "
                             "(default: a floor without a motion is an error)")
    parser.add_argument("--calibration", metavar="CALIBRATION_JSON", type=Path,
                        help="the calibration.json of assess calibrate: its selected effect is applied to the "
                             "items it names (applies_to: its specimens, or all) and the report shows each "
                             "one's risk with and without it (the assessment runs twice)")
    parser.add_argument("--alpha-range", metavar="LOW,HIGH", nargs="?", const=(), type=alpha_range_value,
                        help="with a building sheet: run the level again with the building's lateral stiffness "
                             "ratio alpha at both ends of its range (its system's: 5,20 for moment frames, 1.5,6 "
                             "for braced frames, 0.1,2 for shear walls; for a frame whose alpha comes from "
                             "pushover_slope_ratio alone, the alpha it gives at 2 and 5 %% storey hardening; or "
                             "LOW,HIGH), for the items on the floors "
                             "the building's motions reach, and show each one's risk class at both ends beside "
                             "the level's (up to three times the run's time)")
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


def _tls(args: argparse.Namespace) -> dict:
    """The --tls-* files given, as :meth:`assess.mechanics.distributed.DaskRunner.connect` takes them."""
    return {name: value for name, value in (("tls_ca_file", args.tls_ca_file), ("tls_cert", args.tls_cert),
                                            ("tls_key", args.tls_key)) if value is not None}


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
    item.add_argument("--height-cm", metavar="H", type=positive_number, required=True,
                      help="overall height [cm]")
    item.add_argument("--width-cm", metavar="W", type=positive_number, required=True,
                      help="base dimension in the direction of shaking [cm]")
    item.add_argument("--cg-height-cm", metavar="C", type=positive_number,
                      help="height of the centre of mass [cm] (default H/2, a uniform block)")
    item.add_argument("--mu", metavar="MU", type=coefficient, required=True,
                      help="kinetic friction coefficient, item on floor")
    item.add_argument("--mu-static", metavar="MUS", type=coefficient,
                      help="static friction coefficient (default MU)")
    item.add_argument("--restitution", metavar="E", type=coefficient,
                      help="coefficient of restitution of rocking impacts "
                           "(default Housner's 1 - (2/kappa) sin^2 alpha)")
    motion = parser.add_argument_group("the motion: --record FILE, or --pulse with --ap-g and --tp-s")
    motion.add_argument("--record", metavar="FILE", type=Path, help="floor acceleration record")
    motion.add_argument("--scale", metavar="S", type=positive_number, default=1.0,
                        help="factor applied to the record (default 1)")
    motion.add_argument("--pulse", choices=("A", "B", "C", "rect"), help="pulse type")
    motion.add_argument("--ap-g", metavar="A", type=positive_number, help="pulse amplitude [g]")
    motion.add_argument("--tp-s", metavar="T", type=positive_number, help="pulse period Tp [s]")
    motion.add_argument("--dt-s", metavar="DT", type=positive_number,
                        help="sampling step of the pulse [s] (default min(Tp/400, 0.005))")
    run = parser.add_argument_group("the run")
    run.add_argument("--tail-s", metavar="S", type=coefficient, default=10.0,
                     help="seconds followed after the motion, floor at rest (default 10)")
    run.add_argument("--solver", choices=("auto", "general", "event-driven"), default="auto",
                     help="auto: the fastest solver proved right for the item (default); "
                          "general: Moreau-Jean time stepping; event-driven: the reference solver")
    run.add_argument("--history", metavar="CSV", type=Path,
                     help="also write time_s, floor_accel_g, sliding_cm, theta_over_alpha to CSV")
    run.add_argument("--json", action="store_true", help="print one JSON object (docs/commands.md)")
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
    parser.add_argument("--format", metavar="FORMATS", type=formats, default=FORMATS,
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
                        help="hazard curve (OpenQuake, or USGS nshmp-haz's PGA/curves.csv) for the buildings "
                             "whose row gives no oq_hazard: the "
                             "items' fragilities are integrated over it into annual rates (unlike the main "
                             "command's --oq-hazard, it does not rescale the level's motions)")
    parser.add_argument("--scheduler", metavar="ADDRESS",
                        help="run the simulations on the Dask distributed cluster at ADDRESS "
                             "(default: this machine's cores); the numbers do not depend on it. " + _SCHEDULER_TRUST)
    _add_tls_options(parser)
    parser.add_argument("--format", metavar="FORMATS", type=job_formats, default=JOB_FORMATS,
                        help="what to write into each building's folder besides the CSV files: html, pdf, "
                             "xlsx (default: html,pdf,xlsx)")
    parser.add_argument("--seed", metavar="N", type=whole_number(0), default=0,
                        help="seed of every random draw (default 0)")
    parser.add_argument("--jobs", metavar="N", type=whole_number(1),
                        help="threads for the time-history simulation (default: all cores)")
    parser.add_argument("--allow-files-outside", action="store_true",
                        help="read workbooks and hazard curves outside the portfolio's folder, and records "
                             "outside their workbook's folder (default: refused)")
    parser.add_argument("--quiet", action="store_true", help="do not print progress")
    return parser


def main(argv: list[str] | None = None) -> int:
    """Run one command; returns its exit code (module docstring). Ctrl-C anywhere exits 130, in one line."""
    with sigint_recorded():
        try:
            code = _main(argv)
            sys.stdout.flush()
            return code
        except KeyboardInterrupt:
            return interrupted()
        except BrokenPipeError:
            return reader_gone()


def _main(argv: list[str] | None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    if argv and argv[0] == "simulate":
        args, command = build_simulate_parser().parse_args(argv[1:]), _simulate
    elif argv and argv[0] == "calibrate":
        args, command = build_calibrate_parser().parse_args(argv[1:]), _calibrate
    elif argv and argv[0] == "batch":
        args, command = build_batch_parser().parse_args(argv[1:]), _batch
    else:
        args = build_parser().parse_args(joined_oq_site(argv))  # argparse exits with 2 on a wrong option
        command = _assess
    quiet = command is _simulate or args.quiet

    def say(message: str) -> None:
        """Progress, to stderr; also where an interrupt a library swallowed stops the run."""
        Interrupt.stop_if_received()
        if not quiet:
            print(f"assess: {message}", file=sys.stderr)

    try:
        return command(args, say)
    except InputError as error:
        print(str(error), file=sys.stderr)
        print("Nothing was written.", file=sys.stderr)
        return EXIT_INPUT
    except Exception as error:  # noqa: BLE001 - the one place that turns a bug into exit code 1
        if Interrupt.received or caused_by(error, KeyboardInterrupt):  # e.g. SystemError from numba
            return interrupted()
        if caused_by(error, BrokenPipeError):
            return reader_gone()
        traceback.print_exc()
        print("assess: internal error (a bug, not your input): please report it with the "
              "traceback above. Nothing was written.", file=sys.stderr)
        return EXIT_INTERNAL


def _warn(message: str) -> None:
    """A warning, to stderr, even with --quiet (it is not progress: the input may be wrong)."""
    print(f"assess: {printable(message)}", file=sys.stderr)


def _assess(args: argparse.Namespace, say) -> int:
    startup.warm_up(args.scheduler, args.jobs)
    from assess.command import job  # the core: seconds to import, not needed for --help or a wrong option

    levels = job.run_job(job.AssessmentJob(
        args.workbook, args.hazard, out=args.out, formats=args.format, units=args.units, jobs=args.jobs,
        seed=args.seed, oq_hazard=args.oq_hazard, oq_site=args.oq_site, derive_floors=args.derive_floors,
        calibration=args.calibration, compare_with=args.compare_with, scheduler=args.scheduler,
        scheduler_tls=_tls(args), allow_records_outside=args.allow_records_outside, alpha_range=args.alpha_range),
        say, warn=_warn)
    for level in levels:
        written = write_uninterrupted(level.files, level.out_dir)
        counts = level.result.risk_counts()
        say(f"{level.result.level_label}: {counts['high']} high, {counts['moderate']} moderate, "
            f"{counts['low']} low risk, {counts['anchored']} anchored")
        for path in written:
            print(path)
    return EXIT_OK


def _calibrate(args: argparse.Namespace, say) -> int:
    from assess.command import job  # the core: seconds to import, not needed for --help or a wrong option

    result, files, out_dir = job.run_calibrate(args.workbook, args.measured, args.out, args.format,
                                               args.allow_records_outside, say)
    written = write_uninterrupted(files, out_dir)
    similar = f"; indistinguishable from {', '.join(result.indistinguishable_from)}" \
        if result.indistinguishable_from else ""
    say(f"selected: {result.selected} {result.parameters or ''}{similar}")
    for path in written:
        print(path)
    return EXIT_OK


def _batch(args: argparse.Namespace, say) -> int:
    startup.warm_up(args.scheduler, args.jobs)
    from assess.portfolio import batch  # the core: seconds to import, not needed for --help or a wrong option

    staged, runner, out_dir = batch.run_batch(batch.BatchJob(
        args.portfolio, out=args.out, hazard=args.hazard, oq_hazard=args.oq_hazard, scheduler=args.scheduler,
        scheduler_tls=_tls(args), formats=args.format, seed=args.seed, jobs=args.jobs,
        allow_files_outside=args.allow_files_outside), say)
    try:
        with held_back(out_dir):
            staged.commit()
    finally:
        staged.discard()
    for message in runner.write_errors[:3]:
        say(f"could not store results in the cache ({message}); they will be simulated again next time")
    changed = staged.changes["change"].value_counts()
    say(f"{staged.cases_simulated} cases simulated, {staged.cases_reused} reused; changes since the previous "
        f"run: " + (", ".join(f"{n} {kind}" for kind, n in changed.items()) or "none"))
    for name in staged.files:
        print(out_dir / name)
    return EXIT_OK


def _simulate(args: argparse.Namespace, say) -> int:
    from assess.assessment import simulation  # the engine: seconds to import, not needed for --help or a wrong option

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
    block = simulation.Block(half_width_m=args.width_cm / 200.0, cg_height_m=cg_cm / 100.0,
                             height_m=args.height_cm / 100.0, mu=args.mu, mu_static=mu_static,
                             restitution=args.restitution)
    motion, period = simulation.item_motion(args.record, args.scale, args.pulse, args.ap_g, args.tp_s, args.dt_s)
    run = simulation.simulate_item(block, motion, pulse_period_s=period, tail_s=args.tail_s, solver=args.solver,
                                   return_history=args.history is not None)
    if args.history is not None:
        Interrupt.stop_if_received()
        write_file_atomically(args.history, run.history_csv())
    print(json.dumps(run.as_dict(), indent=2) if args.json else run.as_text())
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
