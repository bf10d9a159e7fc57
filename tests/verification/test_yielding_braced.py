"""A sixth system: the yielding route on a steel braced frame against an OpenSees braced frame (issue 29).

The truth is ``bf6`` (tests/peers/opensees_buildings.py, :data:`peers.opensees_buildings.BRACED`): a 6-storey
steel special concentrically braced frame designed by ASCE 7-22's ELF procedure at S_DS 1.0 g, S_D1 0.6 g, its
braces one section over two storeys, each storey as strong as its braces are stiff, and its braced bay bending as a
truss (α 2.4 from a chevron bay's brace and column areas, where the tool takes 4 for braced frames). The harness
and the items are the other buildings' (tests/peers/yielding_equipment.py): 11 of pyslammer's real records scaled
to the design spectrum at T_1, six items on the mid-height floor and the roof, the product itself with only the
floor histories differing. Measured (``benchmarks/bench_yielding_equipment.py --buildings bf6 --levels DE,MCE_R
--overstrengths "" --own-alpha``, each storey as strong as it is stiff at one yield drift ratio), DE / MCE_R:

==============================  ===========  ===========  ===========
route                           sliding gm   σ ln         risk class
==============================  ===========  ===========  ===========
given strength (0.439 W)        1.23 / 1.06  0.35 / 0.25  0.75 / 0.83
given strength and α 2.4        1.07 / 1.02  0.21 / 0.19  1.0 / 0.75
and its storeys' stiffnesses    1.04 / 1.00  0.20 / 0.11  0.92 / 1.0
and strengths, hardening        1.04 / 1.00  0.20 / 0.11  0.92 / 1.0
strength, pushover's slope      1.05 / 1.00  0.15 / 0.11  1.0 / 0.92
and the model's hardening       1.05 / 1.00  0.15 / 0.09  1.0 / 1.0
and its storeys' stiffnesses    1.04 / 1.00  0.20 / 0.11  0.92 / 1.0
design data (Ω 2)               1.04 / 0.92  0.38 / 0.28  0.83 / 0.67
elastic modes                   1.40 / 1.33  0.39 / 0.36  0.75 / 0.92
==============================  ===========  ===========  ===========

With the slope of the same pushover at 2 % roof drift (``pushover_slope_ratio`` 0.404, read off OpenSees' curve) in
place of α, the tool finds α 2.65 for the bay's 2.4 (``--pushover-slope``; its springs harden at 3 % where the
truth's do at 2 %, test_truth_pushover.py) and every target but the per-case overturn holds. With their 2 %
written in ``storey_hardening_ratio`` (``--own-hardening``) it finds 2.61, and 2.40 with the frame's storey
stiffnesses as well; the targets hold the same.

Before the storeys took one yield drift ratio (at the first storey's), the strength alone gave 1.13 / 1.00 and a
risk class of 0.75 at both levels, over 11 and over all 15 of the harness's records (with α 1.0 and 0.92); over
the 11 the three items that differed were the same at both levels (the mid-height
Kelvinator and ASP, the roof's rack): at DE the tool put them at moderate where the truth has low, their chance
of sliding past their room 2/11 against 1/11 or 0; at MCE_R at moderate where the truth has high, 4-5/11 against
6/11. For a braced frame the stiffness ratio α, which the strength leaves open, decides
the class, as it decides σ ln on the concrete frame (test_yielding_alpha.py). The truth yields little (storey
ductility up to 2.1 at DE, 3.1 at MCE_R; peak drift 0.8 % and 1.2 %), so the elastic route is nearer here than
on the moment frames. Neither model has the braces' buckling (the truth's springs are ``Steel01``, the tool's
bilinear). An exploratory truth with pinched loops in their place (OpenSees ``Hysteretic``, pinch 0.7/0.3, β 0.3;
not in the repository) gave, DE / MCE_R: gm 1.10 / 0.95 with the strength, 0.97 / 0.93 with α 2.4, and a risk
class with α of 0.92 / 0.75: the bilinear springs the tool gives braced frames hold for sliding there too, less
so for the class. test_yielding_buckling.py has a truth whose braces buckle and lose strength (``bf6b``).

Skipped, with the reason, where openseespy or pyslammer is not importable.
"""
from __future__ import annotations

import numpy as np
import pytest

from peers.opensees_buildings import BRACED
from peers.opensees_shear import load_opensees
from peers.yielding_equipment import (OWN_MODEL, PUSHOVER_HARDENING, PUSHOVER_MODEL, PUSHOVER_ROUTE, WHOLE_MODEL,
                                     meets_class_target, meets_sliding_targets)

OPS, WHY = load_opensees()
pytestmark = pytest.mark.skipif(OPS is None, reason=str(WHY))


@pytest.fixture(scope="module")
def braced(tmp_path_factory):
    pytest.importorskip("pyslammer")
    from peers.yielding_equipment import compared_on_its_own

    return compared_on_its_own(BRACED["bf6"], tmp_path_factory.mktemp("bf6"))


def test_the_truth_is_what_its_text_says():
    """The braced bay's α and the design's C_s as the peer module works them out by hand."""
    truth = BRACED["bf6"]
    assert truth.column_alpha == pytest.approx(24 * np.sqrt(1.29e9 / 1.25e11), abs=0.05)
    assert truth.design_cs == pytest.approx(min(1.0 / 6, 0.6 / (0.6 * 6)))
    shares = truth.storey_shear_ratios() / truth.storey_shear_ratios()[0]
    assert shares == pytest.approx([1, 0.956, 0.864, 0.723, 0.532, 0.292], abs=0.002)


def test_with_the_given_strength_the_sliding_targets_hold(braced):
    n = braced["given"]
    assert n["n_sliding"] >= 100
    assert meets_sliding_targets(n), n


@pytest.mark.xfail(strict=True, reason="risk class 75 % (9 of 12 items) with the strength alone over 11 records; "
                                       "100 % with the braced bay's α, 92 % with its own model")
def test_with_the_given_strength_the_risk_class_holds(braced):
    assert meets_class_target(braced["given"]), braced["given"]


def test_with_the_strength_and_the_braced_bays_alpha_every_target_but_the_per_case_overturn_holds(braced):
    n = braced["given + own α"]
    assert meets_sliding_targets(n) and meets_class_target(n), n


def test_with_the_strength_alpha_and_storey_stiffnesses_of_its_own_model_every_target_but_the_per_case_overturn_holds(
        braced):
    """What an engineer with the braced frame's model writes (peers.yielding_equipment.OWN_MODEL): gm 1.04,
    σ ln 0.20, risk class 0.92 at DE."""
    n = braced[OWN_MODEL]
    assert meets_sliding_targets(n) and meets_class_target(n), n


def test_with_the_whole_model_every_target_but_the_per_case_overturn_holds(braced):
    """The same and the storeys' strengths (``storey_strength``) and hardening (peers.yielding_equipment.WHOLE_MODEL):
    the braced frame's storeys are already as strong as they are stiff, so the strengths add little; what is left
    of σ ln is the Rayleigh damping's modes (the tool's 1 and 3, the truth's 1 and 2)."""
    n = braced[WHOLE_MODEL]
    assert meets_sliding_targets(n) and meets_class_target(n), n


def test_with_the_strength_and_the_pushover_s_slope_every_target_but_the_per_case_overturn_holds(braced):
    """The α found from the pushover's slope (2.65) does what the bay's own does: nearer than the strength alone."""
    n = braced[PUSHOVER_ROUTE]
    assert meets_sliding_targets(n), n
    assert meets_class_target(n), n
    assert abs(np.log(n["gm"])) < abs(np.log(braced["given"]["gm"])), (n, braced["given"])


@pytest.mark.parametrize("route", [PUSHOVER_HARDENING, PUSHOVER_MODEL])
def test_with_the_model_s_hardening_beside_the_slope_every_target_but_the_per_case_overturn_holds(braced, route):
    """The springs' 2 % written in ``storey_hardening_ratio``: the α found is 2.61 with the design's storey
    stiffnesses, 2.40 with the frame's own (test_truth_pushover.py); measured gm 1.05 and 1.04, σ ln 0.15 and 0.20,
    risk class 1.0 and 0.92 at DE."""
    n = braced[route]
    assert meets_sliding_targets(n), n
    assert meets_class_target(n), n


def test_from_the_design_data_within_a_factor_of_one_and_a_half_and_nearer_than_the_elastic_route(braced):
    gm, elastic = braced["design"]["gm"], braced["elastic"]["gm"]
    assert 1 / 1.5 <= gm <= 1.5 and abs(np.log(gm)) < abs(np.log(elastic)), (gm, elastic)


def test_alpha_range_flags_most_items_whose_class_the_strength_alone_misses(braced):
    """With the strength alone the class misses 3 of 12 items; run at the braced frames' α 1.5 and 6 as well
    (``--alpha-range``), the class of 2 of those 3 moves between the ends and is flagged. The third keeps one class
    at α 1.5, 4 and 6 where the truth's is another, yet with the bay's own α 2.4 every item's class holds at DE:
    the ends do not bound what lies between them."""
    n = braced["given"]
    assert n["n_class_missed"] >= 2, n  # the strength alone misses: the check below can fail
    assert n["class_missed_flagged"] >= 0.6, n
    assert n["bracket_class_held"] >= 0.9, n
