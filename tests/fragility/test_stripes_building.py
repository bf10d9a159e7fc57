"""Stripes of ground acceleration through the building (assess/fragility/ground_stripes.py).

With a site and a building, the hazard curve's stripes scale the level's ground suite to PGAs fixed in
advance (0.05 to 2 g), pass each scaled ground history through the building to the items' floors and
fit each item's fragility in PGA. Checked here against what the code under test does not compute: the
floor histories the engine is handed against the building's modes applied here to the PGA-scaled ground
histories (built from the building sheet's numbers directly), the stripes against 0.05-2 g spaced in ln
PGA, the exported demand against pelicun's library name, and the rates of two levels of different
amplitude against each other (one rate per item), a curve update against a runner that counts.
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from assess.assessment.motions import level_motions
from assessed import run_assessment
from assess.building import building_modes
from assess.building.design import design_strength
from assess.building.nonlinear import yielding_response, yielding_stick
from assess.building.response import floor_records
from assess.fragility.stripes import fragility_files
from assess.hazard.openquake import read_openquake_hazard
from assess.hazard.records import Record
from assess.inventory import read_workbook
from assess.command.cache import CachingRunner
from assess.mechanics.gateway import PEAKS, LocalRunner, RunnerBase
from declared import check_file
from tests.assessment.test_floor_motions import BUILDING, EQUIPMENT, SITE
from workbooks import write_workbook

REPO = Path(__file__).resolve().parents[2]
CURVE = REPO / "inventories" / "lab-hazard-curve.csv"


def _uhs_text() -> str:
    """A uniform-hazard spectrum in OpenQuake 3.26's layout (tests/data/openquake/constructed-hazard_uhs-mean_1.csv)
    out to 5 s, of a smooth code-like shape (SA/PGA rising to 2.5 at 0.2-0.3 s, then falling about as 1/T),
    PGA 0.3 g at 10 % in 50 years and 0.75 g at 1 %."""
    shape = {0.0: 1.0, 0.05: 1.6, 0.1: 2.1, 0.2: 2.5, 0.3: 2.5, 0.5: 2.2, 0.75: 1.6, 1.0: 1.2, 1.5: 0.8,
             2.0: 0.6, 3.0: 0.4, 4.0: 0.3, 5.0: 0.24}
    names = ["PGA" if t == 0.0 else f"SA({t})" for t in shape]
    header = ["custom_site_id", "lon", "lat"] + [f"{poe}~{n}" for poe in (0.1, 0.01) for n in names]
    values = [f"{pga * ratio:.6E}" for pga in (0.3, 0.75) for ratio in shape.values()]
    meta = "\"generated_by='OpenQuake engine 3.26.0', kind='mean', investigation_time=50.0\""
    return "\n".join(["#" + "," * (len(header) - 1) + meta, ",".join(header),
                      ",".join(["LAB", "-122.30000", "37.90000"] + values)]) + "\n"


#: The stripes' PGAs, from the documented rule: 10 values from 0.05 to 2 g evenly in ln PGA.
STRIPES_G = np.exp(np.linspace(np.log(0.05), np.log(2.0), 10))
PREFIX = "fragility in PGA (ground), through the building"


class Recording(RunnerBase):
    """A runner that keeps every batch it is handed and counts the ``peaks`` cases."""

    def __init__(self):
        self.inner, self.batches, self.peaks = LocalRunner(), [], 0
        self.cases_simulated, self.runs_simulated = 0, {}

    def run(self, cases, *, progress=None):
        self.batches.append(cases)
        if cases.kind == PEAKS:
            self.peaks += len(cases)
        self._count(cases, len(cases))
        return self.inner.run(cases, progress=progress)


def _sheets(site=SITE, response=None):
    building = BUILDING + ([["response", response]] if response else [])
    return {"equipment": [dict(item) for item in EQUIPMENT], "site": site, "building": building}


@pytest.fixture(scope="module", params=["elastic", "yielding"])
def de_run(tmp_path_factory, request):
    """Level DE of the hospital of tests/assessment/test_floor_motions.py, with the lab's curve, through a cache;
    the building elastic, or yielding (its storeys' strength the code's design for the site sheet's values)."""
    folder = tmp_path_factory.mktemp("stripes")
    path = write_workbook(folder / "h.xlsx", _sheets(response=request.param))
    recording = Recording()
    runner = CachingRunner(recording, folder / "cache")
    recording.said = []  # what the run said of its progress, a line at every history through the building
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr("assess.building.yielding.PROGRESS_EVERY_S", 0.0)
        result = run_assessment(read_workbook(path), "DE", seed=3, hazard_curve=read_openquake_hazard(CURVE),
                                runner=runner, progress=recording.said.append)
    return path, folder, recording, result


def test_the_stripes_floor_histories_are_the_pga_scaled_ground_suite_through_the_building(de_run):
    path, _, recording, result = de_run
    level = level_motions(read_workbook(path), "DE", lambda m: None, seed=3)
    ground = [level.records[key] for key in level.table.loc[level.table["floor"] == 0, "record_path"]]
    assert len(ground) == 3
    # the building sheet's numbers: 2 storeys of 4 m, T1 0.3 s, 5 % damping (docs/workbook.md defaults)
    modes = building_modes(2, 4.0, system="other", period_s=0.3, damping=0.05)
    yielding = result.floors["response"].iloc[0] == "yielding" if "response" in result.floors else False
    if yielding:  # the code's design for S_DS 1.0, S_D1 0.6, risk category IV, times the overstrength 2
        strength = design_strength("other", [1.0, 1.0], [4.0, 8.0], 0.3, sds_g=1.0, sd1_g=0.6, risk_category="IV")
        stick = yielding_stick(2, 4.0, strength.storey_yield_ratio, system="other", period_s=0.3, damping=0.05)
    expected = {0: [], 1: [], 2: []}
    top_ductility = []
    for x in STRIPES_G:
        scaled = [Record(g.accel_g * (x / np.max(np.abs(g.accel_g))), g.dt_s, g.name) for g in ground]
        through = floor_records(modes, scaled, floors=[1, 2])
        expected[0] += [s.accel_g for s in scaled]
        for k, record in enumerate(scaled):
            floors = [through[1][k].accel_g, through[2][k].accel_g]
            if yielding:  # each stripe's scaled history through the stick (elastic modes where no storey yields)
                response = yielding_response(stick, record.accel_g, record.dt_s)
                if x == STRIPES_G[-1]:
                    top_ductility.append(response.ductility.max())
                    # yielding: not the linearly scaled elastic floor history
                    assert np.max(np.abs(response.floor_accel_g[2] - floors[1])) > 0.05 * np.max(np.abs(floors[1]))
                if response.ductility.max() >= 1.0:
                    floors = [response.floor_accel_g[1], response.floor_accel_g[2]]
            expected[1].append(floors[0])
            expected[2].append(floors[1])
    if yielding:
        assert min(top_ductility) > 1.0  # the strongest stripe yields the building under every motion
    # the first batch of stripes: the one after the level's own runs (18 cases); every item under its floor
    stripes = [b for b in recording.batches if b.kind == PEAKS][1]
    assert len(stripes) == 3 * 2 * 10 * 3  # items x directions x stripes x ground motions
    height_of = {round(item["height_cm"] / 100.0, 6): item["floor"] for item in EQUIPMENT}
    used = {0: [], 1: [], 2: []}
    for block, k in zip(stripes.blocks, stripes.record_index):
        used[height_of[round(block.height_m, 6)]].append(stripes.records_g[int(k)])
    for floor in (0, 1, 2):
        want = expected[floor]
        assert len(used[floor]) == 2 * len(want)  # both base directions under the same history
        for got in used[floor]:
            errors = [np.max(np.abs(got - w)) / np.max(np.abs(w)) for w in want if w.size == got.size]
            assert min(errors) < 1e-12, floor
        for w in want:  # and every expected history is run
            assert any(g.size == w.size and np.max(np.abs(g - w)) <= 1e-12 * np.max(np.abs(w)) for g in used[floor])


def test_each_floors_basis_says_what_its_stripes_went_through(de_run):
    """The ground floor's stripes are the scaled ground suite itself (the histories above: ``expected[0]`` is the
    ground history), the upper floors' that suite through the building; the basis the report prints says which."""
    _, _, _, result = de_run
    basis = {floor: f["basis"] for floor, f in result.curve_risk.floors.items()}
    assert sorted(basis) == [0, 1, 2]
    assert basis[0].startswith("floor 0: stripes of ground acceleration") and "building" not in basis[0]
    assert all(basis[floor].endswith("scaled and passed through the building") for floor in (1, 2))


def test_the_fragility_is_in_pga_and_exported_as_pelicuns_peak_ground_acceleration(de_run):
    _, _, _, result = de_run
    curve = result.curve_risk
    assert curve.intensity == "PGA"
    table = curve.table.set_index("id")
    assert (table["pfa_per_pga"] == 1.0).all()
    assert all(note.startswith(PREFIX + ", from the stripes of level DE's suite") for note in table["curve_note"])
    for item_id in ("G-1", "M-1", "R-2"):  # the ten stripes are the PGAs themselves, whatever the floor
        levels = np.sort(curve.stripes.query("id == @item_id")["pfa_g"].unique())
        assert all(np.isclose(levels, x, rtol=1e-12).any() for x in STRIPES_G), item_id
    files = fragility_files(curve, result.summary)
    csv = pd.read_csv(pd.io.common.BytesIO(files["fragility/fragility.csv"]))
    assert set(csv["Demand-Type"]) == {"Peak Ground Acceleration"}  # the DLML's name of PGA
    meta = json.loads(files["fragility/fragility.json"])
    comments = [meta[c]["Comments"] for c in meta if c != "_GeneralInformation"]
    assert comments and all("Fragility in PGA (ground), through the building" in c for c in comments)
    assert files["fragility/stripes.csv"].startswith(b"id,mode,pga_g,")
    for name in [name for name in files if name.endswith(".csv")]:
        check_file(files[name], name)  # pga_g declared, and the PGA offsets as whole numbers


def _updated_curve(folder: Path) -> Path:
    """The lab curve with every probability 20 % higher (a hazard model update)."""
    lines = CURVE.read_text().splitlines()
    values = lines[2].split(",")
    lines[2] = ",".join(values[:3] + [f"{min(1.0, float(v) * 1.2):.6E}" for v in values[3:]])
    path = folder / "updated-curve.csv"
    path.write_text("\n".join(lines) + "\n")
    return path



def what_if_runs(result) -> int:
    """The runs of the actions' what-if (assess.decision.actions): every case of an item whose contents are
    movable (the workbook's, or the default of its component type) that rocks or overturns (centre of mass
    above lower_contents_cg_fraction of its height) again, under each of its histories."""
    motions, summary = result.motions, result.summary.set_index("id")
    rocks = set(motions.loc[motions["sim_uplift"].astype(bool), "id"]) | set(summary.index[summary["p_overturn"] > 0])
    rocks &= set(summary.index[summary["contents"] == "movable"])
    return int(motions.loc[motions["id"].isin(rocks), "sim_realizations"].sum())

def test_a_curve_update_reintegrates_without_simulating(de_run):
    path, folder, first, result = de_run
    # the level's cases, the stripes and the actions' what-if: all simulated once
    assert first.peaks == 18 + result.curve_risk.runs + what_if_runs(result)
    again = CachingRunner(Recording(), folder / "cache")  # a new process reads the cache
    updated = run_assessment(read_workbook(path), "DE", seed=3,
                             hazard_curve=read_openquake_hazard(_updated_curve(folder)), runner=again)
    assert again.inner.peaks == 0 and again.cases_simulated == 0
    before, after = result.curve_risk.table.set_index("id"), updated.curve_risk.table.set_index("id")
    for item_id, fit in result.curve_risk.fits.items():
        again_fit = updated.curve_risk.fits[item_id]
        assert (again_fit.status, again_fit.median_g, again_fit.beta) == (fit.status, fit.median_g, fit.beta)
    fitted = before["annual_rate_beyond_clearance"].notna()
    assert fitted.any() and (after.loc[fitted, "annual_rate_beyond_clearance"]
                             > before.loc[fitted, "annual_rate_beyond_clearance"]).all()


@pytest.fixture(scope="module")
def two_levels(tmp_path_factory):
    """``--hazard 2in50,10in50 --oq-hazard`` the lab curve, the ground suites from the site's uniform-hazard
    spectrum, through the job (every level computed before any is written)."""
    from assess.command import job as job_module

    folder = tmp_path_factory.mktemp("levels")
    site = [["key", "value"], ["uhs", "oq/uhs.csv"], ["oq_site", "LAB"], ["suite_size", 3]]
    path = write_workbook(folder / "h.xlsx", _sheets(site), files={"oq/uhs.csv": _uhs_text()})
    recording = Recording()
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(job_module, "engine_runner", lambda scheduler, tls=None: recording)
        outputs = list(job_module.run_job(job_module.AssessmentJob(
            workbook=path, hazard="2in50,10in50", out=folder / "out", formats=(), oq_hazard=CURVE, seed=3)))
    return [o.result for o in outputs], recording


def test_two_levels_give_one_annual_rate_per_item(two_levels):
    (first, second), recording = two_levels
    ground = [r.ground_motions.set_index("motion")["pga_g"].to_numpy() for r in (first, second)]
    assert np.median(ground[0]) > 1.5 * np.median(ground[1])  # suites of different amplitude
    columns = ["annual_rate_beyond_clearance", "annual_rate_overturn", "p50yr_beyond_clearance",
               "p50yr_overturn", "curve_note"]
    a, b = (r.summary.set_index("id")[columns] for r in (first, second))
    pd.testing.assert_frame_equal(a, b)
    assert a["annual_rate_beyond_clearance"].notna().any()
    assert all(note.startswith(f"{PREFIX}, from the stripes of level {first.level_label}'s suite")
               for note in a["curve_note"])
    # the stripes ran once: the two levels' own cases (3 items x 3 motions x 2 directions each) and one set
    assert recording.peaks == 2 * 18 + first.curve_risk.runs + what_if_runs(first) + what_if_runs(second)
    assert second.curve_risk is first.curve_risk


def test_the_note_on_the_hazards_scaling_says_the_buildings_floors_take_the_scaled_ground_through_it(two_levels):
    """``--oq-hazard`` scales the level's ground motions to the curve's PGA before the building passes them to its
    floors; its note said "floor motions by the same factor", true of floors the workbook gives, not of a building's,
    whose floors a yielding storey keeps from scaling with the ground (seen on the sample hospital at 2in50)."""
    (first, second), _ = two_levels
    for result in (first, second):
        scaled = [note for note in result.hazard_notes if note.startswith("Motions scaled by")]
        assert len(scaled) == 1, result.hazard_notes
        assert scaled[0].endswith("; the floors without motions of their own take the scaled ground motions "
                                  "through the building."), scaled[0]
        assert "by the same factor" not in scaled[0]


def test_each_stripes_pass_through_a_yielding_building_says_how_far_it_has_got(de_run):
    """Through the yielding stick each stripe's pass reports its ground histories (3 here) up to all of them,
    for each of the 10 stripes (and the stripes added inside steep rises); the elastic modes' pass is instant
    and says nothing."""
    import re

    _, _, recording, result = de_run
    yielding = result.floors["response"].iloc[0] == "yielding" if "response" in result.floors else False
    found = [re.fullmatch(r"stripe ([\d.]+) g: through the building: (\d+) of (\d+) ground histories", line)
             for line in recording.said]
    ends = {m.group(1) for m in found if m and m.group(2) == m.group(3) == "3"}
    if not yielding:
        assert not ends, recording.said
        return
    assert {f"{x:.3g}" for x in STRIPES_G} <= ends, recording.said


def test_the_curve_says_which_stripes_took_the_yielding_building_past_its_drift_limit(de_run):
    """A stripe's pass through the yielding stick can drive its storeys past the drift it is trusted to (2 % for
    ``other``): those stripes still count, and the curve's notes name them and how many ground histories did it
    at the strongest, from the stick's own peak drifts (recomputed here); the elastic modes name none."""
    import re

    path, _, _, result = de_run
    yielding = result.floors["response"].iloc[0] == "yielding" if "response" in result.floors else False
    notes = [n for n in result.curve_risk.notes if "drift passed its limit" in n]
    if not yielding:
        assert not notes
        return
    level = level_motions(read_workbook(path), "DE", lambda m: None, seed=3)
    ground = [level.records[key] for key in level.table.loc[level.table["floor"] == 0, "record_path"]]
    strength = design_strength("other", [1.0, 1.0], [4.0, 8.0], 0.3, sds_g=1.0, sd1_g=0.6, risk_category="IV")
    stick = yielding_stick(2, 4.0, strength.storey_yield_ratio, system="other", period_s=0.3, damping=0.05)
    passed = {}
    for x in STRIPES_G:
        drifts = [yielding_response(stick, g.accel_g * (x / np.max(np.abs(g.accel_g))), g.dt_s).peak_drift_ratio.max()
                  for g in ground]
        passed[f"{x:.3g}"] = sum(d > 0.02 for d in drifts)
    assert passed[f"{STRIPES_G[-1]:.3g}"] > 0 and passed[f"{STRIPES_G[0]:.3g}"] == 0  # the check can go both ways
    note, = notes
    named = re.search(r"at the stripes? of (.+?) g \(under (\d) of (\d) ground histories at ([\d.]+) g\)", note)
    stripes = set(re.split(r", | and ", named.group(1)))
    assert {x for x, k in passed.items() if k} == stripes & set(passed)  # the ten stripes (refined ones besides)
    assert "(2 %)" in note and named.group(4) == f"{STRIPES_G[-1]:.3g}"
    assert (int(named.group(2)), int(named.group(3))) == (passed[named.group(4)], 3)


def test_the_stripes_and_the_refined_stripes_both_say_how_far_their_runs_have_got(de_run):
    """Both batches of stripe runs report their progress up to their whole count: the ten stripes', then the runs
    added where the failures rise steeply (each count the cases the runner was handed for it)."""
    import re

    _, _, recording, _ = de_run
    peaks = [len(b) for b in recording.batches if b.kind == PEAKS]
    said = recording.said
    refine_at = next(k for k, line in enumerate(said) if re.fullmatch(r"stripes: \d+ more where .+", line))
    done = [re.fullmatch(r"stripes: simulated (\d+) of (\d+) (runs|more runs)", line) for line in said]
    ends = [(k, m.group(3), int(m.group(2))) for k, m in enumerate(done) if m and m.group(1) == m.group(2)]
    (first_at, first_kind, first_total), (more_at, more_kind, more_total) = ends
    assert first_at < refine_at < more_at and (first_kind, more_kind) == ("runs", "more runs")
    # the level's own cases, the ten stripes', the refined ones' (the cache hands every one on: none run before)
    assert (first_total, more_total) == (peaks[1], peaks[2])


def test_the_curve_page_names_ground_acceleration_and_each_floors_basis_once(de_run):
    """Through a building the fragilities are in PGA (test above): the curve page's table heads their median
    "PGA", its lead says the level's ground motions were scaled and passed through the building, and the floors
    whose stripes went through the same (every floor above the ground) are named together before their basis."""
    import html as html_module

    from assess.report.render import render_html

    _, _, _, result = de_run
    page = html_module.unescape(render_html(result))
    assert "(median PGA, β)" in page and "(median PFA, β)" not in page
    assert "under the level's ground motions scaled to 10 stripes" in page and "of ground acceleration, and, above " \
        "the ground floor, passed through the building to the item's floor" in page
    basis = {floor: f["basis"] for floor, f in result.curve_risk.floors.items()}
    shared = basis[1].partition(": ")[2]
    assert basis[2].partition(": ")[2] == shared
    assert f"floor 0: {basis[0].partition(': ')[2]}; floors 1 and 2: {shared}." in page
