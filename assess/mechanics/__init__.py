"""Mechanics of a freestanding rigid block: geometry and mode of response, and the engine that simulates it.

The rest of ``assess`` uses the engine's API only: :mod:`~assess.mechanics.gateway` (every run, as a
batch of cases handed to a runner), :mod:`~assess.mechanics.runner` and
:mod:`~assess.mechanics.distributed` (where the runs go), :mod:`~assess.mechanics.block`,
:mod:`~assess.mechanics.geometry` and :mod:`~assess.mechanics.modes`. The other modules are the
solvers and their parts, chosen by :mod:`~assess.mechanics.engine`.
"""
