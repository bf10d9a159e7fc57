"""What the building's α moves: the yielding route against OpenSees frames whose column is stiffer or softer.

The frames of tests/peers/opensees_buildings.py carry a continuous elastic column beside their storey springs,
with α = H √(GA/EI) = 10, inside the 5 to 20 Miranda & Taghavi (2005) give moment frames; the tool takes 12 for
a moment frame whose ``lateral_stiffness_ratio`` the building sheet does not give. Here the same three frames
(``smf4``, ``smf8``, ``rcf5``) are built with α 5 (columns four times as stiff against the storeys) and 20 (a
quarter), each with the pushover base shear at first yield that column gives it, under the 11 records at DE,
and the product (tests/peers/yielding_equipment.py) runs on them with that ``yield_base_shear_g`` twice: with the
system's α and with the building's own in ``lateral_stiffness_ratio``. Claimed and checked:

* with the building's α the sliding's geometric mean tool/truth lies in issue 29's [0.8, 1.25] on every frame
  at both α (measured 0.96 to 1.18, the frames' storeys at one yield drift ratio; 0.87 to 1.09 before, at the
  first storey's);
* with the system's α it does not on some (measured: ``smf8`` at α 5, 0.44; ``rcf5`` at α 20, 1.78): α, which
  the design data do not fix, moves the upper floors' sliding by up to a factor of 2.6, as much as the
  strength does, which is why the sheet takes it and the report says when it is assumed.

* no answer from the strength alone can meet the targets on every frame: ``smf8`` with α 5 and with α 20 has the
  same pushover strength (0.1316 and 0.1314 W), and its items slide about three times apart (gm 0.35 the α-20
  truth against the α-5 one under the same records, σ ln 0.70; ``rcf5`` 0.37 at strengths 0.231 and 0.202 W,
  ``smf4`` 0.68 at 0.323 and 0.294 W), where the targets' window is 1.56 wide;

* with the pushover's slope at 2 % roof drift in ``pushover_slope_ratio`` in place of α (read off OpenSees' curve,
  the strength from the same pushover; ``--pushover-slope``), the tool finds α 5.4 to 5.6 for the frames of α 5, and
  every one of their items' sliding lies in [0.8, 1.25] (0.96 to 1.13) with σ ln ≤ 0.45 (0.25 to 0.29); for the
  frames of α 20 no α up to 30 gives the stick a slope as low as theirs (0.032; the stick's springs harden at 3 %,
  theirs at 2 %), the tool takes 30 and says so, and their sliding is 0.75 (``smf8``), 0.92 and 0.98: nearer 1
  than with the system's α wherever that one misses, within [0.67, 1.5] everywhere, and the risk class agrees on
  at least 0.75 of the items (at DE; at MCE_R 0.76 to 1.11, ``benchmarks/bench_yielding_equipment.py
  --truth-alphas 5,20 --pushover-slope``).

Not claimed: σ ln ≤ 0.45 with the building's α at α 20 (``rcf5`` 0.54, ``smf8`` 0.64; at α 5 0.13 to 0.28), the
softer column letting the drift gather in a storey, where small differences decide which one
(``benchmarks/bench_yielding_equipment.py --truth-alphas 5,20`` gives every column at DE and MCE_R). The
difference that decides it is the storeys' strengths against each other: with the frames' own in
``storey_strength`` σ ln is 0.09 and 0.18 (test_yielding_storey_strength.py).

Skipped, with the reason, where openseespy or pyslammer is not importable.
"""
from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from peers.opensees_buildings import BUILDINGS
from peers.opensees_shear import load_opensees

OPS, WHY = load_opensees()
pytestmark = pytest.mark.skipif(OPS is None, reason=str(WHY))

FRAMES = ("smf4", "smf8", "rcf5")
ALPHAS = (5.0, 20.0)


@pytest.fixture(scope="module")
def measured(tmp_path_factory):
    pytest.importorskip("pyslammer")
    from peers.yielding_equipment import (assess, compare, given_pushover, given_strength, ground_suite, truth_result,
                                         workbook)

    out = {}
    for name in FRAMES:
        own = BUILDINGS[name]
        suite = ground_suite(11, own.period_s, 1.0)
        for alpha in ALPHAS:
            truth = dataclasses.replace(own, column_alpha=alpha)
            folder = tmp_path_factory.mktemp(f"{name}-{alpha:g}")
            reference = truth_result(truth, suite, "DE", folder)
            strength = given_strength(truth)
            out[name, alpha, "truth"], out[name, alpha, "strength"] = reference, strength[1][1]
            for route, rows in (("system's", strength),
                                ("building's", strength + [["lateral_stiffness_ratio", alpha]]),
                                ("pushover's", given_pushover(truth))):
                result = assess(workbook(folder, truth, suite, "DE", rows), "DE")
                out[name, alpha, route] = compare(result, reference)
    return out


@pytest.mark.parametrize("name", FRAMES)
@pytest.mark.parametrize("alpha", ALPHAS)
def test_with_the_buildings_alpha_the_sliding_is_within_the_issue_target(measured, name, alpha):
    numbers = measured[name, alpha, "building's"]
    assert numbers["n_sliding"] >= 100, numbers  # enough sliding cases to mean something
    assert 0.8 <= numbers["gm"] <= 1.25, (name, alpha, numbers)


def test_with_the_systems_alpha_it_is_not_on_some(measured):
    system = {key[:2]: numbers["gm"] for key, numbers in measured.items() if key[2] == "system's"}
    outside = {key: gm for key, gm in system.items() if not 0.8 <= gm <= 1.25}
    assert outside, system
    for key, gm in outside.items():  # and the building's own α brings each of those nearer
        assert abs(np.log(measured[(*key, "building's")]["gm"])) < abs(np.log(gm)), (key, gm)


def test_the_strength_alone_cannot_tell_two_frames_apart_whose_items_slide_three_times_apart(measured):
    """``smf8`` with α 5 and with α 20: the same pushover strength to 0.1 % (0.1316 and 0.1314 W), and their own items
    slide about three times apart (the α-20 truth against the α-5 one under the same records: gm 0.35, σ ln 0.70,
    the same risk class for 25 % of the items). The targets' window is a factor 1.25 / 0.8 = 1.56 wide, so no
    answer computed from the strength alone lies within the targets of both: the strength cannot stand in for α."""
    from peers.yielding_equipment import TARGET_GM, compare

    low, high = (measured["smf8", alpha, "strength"] for alpha in ALPHAS)
    assert abs(np.log(high / low)) < 0.01, (low, high)
    apart = compare(measured["smf8", 20.0, "truth"], measured["smf8", 5.0, "truth"])
    assert apart["n_sliding"] >= 100, apart
    assert apart["gm"] < TARGET_GM[0] / TARGET_GM[1], apart


def test_with_the_pushover_s_slope_the_sliding_comes_nearer_than_with_the_system_s_alpha(measured):
    """Where the system's α misses the issue's range, the α found from the pushover's slope comes nearer; at α 5 it
    meets the sliding targets; everywhere the sliding is within [0.67, 1.5] and the class agrees on ≥ 0.75."""
    for name in FRAMES:
        for alpha in ALPHAS:
            system, pushover = measured[name, alpha, "system's"], measured[name, alpha, "pushover's"]
            if not 0.8 <= system["gm"] <= 1.25:
                assert abs(np.log(pushover["gm"])) < abs(np.log(system["gm"])), (name, alpha, system, pushover)
            assert 0.67 <= pushover["gm"] <= 1.5, (name, alpha, pushover)
            assert pushover["class_agree"] >= 0.75, (name, alpha, pushover)
        at_five = measured[name, 5.0, "pushover's"]
        assert 0.8 <= at_five["gm"] <= 1.25 and at_five["sigma_ln"] <= 0.45, (name, at_five)
