"""Equipment demand on the floors of yielding buildings: the tool's yielding route against OpenSees buildings.

Run: python benchmarks/bench_yielding_equipment.py [--levels DE,MCE_R] [--buildings smf4,smf8,wall6,wallf6,rcf5]
     [--motions 11] [--overstrengths 1.5,2,3] [--truth-profile] [--truth-strengths 0.9,1.1]
     [--truth-floors 0.995,1.005] [--truth-alphas 5,20] [--own-alpha] [--alpha-bracket] [--pushover-slope]
     [--own-hardening] [--brace-buckling] [--strength-factor F] [--own-strength] [--skip RECORD,...]
     (needs openseespy and pyslammer; about 3 minutes a level)

The truth: five yielding OpenSeesPy buildings of our own (tests/peers/opensees_buildings.py: steel
special moment frames of 4 and 8 storeys and a reinforced-concrete one of 5 with pinching springs (``rcf5``),
with a continuous elastic column, a pinching concrete shear wall
of 6 storeys idealised as a shear building (``wall6``); ASCE 7-22 ELF designs, tapering storey stiffness,
design strengths with an overstrength growing up the height; and the same wall as it bends (``wallf6``: an
elastic cantilever on a pinching base hinge, n = 10 of Ibarra & Krawinkler's stiffness modification, no
stiffness-proportional damping on the hinge); the sources are in that module; ``--buildings bf6`` takes the sixth
system, a 6-storey steel braced frame checked on its own, and ``--buildings smf12`` a 12-storey steel moment
frame, T_1 2.0 s, also on its own: tests/verification/test_yielding_tall.py gives what it measured), under real
records (pyslammer's sample records, the first ``--motions`` of ``peers.yielding_equipment.RECORDS`` but those
``--skip`` names, each a
30 s window from 1 s before 5 % of its Arias intensity) scaled so that their 5 %-damped S_a(T_1) is
the design spectrum's (S_DS 1.0 g, S_D1 0.6 g) at DE, 1.5 times it at MCE_R. Six items (the paper's three prototypes, a
loaded server rack, loaded shelving, a chest freezer) on the mid-height floor and on the roof.

Every route runs the product itself (``run_assessment`` on a workbook whose hazard sheet gives the
scaled ground records at floor 0, with a ``site`` sheet of the same design values, Risk Category II, and
a ``building`` sheet of the building's storeys, height, system and T_1): only the floor histories differ.

* ``truth``: the OpenSees floor histories (the yielding route's stick swapped for OpenSees);
* ``given``: ``response: yielding`` with ``yield_base_shear_g`` from a static pushover of the OpenSees
  building under the ELF pattern: the base shear, column included, when its first storey yields, over the
  weight (``peers.opensees_buildings.pushover_yield_base_shear_g``);
* ``design``: ``response: yielding`` from the design data only (ASCE 7-22 §12.8), the system's default
  overstrength (2.5 for the steel frames, 2 for the others);
* ``design + own hardening`` (``--own-hardening``): the same with the OpenSees springs' hardening in
  ``storey_hardening_ratio``, to which the steel frames' assumed overstrength is taken (2.5 at 3 % is 2.63 at
  their 2 %: the same pushover peak). Measured over 11 records at DE and MCE_R on the six buildings
  (``--buildings smf4,smf8,rcf5,bf6,wall6,wallf6 --levels DE,MCE_R --own-hardening --overstrengths ""``, 404 s):
  sliding gm on the steel frames 1.01, 1.05, 1.10, 1.17 by design alone and 1.07, 1.08, 1.24, 1.20 with their
  hardening (smf4 DE, MCE_R, smf8 DE, MCE_R); over all six 0.92-1.24, σ ln ≤ 0.49 (``rcf5`` DE), risk class
  0.67-0.92 (``bf6`` MCE_R 0.67 both ways), the per-case overturn share pooled 0.68 (0.64 by design alone);
* ``given + brace buckling`` and ``design + brace buckling`` (``--brace-buckling``, braced frames only): ``given``
  and ``design`` with the building sheet's ``brace_buckling`` yes, the tool's storeys of buckling braces. Measured
  (``--buildings bf6b,bf6 --levels DE,MCE_R --overstrengths "" --brace-buckling``, 172 s, then with
  ``--strength-factor 0.6``, every truth storey 0.6 times as strong), sliding gm given / with brace buckling, DE and
  MCE_R: on ``bf6b`` (its braces buckle) 1.16 / 1.21 and 1.01 / 1.07, class 0.92 / 0.92 and 0.92 / 0.83; on ``bf6``
  (they do not) 1.23 / 1.29 and 1.06 / 1.13; 0.6 times as strong, ``bf6b`` 0.94 / 1.03 and 0.78 / 0.91 (class 0.75 /
  0.83 at MCE_R), ``bf6`` 0.98 / 1.07 and 0.85 / 1.00: the law raises a weaker frame's answer by about a sixth at
  MCE_R whether the truth's braces buckle or not;
* ``design x Ω``: the same with ``overstrength`` Ω;
* ``elastic``: ``response: elastic``, today's modal route;
* ``given + truth's stiffness`` (``--truth-profile``): ``given`` with the OpenSees building's storey
  stiffnesses in ``storey_stiffness`` (what an engineer who knows the building would write); the
  other routes but ``given + own α + own stiffness`` (below) take the system's design profile;
* ``truth, strength x f`` (``--truth-strengths``, e.g. ``0.95,1.05``): the OpenSees building itself with every
  storey's (or the hinge's) strength times f, against the truth. No model error at all, only a strength a few
  per cent off, as no pushover knows it better: how finely each column can tell a model from the truth
  (the resolution of the targets, not a route a user has). Measured with 11 motions at DE and MCE_R on the
  four buildings (``--overstrengths 2 --truth-strengths 0.95,1.05``, then ``0.9,1.1``): a strength 5 % off
  agrees on 0.78 and 0.81 of the cases where either overturns (pooled; 0.57 at worst for one building and
  level), on the risk class of 0.83 of the items at worst, σ ln ≤ 0.16; 10 % off, on 0.69 (90 % interval
  0.60-0.77) and 0.80 of those cases (0.46 at worst), the risk class on 0.75 at worst, σ ln ≤ 0.27, sliding
  gm 0.77-0.93 and 1.10-1.17 (with ``rcf5`` as well, 10 % off: 0.67 and 0.82 pooled). The per-case overturn
  share and the risk class per building and level are as coarse as that: a perfect model of a building whose
  strength is known within 10 % scores no better on
  them than ``given`` does (0.67 pooled, 0.75 at worst); σ ln and gm resolve far finer.
* ``truth, floors x f`` (``--truth-floors``, e.g. ``0.995,1.005``): the OpenSees floor histories themselves times f,
  against the truth: no building model at all, only the items' input f off. With 11 motions at DE and MCE_R on the
  five buildings: times 0.995 and 1.005 the overturn verdicts agree on 0.83 and 0.87 of the cases where either
  overturns (pooled), 0.67 and 0.71 at worst for one building and level, the risk class on 0.92 at worst, σ ln
  ≤ 0.10; times 0.98 and 1.02 on 0.75 and 0.77 (0.58 and 0.56 at worst; risk class 0.92 and 0.83), σ ln ≤ 0.07.
  The cases where either overturns are all the loaded shelving rocking about its narrow side, whose overturning
  turns on minor variations of its input (the paper's §1): the per-case share per building and level cannot
  tell floors half a per cent apart. With these routes every other route also gets the per-case share on the
  cases whose verdict the truth holds under every f given (``overturn_agree_held``, ``n_overturn_held``; pooled
  in a table of its own): those a model of the floors can be held to. With 15 motions at DE and MCE_R on the five
  buildings and ``--truth-floors 0.99,0.995,1.005,1.01`` (``--overstrengths "" --own-alpha``, 584 s): held on
  about three quarters of the cases where either overturns; there the strength given agrees on 0.82 (90 %
  interval 0.75-0.87) pooled, 0.63-1.0 per building and level (``wall6`` at MCE_R 0.63, ``smf8`` at DE 0.73),
  with the building's α on 0.86 (0.80-0.90), the design data on 0.76 (0.69-0.82), the elastic modes on 0.66
  (0.59-0.72); over all the cases where either overturns 0.72, 0.73, 0.68 and 0.59.
* ``given + own α`` (``--own-alpha``): ``given`` with the building's own α in ``lateral_stiffness_ratio``
  (``peers.yielding_equipment.own_alpha``: the frames' column's 10, the shear-building wall the sheet's 30, the
  bending wall its 0.1); and ``given + own α + own stiffness``, with the building's storey stiffnesses as well in
  ``storey_stiffness`` (``peers.yielding_equipment.OWN_MODEL``; the four shear buildings, not the bending wall):
  what an engineer with the building's model writes. Measured with the frames' storeys at one yield drift ratio
  (``assess.building.nonlinear.stiffness_strength``, 2026-11-29) over all 18 of pyslammer's records
  (``--levels DE,MCE_R --motions 18 --overstrengths "" --own-alpha --truth-profile``, 501 s; the last three
  records Kocaeli, Mammoth Lakes-2 and Nisqually): with the strength alone gm 0.85-1.25, σ ln up to 0.57
  (``smf8`` at MCE_R, 90 % interval 0.32-0.79), risk class 0.83-1.0, the per-case overturn share 0.71 pooled
  (0.66-0.76); with the building's α too gm 1.04-1.27, σ ln up to 0.54 (the same), class 0.75-1.0, 0.69
  (0.64-0.75); with its own model gm 1.04-1.20, σ ln 0.15-0.44 (the frames 0.15-0.29, ``smf8`` at MCE_R 0.25,
  0.19-0.29; ``wall6`` 0.42-0.44; the bending wall with its α 0.15), class 0.83-1.0 but ``wall6`` at DE (0.75),
  0.70 (0.64-0.76); the design data gm 0.98-1.24, σ ln up to 0.58; the elastic modes gm 1.51-4.16, 0.57. Over
  the first 11 records: given 0.92-1.22, σ ln ≤ 0.50, class 0.75-1.0, per case 0.75 (0.67-0.82); own α
  1.01-1.28; own model 1.01-1.20, σ ln ≤ 0.42. Before (the frames' storeys at the first storey's yield
  drift), over the 18: the strength alone gm 0.85-1.10, σ ln up to 0.56, with α 0.97-1.16, 0.55, where
  ``smf8``'s σ ln at MCE_R was one record's (under Kocaeli the tool's mid-height PFA 22 % below the truth's, ten
  cases carrying 55 % of the variance), and the own model left it at 0.48;
* ``given, truth α a`` and ``given + α, truth α a`` (``--truth-alphas``, e.g. ``5,20``; the frames only): the frame
  rebuilt with its continuous column at α = a in place of its own 10 (stiffer columns at 5, softer at 20, both
  within Miranda & Taghavi's 5-20 for moment frames), its own pushover base shear given, against the tool with
  the system's α (12) and with ``lateral_stiffness_ratio`` a. Measured on the three frames at DE
  (``--levels DE --buildings smf4,smf8,rcf5 --overstrengths "" --truth-alphas 5,20``, the frames' storeys at one
  yield drift ratio): sliding gm 0.44-1.78 with the system's α (outside [0.8, 1.25] on 2 of the 6), 0.96-1.18
  with the building's; σ ln 0.13-0.30 with the building's except at α 20 on ``rcf5`` (0.54) and ``smf8`` (0.64);
  risk class ≥ 0.83 on 4 of the 6 with the building's α (0.75 on two), down to 0.25 with the system's.
  Before, at the first storey's yield drift, at DE and MCE_R: 0.39-1.72 and 0.87-1.16.

* ``given + own α + own stiffness + own strength + own hardening`` (``--own-strength``): the building's whole model,
  its storeys' strengths in ``storey_strength`` (``peers.yielding_equipment.whole_model``), and with
  ``--truth-alphas`` the same at each α (``given + α + own model + own strength, truth α a``). Measured on the five
  buildings and the four frames rebuilt with α 5 and 20 at DE and MCE_R (``--buildings smf4,smf8,rcf5,bf6,wall6,wallf6
  --levels DE,MCE_R --truth-alphas 5,20 --own-alpha --own-strength --truth-profile --overstrengths ""``, 868 s), 26
  pairs: gm 1.00-1.16, σ ln ≤ 0.20 (``bf6`` at DE, where the Rayleigh damping's modes, the tool's 1 and 3 against
  the truth's 1 and 2, are what is left: 0.04 with 1 and 2), risk class 0.83-1.0, the sliding and class targets met
  on all 26; without the strengths (α and stiffnesses given) σ ln up to 0.47 (the α-20 frames) and 0.42 (``wall6``),
  class down to 0.75. The per-case overturn share pooled 0.82 (0.75-0.87), 0.50 at worst (``rcf5`` α 5 at DE): at
  the resolution floor the ``--truth-floors`` routes measure;
* ``given + own strength`` (``--own-strength`` too; with ``--truth-alphas`` at each α): ``given`` and the storeys'
  strengths in ``storey_strength`` (``peers.yielding_equipment.given_strengths``), the system's α and stiffness
  profile: the strength given whole, nothing of the stiffness. Measured (the same command without
  ``--own-alpha --truth-profile``, 994 s; 2026-11-30): sliding within the targets on 15, risk class on 13 of the
  26 pairs where the whole model meets both on all 26; on the buildings as they are 9 and 8 of 10 (``wall6`` at DE
  class 0.67, ``bf6`` at DE 0.75), no better than ``given`` there, and worse on the rebuilt frames (``smf8`` α 5 at
  DE: gm 0.59, class 0.25). A storey's strength and stiffness come from the same members: given apart, the
  strengths put the yielding where the truth's does not (the building note cautions it). On ``smf12`` (``--buildings
  smf12 --levels DE,MCE_R --skip Duzce_1999_375-090 --own-alpha --own-strength``, 146 s) gm 0.79 / 0.85, where the
  whole model gives 1.13 / 1.11, σ ln 0.14 / 0.14, class 0.92 / 1.0;
* ``--alpha-bracket``: ``given`` (and ``given, truth α a``) run with ``--alpha-range`` at the system's ends
  (5 and 20 for the frames, 0.1 and 2 for the walls; its own answer is the same), and whether each item's truth
  lies within what the tool gives at the ends and at the system's α (``bracket_*``; ``class_missed_flagged``: of
  the items whose class the system's α gets wrong, the share whose class moves between the ends, so that the
  report flags them). Measured over 11 records at DE and MCE_R on the five buildings
  (``--levels DE,MCE_R --motions 11 --overstrengths "" --alpha-bracket``, 303 s): the strength alone missed the
  class of 9 of 120 items, 6 of them flagged (the 3 not: one on ``smf4`` at MCE_R, two on ``wall6`` at DE, a shear
  building outside the walls' range of α); the truth's class within the three on 117 of 120. On the frames
  rebuilt with α 5 and 20 (``--levels DE --buildings smf4,smf8,rcf5 --truth-alphas 5,20``): 23 of 26 misses
  flagged, the truth's class within the three on 66 of 72. On ``smf12`` over 17 records at DE and MCE_R (``--skip
  Duzce_1999_375-090``, 177 s): 8 of 8 misses flagged (class 0.50 / 0.83 at the system's α), within on 24 of 24.
* ``given + pushover slope`` (``--pushover-slope``; the frames): ``given`` and the same pushover's slope at 2 % roof
  drift over its initial slope in ``pushover_slope_ratio`` (``peers.yielding_equipment.given_pushover``), from
  which the tool finds α; with ``--own-hardening`` the same and ``given`` again with the OpenSees springs' 2 % in
  ``storey_hardening_ratio`` (``peers.yielding_equipment.own_hardening``), and with ``--truth-profile`` the slope,
  the hardening and the truth's storey stiffnesses (the whole model but α). Measured on the four frames and the
  same rebuilt at α 5 and 20, at DE and MCE_R over 11 records (``--buildings smf4,smf8,rcf5,bf6 --levels
  DE,MCE_R --truth-alphas 5,20 --pushover-slope --own-hardening --truth-profile --overstrengths ""``, 1075 s), 24
  frame-and-earthquake pairs, sliding within [0.8, 1.25] with σ ln ≤ 0.45 / risk class ≥ 0.8: the strength alone
  14 / 14 (gm 0.44-1.86); with the slope 21 / 22 (0.74-1.20: α 30, the search's end, for every α-20 frame, whose
  slope is below what the stick's 3 % hardening gives); with the slope and the hardening 19 / 23 (0.92-1.26: α
  found within 1-9 %; σ ln 0.47-0.65 on three α-20 pairs, as with their α given); with the stiffnesses as well
  23 / 21 (0.88-1.22), as with α and stiffnesses given (14 / 15 of 16). On ``smf12`` (DE and MCE_R over the 11
  records but Düzce): 1 / 1, 2 / 1 and 2 / 2. The per-case overturn share pooled: 0.69, 0.74, 0.74, 0.79. Over
  all 18 records (``--motions 18``, 2207 s beside other work): 12 / 17, 19 / 22, 20 / 23 and 24 / 23 (gm
  0.85-1.19, σ ln ≤ 0.41; with α and stiffnesses given 16 / 15 of 16), the overturn share 0.68, 0.76, 0.75, 0.79.
  Of the items whose class is missed, how many one motion's verdict would mend (``class_missed_one_motion``; the
  same run over 11 records with ``wall6,wallf6`` added, 1,057 s): on the 24 frame pairs, the strength alone 41 of
  64, with the slope 23 of 26, with the slope and the hardening 22 of 27, with the stiffnesses as well 19 of 24
  (``smf4`` MCE_R 3 of 3, ``smf8`` α 5 DE 1 of 3: two roof items 4 of 11 past their room where the truth's are 6,
  the same with α and stiffnesses given; ``smf8`` α 20 MCE_R 3 of 3); the elastic route, on the four frames as
  they are, 4 of 42. A model of the yielding building misses a class where one motion's verdict decides it; the
  elastic one misses by classes. ``wall6`` at DE: 3 misses, 2 of them one motion (given), on every route.

Columns, each route against the truth over the (item, motion, direction) cases: PFA tool/truth at the
mid-height floor and the roof (median over the motions), sliding: geometric mean and σ of
ln(tool/truth) over the cases where the truth slides 1 cm or more and neither overturns (tool floored at
0.1 cm), each with its 90 % interval over the motions (``gm_low``..``sigma_ln_high``: the motions resampled,
``peers.yielding_equipment.motion_bootstrap``); overturn verdicts, two ways: per case, the share of the (item,
motion, direction) cases where
either overturns on which both agree (``overturn_agree``; and over all cases, ``overturn_agree_all``), and
per item, the share of the items whose overturning verdict is the same (``overturn_class_agree``: low,
moderate or high from ``p_overturn`` and the default ``risk_overturn_moderate``/``risk_overturn_high``, the
part of ``risk`` that overturning decides: the verdict a user reads, each item counted once, where the
per-case share rests on the 5-20 cases where either overturns, many on the edge of overturning);
risk class: the share of items whose class is the same (``class_agree``), the items whose class differs
(``n_class_missed``) and of those, how many one motion's verdict on one failure mode, moved, would mend
(``class_missed_one_motion``, ``peers.yielding_equipment.one_motion_away``: a class miss at the resolution of a
suite of that many motions, where the truth's own class moves as far for one motion). Then, per route over the
buildings and levels, where the overturn verdicts part (the tool alone overturns, on the safe side, or the truth
alone) and the pooled
agreement with its 90 % Clopper-Pearson interval. Then, per route and level, the targets pooled over the
buildings, as issue 29's own table pools its two frames per level: gm and σ ln of every case together, the per-case
overturn share, the risk class over all the items, and how many pairs meet the sliding and the class targets on
their own. Measured (the ``--own-strength`` run above): the strength alone (``given``) on the six buildings as they
are, DE / MCE_R, gm 1.05 / 1.04, σ ln 0.37 / 0.33, overturn 0.76 (0.64-0.86) / 0.73 (0.64-0.80), class 0.89 /
0.92, where per pair it misses on 3 of 12; the whole model on its five, 1.07 / 1.05, 0.14 / 0.11, 0.78 / 0.84, 0.95
/ 0.98; the elastic modes 1.91 / 2.12, 0.56 / 0.63, 0.57 / 0.62, 0.57 / 0.60 (the issue's two frames: 2.88 / 3.86,
0.85 / 1.13, 64 % / 81 %, 54 % / 71 %). Then each floor's PFA/PGA (median over
the motions) beside ASCE 7-22 §13.3.1's H_f/R_μ (R_μ = max(√(1.1 R/(I_e Ω_0)), 1.3), eq. 13.3-6): a
sanity check, not a target; with the largest storey ductility over the storeys and the motions, and the
top storey's (median and largest over the motions). Nothing is fitted here.
"""
from __future__ import annotations

import argparse
import dataclasses
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import pandas as pd

REPO = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(REPO / "tests")]

from assess.anchorage.equations import height_factor  # noqa: E402
from assess.building import ALPHA_RANGE_BY_SYSTEM  # noqa: E402
from assess.fragility.suite import binomial_interval  # noqa: E402
from peers.opensees_buildings import BRACED, BUCKLING, BUILDINGS, TALL  # noqa: E402

#: Every truth building by name: the five, and those checked on their own.
TRUTHS = {**BUILDINGS, **BRACED, **BUCKLING, **TALL}
from peers.yielding_equipment import (GIVEN_STRENGTHS, LEVELS, OWN_HARDENING, PUSHOVER_ROUTE, SYSTEM_R,  # noqa: E402
                                      WHOLE_MODEL, assess, bracket_held, compare, given_pushover,
                                      given_pushover_model, given_routes, given_strength, given_strengths,
                                      ground_suite, meets_class_target, meets_sliding_targets, own_hardening,
                                      own_stiffness, stronger, truth_result, whole_model, workbook)


def markdown(frame: pd.DataFrame) -> str:
    """A DataFrame as a Markdown table (numbers to 3 decimals)."""
    def cell(value):
        return f"{value:.3f}" if isinstance(value, float) else str(value)
    lines = ["| " + " | ".join(frame.columns) + " |", "|" + "---|" * len(frame.columns)]
    lines += ["| " + " | ".join(cell(v) for v in row) + " |" for row in frame.itertuples(index=False)]
    return "\n".join(lines)


def pooled_overturn(group: pd.DataFrame) -> tuple:
    """(cases where both agree, their share, its 90 % Clopper-Pearson interval) over the cases of ``group``'s rows
    where either overturns (:func:`assess.fragility.suite.binomial_interval`); NaN where none does."""
    either = int(group["n_overturn"].sum())
    both = either - int(group["overturn_tool_only"].sum() + group["overturn_truth_only"].sum())
    if not either:
        return both, float("nan"), float("nan"), float("nan")
    share = both / either
    return (both, share, *binomial_interval(share, either, 0.90))


def overturn_misses(table: pd.DataFrame) -> str:
    """Where the overturn verdicts part, pooled per route over the buildings and levels: the cases where the tool
    alone overturns (on the safe side) and where the truth alone does, and the share of agreement where either
    overturns with its 90 % Clopper-Pearson interval
    (:func:`assess.fragility.suite.binomial_interval`; the per-case share rests on few cases)."""
    lines = ["| route | both | tool only | truth only | agreement (90 % interval) |", "|---|---|---|---|---|"]
    for route, group in table.groupby("route", sort=False):
        both, share, low, high = pooled_overturn(group)
        lines.append(f"| {route} | {both} | {int(group['overturn_tool_only'].sum())} | "
                     f"{int(group['overturn_truth_only'].sum())} | {share:.2f} ({low:.2f}-{high:.2f}) |")
    return "\n".join(lines)


def pooled_targets(table: pd.DataFrame) -> str:
    """Per route and level, issue 29's targets pooled over the buildings, as the issue's own table pools its two
    frames per level: the sliding gm and σ ln of every case's ln(tool/truth) together (each pair's mean and σ
    combined, the spread between the pairs' means included), the share of all the cases where either overturns on
    which both agree (its 90 % Clopper-Pearson interval), the share of all the items whose risk class agrees; and
    how many of the pairs meet the sliding and the class targets on their own."""
    lines = ["| route | level | pairs | gm | σ ln | overturn agree (90 %) | class | pairs meeting the sliding "
             "targets | pairs meeting the class target |", "|---|---|---|---|---|---|---|---|---|"]
    for (route, level), group in table.dropna(subset=["sigma_ln"]).groupby(["route", "level"], sort=False):
        n, mean_ln = group["n_sliding"], np.log(group["gm"])
        grand = (n * mean_ln).sum() / n.sum()
        variance = (((n - 1) * group["sigma_ln"] ** 2).sum() + (n * (mean_ln - grand) ** 2).sum()) / (n.sum() - 1)
        _, agree_overturn, low, high = pooled_overturn(group)
        agree = (group["class_agree"] * group["n_items"]).sum() / group["n_items"].sum()
        rows = group.to_dict("records")
        lines.append(f"| {route} | {level} | {len(group)} | {np.exp(grand):.2f} | {np.sqrt(variance):.2f} | "
                     f"{agree_overturn:.2f} ({low:.2f}-{high:.2f}) | {agree:.2f} | "
                     f"{sum(map(meets_sliding_targets, rows))} | {sum(map(meets_class_target, rows))} |")
    return "\n".join(lines)


def verdict_held(reference, perturbed) -> pd.Series:
    """The (item, motion, direction) cases whose overturning verdict the truth holds under each of ``perturbed``
    (the truth's own floor histories times f, ``--truth-floors``): True where every one gives the truth's verdict.
    A case outside is on the edge of overturning, where the input a per cent off decides (the paper's §1)."""
    base = reference[1]["sim_overturned"].astype(bool)
    held = pd.Series(True, index=base.index)
    for result in perturbed:
        held &= result[1]["sim_overturned"].astype(bool).reindex(base.index) == base
    return held


def held_agreement(tool, reference, held: pd.Series) -> dict:
    """The per-case overturn agreement on the cases whose verdict the truth holds (:func:`verdict_held`) where
    either overturns: ``overturn_agree_held`` and its count ``n_overturn_held``."""
    t, r = (result[1]["sim_overturned"].astype(bool) for result in (tool, reference))
    t, r = t.align(r, join="inner")
    either = (t | r) & held.reindex(r.index).fillna(False).astype(bool)
    return {"n_overturn_held": int(either.sum()),
            "overturn_agree_held": float((t[either] == r[either]).mean()) if either.any() else np.nan}


def held_misses(table: pd.DataFrame) -> str:
    """:func:`overturn_misses`'s pooled agreement on the cases whose verdict the truth holds, per route."""
    lines = ["| route | cases where either overturns, verdict held | agreement (90 % interval) |", "|---|---|---|"]
    for route, group in table.dropna(subset=["overturn_agree_held"]).groupby("route", sort=False):
        either = int(group["n_overturn_held"].sum())
        both = int(round(float((group["overturn_agree_held"] * group["n_overturn_held"]).sum())))
        low, high = binomial_interval(both / either, either, 0.90)
        lines.append(f"| {route} | {either} | {both / either:.2f} ({low:.2f}-{high:.2f}) |")
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--levels", default="DE")
    parser.add_argument("--buildings", default=",".join(BUILDINGS),
                        help=f"comma-separated, of {', '.join(TRUTHS)} "
                             "(peers.opensees_buildings; "
                             "bf6, the braced frame, bf6b, the same with braces that buckle, and smf12, the 12-storey "
                             "frame, are checked on their own)")
    parser.add_argument("--motions", type=int, default=11)
    parser.add_argument("--skip", default="",
                        help="records of peers.yielding_equipment.RECORDS to leave out (comma-separated), e.g. one "
                             "whose peak, scaled to a long T_1, passes the workbook's 5 g check")
    parser.add_argument("--overstrengths", default="1.5,2,3")
    parser.add_argument("--truth-strengths", default="",
                        help="add the routes 'truth, strength x f' for these f (comma-separated): the OpenSees "
                             "building with its strengths times f, against itself")
    parser.add_argument("--truth-floors", default="",
                        help="add the routes 'truth, floors x f' for these f (comma-separated): the OpenSees "
                             "building's own floor histories times f, against themselves")
    parser.add_argument("--truth-alphas", default="",
                        help="add, for the frames, OpenSees buildings whose column has these α (comma-separated) "
                             "in place of their own 10, each against the routes 'given' (the system's α) and "
                             "'given + α' (lateral_stiffness_ratio the building's)")
    parser.add_argument("--own-alpha", action="store_true",
                        help="add the routes 'given + own α': yield_base_shear_g and the building's own α in "
                             "lateral_stiffness_ratio (peers.yielding_equipment.own_alpha), and 'given + own α + "
                             "own stiffness': those and its storey stiffnesses in storey_stiffness (its model's)")
    parser.add_argument("--alpha-bracket", action="store_true",
                        help="run 'given' (and 'given, truth α a') with --alpha-range at the system's ends, and "
                             "add whether each item's truth lies within what the ends and the system's α give")
    parser.add_argument("--pushover-slope", action="store_true",
                        help="add, for the frames, the route 'given + pushover slope': yield_base_shear_g and the "
                             "same pushover's slope at 2 %% roof drift over its initial slope in pushover_slope_ratio "
                             "(peers.yielding_equipment.given_pushover; the tool finds its α from it)")
    parser.add_argument("--own-hardening", action="store_true",
                        help="add to 'given', 'given + pushover slope' and 'design' (the first two also with "
                             "--truth-alphas) a route "
                             "that also writes the OpenSees springs' hardening in storey_hardening_ratio "
                             "(peers.yielding_equipment.own_hardening); with --truth-profile, the latter with the "
                             "truth's storey stiffnesses too")
    parser.add_argument("--brace-buckling", action="store_true",
                        help="for braced frames, add the routes 'given + brace buckling' and 'design + brace "
                             "buckling': the building sheet's brace_buckling yes (the tool's buckling braces)")
    parser.add_argument("--strength-factor", type=float, default=1.0,
                        help="every truth building's storeys (or hinge) this many times as strong (and its pushover "
                             "strength with them), e.g. 0.6 for a frame that yields more")
    parser.add_argument("--own-strength", action="store_true",
                        help="add the route 'given + own α + own stiffness + own strength + own hardening' (and, with "
                             "--truth-alphas, the same at each α): the building's whole model, its storey strengths "
                             "in storey_strength (peers.yielding_equipment.whole_model)")
    parser.add_argument("--truth-profile", action="store_true",
                        help="add the route 'given + truth's stiffness': yield_base_shear_g and the OpenSees "
                             "building's storey stiffnesses in storey_stiffness")
    args = parser.parse_args(argv)
    rows, ratios = [], []
    start = time.perf_counter()
    for name in args.buildings.split(","):
        truth = TRUTHS[name] if args.strength_factor == 1.0 else stronger(TRUTHS[name], args.strength_factor)
        for level in args.levels.split(","):
            skip = tuple(filter(None, args.skip.split(",")))
            suite = ground_suite(args.motions, truth.period_s, LEVELS[level], skip)
            with tempfile.TemporaryDirectory() as tmp:
                folder = Path(tmp)
                given = given_routes(truth)
                routes = given if args.own_alpha else {"given": given["given"]}
                if args.pushover_slope and np.isfinite(getattr(truth, "column_alpha", np.inf)):
                    routes[PUSHOVER_ROUTE] = given_pushover(truth)
                if args.own_hardening:
                    routes.update({route + OWN_HARDENING: rows + own_hardening(truth)
                                   for route, rows in list(routes.items()) if route in ("given", PUSHOVER_ROUTE)})
                if args.truth_profile and own_stiffness(truth) is not None:
                    stiffness = [["storey_stiffness", own_stiffness(truth)]]
                    routes["given + truth's stiffness"] = routes["given"] + stiffness
                    if args.own_hardening and PUSHOVER_ROUTE + OWN_HARDENING in routes:
                        routes[PUSHOVER_ROUTE + OWN_HARDENING + " + truth's stiffness"] = given_pushover_model(truth)
                whole = whole_model(truth) if args.own_strength else None
                if whole is not None:
                    routes[GIVEN_STRENGTHS] = given_strengths(truth)
                    routes[WHOLE_MODEL] = whole
                routes["design"] = [["response", "yielding"]]
                if args.own_hardening:
                    routes["design" + OWN_HARDENING] = routes["design"] + own_hardening(truth)
                for omega in filter(None, args.overstrengths.split(",")):
                    routes[f"design x {omega}"] = [["response", "yielding"], ["overstrength", float(omega)]]
                if args.brace_buckling and truth.system == "braced frame":
                    buckling = [["brace_buckling", "yes"]]
                    routes.update({"given + brace buckling": routes["given"] + buckling,
                                   "design + brace buckling": routes["design"] + buckling})
                routes["elastic"] = [["response", "elastic"]]
                reference = truth_result(truth, suite, level, folder)
                bracket = ALPHA_RANGE_BY_SYSTEM[truth.system] if args.alpha_bracket else None
                results = {route: assess(workbook(folder, truth, suite, level, extra), level,
                                         bracket if route == "given" else None)
                           for route, extra in routes.items()}
                for factor in filter(None, args.truth_strengths.split(",")):
                    results[f"truth, strength x {factor}"] = truth_result(stronger(truth, float(factor)), suite,
                                                                          level, folder)
                for factor in filter(None, args.truth_floors.split(",")):
                    results[f"truth, floors x {factor}"] = truth_result(truth, suite, level, folder, float(factor))
                framed = np.isfinite(getattr(truth, "column_alpha", np.inf))  # the frames' column; walls have none
                for alpha in filter(None, args.truth_alphas.split(",")) if framed else ():
                    other = dataclasses.replace(truth, column_alpha=float(alpha))
                    strength = given_strength(other)
                    other_reference = truth_result(other, suite, level, folder)
                    other_routes = [(f"given, truth α {alpha}", strength),
                                    (f"given + α, truth α {alpha}",
                                     strength + [["lateral_stiffness_ratio", float(alpha)]])]
                    if args.pushover_slope:
                        other_routes.append((f"{PUSHOVER_ROUTE}, truth α {alpha}", given_pushover(other)))
                    if args.own_hardening:
                        other_routes += [(f"{route.split(',')[0]}{OWN_HARDENING}, truth α {alpha}",
                                          extra + own_hardening(other)) for route, extra in list(other_routes)
                                         if route.startswith(("given,", PUSHOVER_ROUTE))]
                    if args.truth_profile:
                        stiffness = [["storey_stiffness", own_stiffness(other)]]
                        other_routes.append((f"given + α + truth's stiffness, truth α {alpha}",
                                             strength + [["lateral_stiffness_ratio", float(alpha)]] + stiffness))
                        if args.own_hardening and args.pushover_slope:
                            other_routes.append((f"{PUSHOVER_ROUTE}{OWN_HARDENING} + truth's stiffness, "
                                                 f"truth α {alpha}", given_pushover_model(other)))
                    if args.own_strength:
                        other_routes.append((f"{GIVEN_STRENGTHS}, truth α {alpha}", given_strengths(other)))
                        other_routes.append((f"given + α + own model + own strength, truth α {alpha}",
                                             whole_model(other)))
                    for route, extra in other_routes:
                        tool = assess(workbook(folder, other, suite, level, extra), level,
                                      bracket if route.startswith("given,") else None)
                        rows.append({"building": name, "level": level, "route": route,
                                     **compare(tool, other_reference), **bracket_held(tool, other_reference)})
            perturbed = [v for k, v in results.items() if k.startswith("truth, floors x ")]
            held = verdict_held(reference, perturbed) if perturbed else None
            for route, result in results.items():
                rows.append({"building": name, "level": level, "route": route, **compare(result, reference),
                             **bracket_held(result, reference),
                             **(held_agreement(result, reference, held)
                                if held is not None and not route.startswith("truth, floors") else {})})
            r_factor, omega0 = SYSTEM_R[truth.system]
            r_mu = max(np.sqrt(1.1 * r_factor / omega0), 1.3)
            for route, result in [("truth", reference)] + [(k, v) for k, v in results.items()
                                                           if k in ("given", "design")]:
                floors = result[0].floors.set_index("floor")
                for floor in (truth.storeys // 2, truth.storeys):
                    z = floor / truth.storeys
                    ratios.append({"building": name, "level": level, "route": route, "floor": floor,
                                   "pfa_over_pga": floors.loc[floor, "pfa_over_pga_median"],
                                   "hf_over_rmu": float(height_factor(z, truth.period_s)) / r_mu,
                                   "ductility_max_any_storey": floors["ductility_max"].max(),
                                   "ductility_median_top_storey": floors.loc[truth.storeys, "ductility_median"],
                                   "ductility_max_top_storey": floors.loc[truth.storeys, "ductility_max"],
                                   "drift_max": floors["drift_ratio_max"].max()})
            print(f"{name} {level}: done ({time.perf_counter() - start:.0f} s)", file=sys.stderr)
    table = pd.DataFrame(rows)
    pd.set_option("display.width", 200)
    print(markdown(table))
    print()
    pooled = []
    for route, group in table.groupby("route", sort=False):
        pooled.append({"route": route, "gm (range over buildings)": f"{group['gm'].min():.2f}-{group['gm'].max():.2f}",
                       "sigma_ln max": round(group["sigma_ln"].max(), 2),
                       "sigma_ln max, its 90 % interval over the motions": (
                           "{:.2f}-{:.2f}".format(*group.loc[group["sigma_ln"].idxmax(),
                                                             ["sigma_ln_low", "sigma_ln_high"]])),
                       "overturn agree min": round(group["overturn_agree"].min(), 2),
                       "overturn class agree min": round(group["overturn_class_agree"].min(), 2),
                       "class agree min": round(group["class_agree"].min(), 2),
                       "class misses, one motion away": (f"{int(group['n_class_missed'].sum())}, "
                                                         f"{int(group['class_missed_one_motion'].sum())}")})
    print(markdown(pd.DataFrame(pooled)))
    print()
    print(pooled_targets(table))
    print()
    print(overturn_misses(table))
    print()
    if "overturn_agree_held" in table:
        print(held_misses(table))
        print()
    print(markdown(pd.DataFrame(ratios)))
    print(f"\ntotal {time.perf_counter() - start:.0f} s")


if __name__ == "__main__":
    main()
