"""A portfolio's buildings spread over a Dask cluster's workers (``assess batch --scheduler ADDRESS``).

On a cluster, :func:`assess.portfolio.batch.run_portfolio` hands the
buildings it assesses to :class:`BuildingSpread`: each building is one task
(:func:`assess_building`) that runs the main job's assessment and renders its
report on a worker, its cases on that worker's threads, through a
:class:`~assess.command.cache.CachingRunner` of the portfolio's cache folder;
the worker sends back the building's files (bytes) and table, which are
written here. This needs the workers to see the portfolio's files at the same
paths as this machine (a shared file system, as on most clusters, or a
cluster on this machine): :meth:`BuildingSpread.applies` checks it, each
worker reading every workbook and record; otherwise, and where there are fewer
buildings to assess than worker threads, the buildings run one after the
other here with their cases spread over the workers (:class:`~assess.mechanics.distributed.DaskRunner`).

The files are those of a run on one machine, byte for byte: a building's
numbers depend on its inputs alone. So are the cases each building is said to
have simulated and reused (``portfolio.csv``): each task returns the keys of
the cases its building asked for, and :func:`sequential_account` counts them
as one machine running the buildings in order would have, against the cache
as it was when the run began (a case a building before it simulated is
reused).
"""
from __future__ import annotations

import hashlib
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from assess.mechanics.gateway import PEAKS

#: Buildings to assess, per worker thread, from which they are spread over the workers rather than their cases.
BUILDINGS_PER_THREAD = 1


@dataclass
class BuildingOutcome:
    """What a building's assessment made: its files (name -> bytes), its table, its level's label, and the keys
    of the cases it asked the engine for, by batch (``(kind, [key or None, ...])``)."""

    files: dict
    summary: object
    level_label: str
    asked: list = field(default_factory=list)
    write_errors: list = field(default_factory=list)
    simulated: int = 0
    reused: int = 0
    summary_csv: bytes = b""
    seconds: float = 0.0


def assess_building(item, *, seed: int, formats, units, cache_folder: str) -> BuildingOutcome:
    """One building on a worker: the main job's assessment and its outputs, through the portfolio's cache
    (its cases on the worker's threads)."""
    import numba

    from assess.assessment import pipeline
    from assess.command import output
    from assess.command.cache import CachingRunner
    from assess.mechanics.gateway import LocalRunner

    try:
        from distributed import get_worker
        numba.set_num_threads(max(1, min(get_worker().state.nthreads, numba.config.NUMBA_NUM_THREADS)))
    except (ImportError, ValueError):  # not on a worker (a test calls it here)
        pass
    started = time.perf_counter()
    runner = CachingRunner(LocalRunner(), cache_folder)
    runner.asked = []
    result = pipeline.run_assessment(item.inventory, item.level, seed=seed, runner=runner, hazard_curve=item.curve,
                                     allow_records_outside=item.allow_records_outside)
    files = output.render_outputs(result, formats, units=units, pdf_processes=1)  # a worker starts no process
    return BuildingOutcome(files=files, summary=result.summary, level_label=result.level_label,
                           asked=runner.asked, write_errors=list(runner.write_errors),
                           seconds=time.perf_counter() - started)


def sequential_account(known: set, asked_by_building: list[list]) -> list[tuple[int, int]]:
    """(cases simulated, cases reused) of each building, as one :class:`~assess.command.cache.CachingRunner`
    running the buildings in this order would count them: a ``peaks`` case is reused when its key was
    stored before (``known``, the cache when the run began) or asked for earlier in the run, simulated
    otherwise (a case with no key is always simulated). ``known`` is not changed.

    >>> sequential_account({b"a"}, [[("peaks", [b"a", b"b", b"b", None])], [("peaks", [b"b", b"c"])]])
    [(2, 2), (1, 1)]
    """
    seen = set(known)
    counts = []
    for asked in asked_by_building:
        simulated = reused = 0
        for kind, keys in asked:
            for key in keys:
                hit = key is not None and key in seen
                if key is not None:
                    seen.add(key)
                if kind == PEAKS:
                    simulated, reused = simulated + (not hit), reused + hit
        counts.append((simulated, reused))
    return counts


def _file_digests(paths: list[str]) -> list[str | None]:
    """The blake2b of each file as this process reads it (None: it cannot)."""
    digests = []
    for path in paths:
        try:
            digests.append(hashlib.blake2b(Path(path).read_bytes(), digest_size=16).hexdigest())
        except OSError:
            digests.append(None)
    return digests


@dataclass
class BuildingSpread:
    """The buildings of a portfolio spread over the workers of ``runner``'s cluster.

    ``runner`` is the portfolio's :class:`~assess.command.cache.CachingRunner`
    around a :class:`~assess.mechanics.distributed.DaskRunner`.
    """

    runner: object
    #: The files a building's assessment reads (its workbook, its records: ``run_batch`` gives them).
    files_of: Callable = lambda item: [item.building.workbook]
    buildings_per_thread: int = BUILDINGS_PER_THREAD
    reason: str = ""

    @property
    def client(self):
        return self.runner.inner.client

    def applies(self, pending: list) -> bool:
        """Whether to spread these buildings (``PreparedBuilding``) over the workers: at least
        ``buildings_per_thread`` per worker thread, and every worker reads every file of them (``files_of``:
        the workbook and records) at the same path, with the same bytes, as this machine does (``reason``
        says why not)."""
        threads = max(1, sum(self.client.nthreads().values()))
        if len(pending) < max(2, self.buildings_per_thread * threads):
            self.reason = (f"{len(pending)} buildings to assess for {threads} worker threads: the buildings run here "
                           "one after the other, their cases on the workers")
            return False
        paths = sorted({str(Path(path).resolve()) for item in pending for path in self.files_of(item)})
        here = _file_digests(paths)
        theirs = self.client.run(_file_digests, paths)
        if any(digests != here for digests in theirs.values()):
            self.reason = ("the workers do not see the portfolio's workbooks and records as this machine does (no "
                           "shared file system): the buildings run here one after the other, their cases on the "
                           "workers")
            return False
        self.reason = f"{len(pending)} buildings spread over {threads} worker threads"
        return True

    def assess(self, pending: list, *, seed: int, formats, units, say: Callable[[str], None],
               deliver: Callable[[int, BuildingOutcome], None] = lambda number, outcome: None) -> list:
        """The :class:`BuildingOutcome` of each building of ``pending`` (in its order), assessed on the workers,
        the largest first; their cases counted by :func:`sequential_account`. ``deliver(number, outcome)`` is
        called as each arrives (to write its files, which it may then drop: a portfolio's reports need not
        all be held at once)."""
        from distributed import as_completed

        self.runner._load_new_packs()
        known = set(self.runner.known_keys())
        folder = str(Path(self.runner.folder).resolve())
        futures = {}
        for number, item in enumerate(pending):
            cost = len(item.inventory.equipment)
            futures[self.client.submit(assess_building, item, seed=seed, formats=formats, units=units,
                                       cache_folder=folder, pure=False, priority=cost)] = number
        outcomes: list = [None] * len(pending)
        try:
            for future in as_completed(futures, loop=self.client.loop):
                number = futures[future]
                outcomes[number] = future.result()
                future.release()  # the worker forgets it
                deliver(number, outcomes[number])
                say(f"{pending[number].building.name}: assessed on a worker ({sum(o is not None for o in outcomes)}"
                    f"/{len(pending)})")
        finally:
            for future in futures:
                future.release()
        for outcome, (simulated, reused) in zip(outcomes, sequential_account(known, [o.asked for o in outcomes])):
            outcome.simulated, outcome.reused = simulated, reused
            self.runner.write_errors.extend(outcome.write_errors)
        return outcomes
