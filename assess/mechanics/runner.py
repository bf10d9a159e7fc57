"""Where the engine's cases run: the seam between the assessment and the machine(s).

The runners and the batches they take are those of :mod:`assess.mechanics.gateway`
(:class:`~assess.mechanics.gateway.Cases`, ``run(cases)``); this module names
them where the assessment looks for them. :class:`LocalRunner` runs cases on
this machine's threads; the others (a Dask cluster, a cache of earlier
results) take the same batches, so the numbers never depend on where, or
whether again, a case ran.
"""
from __future__ import annotations

from .gateway import Cases, LocalRunner, Runner, RunnerBase

__all__ = ["Cases", "LocalRunner", "Runner", "RunnerBase"]
