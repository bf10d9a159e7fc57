"""OpenQuake engine hazard curves and hazard maps (CSV) -> PGA at a hazard level.

Reads the two CSV exports of the OpenQuake engine's classical and event-based
calculators that give the peak ground acceleration of a site at a hazard level
(``--oq-hazard``, docs/commands.md):

* a **hazard curve**, ``hazard_curve-<kind>-PGA_<calc_id>.csv``::

    #,,,,,"generated_by='OpenQuake engine 3.18.0', start_date='...', checksum=..., kind='mean', investigation_time=1.0, imt='PGA'"
    lon,lat,depth,poe-0.1000000,poe-0.4000000,poe-0.6000000
    0.00000,0.00000,-0.10000,4.553860E-01,5.754042E-02,6.354511E-03

  one row per site: the probability that PGA exceeds each level [g] during the
  investigation time;

* a **hazard map**, ``hazard_map-<kind>_<calc_id>.csv``::

    #,,,,"generated_by='OpenQuake engine 3.18.0', ..., kind='mean', investigation_time=1.0"
    lon,lat,PGA-0.002105,SA(0.2)-0.002105,SA(1.0)-0.002105
    -123.23738,49.27479,3.023730E-03,1.227876E-02,1.304533E-02

  one row per site: the intensity [g] exceeded with probability ``<poe>`` in
  the investigation time.

Format details (gem/oq-engine): the comment row is written by
``openquake/baselib/writers.py::write_csv`` as ``['#'] + [''] * (n - 2) +
[comment]`` where ``comment = ', '.join('%s=%r' % item ...)``, so values are
Python reprs and may hold commas inside quotes or brackets; engines before
about 3.7 wrote ``# key=value, ...`` (or ``# mean, investigation_time=50.0``)
instead, and both are read. Curve columns are ``poe-%.7f`` of the level
(``openquake/calculators/export/hazard.py::export_hcurves_by_imt_csv``), map
columns ``'%s-%s' % (imt, poe)`` (``OqParam.hmap_dt``); a ``custom_site_id``
column may come first and maps carry ``depth`` only off sea level. PGA is in g.

Only PGA is used; other IMT columns of a map are ignored (with a note). A file
with several sites needs the site chosen: ``site=(lon, lat)``, a 0-based row
index (OpenQuake's site order) or a ``custom_site_id``.

Every problem raises :class:`~assess.errors.InputError` naming the file, the
line (``row``) and the column.
"""
from __future__ import annotations

import csv
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from assess.errors import InputError, Problem
from assess.hazard.levels import HazardLevel

#: The intensity measure this module returns.
PGA = "PGA"
#: Columns that locate a site rather than carry hazard values.
SITE_COLUMNS = ("custom_site_id", "lon", "lat", "depth")
#: Two rates of exceedance name the same level when they agree to this (as
#: :meth:`HazardLevel.same_as`).
RATE_REL_TOL = 0.01
#: A site given as (lon, lat) matches a row within this many degrees (the file
#: writes 5 decimals, ~1 m).
SITE_TOL_DEG = 1e-4
#: A poe may rise along the curve by this relative amount before the curve is
#: called non-monotone: the file rounds to 7 significant digits.
POE_RISE_REL_TOL = 1e-5
#: Plausible PGA levels of a curve's columns and values of a map [g]: OpenQuake's own demos and
#: the published regional models sample PGA between about 1e-3 g and 5 g. Outside these
#: bounds a level is taken for an edited or damaged file (1e-298 g would make everything low).
MIN_PLAUSIBLE_PGA_G = 1e-5
MAX_PLAUSIBLE_PGA_G = 10.0
#: Text from the file is quoted in a message only when it looks like a header or a number.
_QUOTABLE = re.compile(r"[A-Za-z0-9_.+\-()~/ ]{1,40}")
_MAX_LISTED_SITES = 12
_MAX_PROBLEMS = 20
_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_CURVE_COLUMN = re.compile(rf"^poe-(?P<iml>{_NUMBER})$")
_MAP_COLUMN = re.compile(r"^(?P<imt>.+?)-(?P<poe>(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)$")
_KIND = re.compile(r"^(mean|max|std|rlz-\d+|quantile-[\d.]+)$")
_OPEN, _CLOSE = "([{", ")]}"


@dataclass(frozen=True)
class Site:
    """One site (row) of an OpenQuake export."""

    index: int  # 0-based row order, OpenQuake's site order
    lon: float  # [deg]
    lat: float  # [deg]
    depth_km: float | None  # [km], None when the file has no depth column
    custom_site_id: str | None
    line: int  # line of the file holding this site (1 = comment line)

    def label(self) -> str:
        text = f"#{self.index} (lon {self.lon:.5f}, lat {self.lat:.5f})"
        return f"{text} '{self.custom_site_id}'" if self.custom_site_id else text


@dataclass(frozen=True, eq=False)
class OpenQuakeHazard:
    """PGA hazard read from an OpenQuake hazard-curve or hazard-map CSV.

    Attributes
    ----------
    path : str
        The file read.
    kind : str
        ``"curve"`` or ``"map"``.
    investigation_time_yr : float
        Time [yr] the file's probabilities of exceedance refer to.
    imt : str
        Always ``"PGA"``.
    statistic : str or None
        OpenQuake's ``kind``: ``mean``, ``rlz-000``, ``quantile-0.85`` ...
    sites : tuple of Site
        Every site of the file, in its order.
    site_index : int
        The site :func:`pga_at_level` uses.
    levels_g : ndarray or None
        Curve: PGA levels [g], increasing.
    poes : ndarray or None
        Curve: probabilities of exceedance in the investigation time, shape
        (sites, levels), made non-increasing along the levels.
    map_poes : ndarray or None
        Map: the probabilities of exceedance of the PGA columns.
    map_values_g : ndarray or None
        Map: PGA [g], shape (sites, map poes).
    metadata : dict
        The comment line's ``key=value`` pairs, unquoted.
    notes : tuple of str
        What was ignored or assumed (other IMTs, realization instead of mean).
    annual_rates : ndarray or None
        Curve: annual rates of exceedance [1/yr], shape (sites, levels), where
        the file gives rates rather than probabilities (a USGS nshmp-haz curve,
        :mod:`assess.hazard.usgs`); ``poes`` then holds their one-year Poisson
        probabilities. None for an OpenQuake file.
    source : str
        The program that wrote the file, as a user reads it: ``OpenQuake`` or
        ``USGS nshmp-haz``.
    """

    path: str
    kind: str
    investigation_time_yr: float
    imt: str
    statistic: str | None
    sites: tuple[Site, ...]
    site_index: int
    levels_g: np.ndarray | None = None
    poes: np.ndarray | None = None
    map_poes: np.ndarray | None = None
    map_values_g: np.ndarray | None = None
    metadata: dict[str, str] = field(default_factory=dict)
    notes: tuple[str, ...] = ()
    annual_rates: np.ndarray | None = None
    source: str = "OpenQuake"

    @property
    def site(self) -> Site:
        return self.sites[self.site_index]


# --------------------------------------------------------------------------- physics


def poe_in_investigation_time(level: HazardLevel, investigation_time_yr: float) -> float:
    """Probability that a level is exceeded in another time window (Poisson).

    .. math::  P_{inv} = 1 - \\exp(-t_{inv} / T_R)

    with :math:`T_R` the level's mean return period [yr] and :math:`t_{inv}`
    the investigation time [yr] of the hazard file. Poisson occurrence is the
    assumption OpenQuake's classical calculator makes for time-independent
    sources.

    >>> from assess.hazard.levels import HazardLevel
    >>> round(poe_in_investigation_time(HazardLevel(0.02, 50.0), 50.0), 12)
    0.02
    >>> round(poe_in_investigation_time(HazardLevel(0.02, 50.0), 1.0), 7)  # not 0.02/50
    0.000404
    """
    return -math.expm1(-investigation_time_yr / level.return_period_yr)


def annual_rate_of_poe(poe: float, investigation_time_yr: float) -> float:
    """Mean annual rate [1/yr] of a probability ``poe`` in ``investigation_time_yr`` (Poisson).

    .. math::  \\lambda = -\\ln(1 - P) / t_{inv}
    """
    return -math.log1p(-poe) / investigation_time_yr


def loglog_interpolate_level(levels_g, poes, poe: float) -> float:
    """Level [g] exceeded with probability ``poe``, by log–log interpolation of a curve.

    Between the two levels that bracket ``poe`` (``poes`` non-increasing with
    ``levels_g``), :math:`\\ln x` is linear in :math:`\\ln P`:

    .. math::

        \\ln x = \\ln x_j + (\\ln P - \\ln P_j)
                 \\frac{\\ln x_{j+1} - \\ln x_j}{\\ln P_{j+1} - \\ln P_j}

    as OpenQuake builds its own hazard maps
    (``openquake/commonlib/calc.py::compute_hazard_maps``: "exp-log
    interpolation"). Unlike OpenQuake, which returns 0 above the curve and
    clamps to the top level below it, this raises ``ValueError`` when ``poe``
    lies outside [smallest non-zero poe, largest poe].

    >>> round(loglog_interpolate_level([0.1, 0.4], [0.1, 0.001], 0.01), 6)  # sqrt(0.1*0.4)
    0.2
    """
    levels = np.asarray(levels_g, dtype=float)
    probs = np.asarray(poes, dtype=float)
    positive = probs[probs > 0.0]
    if positive.size == 0 or not (positive.min() <= poe <= probs[0]):
        raise ValueError(f"poe {poe:g} outside the curve's range")
    j = int(np.flatnonzero(probs >= poe)[-1])
    if probs[j] == poe:
        return float(levels[j])
    slope = (math.log(levels[j + 1]) - math.log(levels[j])) / (
        math.log(probs[j + 1]) - math.log(probs[j]))
    return float(math.exp(math.log(levels[j]) + (math.log(poe) - math.log(probs[j])) * slope))


# --------------------------------------------------------------------------- reading


def parse_openquake_comment(text: str) -> dict[str, str]:
    """``key=value`` pairs of an OpenQuake comment line, values unquoted.

    Commas inside quotes or brackets do not split (``imls=[0.99, 0.61]``,
    ``source_model_tree_path=('b11',)``). A bare word such as the ``mean`` of
    ``# mean, investigation_time=50.0`` (older engines) is kept as ``kind``.

    >>> parse_openquake_comment("generated_by='OpenQuake engine 3.18.0', kind='mean', "
    ...                         "investigation_time=1.0, imls=[0.9, 0.6]")["imls"]
    '[0.9, 0.6]'
    """
    text = text.strip()
    if text.startswith("#"):
        text = text[1:]
    tokens, current, quote, depth = [], [], None, 0
    for char in text:
        if quote:
            quote = None if char == quote else quote
        elif char in "'\"":
            quote = char
        elif char in _OPEN:
            depth += 1
        elif char in _CLOSE:
            depth = max(depth - 1, 0)
        elif char == "," and depth == 0:
            tokens.append("".join(current))
            current = []
            continue
        current.append(char)
    tokens.append("".join(current))
    pairs: dict[str, str] = {}
    for token in (t.strip() for t in tokens):
        if not token:
            continue
        key, sep, value = token.partition("=")
        if not sep or not re.fullmatch(r"[A-Za-z_][\w.]*", key.strip()):
            if _KIND.match(token) and "kind" not in pairs:
                pairs["kind"] = token
            continue
        value = value.strip()
        if len(value) >= 2 and value[0] == value[-1] and value[0] in "'\"":
            value = value[1:-1]
        pairs.setdefault(key.strip(), value)
    return pairs


def _comment_text(line: str) -> str:
    """The metadata text of a comment line, new (``#,,,"..."``) or old (``# ...``) style."""
    cells = next(csv.reader([line.strip()]))
    if cells and cells[0].strip() == "#" and len(cells) > 1:
        return ", ".join(c.strip() for c in cells[1:] if c.strip())
    return line.strip()[1:]


def _shown(text: str, quote: str = "'") -> str:
    """``text`` of the file quoted, if it looks like a header name or a number; else only its length.

    Messages never echo what a file holds beyond that (a file that is not a
    hazard curve may be anything, /etc/passwd or the environment).

    >>> _shown("poe-0.1"), _shown("root:x:0:0:root:/root:/bin/bash")
    ("'poe-0.1'", '(a text of 31 characters, not shown)')
    """
    text = str(text)
    if _QUOTABLE.fullmatch(text):
        return f"{quote}{text}{quote}"
    return f"(a text of {len(text)} characters, not shown)"


def _fail(path, message, fix, line=None, column=None) -> InputError:
    return InputError([Problem(file=str(path), message=message, fix=fix, row=line,
                               column=column)])


_NOT_OQ_FIX = ("give the hazard curve (hazard_curve-mean-PGA_<calc_id>.csv) or hazard map "
               "(hazard_map-mean_<calc_id>.csv) exported by 'oq engine --export-outputs', "
               "unchanged.")


def export_lines(lines) -> tuple[list, list | None, int | None, list]:
    """An OpenQuake CSV export's lines split into its ``#`` comment lines (before the header), its header
    (stripped names; None when there is none), the header's line number and its rows as
    ``(line number, cells)``; blank lines are skipped.

    >>> export_lines(["#,,'kind=mean'", "", "lon,lat, poe-0.1", "1,2,0.5"])
    (["#,,'kind=mean'"], ['lon', 'lat', 'poe-0.1'], 3, [(4, ['1', '2', '0.5'])])
    """
    comments, header, header_line, rows = [], None, None, []
    for number, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        if header is None and line.lstrip().startswith("#"):
            comments.append(line)
            continue
        if header is None:
            header, header_line = [c.strip() for c in next(csv.reader([line]))], number
        else:
            rows.append((number, next(csv.reader([line]))))
    return comments, header, header_line, rows


def read_openquake_hazard(path, site=None) -> OpenQuakeHazard:
    """Read an OpenQuake hazard-curve or hazard-map CSV for PGA.

    Parameters
    ----------
    path : str or Path
        The CSV as exported by the engine (comment line included).
    site : None, int, str or (lon, lat)
        Which site to use when the file holds several: a 0-based row index, a
        ``custom_site_id``, or coordinates [deg] matched within
        :data:`SITE_TOL_DEG`. May be omitted for a one-site file.

    Raises
    ------
    InputError
        Missing file; not an OpenQuake curve or map; no PGA; no or a bad
        ``investigation_time``; a cell that is not a number; a non-monotone
        curve; several sites and none chosen, or a chosen site not in the file.
    """
    path = Path(path)
    if not path.is_file():
        raise _fail(path, "the OpenQuake hazard file does not exist.",
                    "check the path given to --oq-hazard.")
    lines = path.read_text(encoding="utf-8-sig", errors="replace").splitlines()

    comments, header, header_line, rows = export_lines(lines)
    if header is None:
        raise _fail(path, "the file is empty: no header line.", _NOT_OQ_FIX)

    metadata: dict[str, str] = {}
    for line in comments:
        for key, value in parse_openquake_comment(_comment_text(line)).items():
            metadata.setdefault(key, value)

    layout = _layout(path, header, header_line, metadata)
    investigation_time = _investigation_time(path, metadata, bool(comments))
    sites, values = _rows(path, header, rows, layout)
    notes = list(layout["notes"])
    statistic = metadata.get("kind")
    if statistic and statistic != "mean":
        notes.append(f"the file holds '{statistic}', not the mean hazard.")

    if layout["kind"] == "curve":
        levels = np.array(layout["numbers"])
        poes = _monotone_curves(path, sites, values, [header[i] for i in layout["value_cols"]],
                                levels)
        hazard = dict(levels_g=levels, poes=poes)
    else:
        hazard = dict(map_poes=np.array(layout["numbers"]), map_values_g=values)
    index = _choose_site(path, sites, site)
    return OpenQuakeHazard(path=str(path), kind=layout["kind"],
                           investigation_time_yr=investigation_time, imt=PGA,
                           statistic=statistic, sites=tuple(sites), site_index=index,
                           metadata=metadata, notes=tuple(notes), **hazard)


def _layout(path, header, line, metadata) -> dict:
    """Which columns hold what: curve (``poe-<IML>``) or map (``<IMT>-<poe>``)."""
    if "lon" not in header or "lat" not in header:
        raise _fail(path, f"this is not an OpenQuake hazard curve or map: line {line} should be the header "
                    "'lon,lat,...' followed by columns 'poe-<PGA level>' (curve) or 'PGA-<poe>' (map), and "
                    f"it has no lon and lat columns (it has {len(header)} field(s)).", _NOT_OQ_FIX, line=line)
    data_cols = [i for i, name in enumerate(header) if name not in SITE_COLUMNS]
    if not data_cols:
        raise _fail(path, "the header has site columns but no hazard columns.", _NOT_OQ_FIX,
                    line=line)
    names = [header[i] for i in data_cols]
    if any("~" in name for name in names):
        raise _fail(path, "this is a uniform hazard spectrum (columns '<poe>~<IMT>'), not a "
                    "hazard curve or map.", _NOT_OQ_FIX, line=line)
    curve = [_CURVE_COLUMN.match(name) for name in names]
    if all(curve):
        return _curve_layout(path, header, line, metadata, data_cols, curve)
    maps = [_MAP_COLUMN.match(name) for name in names]
    for name, is_curve, is_map in zip(names, curve, maps):
        if is_curve or not is_map or is_map["imt"] == "poe":
            raise _fail(path, f"column {_shown(name)} is neither a hazard-curve column 'poe-<level>' "
                        "nor a hazard-map column '<IMT>-<poe>' (or the file mixes both).",
                        _NOT_OQ_FIX, line=line, column=name if _QUOTABLE.fullmatch(name) else None)
    return _map_layout(path, line, data_cols, names, maps)


def _curve_layout(path, header, line, metadata, data_cols, matches) -> dict:
    imt = metadata.get("imt")
    notes = []
    if imt is None:
        if not re.search(r"(?:^|[-_])PGA(?:[-_.]|$)", path.name):
            raise _fail(path, "the hazard curve does not say its intensity measure: the comment "
                        "line has no imt=... and the file name names none.",
                        "give the curve file exported for PGA (hazard_curve-mean-PGA_<id>.csv) "
                        "with its first comment line.", line=1)
        imt = PGA
        notes.append("the intensity measure (PGA) was taken from the file name.")
    if imt != PGA:
        raise _fail(path, f"this hazard curve is for {_shown(imt, '')}, not PGA.",
                    "give the PGA curve of the same calculation (hazard_curve-mean-PGA_<id>.csv); "
                    "if there is none, add PGA to intensity_measure_types_and_levels and rerun.",
                    line=1)
    levels = [float(m["iml"]) for m in matches]
    for k, level in enumerate(levels):
        if not MIN_PLAUSIBLE_PGA_G <= level <= MAX_PLAUSIBLE_PGA_G:
            raise _fail(path, f"the PGA level of column '{header[data_cols[k]]}' is {level:g} g, outside "
                        f"{MIN_PLAUSIBLE_PGA_G:g} to {MAX_PLAUSIBLE_PGA_G:g} g, the levels a PGA hazard curve "
                        "samples: the file was edited or damaged.",
                        "give the curve as exported by OpenQuake (its levels are the imls of the job.ini's "
                        "intensity_measure_types_and_levels).", line=line, column=header[data_cols[k]])
        if k and level <= levels[k - 1]:
            raise _fail(path, f"the PGA levels must be positive and increase from column to "
                        f"column; '{header[data_cols[k]]}' does not.",
                        "give the curve as exported by OpenQuake.", line=line,
                        column=header[data_cols[k]])
    return dict(kind="curve", value_cols=data_cols, numbers=levels, notes=notes)


def _map_layout(path, line, data_cols, names, matches) -> dict:
    keep = [(i, float(m["poe"])) for i, m in zip(data_cols, matches) if m["imt"] == PGA]
    others = sorted({_shown(m["imt"], "") for m in matches if m["imt"] != PGA})
    if not keep:
        raise _fail(path, f"the hazard map has no PGA column (it has {', '.join(others)}).",
                    "add PGA to intensity_measure_types_and_levels and rerun, or give the PGA "
                    "hazard curve instead.", line=line)
    for i, poe in keep:
        if not 0.0 < poe < 1.0:
            raise _fail(path, f"column {_shown(names[data_cols.index(i)])}: a probability of exceedance "
                        "must lie between 0 and 1.", "give the map as exported by OpenQuake.",
                        line=line, column=names[data_cols.index(i)])
    notes = [f"ignored the columns of {', '.join(others)}: only PGA is used."] if others else []
    return dict(kind="map", value_cols=[i for i, _ in keep], numbers=[p for _, p in keep],
                notes=notes)


def _investigation_time(path, metadata, has_comment) -> float:
    text = metadata.get("investigation_time")
    if text is None:
        where = ("its comment line gives no investigation_time" if has_comment
                 else "the comment line OpenQuake writes first (with investigation_time) is missing")
        raise _fail(path, f"the probabilities cannot be read: {where}.",
                    "give the file as exported, with its first line "
                    "'#,...,\"..., investigation_time=50.0, ...\"' (or add "
                    "investigation_time=<years> to that line).", line=1)
    try:
        value = float(text)
    except ValueError:
        value = float("nan")
    if not (math.isfinite(value) and value > 0.0):
        raise _fail(path, f"investigation_time={_shown(text)} is not a positive number of years.",
                    "give the file as exported by a classical or event-based calculation.", line=1)
    return value


def _rows(path, header, rows, layout):
    """Sites and the hazard values of the kept columns; every bad cell is reported."""
    col = {name: header.index(name) for name in SITE_COLUMNS if name in header}
    value_cols = layout["value_cols"]
    problems: list[Problem] = []
    sites, values = [], []

    def number(cells, i, line):
        text = cells[i].strip() if i < len(cells) else ""
        try:
            x = float(text)
        except ValueError:
            x = float("nan")
        if not math.isfinite(x):
            problems.append(Problem(file=str(path), message=f"{_shown(text)} is not a number.",
                                    fix="give the file as exported by OpenQuake.", row=line,
                                    column=header[i] if _QUOTABLE.fullmatch(header[i]) else None))
        return x

    for line, cells in rows:
        if len(cells) != len(header):
            problems.append(Problem(file=str(path), message=f"the line has {len(cells)} fields, "
                                    f"the header {len(header)}.",
                                    fix="give the file as exported by OpenQuake.", row=line))
            continue
        depth = number(cells, col["depth"], line) if "depth" in col else None
        sites.append(Site(index=len(sites), lon=number(cells, col["lon"], line),
                          lat=number(cells, col["lat"], line), depth_km=depth,
                          custom_site_id=(cells[col["custom_site_id"]].strip()
                                          if "custom_site_id" in col else None), line=line))
        values.append([number(cells, i, line) for i in value_cols])
    if problems:
        raise InputError(_capped(problems))
    if not sites:
        raise _fail(path, "the file has a header but no site rows.",
                    "give the file as exported by OpenQuake.")
    return sites, np.array(values, dtype=float)


def _capped(problems: list[Problem]) -> list[Problem]:
    if len(problems) <= _MAX_PROBLEMS:
        return problems
    rest = len(problems) - _MAX_PROBLEMS
    return problems[:_MAX_PROBLEMS] + [Problem(file=problems[0].file,
                                               message=f"... and {rest} more problems.")]


def _monotone_curves(path, sites, poes, names, levels) -> np.ndarray:
    """Check each curve: poes in [0, 1], non-increasing with the level (up to rounding)."""
    problems = []
    for site, curve in zip(sites, poes):
        bad = np.flatnonzero((curve < 0.0) | (curve > 1.0))
        if bad.size:
            k = int(bad[0])
            problems.append(Problem(file=str(path), message=f"probability of exceedance "
                                    f"{curve[k]:g} is outside 0..1.",
                                    fix="give the curve as exported by OpenQuake.",
                                    row=site.line, column=names[k]))
            continue
        rise = np.flatnonzero(np.diff(curve) > POE_RISE_REL_TOL * curve[:-1] + 1e-15)
        if rise.size:
            k = int(rise[0]) + 1
            problems.append(Problem(
                file=str(path), message=f"the hazard curve is not monotone: the probability of "
                f"exceeding {levels[k]:g} g ({curve[k]:.6E}) is larger than that of exceeding "
                f"{levels[k - 1]:g} g ({curve[k - 1]:.6E}).",
                fix="a probability of exceedance cannot grow with the level; give the curve as "
                "exported by OpenQuake, unedited.", row=site.line, column=names[k]))
    if problems:
        raise InputError(_capped(problems))
    return np.minimum.accumulate(poes, axis=1)  # flatten the 7-digit rounding noise


def _site_list(sites) -> str:
    listed = "; ".join(s.label() for s in sites[:_MAX_LISTED_SITES])
    more = len(sites) - _MAX_LISTED_SITES
    return listed + (f"; ... and {more} more" if more > 0 else "")


class SiteChoiceError(InputError):
    """The site asked for (``--oq-site``, the site sheet's ``oq_site``) is not one of the file's: raised as an
    :class:`~assess.errors.InputError` naming the file, so that a caller that knows where the choice was written
    can name that cell too (:func:`assess.site.target.level_target`)."""


#: How a site is written: a row number, ``lon,lat`` (also ``lon lat``, ``(lon, lat)``, ``[lon, lat]``) or an id.
SITE_FORMS = "lon,lat in degrees (e.g. -122.25,37.87), its row number (0 = first) or its custom_site_id"


def parse_site_choice(text):
    """A site choice as the user writes it (``--oq-site``, the site sheet's ``oq_site``): ``lon,lat`` ->
    (lon, lat), also with a space between, in parentheses or brackets; a whole number -> row index; anything else
    -> an id (OpenQuake's ``custom_site_id``, an nshmp-haz site name). None stays None.

    >>> parse_site_choice("-123.23738, 49.27479"), parse_site_choice("(-122.25, 37.87)"), parse_site_choice(2)
    ((-123.23738, 49.27479), (-122.25, 37.87), 2)
    >>> parse_site_choice("-122.3 37.9"), parse_site_choice("0"), parse_site_choice("HOSP-1")
    ((-122.3, 37.9), 0, 'HOSP-1')
    """
    if text is None:
        return None
    if isinstance(text, (int, np.integer)) and not isinstance(text, bool):
        return int(text)
    if isinstance(text, float) and text.is_integer():
        return int(text)
    value = str(text).strip()
    if re.fullmatch(r"\d+", value):
        return int(value)
    parts = [part for part in re.split(r"[,\s]+", value.strip("()[] ")) if part]
    if len(parts) == 2:
        try:
            return (float(parts[0]), float(parts[1]))
        except ValueError:
            pass
    return value


def _fail_choice(path, message, fix) -> SiteChoiceError:
    return SiteChoiceError([Problem(file=str(path), message=message, fix=fix)])


def _choose_site(path, sites, site) -> int:
    count = len(sites)
    if site is None:
        if count == 1:
            return 0
        raise _fail_choice(path, f"the file holds {count} sites: {_site_list(sites)}.",
                           f"choose the facility's site (--oq-site, or oq_site in the site sheet) as {SITE_FORMS}.")
    if isinstance(site, (int, np.integer)) and not isinstance(site, bool):
        if 0 <= site < count:
            return int(site)
        raise _fail_choice(path, f"site index {site} is not in the file, which holds {count} site(s) "
                           f"(index 0 to {count - 1}): {_site_list(sites)}.",
                           "give an index from 0 to %d." % (count - 1))
    if isinstance(site, str):
        matches = [s.index for s in sites if s.custom_site_id == site.strip()]
        if matches:
            return matches[0]
        raise _fail_choice(path, f"no site has custom_site_id '{site}'; the sites are: "
                           f"{_site_list(sites)}.", f"give one of these sites as {SITE_FORMS}.")
    try:
        lon, lat = (float(v) for v in site)
    except (TypeError, ValueError):
        raise _fail_choice(path, f"the site {site!r} is neither an index, a custom_site_id nor "
                           "lon,lat.", f"give the site as {SITE_FORMS}.") from None
    distance = [max(abs(s.lon - lon), abs(s.lat - lat)) for s in sites]
    best = int(np.argmin(distance))
    if distance[best] <= SITE_TOL_DEG:
        return best
    nearest = sorted(range(count), key=distance.__getitem__)[:3]
    raise _fail_choice(path, f"no site at lon {lon:g}, lat {lat:g} (within {SITE_TOL_DEG:g} deg); the "
                       f"nearest are {'; '.join(sites[i].label() for i in nearest)}.",
                       "give the coordinates of a site of the file, as written there.")


# --------------------------------------------------------------------------- the level


def pga_at_level(hazard: OpenQuakeHazard, level: HazardLevel) -> float:
    """PGA [g] at the chosen site for a hazard level.

    The level (probability ``P`` in ``t`` years, return period :math:`T_R`) is
    first expressed in the file's investigation time with Poisson occurrence,
    :func:`poe_in_investigation_time`. Then:

    * curve: log–log interpolation, :func:`loglog_interpolate_level`; a level
      whose probability lies outside the curve's range (above its lowest
      level's, or below its smallest non-zero one) is refused, never
      extrapolated;
    * map: the PGA column whose annual rate of exceedance matches the level's
      within :data:`RATE_REL_TOL` (1 %); otherwise refused, listing what the
      map has. A map value of 0 is refused too: OpenQuake writes 0 where the
      level lies below the curve's lowest level. (Where the level lies above
      the curve's highest level OpenQuake writes that highest level: a map
      cannot show it; use the curve to be sure.)

    Raises
    ------
    InputError
        The level cannot be read from the file; the message says what the file
        covers and how to get the level.
    """
    t_inv = hazard.investigation_time_yr
    site = hazard.site
    poe = poe_in_investigation_time(level, t_inv)
    what = (f"{level.description}, i.e. a probability of {poe:.4g} in the file's "
            f"{t_inv:g}-year investigation time")
    rerun = "rerun OpenQuake with {} PGA levels in intensity_measure_types_and_levels"
    if hazard.annual_rates is not None:  # a file of annual rates, read as one-year probabilities
        what = (f"{level.description}, i.e. an annual rate of exceedance of {level.annual_rate:.4g} (a "
                f"probability of {poe:.4g} in one year)")
        rerun = f"rerun {hazard.source} with {{}} PGA levels (hazard.customImls of its calculation config)"
    if hazard.kind == "curve":
        levels, curve = hazard.levels_g, hazard.poes[hazard.site_index]
        positive = np.flatnonzero(curve > 0.0)
        if poe > curve[0]:
            raise _fail(hazard.path, f"site {site.label()}: {what}, lies below the curve's lowest "
                        f"PGA level {levels[0]:g} g, which is exceeded with probability only "
                        f"{curve[0]:.4g}.", f"{rerun.format('lower')}, or choose a rarer level.",
                        line=site.line)
        if positive.size == 0 or poe < curve[positive[-1]]:
            top = (f"its highest level with a non-zero probability is {levels[positive[-1]]:g} g "
                   f"({curve[positive[-1]]:.4g})" if positive.size else "all its probabilities "
                   "are zero")
            raise _fail(hazard.path, f"site {site.label()}: {what}, lies above the curve's range: "
                        f"{top}.", f"{rerun.format('higher')}, or choose a more frequent level.",
                        line=site.line)
        return loglog_interpolate_level(levels, curve, poe)

    rates = [annual_rate_of_poe(p, t_inv) for p in hazard.map_poes]
    matches = [k for k, rate in enumerate(rates)
               if math.isclose(rate, level.annual_rate, rel_tol=RATE_REL_TOL)]
    if not matches:
        available = "; ".join(f"PGA-{p:g} (return period {1.0 / r:.0f} years)"
                              for p, r in zip(hazard.map_poes, rates))
        raise _fail(hazard.path, f"the hazard map has no column for {what}; it has "
                    f"{available}.",
                    "choose one of these levels, add the level's probability to 'poes' in the "
                    "job.ini and rerun, or give the hazard curve instead.")
    k = min(matches, key=lambda m: abs(rates[m] / level.annual_rate - 1.0))
    value = float(hazard.map_values_g[hazard.site_index, k])
    if not value > 0.0:
        raise _fail(hazard.path, f"site {site.label()}: the map gives PGA {value:g} g for "
                    f"{what}; OpenQuake writes 0 when the level lies below the hazard curve's "
                    "lowest PGA level.", "give the hazard curve, or rerun with lower PGA levels.",
                    line=site.line, column=f"PGA-{hazard.map_poes[k]:g}")
    if not MIN_PLAUSIBLE_PGA_G <= value <= MAX_PLAUSIBLE_PGA_G:
        raise _fail(hazard.path, f"site {site.label()}: the map gives PGA {value:g} g for {what}, outside "
                    f"{MIN_PLAUSIBLE_PGA_G:g} to {MAX_PLAUSIBLE_PGA_G:g} g: the file was edited or damaged.",
                    "give the map (or the hazard curve) as exported by OpenQuake.", line=site.line,
                    column=f"PGA-{hazard.map_poes[k]:g}")
    return value
