"""Equipment on yielding buildings: the tool's yielding route against OpenSees buildings of our own (issue 29).

Five yielding OpenSeesPy buildings not built from the tool's stick (tests/peers/opensees_buildings.py: steel
special moment frames of 4 and 8 storeys and a reinforced-concrete one of 5 (``rcf5``, pinching springs) with a
continuous elastic column, a pinching concrete wall of 6 idealised as a shear building (``wall6``); ASCE 7-22 ELF
designs, tapering stiffness, an overstrength growing
up the height; and the same wall as it bends (``wallf6``: an elastic cantilever on a pinching base hinge whose
elastic stiffness, hardening and damping are set as concentrated-plasticity models set them, Ibarra &
Krawinkler's n = 10 and Zareian & Medina's damping); the sources are in that module), 11 of pyslammer's
real records scaled to the design spectrum at T_1 (DE), six items on the
mid-height floor and the roof, through the product itself (``run_assessment``) with only the floor histories
differing (tests/peers/yielding_equipment.py). The strength given to the tool is what an engineer would write:
the truth building's own pushover (ELF pattern) base shear at first yield of any storey, column included
(``pushover_yield_base_shear_g``: 0.305, 0.144 and 0.216 for the frames, whose first storey spring alone yields
at 0.275, 0.125 and 0.188 W; 0.36 for both walls). What is claimed, and checked:

* with that ``yield_base_shear_g``, and with only the design data (the system's default overstrength: 2.5
  for steel moment frames, 2 for the others), the sliding's geometric mean tool/truth lies in [0.67, 1.5]
  and nearer 1 than today's elastic route. From the design data, measured at DE/MCE_R (the frames' storeys as
  strong as they are stiff at one yield drift ratio, ``assess.building.nonlinear.stiffness_strength``, since
  2026-11-29; before, at the first storey's): ``smf4`` 1.01/1.05,
  ``smf8`` 1.10/1.17, ``rcf5`` 0.99/1.04, ``wall6`` 1.09/1.05, ``wallf6`` 1.23/1.21 (with 2 for every system, as
  before the steel frames took theirs, the steel frames gave 0.65/0.76 and 0.62/0.83 at DE/MCE_R, strict
  xfails then; 2.5 is Elkady & Lignos' pushover peak of 3.0 for steel moment frames with their gravity framing
  taken to the tool's Ω, assess/building/design.py, not fitted to these bare frames, whose base overstrength
  is 2.2 and 2.0 in their first storey's spring);
* a larger overstrength slides more (1.5, 2, 3: the design-data route's sensitivity; Ω 3 gives the frames
  1.23-1.64, the walls 1.41-1.65, benchmarks/bench_yielding_equipment.py);
* the roof's PFA/PGA stays below ASCE 7-22's H_f (a sanity check);
* issue 29's stricter targets with the given strength, per building: sliding gm in [0.8, 1.25] and σ ln
  ≤ 0.45, met at DE on all five (0.98, σ 0.28 on 4 storeys; 0.92, σ 0.37 on 8; ``wall6`` 0.92, σ 0.38;
  ``wallf6`` 1.05, σ 0.24; ``rcf5`` 1.22, σ 0.43) and at MCE_R on all but ``wall6``'s σ (frames 1.03/0.23,
  1.06/0.32 and 1.13/0.36; ``wall6`` 0.93, σ 0.50; ``wallf6`` 1.07, σ 0.23); overturn verdicts ≥ 75 % of the
  cases where either overturns and risk class ≥ 80 % of the items, met at DE on the steel frames and the
  flexural wall (86 % of 7 cases, 92 %; 75 % of 12, 92 %; 100 % of 5, 100 %; ``wall6`` 80 % of 5 but 75 %,
  ``rcf5`` 67 % of 9 and 100 %), at MCE_R on the 4-storey frame (81 % of 16, 83 %), the concrete frame (81 % of
  16, 92 %) and the flexural wall (89 % of 9, 92 %). The unmet ones at DE are strict xfails with these numbers
  (before the frames' storeys took one yield drift ratio, ``rcf5``'s σ ln at DE was 0.48 and the steel frames'
  verdicts 57 % and 73 %). How finely those two can tell a model from the truth at all: the
  OpenSees building itself with every storey's strength 10 % low, no other difference, meets them no better
  (overturn verdicts pooled over the five buildings and both levels 67 % of the cases where either overturns,
  90 % interval 59-75 %, 33 % at worst; risk class 75 % at worst; the given strength: 67 % pooled, 59-75 %,
  47 % and 75 % at worst), 10 % high 82 % pooled and 50 % at worst (``benchmarks/bench_yielding_equipment.py --levels DE,MCE_R
  --truth-strengths 0.9,1.1``): which motion tips an item on the edge of overturning turns on a few per cent
  of strength, which no pushover fixes; the sliding's gm and σ ln resolve far finer (σ ln ≤ 0.27 there).
  Finer still, with no model at all between them: the OpenSees floor histories themselves times 0.995 or
  1.005, the items' input half a per cent off, agree on 0.83 and 0.87 of the pooled cases where either
  overturns and on **0.67 and 0.71 at worst** for one building and level, the risk class on 0.92 at worst,
  while σ ln ≤ 0.10 and the per-item overturn verdict agrees on ≥ 0.92 of the items (times 0.98 and 1.02:
  0.75 and 0.77 pooled, 0.58 and 0.56 at worst; ``--truth-floors 0.995,1.005,0.98,1.02``; checked here at DE,
  :func:`test_the_per_case_overturn_verdicts_cannot_tell_floors_half_a_per_cent_apart`). Every one of the
  110 cases where the given strength or its truth overturns is the loaded shelving rocking about its narrow
  side, and "minor variations in the input can result in overturning" (the paper's §1, after Yim et al.
  1980 and Makris & Roussos 2000). That is the block's physics, not a solver's: under the 47 OpenSees
  floor histories on which it ever overturns (the 4- and 8-storey frames and the concrete frame at DE, the
  4-storey frame at MCE_R) times 0.99, 0.995, 0.9975, 1, 1.0025, 1.005 and 1.01, the shelving's verdict
  changes within that 1 % on 19, on 13 out of order ("XX.XX.X"), and the tool's three solvers (the engine's
  own choice, the general Moreau-Jean solver and the event-driven one) give the same verdict in all but 4 of
  the 329 runs; MuJoCo's rigid box (peers.mujoco_box), on the first 10 of those 19, changes its verdict within
  that 1 % on 8, out of order on 5 (benchmarks/bench_overturn_sensitivity.py --mujoco 10;
  :func:`test_overturning_turns_on_a_quarter_of_a_per_cent_in_mujoco_as_in_the_tool`). A
  per-case share of 75 % per building and level is finer than any model of the floors can be held to. The
  overturning verdict the report gives, each item's class from ``p_overturn`` over the motions
  (``overturn_class_agree``), agrees on ≥ 0.92 of the items for every building and level with the given
  strength.

* the same targets with what an engineer with the building's model writes, its pushover strength and its
  own α in ``lateral_stiffness_ratio`` (the frames' 10, the shear-building wall the sheet's 30, the bending
  wall its 0.1; ``peers.yielding_equipment.own_alpha``): sliding gm in [0.8, 1.25] and σ ln ≤ 0.45 on all but
  ``rcf5`` at DE (DE: gm 1.01-1.16 and ``rcf5``'s 1.28, a strict xfail, σ ln 0.13-0.39; MCE_R: 1.03-1.25,
  0.10-0.38), risk class ≥ 80 % on all but ``wall6`` at DE (75 %, a strict xfail); the per-case overturn share
  stays at 0.60-0.89, as coarse as the truth's own floors half a per cent off
  (:func:`test_the_issue_targets_with_the_buildings_strength_and_alpha`); and with its storey stiffnesses as well
  in ``storey_stiffness`` (``peers.yielding_equipment.OWN_MODEL``; not the bending wall, which has no storeys of
  its own): gm 1.02-1.20 and σ ln 0.10-0.41 at DE (the frames ≤ 0.27), risk class ≥ 80 % but ``wall6``'s 75 %
  (:func:`test_the_issue_targets_with_the_buildings_own_model`). Over all 18 of the harness's records, where a
  motion moves p by 6 % and not 9 %, the risk class agrees at DE on 0.83-1.0 of the items with the strength
  alone, 0.83-1.0 with its α (``wall6`` 0.75) and 0.83-0.92 with its own model (``wall6`` 0.75)
  (:func:`test_the_risk_class_over_the_whole_suite`); the sliding with the own model gm 1.04-1.20, σ ln ≤ 0.44
  at DE and MCE_R, where the strength alone or with α leaves σ ln at 0.55-0.57 on ``smf8`` at MCE_R.
  α is what the strength alone leaves open: ``rcf5``'s σ ln 0.43 at DE with the system's 12 is 0.27 with its 10,
  ``wall6``'s 0.50 at MCE_R with 1 (a wall's) is 0.38 with a shear building's 30 (test_yielding_alpha.py
  rebuilds the frames with α 5 and 20).

``wall6``'s class misses come from what the truth is: a shear building whose storeys above the first all reach
their yield (their ductility 0.7-1.9 at DE, median 1.0, and 12.6 in storey 2 under Kobe; the first storey's
2.9-24), which caps its floors' acceleration, where the tool's wall, capacity-designed, stays elastic above its
base hinge (assess/building/nonlinear.py) as the bending wall ``wallf6`` does. On Landers and Düzce at DE, with
the building's own model, the tool's roof PFA is 1.92 and 2.02 g against ``wall6``'s 1.05 and 1.07 g (``wallf6``'s
own 2.27 and 1.54 g, the tool's 3.09 and 1.89 g with its strength), and three roof items slide past their room
under 2 to 6 of the 11 motions where the truth's do under 1 to 4; two of the three misses are one motion's verdict
(``class_missed_one_motion``). With the storeys yielding in the tool as well (its wall as a stick of storey
springs, tried, not kept) the class agrees on 0.50-0.92 of the items over the routes at DE, below 0.75 on four
of the six. With the storeys' own strengths given (``storey_strength``, with which the tool's wall is such a stick)
the targets are met at DE and MCE_R, σ ln 0.13 and 0.11 (test_yielding_storey_strength.py): what those sticks
lacked was not the mechanism but the truth's strengths, 1.8 times the design shear at the base to 3.0 at the top.

The tool's shear wall is its elastic model on a base plastic hinge (assess/building/wall_hinge.py; its
kernel checked against OpenSees with the same model in test_wall_hinge_opensees.py). Before it, the tool's
wall was an equivalent shear stick of storey springs, and slid ``wallf6``'s equipment 1.42/1.45 times as far
(σ ln 0.57/0.44) and ``wall6``'s 1.31/1.27 times; what follows is how that was found, with that stick.

The wall slid too much because of its stick, not its truth (measured with the strength given, DE/MCE_R):
the tool's equivalent-shear springs of a flexural wall (α 1) soften up the height to 6 % of the first
storey's at the top, where this truth's shear building keeps 42 %; with the truth's storey stiffnesses the
tool's wall gives gm 1.10/1.11, σ ln 0.15/0.14. Its capacity-designed upper storeys matter next (with the
code's shares instead, 1.00/1.02, but then its top storey yields to ductility 7-9 where the truth's stays
near 1 and the roof's PFA falls to 0.73-0.78 of the truth's); the truth's pinching and hardening
(1.28/1.16) and Rayleigh damping at modes 1 and 2 (1.29/1.27) barely move it. The truth is a shear building,
where a slender wall bends. Against the bending wall ``wallf6`` (same storeys, masses, T_1, pinching and yield
base shear) the tool's wall slides more, not less: gm 1.42/1.45 (σ ln 0.57/0.44), though the roof's and
mid-height's PFA are within 5-10 % of the truth's (tool/truth 1.03/0.93 at the roof, 0.96/1.09 at mid-height).
The hinge's stiffness, the modelling choice the sources leave open, barely moves it: n 5, 10, 20 give
1.44, 1.42, 1.44 at DE and 1.43, 1.45, 1.42 at MCE_R, and Rayleigh damping on the hinge as well 1.44 (n 10,
DE; benchmarks/bench_wall_flexural_truth.py). What moved the first exploration of that benchmark (0.99-1.33)
was the wall's hardening: it gave the hinge spring itself b 0.02, i.e. the wall b 0.08 (hinge 10 EI_el/H) to
0.41 (100 EI_el/H), reproduced here as 1.34 and 1.00. At the same peak the tool's floors stay above the items'
friction longer (time above 0.3 g 1.44 and 1.11 times the truth's at mid-height and roof, DE; ``--histories``):
its stick yields in its first storey's shear spring, which moves every floor above by the same amount, where
the wall's base hinge moves them in proportion to their height (a likely reason, not isolated). The literature
read does not say the tool's wall stick is wrong (its sources are on how to model a hinge, not on a stick's
storeys). With the base hinge (the tool's elastic wall, α 1, on a pinching hinge, the same n and damping
rule as ``wallf6``) ``wallf6``'s sliding falls to 1.05/1.07 (σ ln 0.24/0.23), its floors' PFA within 2-15 %
of the truth's (mid-height 1.02/1.09, roof 1.01/1.15), and ``wall6``'s, a shear building, to 0.92/0.93.

Skipped, with the reason, where openseespy or pyslammer is not importable.
"""
from __future__ import annotations

import numpy as np
import pytest

from assess.anchorage.equations import height_factor
from peers.opensees_buildings import BUILDINGS
from peers.opensees_shear import load_opensees
from peers.yielding_equipment import (OWN_MODEL, PUSHOVER_HARDENING, PUSHOVER_MODEL, PUSHOVER_ROUTE,
                                      TARGET_OVERTURN_AGREE, meets_class_target, meets_sliding_targets,
                                      own_stiffness)

OPS, WHY = load_opensees()
pytestmark = pytest.mark.skipif(OPS is None, reason=str(WHY))

OVERSTRENGTHS = (1.5, 2.0, 3.0)
#: The truth's own floor histories times these: no model error, the input half a per cent off.
FLOOR_SCALES = (0.995, 1.005)


@pytest.fixture(scope="module")
def measured(tmp_path_factory):
    pytest.importorskip("pyslammer")
    from peers.yielding_equipment import (assess, compare, given_pushover, given_pushover_hardening, given_routes,
                                          ground_suite, truth_result, workbook)

    out = {}
    for name, truth in BUILDINGS.items():
        suite = ground_suite(11, truth.period_s, 1.0)
        folder = tmp_path_factory.mktemp(name)
        reference = truth_result(truth, suite, "DE", folder)
        routes = {**given_routes(truth), "elastic": [["response", "elastic"]]}
        if name in FRAMES:
            routes[PUSHOVER_ROUTE] = given_pushover(truth)
            routes[PUSHOVER_HARDENING] = given_pushover_hardening(truth)
        routes["design"] = [["response", "yielding"]]
        routes.update({f"design x {o:g}": [["response", "yielding"], ["overstrength", o]] for o in OVERSTRENGTHS})
        results = {route: assess(workbook(folder, truth, suite, "DE", rows), "DE") for route, rows in routes.items()}
        results.update({f"truth floors x {f:g}": truth_result(truth, suite, "DE", folder, f) for f in FLOOR_SCALES})
        numbers = {route: compare(result, reference) for route, result in results.items()}
        out[name] = {"truth": truth, "numbers": numbers, "floors": results["given"][0].floors.set_index("floor")}
    return out


#: (route, building) where the claim below is not met, with the measured gm (DE): strict xfails (none since the
#: steel moment frames default to 2.5: with 2 the steel frames gave 0.62 and 0.65).
SHORT: dict = {}
#: The truth buildings the claims are checked on: every one of the peer's.
NAMES = tuple(BUILDINGS)
#: Those with storeys of their own, whose stiffnesses an engineer with the model writes (not the bending wall).
MODELLED = tuple(name for name in NAMES if own_stiffness(BUILDINGS[name]) is not None)
#: The frames, whose α their pushover's slope after yield gives (``pushover_slope_ratio``; not the walls).
FRAMES = tuple(name for name in NAMES if np.isfinite(getattr(BUILDINGS[name], "column_alpha", np.inf)))


def _marked(firsts, short, names=NAMES):
    """(first, building) pairs as parameters, those in ``short`` strict xfails that give its words."""
    for first in firsts:
        for name in names:
            marks = ()
            if (first, name) in short:
                marks = pytest.mark.xfail(strict=True, reason=f"{name}, {first}: {short[first, name]}")
            yield pytest.param(first, name, marks=marks, id=f"{first}-{name}")


@pytest.mark.parametrize("route, name", list(_marked(("given", "design"), SHORT)))
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


def test_the_per_case_overturn_verdicts_cannot_tell_floors_half_a_per_cent_apart(measured):
    # The truth against its own floor histories times 0.995 and 1.005 (module docstring): the per-case overturn
    # share falls below issue 29's 75 % on some building, where the sliding and the per-item verdicts hold.
    for factor in FLOOR_SCALES:
        numbers = {name: m["numbers"][f"truth floors x {factor:g}"] for name, m in measured.items()}
        assert min(n["overturn_agree"] for n in numbers.values()) < 0.75, (factor, numbers)
        for name, n in numbers.items():
            assert abs(np.log(n["gm"])) < 0.03 and n["sigma_ln"] <= 0.15, (factor, name, n)
            assert n["overturn_class_agree"] >= 0.9, (factor, name, n)


#: Amplitudes around one floor history (the 8-storey frame's roof under Coalinga at DE), the shelving on it.
AMPLITUDES = (0.99, 0.995, 0.9975, 1.0, 1.0025, 1.005, 1.01)


def test_overturning_turns_on_a_quarter_of_a_per_cent_in_mujoco_as_in_the_tool():
    # Why the per-case share is coarse (module docstring): under one OpenSees roof history times 0.99 to 1.01 the
    # shelving overturns at some amplitudes and not at others, out of order, in the tool's engine and in
    # MuJoCo's rigid box (peers.mujoco_box) alike. Measured: both ".XX..X." (X overturns).
    pytest.importorskip("pyslammer")
    mujoco = pytest.importorskip("mujoco")
    from assess.mechanics.block import Block
    from assess.mechanics.gateway import run_responses
    from peers.mujoco_box import box_model, overturns
    from peers.opensees_buildings import truth_response
    from peers.yielding_equipment import ground_suite, narrow_box

    shelving = narrow_box("SHELVING")
    truth = BUILDINGS["smf8"]
    (_, accel, dt), = [m for m in ground_suite(11, truth.period_s, 1.0) if m[0].startswith("Coalinga")]
    roof = truth_response(truth, accel, dt)[0][truth.storeys]
    block = Block(half_width_m=shelving["half_width_m"], cg_height_m=shelving["height_m"] / 2,
                  height_m=shelving["height_m"], mu=shelving["mu"])
    tool = [r.overturned for r in run_responses([(block, roof * a, dt) for a in AMPLITUDES])]
    model = box_model(mujoco, **shelving)
    peer = [overturns(mujoco, model, roof * a, dt, shelving["height_m"]) for a in AMPLITUDES]
    for verdicts in (tool, peer):
        assert any(verdicts) and not all(verdicts), verdicts
        assert verdicts not in (sorted(verdicts), sorted(verdicts, reverse=True)), verdicts  # not one threshold
    assert sum(t == p for t, p in zip(tool, peer)) >= 5, (tool, peer)


#: Issue 29's targets with the given strength not met at DE, with the measured numbers: strict xfails. Where the
#: overturn verdicts per case miss, the truth's own floors half a per cent off miss too (module docstring).
TARGETS_SHORT = {("verdicts", "wall6"): "overturn verdicts 80 % of 5 cases where either overturns; risk class 75 %",
                 ("verdicts", "rcf5"): "overturn verdicts 67 % of 9 cases; risk class 100 %"}


@pytest.mark.parametrize("target, name", list(_marked(("sliding", "verdicts"), TARGETS_SHORT)))
def test_the_issue_targets_with_the_given_strength(measured, target, name):
    n = measured[name]["numbers"]["given"]
    if target == "sliding":
        assert meets_sliding_targets(n), (name, n)
    else:
        assert n["overturn_agree"] >= TARGET_OVERTURN_AGREE and meets_class_target(n), (name, n)


#: The risk class with the building's strength and α not met at DE, with the measured numbers: strict xfails.
OWN_ALPHA_SHORT = {("class", "wall6"): "risk class 75 % (9 of 12 items), as with the strength alone",
                   ("sliding", "rcf5"): "gm 1.28, σ ln 0.27: the design's stiffness profile (its top storey 0.35 of "
                                        "the first, the truth's 0.55) at one yield drift; with the building's own "
                                        "stiffnesses 1.20, σ ln 0.18"}


@pytest.mark.parametrize("target, name", list(_marked(("sliding", "class"), OWN_ALPHA_SHORT)))
def test_the_issue_targets_with_the_buildings_strength_and_alpha(measured, target, name):
    # What an engineer with the building's model writes: its pushover yield_base_shear_g and its own α in
    # lateral_stiffness_ratio (peers.yielding_equipment.own_alpha: the frames' 10, the shear-building wall the
    # sheet's 30, the bending wall its 0.1). Measured at DE: gm 1.01-1.28 (rcf5's 1.28 the xfail), σ ln 0.13-0.39,
    # risk class 0.83-0.92 but for wall6's 0.75; at MCE_R (bench_yielding_equipment.py --own-alpha) gm 1.03-1.25,
    # σ ln 0.10-0.38, class 0.67-1.0. The per-case overturn share stays coarse (0.60-0.89), as the truth's own
    # floors show it must.
    n = measured[name]["numbers"]["given + own α"]
    assert (meets_sliding_targets if target == "sliding" else meets_class_target)(n), (name, n)


#: The targets with the building's own model not met at DE, with the measured numbers: strict xfails.
OWN_MODEL_SHORT = {("class", "wall6"): "risk class 75 % (9 of 12 items), as on the other routes: a shear building's "
                                        "truth against the tool's wall on its base hinge (module text)"}


@pytest.mark.parametrize("target, name", list(_marked(("sliding", "class"), OWN_MODEL_SHORT, MODELLED)))
def test_the_issue_targets_with_the_buildings_own_model(measured, target, name):
    # What an engineer with the building's model writes (peers.yielding_equipment.OWN_MODEL): its pushover
    # yield_base_shear_g, its own α and its storey stiffnesses in storey_stiffness. The tool's storeys are then as
    # strong as they are stiff at one yield drift ratio (assess.building.nonlinear.stiffness_strength) on the
    # building's own stiffnesses. Measured at DE (11 records): gm 1.02-1.20, σ ln 0.10-0.41 (the frames ≤ 0.27),
    # risk class 0.83-1.0 but for wall6's 0.75; at MCE_R gm 1.08-1.14, σ ln 0.11-0.42, class 0.83-1.0; over all
    # 18 records at DE and MCE_R gm 1.04-1.20, σ ln 0.15-0.44 (the frames ≤ 0.29), class 0.83-1.0 but for wall6's
    # 0.75 at DE (bench_yielding_equipment.py --motions 18 --own-alpha).
    n = measured[name]["numbers"][OWN_MODEL]
    assert (meets_sliding_targets if target == "sliding" else meets_class_target)(n), (name, n)


@pytest.mark.parametrize("target, name", list(_marked(("sliding", "class"), {}, FRAMES)))
def test_the_issue_targets_with_the_strength_and_the_pushover_s_slope(measured, target, name):
    # What an engineer with the building's pushover writes: its yield_base_shear_g and its slope at 2 % roof drift
    # over its initial slope (peers.yielding_equipment.given_pushover), from which the tool finds α (12.5, 12.1 and
    # 12.3 for the frames' 10: its springs harden at 3 %, theirs at 2 %). Measured at DE: gm 0.91-1.20, σ ln
    # 0.28-0.44, class 0.92-1.0; at MCE_R (bench_yielding_equipment.py --pushover-slope) gm 1.02-1.10, σ ln
    # 0.24-0.38, class 0.83-1.0.
    n = measured[name]["numbers"][PUSHOVER_ROUTE]
    assert (meets_sliding_targets if target == "sliding" else meets_class_target)(n), (name, n)


@pytest.mark.parametrize("target, name", list(_marked(("sliding", "class"), {
    ("sliding", "rcf5"): "gm 1.26 at DE: with its springs' 2 % written the α found is the frame's own (10.4), at "
                         "which the tool slides this concrete frame's items 1.28 times as far (the route with its own "
                         "α, above)"}, FRAMES)))
def test_the_issue_targets_with_the_pushover_s_slope_and_the_model_s_hardening(measured, target, name):
    # The same and the storeys' hardening of the building's model (its springs' 2 %) in storey_hardening_ratio
    # (peers.yielding_equipment.PUSHOVER_HARDENING): the α found is then the frame's own 10 within 5 % (10.5, 10.3,
    # 10.4 with the design's storey stiffnesses; 10.0 with its own, test_truth_pushover.py). Measured at DE: gm
    # 1.01-1.26, σ ln 0.27-0.39, class 0.83-1.0; at MCE_R (bench_yielding_equipment.py --pushover-slope
    # --own-hardening) gm 1.07-1.20, σ ln 0.20-0.33, class 0.83-0.92.
    n = measured[name]["numbers"][PUSHOVER_HARDENING]
    assert (meets_sliding_targets if target == "sliding" else meets_class_target)(n), (name, n)


@pytest.fixture(scope="module")
def whole_suite(tmp_path_factory):
    """The given routes at DE over every record of the harness (peers.yielding_equipment.RECORDS, 18), where
    ``measured`` takes the first 11: a risk class from p over 11 motions moves by 1/11 = 9 % a motion, as
    wide as a class's band."""
    pytest.importorskip("pyslammer")
    from peers.yielding_equipment import RECORDS, compared, given_pushover_model, given_routes, ground_suite

    def routes(name, truth):
        return {**given_routes(truth), **({PUSHOVER_MODEL: given_pushover_model(truth)} if name in FRAMES else {})}

    return {name: compared(truth, ground_suite(len(RECORDS), truth.period_s, 1.0), "DE",
                           tmp_path_factory.mktemp(f"{name}-whole"), routes(name, truth))
            for name, truth in BUILDINGS.items()}


#: Over all 18 records, at DE: strict xfails with the measured numbers.
WHOLE_SUITE_SHORT = {("given + own α", "wall6"): "risk class 75 % (9 of 12 items) over the 18 records "
                                                 "(0.75 over the first 11)",
                     ("given + own α", "rcf5"): "gm 1.27 (σ ln 0.29) over the 18 records; 1.20 (σ ln 0.20) with "
                                                "the building's own stiffnesses",
                     (OWN_MODEL, "wall6"): "risk class 75 % (9 of 12 items) over the 18 records"}


@pytest.mark.parametrize("route, name", [*_marked(("given", "given + own α"), WHOLE_SUITE_SHORT),
                                         *_marked((OWN_MODEL,), WHOLE_SUITE_SHORT, MODELLED)])
def test_the_risk_class_over_the_whole_suite(whole_suite, route, name):
    # Over all 18 records (bench_yielding_equipment.py --motions 18 --own-alpha), at DE: the class 0.83-1.0 with the
    # strength alone, 0.75 (wall6, the xfail) to 1.0 with its α, 0.75 (wall6) to 0.92 with the building's own
    # model; the sliding targets with the α at DE (σ ln ≤ 0.42) but for rcf5's gm 1.27, with the own model on all
    # four (gm 1.04-1.19, σ ln ≤ 0.44). At MCE_R the α alone leaves smf8's σ ln at 0.55 (90 % interval over the
    # motions 0.29-0.79), carried by one record (Kocaeli, whose mid-height floor the tool had 22 % low); with the
    # building's own storey stiffnesses too, each storey as strong as it is stiff at one yield drift ratio, 0.25
    # (0.19-0.29).
    n = whole_suite[name][route]
    assert meets_class_target(n), (name, route, n)
    if route != "given":
        assert meets_sliding_targets(n), (name, route, n)


@pytest.mark.parametrize("name", FRAMES)
def test_the_sliding_and_class_targets_over_the_whole_suite_with_the_whole_model_but_alpha(whole_suite, name):
    # The frames' pushover strength and slope, their springs' hardening and their storey stiffnesses, α found from
    # them (peers.yielding_equipment.PUSHOVER_MODEL). Measured over all 18 records at DE: gm 1.03-1.18, σ ln
    # 0.16-0.29, class 0.92; at DE and MCE_R on the four frames and the same rebuilt at α 5 and 20
    # (bench_yielding_equipment.py --motions 18 --truth-alphas 5,20 --pushover-slope --own-hardening --truth-profile)
    # gm 0.85-1.19, σ ln ≤ 0.41 on all 24, class ≥ 0.83 on 23 (0.75 on smf8 at α 20, MCE_R), the per-case overturn
    # share 0.79 pooled (0.56-1.0 per pair, as coarse as the module text says).
    n = whole_suite[name][PUSHOVER_MODEL]
    assert meets_sliding_targets(n), (name, n)
    assert meets_class_target(n), (name, n)
