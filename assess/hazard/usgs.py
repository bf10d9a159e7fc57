"""USGS nshmp-haz hazard curves (CSV) -> the PGA hazard curve of a site; any hazard file, by its header.

In the United States a site's hazard curve comes from the USGS national
seismic hazard model, computed by its engine nshmp-haz ([1]). Its
``HazardCalc`` writes one CSV per intensity measure (IMT), in a folder named
after it (``hazout/PGA/curves.csv``; older versions ``curves/PGA/total.csv``)::

    name,lon,lat,0.005,0.007,0.0098,0.0137,...,2.2,3.3
    Concord CA,-122.00000,37.95000,2.85280770e-03,2.85280770e-03,...,0.0,0.0

* the header: ``name`` (only when the sites were named), ``lon``, ``lat``,
  then the intensity levels of the curve (PGA and SA in g), as Java writes a
  double (``0.005``, ``1.0E-4``);
* one row per site: its name, its coordinates (``%.5f``) and the **annual
  rate** at which each level is exceeded (``%.8e``; ``0.0`` where no source
  reaches the level).

Format details (usgs/nshmp-haz, ``src/gov/usgs/earthquake/nshmp/calc/HazardExport.java``:
``CURVE_FILE_ASCII``, ``VALUE_FMT = "%.8e"``, the header built from
``config.hazard.modelCurves().get(imt).xValues()``; the example outputs in
``etc/example_outputs/*/curves/PGA/total.csv``). The file has no comment
line: its IMT is the name of its folder (``PGA/``) or of the file itself
(``PGA.csv``, ``curves-PGA.csv``), and its values are annual rates unless the
calculation's config set ``hazard.valueFormat`` to ``POISSON_PROBABILITY``
(then one-year probabilities, :math:`1 - e^{-\\lambda}`, which the file
cannot tell apart: below 0.02 they differ from the rate by less than 1 %).

The curve becomes the same object an OpenQuake curve does
(:class:`~assess.hazard.openquake.OpenQuakeHazard`, ``kind="curve"``) with
its annual rates kept as read (``annual_rates``, used by the risk integral,
:func:`assess.hazard.risk_integral.curve_annual_rates`) and their one-year
Poisson probabilities :math:`P = 1 - e^{-\\lambda}` as ``poes`` (investigation
time 1 year), so a level's PGA is read from it as from an OpenQuake curve
(:func:`~assess.hazard.openquake.pga_at_level`). Only PGA is used.

:func:`read_hazard_curve_file` reads either program's file, told apart by the
header (OpenQuake: a ``#`` comment line, then ``poe-<level>`` or
``<IMT>-<poe>`` columns; nshmp-haz: bare numbers after ``lon,lat``), after
checking the file is no larger than :data:`MAX_HAZARD_FILE_BYTES`. Every
problem raises :class:`~assess.errors.InputError` naming the file, the line
(``row``) and the column; text of the file is quoted only where it looks
like a header name or a number.

References
----------
.. [1] Petersen, M. D., Shumway, A. M., Powers, P. M., et al. (2020). The 2018
   update of the US National Seismic Hazard Model: Overview of model and
   implications. Earthquake Spectra 36(1):5-41 (computed with nshmp-haz,
   https://github.com/usgs/nshmp-haz). doi:10.1177/8755293019878199
"""
from __future__ import annotations

import csv
import math
import re
from dataclasses import replace
from pathlib import Path

import numpy as np

from assess.errors import InputError, Problem
from assess.hazard.openquake import (MAX_PLAUSIBLE_PGA_G, MIN_PLAUSIBLE_PGA_G, PGA, POE_RISE_REL_TOL, _QUOTABLE,
                                     OpenQuakeHazard, Site, _capped, _choose_site, _shown, read_openquake_hazard)

#: The program, as messages and the report name it.
SOURCE = "USGS nshmp-haz"
#: Largest hazard file read [bytes]. One site's curve is about 400 bytes; a regional grid of thousands of
#: sites a few megabytes. Larger files are refused before they are read, not read in part.
MAX_HAZARD_FILE_BYTES = 32 * 2**20
#: Largest plausible annual rate of exceedance [1/yr]: no level a curve samples is exceeded a thousand
#: times a year; a larger value comes from an edited or damaged file.
MAX_PLAUSIBLE_RATE_PER_YR = 1000.0
#: nshmp-haz's names of intensity measures (``gov.usgs.earthquake.nshmp.gmm.Imt``: PGA, PGV, PGD, SA0P2 ...).
_IMT_NAME = re.compile(r"^(PGA|PGV|PGD|AI|CAV|SA\d+P\d+)$")
#: Lowest header level above which a header reads as return periods [yr] (nshmp-haz's ``map.csv``), not g.
_RETURN_PERIOD_FLOOR = 10.0
_LOCATION = ("lon", "lat")
_FILE_FIX = ("give the PGA hazard curve exported by nshmp-haz, unchanged (hazout/PGA/curves.csv: "
             "header 'name,lon,lat,<PGA levels>', one row of annual rates per site).")


def _fail(path, message, fix=_FILE_FIX, line=None, column=None) -> InputError:
    return InputError([Problem(file=str(path), message=message, fix=fix, row=line, column=column)])


# --------------------------------------------------------------------------- any hazard file


def is_nshmp_header(cells) -> bool:
    """Whether a CSV header is nshmp-haz's: ``[name,]lon,lat`` then one or more numbers (the levels).

    >>> is_nshmp_header(["name", "lon", "lat", "0.005", "1.0E-4"]), is_nshmp_header(["lon", "lat", "poe-0.1"])
    (True, False)
    """
    cells = [str(cell).strip() for cell in cells]
    start = 3 if cells[:3] == ["name", *_LOCATION] else 2 if cells[:2] == list(_LOCATION) else None
    if start is None or len(cells) <= start:
        return False
    try:
        [float(cell) for cell in cells[start:]]
    except ValueError:
        return False
    return True


def bounded_text(path, max_bytes: int = MAX_HAZARD_FILE_BYTES, option: str = "--oq-hazard") -> str:
    """The text of a hazard file the user named, refused unread beyond ``max_bytes``.

    A file that is not a regular file (a folder, a device) is refused too: it
    could be endless.
    """
    path = Path(path)
    if not path.is_file():
        what = ("is not a file (a folder or a device)" if path.exists() else "does not exist")
        raise _fail(path, f"the hazard file {what}.", f"check the path given to {option}.")
    with path.open("rb") as stream:
        data = stream.read(max_bytes + 1)
    if len(data) > max_bytes:
        raise _fail(path, f"the hazard file is larger than {max_bytes // 2**20} MiB, far more than a site's "
                    "curve (a few hundred bytes a site): it is read no further.",
                    "give the curve of the facility's site: the header line and the site's row (or rerun the "
                    "hazard for that site only).")
    return data.decode("utf-8-sig", errors="replace")


def _first_line(text: str) -> tuple[int, list[str]]:
    for number, line in enumerate(text.splitlines(), start=1):
        if line.strip():
            return number, next(csv.reader([line]))
    return 0, []


def read_hazard_curve_file(path, site=None) -> OpenQuakeHazard:
    """Read an OpenQuake hazard curve or map, or a USGS nshmp-haz curve, for PGA; the format by its header.

    Parameters
    ----------
    path : str or Path
        The file the user named (``--oq-hazard``, a portfolio's ``oq_hazard``);
        nothing else is read.
    site : None, int, str or (lon, lat)
        As :func:`~assess.hazard.openquake.read_openquake_hazard`; a string
        names an OpenQuake ``custom_site_id`` or an nshmp-haz site ``name``.

    Raises
    ------
    InputError
        Missing or too large a file, or what either reader refuses; a file of
        neither format is told what both look like.
    """
    text = bounded_text(path)
    try:
        _, header = _first_line(text)
        if is_nshmp_header(header):
            return read_nshmp_curve(path, site=site, text=text)
        return read_openquake_hazard(path, site=site)
    except csv.Error as error:  # a field over the csv module's limit (128 KiB), a broken quote: no hazard file
        raise _fail(path, f"the file is not a CSV a hazard curve is written in ({error}).",
                    "give the hazard curve as OpenQuake or nshmp-haz exported it.") from None
    except InputError as error:
        raise InputError([replace(p, fix=f"{p.fix} Or give a USGS nshmp-haz curve (hazout/PGA/curves.csv: header "
                                  "'name,lon,lat,<PGA levels>', annual rates).")
                          if p.message.startswith("this is not an OpenQuake hazard curve or map") else p
                          for p in error.problems]) from None


# --------------------------------------------------------------------------- nshmp-haz curves


def imt_of_path(path) -> str | None:
    """The intensity measure a curve file's path names: its folder (``PGA/curves.csv``) or its own name
    (``PGA.csv``, ``site-SA0P2.csv``); PGA if the path names it anywhere, else the first other IMT named,
    else None.

    >>> imt_of_path("hazout/PGA/curves.csv"), imt_of_path("curves/SA0P2.csv"), imt_of_path("curve.csv")
    ('PGA', 'SA0P2', None)
    """
    path = Path(path)
    names = [token for token in re.split(r"[-_. ]+", path.stem) if token] + [path.parent.name]
    found = [name for name in names if _IMT_NAME.match(name)]
    return PGA if PGA in found else (found[0] if found else None)


def _levels(path, header: list[str], start: int, line: int) -> np.ndarray:
    """The header's PGA levels [g]: finite, plausible (as an OpenQuake curve's), increasing."""
    levels = np.array([float(cell) for cell in header[start:]])
    finite = levels[np.isfinite(levels)]
    if finite.size == levels.size and finite.min() >= _RETURN_PERIOD_FLOOR:
        raise _fail(path, "the header's numbers are all 10 or more: return periods in years (nshmp-haz's map.csv, "
                    "the ground motion at each return period), not the levels [g] of a hazard curve.",
                    "give the curves file of the same folder (PGA/curves.csv), not map.csv.", line=line)
    for k, level in enumerate(levels):
        name = header[start + k]
        column = name if _QUOTABLE.fullmatch(name) else None
        if not MIN_PLAUSIBLE_PGA_G <= level <= MAX_PLAUSIBLE_PGA_G:
            raise _fail(path, f"the PGA level of column {_shown(name)} is {level:g} g, outside "
                        f"{MIN_PLAUSIBLE_PGA_G:g} to {MAX_PLAUSIBLE_PGA_G:g} g, the levels a PGA hazard curve samples: "
                        "the file was edited or damaged.", "give the curve as nshmp-haz wrote it (its levels are "
                        "the config's hazard.customImls for PGA).", line=line, column=column)
        if k and level <= levels[k - 1]:
            raise _fail(path, f"the PGA levels must increase from column to column; {_shown(name)} does not.",
                        "give the curve as nshmp-haz wrote it.", line=line, column=column)
    return levels


def _site_rows(path, header: list[str], start: int, rows) -> tuple[list[Site], np.ndarray]:
    """Sites and their annual rates; every bad cell reported (at most a screenful)."""
    problems: list[Problem] = []
    sites, values = [], []

    def number(cells, i, line, low, high, what):
        text = cells[i].strip()
        try:
            x = float(text)
        except ValueError:
            x = math.nan
        if not (math.isfinite(x) and low <= x <= high):
            problems.append(Problem(file=str(path), message=f"{_shown(text)} is not {what}.",
                                    fix="give the curve as nshmp-haz wrote it.", row=line,
                                    column=header[i] if _QUOTABLE.fullmatch(header[i]) else None))
        return x

    rate_text = f"an annual rate of exceedance (a number from 0 to {MAX_PLAUSIBLE_RATE_PER_YR:g} per year)"
    for line, cells in rows:
        if len(cells) != len(header):
            problems.append(Problem(file=str(path), message=f"the line has {len(cells)} fields, the header "
                                    f"{len(header)}.", fix="give the curve as nshmp-haz wrote it (a site's name "
                                    "holds no comma).", row=line))
            continue
        name = cells[0].strip() if start == 3 else None
        lon = number(cells, start - 2, line, -360.0, 360.0, "a longitude in degrees")
        lat = number(cells, start - 1, line, -90.0, 90.0, "a latitude in degrees")
        sites.append(Site(index=len(sites), lon=lon, lat=lat, depth_km=None, line=line,
                          custom_site_id=name if name and _QUOTABLE.fullmatch(name) else None))
        values.append([number(cells, i, line, 0.0, MAX_PLAUSIBLE_RATE_PER_YR, rate_text)
                       for i in range(start, len(header))])
    if problems:
        raise InputError(_capped(problems))
    if not sites:
        raise _fail(path, "the file has a header but no site rows.")
    return sites, np.array(values, dtype=float)


def _monotone(path, sites, rates, names, levels) -> np.ndarray:
    """Each curve's rates must not grow with the level (beyond the file's 9-digit rounding)."""
    problems = []
    for site, curve in zip(sites, rates):
        rise = np.flatnonzero(np.diff(curve) > POE_RISE_REL_TOL * curve[:-1] + 1e-300)
        if rise.size:
            k = int(rise[0]) + 1
            problems.append(Problem(
                file=str(path), message=f"the hazard curve is not monotone: the rate of exceeding {levels[k]:g} g "
                f"({curve[k]:.8e} per year) is larger than that of exceeding {levels[k - 1]:g} g "
                f"({curve[k - 1]:.8e}).", fix="a rate of exceedance cannot grow with the level; give the curve as "
                "nshmp-haz wrote it, unedited.", row=site.line,
                column=names[k] if _QUOTABLE.fullmatch(names[k]) else None))
    if problems:
        raise InputError(_capped(problems))
    return np.minimum.accumulate(rates, axis=1)  # flatten the 9-digit rounding noise


def _choose(path, sites, site) -> int:
    """:func:`~assess.hazard.openquake._choose_site`, its messages speaking of a site's ``name``."""
    try:
        return _choose_site(path, sites, site)
    except InputError as error:
        raise InputError([replace(p, message=p.message.replace("custom_site_id", "name"),
                                  fix=p.fix.replace("custom_site_id", "name")) for p in error.problems]) from None


def read_nshmp_curve(path, site=None, text: str | None = None) -> OpenQuakeHazard:
    """Read a USGS nshmp-haz hazard-curve CSV for PGA (module docstring).

    Parameters
    ----------
    path : str or Path
        The ``curves.csv`` of the PGA folder (or a file whose name says PGA).
    site : None, int, str or (lon, lat)
        A 0-based row index, a site ``name``, or coordinates [deg]; may be
        omitted for a one-site file.
    text : str, optional
        The file's text, already read (:func:`bounded_text`); read here if not.

    Returns
    -------
    OpenQuakeHazard
        ``kind="curve"``, ``annual_rates`` as read (made non-increasing),
        ``poes`` their one-year probabilities, ``investigation_time_yr`` 1.

    Raises
    ------
    InputError
        Not an nshmp-haz curve; not PGA; a level or a rate that is not a
        plausible number; a curve rising with the level; a line of the wrong
        length; several sites and none chosen, or a chosen site not in the file.
    """
    path = Path(path)
    text = bounded_text(path) if text is None else text
    lines = [(number, line) for number, line in enumerate(text.splitlines(), start=1) if line.strip()]
    if not lines:
        raise _fail(path, "the file is empty: no header line.")
    line, header = lines[0][0], [cell.strip() for cell in next(csv.reader([lines[0][1]]))]
    if not is_nshmp_header(header):
        raise _fail(path, f"line {line} is not the header of an nshmp-haz curve: 'name,lon,lat' or 'lon,lat', "
                    "then the levels as numbers.", line=line)
    imt = imt_of_path(path)
    if imt is None:
        raise _fail(path, "the nshmp-haz curve does not say its intensity measure: nshmp-haz names it by the "
                    "folder (PGA/curves.csv), and neither the folder nor the file name names one.",
                    "give the file in its PGA folder as nshmp-haz wrote it (hazout/PGA/curves.csv), or put PGA "
                    "in its name (site-PGA.csv).", line=line)
    if imt != PGA:
        raise _fail(path, f"this nshmp-haz curve is for {imt}, not PGA.", "give the PGA curve of the same "
                    "calculation (hazout/PGA/curves.csv); if there is none, add PGA to the config's hazard.imts "
                    "and rerun.", line=line)
    start = 3 if header[0] == "name" else 2
    levels = _levels(path, header, start, line)
    if levels.size < 2:
        raise _fail(path, "the curve has one level: a hazard curve needs several.", line=line)
    sites, rates = _site_rows(path, header, start, [(n, next(csv.reader([row]))) for n, row in lines[1:]])
    rates = _monotone(path, sites, rates, header[start:], levels)
    index = _choose(path, sites, site)
    notes = []
    if "truncated" in path.name:
        notes.append("nshmp-haz's curves-truncated.csv holds the curve cut at rates of about 1e-4 per year; the "
                     "rarer shaking is extrapolated (curves.csv holds the whole curve).")
    return OpenQuakeHazard(path=str(path), kind="curve", investigation_time_yr=1.0, imt=PGA, statistic=None,
                           sites=tuple(sites), site_index=index, levels_g=levels, poes=-np.expm1(-rates),
                           annual_rates=rates, source=SOURCE, notes=tuple(notes))
