"""Target spectra from OpenQuake exports: uniform-hazard spectra, multi-IMT maps and curves.

A level named by a probability (``2in50``, ``10in50``, ``2475yr``) takes its target
spectrum from the site's OpenQuake run (the ``site`` sheet's ``uhs``). Three exports of
the engine (``oq engine --export-outputs``) hold it:

* a **uniform hazard spectrum**, ``hazard_uhs-<kind>_<calc_id>.csv``::

    #,,,,"generated_by='OpenQuake engine 3.15.0', start_date='...', checksum=..., kind='rlz-001', investigation_time=1.0"
    lon,lat,0.002105~PGA,0.002105~SA(0.2),0.002105~SA(1.0)
    -123.23738,49.27479,2.651139E-03,1.120929E-02,1.218275E-02

  columns ``<poe>~<IMT>``, one group per poe of the job (layout from the engine's user
  guide, "Outputs from Classical PSHA", listing ``lst:output_uhs``, gem/oq-engine; engines
  before about 3.10 wrote ``<poe>-<IMT>`` and an old-style ``# mean, investigation_time=1.0``
  comment, read too);
* a **hazard map** of several IMTs, ``hazard_map-<kind>_<calc_id>.csv``: columns
  ``<IMT>-<poe>`` (as :mod:`assess.hazard.openquake` reads for PGA);
* **hazard curves**, one file per IMT, ``hazard_curve-<kind>-<IMT>_<calc_id>.csv``
  (``imt='SA(0.2)'`` in the comment, columns ``poe-<IML>``): given one, the others of the
  same export (same folder, kind and calculation id) are read with it.

An optional ``custom_site_id`` column may come first and ``depth`` after ``lat``
(as the engine writes them). The site is chosen as in :mod:`assess.hazard.openquake`
(``oq_site``: ``lon,lat``, a 0-based row index or a ``custom_site_id``).

The level's probability is put in the file's investigation time (Poisson,
:func:`~assess.hazard.openquake.poe_in_investigation_time`); each IMT's value is then
interpolated log-log between the file's poes (UHS, map) or along the curve
(:func:`~assess.hazard.openquake.loglog_interpolate_level`, as OpenQuake builds its maps),
never extrapolated. Between IMT periods the spectrum is interpolated log-log in period,
and linearly from PGA (T = 0) to the shortest SA period; beyond the longest it is refused.

Every refusal is an :class:`~assess.errors.InputError` naming the file, the line and the
column (by number), never quoting the file's cells.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from assess.errors import InputError, Problem
from assess.hazard.levels import HazardLevel
from assess.hazard.records import check_record_location
from assess.hazard.openquake import (RATE_REL_TOL, Site, _choose_site, _comment_text, export_lines,
                                     loglog_interpolate_level, parse_openquake_comment,
                                     poe_in_investigation_time)

_NUMBER = r"(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_IMT = r"(?:PGA|SA\((?P<period>" + _NUMBER + r")\))"
_UHS_COLUMN = re.compile(rf"^(?P<poe>{_NUMBER})[~-](?P<imt>PGA|SA\((?P<period>{_NUMBER})\))$")
_MAP_COLUMN = re.compile(rf"^(?P<imt>PGA|SA\((?P<period>{_NUMBER})\))-(?P<poe>{_NUMBER})$")
_CURVE_COLUMN = re.compile(rf"^poe-(?P<iml>{_NUMBER})$")
_CURVE_NAME = re.compile(r"^hazard_curve-(?P<kind>[^-_]+(?:-[\d.]+)?)[-_]"
                         r"(?P<imt>PGA|SA\([\d.]+\))(?P<tail>_\d+)?\.csv$")
_LOCATION_COLUMNS = ("custom_site_id", "lon", "lat", "depth")
#: Largest share by which the file's values may fall along increasing poe before it is refused
#: (7 significant digits are written).
_ROUNDING = 1e-5
_FIX = ("give the uniform-hazard-spectrum (hazard_uhs-mean_<calc_id>.csv), hazard map "
        "(hazard_map-mean_<calc_id>.csv) or hazard curve (hazard_curve-mean-<IMT>_<calc_id>.csv) export "
        "of 'oq engine --export-outputs', unchanged.")


@dataclass(frozen=True)
class UniformHazardSpectrum:
    """The target spectrum of one site at one probability, from an OpenQuake export.

    Attributes
    ----------
    path : str
        The file read (for curves: the one named; ``files`` lists all).
    source : str
        ``"uhs"``, ``"map"`` or ``"curves"``.
    period_s : ndarray
        Periods [s] of the IMTs, increasing; 0 for PGA.
    sa_g : ndarray
        Spectral accelerations [g] at the level's probability (PGA at T = 0).
    poe : float
        The level's probability of exceedance in the file's investigation time.
    investigation_time_yr : float
    site : Site
    statistic : str or None
        OpenQuake's ``kind`` (``mean``, ``rlz-001``, ``quantile-0.85``).
    files : tuple of str
    """

    path: str
    source: str
    period_s: np.ndarray
    sa_g: np.ndarray
    poe: float
    investigation_time_yr: float
    site: Site
    statistic: str | None
    files: tuple[str, ...] = ()

    def target_g(self, period_s):
        """Sa [g] at ``period_s``: log-log between the IMT periods, linear from PGA to the first SA.

        Raises ValueError beyond the longest period of the file (never extrapolated).
        """
        return spectrum_between_periods(self.period_s, self.sa_g, period_s)

    def __call__(self, period_s):
        """Same as :meth:`target_g`: the spectrum is a target callable with ``max_period_s``."""
        return self.target_g(period_s)

    @property
    def max_period_s(self) -> float:
        return float(self.period_s[-1])


def spectrum_between_periods(periods_s, sa_g, period_s):
    """Sa [g] at ``period_s`` from spectral points (period 0 = PGA).

    .. math::  \\ln S_a(T) = \\ln S_a(T_j) + \\frac{\\ln T - \\ln T_j}{\\ln T_{j+1} - \\ln T_j}
               (\\ln S_a(T_{j+1}) - \\ln S_a(T_j))

    between SA periods, linear in T between PGA (T = 0) and the shortest SA period.

    >>> round(float(spectrum_between_periods([0.0, 0.2, 1.0], [0.4, 1.0, 0.5], 0.1)), 6)  # linear
    0.7
    >>> round(float(spectrum_between_periods([0.0, 0.2, 1.0], [0.4, 1.0, 0.5], 0.2 ** 0.5)), 6)  # log-log
    0.707107
    """
    points = np.asarray(periods_s, dtype=float)
    values = np.asarray(sa_g, dtype=float)
    period = np.asarray(period_s, dtype=float)
    if np.any(period < 0) or np.any(period > points[-1] * (1 + 1e-9)):
        raise ValueError(f"period outside 0-{points[-1]:g} s, the periods the hazard file has")
    positive = points > 0
    log_points, log_values = np.log(points[positive]), np.log(values[positive])
    safe = np.clip(period, points[positive][0], points[-1])
    out = np.exp(np.interp(np.log(safe), log_points, log_values))
    if points[0] == 0.0:
        first = points[positive][0]
        short = period < first
        out = np.where(short, values[0] + (values[positive][0] - values[0]) * period / first, out)
    elif np.any(period < points[0]):
        raise ValueError(f"period below {points[0]:g} s, the shortest the hazard file has")
    return out


def _period_of(match) -> float:
    return 0.0 if match.group("imt") == "PGA" else float(match.group("period"))


def _fail(path, message, fix=_FIX, line=None, column=None) -> InputError:
    return InputError([Problem(file=str(path), message=message, fix=fix, row=line,
                               column=None if column is None else f"{column}")])


def _read(path):
    """(metadata, header, header line number, [(line number, cells)])."""
    if not path.is_file():
        raise _fail(path, "the OpenQuake file does not exist.",
                    "check the 'uhs' path of the site sheet (relative to the workbook).")
    if path.stat().st_size > 64 * 1024 * 1024:
        raise _fail(path, "the file is larger than 64 MB.", "export the site's hazard only (oq_site) or a "
                    "smaller region.")
    lines = path.read_text(encoding="utf-8-sig", errors="replace").splitlines()
    comments, header, header_line, rows = export_lines(lines)
    metadata = {}
    for line in comments:
        for key, value in parse_openquake_comment(_comment_text(line)).items():
            metadata.setdefault(key, value)
    if header is None:
        raise _fail(path, "the file is empty: no header line.")
    if "lon" not in header or "lat" not in header:
        raise _fail(path, "the header has no 'lon' and 'lat' columns: this is not an OpenQuake hazard export.",
                    line=header_line)
    if not rows:
        raise _fail(path, "the file has a header but no site rows.", line=header_line)
    return metadata, header, header_line, rows


def _investigation_time(path, metadata) -> float:
    text = metadata.get("investigation_time")
    try:
        value = float(text)
    except (TypeError, ValueError):
        value = math.nan
    if not (math.isfinite(value) and value > 0):
        raise _fail(path, "the comment line gives no investigation_time (years), so its probabilities "
                    "cannot be tied to a hazard level.", line=1)
    return value


def _sites_and_values(path, header, rows, value_columns):
    """Sites of the rows and their numbers in ``value_columns`` (shape sites x columns)."""
    where = {name: header.index(name) for name in _LOCATION_COLUMNS if name in header}
    sites, values = [], np.zeros((len(rows), len(value_columns)))
    for k, (line, cells) in enumerate(rows):
        if len(cells) != len(header):
            raise _fail(path, f"the row has {len(cells)} cells, the header {len(header)}.", line=line)

        def number(i):
            try:
                x = float(cells[i])
            except ValueError:
                x = math.nan
            if not math.isfinite(x):
                raise _fail(path, "a cell is not a finite number.", line=line, column=i + 1)
            return x
        lon, lat = number(where["lon"]), number(where["lat"])
        depth = number(where["depth"]) if "depth" in where else None
        custom = cells[where["custom_site_id"]].strip() if "custom_site_id" in where else None
        sites.append(Site(index=k, lon=lon, lat=lat, depth_km=depth, custom_site_id=custom, line=line))
        for j, i in enumerate(value_columns):
            values[k, j] = number(i)
            if values[k, j] < 0:
                raise _fail(path, "a value is negative.", line=line, column=i + 1)
    return sites, values


def _level_poe(path, level: HazardLevel, investigation_time_yr: float) -> float:
    if not level.has_probability:
        raise _fail(path, f"the level '{level.name}' is not a probability, so the hazard file cannot give it.",
                    "name the level by a probability (2in50, 10in50, 2475yr) or use DE / MCE_R with sds_g "
                    "and sd1_g.")
    return poe_in_investigation_time(level, investigation_time_yr)


def _between_poes(path, poes, values_g, poe, what, line):
    """Value at ``poe`` between the file's poes, log-log; the nearest column within 1 % of the rate."""
    order = np.argsort(-poes)
    p, v = poes[order], values_g[order]
    rates = -np.log1p(-p)
    rate = -math.log1p(-poe)
    close = np.flatnonzero(np.abs(rates / rate - 1.0) <= RATE_REL_TOL)
    if close.size:
        return float(v[close[0]])
    if not (p[-1] < poe < p[0]):
        raise _fail(path, f"the level's probability ({poe:.4g} in the file's investigation time) is outside "
                    f"the file's poes for {what} ({p[-1]:.4g} to {p[0]:.4g}); it is not extrapolated.",
                    "run OpenQuake with this level's poe among 'poes' (job.ini), or choose a level inside "
                    "that range.", line=line)
    if np.any(v <= 0):
        raise _fail(path, f"a value for {what} is 0, so it cannot be interpolated in log.", line=line)
    if np.any(np.diff(v) < -_ROUNDING * v[:-1]):
        raise _fail(path, f"the values for {what} fall as the poe falls: not a hazard export.", line=line)
    return loglog_interpolate_level(v, p, poe)


def read_target_spectrum(path, level: HazardLevel, site=None) -> UniformHazardSpectrum:
    """The target spectrum of ``level`` at the chosen site of an OpenQuake export.

    Parameters
    ----------
    path : str or Path
        A ``hazard_uhs``, multi-IMT ``hazard_map`` or one ``hazard_curve`` export (CSV).
    level : HazardLevel
        A level named by a probability.
    site : None, int, str or (lon, lat)
        The site (``oq_site``), as :func:`assess.hazard.openquake.read_openquake_hazard` takes it.

    Raises
    ------
    InputError
        Not an OpenQuake export of these kinds; no investigation time; a cell not a number; the
        level's probability outside the file's; several sites and none chosen.
    """
    path = Path(path)
    metadata, header, header_line, rows = _read(path)
    investigation_time = _investigation_time(path, metadata)
    poe = _level_poe(path, level, investigation_time)
    uhs = [(i, _UHS_COLUMN.match(name)) for i, name in enumerate(header)]
    uhs = [(i, m) for i, m in uhs if m]
    maps = [(i, m) for i, m in ((i, _MAP_COLUMN.match(name)) for i, name in enumerate(header)) if m]
    if any(_CURVE_COLUMN.match(name) for name in header):
        return _from_curves(path, level, site)
    columns = uhs or maps
    if not columns:
        raise _fail(path, "no column is a spectral value (<poe>~PGA, <poe>~SA(T), or PGA-<poe>, SA(T)-<poe>).",
                    line=header_line)
    for i, match in columns:
        if not 0.0 < float(match.group("poe")) < 1.0:
            raise _fail(path, f"column {i + 1}'s probability of exceedance ({float(match.group('poe')):g}) is not "
                        "between 0 and 1.", "export the spectra again from OpenQuake (poes in job.ini are "
                        "probabilities in the investigation time).", line=header_line, column=i + 1)
    sites, values = _sites_and_values(path, header, rows, [i for i, _ in columns])
    index = _choose_site(path, sites, site)
    by_period: dict[float, list[tuple[float, float]]] = {}
    for j, (i, match) in enumerate(columns):
        by_period.setdefault(_period_of(match), []).append((float(match.group("poe")), values[index, j]))
    periods = sorted(by_period)
    sa = []
    for period in periods:
        pairs = np.array(by_period[period])
        what = "PGA" if period == 0 else f"SA({period:g})"
        sa.append(_between_poes(path, pairs[:, 0], pairs[:, 1], poe, what, sites[index].line))
    _check_spectrum(path, periods, sa, sites[index].line)
    return UniformHazardSpectrum(str(path), "uhs" if uhs else "map", np.array(periods), np.array(sa), poe,
                                 investigation_time, sites[index], _unquoted(metadata.get("kind")), (str(path),))


def _unquoted(text):
    return None if text is None else str(text).strip().strip("'\"")


def _check_spectrum(path, periods, sa, line):
    if not any(p > 0 for p in periods):
        raise _fail(path, "the file has no SA(T) column, only PGA: it gives no spectrum.",
                    "export the uniform hazard spectra (job.ini: uniform_hazard_spectra = true, SA periods "
                    "in intensity_measure_types_and_levels).", line=line)
    if any(s <= 0 for s in sa):
        raise _fail(path, "a spectral value at the level is 0.", line=line)


def curve_files(path) -> list[Path]:
    """The per-IMT curve files of the export ``path`` belongs to (same folder, kind and calc id)."""
    path = Path(path)
    match = _CURVE_NAME.match(path.name)
    if not match:
        return [path]
    kind, tail = match.group("kind"), match.group("tail") or ""
    found = []
    for other in sorted(path.parent.iterdir()):
        m = _CURVE_NAME.match(other.name)
        if m and m.group("kind") == kind and (m.group("tail") or "") == tail:
            # a file of the export is read only where the named one is: never through a link that leaves its
            # folder (another file of this machine, /proc), never a FIFO or a device
            if check_record_location(other, path.parent) is not None or not other.is_file():
                raise _fail(other, "this curve file of the same export is not a plain file in the export's folder "
                            "(a link out of it, or a pipe or device): it is not read.",
                            "keep the export's curve files in one folder, as OpenQuake writes them.")
            found.append(other)
    return found or [path]


def _from_curves(path, level, site) -> UniformHazardSpectrum:
    files = curve_files(path)
    periods, sa, chosen, statistic, poe, investigation_time = [], [], None, None, None, None
    for file in files:
        metadata, header, header_line, rows = _read(file)
        time_yr = _investigation_time(file, metadata)
        if investigation_time is not None and abs(time_yr - investigation_time) > 1e-9 * investigation_time:
            raise _fail(file, "its investigation_time differs from the other curves' of the export.", line=1)
        investigation_time = time_yr
        poe = _level_poe(file, level, time_yr)
        imt = _unquoted(metadata.get("imt"))
        match = re.fullmatch(_IMT, imt or "")
        if not match:
            raise _fail(file, "the comment line names no PGA or SA(T) intensity measure ('imt').", line=1)
        columns = [(i, _CURVE_COLUMN.match(name)) for i, name in enumerate(header)]
        columns = [(i, m) for i, m in columns if m]
        if len(columns) < 2:
            raise _fail(file, "a hazard curve needs two or more poe-<level> columns.", line=header_line)
        sites, values = _sites_and_values(file, header, rows, [i for i, _ in columns])
        index = _choose_site(file, sites, site)
        if chosen is not None and (abs(sites[index].lon - chosen.lon) > 1e-6
                                   or abs(sites[index].lat - chosen.lat) > 1e-6):
            raise _fail(file, "the chosen site is not at the same place in every curve file of the export.",
                        line=sites[index].line)
        chosen = sites[index]
        levels = np.array([float(m.group("iml")) for _, m in columns])
        curve = values[index]
        if np.any(np.diff(levels) <= 0) or np.any(np.diff(curve) > _ROUNDING * np.maximum(curve[:-1], 1e-300)):
            raise _fail(file, "the curve's levels do not increase or its poes rise.", line=chosen.line)
        positive = curve[curve > 0]
        what = "PGA" if match.group("period") is None else f"SA({match.group('period')})"
        if positive.size == 0 or not (positive.min() <= poe <= curve[0]):
            raise _fail(file, f"the level's probability ({poe:.4g} in {time_yr:g} yr) is outside the {what} "
                        f"curve's range; it is not extrapolated.", "extend the curve's intensity levels "
                        "(job.ini intensity_measure_types_and_levels) so that it spans this probability.",
                        line=chosen.line)
        periods.append(0.0 if match.group("period") is None else float(match.group("period")))
        sa.append(loglog_interpolate_level(levels, np.minimum.accumulate(curve), poe))
        statistic = _unquoted(metadata.get("kind"))
    order = np.argsort(periods)
    if len(set(periods)) != len(periods):
        raise _fail(path, "two curve files of the export are for the same intensity measure.")
    _check_spectrum(path, periods, sa, chosen.line)
    return UniformHazardSpectrum(str(path), "curves", np.array(periods)[order], np.array(sa)[order], poe,
                                 investigation_time, chosen, statistic, tuple(str(f) for f in files))
