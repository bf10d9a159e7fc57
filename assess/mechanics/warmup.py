"""The first run after an install: the general solver compiles in a second process meanwhile.

The engine's kernels are compiled by numba on their first call and cached on
disk, so only the first run after an install (or an upgrade) pays for it:
some 20 s on a laptop, of which the general solver's kernel
(:mod:`assess.mechanics.timestepping`) is about 7 s. A run reaches that solver
last (sliding kernel, then rocking kernel, then the runs they hand on), after
compiling the other two. :func:`start` compiles the general solver in a
second Python process while this one goes on; :func:`wait` is called before
the general solver's first use and waits for that process, so that the
solver then loads from the cache instead of compiling a second time.

Nothing happens when the general solver is already in the cache, when the
engine may use one thread only (``--jobs 1``), or when the job runs on a Dask
cluster (its workers compile there). Whatever goes wrong in the second
process (it is killed, it fails, the cache cannot be written) only means that
this one compiles the solver itself, as it would have; the answers are the
same either way. The second process is stopped if this one ends first.
"""
from __future__ import annotations

import atexit
import inspect
import subprocess
import sys
from pathlib import Path

import numba

_process: subprocess.Popen | None = None


def general_solver_cached() -> bool:
    """Whether numba's cache holds the general solver's batch kernel for its current source: its index file,
    named as numba names it (``<module>.<function>-<first line>.py<major><minor>.nbi``) in the dispatcher's
    cache folder (its public ``stats.cache_path``), written after the source file last changed (numba
    rewrites an index whose source changed). A file not found counts as not cached: at worst a later run
    then loads the kernel from the cache in a second process too.
    """
    from .timestepping import _cases

    function = _cases.py_func
    source = Path(inspect.getsourcefile(function))
    index = Path(_cases.stats.cache_path) / (f"{source.stem}.{function.__qualname__}-{function.__code__.co_firstlineno}"
                                             f".py{sys.version_info.major}{sys.version_info.minor}.nbi")
    try:
        return index.stat().st_mtime >= source.stat().st_mtime
    except OSError:
        return False


def start(threads: int | None = None) -> None:
    """Compile the general solver in a second process if it is not cached (see the module docstring).

    ``threads``: the threads the engine will use, if not yet set (``--jobs``); default numba's.
    """
    global _process
    if _process is not None or (threads or numba.get_num_threads()) < 2 or general_solver_cached():
        return
    try:
        _process = subprocess.Popen([sys.executable, "-m", "assess.mechanics.warmup"], stdin=subprocess.DEVNULL,
                                    stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    except OSError:
        return
    atexit.register(_stop)


def running() -> bool:
    """Whether this run started the general solver's compilation (:func:`start`): a first run after install."""
    return _process is not None


def wait() -> None:
    """Wait for the compile :func:`start` began, if any (the general solver then loads from the cache)."""
    global _process
    if _process is not None:
        _process.wait()
        _process = None


def _stop() -> None:
    if _process is not None and _process.poll() is None:
        _process.kill()
        _process.wait()


def _compile() -> None:
    """Compile (and cache) the general solver's batch kernel on a tiny case."""
    from .block import Block
    from .timestepping import time_stepping_case_peaks

    block = Block(half_width_m=0.2, cg_height_m=0.5, height_m=1.0, mu=0.3)
    time_stepping_case_peaks([block], [[0.0, 0.5, 0.0]], 0.01, [0], tail_s=0.1)


if __name__ == "__main__":
    _compile()
