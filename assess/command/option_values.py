"""What the command line's options take: argparse types that refuse a wrong value naming the option (exit 2).

:mod:`assess.cli` reads this before it imports the core, so it imports nothing heavy at the top.
"""
from __future__ import annotations

import argparse

#: What the report may be written as (``assess calibrate``).
FORMATS = ("html", "pdf")
#: What the main job writes besides the CSV files: the report and summary.xlsx.
JOB_FORMATS = ("html", "pdf", "xlsx")


def formats(text: str, allowed: tuple[str, ...] = FORMATS) -> tuple[str, ...]:
    chosen = tuple(part.strip().lower() for part in text.split(",") if part.strip())
    unknown = [part for part in chosen if part not in allowed]
    if unknown or not chosen:
        raise argparse.ArgumentTypeError(
            f"'{text}' is not a list of formats; use {', '.join(allowed)}, comma-separated (e.g. {','.join(allowed)})")
    return chosen


def job_formats(text: str) -> tuple[str, ...]:
    return formats(text, JOB_FORMATS)


def number(accept, requirement: str):
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


positive_number = number(lambda value: value > 0.0, "a positive number")
coefficient = number(lambda value: value >= 0.0, "a number of 0 or more")


def whole_number(minimum: int):
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


def alpha_range_value(text: str) -> tuple[float, float]:
    """``--alpha-range LOW,HIGH``: two lateral stiffness ratios, low below high, both inside the building sheet's
    bounds (:data:`assess.inventory.site_building.LATERAL_STIFFNESS_RATIO_RANGE`)."""
    from assess.inventory.site_building import LATERAL_STIFFNESS_RATIO_RANGE  # only with the option: pandas

    least, most = LATERAL_STIFFNESS_RATIO_RANGE
    try:
        low, high = (float(part) for part in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not two numbers LOW,HIGH (e.g. 5,20)") from None
    if not (least <= low < high <= most):
        raise argparse.ArgumentTypeError(f"'{text}': give LOW below HIGH, both from {least:g} to {most:g}")
    return low, high
