"""ASCE 7 design and MCE_R response spectra of a site, from the values a hazard lookup gives.

What each edition does, and what this module does with it
---------------------------------------------------------
**ASCE 7-16** §11.4: the mapped MCE_R accelerations SS and S1 and the site class give
SMS = Fa SS and SM1 = Fv S1 (eqs. 11.4-1, 11.4-2) with the site coefficients of
Tables 11.4-1 and 11.4-2 (linear interpolation between the tabulated SS and S1, as
the tables' note allows); SDS = 2/3 SMS, SD1 = 2/3 SM1 (eqs. 11.4-3, 11.4-4); the
design spectrum of §11.4.6 (:func:`design_spectral_acceleration_g`); the MCE_R
spectrum is 1.5 times it (§11.4.7). Stated choices of §11.4.3-§11.4.8:

* site class D "by default" (soil not known, §11.4.3): Fa not less than 1.2 (§11.4.4);
* site class B without measured shear-wave velocity: Fa = Fv = 1.0 (§11.4.3), spelled
  ``B (unmeasured)``;
* site class E with SS ≥ 1.0: §11.4.8 asks a site-specific hazard analysis unless Fa is
  taken as Site Class C's (exception 1): C's Fa is used, and said so in the notes;
* site classes D and E with S1 ≥ 0.2: §11.4.8 asks a site-specific hazard analysis,
  with exceptions 2 and 3 for the equivalent lateral force procedure only; the
  table's Fv is used here and the notes say that the code asks a site-specific
  analysis (a target spectrum for equipment, not a design of the structure);
* site class F: refused (a site response analysis, §20.3.1).

**ASCE 7-22** §11.4 takes SMS and SM1 (and a multi-period MCE_R spectrum) directly from
the USGS Seismic Design Geodatabase for the site class, which has nine classes (A, B,
BC, C, CD, D, DE, E, F); there are no Fa/Fv tables. From SDS and SD1 (with TL) this
module builds the two-period design spectrum of §11.4.5.2, the same shape as 7-16's
§11.4.6. The multi-period spectrum of §11.4.5.1 (which 7-22 asks for response-history
analysis) cannot be made from SDS and SD1: give it as a tabulated target instead
(:func:`tabulated_target`). Given SS, S1 and a site class with 7-22, this module uses
ASCE 7-16's Tables 11.4-1/11.4-2 for classes A to E and says so in the notes; for BC,
CD and DE (which those tables lack) and for 7-22's "default" class it refuses: the
USGS lookup for the site gives SDS and SD1 directly.

TL (the long-period transition period, ASCE 7 Figures 22-14 to 22-17) may be left out:
the spectrum then keeps SD1/T at every period (the T > TL branch, lower, is never
used), which is conservative, and the notes say so.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


ASCE_7_16 = "ASCE 7-16"
ASCE_7_22 = "ASCE 7-22"
CODES = (ASCE_7_22, ASCE_7_16)
#: MCE_R spectrum = this times the design spectrum (ASCE 7-16 §11.4.7; 7-22 §11.4.6).
MCE_R_OVER_DESIGN = 1.5

#: ASCE 7-16 Table 11.4-1: Fa at SS = 0.25, 0.5, 0.75, 1.0, 1.25, 1.5 (the same values, with
#: §11.4.4's default-D floor and §11.4.8's class-E exception, are in the site-amplification
#: tables of the USGS U.S. Seismic Design Maps web application, SiteAmplification.js).
_SS_POINTS_G = (0.25, 0.50, 0.75, 1.00, 1.25, 1.50)
_FA_TABLE = {
    "A": (0.8, 0.8, 0.8, 0.8, 0.8, 0.8),
    "B": (0.9, 0.9, 0.9, 0.9, 0.9, 0.9),
    "C": (1.3, 1.3, 1.2, 1.2, 1.2, 1.2),
    "D": (1.6, 1.4, 1.2, 1.1, 1.0, 1.0),
    # SS >= 1.0: "see §11.4.8" in the table; its exception 1 takes site class C's Fa (1.2)
    "E": (2.4, 1.7, 1.3, 1.2, 1.2, 1.2),
}
#: ASCE 7-16 Table 11.4-2: Fv at S1 = 0.1, 0.2, 0.3, 0.4, 0.5, 0.6.
_S1_POINTS_G = (0.10, 0.20, 0.30, 0.40, 0.50, 0.60)
_FV_TABLE = {
    "A": (0.8, 0.8, 0.8, 0.8, 0.8, 0.8),
    "B": (0.8, 0.8, 0.8, 0.8, 0.8, 0.8),
    "C": (1.5, 1.5, 1.5, 1.5, 1.5, 1.4),
    "D": (2.4, 2.2, 2.0, 1.9, 1.8, 1.7),
    "E": (4.2, 3.3, 2.8, 2.4, 2.2, 2.0),
}
#: Fa of site class D "by default" is not taken below this (ASCE 7-16 §11.4.4).
DEFAULT_D_MINIMUM_FA = 1.2
#: Site classes of each edition (ASCE 7-16 Table 20.3-1; ASCE 7-22 Table 20.2-1).
SITE_CLASSES_7_16 = ("A", "B", "C", "D", "E", "F")
SITE_CLASSES_7_22 = ("A", "B", "BC", "C", "CD", "D", "DE", "E", "F")


# --------------------------------------------------------------------------- physics

def design_spectral_acceleration_g(period_s, sds_g, sd1_g, tl_s=None):
    """Design spectral acceleration Sa [g] (ASCE 7-16 §11.4.6, eqs. 11.4-5 to 11.4-8;
    ASCE 7-22 §11.4.5.2, the two-period spectrum).

    .. math::

        S_a = \\begin{cases}
          S_{DS}\\,(0.4 + 0.6\\,T/T_0) & T < T_0 \\\\
          S_{DS} & T_0 \\le T \\le T_S \\\\
          S_{D1}/T & T_S < T \\le T_L \\\\
          S_{D1} T_L / T^2 & T > T_L
        \\end{cases}
        \\qquad T_0 = 0.2\\,S_{D1}/S_{DS}, \\quad T_S = S_{D1}/S_{DS}.

    Parameters
    ----------
    period_s : float or array_like
        Periods T [s], ≥ 0.
    sds_g, sd1_g : float
        Design spectral accelerations at short periods and at 1 s [g], > 0.
    tl_s : float or None
        Long-period transition period TL [s]; None: no T > TL branch.

    Returns
    -------
    ndarray
        Sa [g], the shape of ``period_s``.

    Examples
    --------
    SDS = 1.0 g, SD1 = 0.6 g, TL = 8 s: T0 = 0.12 s, TS = 0.6 s;
    Sa(0) = 0.4, Sa(0.06) = 0.7, Sa(0.3) = 1.0, Sa(1.2) = 0.5, Sa(10) = 0.6·8/100 = 0.048:

    >>> [round(float(x), 6) for x in design_spectral_acceleration_g([0, 0.06, 0.3, 1.2, 10], 1.0, 0.6, 8.0)]
    [0.4, 0.7, 1.0, 0.5, 0.048]
    """
    period = np.asarray(period_s, dtype=float)
    t0, ts = 0.2 * sd1_g / sds_g, sd1_g / sds_g
    safe = np.where(period > 0, period, 1.0)
    sa = np.where(period < t0, sds_g * (0.4 + 0.6 * period / t0),
                  np.where(period <= ts, sds_g, sd1_g / safe))
    if tl_s is not None:
        sa = np.where(period > tl_s, sd1_g * tl_s / safe ** 2, sa)
    return sa


def _interpolated(points, values, x):
    """Linear interpolation in a code table, constant beyond its ends (the tables' "≤" and "≥" columns)."""
    return float(np.interp(x, points, values))


def site_coefficient_fa(ss_g, site_class, *, default_class=False):
    """Short-period site coefficient Fa (ASCE 7-16 Table 11.4-1, linear interpolation).

    Parameters
    ----------
    ss_g : float
        Mapped MCE_R spectral acceleration at 0.2 s, SS [g].
    site_class : str
        ``A``, ``B``, ``B (unmeasured)``, ``C``, ``D`` or ``E``.
    default_class : bool
        Site class D chosen by default (§11.4.3): Fa ≥ 1.2 (§11.4.4).

    Examples
    --------
    Site class D, SS = 1.325 g, by default: table 1.0, raised to 1.2 (ENERCALC's ASCE 7-16
    example for a Santa Ana permit, Fa = 1.20):

    >>> site_coefficient_fa(1.325, "D", default_class=True), site_coefficient_fa(0.6, "D")
    (1.2, 1.32)
    """
    if site_class == "B (unmeasured)":
        return 1.0
    value = round(_interpolated(_SS_POINTS_G, _FA_TABLE[site_class], ss_g), 12)
    if default_class and site_class == "D":
        value = max(value, DEFAULT_D_MINIMUM_FA)
    return value


def site_coefficient_fv(s1_g, site_class):
    """Long-period site coefficient Fv (ASCE 7-16 Table 11.4-2, linear interpolation).

    Examples
    --------
    Site class D, S1 = 0.47201 g: 1.9 − 0.7201·0.1 = 1.828 (ENERCALC's example: Fv = 1.83):

    >>> round(site_coefficient_fv(0.47201, "D"), 4)
    1.828
    """
    if site_class == "B (unmeasured)":
        return 1.0
    return round(_interpolated(_S1_POINTS_G, _FV_TABLE[site_class], s1_g), 12)


# --------------------------------------------------------------------------- the site's spectrum

@dataclass(frozen=True)
class DesignSpectrum:
    """The design and MCE_R spectra of a site (ASCE 7), with where their numbers came from.

    Attributes
    ----------
    code : str
        ``ASCE 7-22`` or ``ASCE 7-16``.
    sds_g, sd1_g : float
        Design spectral accelerations [g].
    tl_s : float or None
        Long-period transition period [s]; None: not given (no T > TL branch).
    site_class : str or None
        As given (None when SDS and SD1 were given).
    fa, fv : float or None
        Site coefficients used (None when SDS and SD1 were given).
    ss_g, s1_g : float or None
        Mapped MCE_R accelerations given.
    notes : tuple of str
        Every choice the code left open, in words for the report.
    """

    code: str
    sds_g: float
    sd1_g: float
    tl_s: float | None = None
    site_class: str | None = None
    fa: float | None = None
    fv: float | None = None
    ss_g: float | None = None
    s1_g: float | None = None
    notes: tuple[str, ...] = field(default_factory=tuple)

    @property
    def sms_g(self) -> float:
        """MCE_R spectral acceleration at short periods [g] (1.5 SDS)."""
        return MCE_R_OVER_DESIGN * self.sds_g

    @property
    def sm1_g(self) -> float:
        """MCE_R spectral acceleration at 1 s [g] (1.5 SD1)."""
        return MCE_R_OVER_DESIGN * self.sd1_g

    @property
    def t0_s(self) -> float:
        return 0.2 * self.sd1_g / self.sds_g

    @property
    def ts_s(self) -> float:
        return self.sd1_g / self.sds_g

    def design_g(self, period_s):
        """Design spectrum Sa [g] at ``period_s`` (:func:`design_spectral_acceleration_g`)."""
        return design_spectral_acceleration_g(period_s, self.sds_g, self.sd1_g, self.tl_s)

    def mce_r_g(self, period_s):
        """MCE_R spectrum Sa [g]: 1.5 times the design spectrum (ASCE 7-16 §11.4.7)."""
        return MCE_R_OVER_DESIGN * self.design_g(period_s)

    def target_g(self, level_name: str, period_s):
        """The target spectrum of a level named ``DE`` or ``MCE_R`` (case-insensitive)."""
        key = level_name.strip().upper().replace("-", "_")
        if key == "DE":
            return self.design_g(period_s)
        if key in ("MCE_R", "MCER", "MCE"):
            return self.mce_r_g(period_s)
        raise ValueError(f"level {level_name!r} names no ASCE 7 spectrum (DE or MCE_R)")


def from_design_values(sds_g, sd1_g, tl_s=None, code=ASCE_7_22) -> DesignSpectrum:
    """The site's spectra from SDS, SD1 (and TL) as a hazard lookup gives them.

    >>> s = from_design_values(1.0, 0.6, 8.0)
    >>> round(s.sms_g, 6), round(s.ts_s, 6), round(float(s.mce_r_g(1.2)), 6)
    (1.5, 0.6, 0.75)
    """
    notes = [f"{code}: design spectrum from SDS {sds_g:g} g and SD1 {sd1_g:g} g"
             + (" (§11.4.5.2, the two-period spectrum)" if code == ASCE_7_22 else " (§11.4.6)")]
    if code == ASCE_7_22:
        notes.append("ASCE 7-22 asks the multi-period spectrum of the USGS lookup for response-history "
                     "analysis (§11.4.5.1); the two-period spectrum stands in for it here")
    notes.extend(_tl_notes(tl_s))
    return DesignSpectrum(code, float(sds_g), float(sd1_g), None if tl_s is None else float(tl_s),
                          notes=tuple(notes))


def _tl_notes(tl_s):
    if tl_s is None:
        return ["TL not given: SD1/T is kept at every period (no T > TL branch), which is conservative"]
    return []


def from_mapped_values(ss_g, s1_g, site_class, tl_s=None, code=ASCE_7_22) -> DesignSpectrum:
    """The site's spectra from SS, S1 and the site class through ASCE 7-16's site coefficients.

    SMS = Fa SS, SM1 = Fv S1 (ASCE 7-16 eqs. 11.4-1, 11.4-2), SDS = 2/3 SMS, SD1 = 2/3 SM1
    (eqs. 11.4-3, 11.4-4). ``site_class`` is ``A``, ``B``, ``B (unmeasured)``, ``C``, ``D``,
    ``D (default)`` or ``E`` (see the module docstring for §11.4.3-§11.4.8 and for ASCE 7-22).

    Raises
    ------
    ValueError
        A site class the code gives no coefficients for here (F; BC, CD, DE or default under
        ASCE 7-22), with the reason.

    Examples
    --------
    ENERCALC's ASCE 7-16 example (Santa Ana building permit): SS 1.325 g, S1 0.47201 g, site
    class D by default: SMS 1.590, SM1 0.863, SDS 1.060, SD1 0.575 g.

    >>> s = from_mapped_values(1.325, 0.47201, "D (default)", code="ASCE 7-16")
    >>> round(s.sms_g, 3), round(s.sm1_g, 3), round(s.sds_g, 3), round(s.sd1_g, 3)
    (1.59, 0.863, 1.06, 0.575)
    """
    site_class = str(site_class).strip()
    key = site_class.upper()
    default_class = key in ("D (DEFAULT)", "DEFAULT", "D-DEFAULT")
    notes = []
    if code == ASCE_7_22:
        if key in ("BC", "CD", "DE") or default_class:
            raise ValueError(
                f"ASCE 7-22 gives no site coefficients for site class {site_class}: it takes SMS and SM1 "
                "for that class from the USGS Seismic Design Geodatabase")
        notes.append("ASCE 7-22 takes SMS and SM1 from the USGS lookup; from SS and S1 the site "
                     "coefficients of ASCE 7-16 Tables 11.4-1 and 11.4-2 are used")
    if key == "F":
        raise ValueError("site class F needs a site response analysis (ASCE 7-16 §20.3.1, §11.4.8): "
                         "give the resulting SDS and SD1")
    if key in ("B (UNMEASURED)", "B-ESTIMATED", "B (ESTIMATED)"):
        table_class = "B (unmeasured)"
        notes.append("site class B without measured shear-wave velocity: Fa = Fv = 1.0 (ASCE 7-16 §11.4.3)")
    elif default_class:
        table_class = "D"
        notes.append("site class D by default: Fa not less than 1.2 (ASCE 7-16 §11.4.4)")
    elif key in _FA_TABLE:
        table_class = key
    else:
        raise ValueError(f"unknown site class {site_class!r}")
    fa = site_coefficient_fa(ss_g, table_class, default_class=default_class)
    fv = site_coefficient_fv(s1_g, table_class)
    if table_class == "E" and ss_g >= 1.0:
        notes.append("site class E with SS ≥ 1.0: Fa of site class C (ASCE 7-16 §11.4.8, exception 1)")
    if table_class in ("D", "E") and s1_g >= 0.2:
        notes.append(f"site class {table_class} with S1 ≥ 0.2 g: ASCE 7-16 §11.4.8 asks a site-specific "
                     "ground-motion hazard analysis; Table 11.4-2's Fv is used for this target")
    sds, sd1 = 2.0 / 3.0 * fa * ss_g, 2.0 / 3.0 * fv * s1_g
    notes.append(f"Fa = {fa:.3g}, Fv = {fv:.3g}: SMS = {fa * ss_g:.3g} g, SM1 = {fv * s1_g:.3g} g, "
                 f"SDS = {sds:.3g} g, SD1 = {sd1:.3g} g")
    notes.extend(_tl_notes(tl_s))
    return DesignSpectrum(code, sds, sd1, None if tl_s is None else float(tl_s), site_class=site_class,
                          fa=fa, fv=fv, ss_g=float(ss_g), s1_g=float(s1_g), notes=tuple(notes))


# --------------------------------------------------------------------------- a spectrum given as points

def tabulated_target(period_s, sa_g):
    """A target spectrum given as points (e.g. ASCE 7-22's multi-period spectrum from the USGS
    lookup): Sa [g] at any period by linear interpolation in log(T)-log(Sa), refusing to
    extrapolate (ValueError).

    >>> f = tabulated_target([0.1, 1.0], [1.0, 0.1])
    >>> round(float(f(0.316227766)), 6)
    0.316228
    """
    points = np.asarray(period_s, dtype=float)
    values = np.asarray(sa_g, dtype=float)
    if points.size < 2 or np.any(np.diff(points) <= 0) or np.any(points <= 0) or np.any(values <= 0):
        raise ValueError("a tabulated spectrum needs two or more increasing positive periods and positive Sa")

    def target(period):
        period = np.asarray(period, dtype=float)
        if np.any(period < points[0] * (1 - 1e-9)) or np.any(period > points[-1] * (1 + 1e-9)):
            raise ValueError(f"period outside the tabulated range {points[0]:g}-{points[-1]:g} s")
        clipped = np.clip(period, points[0], points[-1])
        return np.exp(np.interp(np.log(clipped), np.log(points), np.log(values)))
    return target
