"""assess batch on a Dask cluster: its buildings spread over the workers, the files those of one machine.

A scheduler and two worker processes are started on 127.0.0.1. The same
portfolio is run with and without ``--scheduler``, then again with every
building edited, and every file of the two output folders (the cache's packs
aside) is compared byte for byte: the buildings' folders (their PDF reports
included, laid out on the workers), portfolio.csv with
each building's cases simulated and reused, changes.csv, the page and the
manifest. Two buildings share a workbook's items, so the second reuses the
first's cases: the count a worker cannot see, worked out afterwards
(:func:`assess.portfolio.spread.sequential_account`), which is also checked
against a cache run building after building.
"""
from __future__ import annotations

import io
import shutil
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

distributed = pytest.importorskip("distributed")

from assess import cli  # noqa: E402
from assess.command.cache import CachingRunner  # noqa: E402
from assess.hazard.pulses import pulse_acceleration  # noqa: E402
from assess.mechanics.block import Block  # noqa: E402
from assess.mechanics.gateway import Cases  # noqa: E402
from assess.portfolio.spread import sequential_account  # noqa: E402
from test_batch import ITEMS, LEVEL, _write_building  # noqa: E402
from workbooks import write_workbook  # noqa: E402

#: Two buildings with alpha's items: the second reuses every case of the first.
BUILDINGS = {"alpha": ITEMS["alpha"], "alpha-twin": ITEMS["alpha"], "beta": ITEMS["beta"]}


@pytest.fixture(scope="module")
def cluster():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None, silence_logs=40, env={"NUMBA_NUM_THREADS": "1"}) as local:
        yield local


def _portfolio(folder: Path, buildings) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    for name, items in buildings.items():
        _write_building(folder, name, items)
    return write_workbook(folder / "portfolio.xlsx",
                          {"buildings": [{"building": name, "workbook": f"{name}.xlsx", "level": LEVEL}
                                         for name in buildings]})


def _files(out: Path) -> dict:
    return {p.relative_to(out).as_posix(): p.read_bytes() for p in sorted(out.rglob("*"))
            if p.is_file() and ".cache" not in p.relative_to(out).parts}


def _executed(cluster) -> dict:
    with distributed.Client(cluster.scheduler_address, set_as_default=False) as client:
        return client.run(lambda dask_worker: dask_worker.state.executed_count)


def test_a_portfolio_on_the_cluster_writes_what_one_machine_writes(cluster, tmp_path, capsys):
    edited = {name: [(i, h, w, d, mu + 0.05 if i.endswith("2") else mu, c) for i, h, w, d, mu, c in items]
              for name, items in BUILDINGS.items()}
    originals, edits = _portfolio(tmp_path / "original", BUILDINGS).parent, _portfolio(tmp_path / "edited", edited).parent
    outs = {}
    for where, extra in (("here", []), ("cluster", ["--scheduler", cluster.scheduler_address])):
        # one site, its files the same bytes in both runs: the manifest holds their paths and digests
        site, out = tmp_path / "site", tmp_path / f"out-{where}"
        shutil.rmtree(site, ignore_errors=True)
        shutil.copytree(originals, site)
        before = _executed(cluster)
        assert cli.main(["batch", str(site / "portfolio.xlsx"), "--out", str(out), "--format", "xlsx,pdf",
                         *extra]) == 0
        after = _executed(cluster)
        printed = capsys.readouterr().err
        if extra:
            assert "buildings spread over 2 worker threads" in printed
            assert all(after[w] > before[w] for w in after)  # both workers assessed buildings
        first = _files(out)
        shutil.copytree(edits, site, dirs_exist_ok=True)  # every building edited: all assessed again
        assert cli.main(["batch", str(site / "portfolio.xlsx"), "--out", str(out), "--format", "xlsx", "--quiet",
                         *extra]) == 0  # the update's tables (the first run compared the PDFs)
        outs[where] = first, _files(out)
    for run in (0, 1):
        here, there = outs["here"][run], outs["cluster"][run]
        assert sorted(here) == sorted(there)
        for name in here:
            assert here[name] == there[name], (run, name)
    table = pd.read_csv(io.BytesIO(outs["cluster"][0]["portfolio.csv"])).set_index("building")
    # the twin reused every case of alpha (as one machine counts them), though a worker assessed it apart
    cases = len(ITEMS["alpha"]) * 2
    assert (table.loc["alpha", "cases_simulated"], table.loc["alpha", "cases_reused"]) == (cases, 0)
    assert (table.loc["alpha-twin", "cases_simulated"], table.loc["alpha-twin", "cases_reused"]) == (0, cases)


def test_the_sequential_account_is_what_a_cache_counts_building_after_building(tmp_path):
    """Three 'buildings' of overlapping batches through one cache, in order: its counts after each are the
    account of the keys each asked for, against the cache as it began (a pack stored beforehand)."""
    time_s = np.arange(0.0, 1.0, 0.01)
    records = [pulse_acceleration("A", 0.5, 0.8, time_s), pulse_acceleration("B", 0.4, 0.6, time_s)]
    blocks = [Block(half_width_m=0.4, cg_height_m=0.5, height_m=1.0, mu=mu) for mu in (0.1, 0.2, 0.3, 0.4)]

    def batch(picks):
        return Cases.peaks([blocks[b] for b, _ in picks], records, [0.01, 0.01], [j for _, j in picks])

    stored_before = batch([(0, 0), (1, 1)])
    buildings = [[batch([(0, 0), (2, 0), (2, 0)]), batch([(2, 0), (3, 1)])],
                 [batch([(0, 0), (3, 1), (1, 1), (1, 0)])],
                 [batch([(1, 0), (2, 1)])]]
    runner = CachingRunner(folder=tmp_path / "cache")
    runner.run(stored_before)
    fresh = CachingRunner(folder=tmp_path / "cache")
    fresh._load_new_packs()
    known = set(fresh.known_keys())
    assert len(known) == 2
    fresh.asked = []
    counted, asked = [], []
    for building in buildings:
        start, done = (fresh.cases_simulated, fresh.cases_reused), len(fresh.asked)
        for cases in building:
            fresh.run(cases)
        counted.append((fresh.cases_simulated - start[0], fresh.cases_reused - start[1]))
        asked.append(fresh.asked[done:])
    # by hand: (0,0) and (1,1) stored before; (2,0) new, again, again; (3,1) new; (1,0) new; (2,1) new
    assert counted == [(2, 3), (1, 3), (1, 1)]
    assert sequential_account(known, asked) == counted


class _Workers:
    """A client's two workers as BuildingSpread asks them: threads, and a function run on each; the second
    worker reads files as ``second`` says (None: as this machine)."""

    def __init__(self, second=None):
        self.second = second

    def nthreads(self):
        return {"tcp://a": 1, "tcp://b": 1}

    def run(self, function, *args):
        return {"tcp://a": function(*args), "tcp://b": function(*args) if self.second is None else self.second(*args)}


class _Runner:
    def __init__(self, client):
        self.inner = type("Inner", (), {"client": client})()


def test_buildings_are_spread_only_when_enough_and_every_worker_reads_their_files(tmp_path):
    from assess.portfolio.batch import building_records, prepare_buildings, read_portfolio
    from assess.portfolio.spread import BuildingSpread

    site = _portfolio(tmp_path / "site", BUILDINGS)
    prepared = prepare_buildings(read_portfolio(site))
    read = []

    def files_of(item):  # as run_batch gives them: the workbook and its record
        read.append(item.building.name)
        return [item.building.workbook, *building_records(item)]

    assert building_records(prepared[0]) == [str(site.parent / "records" / "m1.csv")]
    assert BuildingSpread(_Runner(_Workers()), files_of=files_of).applies(prepared)
    assert sorted(read) == sorted(BUILDINGS)
    few = BuildingSpread(_Runner(_Workers()), files_of=files_of)
    assert not few.applies(prepared[:1]) and "1 buildings to assess for 2 worker threads" in few.reason
    for elsewhere in (lambda paths: [None] * len(paths),  # no shared file system: the files are not there
                      lambda paths: ["another file"] * len(paths)):  # other files at the same paths
        apart = BuildingSpread(_Runner(_Workers(elsewhere)), files_of=files_of)
        assert not apart.applies(prepared) and "do not see the portfolio's workbooks" in apart.reason
