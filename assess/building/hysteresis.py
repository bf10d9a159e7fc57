"""Storey springs with hysteresis: the force-drift laws of the yielding stick (:mod:`assess.building.nonlinear`).

Three laws, each a pure function of the spring's committed state and a trial drift
(path-dependent through that state only, as a finite-element material is):

* **Bilinear with kinematic hardening** (:func:`bilinear_trial`), for steel frames and
  braces: elastic stiffness k_0 up to the yield force F_y, then b k_0; unloading at
  k_0; the elastic range stays 2 F_y wide and travels with the hardening line. It is
  the bilinear hysteresis of Clough [1]_ without stiffness degradation, and OpenSees'
  ``Steel01`` with no isotropic hardening (a_1 = a_3 = 0), the bilinear limit of the
  Menegotto-Pinto law as Filippou et al. [2]_ use it.

  .. math::  F = \\min\\big(\\max(F_c + k_0\\,(d - d_c),\\; b k_0 d - (1-b)F_y),\\; b k_0 d + (1-b)F_y\\big)

* **Stiffness-degrading, pinching** (:func:`pinching_trial`), for concrete frames and
  walls: the same bilinear backbone (envelope), unloading at k_0 (d_max/d_y)^-β (the
  unloading rule of Takeda, Sozen & Nielsen [3]_, β = 0.4 there), reloading towards
  the largest drift reached in that direction through a pinching point at
  (pinch_x of the way, pinch_y of the force) — the rules of OpenSees' ``Hysteretic``
  material (a modified Clough/Takeda law after Park, Reinhorn & Kunnath [4]_) with a
  bilinear hardening backbone and no strength-damage terms (damage1 = damage2 = 0),
  re-written here from its published rules and its source (:func:`hysteretic_trial`, on
  any trilinear backbone, each side its own). Its degrading, pinched loops dissipate
  less energy per cycle than the bilinear ones at the same ductility.

* **Buckling braces** (``buckling``, :func:`brace_backbones`), for a special
  concentrically braced frame, which yields by "brace buckling and yielding of the brace in
  tension" (AISC 341-16 §F2.1 [5]_): the storey is its two braces, one pulled and one pushed,
  each the Hysteretic law on its own backbone (mirrored: the pulled brace's tension side is
  the pushed one's), as OpenSees builds them with two ``Hysteretic`` materials in
  ``Parallel``. The pushed brace buckles at :data:`BRACE_BUCKLING_RATIO` of its tension
  yield (AISC 360-16 eq. E3-2 [6]_) and falls to :data:`BRACE_POST_BUCKLING_RATIO` of that
  (AISC 341-16 §F2.3's expected post-buckling strength); pinched loops (a buckled brace
  carries little until pulled straight), no unloading degradation. Pushed one way the
  storey's force rises past its first yield until the pulled brace yields, then falls.

References
----------
.. [1] Clough, R. W., Johnston, S. B. (1966). Effect of stiffness degradation on
   earthquake ductility requirements. Proc. 2nd Japan Earthquake Eng. Symp., 227-232.
.. [2] Filippou, F. C., Popov, E. P., Bertero, V. V. (1983). Effects of bond
   deterioration on hysteretic behavior of reinforced concrete joints. Report
   UCB/EERC-83/19, University of California, Berkeley.
.. [3] Takeda, T., Sozen, M. A., Nielsen, N. N. (1970). Reinforced concrete response
   to simulated earthquakes. J. Struct. Div. ASCE 96(ST12):2557-2573.
.. [4] Park, Y. J., Reinhorn, A. M., Kunnath, S. K. (1987). IDARC: Inelastic damage
   analysis of reinforced concrete frame-shear-wall structures. Report NCEER-87-0008.
   OpenSees ``Hysteretic`` material: https://opensees.berkeley.edu/wiki/index.php/Hysteretic_Material
   (SRC/material/uniaxial/HystereticMaterial.cpp).
.. [5] ANSI/AISC 341-16 (2016). Seismic Provisions for Structural Steel Buildings. §F2 (special
   concentrically braced frames), as help.idecad.com's page on §F2 and an eng-tips thread on §F2.3 give it.
.. [6] ANSI/AISC 360-16 (2016). Specification for Structural Steel Buildings. §E3 (flexural buckling).
"""
from __future__ import annotations

import numpy as np
from numba import njit

#: Law codes the compiled kernel dispatches on.
BILINEAR = 0
PINCHING = 1
BUCKLING = 2
LAWS = {"bilinear": BILINEAR, "pinching": PINCHING, "buckling": BUCKLING}

#: Slots of a hysteretic spring's state vector (committed or trial); a storey of buckling braces holds two.
_STRAIN, _STRESS, _TANGENT, _ROT_MAX, _ROT_MIN, _ROT_PU, _ROT_NU, _LOAD = range(8)
HYSTERETIC_SIZE = 8
#: A storey spring's state: the pulled brace's hysteretic state, then the pushed one's (the first alone otherwise).
STATE_SIZE = 2 * HYSTERETIC_SIZE
_BIG = 1.0e16  # OpenSees' POS_INF_STRAIN

#: Slots of a hysteretic spring's parameters: its backbone's three points on each side (drift, force), the
#: negative side's negative, then pinch_x, pinch_y and the unloading exponent β.
_R1P, _M1P, _R2P, _M2P, _R3P, _M3P, _R1N, _M1N, _R2N, _M2N, _R3N, _M3N, _PINCH_X, _PINCH_Y, _BETA = range(15)
PARAMETERS = 15

#: A brace's buckling strength over its tension yield strength, F_cr/F_y: AISC 360-16 eq. E3-2,
#: F_cr = 0.658^(F_y/F_e) F_y with F_e = π² E/(KL/r)², is 0.55 F_y at KL/r 90 and F_y 345 MPa (0.77 at 60, 0.32
#: at 120); 0.5 taken. The storey's pushed brace buckles at the storey's yield drift, where the storey carries
#: its F_y, and the pulled one yields in tension at 1/0.5 = 2 times that drift.
BRACE_BUCKLING_RATIO = 0.5
#: What a buckled brace keeps of its buckling strength: AISC 341-16 §F2.3(b)'s expected post-buckling strength,
#: 0.3 times the expected compressive strength (as an eng-tips thread on SCBF beams quotes it,
#: eng-tips.com/threads/design-of-beams-in-special-concentric-braced-frames.562823).
BRACE_POST_BUCKLING_RATIO = 0.3
#: The drift, over the buckling drift, at which the buckled brace is down to that strength (a judgement).
BRACE_POST_BUCKLING_DRIFT_RATIO = 5.0
#: The braces' loops' pinching (pinch_x, pinch_y): a buckled brace carries little until it is pulled straight
#: again (a judgement); no unloading degradation (β 0).
BRACE_PINCH = (0.4, 0.2)
#: Drift, over the yield drift, of the backbones' last points (the hardening goes on beyond).
_LAST_POINT = 100.0


@njit(cache=True)
def bilinear_trial(drift, committed_drift, committed_force, stiffness, yield_force, hardening):  # pragma: no cover
    """(force, tangent) of the bilinear kinematic-hardening spring at a trial drift [m] from its committed state."""
    force = committed_force + stiffness * (drift - committed_drift)
    upper = hardening * stiffness * drift + (1.0 - hardening) * yield_force
    lower = hardening * stiffness * drift - (1.0 - hardening) * yield_force
    if force > upper:
        return upper, hardening * stiffness
    if force < lower:
        return lower, hardening * stiffness
    return force, stiffness


@njit(cache=True)
def _side(p, sign):  # pragma: no cover - compiled
    """One side of the backbone of ``p`` (a :data:`PARAMETERS` row), ``sign`` +1 the positive side and -1 the
    negative one (its points negative): its points r_1, m_1, r_2, m_2, r_3, m_3 and slopes e_1, e_2, e_3."""
    o = _R1P if sign > 0.0 else _R1N
    r1, m1, r2, m2, r3, m3 = p[o], p[o + 1], p[o + 2], p[o + 3], p[o + 4], p[o + 5]
    return r1, m1, r2, m2, r3, m3, m1 / r1, (m2 - m1) / (r2 - r1), (m3 - m2) / (r3 - r2)


@njit(cache=True)
def _envelope(strain, p, sign):  # pragma: no cover - compiled
    """Backbone (force, tangent) on the ``sign`` side (OpenSees' ``posEnvlpStress`` and ``negEnvlpStress``)."""
    r1, m1, r2, m2, r3, m3, e1, e2, e3 = _side(p, sign)
    if sign * strain <= 0.0:
        return 0.0, e1 * 1.0e-9
    if sign * strain <= sign * r1:
        return e1 * strain, e1
    if sign * strain <= sign * r2:
        return m1 + e2 * (strain - r1), e2
    if sign * strain <= sign * r3 or e3 > 0.0:
        return m2 + e3 * (strain - r2), e3
    return m3, e1 * 1.0e-9


@njit(cache=True)
def _release_limit(strain, p, sign):  # pragma: no cover - compiled
    """Where a softening branch of the envelope reached at ``strain`` (on the ``sign`` side) would cross zero
    force: reloading towards the other side starts there at the latest (OpenSees' ``posEnvlpRotlim`` and
    ``negEnvlpRotlim``); ±:data:`_BIG` where it has no softening branch."""
    r1, m1, r2, m2, _, _, _, e2, e3 = _side(p, sign)
    limit = sign * _BIG
    if sign * strain <= sign * r1:
        return limit
    if sign * strain <= sign * r2 and e2 < 0.0:
        limit = r1 - m1 / e2
    if sign * strain > sign * r2 and e3 < 0.0:
        limit = r2 - m2 / e3
    if limit == sign * _BIG:
        return limit
    return sign * _BIG if sign * _envelope(limit, p, sign)[0] > 0.0 else limit


@njit(cache=True)
def _unloading(committed, p, sign):  # pragma: no cover - compiled
    """(the stiffness unloading from the ``sign`` side at its committed peak, that side's undegraded one): the
    steepest of its backbone's slopes, times (peak/r_1)^-β once the peak is past r_1 (Takeda's rule)."""
    r1, _, _, _, _, _, e1, e2, e3 = _side(p, sign)
    steepest = max(e1, e2, e3)
    factor = (committed[_ROT_MAX if sign > 0.0 else _ROT_MIN] / r1) ** p[_BETA]
    return steepest * (1.0 if factor < 1.0 else 1.0 / factor), steepest


@njit(cache=True)
def hysteretic_trial(committed, trial, strain, p):  # pragma: no cover - compiled
    """Trial state (written into ``trial``) of a pinching, stiffness-degrading spring at drift ``strain``.

    ``committed`` and ``trial`` are state vectors of :data:`HYSTERETIC_SIZE`, ``p`` the spring's
    :data:`PARAMETERS` row: the rules of OpenSees' Hysteretic material on its trilinear backbone, each side
    its own, with no damage terms (damage1 = damage2 = 0). Moving towards side ``sign`` (OpenSees'
    ``positiveIncrement`` for +1, ``negativeIncrement`` its mirror for -1), the spring unloads from the other
    side, then reloads through the pinching point towards the largest drift reached on this one.
    """
    for s in range(HYSTERETIC_SIZE):
        trial[s] = committed[s]
    load = committed[_LOAD]
    if load == 0.0 and strain == 0.0:
        return
    d_strain = strain - committed[_STRAIN]
    if abs(d_strain) < 2.220446049250313e-16:
        return
    trial[_STRAIN] = strain
    if strain >= committed[_ROT_MAX]:
        trial[_ROT_MAX] = strain
        trial[_STRESS], trial[_TANGENT] = _envelope(strain, p, 1.0)
        trial[_LOAD] = 1.0
        return
    if strain <= committed[_ROT_MIN]:
        trial[_ROT_MIN] = strain
        trial[_STRESS], trial[_TANGENT] = _envelope(strain, p, -1.0)
        trial[_LOAD] = 2.0
        return
    sign = 1.0 if d_strain > 0.0 else -1.0
    peak, away = (_ROT_MAX, _ROT_MIN) if sign > 0.0 else (_ROT_MIN, _ROT_MAX)
    release = _ROT_NU if sign > 0.0 else _ROT_PU  # where the force from the other side reached zero
    towards, towards_elastic = _unloading(committed, p, sign)
    back, back_elastic = _unloading(committed, p, -sign)
    c_stress = committed[_STRESS]
    pinch_x, pinch_y = p[_PINCH_X], p[_PINCH_Y]
    if load == (2.0 if sign > 0.0 else 1.0) and sign * c_stress <= 0.0:
        trial[release] = committed[_STRAIN] - c_stress / back
    trial[_LOAD] = 1.0 if sign > 0.0 else 2.0
    rot_peak = sign * max(min(sign * trial[peak], _BIG), sign * p[_R1P if sign > 0.0 else _R1N])
    trial[peak] = rot_peak
    peak_force = _envelope(rot_peak, p, sign)[0]
    rot_rel = sign * max(sign * _release_limit(committed[away], p, -sign), sign * trial[release])
    rot_mp2 = rot_peak - (1.0 - pinch_y) * peak_force / towards
    rot_ch = rot_rel + (rot_mp2 - rot_rel) * pinch_x
    if sign * strain < sign * trial[release]:  # still unloading from the other side
        tangent = back
        stress = c_stress + tangent * d_strain
        if sign * stress >= 0.0:
            stress, tangent = 0.0, back_elastic * 1.0e-9
    elif sign * strain < sign * rot_ch:  # towards the pinching point
        if sign * strain <= sign * rot_rel:
            stress, tangent = 0.0, towards_elastic * 1.0e-9
        else:
            tangent = peak_force * pinch_y / (rot_ch - rot_rel)
            unloading = c_stress + towards * d_strain
            stress = (strain - rot_rel) * tangent
            if sign * unloading < sign * stress:
                stress, tangent = unloading, towards
    else:  # from the pinching point towards the peak
        tangent = (1.0 - pinch_y) * peak_force / (rot_peak - rot_ch)
        unloading = c_stress + towards * d_strain
        stress = pinch_y * peak_force + (strain - rot_ch) * tangent
        if sign * unloading < sign * stress:
            stress, tangent = unloading, towards
    trial[_STRESS] = stress
    trial[_TANGENT] = tangent


@njit(cache=True)
def spring_trial(law, committed, trial, strain, k0, fy, hardening, p):  # pragma: no cover - compiled
    """(force, tangent) of one storey spring of law ``law`` at a trial drift, its trial state written into
    ``trial``; ``committed`` and ``trial`` of :data:`STATE_SIZE`, ``p`` its :func:`spring_parameters` (2 rows)."""
    if law == BILINEAR:
        force, tangent = bilinear_trial(strain, committed[_STRAIN], committed[_STRESS], k0, fy, hardening)
        trial[_STRAIN], trial[_STRESS], trial[_TANGENT] = strain, force, tangent
        return force, tangent
    hysteretic_trial(committed[:HYSTERETIC_SIZE], trial[:HYSTERETIC_SIZE], strain, p[0])
    force, tangent = trial[_STRESS], trial[_TANGENT]
    if law == BUCKLING:
        hysteretic_trial(committed[HYSTERETIC_SIZE:], trial[HYSTERETIC_SIZE:], strain, p[1])
        force += trial[HYSTERETIC_SIZE + _STRESS]
        tangent += trial[HYSTERETIC_SIZE + _TANGENT]
    return force, tangent


def bilinear_backbone(k0, fy, hardening, pinch_x, pinch_y, beta) -> np.ndarray:
    """The :data:`PARAMETERS` row of a pinching spring on a symmetric bilinear backbone: k_0 to F_y, then b k_0
    (OpenSees' Hysteretic with rot1 = F_y/k_0 and E_2 = E_3 = b k_0)."""
    dy = fy / k0
    points = [(dy, fy), *((r * dy, fy + hardening * k0 * (r - 1.0) * dy) for r in (_LAST_POINT / 2, _LAST_POINT))]
    return np.array([v for d, f in points for v in (d, f)] + [-v for d, f in points for v in (d, f)]
                    + [pinch_x, pinch_y, beta])


def brace_backbones(k0, fy, hardening) -> np.ndarray:
    """The two :data:`PARAMETERS` rows of a storey of buckling braces, k_0 and F_y the storey's (its first
    nonlinearity, the pushed brace buckling): the pulled brace, then the pushed one, its mirror.

    Each brace has half the storey's stiffness; it buckles at :data:`BRACE_BUCKLING_RATIO` of its tension yield
    force F_t, at the storey's yield drift d_y = F_y/k_0 (so F_t = F_y/(2 × that ratio)), falls to
    :data:`BRACE_POST_BUCKLING_RATIO` of its buckling force at :data:`BRACE_POST_BUCKLING_DRIFT_RATIO` d_y and keeps
    it; pulled, it yields at F_t and hardens at ``hardening`` of its stiffness. Pushed one way the storey
    carries F_y at d_y, then more until the pulled brace yields, then less as the pushed one loses its strength.
    """
    kb = k0 / 2.0
    dy = fy / k0
    tension = fy / (2.0 * BRACE_BUCKLING_RATIO)
    dt = tension / kb
    pulled = [(dt, tension), *((r * dt, tension + hardening * kb * (r - 1.0) * dt) for r in (_LAST_POINT / 2,
                                                                                              _LAST_POINT))]
    buckling = BRACE_BUCKLING_RATIO * tension
    after = BRACE_POST_BUCKLING_RATIO * buckling
    pushed = [(dy, buckling), (BRACE_POST_BUCKLING_DRIFT_RATIO * dy, after), (_LAST_POINT * dy, after)]
    pinch = [*BRACE_PINCH, 0.0]
    return np.array([[v for d, f in pulled for v in (d, f)] + [-v for d, f in pushed for v in (d, f)] + pinch,
                     [v for d, f in pushed for v in (d, f)] + [-v for d, f in pulled for v in (d, f)] + pinch])


def spring_parameters(law, k0, fy, hardening, pinch_x=0.8, pinch_y=0.4, beta=0.4) -> np.ndarray:
    """The (2, :data:`PARAMETERS`) parameters of one spring of law ``law`` (a name of :data:`LAWS`) as
    :func:`spring_trial` takes them: the bilinear law's are unused, the pinching law's second row too."""
    if law == "buckling":
        return brace_backbones(k0, fy, hardening)
    row = bilinear_backbone(k0, fy, hardening, pinch_x, pinch_y, beta)
    return np.array([row, row])


@njit(cache=True)
def _cycle(drifts, law, k0, fy, hardening, parameters):  # pragma: no cover - compiled
    """Forces of one spring along a drift path (every point committed)."""
    committed = np.zeros(STATE_SIZE)
    committed[_TANGENT] = k0
    trial = committed.copy()
    out = np.empty(drifts.size)
    for i in range(drifts.size):
        out[i] = spring_trial(law, committed, trial, drifts[i], k0, fy, hardening, parameters)[0]
        committed[:] = trial
    return out


def spring_forces(drift_path_m, law, stiffness_n_m, yield_force_n, hardening=0.03, pinch_x=0.8,
                  pinch_y=0.4, beta=0.4):
    """Force [N] of one storey spring along a drift path [m] (each point a committed state).

    Examples
    --------
    A bilinear spring, k_0 = 100 N/m, F_y = 10 N (d_y = 0.1 m), b = 0.1, pushed to 0.3 m
    (F = 10 + 0.1·100·0.2 = 12 N), then back to 0.1 m (12 - 100·0.2 = -8 N):

    >>> spring_forces([0.1, 0.3, 0.1], "bilinear", 100.0, 10.0, hardening=0.1).round(6).tolist()
    [10.0, 12.0, -8.0]

    A storey of buckling braces, k_0 = 100 N/m, F_y = 10 N, b = 0: at d_y = 0.1 m both braces carry 5 N, the
    pushed one buckling; at 0.2 m the pulled one yields (10 N) and the pushed one has fallen a quarter of the way
    to 1.5 N (4.125 N):

    >>> spring_forces([0.1, 0.2], "buckling", 100.0, 10.0, hardening=0.0).round(6).tolist()
    [10.0, 14.125]
    """
    path = np.ascontiguousarray(drift_path_m, dtype=float)
    k0, fy, b = float(stiffness_n_m), float(yield_force_n), float(hardening)
    return _cycle(path, LAWS[law], k0, fy, b, spring_parameters(law, k0, fy, b, pinch_x, pinch_y, beta))
