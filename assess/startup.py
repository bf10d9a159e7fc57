"""What the ``assess`` command starts before it imports the core (seconds of imports): on a first run after
install, the general solver's compilation on a second core (:mod:`assess.mechanics.warmup`)."""
from __future__ import annotations


def warm_up(scheduler: str | None, jobs: int | None) -> None:
    """A first run after install on this machine: the general solver compiles while the core imports
    (:meth:`assess.mechanics.runner.LocalRunner.warm_up`); nothing where a cluster (``scheduler``) runs
    the engine."""
    if scheduler is None:
        from assess.mechanics.runner import LocalRunner

        LocalRunner().warm_up(jobs)
