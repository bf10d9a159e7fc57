"""Equipment on yielding buildings: the tool's yielding route against OpenSees buildings of our own (issue 29).

Three yielding OpenSeesPy shear buildings not built from the tool's stick (tests/peers/opensees_buildings.py:
steel special moment frames of 4 and 8 storeys, a pinching concrete wall of 6; tapering stiffness, an
overstrength growing up the height), 11 of pyslammer's real records scaled to the design spectrum at T_1
(DE), six items on the mid-height floor and the roof, through the product itself (``run_assessment``)
with only the floor histories differing (tests/peers/yielding_equipment.py). What is claimed, and checked:

* with ``yield_base_shear_g`` the OpenSees building's, and with only the design data (the default
  overstrength 2), the sliding's geometric mean tool/truth lies in [0.67, 1.5] on every building, and
  nearer 1 than today's elastic route;
* a larger overstrength slides more (1.5, 2, 3: the design-data route's sensitivity);
* the roof's PFA/PGA stays below ASCE 7-22's H_f (a sanity check).

The issue's stricter targets with the given strength (gm in [0.8, 1.25], σ ln ≤ 0.45, overturn verdicts
≥ 75 % where either overturns, risk class ≥ 80 %) are **not** met on these buildings (measured: gm
0.69-1.18, σ ln 0.44-1.06, overturn verdicts 14-57 % where either overturns (98-99 % over all cases),
risk class 67-100 %; benchmarks/bench_yielding_equipment.py prints the table): that test is a strict
xfail, so that it says so until it passes. The 8-storey frame is furthest: its roof shakes 1.6 times the
OpenSees one, because the tool's frames keep an elastic flexural column beside the yielding springs
(assess.building.nonlinear.FLEXURE_BY_SYSTEM) while these OpenSees buildings are shear buildings, and
because the tool spreads the strength as the code does while these buildings are stronger up the height.

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
    from peers.opensees_buildings import BUILDINGS
    from peers.yielding_equipment import assess, compare, ground_suite, opensees_floors, workbook

    out = {}
    for name, truth in BUILDINGS.items():
        suite = ground_suite(11, truth.period_s, 1.0)
        folder = tmp_path_factory.mktemp(name)
        with opensees_floors(truth, suite):
            reference = assess(workbook(folder, truth, suite, "DE", [["response", "yielding"]]), "DE")
        routes = {"given": [["response", "yielding"], ["yield_base_shear_g", round(truth.yield_base_shear_g, 6)]],
                  "elastic": [["response", "elastic"]]}
        routes.update({f"design x {o:g}": [["response", "yielding"], ["overstrength", o]] for o in OVERSTRENGTHS})
        results = {route: assess(workbook(folder, truth, suite, "DE", rows), "DE") for route, rows in routes.items()}
        numbers = {route: compare(result, reference) for route, result in results.items()}
        out[name] = {"truth": truth, "numbers": numbers, "floors": results["given"][0].floors.set_index("floor")}
    return out


@pytest.mark.parametrize("route", ["given", "design x 2"])
def test_sliding_within_a_factor_of_one_and_a_half_and_nearer_than_the_elastic_route(measured, route):
    for name, m in measured.items():
        gm, elastic = m["numbers"][route]["gm"], m["numbers"]["elastic"]["gm"]
        assert 1 / 1.5 <= gm <= 1.5, (name, route, gm)
        assert abs(np.log(gm)) < abs(np.log(elastic)), (name, route, gm, elastic)
        assert m["numbers"][route]["n_sliding"] >= 100  # enough sliding cases to mean something


def test_a_larger_overstrength_slides_more(measured):
    for name, m in measured.items():
        gms = [m["numbers"][f"design x {o:g}"]["gm"] for o in OVERSTRENGTHS]
        assert gms == sorted(gms) and gms[-1] > 1.5 * gms[0], (name, gms)


def test_the_roof_pfa_over_pga_stays_below_asce_7_22_hf(measured):
    for name, m in measured.items():
        truth, floors = m["truth"], m["floors"]
        roof = floors.loc[truth.storeys]
        assert roof["pfa_over_pga_median"] < float(height_factor(1.0, truth.period_s)), name


@pytest.mark.xfail(strict=True, reason="issue 29's targets with the given strength are not met on these buildings "
                                       "(module docstring)")
def test_the_issue_targets_with_the_given_strength(measured):
    for name, m in measured.items():
        n = m["numbers"]["given"]
        assert 0.8 <= n["gm"] <= 1.25 and n["sigma_ln"] <= 0.45, (name, n)
        assert n["overturn_agree"] >= 0.75 and n["class_agree"] >= 0.8, (name, n)
