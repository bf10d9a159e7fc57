"""A level's ground suite, scaled or matched to its target spectrum.

Two routes, one result (:class:`GroundSuite`):

**Records** (:func:`select_and_scale`), as ASCE 7-22 §16.2 asks of a suite for response-history
analysis:

* suite size: ``suite_size`` motions (default 11, the minimum of §16.2.2; a synthetic suite's default is
  :data:`SYNTHETIC_SUITE_SIZE`, enough motions for an item's class to be clear);
* period range (§16.2.3.1): from 0.2 T_min to 2 T_max, where T_min and T_max are the
  shortest and longest of the periods that matter here: the building's first modes and the
  items' own periods, passed in (:func:`period_range_s`);
* each motion's spectrum: its own for one component; for a horizontal pair its
  maximum-direction spectrum RotD100 (Boore 2010), the measure of ASCE 7-22's
  maximum-direction MCE_R target (§16.2.3.2 compares the pairs' maximum-direction spectra
  with the target);
* amplitude scaling: each motion's factor minimises the mean squared log misfit to the
  target over the range, ln λ = mean(ln S_target − ln S_motion) (the geometric-mean fit),
  held within ``scale_bounds`` (default 0.25-4: ASCE 7-22 sets no bound; large factors
  distort a record's frequency content and duration relative to the scenario, so moderate
  factors are common practice, e.g. NIST GCR 11-917-15 §3); the ``suite_size`` motions of
  least misfit after scaling form the suite (ties broken by name);
* §16.2.3.2: the suite's mean spectrum must not fall below 90 % of the target anywhere in the
  range: a common factor max(1, 0.9 / min ratio) is applied to every motion of the suite.

**Synthetic** (:func:`synthetic_suite`), when no records are given: spectrum-compatible motions.
Each starts as one realisation of the Rezaeian & Der Kiureghian (2008) nonstationary filtered
white noise (:func:`assess.hazard.synthesis.rezaeian_residual`: gamma modulating function,
time-varying filter), seeded per motion from the level and the motion's index
(:func:`motion_seed`), and is then matched to the target by the iterative Fourier-amplitude
scaling of SIMQKE (Gasparini & Vanmarcke 1976): the amplitudes are multiplied by the ratio of
target to response spectrum at the frequency 1/T, phases kept, until the spectrum is within
``match_tolerance`` of the target over the range. After each pass the acceleration is
baseline-corrected (:func:`assess.site.matching.baseline_corrected`: a linear correction of the acceleration that
brings the end velocity and displacement to zero, Boore 2001 style), so the final history
both matches and ends at rest. One horizontal component per motion, matched to the target as
it is (maximum-direction when the target is).

References
----------
ASCE/SEI 7-22, Minimum Design Loads and Associated Criteria for Buildings and Other Structures,
  §16.2 (ground motions for response-history analysis).
Boore, D. M. (2001). Effect of baseline corrections on displacements and response spectra for
  several recordings of the 1999 Chi-Chi, Taiwan, earthquake. Bull. Seismol. Soc. Am.
  91(5):1199-1211. doi:10.1785/0120000703
Boore, D. M. (2010). doi:10.1785/0120090400 (RotD100).
Clopper, C. J., Pearson, E. S. (1934). The use of confidence or fiducial limits illustrated in the case of the
  binomial. Biometrika 26(4):404-413. doi:10.1093/biomet/26.4.404
Hanley, J. A., Lippman-Hand, A. (1983). If nothing goes wrong, is everything all right? Interpreting zero
  numerators. JAMA 249(13):1743-1745. doi:10.1001/jama.1983.03330370053031
Gasparini, D. A., Vanmarcke, E. H. (1976). SIMQKE: a program for artificial motion
  generation. MIT Department of Civil Engineering, Report R76-4.
NIST GCR 11-917-15 (2011). Selecting and scaling earthquake ground motions for performing
  response-history analyses. NEHRP Consultants Joint Venture.
Rezaeian, S., Der Kiureghian, A. (2008). doi:10.1002/eqe.831.
"""
from __future__ import annotations

import hashlib
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Sequence

import numpy as np
import pandas as pd

from assess.errors import InputError, Problem
from assess.hazard.records import DT_TOLERANCE, MIN_DURATION_S, Record, check_record_location, read_record
from assess.hazard.synthesis import rezaeian_residual
from assess.mechanics.geometry import STANDARD_GRAVITY_M_S2
from assess.site.matching import check_periods_s, match_pair, match_spectrum
from assess.site.spectrum import pseudo_acceleration_spectrum, rotd_spectrum

#: Records in a suite selected from a records folder (ASCE 7-22 §16.2.2: at least 11).
DEFAULT_SUITE_SIZE = 11
#: Synthetic motions in a suite: enough for an item that none of them overturns to be clearly ``low``. With n
#: motions and no failure, the upper end of the 90 % Clopper-Pearson interval (Clopper & Pearson 1934) is
#: 1 - 0.05^(1/n) (about 3/n, the "rule of three": Hanley & Lippman-Hand 1983); the lowest threshold a class
#: turns on is overturning's 2.5 % (assess.decision.risk_classes), so n >= ln 0.05 / ln 0.975 = 118.3: 120 motions put
#: a 0-of-120 item's interval (0-2.5 %) inside ``low``. Eleven motions (ASCE 7's minimum for a building's
#: own response) bound the same item only below 24 %, which spans every class. A synthetic motion costs
#: what its matching costs (about 0.05 s), so the evidence is cheap where records are not.
SYNTHETIC_SUITE_SIZE = 120
#: Bounds of one record's amplitude scale factor (see the module docstring).
DEFAULT_SCALE_BOUNDS = (0.25, 4.0)
#: The suite's mean spectrum is at least this share of the target over the range (§16.2.3.2).
MEAN_RATIO_MIN = 0.9
#: A suite whose mean is this many times the target or more at the median period of its range is said to
#: overshoot (a caution): §16.2.3.2 bounds the mean from below only, and one common factor that lifts a suite's
#: weakest period to 90 % lifts every other period with it, so a pool of records shaped unlike the target gives a
#: suite of a stronger earthquake than the level's. 1.3: the overshoot an 11-record suite's spread alone gives
#: (the arithmetic mean of records centred on the target in ln, with a spread σ ln of 0.7, is e^(σ²/2) = 1.28
#: times it); a judgement, not a code value.
OVERSHOOT_RATIO = 1.3
#: The suite's mean PGA is said (a caution) where it is outside these shares of the target's PGA (its value at
#: T = 0): items on the ground floor stand on the ground motion itself, whose peak is their demand. A judgement:
#: synthetic suites matched to ASCE 7 spectra stay within it (0.94-1.11 of 0.4 S_DS, two sites and three
#: period ranges), the constructed UHS's fall to 0.53-0.63 of its PGA.
PGA_RATIO_BOUNDS = (0.8, 1.25)
#: Period range bounds as multiples of the shortest and longest period that matters (§16.2.3.1).
LOWER_FACTOR, UPPER_FACTOR = 0.2, 2.0
#: Periods [s] shown in spectrum.csv besides the range's own (an NGA-West2-like ladder).
REPORT_PERIODS_S = (0.01, 0.02, 0.03, 0.05, 0.075, 0.1, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5, 0.75,
                    1.0, 1.5, 2.0, 3.0, 4.0, 5.0, 7.5, 10.0)
#: A synthetic motion whose spectrum deviates from the target by more than this share somewhere in the range is
#: named in the suite's notes. One realisation matched by :func:`match_spectrum` deviates by 9-16 % at most on
#: the dense check (20 motions, S_DS 1.1 g, S_D1 0.6 g, 0.05-8 s; median 11 %): narrow dips between the
#: periods it scales at; what ASCE 7-22 §16.2.3.3 constrains is the suite's mean (:data:`MEAN_RATIO_MIN`).
SYNTHETIC_TOLERANCE = 0.20
#: Files read from a records folder at most.
MAX_RECORD_FILES = 2000
#: Components that are not horizontal (skipped in a records folder).
_VERTICAL = re.compile(r"[-_ ](UP|DWN|DN|V|VER|VERT|HNZ|Z)$", re.IGNORECASE)
#: A trailing horizontal-component designator (an azimuth, H1/H2, N/E, FN/FP ...).
_COMPONENT = re.compile(r"[-_ ](\d{3}|H1|H2|HN1|HN2|HNE|HNN|HLE|HLN|N|E|S|W|NS|EW|FN|FP|X|Y|L|T|NORTH|EAST)$",
                        re.IGNORECASE)


# --------------------------------------------------------------------------- period range

#: Shortest period [s] a suite is matched or checked at: below it an ASCE 7 or uniform-hazard spectrum is the
#: peak ground acceleration's straight line, and a 5 %-damped oscillator follows the ground (Sa = PGA): nothing
#: there shapes a floor's motion or an item's response, and matching there chases a few time steps' worth of
#: content (at 0.005 s, 0.05 s is 10 steps a cycle). The suite's PGA is not matched: it is checked against the
#: target's at T = 0 (:func:`amplitude_cautions`), since a UHS's straight line from its PGA to its first SA period
#: need not be what a motion's spectrum does there.
MIN_PERIOD_S = 0.05
#: The fewest time steps a cycle at the range's shortest period may hold.
MIN_STEPS_PER_CYCLE = 10
#: Longest period [s] a suite is matched or checked at: the longest of a ground-motion model's spectral periods
#: (NGA-West2, and USGS's 2018 hazard model, stop at 10 s), beyond which a target spectrum is extrapolated.
MAX_PERIOD_S = 10.0


def period_range_s(periods_s, *, mass_period_s=None, lower_factor=LOWER_FACTOR, upper_factor=UPPER_FACTOR,
                   min_period_s=MIN_PERIOD_S, max_period_s=MAX_PERIOD_S):
    """(lower, upper) period range [s] of the suite: 0.2 T_min and 2 T_max (ASCE 7-22 §16.2.3.1), within
    [``min_period_s``, ``max_period_s``].

    ``periods_s`` are the periods that matter: the building's first modes in its two
    directions and the band of periods the items respond to. ``mass_period_s``, where known, is the
    shortest period of the modes needed for 90 % of the building's mass: §16.2.3.1 asks the range to
    reach down to it too, so the lower bound is the smaller of the two. The range never reaches below
    :data:`MIN_PERIOD_S` nor beyond :data:`MAX_PERIOD_S` (see their notes).

    >>> period_range_s([0.7, 0.5, 1.2]), period_range_s([0.7, 0.5, 1.2], mass_period_s=0.08)
    ((0.1, 2.4), (0.08, 2.4))
    >>> period_range_s([0.03, 12.0])  # a stiff wall's fifth mode, a tall tower's first
    (0.05, 10.0)
    """
    periods = np.asarray(periods_s, dtype=float).ravel()
    if periods.size == 0 or np.any(~np.isfinite(periods)) or np.any(periods <= 0):
        raise ValueError("the periods that matter must be positive numbers [s]")
    lower = float(lower_factor * periods.min())
    if mass_period_s is not None:
        lower = min(lower, float(mass_period_s))
    upper = float(upper_factor * periods.max())
    return float(min(max(lower, min_period_s), max_period_s)), float(max(min(upper, max_period_s), min_period_s))


def report_periods_s(lower_s, upper_s, max_period_s=np.inf):
    """Periods [s] of spectrum.csv: :data:`REPORT_PERIODS_S`, the range's bounds and 25 points inside."""
    periods = np.union1d(np.array(REPORT_PERIODS_S), np.geomspace(lower_s, upper_s, 25))
    periods = periods[periods <= max_period_s * (1 + 1e-12)]
    return np.round(periods, 6)


# --------------------------------------------------------------------------- motions

@dataclass(frozen=True)
class Motion:
    """One ground motion of a suite: one component, or a horizontal pair (``second``)."""

    name: str
    first: Record
    second: Record | None = None
    source: str = ""  # file name(s) or "synthetic"
    seed: int | None = None

    def scaled(self, factor: float) -> "Motion":
        return Motion(self.name, self.first.scaled(factor),
                      None if self.second is None else self.second.scaled(factor), self.source, self.seed)

    @property
    def pga_g(self) -> float:
        """Peak ground acceleration [g]: the larger component's (RotD100 at T = 0 for a pair)."""
        if self.second is None:
            return self.first.pta_g
        n = min(self.first.accel_g.size, self.second.accel_g.size)
        return float(np.max(np.hypot(self.first.accel_g[:n], self.second.accel_g[:n])))

    def spectrum_g(self, period_s) -> np.ndarray:
        """5 %-damped Sa [g]: the component's own, or RotD100 of a pair."""
        if self.second is None:
            return pseudo_acceleration_spectrum(self.first.accel_g, self.first.dt_s, period_s)
        return rotd_spectrum(self.first.accel_g, self.second.accel_g, self.first.dt_s, period_s,
                             percentile=(100.0,))[100.0]


def _component_key(stem: str) -> str | None:
    """Name shared by the two horizontal components of one recording (None for a vertical one)."""
    if _VERTICAL.search(stem):
        return None
    return _COMPONENT.sub("", stem)


def read_records_folder(folder, *, workbook_folder=None, what: str = "records") -> list[Motion]:
    """The ground motions of a records folder: PEER NGA ``.AT2`` or CSV files, paired by name.

    Two files whose names differ only in a trailing horizontal-component designator (an
    azimuth such as ``-090``/``-360``, ``H1``/``H2``, ``N``/``E``, ``FN``/``FP``) form a pair;
    vertical components (``UP``, ``DWN``, ``V``, ``HNZ``) are skipped; any other file is one
    motion. Files are read with :func:`~assess.hazard.records.read_record` (at least 2 s long).
    With ``workbook_folder``, the folder and every file must lie inside it once links are followed
    (:func:`~assess.hazard.records.check_record_location`).

    Raises
    ------
    InputError
        The folder is missing or holds no record; a file cannot be read (its own message);
        the two components of a pair have different steps.
    """
    folder = Path(folder)
    if not folder.is_dir():
        raise InputError([Problem(str(folder), f"the {what} folder does not exist.",
                                  "give a folder, relative to the workbook, holding .AT2 or .csv records.")])
    files = sorted(p for p in folder.iterdir() if p.is_file() and p.suffix.lower() in (".at2", ".csv"))
    if workbook_folder is not None:
        for path in [folder] + files:
            outside = check_record_location(path, workbook_folder)
            if outside:
                raise InputError([Problem(str(path), outside, f"put the {what} folder inside the workbook's folder.")])
    if len(files) > MAX_RECORD_FILES:
        raise InputError([Problem(str(folder), f"the {what} folder holds more than {MAX_RECORD_FILES} records.",
                                  "keep the candidate records of this site only.")])
    groups: dict[str, list[Path]] = {}
    for path in files:
        key = _component_key(path.stem)
        if key is not None:
            groups.setdefault(key, []).append(path)
    if not groups:
        raise InputError([Problem(str(folder), f"the {what} folder holds no horizontal record (.AT2 or .csv).",
                                  "put the candidate ground-motion records there.")])
    motions = []
    for key in sorted(groups):
        paths = groups[key]
        records = [read_record(p, min_duration_s=MIN_DURATION_S) for p in paths]
        if len(paths) == 2:
            first, second = records
            if abs(first.dt_s - second.dt_s) > DT_TOLERANCE * first.dt_s:
                raise InputError([Problem(str(paths[1]), f"its time step ({second.dt_s:g} s) differs from that of "
                                          f"{paths[0].name} ({first.dt_s:g} s), the other component of the pair.",
                                          "give both components of one recording, or rename one so that they "
                                          "are not read as a pair.")])
            motions.append(Motion(key, first, second, f"{paths[0].name} + {paths[1].name}"))
        else:
            motions.extend(Motion(p.stem, r, None, p.name) for p, r in zip(paths, records))
    return motions


# --------------------------------------------------------------------------- the suite

@dataclass(frozen=True)
class GroundSuite:
    """A level's ground suite against its target.

    Attributes
    ----------
    level : str
        The level's name.
    method : str
        ``"records"`` (amplitude-scaled), ``"matched records"`` or ``"synthetic"``.
    motions : tuple of Motion
        The suite, scaled (records) or matched (synthetic).
    scale_factors : ndarray
        Each motion's factor (1 for synthetic motions).
    lower_s, upper_s : float
        The period range [s].
    min_mean_ratio : float
        Smallest ratio of the suite's mean spectrum to the target over the range (dense grid).
    ground_motions : DataFrame
        One row per motion: ``level, motion, record, seed, scale_factor, pga_g, misfit_ln`` (the root mean
        square of ln(Sa/target) over the range), ``max_deviation`` (the largest |Sa/target − 1| there)
        and ``sa_<T>s_g`` at the periods of ``spectrum`` (columns of ground_motions.csv).
    spectrum : DataFrame
        One row per period: ``level, period_s, target_g, suite_mean_g, ratio, in_range,
        range_lower_s, range_upper_s`` (spectrum.csv).
    notes : tuple of str
        How the suite was made, in clauses.
    cautions : tuple of str
        Those of ``notes`` that say where the suite falls short of what ASCE 7-22 §16.2 asks (the period range cut
        at the target's longest period, the mean below 90 % of the target, records scaled beyond the bounds) or is
        not of the level's amplitude (a mean far above the target, a mean PGA off the target's:
        :func:`amplitude_cautions`):
        the report's note on the ground motions says them (:func:`assess.assessment.floors.site_note`).
    """

    level: str
    method: str
    motions: tuple[Motion, ...]
    scale_factors: np.ndarray
    lower_s: float
    upper_s: float
    min_mean_ratio: float
    ground_motions: pd.DataFrame
    spectrum: pd.DataFrame
    notes: tuple[str, ...] = field(default_factory=tuple)
    cautions: tuple[str, ...] = field(default_factory=tuple)

    @property
    def records(self) -> list[Record]:
        """The first component of each motion (what a one-component floor motion takes)."""
        return [m.first for m in self.motions]


def _tables(level, motions, factors, target, lower, upper, max_period, misfits, deviations, seeds):
    periods = report_periods_s(lower, upper, max_period)
    spectra = np.array([m.spectrum_g(periods) for m in motions])
    target_g = np.asarray(target(periods), dtype=float)
    mean = spectra.mean(axis=0)
    rows = []
    for k, motion in enumerate(motions):
        row = {"level": level, "motion": motion.name, "record": motion.source,
               "seed": None if seeds[k] is None else int(seeds[k]), "scale_factor": float(factors[k]),
               "pga_g": motion.pga_g, "misfit_ln": float(misfits[k]), "max_deviation": float(deviations[k])}
        row.update({f"sa_{p:g}s_g": float(s) for p, s in zip(periods, spectra[k])})
        rows.append(row)
    spectrum = pd.DataFrame({"level": level, "period_s": periods, "target_g": target_g, "suite_mean_g": mean,
                             "ratio": mean / target_g,
                             "in_range": (periods >= lower * (1 - 1e-9)) & (periods <= upper * (1 + 1e-9)),
                             "range_lower_s": lower, "range_upper_s": upper})
    return pd.DataFrame(rows), spectrum


def _within_target(target, lower, upper):
    """The range clipped to the periods the target gives (a UHS ends at its longest SA), and a note if clipped.

    Returns ``(lower, upper, max_period, note)``; raises ValueError when the target ends below the range's
    lower end (it gives no spectrum where the suite must be matched).
    """
    max_period = float(getattr(target, "max_period_s", np.inf))
    if upper <= max_period * (1 + 1e-9):
        return lower, upper, max_period, None
    if max_period <= lower * (1 + 1e-9):
        raise ValueError(f"the target spectrum ends at {max_period:.3g} s, below the period range's lower end "
                         f"{lower:.3g} s")
    note = (f"the period range (ASCE 7-22 §16.2.3.1: up to twice the longest period that matters, the building's or "
            f"an item's rocking) would reach {upper:.3g} s, beyond the target spectrum's longest period "
            f"{max_period:.3g} s: the suite is matched and checked up to {max_period:.3g} s")
    return lower, max_period, max_period, note


def amplitude_cautions(motions: Sequence[Motion], target: Callable, periods_s, ratio, *, common_factor=1.0) -> list:
    """What a suite's amplitude says that its 90 % floor does not: a mean far above the target over most of the
    range (:data:`OVERSHOOT_RATIO`), a mean PGA outside :data:`PGA_RATIO_BOUNDS` of the target's.

    ``ratio`` is the suite's mean over the target at ``periods_s`` (the range's check grid); ``common_factor`` the
    factor the suite was lifted by, if any. A target without a value at T = 0 (a UHS without PGA) gives no PGA
    check.

    >>> from assess.hazard.records import Record
    >>> flat = lambda period_s: np.full(np.shape(period_s), 0.5)
    >>> motion = Motion("m", Record(np.array([0.0, 0.6, -0.3, 0.0]), 0.01, "m"), None, "records", None)
    >>> amplitude_cautions([motion], flat, [0.1, 1.0, 2.0], [2.0, 2.4, 0.9], common_factor=1.8)[0][:61]
    "the suite's mean is 2.0 times the target at the median period"
    >>> amplitude_cautions([motion], flat, [0.1, 1.0], [1.0, 1.1])
    []
    """
    cautions = []
    periods, ratio = np.asarray(periods_s, dtype=float), np.asarray(ratio, dtype=float)
    typical = float(np.median(ratio))
    if typical >= OVERSHOOT_RATIO:
        weakest = float(periods[np.argmin(ratio)])
        lifted = (f"the common factor {common_factor:.2f} that lifts its weakest period ({weakest:.3g} s) to "
                  f"{MEAN_RATIO_MIN:.0%} of the target lifts every other period with it, so " if common_factor > 1.0
                  else "")
        cautions.append(f"the suite's mean is {typical:.1f} times the target at the median period of the range "
                        f"({ratio.max():.1f} at most): {lifted}the items are assessed under stronger shaking than "
                        "the level's; records shaped like the target spectrum, the site sheet's records_scaling "
                        "matched (each record matched to it), or no records folder (synthetic motions matched to it) "
                        "give the level's own")
    try:
        target_pga = float(np.asarray(target(np.array([0.0])), dtype=float)[0])
    except ValueError:  # a UHS without PGA: nothing to check against
        return cautions
    pga = float(np.mean([motion.pga_g for motion in motions]))
    low, high = PGA_RATIO_BOUNDS
    if target_pga > 0 and not low <= pga / target_pga <= high:
        cautions.append(f"the suite's mean PGA is {pga / target_pga:.0%} of the target's ({pga:.3g} g against "
                        f"{target_pga:.3g} g), which the fit over the range does not set: items on the ground "
                        f"floor stand on the motions' own peaks, {'below' if pga < target_pga else 'above'} the "
                        "level's")
    return cautions


def _first_names(names, shown=5) -> str:
    """The first ``shown`` of ``names``, comma-separated, with ", …" where there are more.

    >>> _first_names(["a", "b"]), _first_names(list("abcdefg"), 3)
    ('a, b', 'a, b, c, …')
    """
    return ", ".join(names[:shown]) + (", …" if len(names) > shown else "")


def _selected(candidates, target, periods_s, suite_size, scale_bounds, mass_period_s):
    """The range and the ``suite_size`` candidates of least log misfit to ``target`` over it, each scaled by the
    factor (within ``scale_bounds``) that centres it on the target in ln: ``lower, upper, max_period, clipped``
    (:func:`_within_target`), the check grid, ln of the target there, the candidates' spectra there, every
    candidate's ln factor and the indices chosen."""
    lower, upper, max_period, clipped = _within_target(target, *period_range_s(periods_s, mass_period_s=mass_period_s))
    if len(candidates) < suite_size:
        raise ValueError(f"{len(candidates)} candidate motions for a suite of {suite_size}")
    grid = check_periods_s(lower, upper)
    log_target = np.log(np.asarray(target(grid), dtype=float))
    spectra = np.array([m.spectrum_g(grid) for m in candidates])
    if np.any(spectra <= 0):
        raise ValueError("a candidate motion has a zero spectrum over the range")
    low, high = scale_bounds
    log_factor = np.clip(np.mean(log_target - np.log(spectra), axis=1), np.log(low), np.log(high))
    misfit = np.sqrt(np.mean((np.log(spectra) + log_factor[:, None] - log_target) ** 2, axis=1))
    order = sorted(range(len(candidates)), key=lambda k: (round(float(misfit[k]), 12), candidates[k].name))
    return lower, upper, max_period, clipped, grid, log_target, spectra, log_factor, order[:suite_size]


def matched_suite_cautions(motions: Sequence[Motion], target: Callable, periods_s, ratio, clipped: str) -> list:
    """The cautions of a suite matched to its target, synthetic or recorded: its mean below the 90 % ASCE 7-22
    §16.2.3.3 asks of a matched suite, the range cut at the target's longest period (``clipped``, "" when not),
    and :func:`amplitude_cautions`; ``ratio`` the suite's mean over the target at ``periods_s``."""
    ratio = np.asarray(ratio, dtype=float)
    cautions = []
    if ratio.min() < MEAN_RATIO_MIN:
        cautions.append(f"the suite's mean falls to {ratio.min():.1%} of the target in the range, below the "
                        f"{MEAN_RATIO_MIN:.0%} ASCE 7-22 §16.2.3.3 asks of a matched suite")
    if clipped:
        cautions.append(clipped)
    return cautions + amplitude_cautions(motions, target, periods_s, ratio)


def select_and_scale(candidates: Sequence[Motion], target: Callable, periods_s, *, level: str,
                     suite_size: int = DEFAULT_SUITE_SIZE, scale_bounds=DEFAULT_SCALE_BOUNDS,
                     mean_ratio_min: float = MEAN_RATIO_MIN, mass_period_s=None) -> GroundSuite:
    """Select ``suite_size`` motions from ``candidates`` and amplitude-scale them to ``target``.

    Parameters
    ----------
    candidates : sequence of Motion
        E.g. :func:`read_records_folder`.
    target : callable
        Sa [g] of the target at an array of periods [s] (``DesignSpectrum.design_g``, a
        UHS's ``target_g``); an object with ``max_period_s`` limits the range.
    periods_s : array_like
        The periods that matter [s] (building's first modes, items' own): the range is
        :func:`period_range_s` of them.
    level : str
        The level's name, for the tables.
    suite_size : int
    scale_bounds : (float, float)
    mean_ratio_min : float
    mass_period_s : float, optional
        See :func:`period_range_s`.

    Raises
    ------
    ValueError
        Fewer candidates than ``suite_size``; a range beyond the target's periods.
    """
    lower, upper, max_period, clipped, grid, log_target, spectra, log_factor, chosen = _selected(
        candidates, target, periods_s, suite_size, scale_bounds, mass_period_s)
    low, high = scale_bounds
    factors = np.exp(log_factor[chosen])
    mean = (spectra[chosen] * factors[:, None]).mean(axis=0)
    ratio = mean / np.exp(log_target)
    common = max(1.0, mean_ratio_min / float(ratio.min()))
    if common > high:  # the records, each scaled within the bounds, stay far below the target
        raise ValueError(f"the selected records, each scaled at most {high:g} times, reach only "
                         f"{float(ratio.min()):.2g} of the target spectrum somewhere in {lower:.3g}-{upper:.3g} s; "
                         f"a common factor of {common:.3g} would be needed (records this weak are not of this "
                         "site's hazard)")
    factors = factors * common
    notes = [f"{suite_size} of {len(candidates)} motions selected by least log misfit after scaling over "
             f"{lower:.3g}-{upper:.3g} s (ASCE 7-22 §16.2.3.1: 0.2 T_min to 2 T_max)"]
    cautions = [clipped] if clipped else []
    if common > 1.0:
        notes.append(f"common factor {common:.3f} so that the suite's mean is at least {mean_ratio_min:.0%} of the "
                     "target over the range (ASCE 7-22 §16.2.3.2)")
    outside = [candidates[k].name for k, f in zip(chosen, factors) if not (low * (1 - 1e-9) <= f <= high * (1 + 1e-9))]
    if outside:
        one = len(outside) == 1
        cautions.append(f"{len(outside)} motion{'' if one else 's'} ({_first_names(outside)}) "
                        f"{'is' if one else 'are'} scaled "
                        f"beyond {low:g}-{high:g} by the common factor (ground_motions.csv's scale_factor): records "
                        "nearer the target's level in the records folder would need less")
    motions = tuple(candidates[k].scaled(float(f)) for k, f in zip(chosen, factors))
    cautions += amplitude_cautions(motions, target, grid, ratio * common, common_factor=common)
    min_ratio = float(ratio.min() * common)
    scaled_ln = np.log(spectra[chosen]) + np.log(factors)[:, None] - log_target[None, :]
    ground, spectrum = _tables(level, motions, factors, target, lower, upper, max_period,
                               np.sqrt(np.mean(scaled_ln ** 2, axis=1)), np.max(np.abs(np.expm1(scaled_ln)), axis=1),
                               [None] * len(chosen))
    return GroundSuite(level, "records", motions, factors, lower, upper, min_ratio, ground, spectrum,
                       tuple(notes + cautions), tuple(cautions))


# --------------------------------------------------------------------------- synthetic motions

def motion_seed(index: int, base_seed: int = 0) -> int:
    """Seed [0, 2⁶³) of synthetic motion ``index``: a hash of (base seed, index).

    The seed does not depend on the level, the site's values or the items: motion k of every level and
    every hazard value of a site starts from the same realisation (common random numbers), so that two
    levels differ only by their targets, and the same index gives the same history on every run,
    machine and worker.

    >>> motion_seed(0) == motion_seed(0) != motion_seed(1) != motion_seed(1, base_seed=1)
    True
    """
    digest = hashlib.sha256(f"assess-ground-suite|{int(base_seed)}|{int(index)}".encode()).digest()
    return int.from_bytes(digest[:8], "big") >> 1


#: Significant duration D5-95 [s] of the synthetic motions' stochastic model, and its filter's
#: rate of change of frequency [Hz/s]: a 20 s strong phase of constant predominant frequency.
#: Why not the model's sample means (about 10 s and -0.1 Hz/s): the Fourier scaling matches a
#: motion's spectrum far more closely when the strong phase holds more cycles (measured over 6 seeds
#: for SDS 1.0 g, SD1 0.6 g, 0.07-2.8 s: within 10 % after 30 passes for 3 of 6 at 10-12 s and
#: -0.1 Hz/s, 5 of 6 at 20 s and 0 Hz/s). The longer strong phase is a conservative choice for the
#: items' sliding (more cycles).
SYNTHETIC_D5_95_S = 20.0
SYNTHETIC_FILTER_SLOPE_HZ_S = 0.0
#: Fourier-scaling passes of one motion's matching (the best pass is kept).
MATCH_PASSES = 40


def _realisation_g(seed: int, dt_s: float, d5_95_s: float) -> np.ndarray:
    """Motion ``seed``'s realisation of the stochastic model [g], before matching (:func:`synthetic_motion`)."""
    duration_s = 2.5 * d5_95_s + 5.0
    n = int(round(duration_s / dt_s)) + 1
    quiet = int(round((duration_s - 5.0) / dt_s))
    residual = rezaeian_residual(n, dt_s, 1.0, d5_95_s, 0.45 * d5_95_s, np.random.default_rng(seed),
                                 high_pass_hz=None, f_slope_hz_s=SYNTHETIC_FILTER_SLOPE_HZ_S)
    accel_g = residual / STANDARD_GRAVITY_M_S2
    accel_g[quiet:] = 0.0
    return accel_g


#: Matched motions of this process by (seed, step, D5-95, range, target shape): a level whose target is
#: another's times a constant (ASCE 7's DE is 2/3 of MCE_R) is the other's motions times that constant.
_MATCHED: dict = {}
_MATCHED_MAX = 4096


def _unit_target(target: Callable, lower_s: float, upper_s: float):
    """``target``'s shape over [lower_s, upper_s] at unit amplitude, what a motion is matched to before it is scaled
    to the target's (so that two levels whose targets differ by a factor get motions that differ by it): the unit
    target (a callable with ``max_period_s``), the amplitude [g] (the target's largest Sa on 64 log-spaced periods
    of the range) and the unit shape on those periods.

    Raises ValueError where the target is not positive over the range."""
    band = np.geomspace(lower_s, upper_s, 64)
    shape = np.asarray(target(band), dtype=float)
    if np.any(~np.isfinite(shape)) or np.any(shape <= 0):
        raise ValueError(f"the target spectrum is not positive over {lower_s:.3g}-{upper_s:.3g} s")
    amplitude = float(shape.max())

    def unit_target(period_s):
        return np.asarray(target(period_s), dtype=float) / amplitude
    unit_target.max_period_s = getattr(target, "max_period_s", np.inf)
    return unit_target, amplitude, shape / amplitude


def _fit(motions: Sequence[Motion], target: Callable, grid):
    """A suite's spectra against ``target`` on ``grid``: the mean over the target there, and each motion's root mean
    square of ln(Sa/target)."""
    spectra = np.array([m.spectrum_g(grid) for m in motions])
    target_grid = np.asarray(target(grid), dtype=float)
    return spectra.mean(axis=0) / target_grid, np.sqrt(np.mean(np.log(spectra / target_grid) ** 2, axis=1))


def synthetic_motion(target: Callable, lower_s: float, upper_s: float, seed: int, *, dt_s: float = 0.005,
                     d5_95_s: float = SYNTHETIC_D5_95_S, tolerance: float = SYNTHETIC_TOLERANCE,
                     name: str = "synthetic") -> tuple[Record, float]:
    """One spectrum-compatible ground motion: motion ``seed``'s realisation of the Rezaeian & Der
    Kiureghian (2008) model matched to ``target`` over [lower_s, upper_s] (:func:`match_spectrum`).

    The stochastic model (:func:`assess.hazard.synthesis.rezaeian_residual`): filter frequency
    5 Hz, :data:`SYNTHETIC_FILTER_SLOPE_HZ_S`, damping 0.2; D5-95 = ``d5_95_s``,
    t_mid = 0.45 D5-95 (the envelope rises from t = 0); no high-pass (the matching's baseline
    correction takes its place); the amplitude is set by the matching. The record lasts
    2.5 D5-95 + 5 s and its last 5 s start at rest (so the Fourier passes do not wrap the strong
    motion round).

    One realisation per seed, whatever the target: the matching stops once the spectrum is within
    0.9 ``tolerance`` on the dense check (a margin for dips between its periods), else keeps its best
    of :data:`MATCH_PASSES` passes, and the motion is returned with its largest deviation either way
    (never another realisation: drawing until one fits would make the suite depend on the target's
    values, and a level's answer on unrelated motions). The matching is homogeneous (a target times c
    gives the motion times c), so it is done once per target shape and scaled.

    Returns
    -------
    (Record, float)
        The motion [g] and its largest |Sa/target − 1| over the range.
    """
    unit_target, amplitude, unit_shape = _unit_target(target, lower_s, upper_s)
    key = (int(seed), float(dt_s), float(d5_95_s), float(lower_s), float(upper_s), float(tolerance),
           tuple(np.round(unit_shape, 12)))
    if key not in _MATCHED:
        if len(_MATCHED) >= _MATCHED_MAX:
            _MATCHED.clear()
        _MATCHED[key] = match_spectrum(_realisation_g(seed, dt_s, d5_95_s), dt_s, unit_target, lower_s, upper_s,
                                       tolerance=0.9 * tolerance, max_iterations=MATCH_PASSES)
    matched, error = _MATCHED[key]
    return Record(matched * amplitude, dt_s, name), float(error)


def synthetic_suite(target: Callable, periods_s, *, level: str, suite_size: int = SYNTHETIC_SUITE_SIZE,
                    base_seed: int = 0, dt_s: float = 0.005, tolerance: float = SYNTHETIC_TOLERANCE,
                    mass_period_s=None, progress: Callable | None = None) -> GroundSuite:
    """``suite_size`` spectrum-compatible synthetic motions for ``target`` (see the module docstring).

    Motion k is seeded by :func:`motion_seed` (k, ``base_seed``): the same realisations for every level.
    The suite is never refused for its match: each motion's largest deviation from the target over the
    range is in ``ground_motions.csv`` (``max_deviation``), and the notes say how many are beyond ``tolerance``
    and the suite's mean against the target (ASCE 7-22 §16.2.3.3 asks a matched suite's mean to be at
    least 90 % of the target over the range).

    Raises
    ------
    ValueError
        The target gives no spectrum over the range (a UHS that ends below its lower end).
    """
    lower, upper = period_range_s(periods_s, mass_period_s=mass_period_s,
                                  min_period_s=max(MIN_PERIOD_S, MIN_STEPS_PER_CYCLE * dt_s))
    lower, upper, max_period, clipped = _within_target(target, lower, upper)
    motions, seeds, errors = [], [], []
    for index in range(suite_size):
        seed = motion_seed(index, base_seed)
        record, error = synthetic_motion(target, lower, upper, seed, dt_s=dt_s, tolerance=tolerance,
                                         name=f"{level} synthetic {index + 1}")
        motions.append(Motion(record.name, record, None, "synthetic", seed))
        seeds.append(seed)
        errors.append(error)
        if progress is not None:
            progress(index + 1, suite_size)
    factors = np.ones(suite_size)
    grid = check_periods_s(lower, upper)
    ratio, misfit_ln = _fit(motions, target, grid)
    errors = np.array(errors)
    ground, spectrum = _tables(level, motions, factors, target, lower, upper, max_period, misfit_ln, errors, seeds)
    notes = [f"{suite_size} synthetic motions (Rezaeian & Der Kiureghian 2008 model, matched by iterative "
             f"Fourier scaling) over {lower:.3g}-{upper:.3g} s: each within {errors.max():.1%} of the target "
             f"(median {np.median(errors):.1%}); the suite's mean within {ratio.min():.1%}-{ratio.max():.1%} "
             "of it"]
    beyond = int(np.sum(errors > tolerance))
    if beyond:
        one = beyond == 1
        notes.append(f"{beyond} of the {suite_size} motions deviate{'s' if one else ''} from the target by more than "
                     f"{tolerance:.0%} somewhere in the range (at most {errors.max():.1%}): the closest match of "
                     f"{'its' if one else 'their'} one realisation, kept so that every level and hazard value uses "
                     "the same realisations")
    cautions = matched_suite_cautions(motions, target, grid, ratio, clipped)
    return GroundSuite(level, "synthetic", tuple(motions), factors, lower, upper, float(ratio.min()), ground,
                       spectrum, tuple(notes + cautions), tuple(cautions))


def matched_records(candidates: Sequence[Motion], target: Callable, periods_s, *, level: str,
                    suite_size: int = DEFAULT_SUITE_SIZE, tolerance: float = SYNTHETIC_TOLERANCE,
                    mass_period_s=None) -> GroundSuite:
    """``suite_size`` records of ``candidates``, selected as :func:`select_and_scale` selects them, each matched to
    ``target`` over the range instead of scaled (ASCE 7-22 §16.2.3.3, spectral matching): its Fourier amplitudes
    scaled pass by pass as a synthetic motion's are (:func:`assess.site.matching.match_spectrum`; a pair's both
    components by the gain of its RotD100, :func:`assess.site.matching.match_pair`), its phases, so its
    duration, pulses and the order of its cycles, kept.

    What it is for: one factor per record leaves a suite's mean as far above the target as the records are
    shaped unlike it, wherever its weakest period has to be lifted to 90 % (:func:`amplitude_cautions`); a
    matched suite's mean is the target's. A record is matched to the target's shape over the range at unit
    amplitude, then scaled to the target's (as :func:`synthetic_motion`): the motions of two levels whose targets
    differ by a factor (ASCE 7's DE and MCE_R) differ by that factor exactly. A record is never refused for its
    match: each one's largest deviation is in ground_motions.csv (``max_deviation``), those beyond
    ``tolerance`` are counted in the notes; its ``scale_factor`` is 1.

    Raises
    ------
    ValueError
        As :func:`select_and_scale`: fewer candidates than ``suite_size``, a range beyond the target's periods.
    """
    lower, upper, max_period, clipped, grid, _, _, _, chosen = _selected(
        candidates, target, periods_s, suite_size, DEFAULT_SCALE_BOUNDS, mass_period_s)
    unit_target, amplitude, _ = _unit_target(target, lower, upper)
    motions, errors = [], []
    for k in chosen:
        motion = candidates[k]
        dt_s = motion.first.dt_s
        if motion.second is None:
            accel, error = match_spectrum(motion.first.accel_g, dt_s, unit_target, lower, upper,
                                          tolerance=0.9 * tolerance, max_iterations=MATCH_PASSES)
            second = None
        else:
            (accel, other), error = match_pair(motion.first.accel_g, motion.second.accel_g, dt_s, unit_target,
                                               lower, upper, tolerance=0.9 * tolerance, max_iterations=MATCH_PASSES)
            second = Record(other * amplitude, dt_s, motion.second.name)
        motions.append(Motion(motion.name, Record(accel * amplitude, dt_s, motion.first.name), second,
                              motion.source, None))
        errors.append(error)
    errors = np.array(errors)
    ratio, misfit_ln = _fit(motions, target, grid)
    ground, spectrum = _tables(level, motions, np.ones(len(motions)), target, lower, upper, max_period, misfit_ln,
                               errors, [None] * len(motions))
    notes = [f"{suite_size} of {len(candidates)} records selected by least log misfit over {lower:.3g}-{upper:.3g} s "
             "and each matched to the target (its Fourier amplitudes scaled, its phases kept; a pair by its "
             f"RotD100): each within {errors.max():.1%} of it (median {np.median(errors):.1%}); the suite's mean "
             f"within {ratio.min():.1%}-{ratio.max():.1%} of it"]
    beyond = [m.name for m, e in zip(motions, errors) if e > tolerance]
    if beyond:
        notes.append(f"{len(beyond)} of the {suite_size} records deviate{'s' if len(beyond) == 1 else ''} from the "
                     f"target by more than {tolerance:.0%} somewhere in the range (at most {errors.max():.1%}): "
                     f"{_first_names(beyond)}, their closest match")
    cautions = matched_suite_cautions(motions, target, grid, ratio, clipped)
    return GroundSuite(level, "matched records", tuple(motions), np.ones(len(motions)), lower, upper,
                       float(ratio.min()), ground, spectrum, tuple(notes + cautions), tuple(cautions))


def ground_suite(target: Callable, periods_s, *, level: str, records_folder=None, workbook_folder=None,
                 suite_size: int | None = None, base_seed: int = 0, mass_period_s=None,
                 progress: Callable | None = None, records_scaling: str = "amplitude") -> GroundSuite:
    """A level's ground suite: selected from ``records_folder`` and scaled to the target (``records_scaling``
    ``amplitude``, :func:`select_and_scale`) or matched to it (``matched``, :func:`matched_records`), or
    synthetic without it.

    Raises InputError for the folder and its records (:func:`read_records_folder`), ValueError
    when the suite cannot be made (fewer records than ``suite_size``, a target that gives no spectrum
    over the range): the caller names the cell of the cause (the records folder, the ``uhs`` file).
    A synthetic suite is never refused for its match (:func:`synthetic_suite`).
    """
    if records_folder is not None:
        choose = matched_records if records_scaling == "matched" else select_and_scale
        return choose(read_records_folder(records_folder, workbook_folder=workbook_folder), target, periods_s,
                      level=level, suite_size=suite_size or DEFAULT_SUITE_SIZE, mass_period_s=mass_period_s)
    return synthetic_suite(target, periods_s, level=level, suite_size=suite_size or SYNTHETIC_SUITE_SIZE,
                           base_seed=base_seed,
                           mass_period_s=mass_period_s, progress=progress)
