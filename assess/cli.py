"""Command line: parses arguments, calls the core, formats what it returns.

Exit codes: 0 done; 2 the input is wrong (every problem listed, no traceback,
nothing written); 1 an internal error.
"""
from __future__ import annotations

import argparse
import sys
import traceback
from pathlib import Path

from assess import __version__
from assess.errors import InputError, Problem

EXIT_OK, EXIT_INTERNAL, EXIT_INPUT = 0, 1, 2
FORMATS = ("html", "pdf")

DESCRIPTION = """\
Assess the freestanding equipment of a building under a design earthquake:
which items slide, rock or overturn, how far they slide, and the probability
that sliding exceeds the room each item has (Konstantinidis & Makris 2010).

Reads WORKBOOK (sheets equipment, hazard, settings: see README), assesses every
item under the motions of hazard level LEVEL, and writes summary.csv,
motions.csv, report.html and report.pdf into --out."""


def _formats(text: str) -> tuple[str, ...]:
    chosen = tuple(part.strip().lower() for part in text.split(",") if part.strip())
    unknown = [part for part in chosen if part not in FORMATS]
    if unknown or not chosen:
        raise argparse.ArgumentTypeError(
            f"'{text}' is not a list of report formats; use html, pdf or html,pdf")
    return chosen


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
        epilog="Exit codes: 0 done; 2 the input is wrong (each problem is named); 1 internal error.")
    parser.add_argument("workbook", metavar="WORKBOOK", type=Path, help="the inventory workbook (.xlsx)")
    parser.add_argument("--hazard", metavar="LEVEL", required=True,
                        help="hazard level as the workbook names it; 2in50, 2%%/50yr and 2475yr are the same level")
    parser.add_argument("--out", metavar="DIR", type=Path,
                        help="output folder (default: reports/<workbook stem>-<LEVEL>/)")
    parser.add_argument("--format", metavar="FORMATS", type=_formats, default=FORMATS,
                        help="report formats, comma-separated: html, pdf (default: html,pdf); "
                             "the CSV files are always written")
    parser.add_argument("--jobs", metavar="N", type=_whole_number(1), default=1,
                        help="parallel worker processes for time-history simulation (default 1)")
    parser.add_argument("--seed", metavar="N", type=_whole_number(0), default=0,
                        help="seed of every random draw; the same inputs and seed give the same numbers (default 0)")
    parser.add_argument("--quiet", action="store_true", help="do not print progress")
    parser.add_argument("--version", action="version", version=f"assess {__version__}")
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)  # argparse exits with 2 on a wrong option
    say = (lambda message: None) if args.quiet else (lambda message: print(f"assess: {message}", file=sys.stderr))
    try:
        return _assess(args, say)
    except InputError as error:
        print(str(error), file=sys.stderr)
        print("Nothing was written.", file=sys.stderr)
        return EXIT_INPUT
    except KeyboardInterrupt:
        print("assess: interrupted; nothing was written.", file=sys.stderr)
        return EXIT_INTERNAL
    except Exception:  # noqa: BLE001 - the one place that turns a bug into exit code 1
        traceback.print_exc()
        print("assess: internal error (a bug, not your input): please report it with the "
              "traceback above. Nothing was written.", file=sys.stderr)
        return EXIT_INTERNAL


def _assess(args: argparse.Namespace, say) -> int:
    from assess.hazard.levels import parse_level
    from assess.inventory import read_workbook
    from assess.output import render_outputs, write_atomically
    from assess.pipeline import run_assessment

    try:
        level_name = parse_level(args.hazard).name
    except ValueError as error:
        raise InputError([Problem(file="--hazard", message=str(error))]) from None
    say(f"reading {args.workbook}")
    inventory = read_workbook(args.workbook)
    result = run_assessment(inventory, args.hazard, seed=args.seed, progress=say)
    say("rendering " + ", ".join(["summary.csv", "motions.csv"] + [f"report.{f}" for f in args.format]))
    files = render_outputs(result, args.format)
    out_dir = args.out or Path("reports") / f"{args.workbook.stem}-{level_name}"
    written = write_atomically(files, out_dir)
    counts = result.risk_counts()
    say(f"{counts['high']} high, {counts['moderate']} moderate, {counts['low']} low risk, "
        f"{counts['anchored']} anchored")
    for path in written:
        print(path)
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
