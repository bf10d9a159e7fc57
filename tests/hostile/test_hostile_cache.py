"""Hostile packs in the cache folder (an output folder copied from elsewhere brings its ``.cache`` along).

A pack is never trusted: a row whose values the engine cannot have produced
is a miss (the case is simulated again, the numbers are the engine's), a pack
that would inflate past :data:`assess.command.cache.MAX_PACK_BYTES` is not inflated,
and only regular files are opened (a FIFO named ``*.npz`` does not hang the
run). Memory and time are measured in a child process, with a timeout as the
hang guard.
"""
from __future__ import annotations

import os
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np
import pytest

import assess.command.cache as cache
from assess.command.cache import CachingRunner
from assess.mechanics.engine import simulate_cases
from tests.assessment.test_cache import TAIL_S, Recording, _assert_identical, _batch

ROOT = Path(__file__).resolve().parents[2]


def _tampered(folder: Path, **columns):
    """Store the batch's results in ``folder``, then rewrite its one pack with ``columns`` replaced."""
    batch = _batch()
    CachingRunner(Recording(), folder).simulate_cases(*batch, tail_s=TAIL_S)
    (pack,) = folder.glob("*.npz")
    with np.load(pack) as stored:
        arrays = {name: stored[name] for name in stored.files}
    for name, value in columns.items():
        column = arrays[name].copy() if not isinstance(value, np.ndarray) else value
        if not isinstance(value, np.ndarray):
            column[:] = value
        arrays[name] = column
    pack.unlink()
    np.savez_compressed(pack, **arrays)
    return batch


@pytest.mark.parametrize("columns", [
    {"sliding_max_m": np.nan}, {"sliding_max_m": -5.0}, {"sliding_max_m": np.inf},
    {"theta_max_over_alpha": np.nan}, {"theta_max_over_alpha": -1.0},
    {"sliding_residual_m": 7.0},  # larger than the peak it is the end of
    {"mode": "exploded"}, {"solver": "\x1b[31mred"},
], ids=lambda c: ",".join(f"{k}={v!r}" for k, v in c.items()))
def test_a_pack_value_the_engine_cannot_give_is_a_miss(tmp_path, columns):
    batch = _tampered(tmp_path, **columns)
    recording = Recording()
    got = CachingRunner(recording, tmp_path).simulate_cases(*batch, tail_s=TAIL_S)
    assert len(recording.blocks) == len(batch[0])  # every case simulated again
    _assert_identical(got, simulate_cases(*batch, tail_s=TAIL_S))


def test_only_the_bad_rows_of_a_pack_are_misses(tmp_path):
    batch = _batch()
    CachingRunner(Recording(), tmp_path).simulate_cases(*batch, tail_s=TAIL_S)
    (pack,) = tmp_path.glob("*.npz")
    with np.load(pack) as stored:
        arrays = {name: stored[name] for name in stored.files}
    arrays["sliding_max_m"] = arrays["sliding_max_m"].copy()
    arrays["sliding_max_m"][0] = np.nan
    pack.unlink()
    np.savez_compressed(pack, **arrays)
    recording = Recording()
    got = CachingRunner(recording, tmp_path).simulate_cases(*batch, tail_s=TAIL_S)
    assert len(recording.blocks) == 1
    _assert_identical(got, simulate_cases(*batch, tail_s=TAIL_S))


def _bomb(path: Path, inflated_bytes: int) -> None:
    """A pack of the right names whose ``keys`` inflate to ``inflated_bytes`` of zeros (a few MB on disk)."""
    count = inflated_bytes // cache.KEY_BYTES
    header = {"descr": f"|S{cache.KEY_BYTES}", "fortran_order": False, "shape": (count,)}
    chunk = bytes(1 << 24)
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED, compresslevel=1) as archive:
        with archive.open("keys.npy", "w", force_zip64=True) as member:
            np.lib.format.write_array_header_1_0(member, header)
            left = count * cache.KEY_BYTES
            while left:
                member.write(chunk[:min(left, len(chunk))])
                left -= min(left, len(chunk))
        for name, value in [("format", np.array(cache.PACK_FORMAT))] + \
                [(n, np.zeros(count)) for n in ("sliding_max_m",)]:
            with archive.open(f"{name}.npy", "w") as member:
                np.lib.format.write_array(member, value[:1] if value.ndim else value)


#: Loads every pack of the folder given as argument with a CachingRunner, prints peak memory [MB] and seconds.
_LOADER = """
import resource, sys, time
import numpy as np
from assess.command.cache import CachingRunner
before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
started = time.monotonic()
runner = CachingRunner(None, sys.argv[1], version="v")
runner._load_new_packs()
print(len(runner._index.keys), round(time.monotonic() - started, 2), round(before),
      round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024))
"""


def _load_in_a_child(folder: Path, timeout_s: float):
    done = subprocess.run([sys.executable, "-c", _LOADER, str(folder)], capture_output=True, text=True,
                          timeout=timeout_s, env={**os.environ, "PYTHONPATH": str(ROOT)})
    assert done.returncode == 0 and "Traceback" not in done.stderr, done.stderr
    rows, seconds, before_mb, peak_mb = done.stdout.split()
    return int(rows), float(seconds), float(before_mb), float(peak_mb)


def test_a_pack_that_inflates_to_1_6_gb_is_not_inflated(tmp_path):
    folder = tmp_path / ".cache"
    folder.mkdir()
    _bomb(folder / "bomb.npz", 1_600_000_000)
    assert (folder / "bomb.npz").stat().st_size < 10_000_000
    rows, seconds, before_mb, peak_mb = _load_in_a_child(folder, timeout_s=120)
    assert rows == 0
    assert peak_mb - before_mb < 50, (before_mb, peak_mb)  # it was 1.7 GB
    assert not (folder / "bomb.npz").exists()  # removed as unreadable


def test_a_pack_whose_header_lies_about_its_size_is_not_read(tmp_path):
    """The .npy header claims 10^12 keys in a small member: refused from the header, nothing allocated."""
    folder = tmp_path / ".cache"
    folder.mkdir()
    with zipfile.ZipFile(folder / "liar.npz", "w") as archive:
        with archive.open("keys.npy", "w") as member:
            np.lib.format.write_array_header_1_0(member, {"descr": "|S16", "fortran_order": False,
                                                          "shape": (10 ** 12,)})
        for name in ("format",) + cache._FLOATS + cache._BOOLS + cache._TEXTS:
            with archive.open(f"{name}.npy", "w") as member:
                np.lib.format.write_array(member, np.array(1))
    assert cache._read_pack(folder / "liar.npz") is None


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs on this system")
def test_a_fifo_named_npz_does_not_hang(tmp_path):
    folder = tmp_path / ".cache"
    folder.mkdir()
    os.mkfifo(folder / "stuck.npz")
    rows, seconds, _, _ = _load_in_a_child(folder, timeout_s=60)  # np.load waited for a writer forever
    assert rows == 0


def test_links_and_folders_named_npz_are_not_read(tmp_path):
    folder = tmp_path / ".cache"
    batch = _batch()
    CachingRunner(Recording(), folder).simulate_cases(*batch, tail_s=TAIL_S)
    (pack,) = folder.glob("*.npz")
    elsewhere = tmp_path / "elsewhere.npz"
    pack.rename(elsewhere)
    (folder / "link.npz").symlink_to(elsewhere)
    (folder / "dir.npz").mkdir()
    recording = Recording()
    got = CachingRunner(recording, folder).simulate_cases(*batch, tail_s=TAIL_S)
    assert len(recording.blocks) == len(batch[0])
    _assert_identical(got, simulate_cases(*batch, tail_s=TAIL_S))
    assert elsewhere.is_file()  # the link's target is left alone


def test_a_pack_larger_than_the_bound_on_disk_is_not_opened(tmp_path, monkeypatch):
    batch = _batch()
    CachingRunner(Recording(), tmp_path).simulate_cases(*batch, tail_s=TAIL_S)
    (pack,) = tmp_path.glob("*.npz")
    assert cache._read_pack(pack) is not None
    monkeypatch.setattr(cache, "MAX_PACK_BYTES", pack.stat().st_size - 1)
    assert cache._read_pack(pack) is None
