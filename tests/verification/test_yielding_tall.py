"""A taller frame: the yielding route on a 12-storey steel moment frame against an OpenSees one (issue 29).

The truth is ``smf12`` (tests/peers/opensees_buildings.py, :data:`peers.opensees_buildings.TALL`): 12 storeys of
4 m, T_1 2.0 s, designed by ASCE 7-22's ELF procedure at S_DS 1.0 g, S_D1 0.6 g (C_s at its least, 0.044), its
members changing every two storeys (the roof pair at 0.36 of the base's stiffness), its overstrength growing from
2.0 at the base to 3.2 at the roof, the frames' continuous column (α 10), set before the tool was run on it. The
harness and the items are the other buildings' (tests/peers/yielding_equipment.py): pyslammer's real records
scaled to the design spectrum at T_1, six items on the mid-height floor and the roof, the product itself with
only the floor histories differing. The higher modes carry more of a tall frame's floor motion, and the truth
yields most at its top storeys (ductility up to 9 at DE, 13 at MCE_R).

Measured over the first 11 records at DE (``benchmarks/bench_yielding_equipment.py --buildings smf12 --motions 11
--overstrengths "" --own-alpha``), and over 17 records at DE / MCE_R (``--levels DE,MCE_R --motions 17 --skip
Duzce_1999_375-090 --overstrengths "2,3" --own-alpha``: Düzce, scaled to S_a(2 s) at MCE_R, peaks at 5.7 g, which
the workbook refuses as a likely unit mistake):

==============================  ===========================  ===========================  ==================
route                           sliding gm, 11 / 17 DE / 17   σ ln                         risk class
                                MCE_R
==============================  ===========================  ===========================  ==================
given strength (0.087 W)        0.66 / 0.66 / 0.70           0.73 / 0.66 / 0.46           0.58 / 0.50 / 0.83
and its pushover's slope        0.74 / – / –                 0.63 / – / –                 0.75 / – / –
and the model's hardening       0.89 / – / –                 0.43 / – / –                 0.75 / – / –
and its storeys' stiffnesses    0.98 / – / –                 0.36 / – / –                 0.83 / – / –
given strength and α 10         0.84 / 0.87 / 0.88           0.48 / 0.46 / 0.45           0.75 / 0.83 / 0.83
and its storeys' stiffnesses    0.99 / 0.98 / 0.94           0.35 / 0.38 / 0.36           0.83 / 0.92 / 1.0
and strengths, hardening        1.12 / – / –                 0.15 / – / –                 0.92 / – / –
design data (Ω 2.5)             0.995 / 1.02 / 1.02          0.28 / 0.33 / 0.39           0.83 / 0.67 / 1.0
elastic modes                   2.85 / 2.91 / 3.53           0.59 / 0.65 / 0.62           0.58 / 0.50 / 0.67
==============================  ===========================  ===========================  ==================

With the strength alone the tool slides the items a third less than the truth: the frame's α, which the
strength leaves open, decides it. The tool's α for a moment frame is 12 where this building's is 10, and
between those two the truth's own sliding moves by a third (the same routes against truths of α 12 and 14,
``--truth-alphas 12,14``: the tool with its α 12 gives 0.89 against the truth of α 12 and 1.00 against the one
of α 14; with α 14 given, 0.90). Given α, 0.84-0.90 on every one of those truths; given the storeys'
stiffnesses as well, every target of the issue holds (the roof pair at 0.36 of the base where the system's
design profile, storey stiffness with the storey shear, falls to 0.21). With the storeys' strengths
(``storey_strength``) and the springs' hardening beside them, the whole model, σ ln falls from 0.35 to 0.15 (over the
11 records but Düzce, DE / MCE_R, ``--own-alpha --own-strength``: gm 1.13 / 1.11, σ ln 0.14 / 0.14, class 0.92 /
1.0). The design data alone come out near 1
here because the default overstrength (2.5) is above this building's (2.0, the pushover's 0.087 over C_s 0.044):
the two errors cancel, as ``design x 2`` (the building's own overstrength, 0.68 / 0.71) shows.

With the slope of the same pushover at 2 % roof drift in ``pushover_slope_ratio`` (0.065, read off OpenSees' curve;
``--pushover-slope``) the tool finds α 11.1: its storey springs harden at 3 % where the truth's do at 2 %, and
one slope cannot tell the column from the springs (with the truth's springs at 3 % it finds 10.0,
test_truth_pushover.py). That brings the sliding two fifths of the way from the strength alone's to the building's α
(0.74 at DE; 0.83 at MCE_R over the same 11 records, where the strength alone gives 0.74) and the risk class to
0.75 (1.0 at MCE_R); the targets hold at MCE_R, not at DE (``--pushover-slope --levels DE,MCE_R --motions 11 --skip
Duzce_1999_375-090``). With the springs' 2 % written in ``storey_hardening_ratio`` beside the slope
(``--own-hardening``) it finds 9.6 (10.0 with the frame's storey stiffnesses as well): the sliding targets hold (gm
0.89, σ ln 0.43 over the first 11 records; 0.91 / 0.45 and 0.98 / 0.35 at DE and MCE_R over the 11 without Düzce),
the risk class stays at 0.75 at DE (0.92 at MCE_R), and with the frame's storey stiffnesses too every target holds
(0.98, 0.36, 0.83).

Where the building's α is not known, ``--alpha-range`` runs the level again at the moment frames' α 5 and 20:
with the strength alone, every item whose class it misses has a class that moves between the ends, and is
flagged (5 of 5 over these 11 records at DE; 8 of 8 over 17 at DE and MCE_R, ``--alpha-bracket``), and every
item's truth lies within what the ends and the system's α give.

Skipped, with the reason, where openseespy or pyslammer is not importable.
"""
from __future__ import annotations

import pytest

from peers.opensees_buildings import TALL
from peers.opensees_shear import load_opensees
from peers.yielding_equipment import (OWN_MODEL, PUSHOVER_HARDENING, PUSHOVER_MODEL, PUSHOVER_ROUTE, TARGET_GM,
                                     WHOLE_MODEL, meets_class_target, meets_sliding_targets)

OPS, WHY = load_opensees()
pytestmark = pytest.mark.skipif(OPS is None, reason=str(WHY))


@pytest.fixture(scope="module")
def tall(tmp_path_factory):
    pytest.importorskip("pyslammer")
    from peers.yielding_equipment import compared_on_its_own

    return compared_on_its_own(TALL["smf12"], tmp_path_factory.mktemp("smf12"))


def test_the_truth_is_what_its_text_says():
    """C_s at ASCE 7-22 eq. 12.8-5's least and k at T_1 2.0 s, as the peer module works them out by hand."""
    truth = TALL["smf12"]
    assert truth.design_cs == pytest.approx(max(min(1.0 / 8, 0.6 / (2.0 * 8)), 0.044 * 1.0))
    assert truth.exponent_k == pytest.approx(1 + (2.0 - 0.5) / 2)
    assert 0.0724 * 48.0 ** 0.8 < truth.period_s < 1.4 * 0.0724 * 48.0 ** 0.8  # within C_u T_a


def test_with_the_building_s_own_model_every_target_holds(tall):
    n = tall[OWN_MODEL]
    assert n["n_sliding"] >= 150
    assert meets_sliding_targets(n), n
    assert meets_class_target(n), n


def test_with_the_building_s_alpha_the_sliding_is_within_the_targets_gm(tall):
    """Given α, the geometric mean is within the issue's range; σ ln (0.48 over these 11 records) is not claimed."""
    n = tall["given + own α"]
    assert TARGET_GM[0] <= n["gm"] <= TARGET_GM[1], n


@pytest.mark.xfail(strict=True, reason="sliding gm 0.66 with the strength alone: the system's α 12 against the "
                                       "building's 10, between which the truth's own sliding moves by a third")
def test_with_the_given_strength_the_sliding_targets_hold(tall):
    assert meets_sliding_targets(tall["given"]), tall["given"]


def test_with_the_pushover_s_slope_the_sliding_and_the_class_come_nearer_than_with_the_strength_alone(tall):
    """The α found from the pushover's slope (11.1 for the frame's 10) moves the answer towards the building's α."""
    pushover, given, own = tall[PUSHOVER_ROUTE], tall["given"], tall["given + own α"]
    assert given["gm"] < pushover["gm"] < own["gm"], (given, pushover, own)
    assert pushover["class_agree"] > given["class_agree"], (given, pushover)


@pytest.mark.xfail(strict=True, reason="sliding gm 0.74 at DE with the pushover's slope: the α it finds (11.1) rests "
                                       "on the stick's springs hardening at 3 %, the frame's at 2 % (written, below)")
def test_with_the_pushover_s_slope_the_sliding_targets_hold(tall):
    assert meets_sliding_targets(tall[PUSHOVER_ROUTE]), tall[PUSHOVER_ROUTE]


def test_with_the_model_s_hardening_beside_the_slope_the_sliding_targets_hold(tall):
    """The frame's 2 % in ``storey_hardening_ratio``: α 9.6 found, gm 0.89, σ ln 0.43."""
    assert meets_sliding_targets(tall[PUSHOVER_HARDENING]), tall[PUSHOVER_HARDENING]


@pytest.mark.xfail(strict=True, reason="risk class 0.75 (9 of 12 items) at DE with the pushover's slope and the "
                                       "model's hardening, with the design's storey stiffnesses")
def test_with_the_model_s_hardening_beside_the_slope_the_risk_class_holds(tall):
    assert meets_class_target(tall[PUSHOVER_HARDENING]), tall[PUSHOVER_HARDENING]


def test_with_the_whole_model_but_alpha_every_target_holds(tall):
    """The pushover's strength and slope, the model's hardening and storey stiffnesses, α found (10.0)."""
    n = tall[PUSHOVER_MODEL]
    assert meets_sliding_targets(n), n
    assert meets_class_target(n), n


def test_with_the_whole_model_every_target_holds(tall):
    """The pushover's strength, α, the model's storey stiffnesses and strengths (``storey_strength``) and hardening:
    σ ln well under the issue's 0.45, where the same without the strengths is at 0.36."""
    n = tall[WHOLE_MODEL]
    assert n["n_sliding"] >= 150
    assert meets_sliding_targets(n), n
    assert meets_class_target(n), n
    assert n["sigma_ln"] < tall[OWN_MODEL]["sigma_ln"], (n, tall[OWN_MODEL])


def test_the_design_data_alone_are_within_the_design_range_and_the_elastic_modes_are_not(tall):
    """The issue's [0.67, 1.5] for the design data alone; the elastic modes slide the items well over twice as far."""
    assert 0.67 <= tall["design"]["gm"] <= 1.5, tall["design"]
    assert tall["elastic"]["gm"] > 2.0, tall["elastic"]


def test_alpha_range_flags_every_item_whose_class_the_strength_alone_misses(tall):
    """With the strength alone the class misses (0.58 here); run at the moment frames' α 5 and 20 as well
    (``--alpha-range``), every item it misses is flagged (its class moves between the ends), and every item's truth
    lies within what the ends and the system's α give."""
    n = tall["given"]
    assert n["n_class_missed"] >= 2, n  # the strength alone misses: the check below can fail
    assert n["class_missed_flagged"] == 1.0, n
    assert n["bracket_class_held"] == 1.0, n
