"""The one road to the engine: every run is a case of a :class:`Cases` batch handed to a runner.

A *case* is a block under a record (its index in the batch's records), and
what is asked of the run:

* ``peaks`` (:meth:`Cases.peaks`): the peaks of the rigid block under one
  horizontal component, by the solver proved right for it
  (:func:`assess.mechanics.engine.simulate_cases`: sliding kernel, rocking
  kernel checked after the run, general solver otherwise). The assessment's
  item × motion × direction cases and the hazard curve's stripes.
* ``planar`` (:meth:`Cases.planar`): a block that cannot uplift, sliding in
  the plane under two components at once (its record along the width, and
  ``record_index_2`` along the depth), friction μmg opposing its velocity
  (:func:`assess.mechanics.sliding_2d.sliding_2d_peaks_batch`): peak distance
  from rest and residual distance, as :class:`CasePeaks`.
* ``response`` (:meth:`Cases.responses`): the full
  :class:`~assess.mechanics.block.BlockResponse` of one run (mode sequence;
  with ``history`` the time histories), by the same choice of solver
  (:func:`assess.mechanics.engine.simulate`), or a forced general solver
  (``solver``). The report's worst-run histories, the calibration's test
  simulations and ``assess simulate``.

:func:`run_cases` is the dispatch: the only place outside the engine's own
solvers that calls a kernel. A *runner* has ``run(cases, progress=None)``
returning :class:`CasePeaks` (``peaks``, ``planar``) or a list of
:class:`~assess.mechanics.block.BlockResponse` (``response``), in case order:
:class:`LocalRunner` (this machine's threads),
:class:`assess.command.cache.CachingRunner` (results stored by the content of each
case, the kind of run included) and
:class:`assess.mechanics.distributed.DaskRunner` (a cluster). A case's result
depends on the case alone, so it is the same, byte for byte, whichever runner
answered it and whatever else was in its batch.
"""
from __future__ import annotations

import importlib
from dataclasses import dataclass, field
from typing import Callable, Optional, Protocol, Sequence, Union

import numpy as np

from .block import Block
from .engine import (DEFAULT_TAIL_S, ELASTIC_INTERFACE_KERNEL, EVENT_DRIVEN, GENERAL, ROCKING_KERNEL, SLIDING_KERNEL,
                     VELOCITY_FRICTION_KERNEL, BlockOnInterface,
                     CasePeaks, SlidingInterface, checked_record_index, pure_sliding_proved, simulate,
                     simulate_cases)
from . import warmup
from .modes import REST, SLIDE
from .sliding_2d import sliding_2d_peaks_batch

__all__ = ["PEAKS", "PLANAR", "RESPONSE", "KINDS", "SOLVERS", "PLANAR_KERNEL", "DEFAULT_TAIL_S", "Cases",
           "CasePeaks", "Runner", "RunnerBase", "LocalRunner", "run_cases", "run_responses", "solver_installed",
           "pure_sliding_proved", "BlockOnInterface", "SlidingInterface", "SLIDING_KERNEL", "ROCKING_KERNEL",
           "GENERAL", "EVENT_DRIVEN", "ENGINE_SOLVERS"]

PEAKS = "peaks"
PLANAR = "planar"
RESPONSE = "response"
#: The kinds of run (part of a case's identity: the cache keys them apart).
KINDS = (PEAKS, PLANAR, RESPONSE)
#: ``auto``: the solver proved right for the block; the others force a general solver (``response`` only).
SOLVERS = ("auto", "general", "event-driven")
PLANAR_KERNEL = "sliding kernel (2-D)"
#: Every solver a run may name as the one that gave its answer (what a stored result may say).
ENGINE_SOLVERS = (SLIDING_KERNEL, VELOCITY_FRICTION_KERNEL, ELASTIC_INTERFACE_KERNEL, ROCKING_KERNEL, GENERAL,
                  EVENT_DRIVEN, PLANAR_KERNEL)

Progress = Optional[Callable[[int, int], None]]
Result = Union[CasePeaks, list]


@dataclass(frozen=True, eq=False)
class Cases:
    """A batch of runs of one kind: case k is ``blocks[k]`` under ``records_g[record_index[k]]``.

    ``dt_s[j]`` is the sample interval [s] of record j; ``tail_s`` the seconds
    followed after the record with the floor at rest. ``record_index_2``
    (``planar`` only) names each case's component along the block's depth;
    ``history`` and ``solver`` (``response`` only) ask for the time histories
    and force a solver. Build one with :meth:`peaks`, :meth:`planar` or
    :meth:`responses`.
    """

    kind: str
    blocks: Sequence[Block]
    records_g: Sequence[np.ndarray]
    dt_s: Sequence[float]
    record_index: np.ndarray
    record_index_2: Optional[np.ndarray] = None
    tail_s: float = DEFAULT_TAIL_S
    history: bool = False
    solver: str = "auto"

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"kind must be one of {KINDS}, not {self.kind!r}")
        if len(self.dt_s) != len(self.records_g):
            raise ValueError("dt_s must give one sample interval per record")
        n = len(self.blocks)
        object.__setattr__(self, "record_index", checked_record_index(self.record_index, n))
        if (self.kind == PLANAR) != (self.record_index_2 is not None):
            raise ValueError("record_index_2 (the component along the depth) is given for planar runs, "
                             "and only for them")
        if self.record_index_2 is not None:
            object.__setattr__(self, "record_index_2", checked_record_index(self.record_index_2, n))
        for index in (self.record_index, self.record_index_2):
            if index is not None and index.size and (index.min() < 0 or index.max() >= len(self.records_g)):
                raise ValueError("a record index names no record of the batch")
        if self.kind != RESPONSE and (self.history or self.solver != "auto"):
            raise ValueError("history and solver are options of response runs")
        if self.solver not in SOLVERS:
            raise ValueError(f"solver must be 'auto', 'general' or 'event-driven', not {self.solver!r}")

    # ------------------------------------------------------------------ builders
    @classmethod
    def peaks(cls, blocks, records_g, dt_s, record_index, *, tail_s=DEFAULT_TAIL_S) -> "Cases":
        """Peaks of each block under its record (one horizontal component)."""
        return cls(PEAKS, list(blocks), list(records_g), [float(d) for d in dt_s], record_index,
                   tail_s=float(tail_s))

    @classmethod
    def planar(cls, blocks, records_g, dt_s, record_index, record_index_2, *, tail_s=DEFAULT_TAIL_S) -> "Cases":
        """Sliding in the plane of blocks that cannot uplift: component ``record_index`` along the width,
        ``record_index_2`` along the depth (same sample interval and length)."""
        return cls(PLANAR, list(blocks), list(records_g), [float(d) for d in dt_s], record_index,
                   record_index_2=record_index_2, tail_s=float(tail_s))

    @classmethod
    def responses(cls, blocks, records_g, dt_s, record_index, *, tail_s=DEFAULT_TAIL_S, history=False,
                  solver="auto") -> "Cases":
        """The full response of each block under its record (with ``history``: u and θ at the samples)."""
        return cls(RESPONSE, list(blocks), list(records_g), [float(d) for d in dt_s], record_index,
                   tail_s=float(tail_s), history=bool(history), solver=str(solver))

    @classmethod
    def responses_of(cls, runs, *, tail_s=DEFAULT_TAIL_S, history=False, solver="auto") -> "Cases":
        """:meth:`responses` of ``runs``, a sequence of (block, floor_accel_g, dt_s); a record given as the
        same array object to several runs is one record of the batch."""
        records, dts, index, slot = [], [], [], {}
        blocks = []
        for block, accel_g, dt_s in runs:
            key = (id(accel_g), float(dt_s))
            if key not in slot:
                slot[key] = len(records)
                records.append(accel_g)
                dts.append(float(dt_s))
            blocks.append(block)
            index.append(slot[key])
        return cls.responses(blocks, records, dts, np.asarray(index, dtype=np.int64), tail_s=tail_s,
                             history=history, solver=solver)

    # ------------------------------------------------------------------ parts
    def __len__(self) -> int:
        return len(self.blocks)

    def options(self) -> str:
        """What is asked of every run besides block and records, as exact text (part of the cache key).

        >>> Cases.responses([], [], [], [], tail_s=2.0, history=True).options()
        'response|tail=2.0|history=True|solver=auto'
        """
        text = f"{self.kind}|tail={float(self.tail_s)!r}"
        if self.kind == RESPONSE:
            text += f"|history={self.history}|solver={self.solver}"
        return text

    def records_used(self, cases=None) -> np.ndarray:
        """Indices of the records that the cases ``cases`` (default all) run under, sorted."""
        cases = slice(None) if cases is None else cases
        used = self.record_index[cases]
        if self.record_index_2 is not None:
            used = np.concatenate([used, self.record_index_2[cases]])
        return np.unique(used)

    def subset(self, cases, records_g=None) -> "Cases":
        """The cases ``cases`` (indices, in that order) as a batch of their own, with only the records they
        use (renumbered; ``records_g`` replaces them, e.g. by handles of a cluster's copies)."""
        cases = np.asarray(cases, dtype=np.int64)
        used = self.records_used(cases)
        renumber = np.full(len(self.records_g), -1, dtype=np.int64)
        renumber[used] = np.arange(used.size)
        records = [self.records_g[j] for j in used] if records_g is None else list(records_g)
        return Cases(self.kind, [self.blocks[k] for k in cases], records, [self.dt_s[j] for j in used],
                     renumber[self.record_index[cases]],
                     None if self.record_index_2 is None else renumber[self.record_index_2[cases]],
                     tail_s=self.tail_s, history=self.history, solver=self.solver)


def run_cases(cases: Cases, *, progress: Progress = None, seconds_by_solver: Optional[dict] = None) -> Result:
    """Run every case of ``cases`` on this machine: the gateway's one dispatch to the solvers.

    Returns :class:`CasePeaks` for ``peaks`` and ``planar`` runs, a list of
    :class:`~assess.mechanics.block.BlockResponse` for ``response`` runs, in
    case order. ``progress(done, total)`` is told as cases finish;
    ``seconds_by_solver`` (``peaks`` runs) as in
    :func:`~assess.mechanics.engine.simulate_cases`.
    """
    if cases.kind == PEAKS:
        return simulate_cases(cases.blocks, cases.records_g, cases.dt_s, cases.record_index, tail_s=cases.tail_s,
                              progress=progress, seconds_by_solver=seconds_by_solver)
    if cases.kind == PLANAR:
        return _planar_peaks(cases, progress)
    responses = []
    for k, (block, j) in enumerate(zip(cases.blocks, cases.record_index.tolist())):
        responses.append(simulate(block, cases.records_g[j], cases.dt_s[j], tail_s=cases.tail_s,
                                  return_history=cases.history, solver=cases.solver))
        if progress is not None:
            progress(k + 1, len(cases))
    return responses


def _planar_peaks(cases: Cases, progress: Progress) -> CasePeaks:
    """The 2-D sliding kernel for each pair of components, its blocks at once (each block's run is its own)."""
    n = len(cases)
    mu = np.array([b.mu for b in cases.blocks], dtype=float)
    mu_static = np.array([b.mu_static for b in cases.blocks], dtype=float)
    if n and not np.all(pure_sliding_proved(mu_static, np.array([b.b_over_h for b in cases.blocks]))):
        raise ValueError("planar runs are for blocks that cannot uplift (mu_s < b/h in both base directions)")
    peak, residual = np.zeros(n), np.zeros(n)
    pairs = np.stack([cases.record_index, cases.record_index_2], axis=1) if n else np.zeros((0, 2), np.int64)
    done = 0
    for first, second in np.unique(pairs, axis=0).tolist():
        idx = np.flatnonzero((cases.record_index == first) & (cases.record_index_2 == second))
        peak_m, residual_m = sliding_2d_peaks_batch([cases.records_g[first]], [cases.records_g[second]],
                                                    cases.dt_s[first], mu[idx], mu_static[idx])
        peak[idx], residual[idx] = peak_m[:, 0], residual_m[:, 0]
        done += idx.size
        if progress is not None:
            progress(done, n)
    return CasePeaks(sliding_max_m=peak, sliding_residual_m=residual, theta_max_over_alpha=np.zeros(n),
                     uplift=np.zeros(n, dtype=bool), overturned=np.zeros(n, dtype=bool),
                     mode=np.where(peak > 0.0, SLIDE, REST).astype(str),
                     solver=np.full(n, PLANAR_KERNEL).astype(str))


class Runner(Protocol):
    """What runs the engine's cases (:class:`LocalRunner`, ``CachingRunner``, ``DaskRunner``).

    ``cases_simulated`` counts the ``peaks`` cases it simulated (the
    assessment's item × motion × direction runs and the stripes: the
    portfolio's account); ``runs_simulated`` every run, by kind.
    """

    cases_simulated: int
    runs_simulated: dict

    def run(self, cases: Cases, *, progress: Progress = None) -> Result:
        ...


class RunnerBase:
    """What every runner shares: the counters and :meth:`simulate_cases`, ``run`` of ``peaks`` cases."""

    cases_simulated: int
    runs_simulated: dict

    def _count(self, cases: Cases, simulated: int) -> None:
        if cases.kind == PEAKS:
            self.cases_simulated += int(simulated)
        self.runs_simulated[cases.kind] = self.runs_simulated.get(cases.kind, 0) + int(simulated)

    def simulate_cases(self, blocks, records_g, dt_s, record_index, *, tail_s: float = DEFAULT_TAIL_S,
                       progress: Progress = None) -> CasePeaks:
        """``run`` of :meth:`Cases.peaks` (same arguments and result as
        :func:`assess.mechanics.engine.simulate_cases`)."""
        return self.run(Cases.peaks(blocks, records_g, dt_s, record_index, tail_s=tail_s), progress=progress)


@dataclass
class LocalRunner(RunnerBase):
    """Run cases on this machine's threads (the compiled kernels), through :func:`run_cases`."""

    cases_simulated: int = field(default=0)
    runs_simulated: dict = field(default_factory=dict)

    def run(self, cases: Cases, *, progress: Progress = None) -> Result:
        result = run_cases(cases, progress=progress)
        self._count(cases, len(cases))
        return result

    def warm_up(self, threads: int | None = None) -> None:
        """On a first run after install, compile the general solver in a second process meanwhile
        (:mod:`assess.mechanics.warmup`; ``threads``: the engine's, if not yet set); the engine waits
        for it before the solver's first use."""
        warmup.start(threads)

    @staticmethod
    def warming_up() -> bool:
        """Whether this run compiles the general solver in a second process (:meth:`warm_up` started it:
        a first run after install)."""
        return warmup.running()


def run_responses(runs, runner: Optional[Runner] = None, *, tail_s=DEFAULT_TAIL_S, history=False,
                  solver="auto") -> list:
    """The :class:`~assess.mechanics.block.BlockResponse` of each (block, floor_accel_g, dt_s) of ``runs``,
    through ``runner`` (default: a :class:`LocalRunner`).

    >>> from assess.hazard.pulses import pulse_acceleration
    >>> block = Block(half_width_m=0.311, cg_height_m=1.143, height_m=2.286, mu=0.13)
    >>> accel = pulse_acceleration("B", 0.54, 2.1, np.arange(0, 2.1, 0.005))
    >>> [(r.mode, r.solver) for r in run_responses([(block, accel, 0.005)])]
    [('slide', 'sliding kernel')]
    """
    runner = runner if runner is not None else LocalRunner()
    cases = Cases.responses_of(runs, tail_s=tail_s, history=history, solver=solver)
    return list(runner.run(cases)) if len(cases) else []


def solver_installed(module: str) -> bool:
    """Whether the solver module ``module`` (e.g. ``assess.mechanics.interface``) can be imported."""
    try:
        importlib.import_module(module)
    except ImportError:
        return False
    return True
