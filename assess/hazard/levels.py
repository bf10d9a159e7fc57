"""Hazard levels: one level, many spellings, or a label.

A level is either a probability of exceedance ``P`` in an exposure time ``t``
(years), equivalently a mean return period (Poisson occurrence):

.. math::  T_R = -t / \\ln(1 - P)

so ``2in50``, ``2%/50yr``, ``2% in 50 years`` and ``2475yr`` name the same
level (2 % in 50 years gives :math:`T_R` = 2475 years; two spellings are the
same level when their annual exceedance rates agree to 1 %), or a *label*:
any other text (``DE``, ``MCE_R``, ``SLE``, ``test``), which names the level
the hazard study or the table test calls so and is matched as text, ignoring
case and surrounding blanks. A label carries no probability, so nothing that
needs one (an OpenQuake hazard curve) can be read at it.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

_EXPOSURE_YEARS_DEFAULT = 50.0
#: Return periods a probability level may have [yr]. Below 1 year a "level" is
#: a yearly event, above 10^8 years no hazard study defines the ground motion
#: (OpenQuake curves end near 10^-6 to 10^-7 per year); outside, the spelling is a mistake.
RETURN_PERIOD_MIN_YR, RETURN_PERIOD_MAX_YR = 1.0, 1e8
#: A return-period spelling is re-expressed as a probability in 50 years, which
#: keeps its meaning only above some 10 years (10 yr is 99.3 % in 50 years).
RETURN_PERIOD_SPELLED_MIN_YR = 10.0
#: Longest label; it names an output folder and heads the report.
LABEL_MAX_CHARS = 40

_NUMBER = r"\d+(?:\.\d+)?"
_PROBABILITY_IN_TIME = re.compile(
    rf"^\s*(?P<p>{_NUMBER})\s*%?\s*(?:in|/|_|-)\s*(?P<t>{_NUMBER})\s*"
    r"(?:y|yr|yrs|year|years)?\s*$",
    re.IGNORECASE,
)
_RETURN_PERIOD = re.compile(
    rf"^\s*(?:tr\s*=?\s*)?(?P<tr>{_NUMBER})\s*(?:-?\s*)(?:y|yr|yrs|year|years)"
    r"(?:\s*return\s*period)?\s*$",
    re.IGNORECASE,
)
_UNSAFE_IN_NAME = re.compile(r"[^\w.+-]+")


@dataclass(frozen=True)
class HazardLevel:
    """A hazard level: a probability of exceedance in an exposure time, or a label.

    ``label`` is empty for a probability level; a label level has
    ``probability`` and ``exposure_years`` None.
    """

    probability: float | None  # probability of exceedance in ``exposure_years`` [-]
    exposure_years: float | None  # [yr]
    label: str = ""

    @classmethod
    def labelled(cls, text: str) -> "HazardLevel":
        """A level named by ``text`` alone (``DE``, ``MCE_R``, ``test``)."""
        return cls(None, None, " ".join(str(text).split()))

    @property
    def has_probability(self) -> bool:
        return self.probability is not None

    @property
    def return_period_yr(self) -> float:
        """Mean return period [yr], :math:`-t/\\ln(1-P)`."""
        return -self._probability_level().exposure_years / math.log1p(-self.probability)

    @property
    def annual_rate(self) -> float:
        """Mean annual rate of exceedance [1/yr]."""
        return 1.0 / self.return_period_yr

    @property
    def name(self) -> str:
        """Canonical short name, safe in a file name: ``2in50``, ``0.04in50``; a label with
        every run of characters other than letters, digits, ``.``, ``+``, ``-`` and ``_``
        replaced by ``_`` (``MCE R`` -> ``MCE_R``)."""
        if not self.has_probability:
            return _UNSAFE_IN_NAME.sub("_", self.label).strip("._") or "level"
        return f"{_percent_text(self)}in{_plain(self.exposure_years, 6)}"

    @property
    def key(self) -> str:
        """What two spellings of one label share (the label without case); the name otherwise."""
        return self.label.casefold() if not self.has_probability else self.name

    @property
    def description(self) -> str:
        if not self.has_probability:
            return f"{self.label}, a level named by label (no probability of exceedance given)"
        return (f"{_percent_text(self)}% in {_plain(self.exposure_years, 6)} years "
                f"(return period {self.return_period_yr:.0f} years)")

    def same_as(self, other: "HazardLevel") -> bool:
        """Two spellings of one level: equal labels (ignoring case), or annual rates within 1 %."""
        if self.has_probability != other.has_probability:
            return False
        if not self.has_probability:
            return self.key == other.key
        return math.isclose(self.annual_rate, other.annual_rate, rel_tol=0.01)

    def _probability_level(self) -> "HazardLevel":
        if not self.has_probability:
            raise ValueError(f"the level '{self.label}' is a label; it has no probability of "
                             "exceedance or return period")
        return self


def _plain(x: float, digits: int) -> str:
    """``x`` to ``digits`` significant digits, positional (never ``1e-05``), no trailing zeros."""
    return np.format_float_positional(float(x), precision=digits, unique=True, fractional=False,
                                      trim="-")


def _percent_text(level: HazardLevel) -> str:
    """The probability in percent with the fewest significant digits that parse back to a rate
    within 0.2 % (well inside :meth:`HazardLevel.same_as`'s 1 %) and stay below 100 %:
    ``0.04`` stays ``0.04`` (not ``0``), 2475 yr reads ``2`` and 475 yr ``10``."""
    percent = level.probability * 100.0
    for digits in range(1, 18):
        text = _plain(percent, digits)
        value = float(text)
        if 0.0 < value < 100.0 and math.isclose(
                -math.log1p(-value / 100.0), -math.log1p(-level.probability), rel_tol=2e-3):
            return text
    return _plain(percent, 17)


def parse_level(text: object) -> HazardLevel:
    """Parse a hazard-level spelling, or take the text as a label.

    Accepts ``2in50``, ``2%/50yr``, ``2% in 50 years``, ``2_50``, ``2475yr``,
    ``2475 years`` as probabilities; any other text of at most
    :data:`LABEL_MAX_CHARS` characters is a label (``DE``, ``MCE_R``,
    ``test``). Raises ``ValueError`` for an empty text, an overlong label, and
    a probability spelling out of range (``0in50``, ``150%/50yr``, ``0.5yr``).

    Examples
    --------
    >>> round(parse_level("2in50").return_period_yr)
    2475
    >>> parse_level("2475yr").same_as(parse_level("2%/50yr"))
    True
    >>> parse_level("0.04in50").name
    '0.04in50'
    >>> parse_level("MCE_R").same_as(parse_level(" mce_r "))
    True
    """
    s = str(text).strip()
    match = _PROBABILITY_IN_TIME.match(s)
    if match:
        percent, years = float(match["p"]), float(match["t"])
        if not (0 < percent < 100 and math.isfinite(years) and years > 0):
            raise ValueError(f"hazard level '{_cap(s)}': the probability must lie between 0 and "
                             "100 % and the exposure time must be positive")
        return _bounded(HazardLevel(percent / 100.0, years), s)
    match = _RETURN_PERIOD.match(s)
    if match:
        return_period = float(match["tr"])
        if not RETURN_PERIOD_SPELLED_MIN_YR <= return_period <= RETURN_PERIOD_MAX_YR:
            raise ValueError(f"hazard level '{_cap(s)}': a return period lies between "
                             f"{RETURN_PERIOD_SPELLED_MIN_YR:g} and {RETURN_PERIOD_MAX_YR:g} years")
        probability = -math.expm1(-_EXPOSURE_YEARS_DEFAULT / return_period)
        return HazardLevel(probability, _EXPOSURE_YEARS_DEFAULT)
    if not s:
        raise ValueError("the hazard level is empty; write it as '2in50', '2%/50yr', "
                         "'2475yr' or a label such as 'DE'")
    if len(s) > LABEL_MAX_CHARS:
        raise ValueError(f"the hazard level '{_cap(s)}' is {len(s)} characters long; a level is a "
                         f"probability such as '2in50' or '2475yr', or a label of at most "
                         f"{LABEL_MAX_CHARS} characters such as 'DE' or 'MCE_R'")
    if any(not character.isprintable() for character in s.replace(" ", "")):
        raise ValueError(f"the hazard level {s!r:.60} holds control characters; write it as "
                         "'2in50', '2475yr' or a label such as 'DE'")
    return HazardLevel.labelled(s)


def _bounded(level: HazardLevel, text: str) -> HazardLevel:
    """``level`` when its return period lies in the bounds, else ``ValueError``."""
    return_period = level.return_period_yr
    if not RETURN_PERIOD_MIN_YR <= return_period <= RETURN_PERIOD_MAX_YR:
        raise ValueError(f"hazard level '{_cap(text)}' has a return period of {return_period:.3g} "
                         f"years; a hazard level lies between {RETURN_PERIOD_MIN_YR:g} and "
                         f"{RETURN_PERIOD_MAX_YR:g} years")
    return level


def _cap(text: str, limit: int = 60) -> str:
    return text if len(text) <= limit else text[:limit - 1] + "…"
