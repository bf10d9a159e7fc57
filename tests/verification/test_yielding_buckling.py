"""The yielding route on a braced frame whose braces buckle, against OpenSees (issue 29).

``bf6`` (test_yielding_braced.py) has bilinear storey springs, as the tool gives braced frames: neither has the
braces' buckling, by which a special concentrically braced frame does most of its yielding. ``bf6b``
(:data:`peers.opensees_buildings.BUCKLING`) is ``bf6`` with each storey made of its two braces, one pulled and one
pushed (:func:`peers.opensees_yielding.buckling_brace_pair`): the pushed one buckles at half the pulled one's
tension yield (AISC 360-16 eq. E3-2 at KL/r 90) and keeps 0.3 of that after buckling (AISC 341-16 §F2.3, as
recalled); pinched loops. Its storeys carry F_y at their yield drift, 1.41 F_y at twice it, then less, where
``bf6``'s harden at 2 %. The harness and the items are the other buildings' (tests/peers/yielding_equipment.py):
11 of pyslammer's records scaled to the design spectrum at T_1, six items on the mid-height floor and the roof.

Measured (``benchmarks/bench_yielding_equipment.py --buildings bf6b --levels DE,MCE_R --overstrengths ""``, and
``bf6b`` against ``bf6`` by :func:`peers.yielding_equipment.compare`), DE / MCE_R:

=========================================  ===========  ===========  ===========
route (against ``bf6b``)                   sliding gm   σ ln         risk class
=========================================  ===========  ===========  ===========
given strength (its pushover's, 0.439 W)   1.16 / 1.01  0.34 / 0.29  0.92 / 0.92
and the pushover's slope and hardening     0.99 / 0.95  0.18 / 0.18  0.92 / 0.83
design data (Ω 2)                          0.98 / 0.87  0.39 / 0.35  0.83 / 0.75
elastic modes                              1.32 / 1.28  0.40 / 0.36  0.92 / 0.83
``bf6`` (no buckling) against ``bf6b``     0.94 / 0.96  0.13 / 0.13  0.83 / 0.92
=========================================  ===========  ===========  ===========

With the braces buckling the roof's PFA is 4-5 % higher and the items slide 4-6 % farther than on ``bf6``: its
storeys, once the pulled brace yields, carry up to 1.41 F_y where ``bf6``'s carry 1.02 F_y at the same drift, and
the frame yields little (storey ductility 2-3) with its bay, bending as a truss (α 2.4), carrying a large share of
the storeys' shear elastically. The tool's
bilinear springs meet the sliding and class targets on it with the strength given, as on ``bf6`` (1.23 / 1.06,
0.35 / 0.25, 0.75 / 0.83).

A frame that yields more leans on the buckling more. With every storey 0.6 times as strong (first yield 0.263 W
where ``bf6b``'s is 0.439), the strength alone gives gm 0.94 / 0.78, σ ln 0.41 / 0.41, class 0.83 / 0.75: at
MCE_R the truth's storeys, gaining strength until the pulled brace yields, shake the floors harder than bilinear
springs that harden at 3 % past first yield (on ``bf6`` as weak, without buckling, 0.98 / 0.85, 0.40 / 0.37, class
1.0 / 0.92). The pushover's slope at 2 % roof drift, which the buckling frame's pushover shows rising, brings the
sliding back (0.98 / 0.90, σ ln 0.26 / 0.24) but not the class at MCE_R (0.75: 3 misses, 1 of them one motion
away).

The tool's own buckling braces (the building sheet's ``brace_buckling`` yes: the ``buckling`` law of
:mod:`assess.building.hysteresis`, OpenSees' Hysteretic rules re-written, the same brace pair as the truth's to
1e-9) meet the targets there: on the weaker frame at MCE_R gm 0.91, σ ln 0.37, class 0.83 with the strength alone;
on ``bf6b`` itself gm 1.21 / 1.07, σ ln 0.36 / 0.28, class 0.92 / 0.83 (DE / MCE_R); from the design data gm
1.04 / 1.01. On ``bf6``, whose braces do not buckle, they slide the items 1.29 / 1.13 times as far (the bilinear
springs 1.23 / 1.06), and on ``bf6`` 0.6 times as strong 1.07 / 1.00 (0.98 / 0.85): at MCE_R the law raises the
weaker frames' answer by the same sixth whether the truth's braces buckle or not (0.91/0.78 and 1.00/0.85), so what
it mends on the weaker ``bf6b`` is not the buckling alone (``benchmarks/bench_yielding_equipment.py --buildings
bf6b,bf6 --levels DE,MCE_R --overstrengths "" --brace-buckling``, and the same with ``--strength-factor 0.6``).
The law is the engineer's to choose, by what the braces do.

Skipped, with the reason, where openseespy or pyslammer is not importable.
"""
from __future__ import annotations

import numpy as np
import pytest

from peers.opensees_buildings import BRACED, BUCKLING
from peers.opensees_shear import load_opensees
from peers.opensees_yielding import (BRACE_BUCKLING_RATIO, BRACE_POST_BUCKLING_DEFORMATION_RATIO,
                                     BRACE_POST_BUCKLING_RATIO, buckling_brace_pair)
from peers.yielding_equipment import meets_class_target, meets_sliding_targets

OPS, WHY = load_opensees()
pytestmark = pytest.mark.skipif(OPS is None, reason=str(WHY))
LEVELS = {"DE": 1.0, "MCE_R": 1.5}


def _pushed(drifts, sign=1.0, k0=1000.0, fy=10.0, hardening=0.02):
    """The brace pair's force along a monotonic push to each of ``drifts`` (× its yield drift), ``sign`` the way."""
    OPS.wipe()
    OPS.model("basic", "-ndm", 1, "-ndf", 1)
    buckling_brace_pair(OPS, 10, k0, fy, hardening)
    OPS.testUniaxialMaterial(10)
    dy, out = fy / k0, {}
    for d in np.linspace(0.0, max(drifts), 2001)[1:]:
        OPS.setStrain(float(sign * d * dy))
        for target in drifts:
            if abs(d - target) < 1e-9:
                out[target] = sign * OPS.getStress() / fy
    OPS.wipe()
    return out


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_a_storey_of_buckling_braces_follows_its_backbone_worked_by_hand(sign):
    """k_0 1000 N/m, F_y 10 N, b 0.02 (yield drift d_y 0.01 m), each brace k_0/2, either way:

    * at 0.5 d_y, elastic: 0.5 F_y;
    * at d_y the pushed brace buckles at 0.5 F_y, the pulled one at k_0/2 d_y = 0.5 F_y: F_y;
    * at 2 d_y the pulled brace yields (F_y) and the pushed one has fallen a quarter of the way from 0.5 F_y to
      0.3 × 0.5 F_y = 0.15 F_y, which it reaches at 5 d_y: 0.5 - 0.35/4 = 0.4125 F_y; 1.4125 F_y;
    * at 5 d_y: F_y + 0.02 (k_0/2)(3 d_y) = 1.03 F_y and 0.15 F_y: 1.18 F_y.
    """
    assert (BRACE_BUCKLING_RATIO, BRACE_POST_BUCKLING_RATIO, BRACE_POST_BUCKLING_DEFORMATION_RATIO) == (0.5, 0.3, 5.0)
    forces = _pushed([0.5, 1.0, 2.0, 5.0], sign)
    assert forces == pytest.approx({0.5: 0.5, 1.0: 1.0, 2.0: 1.4125, 5.0: 1.18}, rel=1e-6)


def test_the_tool_s_buckling_braces_are_opensees_brace_pair():
    """The tool's ``buckling`` law (:func:`assess.building.hysteresis.brace_backbones`, the rules of OpenSees'
    Hysteretic re-written) against OpenSees' own pair of mirrored ``Hysteretic`` braces in ``Parallel``, along a
    drift path of cycles growing to 8 yield drifts either way and back (12,000 points, each committed): the same
    force to 1e-9 F_y (measured: 0, both ways)."""
    from assess.building.hysteresis import spring_forces
    k0, fy, hardening = 1000.0, 10.0, 0.02
    t = np.linspace(0.0, 60.0, 12001)
    path = fy / k0 * (np.sin(t) * np.linspace(0.3, 8.0, t.size) + 1.5 * np.sin(0.23 * t + 1.0)
                      + 0.4 * np.sin(3.1 * t))
    for way in (path, -path):
        OPS.wipe()
        OPS.model("basic", "-ndm", 1, "-ndf", 1)
        buckling_brace_pair(OPS, 10, k0, fy, hardening)
        OPS.testUniaxialMaterial(10)
        theirs = []
        for drift in way:
            OPS.setStrain(float(drift))
            theirs.append(OPS.getStress())
        OPS.wipe()
        ours = spring_forces(way, "buckling", k0, fy, hardening=hardening)
        assert np.abs(ours - np.array(theirs)).max() <= 1e-9 * fy
        assert max(theirs) > 1.4 * fy  # past the pulled brace's yield and the pushed one's buckling


#: The building sheet's row that gives the tool's braced frame buckling braces.
BUCKLING_ROW = [["brace_buckling", "yes"]]


@pytest.fixture(scope="module")
def buckled(tmp_path_factory):
    """compare()'s numbers per level: each route against ``bf6b``, and ``bf6`` itself against it."""
    pytest.importorskip("pyslammer")
    from peers.yielding_equipment import assess, compare, given_strength, ground_suite, truth_result, workbook
    truth, plain = BUCKLING["bf6b"], BRACED["bf6"]
    routes = {"given": given_strength(truth), "design": [["response", "yielding"]],
              "elastic": [["response", "elastic"]], "given + brace buckling": given_strength(truth) + BUCKLING_ROW,
              "design + brace buckling": [["response", "yielding"]] + BUCKLING_ROW}
    numbers = {}
    for level, factor in LEVELS.items():
        folder = tmp_path_factory.mktemp(f"bf6b-{level}")
        suite = ground_suite(11, truth.period_s, factor)
        reference = truth_result(truth, suite, level, folder)
        numbers[level] = {route: compare(assess(workbook(folder, truth, suite, level, rows), level), reference)
                          for route, rows in routes.items()}
        numbers[level]["bf6"] = compare(truth_result(plain, suite, level, folder), reference)
    return numbers


@pytest.mark.parametrize("level", list(LEVELS))
def test_the_braces_buckling_raises_the_truth_s_roof_motion(buckled, level):
    """The buckling truth is not ``bf6`` again: ``bf6``'s roof's median PFA is 0.958 and 0.948 of ``bf6b``'s (DE,
    MCE_R), and its items slide 0.94 and 0.96 times as far: stronger storeys once the pulled brace yields."""
    n = buckled[level]["bf6"]
    assert n["pfa_roof"] < 0.98, n
    assert n["gm"] < 0.98, n


@pytest.mark.parametrize("route", ["given", "given + brace buckling"])
@pytest.mark.parametrize("level", list(LEVELS))
def test_with_the_given_strength_the_sliding_and_class_targets_are_met_on_braces_that_buckle(buckled, level, route):
    """The bilinear springs: gm 1.16 / 1.01, σ ln 0.34 / 0.29, class 0.92 / 0.92 (DE / MCE_R); the tool's buckling
    braces (``brace_buckling`` yes): 1.21 / 1.07, 0.36 / 0.28, 0.92 / 0.83. On this frame, which yields little, the
    law moves little."""
    n = buckled[level][route]
    assert n["n_sliding"] >= 100
    assert meets_sliding_targets(n) and meets_class_target(n), n


@pytest.mark.parametrize("route", ["design", "design + brace buckling"])
@pytest.mark.parametrize("level", list(LEVELS))
def test_from_the_design_data_within_a_factor_of_one_and_a_half_and_nearer_than_the_elastic_route(buckled, level,
                                                                                                 route):
    """gm 0.98 / 0.87 with the bilinear springs, 1.04 / 1.01 with the buckling braces (DE / MCE_R)."""
    gm, elastic = buckled[level][route]["gm"], buckled[level]["elastic"]["gm"]
    assert 1 / 1.5 <= gm <= 1.5 and abs(np.log(gm)) < abs(np.log(elastic)), (gm, elastic)


#: The weaker braced frame (module text): every storey's strength times this.
WEAKER = 0.6


@pytest.fixture(scope="module")
def weaker(tmp_path_factory):
    """compare()'s numbers at MCE_R against ``bf6b`` with every storey :data:`WEAKER` times as strong: the strength
    alone, and with the pushover's slope."""
    pytest.importorskip("pyslammer")
    from peers.yielding_equipment import compared, given_pushover, given_strength, ground_suite, stronger
    truth = stronger(BUCKLING["bf6b"], WEAKER)
    suite = ground_suite(11, truth.period_s, LEVELS["MCE_R"])
    routes = {"given": given_strength(truth), "given + pushover slope": given_pushover(truth),
              "given + brace buckling": given_strength(truth) + BUCKLING_ROW}
    return compared(truth, suite, "MCE_R", tmp_path_factory.mktemp("bf6b-weaker"), routes)


@pytest.mark.xfail(strict=True, reason="a braced frame that yields more, its braces buckling: with the strength "
                                       "alone the items slide 0.78 times as far as on the truth at MCE_R")
def test_on_a_weaker_frame_whose_braces_buckle_the_strength_alone_meets_the_sliding_targets(weaker):
    assert meets_sliding_targets(weaker["given"]), weaker["given"]


def test_on_a_weaker_frame_whose_braces_buckle_the_pushover_s_slope_brings_the_sliding_back(weaker):
    """gm 0.90 and σ ln 0.24 with the slope, where the strength alone gives 0.78 and 0.41."""
    n, alone = weaker["given + pushover slope"], weaker["given"]
    assert meets_sliding_targets(n), n
    assert abs(np.log(n["gm"])) < abs(np.log(alone["gm"])), (n, alone)


def test_on_a_weaker_frame_whose_braces_buckle_the_braces_law_meets_the_targets_with_the_strength_alone(weaker):
    """gm 0.91, σ ln 0.37, class 0.83 at MCE_R with ``brace_buckling`` yes and the pushover's strength, where the
    bilinear springs give 0.78, 0.41, 0.75. Not the buckling alone: on ``bf6`` as weak, whose braces do not buckle,
    the law moves the answer as far (0.85 to 1.00; module text)."""
    n, bilinear = weaker["given + brace buckling"], weaker["given"]
    assert meets_sliding_targets(n) and meets_class_target(n), n
    assert abs(np.log(n["gm"])) < abs(np.log(bilinear["gm"])), (n, bilinear)
