"""The one simulation gateway: every run of the engine goes through a runner, whatever its kind.

A counting runner around :class:`LocalRunner` sees every case of an assessment (the level's peaks, the
stripes of the hazard curve, the planar sliding of a record pair, the worst-run histories), counted from
the workbook, not from the run's own outputs; a cache folder answers a second run without a simulation;
a case gives the same bytes whatever batch it is in; and no module outside ``assess/mechanics`` imports a
kernel.
"""
from __future__ import annotations

import ast
import dataclasses
from pathlib import Path

import numpy as np
import pytest

from assessed import run_assessment
from assess.hazard.openquake import read_openquake_hazard
from assess.hazard.pulses import pulse_acceleration
from assess.mechanics.block import Block
from assess.command.cache import CachingRunner, case_keys
from assess.mechanics.gateway import (PEAKS, PLANAR, PLANAR_KERNEL, RESPONSE, Cases, LocalRunner, RunnerBase,
                                      run_cases)
from assess.mechanics.sliding import sliding_response
from assess.mechanics.sliding_2d import sliding_2d_peaks_batch
from tests.fragility.test_planar import component, pair_inventory

REPO = Path(__file__).resolve().parents[2]
CURVE = REPO / "inventories" / "lab-hazard-curve.csv"
#: The public API of the engine; every other module of assess/mechanics is a solver or its parts.
ENGINE_API = {"gateway", "runner", "block", "geometry", "modes", "distributed"}


class Counting(RunnerBase):
    """A runner that hands every batch to a :class:`LocalRunner` and counts the runs by kind."""

    def __init__(self):
        self.inner, self.seen = LocalRunner(), {}
        self.cases_simulated, self.runs_simulated = 0, {}

    def run(self, cases, *, progress=None):
        self.seen[cases.kind] = self.seen.get(cases.kind, 0) + len(cases)
        self._count(cases, len(cases))
        return self.inner.run(cases, progress=progress)


@pytest.fixture(scope="module")
def pair(tmp_path_factory):
    """The planar tests' two items (SLIDER cannot uplift, ROCKER can, its contents movable) under one record
    pair."""
    folder = tmp_path_factory.mktemp("pair")
    first = component(0.5, 0.9, 0.3)
    inventory = pair_inventory(folder, first, component(0.4, 0.7, 1.1))
    return dataclasses.replace(inventory, equipment=inventory.equipment.assign(contents=["none", "movable"]))



def what_if_runs(result, equipment) -> int:
    """The runs of the actions' what-if (assess.decision.actions): every case of an item whose contents are
    movable (the workbook's ``equipment``) that rocks or overturns (centre of mass above
    lower_contents_cg_fraction of its height) again, under each of its histories."""
    motions, summary = result.motions, result.summary.set_index("id")
    rocks = set(motions.loc[motions["sim_uplift"].astype(bool), "id"]) | set(summary.index[summary["p_overturn"] > 0])
    rocks &= set(equipment.loc[equipment["contents"] == "movable", "id"])
    return int(motions.loc[motions["id"].isin(rocks), "sim_realizations"].sum())

def test_the_runner_sees_every_run_of_an_assessment(pair):
    """2 items x 1 motion x 2 directions (peaks), the stripes, SLIDER in the plane (the one item that cannot
    uplift under the one pair), and one worst-run history per item: all through the runner, none beside it."""
    runner = Counting()
    result = run_assessment(pair, "test", hazard_curve=read_openquake_hazard(CURVE), runner=runner)
    items, motions, directions = 2, 1, 2
    stripes = result.curve_risk.runs
    assert stripes > 0
    # summary.csv carries each item's contents as the workbook gives them
    assert result.summary.set_index("id").loc[["SLIDER", "ROCKER"], "contents"].tolist() == ["none", "movable"]
    lowered = what_if_runs(result, pair.equipment)  # the item that rocks, again with its contents low: 1 motion x 2 directions
    assert lowered == motions * directions
    assert runner.seen == {PEAKS: items * motions * directions + stripes + lowered, PLANAR: 1, RESPONSE: items}
    assert runner.inner.runs_simulated == runner.seen
    # the portfolio's account: peaks
    assert runner.cases_simulated == items * motions * directions + stripes + lowered
    assert len(result.histories) == items


def test_a_cache_answers_a_second_assessment_without_a_simulation(pair, tmp_path):
    """Planar and history runs are stored as the peaks are: the second run simulates nothing and gives the
    same summary, motions and histories, bit for bit."""
    first_runner = CachingRunner(LocalRunner(), tmp_path / "cache")
    first = run_assessment(pair, "test", runner=first_runner)
    assert set(first_runner.runs_simulated) == {PEAKS, PLANAR, RESPONSE}
    again = CachingRunner(Counting(), tmp_path / "cache")  # a new process: reads the folder
    second = run_assessment(pair, "test", runner=again)
    assert again.inner.seen == {} and not any(again.runs_simulated.values()) and again.cases_simulated == 0
    assert again.runs_reused == first_runner.runs_simulated
    assert second.summary.equals(first.summary) and second.motions.equals(first.motions)
    for got, want in zip(second.histories, first.histories, strict=True):
        assert got.keys() == want.keys()
        for key, value in want.items():
            if isinstance(value, np.ndarray):
                np.testing.assert_array_equal(got[key], value, err_msg=key)
            else:
                assert got[key] == value, key


def _blocks_and_records():
    time_s = np.arange(0.0, 2.0, 0.01)
    records = [pulse_acceleration("B", 0.5, 0.8, time_s), pulse_acceleration("A", 0.7, 0.5, time_s)]
    blocks = [Block(half_width_m=0.5, cg_height_m=0.5, height_m=1.0, mu=0.2),   # slides
              Block(half_width_m=0.2, cg_height_m=1.0, height_m=2.0, mu=0.7),   # rocks
              Block(half_width_m=0.3, cg_height_m=0.9, height_m=1.8, mu=0.35)]  # slide-rocks
    return blocks, records


def test_a_case_gives_the_same_bytes_in_any_batch():
    blocks, records = _blocks_and_records()
    alone = [run_cases(Cases.responses([b], [r], [0.01], [0], history=True))[0] for r in records for b in blocks]
    together = run_cases(Cases.responses([b for _ in records for b in blocks], records, [0.01, 0.01],
                                         np.repeat([0, 1], len(blocks)), history=True))
    for a, b in zip(alone, together, strict=True):
        assert (a.sliding_max_m, a.theta_max_over_alpha, a.mode_sequence, a.solver) == \
            (b.sliding_max_m, b.theta_max_over_alpha, b.mode_sequence, b.solver)
        np.testing.assert_array_equal(a.theta_rad, b.theta_rad)
    peaks = run_cases(Cases.peaks([blocks[0]] * 2, records, [0.01, 0.01], [0, 1]))
    assert peaks.sliding_max_m.tolist() == [together[0].sliding_max_m, together[3].sliding_max_m]


def test_planar_runs_are_the_2d_kernel_and_reduce_to_the_exact_1d_kernel_on_one_line():
    """A pair along one line (second = 0.75 first): the 2-D peak is Newmark's exact 1-D answer under the
    resultant 1.25 first (an independent kernel), and the gateway's numbers are the 2-D kernel's."""
    blocks, records = _blocks_and_records()
    slider = blocks[0]
    pair = [records[0], 0.75 * records[0]]
    peaks = run_cases(Cases.planar([slider], pair, [0.01, 0.01], [0], [1]))
    direct, _ = sliding_2d_peaks_batch([pair[0]], [pair[1]], 0.01, [slider.mu])
    assert peaks.sliding_max_m[0] == direct[0, 0] and peaks.solver[0] == PLANAR_KERNEL
    assert peaks.sliding_max_m[0] == pytest.approx(sliding_response(1.25 * records[0], 0.01, 0.2).sliding_max_m,
                                                   rel=1e-9)
    with pytest.raises(ValueError, match="cannot uplift"):
        run_cases(Cases.planar([blocks[1]], pair, [0.01, 0.01], [0], [1]))


def test_the_kind_of_run_is_part_of_the_cache_key():
    blocks, records = _blocks_and_records()
    asked = [Cases.peaks(blocks[:1], records[:1], [0.01], [0]),
             Cases.responses(blocks[:1], records[:1], [0.01], [0]),
             Cases.responses(blocks[:1], records[:1], [0.01], [0], history=True),
             Cases.responses(blocks[:1], records[:1], [0.01], [0], solver="general"),
             Cases.planar(blocks[:1], records, [0.01, 0.01], [0], [1]),
             Cases.planar(blocks[:1], records, [0.01, 0.01], [1], [0])]
    keys = [case_keys(cases, "v")[0] for cases in asked]
    assert len(set(keys)) == len(keys)


@pytest.mark.parametrize("build, message", [
    (lambda b, r: Cases("peaks", b, r, [0.01], [0], record_index_2=[0]), "record_index_2"),
    (lambda b, r: Cases("planar", b, r, [0.01], [0]), "record_index_2"),
    (lambda b, r: Cases("peaks", b, r, [0.01], [0], history=True), "response runs"),
    (lambda b, r: Cases.responses(b, r, [0.01], [0], solver="fast"), "solver must be"),
    (lambda b, r: Cases.peaks(b, r, [0.01], [1]), "names no record"),
    (lambda b, r: Cases("history", b, r, [0.01], [0]), "kind must be"),
])
def test_a_batch_that_asks_for_nothing_valid_is_refused(build, message):
    blocks, records = _blocks_and_records()
    with pytest.raises(ValueError, match=message):
        build(blocks[:1], records[:1])


def _imports(path: Path) -> set[str]:
    """Every module ``path`` imports, at the top or inside a function, as absolute names."""
    names = set()
    package = "assess." + ".".join(path.relative_to(REPO / "assess").parts[:-1])
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                base = ".".join(package.rstrip(".").split(".")[:len(package.rstrip(".").split(".")) - node.level + 1]
                                + ([base] if base else []))
            names.add(base)
            names.update(f"{base}.{alias.name}" for alias in node.names)
        elif isinstance(node, ast.Call) and getattr(node.func, "attr", "") == "import_module" and node.args \
                and isinstance(node.args[0], ast.Constant):
            names.add(node.args[0].value)
    return names


def test_no_module_outside_the_engine_imports_a_solver():
    """Outside assess/mechanics only the engine's API is imported (function-level imports included)."""
    offenders = []
    for path in sorted((REPO / "assess").rglob("*.py")):
        if "mechanics" in path.relative_to(REPO / "assess").parts:
            continue
        for name in _imports(path):
            parts = name.split(".")
            if parts[:2] == ["assess", "mechanics"] and len(parts) > 2 and parts[2] not in ENGINE_API:
                offenders.append(f"{path.relative_to(REPO)}: {name}")
    assert offenders == []
