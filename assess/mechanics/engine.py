"""The engine: which solver answers for a block, and many blocks under many motions.

A block's motion is computed by the fastest solver that is *proved* right for
it, and by the general solver otherwise:

1. **Pure sliding kernel** (:mod:`assess.mechanics.sliding`, exact) when
   :math:`\\mu_s < b/h`. Uplift is then impossible while both corners are on
   the floor: the friction force, at most :math:`\\mu_s N` at the base, has a
   moment about the centre of mass of at most :math:`\\mu_s N h < N b`, which
   the normal forces balance without either corner's share becoming negative
   (moment balance about the centre of mass, [1] §3; [2]).
2. **Pure rocking kernel** (:mod:`assess.mechanics.rocking`) when
   :math:`\\mu_s \\ge b/h`, *checked* after the run: it is kept only if the
   pivot's friction demand |F|/N never exceeded μ_s and its normal force
   stayed positive. With :math:`\\mu_s \\ge \\tan\\alpha` the block cannot
   slide from rest before it uplifts, nor slip at a Housner impact (see the
   rocking module), so these two checks are the whole proof.
3. **General solver** otherwise (slide-rock, flight): the Moreau–Jean
   time-stepping scheme of :mod:`assess.mechanics.timestepping` (which takes
   the intervals where the block rocks on one sticking pivot by the rocking
   kernel's steps), whose results the event-driven solver of
   :mod:`assess.mechanics.event_driven` confirms in the tests.

After the record the floor is at rest and the block is followed for
``tail_s`` more seconds (run-out of sliding, free rocking, or a late
overturning). Every solver takes the floor at rest right after the last
sample (the floor motion is zero after the record, and after Tp for a pulse): a step there,
not a ramp down over one more sample interval, so that a pulse ending at full
amplitude (Type B) pushes the block for the same time in each.

References
----------
.. [1] Konstantinidis, D., Makris, N. (2010). Bull. Earthquake Eng.
   8:1457-1477, §3. doi:10.1007/s10518-010-9192-8
.. [2] Shenton, H. W. (1996). Criteria for initiation of slide, rock, and
   slide-rock rigid-body modes. J. Eng. Mech. 122(7):690-693.
   doi:10.1061/(ASCE)0733-9399(1996)122:7(690)
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from time import perf_counter, process_time
from typing import Callable, Optional, Sequence

import numpy as np

from .block import Block, BlockResponse
from .event_driven import simulate_event_driven
from .interface import elastic_interface_response, velocity_friction_response
from .modes import REST, ROCK, SLIDE
from .rocking import rocking_case_peaks, rocking_response
from .sliding import sliding_peaks_batch, sliding_response
from .timestepping import simulate_time_stepping, time_stepping_case_peaks
from . import warmup

SLIDING_KERNEL = "sliding kernel"
VELOCITY_FRICTION_KERNEL = "sliding kernel (velocity-dependent friction)"
ELASTIC_INTERFACE_KERNEL = "sliding kernel (elastic interface)"
ROCKING_KERNEL = "rocking kernel"
GENERAL = "general (time-stepping)"
EVENT_DRIVEN = "general (event-driven)"
#: Seconds followed after the record, floor at rest, by default.
DEFAULT_TAIL_S = 10.0


@dataclass(frozen=True)
class SlidingInterface:
    """A sliding law richer than Coulomb friction, for a block that cannot uplift.

    Exactly one of the two laws of :mod:`assess.mechanics.interface`:
    velocity-dependent friction (``low_speed_factor`` f and ``rate_s_m``:
    μ(u̇) rises from f·μ at rest to μ, breakaway at μ_s;
    :func:`~assess.mechanics.interface.velocity_friction_response`) or an
    elastic-perfectly-plastic interface (``yield_displacement_m``;
    :func:`~assess.mechanics.interface.elastic_interface_response`). Those
    kernels model sliding only, so the engine uses them where uplift is
    impossible (μ_s < b/h) and the rigid block's solvers elsewhere.
    """

    low_speed_factor: Optional[float] = None
    rate_s_m: Optional[float] = None
    yield_displacement_m: Optional[float] = None

    def __post_init__(self):
        velocity = self.low_speed_factor is not None or self.rate_s_m is not None
        elastic = self.yield_displacement_m is not None
        if velocity == elastic:
            raise ValueError("give either low_speed_factor and rate_s_m, or yield_displacement_m")
        if velocity and not (self.low_speed_factor is not None and self.rate_s_m is not None
                             and 0.0 < self.low_speed_factor <= 1.0 and self.rate_s_m > 0.0):
            raise ValueError("velocity friction needs 0 < low_speed_factor <= 1 and rate_s_m > 0")
        if elastic and not (np.isfinite(self.yield_displacement_m) and self.yield_displacement_m > 0.0):
            raise ValueError("yield_displacement_m must be positive")

    @property
    def solver(self) -> str:
        return ELASTIC_INTERFACE_KERNEL if self.yield_displacement_m is not None else VELOCITY_FRICTION_KERNEL

    def response(self, block: Block, floor_accel_g, dt_s, return_history=False):
        """The interface kernel's :class:`~assess.mechanics.sliding.SlidingResult` for ``block``."""
        if self.yield_displacement_m is not None:
            return elastic_interface_response(floor_accel_g, dt_s, mu=block.mu,
                                              yield_displacement_m=self.yield_displacement_m,
                                              return_history=return_history)
        return velocity_friction_response(floor_accel_g, dt_s, mu_min=self.low_speed_factor * block.mu,
                                          mu_max=block.mu, rate_s_m=self.rate_s_m, mu_static=block.mu_static,
                                          return_history=return_history)


@dataclass(frozen=True)
class BlockOnInterface(Block):
    """A :class:`~assess.mechanics.block.Block` that slides on a :class:`SlidingInterface`.

    >>> block = BlockOnInterface(half_width_m=0.3, cg_height_m=1.0, height_m=2.0, mu=0.2,
    ...                          interface=SlidingInterface(yield_displacement_m=0.005))
    >>> block.interface.solver
    'sliding kernel (elastic interface)'
    """

    interface: Optional[SlidingInterface] = None


def pure_sliding_proved(mu_static, b_over_h):
    """Whether uplift is impossible, so the pure sliding kernel is exact: μ_s < b/h.

    >>> bool(pure_sliding_proved(0.13, 0.272)), bool(pure_sliding_proved(0.68, 0.272))
    (True, False)
    """
    return np.asarray(mu_static) < np.asarray(b_over_h)


def first_solvers(blocks: Sequence[Block]) -> np.ndarray:
    """The solver each block runs by first: the engine's one choice (module docstring).

    Where uplift is impossible (:func:`pure_sliding_proved`), the sliding
    kernel, or the kernel of the block's :class:`SlidingInterface`: that run is
    the answer. Elsewhere the rocking kernel, whose run is kept where pure
    rocking held (:func:`pure_rocking_held`) and handed to the general solver
    otherwise.

    >>> first_solvers([Block(half_width_m=0.3, cg_height_m=1.0, height_m=2.0, mu=0.2),
    ...                Block(half_width_m=0.3, cg_height_m=1.0, height_m=2.0, mu=0.5)]).tolist()
    ['sliding kernel', 'rocking kernel']
    """
    mu_static = np.array([b.mu_static for b in blocks], dtype=float)
    sliding = pure_sliding_proved(mu_static, np.array([b.b_over_h for b in blocks], dtype=float))
    solvers = np.where(sliding, SLIDING_KERNEL, ROCKING_KERNEL).astype(object)
    for i in np.flatnonzero(sliding):
        interface = getattr(blocks[i], "interface", None)
        if interface is not None:
            solvers[i] = interface.solver
    return solvers


def pure_rocking_held(friction_demand_max, normal_force_min_over_weight, mu_static):
    """Whether a pure-rocking run is the block's true motion: |F|/N ≤ μ_s and N > 0 throughout.

    >>> bool(pure_rocking_held(0.34, 0.8, 0.68)), bool(pure_rocking_held(0.34, 0.8, 0.30))
    (True, False)
    """
    return (np.asarray(friction_demand_max) <= np.asarray(mu_static)) & (
        np.asarray(normal_force_min_over_weight) > 0.0)


def with_tail(floor_accel_g, dt_s, tail_s=DEFAULT_TAIL_S):
    """The record followed by ``tail_s`` seconds of zeros [g].

    Not the floor at rest after the record: read as samples, linear between
    them, these zeros ramp the floor down over the interval after the last
    sample. The solvers take ``tail_s`` themselves and step the floor to rest
    at the last sample.
    """
    accel = np.asarray(floor_accel_g, dtype=float)
    return np.concatenate([accel, np.zeros(int(np.ceil(tail_s / dt_s)))])


def _onset_time_s(floor_accel_g, dt_s, threshold_g):
    """First time [s] at which the piecewise-linear |a_g| exceeds ``threshold_g``; NaN if never."""
    above = np.flatnonzero(np.abs(floor_accel_g) > threshold_g)
    if above.size == 0:
        return np.nan
    k = int(above[0])
    if k == 0:
        return 0.0
    a0, a1 = floor_accel_g[k - 1], floor_accel_g[k]
    target = np.copysign(threshold_g, a1)
    return (k - 1 + (target - a0) / (a1 - a0)) * dt_s


def simulate(block: Block, floor_accel_g, dt_s, *, tail_s=DEFAULT_TAIL_S, return_history=False,
             solver="auto") -> BlockResponse:
    """Response of one block to one floor motion, by the solver proved right for it.

    Parameters
    ----------
    block : Block
    floor_accel_g : array-like
        Floor acceleration [g] at 0, dt, 2dt, ..., linear between samples.
    dt_s : float
        Sample interval [s].
    tail_s : float
        Seconds followed after the record with the floor at rest.
    return_history : bool
        Also return u and θ at the samples (record and tail).
    solver : {"auto", "general", "event-driven"}
        ``auto`` dispatches as the module docstring says; the others force a
        general solver.

    Returns
    -------
    BlockResponse
        ``solver`` names the solver that answered.

    Examples
    --------
    The FORMA incubator with its best-fit μ = 0.13 under a 0.54 g, 2.1 s
    Type-B pulse (the Los Gatos approximation of [1], p. 1470) slides; with
    μ = 0.68 under a 0.30 g pulse it rocks on its corners without slipping:

    >>> from assess.hazard.pulses import pulse_acceleration
    >>> forma = dict(half_width_m=0.311, cg_height_m=1.143, height_m=2.286)
    >>> time_s = np.arange(0, 2.1, 0.005)
    >>> r = simulate(Block(mu=0.13, **forma), pulse_acceleration("B", 0.54, 2.1, time_s), 0.005)
    >>> r.mode, r.uplift, r.solver
    ('slide', False, 'sliding kernel')
    >>> r = simulate(Block(mu=0.68, **forma), pulse_acceleration("B", 0.30, 2.1, time_s), 0.005)
    >>> r.mode, r.solver
    ('rock', 'rocking kernel')
    """
    accel = np.asarray(floor_accel_g, dtype=float)
    if solver == "event-driven":
        response = simulate_event_driven(block, accel, dt_s, tail_s=tail_s, return_history=return_history)
        return _named(response, EVENT_DRIVEN)
    if solver == "general":
        return _general(block, accel, dt_s, tail_s, return_history)
    if solver != "auto":
        raise ValueError(f"solver must be 'auto', 'general' or 'event-driven', not {solver!r}")
    first = first_solvers([block])[0]
    if first == SLIDING_KERNEL:
        return _sliding(block, accel, dt_s, tail_s, return_history)
    if first != ROCKING_KERNEL:
        return _on_interface(block, accel, dt_s, tail_s, return_history)
    rocking = rocking_response(accel, dt_s, block.alpha_rad, block.p_rad_s,
                               restitution=block.restitution_effective, return_history=return_history,
                               inertia_ratio_value=block.inertia_ratio, tail_s=tail_s)
    if not pure_rocking_held(rocking.friction_demand_max, rocking.normal_force_min_over_weight,
                             block.mu_static):
        return _general(block, accel, dt_s, tail_s, return_history)
    onset = _onset_time_s(accel, dt_s, block.b_over_h)
    sequence = ((0.0, REST),) + (((float(onset), ROCK),) if rocking.uplift else ())
    history = {}
    if return_history:
        history = dict(time_s=rocking.time_s, sliding_m=np.zeros_like(rocking.theta_rad),
                       theta_rad=rocking.theta_rad)
    return BlockResponse(sliding_max_m=0.0, sliding_residual_m=0.0,
                         theta_max_over_alpha=rocking.theta_max_over_alpha, uplift=rocking.uplift,
                         overturned=rocking.overturned, overturn_time_s=rocking.overturn_time_s,
                         mode_sequence=sequence, solver=ROCKING_KERNEL, **history)


def _sliding(block, accel, dt_s, tail_s, return_history):
    result = sliding_response(accel, dt_s, block.mu, block.mu_static, return_history=return_history)
    return _pure_sliding_response(result, block, accel, dt_s, tail_s, return_history, SLIDING_KERNEL)


def _on_interface(block, accel, dt_s, tail_s, return_history):
    """A block that cannot uplift, sliding on its :class:`SlidingInterface` (run-out included)."""
    result = block.interface.response(block, accel, dt_s, return_history=return_history)
    return _pure_sliding_response(result, block, accel, dt_s, tail_s, return_history, block.interface.solver)


def _pure_sliding_response(result, block, accel, dt_s, tail_s, return_history, solver) -> BlockResponse:
    """A sliding kernel's result as the engine's response: modes rest then slide, no rotation.

    The run-out after the record is solved exactly but not sampled: the tail of
    the history shows the residual (reached within the run-out time |u̇|/(μg)
    of the last sample).
    """
    onset = _onset_time_s(accel, dt_s, block.mu_static)
    slid = result.slide_time_s > 0.0
    sequence = ((0.0, REST),) + (((float(onset) if np.isfinite(onset) else 0.0, SLIDE),) if slid else ())
    history = {}
    if return_history:
        n_tail = int(np.ceil(tail_s / dt_s))
        time_s = np.arange(accel.size + n_tail) * dt_s
        sliding_m = np.concatenate([result.sliding_m, np.full(n_tail, result.sliding_residual_m)])
        history = dict(time_s=time_s, sliding_m=sliding_m, theta_rad=np.zeros(time_s.size))
    return BlockResponse(sliding_max_m=float(result.sliding_max_m),
                         sliding_residual_m=float(result.sliding_residual_m), theta_max_over_alpha=0.0,
                         uplift=False, overturned=False, overturn_time_s=np.nan, mode_sequence=sequence,
                         solver=solver, **history)


def _general(block, accel, dt_s, tail_s, return_history):
    warmup.wait()  # a first run: the solver may be compiling in a second process, to load from the cache
    response = simulate_time_stepping(block, accel, dt_s, tail_s=tail_s, return_history=return_history)
    return _named(response, GENERAL)


def _named(response: BlockResponse, solver: str) -> BlockResponse:
    return replace(response, solver=solver)


def checked_record_index(record_index, n_cases: int) -> np.ndarray:
    """``record_index`` as int64, one record per case (every runner's ``simulate_cases`` takes it so)."""
    record_index = np.asarray(record_index, dtype=np.int64)
    if record_index.shape != (n_cases,):
        raise ValueError("record_index must give one record per block")
    return record_index


@dataclass(frozen=True)
class CasePeaks:
    """Peaks of many (block, motion) cases (:func:`simulate_cases`); arrays of shape (n_cases,).

    Fields as in :class:`~assess.mechanics.block.BlockResponse`, plus ``mode``
    (the run's mode, :func:`~assess.mechanics.block.summary_mode`) and
    ``solver`` (which solver answered).
    """

    sliding_max_m: np.ndarray
    sliding_residual_m: np.ndarray
    theta_max_over_alpha: np.ndarray
    uplift: np.ndarray
    overturned: np.ndarray
    mode: np.ndarray
    solver: np.ndarray


#: Cases per call of the parallel kernels (about a second each on two cores); ``progress`` is told after each.
ROCKING_CASES_PER_CALL = 32768
GENERAL_CASES_PER_CALL = 4096


def simulate_cases(blocks: Sequence[Block], records_g: Sequence[np.ndarray], dt_s: Sequence[float],
                   record_index, *, tail_s=DEFAULT_TAIL_S,
                   progress: Optional[Callable[[int, int], None]] = None,
                   seconds_by_solver: Optional[dict] = None) -> CasePeaks:
    """Simulate case k = block ``blocks[k]`` under record ``records_g[record_index[k]]``.

    Cases are grouped by the solver proved for them and run in the parallel
    kernels: those that cannot uplift in the sliding kernel, a record at a
    time; the others in the rocking kernel, which stops a run as soon as its
    pivot would slip or lift; those runs are re-run from the start by the
    general solver. Blocks on a :class:`SlidingInterface` that cannot uplift
    run its kernel one by one. Same results as :func:`simulate` case by case,
    peaks only.

    ``progress(done, total)`` is called as groups of cases finish. If
    ``seconds_by_solver`` is given, the seconds spent in each solver, as
    (wall, CPU of all threads), are added to it under the solver's name (the
    rocking kernel's include the runs it hands on to the general solver).
    """
    n = len(blocks)
    record_index = checked_record_index(record_index, n)
    sliding_max, residual = np.zeros(n), np.zeros(n)
    theta_max = np.zeros(n)
    uplift, overturned = np.zeros(n, dtype=bool), np.zeros(n, dtype=bool)
    mode = np.full(n, REST, dtype=object)
    solver = np.full(n, "", dtype=object)
    mu = np.array([b.mu for b in blocks], dtype=float)
    mu_static = np.array([b.mu_static for b in blocks], dtype=float)
    first = first_solvers(blocks)
    sliding_set = first != ROCKING_KERNEL
    on_interface = sliding_set & (first != SLIDING_KERNEL)
    done = 0
    clock = {"solver": None, "start": (0.0, 0.0)}

    def timing(name):
        """Charge the time since the last call to the solver then running, and start ``name``'s."""
        now = (perf_counter(), process_time())
        if seconds_by_solver is not None and clock["solver"] is not None:
            wall, cpu = seconds_by_solver.get(clock["solver"], (0.0, 0.0))
            seconds_by_solver[clock["solver"]] = (wall + now[0] - clock["start"][0], cpu + now[1] - clock["start"][1])
        clock["solver"], clock["start"] = name, now

    def advance(count):
        nonlocal done
        done += int(count)
        if progress is not None and count:
            progress(done, n)

    # 1. cannot uplift (mu_s < b/h): the exact sliding kernel, a record at a time
    timing(SLIDING_KERNEL)
    for j, record in enumerate(records_g):
        in_record = (record_index == j) & sliding_set
        if not in_record.any():
            continue
        accel = np.asarray(record, dtype=float)
        for i in np.flatnonzero(in_record & on_interface):
            response = _on_interface(blocks[i], accel, dt_s[j], tail_s, False)
            sliding_max[i], residual[i] = response.sliding_max_m, response.sliding_residual_m
            mode[i], solver[i] = response.mode, response.solver
        idx = np.flatnonzero(in_record & ~on_interface)
        if idx.size:
            peak, res = sliding_peaks_batch([accel], dt_s[j], mu[idx], mu_static[idx])
            sliding_max[idx], residual[idx] = peak[:, 0], res[:, 0]
            mode[idx] = np.where(peak[:, 0] > 0.0, SLIDE, REST)
            solver[idx] = SLIDING_KERNEL
        advance(np.count_nonzero(in_record))
    # 2. may uplift: pure rocking, kept where its pivot never slipped nor lifted
    general = []
    timing(ROCKING_KERNEL)
    for idx in _calls(np.flatnonzero(~sliding_set), ROCKING_CASES_PER_CALL):
        records, dts, index = _records_of(records_g, dt_s, record_index[idx])
        alpha, p, e, kappa = _rocking_constants(blocks, idx)
        rock = rocking_case_peaks(records, dts, index, alpha, p, e, kappa, tail_s=tail_s, mu_static=mu_static[idx])
        held = pure_rocking_held(rock.friction_demand_max, rock.normal_force_min_over_weight, mu_static[idx])
        kept = idx[held]
        theta_max[kept] = rock.theta_max_over_alpha[held]
        uplift[kept] = rock.uplift[held]
        overturned[kept] = rock.overturned[held]
        mode[kept] = np.where(rock.uplift[held], ROCK, REST)
        solver[kept] = ROCKING_KERNEL
        general.append(idx[~held])
        advance(kept.size)
    # 3. the others slide and rock (or fly): the general solver
    timing(GENERAL)
    for idx in _calls(np.concatenate(general) if general else np.zeros(0, dtype=np.int64), GENERAL_CASES_PER_CALL):
        records, dts, index = _records_of(records_g, dt_s, record_index[idx])
        warmup.wait()  # a first run: the solver may be compiling in a second process, to load from the cache
        peaks = time_stepping_case_peaks([blocks[i] for i in idx], records, dts, index, tail_s=tail_s)
        sliding_max[idx], residual[idx] = peaks.sliding_max_m, peaks.sliding_residual_m
        theta_max[idx], uplift[idx], overturned[idx] = peaks.theta_max_over_alpha, peaks.uplift, peaks.overturned
        mode[idx] = peaks.mode
        solver[idx] = GENERAL
        advance(idx.size)
    timing(None)
    return CasePeaks(sliding_max_m=sliding_max, sliding_residual_m=residual,
                     theta_max_over_alpha=theta_max, uplift=uplift, overturned=overturned,
                     mode=mode.astype(str), solver=solver.astype(str))


def _rocking_constants(blocks, idx):
    """Arrays of α, p, e and κ of ``blocks[i]`` for i in ``idx``, worked out once per distinct block
    (the blocks of an assessment repeat over its motions; a block is a frozen dataclass, so equal
    blocks hash alike)."""
    memo = {}
    rows = []
    for i in idx:
        block = blocks[i]
        try:
            row = memo.get(block)
        except TypeError:  # an unhashable Block subclass
            row, block = None, None
        if row is None:
            row = (blocks[i].alpha_rad, blocks[i].p_rad_s, blocks[i].restitution_effective, blocks[i].inertia_ratio)
            if block is not None:
                memo[block] = row
        rows.append(row)
    return np.array(rows, dtype=float).reshape(-1, 4).T


def _calls(cases, size):
    """``cases`` in consecutive groups of at most ``size``."""
    return [cases[start:start + size] for start in range(0, cases.size, size)]


def _records_of(records_g, dt_s, record_index):
    """The records that ``record_index`` names, their intervals, and the index into them."""
    used, index = np.unique(record_index, return_inverse=True)
    return [records_g[j] for j in used], [float(dt_s[j]) for j in used], index.astype(np.int64)
