"""A first run compiles the general solver in a second process (assess.mechanics.warmup)."""
import os
import shutil
import subprocess
import sys
import textwrap

import pytest


def run_python(code, cache_dir, timeout_s=300):
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache_dir))
    done = subprocess.run([sys.executable, "-c", textwrap.dedent(code)], env=env, capture_output=True, text=True,
                          timeout=timeout_s)
    assert done.returncode == 0, done.stderr[-2000:]
    return done.stdout


@pytest.fixture(scope="module")
def first_run(tmp_path_factory):
    """``(printed, cache folder)``: a first run on an empty cache folder, which starts the second process and
    waits for it. Made once for the module (the compile takes about 10 s); a test that changes the folder
    works on a copy of it."""
    cache_dir = tmp_path_factory.mktemp("numba-cache")
    out = run_python("""
        import numba
        numba.set_num_threads(min(2, numba.config.NUMBA_NUM_THREADS))
        from assess.mechanics import warmup
        print(warmup.general_solver_cached())
        warmup.start()
        started = warmup._process is not None
        warmup.wait()
        print(started, warmup.general_solver_cached())
        warmup.start()  # cached now: nothing to do
        print(warmup._process is None)
    """, cache_dir)
    return out, cache_dir


def test_an_empty_cache_is_filled_by_the_second_process_and_the_solver_then_loads_from_it(first_run):
    out, cache_dir = first_run
    if numba_threads() < 2:
        assert out.split() == ["False", "False", "False", "True"]
    else:
        assert out.split() == ["False", "True", "True", "True"]
        assert any(name.startswith("timestepping._cases") for name in os.listdir(cache_files(cache_dir)))


def test_nothing_starts_on_one_thread(tmp_path):
    out = run_python("""
        import numba
        numba.set_num_threads(1)
        from assess.mechanics import warmup
        warmup.start()
        print(warmup._process is None)
    """, tmp_path)
    assert out.split() == ["True"]


def test_the_second_process_is_stopped_when_the_first_ends(tmp_path):
    if numba_threads() < 2:
        pytest.skip("needs two numba threads")
    pid = int(run_python("""
        from assess.mechanics import warmup
        warmup.start()
        print(warmup._process.pid)
    """, tmp_path))
    with pytest.raises(ProcessLookupError):
        os.kill(pid, 0)


def numba_threads():
    import numba
    return numba.config.NUMBA_NUM_THREADS


def cache_files(cache_dir):
    """The folder numba writes assess.mechanics' cache into, under NUMBA_CACHE_DIR."""
    for root, _dirs, files in os.walk(cache_dir):
        if any(name.endswith(".nbi") for name in files):
            return root
    raise AssertionError(f"no numba cache index under {cache_dir}")


def test_an_index_older_than_the_source_counts_as_not_cached(first_run, tmp_path):
    """numba rewrites an index whose source changed: one written before the source last changed is stale."""
    if numba_threads() < 2:
        pytest.skip("needs two numba threads")
    cache_dir = tmp_path / "numba-cache"
    shutil.copytree(first_run[1], cache_dir)  # the first run's cache, its files' times kept
    out = run_python("""
        import inspect, os
        from assess.mechanics import warmup
        from assess.mechanics.timestepping import _cases
        before = warmup.general_solver_cached()
        source = os.stat(inspect.getsourcefile(_cases.py_func)).st_mtime
        folder = _cases.stats.cache_path
        for name in os.listdir(folder):
            if name.startswith("timestepping._cases-") and name.endswith(".nbi"):
                os.utime(os.path.join(folder, name), (source - 60, source - 60))
        print(before, warmup.general_solver_cached())
    """, cache_dir)
    assert out.split() == ["True", "False"]
