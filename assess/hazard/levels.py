"""Hazard levels: one level, many spellings.

A level is a probability of exceedance ``P`` in an exposure time ``t`` (years),
equivalently a mean return period (Poisson occurrence):

.. math::  T_R = -t / \\ln(1 - P)

so ``2in50``, ``2%/50yr``, ``2% in 50 years`` and ``2475yr`` name the same
level (2 % in 50 years gives :math:`T_R` = 2475 years). Two spellings are the
same level when their annual exceedance rates agree to 1 %.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

_EXPOSURE_YEARS_DEFAULT = 50.0

_PROBABILITY_IN_TIME = re.compile(
    r"^\s*(?P<p>\d+(?:\.\d+)?)\s*%?\s*(?:in|/|_|-)\s*(?P<t>\d+(?:\.\d+)?)\s*"
    r"(?:y|yr|yrs|year|years)?\s*$",
    re.IGNORECASE,
)
_RETURN_PERIOD = re.compile(
    r"^\s*(?:tr\s*=?\s*)?(?P<tr>\d+(?:\.\d+)?)\s*(?:-?\s*)(?:y|yr|yrs|year|years)"
    r"(?:\s*return\s*period)?\s*$",
    re.IGNORECASE,
)


@dataclass(frozen=True)
class HazardLevel:
    """A hazard level as a probability of exceedance in an exposure time."""

    probability: float  # probability of exceedance in ``exposure_years`` [-]
    exposure_years: float  # [yr]

    @property
    def return_period_yr(self) -> float:
        """Mean return period [yr], :math:`-t/\\ln(1-P)`."""
        return -self.exposure_years / math.log1p(-self.probability)

    @property
    def annual_rate(self) -> float:
        """Mean annual rate of exceedance [1/yr]."""
        return 1.0 / self.return_period_yr

    @property
    def name(self) -> str:
        """Canonical short name, e.g. ``2in50``."""
        return f"{_fmt(round(self.probability * 100, 1))}in{_fmt(self.exposure_years)}"

    @property
    def description(self) -> str:
        return (f"{_fmt(round(self.probability * 100, 1))}% in {_fmt(self.exposure_years)} years "
                f"(return period {self.return_period_yr:.0f} years)")

    def same_as(self, other: "HazardLevel") -> bool:
        return math.isclose(self.annual_rate, other.annual_rate, rel_tol=0.01)


def _fmt(x: float) -> str:
    return f"{x:g}"


def parse_level(text: object) -> HazardLevel:
    """Parse a hazard-level spelling.

    Accepts ``2in50``, ``2%/50yr``, ``2% in 50 years``, ``2_50``, ``2475yr``,
    ``2475 years``. Raises ``ValueError`` with the accepted forms otherwise.

    Examples
    --------
    >>> round(parse_level("2in50").return_period_yr)
    2475
    >>> parse_level("2475yr").same_as(parse_level("2%/50yr"))
    True
    """
    s = str(text).strip()
    match = _PROBABILITY_IN_TIME.match(s)
    if match:
        percent = float(match["p"])
        years = float(match["t"])
        if not 0 < percent < 100 or years <= 0:
            raise ValueError(f"hazard level '{s}': the probability must lie between 0 and 100 % "
                             "and the exposure time must be positive")
        return HazardLevel(percent / 100.0, years)
    match = _RETURN_PERIOD.match(s)
    if match:
        return_period = float(match["tr"])
        if return_period <= 0:
            raise ValueError(f"hazard level '{s}': the return period must be positive")
        probability = 1.0 - math.exp(-_EXPOSURE_YEARS_DEFAULT / return_period)
        return HazardLevel(probability, _EXPOSURE_YEARS_DEFAULT)
    raise ValueError(f"'{s}' is not a hazard level; write it as '2in50', '2%/50yr', "
                     "'2% in 50 years' or a return period such as '2475yr'")
