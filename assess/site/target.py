"""Which target spectrum a level names, given what the ``site`` sheet holds.

``DE`` names the design spectrum (ASCE 7, from SDS, SD1 and TL or from SS, S1 and the site
class: :mod:`assess.site.asce7`), ``MCE_R`` 1.5 times it, and a probability (``2in50``,
``10in50``, ``2475yr``) the uniform-hazard spectrum of the site's OpenQuake export at that
probability (:mod:`assess.site.uhs`). Anything else names no target: refused, saying what to add.
"""
from __future__ import annotations

from pathlib import Path
from typing import Callable

from assess.errors import InputError, Problem
from assess.hazard.levels import HazardLevel
from assess.site.asce7 import DesignSpectrum
from assess.site.uhs import read_target_spectrum

_DESIGN_NAMES = {"DE": "design", "MCE_R": "MCE_R", "MCER": "MCE_R", "MCE": "MCE_R"}


def asce7_level(level: HazardLevel) -> str | None:
    """Which ASCE 7 spectrum a level's name names: ``"design"`` (DE), ``"MCE_R"`` (MCE_R, MCER, MCE) or None.

    >>> from assess.hazard.levels import parse_level
    >>> asce7_level(parse_level("DE")), asce7_level(parse_level("mce-r")), asce7_level(parse_level("2in50"))
    ('design', 'MCE_R', None)
    """
    if level.has_probability:
        return None
    return _DESIGN_NAMES.get(level.name.strip().upper().replace("-", "_"))


def level_target(level: HazardLevel, *, design: DesignSpectrum | None = None, uhs_path=None, oq_site=None,
                 workbook: str = "", sheet: str = "site") -> Callable:
    """The target spectrum of ``level``: a callable Sa [g] of period [s] (with ``max_period_s`` for a UHS).

    Parameters
    ----------
    level : HazardLevel
    design : DesignSpectrum, optional
        The site's ASCE 7 spectrum (:func:`assess.assessment.floors.design_spectrum_of`).
    uhs_path : path, optional
        The ``uhs`` file, already resolved against the workbook's folder.
    oq_site : optional
        The site in that file (:func:`assess.site.uhs.parse_site_choice`).
    workbook, sheet : str
        For the messages.

    Raises
    ------
    InputError
        The level names no target the sheet can give.

    Examples
    --------
    >>> from assess.site.asce7 import from_design_values
    >>> from assess.hazard.levels import parse_level
    >>> target = level_target(parse_level("MCE_R"), design=from_design_values(1.0, 0.6, 8.0))
    >>> round(float(target(1.0)), 6)
    0.9
    """
    kind = asce7_level(level)
    if kind is not None:
        if design is None:
            raise InputError([Problem(workbook, f"level '{level.name}' names the ASCE 7 {kind} "
                                      "spectrum, but the site sheet gives neither sds_g and sd1_g nor ss_g, s1_g "
                                      "and site_class.", "add them to the site sheet (a USGS hazard lookup for "
                                      "the site gives them).", sheet=sheet)])
        return design.design_g if kind == "design" else design.mce_r_g
    if level.has_probability:
        if uhs_path is None:
            raise InputError([Problem(workbook, f"level '{level.name}' is a probability, which only an OpenQuake "
                                      "export gives a spectrum for, and the site sheet names no 'uhs' file.",
                                      "add 'uhs' (the hazard_uhs-mean_<id>.csv of the site's OpenQuake run), or "
                                      "run the level DE or MCE_R.", sheet=sheet)])
        return read_target_spectrum(Path(uhs_path), level, oq_site)
    raise InputError([Problem(workbook, f"level '{level.name}' names no target spectrum.",
                              "run DE, MCE_R or a probability (2in50, 10in50) with a site sheet, or give the "
                              "level's motions in the hazard sheet.", sheet=sheet)])
