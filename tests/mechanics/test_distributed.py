"""The engine on a Dask cluster (``--scheduler``): the numbers of a run on this machine, bit for bit.

A scheduler and two worker processes are started on 127.0.0.1 (one thread
each). The main job on inventories/lab.xlsx is run serially (the session's run, tests/conftest.py)
and through the scheduler and its summary.csv and motions.csv compared byte for byte; the
runner itself is compared with the engine on cases of every solver, cut into
small tasks so that they spread over both workers and come back out of order. The pieces that
ship a batch (the block table, the tasks of equal cost) are checked against their definitions.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

distributed = pytest.importorskip("distributed")

from assess import cli  # noqa: E402
from assess.hazard.pulses import pulse_acceleration  # noqa: E402
from assess.mechanics.block import Block  # noqa: E402
from assess.mechanics.distributed import (DaskRunner, block_table, blocks_from_table, case_steps,  # noqa: E402
                                         cost_tasks, task_count)
from assess.mechanics.engine import (GENERAL, ROCKING_KERNEL, SLIDING_KERNEL, BlockOnInterface,  # noqa: E402
                                    SlidingInterface, simulate_cases)
from assess.mechanics.gateway import Cases, run_cases  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
LAB = ROOT / "inventories" / "lab.xlsx"


@pytest.fixture(scope="module")
def cluster():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None, silence_logs=40) as local:
        yield local


def _tasks_run(cluster) -> dict:
    """Tasks each worker has executed so far."""
    with distributed.Client(cluster.scheduler_address, set_as_default=False) as client:
        return client.run(lambda dask_worker: dask_worker.state.executed_count)


def test_main_job_through_the_scheduler_writes_the_serial_numbers(cluster, lab_run, tmp_path):
    """The serial run is the session's run of the lab on this machine (tests/conftest.py)."""
    scratch, done = lab_run
    serial, remote = scratch / "reports" / "lab-2in50", tmp_path / "remote"
    assert done.returncode == 0, done.stderr
    before = _tasks_run(cluster)
    assert cli.main([str(LAB), "--hazard", "2in50", "--out", str(remote), "--format", "xlsx", "--quiet",
                     "--scheduler", cluster.scheduler_address]) == 0
    after = _tasks_run(cluster)
    assert all(after[w] > before[w] for w in after)  # both workers ran some of the cases
    for name in ("summary.csv", "motions.csv"):
        assert (remote / name).read_bytes() == (serial / name).read_bytes(), name


def _mixed_cases():
    """Blocks that slide, rock, and slide-rock, under three pulses (every solver of the engine)."""
    time_s = np.arange(0.0, 2.0, 0.01)
    records = [pulse_acceleration(kind, amplitude, 1.0, time_s) for kind, amplitude in
               (("A", 0.5), ("B", 0.4), ("A", 0.9))]
    blocks, index = [], []
    for j in range(len(records)):
        for height_m in (0.8, 1.6, 2.4):
            for mu in (0.15, 0.3, 0.45, 0.7):
                blocks.append(Block(half_width_m=0.25, cg_height_m=height_m / 2, height_m=height_m, mu=mu))
                index.append(j)
    order = np.random.default_rng(7).permutation(len(blocks))  # records interleaved in case order
    return [blocks[k] for k in order], records, [0.01] * len(records), np.asarray(index)[order]


def test_runner_reassembles_in_case_order(cluster):
    blocks, records, dts, index = _mixed_cases()
    expected = simulate_cases(blocks, records, dts, index)
    assert {SLIDING_KERNEL, ROCKING_KERNEL, GENERAL} <= set(expected.solver)
    seen = []
    # tasks far smaller than the runner cuts by default: they spread over both workers and finish out of order
    runner = DaskRunner.connect(cluster.scheduler_address, tasks_per_thread=4, min_task_steps=1)
    try:
        got = runner.simulate_cases(blocks, records, dts, index, progress=lambda done, total: seen.append(done))
    finally:
        runner.close()
    assert runner.cases_simulated == len(blocks) and runner.tasks_run == 2 * 4
    assert seen[-1] == len(blocks) and seen == sorted(seen)
    for name in ("sliding_max_m", "sliding_residual_m", "theta_max_over_alpha", "uplift", "overturned", "mode",
                 "solver"):
        np.testing.assert_array_equal(getattr(got, name), getattr(expected, name), err_msg=name)


def test_planar_and_history_runs_on_the_cluster_are_the_local_ones(cluster):
    """Every kind of run goes through the runner: the cluster's planar peaks and full responses (histories
    included) are this machine's, bit for bit, in case order."""
    blocks, records, dts, index = _mixed_cases()
    sliders = [k for k, b in enumerate(blocks) if b.mu_static < b.b_over_h]
    planar = Cases.planar([blocks[k] for k in sliders], records, dts, index[sliders], (index[sliders] + 1) % 3)
    responses = Cases.responses(blocks[:12], records, dts, index[:12], tail_s=1.0, history=True)
    runner = DaskRunner.connect(cluster.scheduler_address, tasks_per_thread=3, min_task_steps=1)
    try:
        got_planar, got_responses = runner.run(planar), runner.run(responses)
    finally:
        runner.close()
    assert runner.runs_simulated == {"planar": len(sliders), "response": 12} and runner.cases_simulated == 0
    expected = run_cases(planar)
    for name in ("sliding_max_m", "sliding_residual_m", "mode", "solver"):
        np.testing.assert_array_equal(getattr(got_planar, name), getattr(expected, name), err_msg=name)
    for got, want in zip(got_responses, run_cases(responses), strict=True):
        assert (got.sliding_max_m, got.theta_max_over_alpha, got.mode_sequence, got.solver) == \
            (want.sliding_max_m, want.theta_max_over_alpha, want.mode_sequence, want.solver)
        np.testing.assert_array_equal(got.theta_rad, want.theta_rad)
        np.testing.assert_array_equal(got.sliding_m, want.sliding_m)


@pytest.mark.parametrize("address", ["tcp://127.0.0.1:1", "http://127.0.0.1:8787"])
def test_unreachable_or_invalid_scheduler_exits_2(address, tmp_path, capsys):
    out = tmp_path / "out"
    code = cli.main([str(LAB), "--hazard", "2in50", "--out", str(out), "--format", "xlsx", "--quiet",
                     "--scheduler", address])
    err = capsys.readouterr().err
    assert code == 2
    assert address in err and "--scheduler" in err and "Fix:" in err
    assert "Traceback" not in err
    assert not out.exists() or not any(out.iterdir())


def _odd_blocks():
    """Blocks of every field the table carries: restitution given, feet, both sliding interfaces, none."""
    return [Block(half_width_m=0.3, cg_height_m=0.6, height_m=1.2, mu=0.2, mu_static=0.25),
            Block(half_width_m=0.3, cg_height_m=0.6, height_m=1.2, mu=0.5, restitution=0.8, foot_inset_m=0.05),
            BlockOnInterface(half_width_m=0.5, cg_height_m=0.4, height_m=0.8, mu=0.2,
                             interface=SlidingInterface(yield_displacement_m=0.004)),
            BlockOnInterface(half_width_m=0.5, cg_height_m=0.4, height_m=0.8, mu=0.2, mu_static=0.3,
                             interface=SlidingInterface(low_speed_factor=0.6, rate_s_m=0.05)),
            BlockOnInterface(half_width_m=0.5, cg_height_m=0.4, height_m=0.8, mu=0.3)]


def test_block_table_gives_back_every_block_field_for_field():
    blocks = _odd_blocks()
    twice = blocks + [Block(half_width_m=0.3, cg_height_m=0.6, height_m=1.2, mu=0.2, mu_static=0.25)] + blocks
    table, rows = block_table(twice)
    assert table.shape[0] == len(blocks)  # an equal block, or the same object again, takes the same row
    assert rows.tolist() == [0, 1, 2, 3, 4, 0, 0, 1, 2, 3, 4]
    rebuilt = blocks_from_table(table)
    assert [type(b) for b in rebuilt] == [type(b) for b in blocks]
    assert rebuilt == blocks  # dataclass equality: every field, the interface's included

    class Marked(Block):
        pass

    assert block_table(blocks + [Marked(half_width_m=0.3, cg_height_m=0.6, height_m=1.2, mu=0.2)]) is None


def test_cost_tasks_take_every_case_once_and_an_equal_share_of_each_record():
    rng = np.random.default_rng(3)
    index = rng.integers(0, 7, size=1001)
    steps = np.array([400, 900, 50, 1200, 700, 300, 2000])[index]
    tasks = cost_tasks(index, steps, 6)
    assert len(tasks) == 6
    assert sorted(np.concatenate(tasks).tolist()) == list(range(index.size))
    for j in range(7):
        counts = [int(np.count_nonzero(index[t] == j)) for t in tasks]
        assert max(counts) - min(counts) <= 1, (j, counts)
    costs = [int(steps[t].sum()) for t in tasks]
    assert max(costs) - min(costs) <= 400 + 900 + 50 + 1200 + 700 + 300 + 2000  # one case of each record at most
    assert all(np.all(np.diff(index[t]) >= 0) for t in tasks)  # a task's cases in record order
    assert task_count(10**12, 50, 16) == 50 and task_count(5, 10, 16, min_task_steps=1) == 5


def test_case_steps_are_the_record_and_its_tail():
    blocks = _odd_blocks()[:2]
    cases = Cases.peaks(blocks, [np.zeros(101), np.zeros(10)], [0.01, 0.005], [1, 0], tail_s=0.5)
    assert case_steps(cases).tolist() == [10 + 100, 101 + 50]


def test_interface_and_unshippable_blocks_on_the_cluster_are_the_local_ones(cluster):
    """Blocks on sliding interfaces travel in the table; a block of a class the table does not know travels as
    itself: the numbers are this machine's either way."""
    time_s = np.arange(0.0, 2.0, 0.01)
    records = [pulse_acceleration("A", 0.6, 1.0, time_s), pulse_acceleration("B", 0.5, 0.8, time_s)]

    class Marked(Block):
        pass

    runner = DaskRunner.connect(cluster.scheduler_address, tasks_per_thread=2, min_task_steps=1)
    try:
        for extra in ([], [Marked(half_width_m=0.25, cg_height_m=0.8, height_m=1.6, mu=0.5)]):
            blocks = (_odd_blocks() + extra) * 2
            index = np.repeat([0, 1], len(blocks) // 2)
            expected = simulate_cases(blocks, records, [0.01, 0.01], index)
            got = runner.simulate_cases(blocks, records, [0.01, 0.01], index)
            for name in ("sliding_max_m", "sliding_residual_m", "theta_max_over_alpha", "uplift", "overturned",
                         "mode", "solver"):
                np.testing.assert_array_equal(getattr(got, name), getattr(expected, name), err_msg=name)
    finally:
        runner.close()
