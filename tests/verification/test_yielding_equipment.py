"""Equipment on yielding buildings: the tool's yielding route against OpenSees buildings of our own (issue 29).

Three yielding OpenSeesPy buildings not built from the tool's stick (tests/peers/opensees_buildings.py: steel
special moment frames of 4 and 8 storeys with a continuous elastic column, a pinching concrete wall of 6;
ASCE 7-22 ELF designs, tapering stiffness, an overstrength growing up the height; the sources are in that
module), 11 of pyslammer's real records scaled to the design spectrum at T_1 (DE), six items on the
mid-height floor and the roof, through the product itself (``run_assessment``) with only the floor histories
differing (tests/peers/yielding_equipment.py). What is claimed, and checked:

* with ``yield_base_shear_g`` the OpenSees building's, and with only the design data (the default
  overstrength 2), the sliding's geometric mean tool/truth lies in [0.67, 1.5] and nearer 1 than today's
  elastic route: on the wall, and on the 4-storey frame with the strength given. **Not** on the 8-storey
  frame (measured 0.62 at DE, 0.83 at MCE_R, both routes; 0.42/0.56 with uniform storeys before the frames
  took the design's stiffness profile, docs/workbook.md ``storey_stiffness``), nor on the 4-storey frame from
  the design data (0.65 at DE, 0.76 at MCE_R; 0.61/0.72 before: its truth's base overstrength is 2.2, the
  default 2): strict xfails (:data:`SHORT`), so that they say so until they pass. Its truth is uncertain
  by about as much: with uniform storeys, the same measurement with the truth's column at α 12 (the tool's)
  gave 0.51/0.67, at α 20 0.70/0.98 (Miranda & Taghavi's range for frames is 5-20; the truth takes 10).
  Giving the tool the truth's own storey stiffnesses (``storey_stiffness``) gives 0.71/0.81 (4 storeys) and
  0.48/0.70 (8 storeys) with the strength given: no nearer than the design profile;
* a larger overstrength slides more (1.5, 2, 3: the design-data route's sensitivity);
* the roof's PFA/PGA stays below ASCE 7-22's H_f (a sanity check).

The issue's stricter targets with the given strength (gm in [0.8, 1.25], σ ln ≤ 0.45, overturn verdicts
≥ 75 % where either overturns, risk class ≥ 80 %) are **not** met (measured at DE and MCE_R: gm 0.62-1.31,
σ ln 0.28-0.47, overturn verdicts 58-87 % where either overturns (98-99 % over all cases), risk class
58-83 %; benchmarks/bench_yielding_equipment.py --levels DE,MCE_R prints the table): that test is a strict
xfail. The 4-storey frame comes nearest (gm 0.76/0.86, σ ln 0.38/0.28); the 8-storey frame's roof slides
too little at DE (above); the wall's too much (gm 1.31/1.27: the tool's capacity-designed upper wall,
assess.building.nonlinear.capacity_design_strength, is stronger than this truth's, whose upper reinforcement
is nearer its demand).

Skipped, with the reason, where openseespy or pyslammer is not importable.
"""
from __future__ import annotations

import numpy as np
import pytest

from assess.building.floors import height_factor
from peers.opensees_shear import load_opensees

OPS, WHY = load_opensees()
pytestmark = pytest.mark.skipif(OPS is None, reason=str(WHY))

OVERSTRENGTHS = (1.5, 2.0, 3.0)


@pytest.fixture(scope="module")
def measured(tmp_path_factory):
    pytest.importorskip("pyslammer")
    from peers.opensees_buildings import BUILDINGS, pushover_yield_base_shear_g
    from peers.yielding_equipment import assess, compare, ground_suite, opensees_floors, workbook

    out = {}
    for name, truth in BUILDINGS.items():
        suite = ground_suite(11, truth.period_s, 1.0)
        folder = tmp_path_factory.mktemp(name)
        with opensees_floors(truth, suite):
            reference = assess(workbook(folder, truth, suite, "DE", [["response", "yielding"]]), "DE")
        routes = {"given": [["response", "yielding"], ["yield_base_shear_g", round(pushover_yield_base_shear_g(truth), 6)]],
                  "elastic": [["response", "elastic"]]}
        routes.update({f"design x {o:g}": [["response", "yielding"], ["overstrength", o]] for o in OVERSTRENGTHS})
        results = {route: assess(workbook(folder, truth, suite, "DE", rows), "DE") for route, rows in routes.items()}
        numbers = {route: compare(result, reference) for route, result in results.items()}
        out[name] = {"truth": truth, "numbers": numbers, "floors": results["given"][0].floors.set_index("floor")}
    return out


#: (route, building) where the claim below is not met, with the measured gm (DE): strict xfails.
SHORT = {("given", "smf8"): 0.62, ("design x 2", "smf8"): 0.62, ("design x 2", "smf4"): 0.65}


def _cases():
    for route in ("given", "design x 2"):
        for name in ("smf4", "smf8", "wall6"):
            marks = ()
            if (route, name) in SHORT:
                marks = pytest.mark.xfail(strict=True, reason=f"{name}, {route}: gm {SHORT[route, name]} (DE), "
                                                              f"below 0.67 (module docstring)")
            yield pytest.param(route, name, marks=marks, id=f"{route}-{name}")


@pytest.mark.parametrize("route, name", list(_cases()))
def test_sliding_within_a_factor_of_one_and_a_half_and_nearer_than_the_elastic_route(measured, route, name):
    m = measured[name]
    gm, elastic = m["numbers"][route]["gm"], m["numbers"]["elastic"]["gm"]
    assert m["numbers"][route]["n_sliding"] >= 100  # enough sliding cases to mean something
    assert abs(np.log(gm)) < abs(np.log(elastic)), (name, route, gm, elastic)
    assert 1 / 1.5 <= gm <= 1.5, (name, route, gm)


def test_a_larger_overstrength_slides_more(measured):
    for name, m in measured.items():
        gms = [m["numbers"][f"design x {o:g}"]["gm"] for o in OVERSTRENGTHS]
        assert gms == sorted(gms) and gms[-1] > 1.5 * gms[0], (name, gms)


def test_the_roof_pfa_over_pga_stays_below_asce_7_22_hf(measured):
    for name, m in measured.items():
        truth, floors = m["truth"], m["floors"]
        roof = floors.loc[truth.storeys]
        assert roof["pfa_over_pga_median"] < float(height_factor(1.0, truth.period_s)), name


@pytest.mark.xfail(strict=True, reason="issue 29's targets with the given strength are not met on these buildings: "
                                       "gm 0.62-1.31, sigma ln up to 0.47, overturn verdicts 58-87 %, risk class "
                                       "58-83 % at DE and MCE_R (module docstring)")
def test_the_issue_targets_with_the_given_strength(measured):
    for name, m in measured.items():
        n = m["numbers"]["given"]
        assert 0.8 <= n["gm"] <= 1.25 and n["sigma_ln"] <= 0.45, (name, n)
        assert n["overturn_agree"] >= 0.75 and n["class_agree"] >= 0.8, (name, n)
