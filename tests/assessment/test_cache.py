"""The cache of engine results (assess.command.cache): the same numbers, and a miss for every change that matters.

What was simulated is observed by the runner the cache wraps (a recording
runner that keeps the blocks it was handed), never taken from the cache's
own counters alone; the expected numbers are those of the engine run without
any cache.
"""
from __future__ import annotations

import shutil
from dataclasses import replace

import numpy as np
import pytest

import assess.command.cache as cache
from assess.hazard.records import pulse_record
from assess.mechanics.block import Block
from assess.command.cache import CachingRunner, block_fingerprint, engine_version
from assess.mechanics.engine import BlockOnInterface, SlidingInterface, simulate_cases
from assess.mechanics.gateway import run_cases
from assess.mechanics.runner import LocalRunner, RunnerBase

TAIL_S = 2.0


class Recording(RunnerBase):
    """A runner that simulates with the engine and keeps every block and record it was handed."""

    def __init__(self):
        self.blocks, self.records = [], []
        self.cases_simulated, self.runs_simulated = 0, {}

    def run(self, cases, *, progress=None):
        self.blocks.extend(cases.blocks)
        self.records.extend(np.asarray(cases.records_g[j]) for j in cases.record_index)
        self._count(cases, len(cases))
        return run_cases(cases, progress=progress)


def _blocks():
    """A squat slider, a slender rocker, a slide-rock block and one on an elastic interface."""
    return [Block(half_width_m=0.6, cg_height_m=0.5, height_m=1.0, mu=0.2),
            Block(half_width_m=0.15, cg_height_m=1.0, height_m=2.0, mu=0.6),
            Block(half_width_m=0.3, cg_height_m=0.9, height_m=1.8, mu=0.35, mu_static=0.4),
            BlockOnInterface(half_width_m=0.5, cg_height_m=0.5, height_m=1.0, mu=0.25,
                             interface=SlidingInterface(yield_displacement_m=0.004))]


def _records():
    return [pulse_record("B", 0.6, 0.8, 0.004), pulse_record("A", 0.9, 0.5, 0.004)]


def _batch(blocks=None, records=None):
    """Every block under every record: (blocks, records_g, dt_s, record_index)."""
    blocks = _blocks() if blocks is None else blocks
    records = _records() if records is None else records
    case_blocks = [b for _ in records for b in blocks]
    index = np.repeat(np.arange(len(records)), len(blocks))
    return case_blocks, [r.accel_g for r in records], [r.dt_s for r in records], index


def _assert_identical(a, b):
    for name in ("sliding_max_m", "sliding_residual_m", "theta_max_over_alpha", "uplift", "overturned",
                 "mode", "solver"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)


def test_cached_numbers_are_the_engines(tmp_path):
    batch = _batch()
    expected = simulate_cases(*batch, tail_s=TAIL_S)
    assert set(expected.solver) >= {"sliding kernel", "rocking kernel"}  # the batch spans the solvers
    first = CachingRunner(Recording(), tmp_path)
    _assert_identical(first.simulate_cases(*batch, tail_s=TAIL_S), expected)
    again = CachingRunner(Recording(), tmp_path)  # a new process: reads the folder
    _assert_identical(again.simulate_cases(*batch, tail_s=TAIL_S), expected)
    assert again.inner.blocks == [] and again.cases_reused == len(batch[0]) and again.cases_simulated == 0


def test_mixed_hits_and_misses_come_back_in_case_order(tmp_path):
    blocks, records = _blocks(), _records()
    CachingRunner(Recording(), tmp_path).simulate_cases(*_batch(blocks[:2], records[:1]), tail_s=TAIL_S)
    # interleave: cached and new cases, the records in the other order
    case_blocks = [blocks[3], blocks[0], blocks[2], blocks[1], blocks[0], blocks[3]]
    index = np.array([1, 0, 0, 0, 1, 0])
    recs = [records[0].accel_g, records[1].accel_g]
    dts = [records[0].dt_s, records[1].dt_s]
    runner = CachingRunner(Recording(), tmp_path)
    got = runner.simulate_cases(case_blocks, recs, dts, index, tail_s=TAIL_S)
    _assert_identical(got, simulate_cases(case_blocks, recs, dts, index, tail_s=TAIL_S))
    # the two cases of record 0 with blocks 0 and 1 were stored; the rest ran (block 3 on record 0 once)
    assert runner.cases_simulated == 4 and runner.cases_reused == 2
    assert len(runner.inner.blocks) == 4


def test_unchanged_hits_and_a_changed_block_field_misses(tmp_path):
    batch = _batch()
    CachingRunner(Recording(), tmp_path).simulate_cases(*batch, tail_s=TAIL_S)
    blocks = _blocks()
    # the smallest change of one field: the next float after mu
    blocks[2] = replace(blocks[2], mu=float(np.nextafter(blocks[2].mu, 1.0)))
    recording = Recording()
    runner = CachingRunner(recording, tmp_path)
    got = runner.simulate_cases(*_batch(blocks), tail_s=TAIL_S)
    assert recording.blocks == [blocks[2], blocks[2]]  # its case under each of the two records, nothing else
    _assert_identical(got, simulate_cases(*_batch(blocks), tail_s=TAIL_S))


@pytest.mark.parametrize("field, value", [("restitution", 0.5), ("foot_inset_m", 0.01),
                                          ("cg_height_m", 0.45)])
def test_every_block_field_is_in_the_key(tmp_path, field, value):
    blocks = _blocks()
    CachingRunner(Recording(), tmp_path).simulate_cases(*_batch(blocks), tail_s=TAIL_S)
    blocks[0] = replace(blocks[0], **{field: value})
    recording = Recording()
    CachingRunner(recording, tmp_path).simulate_cases(*_batch(blocks), tail_s=TAIL_S)
    assert recording.blocks == [blocks[0], blocks[0]]


def test_a_nested_interface_field_is_in_the_key(tmp_path):
    blocks = _blocks()
    CachingRunner(Recording(), tmp_path).simulate_cases(*_batch(blocks), tail_s=TAIL_S)
    blocks[3] = replace(blocks[3], interface=SlidingInterface(yield_displacement_m=0.005))
    recording = Recording()
    CachingRunner(recording, tmp_path).simulate_cases(*_batch(blocks), tail_s=TAIL_S)
    assert recording.blocks == [blocks[3], blocks[3]]


def test_a_changed_record_sample_misses_only_that_records_cases(tmp_path):
    records = _records()
    CachingRunner(Recording(), tmp_path).simulate_cases(*_batch(records=records), tail_s=TAIL_S)
    edited = records[1].accel_g.copy()
    edited[10] = float(np.nextafter(edited[10], 2.0))
    records[1] = replace(records[1], accel_g=edited)
    recording = Recording()
    got = CachingRunner(recording, tmp_path).simulate_cases(*_batch(records=records), tail_s=TAIL_S)
    assert len(recording.blocks) == len(_blocks())
    assert all(np.array_equal(r, edited) for r in recording.records)
    _assert_identical(got, simulate_cases(*_batch(records=records), tail_s=TAIL_S))


def test_a_changed_time_step_or_tail_misses(tmp_path):
    blocks, recs, dts, index = _batch()
    CachingRunner(Recording(), tmp_path).simulate_cases(blocks, recs, dts, index, tail_s=TAIL_S)
    recording = Recording()
    CachingRunner(recording, tmp_path).simulate_cases(blocks, recs, [dts[0], dts[1] * 1.001], index,
                                                      tail_s=TAIL_S)
    assert len(recording.blocks) == len(_blocks())
    recording = Recording()
    CachingRunner(recording, tmp_path).simulate_cases(blocks, recs, dts, index, tail_s=TAIL_S + 1.0)
    assert len(recording.blocks) == len(blocks)


def test_an_engine_change_misses_everything(tmp_path):
    batch = _batch()
    CachingRunner(Recording(), tmp_path / "cache").simulate_cases(*batch, tail_s=TAIL_S)
    recording = Recording()
    CachingRunner(recording, tmp_path / "cache", version="another engine").simulate_cases(*batch, tail_s=TAIL_S)
    assert len(recording.blocks) == len(batch[0])
    # the version follows the engine's source: one changed byte of one module changes it
    mechanics = tmp_path / "mechanics"
    shutil.copytree(cache._MECHANICS, mechanics, ignore=shutil.ignore_patterns("__pycache__"))
    assert engine_version(mechanics) == engine_version()
    source = mechanics / "sliding.py"
    source.write_text(source.read_text() + "\n# a change\n")
    assert engine_version(mechanics) != engine_version()


def test_identical_cases_in_one_batch_run_once(tmp_path):
    twin = _blocks()[0]
    copy = Block(half_width_m=0.6, cg_height_m=0.5, height_m=1.0, mu=0.2)  # equal fields, another object
    recording = Recording()
    runner = CachingRunner(recording, tmp_path)
    records = _records()
    got = runner.simulate_cases([twin, copy], [records[0].accel_g], [records[0].dt_s], [0, 0], tail_s=TAIL_S)
    assert len(recording.blocks) == 1 and runner.cases_simulated == 1 and runner.cases_reused == 1
    assert got.sliding_max_m[0] == got.sliding_max_m[1] > 0.0


def test_a_damaged_pack_is_a_miss_not_an_error(tmp_path):
    batch = _batch()
    CachingRunner(Recording(), tmp_path).simulate_cases(*batch, tail_s=TAIL_S)
    (pack,) = tmp_path.glob("*.npz")
    pack.write_bytes(pack.read_bytes()[:100])  # truncated
    (tmp_path / "0000.npz").write_bytes(b"not a pack")
    recording = Recording()
    got = CachingRunner(recording, tmp_path).simulate_cases(*batch, tail_s=TAIL_S)
    assert len(recording.blocks) == len(batch[0])
    _assert_identical(got, simulate_cases(*batch, tail_s=TAIL_S))


def test_packs_are_merged_and_the_folder_is_bounded(tmp_path, monkeypatch):
    monkeypatch.setattr(cache, "MAX_PACKS", 2)
    blocks = _blocks()
    runner = CachingRunner(Recording(), tmp_path)
    for block in blocks:  # four calls, four packs: merged when past two
        runner.simulate_cases(*_batch([block]), tail_s=TAIL_S)
    assert 1 <= len(list(tmp_path.glob("*.npz"))) <= 2
    recording = Recording()
    CachingRunner(recording, tmp_path).simulate_cases(*_batch(), tail_s=TAIL_S)
    assert recording.blocks == []  # nothing lost in the merge
    bounded = CachingRunner(Recording(), tmp_path / "small", max_bytes=1)
    bounded.simulate_cases(*_batch(), tail_s=TAIL_S)
    assert list((tmp_path / "small").glob("*.npz")) == []  # over the bound: trimmed


def test_an_unwritable_folder_still_gives_the_numbers(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    runner = CachingRunner(LocalRunner(), blocker / "cache")  # its parent is a file: cannot be created
    got = runner.simulate_cases(*_batch(), tail_s=TAIL_S)
    _assert_identical(got, simulate_cases(*_batch(), tail_s=TAIL_S))
    assert runner.write_errors and runner.inner.cases_simulated == len(_batch()[0])


def test_block_fingerprint_is_exact():
    a = Block(half_width_m=0.1 + 0.2, cg_height_m=1.0, height_m=2.0, mu=0.2)
    b = Block(half_width_m=0.3, cg_height_m=1.0, height_m=2.0, mu=0.2)
    assert a.half_width_m != b.half_width_m and block_fingerprint(a) != block_fingerprint(b)
    assert "0.30000000000000004" in block_fingerprint(a)


def test_two_runners_on_one_folder_lose_nothing(tmp_path):
    blocks = _blocks()
    first, second = CachingRunner(Recording(), tmp_path), CachingRunner(Recording(), tmp_path)
    first.simulate_cases(*_batch(blocks[:2]), tail_s=TAIL_S)  # both started before either wrote
    second.simulate_cases(*_batch(blocks[2:]), tail_s=TAIL_S)
    second.simulate_cases(*_batch(blocks[:2]), tail_s=TAIL_S)  # sees what the first one stored
    assert second.inner.blocks == _batch(blocks[2:])[0]
    third = Recording()
    CachingRunner(third, tmp_path).simulate_cases(*_batch(), tail_s=TAIL_S)
    assert third.blocks == []
