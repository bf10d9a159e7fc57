"""The yielding building of a ``building`` sheet: its stick, its floors' histories and what its storeys did.

The building sheet's ``response: yielding`` (by default wherever the storeys' strength is known,
docs/workbook.md) passes each ground motion through a stick of yielding storey springs
(:func:`~assess.building.nonlinear.yielding_stick`: bilinear springs for steel frames and braces,
pinching, stiffness-degrading ones for concrete; Rayleigh damping on the tangent stiffness), or, for a
shear wall, the elastic model on a pinching plastic hinge at its base (:mod:`assess.building.wall_hinge`), started
from the building's elastic model (:func:`~assess.building.modes.building_modes`: the same T_1, α and
storeys' stiffness profile, ``modes.storey_stiffness``) with each storey's strength from
``yield_base_shear_g`` or the code's design times an overstrength
(:func:`~assess.building.design.design_strength`), raised above the code's distribution where the
system's design makes a storey stronger (:data:`~assess.building.nonlinear.STRENGTH_BY_SYSTEM`). A
ground motion under which no storey yields (every storey's ductility below 1) gives the elastic route's
floor histories themselves (:func:`~assess.building.response.floor_records`): a building strong enough to
stay elastic is assessed exactly as the elastic route assesses it. The two models are not the same building at the
threshold, though: for frames (the stick keeps the elastic model's flexural column) the stick's
elastic limit is within 2-25 % RMS of the modal route's histories (Rayleigh against modal damping;
roof PFA 0.98-1.10 times); a wall on its base hinge (the same T_1, its higher modes 2-2.5 % shorter, no
damping on the hinge) within 23-43 % RMS, roof PFA 0.94-1.03 times; but ``other``'s stick is an
equivalent shear stick (a storey spring cannot yield in flexure), whose elastic limit differs from the
shear-flexural modes (α = 1) by 150-185 % RMS with a roof PFA 1.25-1.65 times the modal one (3 to 12
storeys, ``benchmarks/yielding_elastic_limit.py``): a motion that only just yields such a building gets
floor motions noticeably different from one that just does not.

What the storeys did under each motion (peak drift ratio, ductility; for a wall on its base hinge, the
wall's rotation ductility at its base in storey 1's place and none above, where it does not yield) goes to
``floors.csv`` (:func:`storey_table`); a drift ratio beyond :data:`DRIFT_LIMIT_BY_SYSTEM` is beyond what the stick
can be trusted for. The limits are the transient drifts of the *Collapse Prevention* structural
performance level of FEMA 356 [1]_ Table C1-3 (steel moment frames 5 %, concrete frames 4 %,
braced steel frames and concrete walls 2 %): there the building is near collapse, its members lose
strength with every cycle, which the stick's springs (no strength degradation) do not follow, and
its floors' motions are no longer the model's. The building's own collapse is not assessed.

A stick's history depends only on the stick and the ground history, so the same ground history gives
the same floor histories bit for bit: the equipment cases simulated under them are found in the case
cache (:mod:`assess.command.cache`) on the next run, a curve update included. Within a run, the
stick's answers are kept up to :data:`MEMORY_BYTES` (:func:`stick_history`), so that the floors table
and the stripes' onset do not simulate a ground history twice; and a hazard curve's stripes, which pass
each ground history through at many scales, do not run the stick under a copy weaker than one that yielded
no storey (:class:`ElasticBound`: the stick is linear below its first yield).

References
----------
.. [1] FEMA 356 (2000). Prestandard and Commentary for the Seismic Rehabilitation of Buildings.
   Federal Emergency Management Agency. Table C1-3 (structural performance levels and damage:
   vertical elements, drift).
"""
from __future__ import annotations

import hashlib
import threading
import time
from collections import OrderedDict
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, replace
from typing import Callable, Optional, Sequence

import numba
import numpy as np
import pandas as pd

from assess.hazard.records import Record

from .design import DesignStrength, design_strength, importance_factor
from .modes import BuildingModes
from .nonlinear import (FLEXURE_BY_SYSTEM, GRAVITY_M_S2, STRENGTH_BY_SYSTEM, YieldingStick, elastic_periods,
                        yielding_response, yielding_stick)
from .response import floor_records
from .wall_hinge import HingedWall, hinged_periods, hinged_wall_response

#: Storey drift ratio beyond which the stick is not trusted, per lateral system [-]: the Collapse
#: Prevention level's transient drift of FEMA 356 Table C1-3 (module text); ``other`` takes the lowest.
DRIFT_LIMIT_BY_SYSTEM = {
    "steel moment frame": 0.05,
    "concrete moment frame": 0.04,
    "eccentrically braced frame": 0.02,
    "braced frame": 0.02,
    "shear wall": 0.02,
    "other": 0.02,
}
#: The largest stability coefficient θ ASCE 7-22 §12.8.7 lets a building have (0.5/(β C_d), at most 0.25).
STABILITY_COEFFICIENT_MAX = 0.25
#: How the storeys' strengths rise above the code's shares, in the words of the strength's source, by rule
#: (:data:`~assess.building.nonlinear.STRENGTH_BY_SYSTEM`'s, or ``"given"``: the sheet's ``storey_strength``).
STRENGTH_WORDS = {
    "stiffness": "each storey at least as strong as its stiffness makes it at one yield drift ratio, the first to "
                 "yield doing so at that base shear",
    "capacity design": "each storey at least as strong as a capacity-designed wall's linear moment envelope makes it",
    "given": "the storeys as strong against each other as storey_strength gives, the first to yield doing so at that "
             "base shear",
}
#: Bytes of stick answers (every floor's history per ground history) a run keeps, most recent first.
MEMORY_BYTES = 256 * 2 ** 20
#: Which yielding model a building's stick is (:attr:`YieldingBuilding.yielding_model`, ``floors.csv``'s
#: ``yielding_model``): storeys that yield in their springs
#: (:class:`~assess.building.nonlinear.YieldingStick`), or a wall's elastic model on a plastic hinge at its
#: base that yields there only (:class:`~assess.building.wall_hinge.HingedWall`).
STOREY_SPRINGS = "storey springs"
BASE_HINGE = "base hinge"


@dataclass(frozen=True)
class YieldingBuilding:
    """The yielding building the floor route uses, beside the elastic model it starts from.

    Attributes
    ----------
    modes : BuildingModes
        The building's elastic model (its periods and floors; the elastic route's histories where no
        storey yields).
    stick : YieldingStick or HingedWall
        The stick of storey springs, or a wall's elastic model on its base hinge.
    strength : DesignStrength
        Where its storeys' strength came from.
    system : str
        The lateral system.
    drift_limit : float
        :data:`DRIFT_LIMIT_BY_SYSTEM` of the system [-].
    p_delta : bool
        Whether the stick carries the gravity loads' P-Delta stiffness.
    key : str
        A digest of the stick (what its histories depend on), for :func:`yielding_histories`'s memory.
    importance : float
        I_e of the building's risk category (ASCE 7-22 Table 1.5-2), with the system's R and Ω_0 what the code's
        R_μ of its floors is made of (:func:`assess.assessment.floors.with_code_check`) [-].
    """

    modes: BuildingModes
    stick: YieldingStick
    strength: DesignStrength
    system: str
    drift_limit: float
    p_delta: bool
    key: str
    importance: float = 1.0

    @property
    def yielding_model(self) -> str:
        """:data:`BASE_HINGE` where the stick is a wall on its base hinge, else :data:`STOREY_SPRINGS`: the
        model that runs, read from the stick itself."""
        return BASE_HINGE if isinstance(self.stick, HingedWall) else STOREY_SPRINGS

    @property
    def stability_coefficient(self) -> float:
        """θ of the first mode under the gravity loads' P-Delta: 1 − (T_1/T_1,PΔ)², T_1,PΔ the elastic stick's first
        period with the geometric stiffness (0 without P-Delta; inf where it makes the stick unstable).

        For a shear building whose storeys share one θ_i = P_i/(k_i h_i), ω² falls to ω²(1 − θ) (Chopra,
        *Dynamics of Structures*, §18.6): the first mode's θ is that stability coefficient, ASCE 7-22 §12.8.7's
        θ = P Δ/(V h C_d) at the elastic drift (Δ = C_d δ_e), which the code keeps at most 0.5/(β C_d) ≤ 0.25
        (:data:`STABILITY_COEFFICIENT_MAX`).
        """
        if not self.p_delta:
            return 0.0
        periods = hinged_periods(self.stick) if isinstance(self.stick, HingedWall) else elastic_periods(self.stick)
        first = float(periods[0])
        return float(1.0 - (self.periods_s[0] / first) ** 2) if np.isfinite(first) else float("inf")

    @property
    def hardening(self) -> float:
        """The storeys' stiffness after yield over their stiffness before (one for every storey; a wall on its base
        hinge: the assembly's, :attr:`~assess.building.wall_hinge.HingedWall.hardening`)."""
        return float(np.ravel(self.stick.hardening)[0])

    def beyond_drift_limit(self, history: "StickHistory") -> np.ndarray:
        """Which storeys' peak drift passed :attr:`drift_limit` under one ground history (what the stick is
        trusted to): the one test behind ``floors.csv``'s ``motions_beyond_drift_limit`` and the items' flag."""
        return np.asarray(history.peak_drift_ratio) > self.drift_limit

    # the elastic model's description, as the route reads it from BuildingModes
    @property
    def storeys(self) -> int:
        return self.modes.storeys

    @property
    def floor_heights_m(self) -> np.ndarray:
        return self.modes.floor_heights_m

    @property
    def periods_s(self) -> np.ndarray:
        return self.modes.periods_s

    @property
    def n_modes(self) -> int:
        return self.modes.n_modes

    @property
    def effective_mass_ratio(self) -> np.ndarray:
        return self.modes.effective_mass_ratio


def _stick_key(stick) -> str:
    digest = hashlib.blake2b(digest_size=16)
    if isinstance(stick, HingedWall):
        values = (stick.floor_masses_kg, stick.storey_heights_m, stick.assembled_stiffness(0.0),
                  [stick.hinge_stiffness_n_m_rad, stick.reference_stiffness_n_m_rad, stick.yield_moment_n_m,
                   stick.hinge_hardening, stick.stiffness_ratio_n], np.asarray(stick.rayleigh, dtype=float))
        digest.update(b"base hinge|")
    else:
        values = (stick.floor_masses_kg, stick.storey_heights_m, stick.stiffness_n_m, stick.yield_force_n,
                  stick.hardening, stick.linear_stiffness_n_m, np.asarray(stick.rayleigh, dtype=float))
    for value in values:
        digest.update(np.ascontiguousarray(value, dtype=float).tobytes())
    digest.update(f"{stick.law}|{stick.pinch_x}|{stick.pinch_y}|{stick.unloading_beta}|"
                  f"{getattr(stick, 'damping_stiffness', 'elastic part')}".encode())
    return digest.hexdigest()


def yielding_building(modes: BuildingModes, system: str, *, damping: float = 0.05, sds_g=None, sd1_g=None,
                      tl_s=None, s1_g=None, risk_category="II", overstrength=None, yield_base_shear_g=None,
                      p_delta: bool = False, code: str = "ASCE 7-22", hardening=None,
                      law: str | None = None, storey_strength=None) -> YieldingBuilding:
    """The yielding stick of a building whose elastic model is ``modes`` (equal floor masses, uniform storeys).

    The storeys' strength: ``yield_base_shear_g`` where given, else ASCE 7-22 §12.8's design from the site's
    values at the building's T_1 (``modes.periods_s[0]``) times ``overstrength``
    (:func:`~assess.building.design.design_strength`), spread over the storeys by the code's distribution
    and raised where the system's design makes a storey stronger
    (:data:`~assess.building.nonlinear.STRENGTH_BY_SYSTEM`: ``strength.storey_yield_ratio`` is the
    result); the springs' law and the stick's flexure are the system's (:data:`~assess.building.design.LAW_BY_SYSTEM`,
    :data:`~assess.building.nonlinear.FLEXURE_BY_SYSTEM`). The strength's words name ``code``, the site's
    edition (the provisions used read the same in ASCE 7-16 and 7-22). ``hardening``: the storeys' (a wall's base's)
    stiffness after yield over their stiffness before, where the engineer gives the model's; else
    :data:`~assess.building.nonlinear.DEFAULT_HARDENING`. ``law``: the springs' law where not the system's (a braced
    frame's ``buckling`` braces, :func:`~assess.building.hysteresis.brace_backbones`). ``storey_strength``: the
    storeys' strengths against each other where the engineer gives the model's (one positive number per storey,
    :func:`~assess.building.nonlinear.given_strength`), in place of the system's rule; a shear wall whose storeys'
    strengths are given yields storey by storey (a stick of storey springs,
    :func:`~assess.building.nonlinear.yielding_stick`'s ``"equivalent shear"``), not at a base hinge.

    Examples
    --------
    A 4-storey steel moment frame, T_1 0.6 s, at S_DS 1.0, S_D1 0.6: C_s 0.125, yield at 2.5 × 0.125:

    >>> from assess.building.modes import building_modes
    >>> modes = building_modes(4, 4.0, system="steel moment frame", period_s=0.6)
    >>> b = yielding_building(modes, "steel moment frame", sds_g=1.0, sd1_g=0.6)
    >>> round(b.strength.yield_base_shear_g, 4), b.stick.law, b.drift_limit
    (0.3125, 'bilinear', 0.05)
    """
    heights = modes.floor_heights_m[1:]
    storey_heights = np.diff(modes.floor_heights_m)
    period_s = float(modes.periods_s[0])
    flexure = FLEXURE_BY_SYSTEM[system]
    if storey_strength is not None and flexure == "base hinge":
        flexure = "equivalent shear"
    strength = design_strength(system, np.ones(modes.storeys), heights, period_s, sds_g=sds_g, sd1_g=sd1_g,
                               tl_s=tl_s, s1_g=s1_g, risk_category=risk_category, overstrength=overstrength,
                               yield_base_shear_g=yield_base_shear_g, code=code,
                               spread=flexure != "base hinge", hardening=hardening)
    arguments = dict(system=system, period_s=period_s, alpha=modes.alpha, storey_stiffness=modes.storey_stiffness,
                     damping=damping, p_delta=p_delta, hardening=hardening, law=law, flexure=flexure)
    profile = None if storey_strength is None else np.asarray(storey_strength, dtype=float)
    stick = yielding_stick(modes.storeys, storey_heights, strength.storey_yield_ratio, strength_profile=profile,
                           **arguments)
    importance = importance_factor(risk_category)
    if isinstance(stick, HingedWall):  # only the base yields: the storeys above have no yield shear
        strength = replace(strength, storey_yield_ratio=np.concatenate([strength.storey_yield_ratio[:1],
                                                                        np.full(modes.storeys - 1, np.nan)]),
                           source=f"{strength.source}; the wall yields in flexure at its base only, its plastic "
                                  f"hinge carrying the moment of {code} §12.8.3's lateral forces at that base shear, "
                                  "and stays elastic above")
        return YieldingBuilding(modes, stick, strength, system, DRIFT_LIMIT_BY_SYSTEM[system], bool(p_delta),
                                _stick_key(stick), importance)
    code = yielding_stick(modes.storeys, storey_heights, strength.storey_yield_ratio, strength_profile="code",
                          **arguments)
    rule = STRENGTH_BY_SYSTEM[system] if profile is None else "given"
    strength = replace(strength, storey_yield_ratio=strength.storey_yield_ratio * stick.yield_force_n
                       / code.yield_force_n,
                       source=f"{strength.source}; " + STRENGTH_WORDS[rule])
    return YieldingBuilding(modes, stick, strength, system, DRIFT_LIMIT_BY_SYSTEM[system], bool(p_delta),
                            _stick_key(stick), importance)


@dataclass(frozen=True)
class StickHistory:
    """One ground history through the stick: every floor's acceleration (row 0 the ground) and each storey's
    peak drift ratio and ductility; ``elastic`` where no storey yielded (the rows are then the elastic
    route's histories). A wall on its base hinge gives its rotation ductility at the base
    (:mod:`assess.building.wall_hinge`) in the first storey's place and NaN above (those storeys do not
    yield)."""

    floor_accel_g: np.ndarray
    peak_drift_ratio: np.ndarray
    ductility: np.ndarray
    elastic: bool


_MEMORY: "OrderedDict[tuple, StickHistory]" = OrderedDict()
_MEMORY_USED = [0]  # bytes of the histories in _MEMORY
_MEMORY_LOCK = threading.Lock()


def forget() -> None:
    """Empty the memory of :func:`stick_history` (tests)."""
    with _MEMORY_LOCK:
        _MEMORY.clear()
        _MEMORY_USED[0] = 0


def _ground_key(ground_accel_g, dt_s: float) -> tuple:
    """What tells one ground history from another: its interval, its length and a digest of its samples."""
    ground = np.ascontiguousarray(ground_accel_g, dtype=float)
    return float(dt_s), ground.size, hashlib.blake2b(ground.tobytes(), digest_size=16).digest()


def stick_history(building: YieldingBuilding, ground_accel_g, dt_s: float) -> StickHistory:
    """One ground history through ``building`` (module text: the elastic route's histories where no storey
    yields), kept in memory up to :data:`MEMORY_BYTES` of the most recent."""
    ground = np.ascontiguousarray(ground_accel_g, dtype=float)
    key = (building.key, *_ground_key(ground, dt_s))
    with _MEMORY_LOCK:
        if key in _MEMORY:
            _MEMORY.move_to_end(key)
            return _MEMORY[key]
    # the compiled kernels release the GIL
    response = (hinged_wall_response(building.stick, ground, dt_s) if isinstance(building.stick, HingedWall)
                else yielding_response(building.stick, ground, dt_s))
    ductility = response.ductility[np.isfinite(response.ductility)]
    elastic = bool(np.all(ductility < 1.0))
    accel = _elastic_floors(building, ground, dt_s) if elastic else response.floor_accel_g
    out = StickHistory(accel, response.peak_drift_ratio, response.ductility, elastic)
    with _MEMORY_LOCK:
        if key not in _MEMORY:
            _MEMORY[key] = out
            _MEMORY_USED[0] += accel.nbytes
        while _MEMORY_USED[0] > MEMORY_BYTES and len(_MEMORY) > 1:
            _, dropped = _MEMORY.popitem(last=False)
            _MEMORY_USED[0] -= dropped.floor_accel_g.nbytes
    return out


def _elastic_floors(building: YieldingBuilding, ground: np.ndarray, dt_s: float) -> np.ndarray:
    """Every floor's acceleration [g] (row 0 the ground) under a ground history that yields no storey: the
    elastic route's (module text)."""
    history = floor_records(building.modes, [Record(ground, dt_s, "")])
    return np.vstack([history[k][0].accel_g for k in range(building.storeys + 1)])


@dataclass(frozen=True)
class ElasticUnder:
    """What the stick did under a ground history that yielded no storey: the history's scale factor (to the
    unscaled ground history it is a copy of) and each storey's peak drift ratio and ductility there."""

    factor: float
    peak_drift_ratio: np.ndarray
    ductility: np.ndarray


class ElasticBound:
    """For each unscaled ground history passed through one yielding building at several scales (the stripes
    of a hazard curve), the strongest scale under which no storey yielded.

    The stick is linear until its first spring yields, from rest, whatever its springs' law: under a
    weaker copy of a ground history that yielded no storey, no storey yields either and every drift is
    that copy's factor times the stronger one's. Such a copy's floors are the elastic route's histories
    (:func:`stick_history`), found without running the stick (:func:`weaker_elastic_history`); the same
    answers, with less work, in any order of the scales (the stronger first leaves the most to skip).
    """

    def __init__(self):
        self._known: dict[tuple, ElasticUnder] = {}
        self._lock = threading.Lock()

    def below(self, ground: Record, factor: float) -> Optional[ElasticUnder]:
        """What the stick did under the strongest copy of ``ground`` that yielded no storey, where ``ground``
        times ``factor`` is no stronger than it; else None."""
        with self._lock:
            known = self._known.get(_ground_key(ground.accel_g, ground.dt_s))
        return known if known is not None and 0.0 < factor <= known.factor else None

    def learn(self, ground: Record, factor: float, history: StickHistory) -> None:
        """Keep ``history``, the stick under ``ground`` times ``factor``, where it yielded no storey and is the
        strongest such copy so far."""
        if not history.elastic:
            return
        key = _ground_key(ground.accel_g, ground.dt_s)
        with self._lock:
            if key not in self._known or factor > self._known[key].factor:
                self._known[key] = ElasticUnder(float(factor), history.peak_drift_ratio, history.ductility)


def weaker_elastic_history(building: YieldingBuilding, ground_accel_g, dt_s: float, stronger: ElasticUnder,
                           factor: float) -> StickHistory:
    """``ground_accel_g``, a copy ``factor`` times an unscaled ground history of which ``stronger`` is a stronger
    copy that yielded no storey, through ``building`` without running its stick (:class:`ElasticBound`): the
    elastic route's floors, and the stronger copy's drifts and ductilities times ``factor / stronger.factor``."""
    ratio = float(factor) / stronger.factor
    if not 0.0 < ratio <= 1.0:
        raise ValueError("a copy is known to stay elastic only where it is no stronger than one that did")
    ground = np.ascontiguousarray(ground_accel_g, dtype=float)
    return StickHistory(_elastic_floors(building, ground, dt_s), stronger.peak_drift_ratio * ratio,
                        stronger.ductility * ratio, True)


def yielding_histories(building: YieldingBuilding, ground_motions: Sequence[Record],
                       floors: Optional[Sequence[int]] = None, progress: Optional[Callable[[int, int], None]] = None,
                       scaled_from: Optional[tuple[Sequence[Record], Sequence[float], ElasticBound]] = None
                       ) -> tuple[dict[int, list[Record]], list[StickHistory]]:
    """Every ground motion through the yielding building: the floors' histories as records (as
    :func:`~assess.building.response.floor_records` gives them) and each motion's :class:`StickHistory`;
    ``progress(done, total)`` after each motion, where given. With ``scaled_from`` ``(grounds, factors, bound)``,
    motion m is ``grounds[m]`` times ``factors[m]``: one the ``bound`` knows to stay elastic is not run through
    the stick (:class:`ElasticBound`), and the bound learns those that stay elastic."""
    wanted = list(range(building.storeys + 1)) if floors is None else [int(k) for k in floors]
    if any(not 0 <= k <= building.storeys for k in wanted):
        raise ValueError(f"floors must lie between 0 and {building.storeys}")
    out = {k: [] for k in wanted}
    grounds = [np.ascontiguousarray(motion.accel_g, dtype=float) for motion in ground_motions]
    # each motion on its own thread (the kernel releases the GIL): what changes is when, not what
    histories = []
    unscaled, factors, bound = scaled_from if scaled_from is not None else (None, None, None)
    known = [None] * len(grounds) if bound is None else [bound.below(g, f) for g, f in zip(unscaled, factors)]

    def through(m: int) -> StickHistory:
        if known[m] is not None:
            return weaker_elastic_history(building, grounds[m], ground_motions[m].dt_s, known[m], factors[m])
        history = stick_history(building, grounds[m], ground_motions[m].dt_s)
        if bound is not None:
            bound.learn(unscaled[m], factors[m], history)
        return history

    with ThreadPoolExecutor(max(1, min(numba.get_num_threads(), len(grounds)))) as pool:
        for history in pool.map(through, range(len(grounds))):
            histories.append(history)
            if progress is not None:
                progress(len(histories), len(grounds))
    for motion, ground, history in zip(ground_motions, grounds, histories):
        for k in wanted:
            accel = ground.copy() if k == 0 else history.floor_accel_g[k].copy()
            out[k].append(Record(accel, motion.dt_s, motion.name if k == 0 else f"{motion.name} @ floor {k}"))
    return out, histories


#: Seconds between two lines of a pass's progress (:func:`pass_progress`): a pass quicker than this says nothing.
PROGRESS_EVERY_S = 5.0


def pass_progress(progress: Callable[[str], None], lead: str = "") -> Callable[[int, int], None]:
    """``progress(done, total)`` for :func:`yielding_histories` that says "``lead``through the building: done of
    total ground histories" to ``progress`` once :data:`PROGRESS_EVERY_S` have passed since the pass began or
    last said it, and at the end of a pass that said anything."""
    last = [time.monotonic(), False]  # when it last spoke (or began), and whether it has

    def report(done: int, total: int) -> None:
        now = time.monotonic()
        if now - last[0] >= PROGRESS_EVERY_S or (done == total and last[1]):
            progress(f"{lead}through the building: {done} of {total} ground histories")
            last[:] = [now, True]
    return report


def through_building(building, ground_motions: Sequence[Record], floors: Optional[Sequence[int]] = None,
                     progress: Optional[Callable[[int, int], None]] = None,
                     scaled_from: Optional[tuple[Sequence[Record], Sequence[float], ElasticBound]] = None
                     ) -> tuple[dict[int, list[Record]], list[bool]]:
    """The floors' histories under each ground motion, through the building as it is modelled: its elastic
    modes (:class:`~assess.building.modes.BuildingModes`) or its yielding stick (:class:`YieldingBuilding`,
    ``progress`` and ``scaled_from`` as :func:`yielding_histories` takes them); with, for each ground motion,
    whether the stick's storey drift passed :attr:`YieldingBuilding.drift_limit` under it (what the model is
    trusted to; never for the elastic modes)."""
    if isinstance(building, YieldingBuilding):
        records, sticks = yielding_histories(building, ground_motions, floors, progress, scaled_from)
        return records, [bool(building.beyond_drift_limit(stick).any()) for stick in sticks]
    return floor_records(building, ground_motions, floors=floors), [False] * len(ground_motions)


def storey_table(building: YieldingBuilding, histories: Sequence[StickHistory], floors) -> pd.DataFrame:
    """What each storey did over the suite, one row per floor of ``floors`` (storey k below floor k; floor 0
    has none): the columns ``floors.csv`` adds for a yielding building (docs/outputs.md).

    Columns: ``response`` (``yielding``), ``yielding_model`` (:attr:`YieldingBuilding.yielding_model`:
    ``storey springs`` or ``base hinge``), ``yield_base_shear_g``, ``storey_yield_ratio`` (the storey's
    shear, its columns' share included, when its spring yields under the code's lateral forces, over the weight),
    ``storey_spring_yield_ratio`` (the spring's own yield shear over the weight: what ``storey_strength`` gives, the
    same where no column stands apart from the springs; NaN for a wall on its base hinge), ``drift_ratio_median``,
    ``drift_ratio_min``, ``drift_ratio_max`` (peak storey drift over its height), ``ductility_median``,
    ``ductility_min``, ``ductility_max`` (peak drift over the yield drift; a wall on its base hinge: the wall's
    rotation ductility at its base in storey 1, NaN above, as ``storey_yield_ratio``), ``motions_yielded`` (motions
    under which any storey yielded), ``drift_limit`` and ``motions_beyond_drift_limit`` (motions whose storey drift
    passed it).
    """
    drift = np.array([h.peak_drift_ratio for h in histories])
    beyond = np.array([building.beyond_drift_limit(h) for h in histories])
    ductility = np.array([h.ductility for h in histories])
    yielded = int(sum(not h.elastic for h in histories))
    stick = building.stick
    springs = (np.full(building.modes.storeys, np.nan) if isinstance(stick, HingedWall)
               else stick.yield_force_n / (stick.floor_masses_kg.sum() * GRAVITY_M_S2))
    rows = []
    for k in sorted(int(f) for f in floors):
        row = {"response": "yielding", "yielding_model": building.yielding_model,
               "yield_base_shear_g": building.strength.yield_base_shear_g,
               "storey_hardening_ratio": building.hardening, "storey_yield_ratio": np.nan,
               "storey_spring_yield_ratio": np.nan,
               "drift_ratio_median": np.nan, "drift_ratio_min": np.nan, "drift_ratio_max": np.nan,
               "ductility_median": np.nan, "ductility_min": np.nan, "ductility_max": np.nan, "motions_yielded": yielded,
               "drift_limit": building.drift_limit, "motions_beyond_drift_limit": np.nan}
        if k > 0:
            d, mu = drift[:, k - 1], ductility[:, k - 1]
            row.update(storey_yield_ratio=float(building.strength.storey_yield_ratio[k - 1]),
                       storey_spring_yield_ratio=float(springs[k - 1]),
                       drift_ratio_median=float(np.median(d)), drift_ratio_min=float(d.min()),
                       drift_ratio_max=float(d.max()), ductility_median=float(np.median(mu)),
                       ductility_min=float(mu.min()), ductility_max=float(mu.max()),
                       motions_beyond_drift_limit=int(np.sum(beyond[:, k - 1])))
        rows.append(row)
    return pd.DataFrame(rows)
