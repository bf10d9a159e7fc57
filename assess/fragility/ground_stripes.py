"""Stripes of ground acceleration through the building: one fragility in PGA per item, whatever the level.

Where a building sheet gives the floors' motions (each floor's history is a
ground history of the level's suite through the building: its elastic modes,
:mod:`assess.building.response`, or its yielding stick,
:mod:`assess.building.yielding`), the stripes of the hazard curve
(:mod:`assess.fragility.stripes`) are stripes of *ground* acceleration:

1. every ground history of the suite is scaled to a PGA x_j, for the
   :data:`~assess.fragility.stripes.N_STRIPES` values of
   :data:`~assess.fragility.stripes.STRIPE_PGA_G` evenly spaced in ln x
   (a pair of records by one factor that brings the larger peak to x_j, as at
   the floor);
2. the scaled ground histories pass through the building
   (:func:`assess.building.yielding.through_building`: the level's elastic
   modes or yielding stick) to the
   floors the items stand on; the items of a floor run under its histories,
   the ground floor's under the scaled ground histories (the engine, both base
   directions, as for the floor stripes);
3. the fragility is fitted in PGA directly, refined where the failures jump,
   and integrated over the curve with PFA/PGA = 1: the building's
   amplification, its frequency content and the record-to-record scatter of
   the floor are all inside the simulated outcomes, rather than a median
   ratio moving a floor's fragility to the ground.

The stripes are fixed in PGA, so they depend neither on the curve (a new curve
re-integrates the same outcomes: the cache answers every run) nor on the
amplitude of the level's suite: the same ground histories give the same
fragilities at any level, which is why the job computes them once, from its
first level's suite, and gives every level the same rates
(:func:`assess.command.job.run_job`).

An elastic building is linear, so a floor history under a scaled ground
history is the scaled floor history; the histories are still passed through
the building at each stripe, as documented, and equal the scaled ones to
rounding. A yielding building (``response: yielding``,
:mod:`assess.building.yielding`) is not: each stripe's scaled ground
histories pass through its nonlinear stick, so that a stronger stripe yields
its storeys more and its floors' motions are not the scaled weaker ones. Below
its first yield, though, the stick is linear: the stripes pass through it from
the strongest down, and a ground history's copy weaker than one that yielded no
storey takes the elastic route's floors without running the stick
(:class:`~assess.building.yielding.ElasticBound`), the same floors the stick
would give (it gives the elastic route's wherever no storey yields).
Where a stripe drives its storeys' drift past what the stick is trusted to
(:attr:`~assess.building.yielding.YieldingBuilding.drift_limit`), its outcomes
still count, and the curve's notes say at which stripes and under how many
ground histories (:func:`beyond_drift_note`), as ``floors.csv`` says it of the
level's suite.
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from assess.building.yielding import ElasticBound, YieldingBuilding, pass_progress, through_building
from assess.quantity_text import floor_text
from assess.fragility.stripes import (N_STRIPES, STRIPE_PGA_G, CurveRisk, FloorItems, StripeBatch, checked_curve,
                                      fit_and_integrate, stripe_levels_g)

#: Opens every item's ``curve_note`` when its fragility is in ground acceleration.
NOTE = "fragility in PGA (ground), through the building"


def ground_sources(cases: pd.DataFrame, level_table: pd.DataFrame) -> dict[int, int] | None:
    """``{motion_key: ground motion_key}`` for every motion of ``cases`` when each is either a ground motion
    of the level (floor 0) that the building passes to the floors, or a floor's motion through the building
    (``from_ground`` >= 0); None otherwise (no building, or a floor with its own motions: the stripes stay
    stripes of floor acceleration, :func:`assess.fragility.stripes.curve_risk`)."""
    if "from_ground" not in level_table or not (level_table["from_ground"] >= 0).any():
        return None
    table = level_table.set_index("motion_key")
    sources = set(int(k) for k in table.loc[table["from_ground"] >= 0, "from_ground"])
    out = {}
    for key in set(int(k) for k in cases["motion_key"]):
        from_ground = int(table.at[key, "from_ground"])
        if from_ground >= 0:
            out[key] = from_ground
        elif key in sources:
            out[key] = key
        else:
            return None
    return out


def ground_histories(cases: pd.DataFrame, floor: int, motions: dict, sources: dict,
                     record_pairs: dict) -> list:
    """The ground histories behind a floor's motions, in the order of its motions (``motion_key``) and
    their histories: ``(width, depth)`` per history (the same record twice without a pair)."""
    keys = sorted(set(int(k) for k in cases.loc[cases["floor"] == floor, "motion_key"]))
    out = []
    for key in keys:
        ground = sources[key]
        if ground in record_pairs:
            out.append(record_pairs[ground])
        else:
            out.extend((record, record) for record, _ in motions[ground])
    return out


def stripe_histories(modes, ground: list, pga_g: float, floors, progress=None,
                     bound: ElasticBound | None = None) -> tuple[dict[int, list], list[bool]]:
    """Per floor of ``floors``: ``(width, depth)`` histories under each ground history of ``ground`` scaled
    to PGA ``pga_g`` [g] (a pair by one factor: its larger peak at ``pga_g``) and passed through the
    building (:func:`assess.building.yielding.through_building`); floor 0 gets the scaled ground histories.
    With them, per ground history of ``ground``, whether a yielding building's storey drift passed its limit
    under it (either component of a pair; never for elastic modes, nor without a floor above the ground).
    ``bound``, where given, keeps what a yielding building did under each ground history from one stripe to the
    next: a copy weaker than one that yielded no storey is not run through its stick again
    (:class:`~assess.building.yielding.ElasticBound`)."""
    scaled, factors = [], []
    for first, second in ground:
        factor = pga_g / max(float(np.max(np.abs(first.accel_g))), float(np.max(np.abs(second.accel_g))))
        scaled.append((first.scaled(factor), second.scaled(factor) if second is not first else None))
        factors.append(factor)
    wanted = sorted(set(int(f) for f in floors))
    upper = [f for f in wanted if f > 0]
    paired = [k for k, (_, d) in enumerate(scaled) if d is not None]
    # every history of the stripe (each pair's second after the firsts) through the building in one pass
    scaled_from = None if bound is None else ([w for w, _ in ground] + [ground[k][1] for k in paired],
                                              factors + [factors[k] for k in paired], bound)
    through, beyond = through_building(modes, [w for w, _ in scaled] + [scaled[k][1] for k in paired],
                                       floors=upper, progress=progress, scaled_from=scaled_from) \
        if upper else ({}, [False] * len(scaled))
    depth_at = {k: len(scaled) + j for j, k in enumerate(paired)}
    beyond_any = [bool(beyond[k]) or (k in depth_at and bool(beyond[depth_at[k]])) for k in range(len(scaled))]
    out = {}
    for floor in wanted:
        histories = []
        for k, (w, d) in enumerate(scaled):
            first = w if floor == 0 else through[floor][k]
            if d is None:
                histories.append((first, first))
            else:
                histories.append((first, d if floor == 0 else through[floor][depth_at[k]]))
        out[floor] = histories
    return out, beyond_any


def ground_stripe_runs(cases: pd.DataFrame, motions: dict, sources: dict, modes, plan, runner,
                       progress=None, record_pairs: dict | None = None, say=None,
                       beyond: dict | None = None, bound: ElasticBound | None = None) -> pd.DataFrame:
    """Simulate items under their floor's histories for the ground suite scaled to stripes of PGA.

    ``plan``: ``(floor, pga_g, ids)`` as for :func:`assess.fragility.stripes.stripe_runs` (``pga_g`` in
    place of the floor's PFA); the same columns are returned, ``pfa_g`` holding the stripe's PGA [g].
    ``say(text)``, where given, hears how far each stripe's pass through a yielding building has got.
    ``beyond``, where given, gathers ``{pga_g: [flag per ground history passed]}``: whether each pass took the
    storeys' drift past the building's limit (:func:`stripe_histories`). The stripes pass through the building
    from the strongest down, so that ``bound`` (:func:`stripe_histories`), where given, spares the stick the
    copies of a ground history weaker than one that yielded no storey.
    """
    record_pairs = record_pairs or {}
    per_item = cases.drop_duplicates(["id", "direction"])
    ground_of = {}
    at_stripe = {}
    for floor, pga_g, _ in plan:
        at_stripe.setdefault(pga_g, set()).add(floor)
    histories_at = {}
    for pga_g, floors in sorted(at_stripe.items(), reverse=True):
        for floor in floors:
            if floor not in ground_of:
                ground_of[floor] = ground_histories(cases, floor, motions, sources, record_pairs)
        by_ground = {}  # floors under the same ground histories pass through the building together
        for floor in floors:
            by_ground.setdefault(tuple(id(w) for w, _ in ground_of[floor]), []).append(floor)
        for group in by_ground.values():
            through, flags = stripe_histories(modes, ground_of[group[0]], pga_g, group,
                                              progress=pass_progress(say, f"stripe {pga_g:.3g} g: ") if say else None,
                                              bound=bound)
            if beyond is not None:
                beyond.setdefault(pga_g, []).extend(flags)
            for floor in group:
                histories_at[(floor, pga_g)] = through[floor]
    batch = StripeBatch()
    for floor, pga_g, ids in plan:
        on_floor = per_item[per_item["floor"] == floor]
        if ids is not None:
            on_floor = on_floor[on_floor["id"].isin(ids)]
        on_floor = FloorItems.of(on_floor)
        for h, (first, second) in enumerate(histories_at[(floor, pga_g)]):
            batch.add(first, second, on_floor, pga_g, h)
    return batch.run(runner, progress)


def max_peak_ratio(modes, ground: list, floor: int) -> float:
    """The largest peak of the floor's histories over the peak of their ground history (a pair: its larger
    component) [-]; 1 at the ground for a single record. A linear building: the same at every stripe. A
    yielding building (:class:`~assess.building.yielding.YieldingBuilding`): the larger of its elastic
    modes' ratio (what it does under a stripe too weak to yield it) and its ratio at 1 g (yielding lowers
    it, so the elastic one is the larger in practice)."""
    def ratio(building, pga_g):
        through = stripe_histories(building, ground, pga_g, [floor])[0][floor]
        return max(max(float(np.max(np.abs(w.accel_g))), float(np.max(np.abs(d.accel_g)))) / pga_g
                   for w, d in through)

    if isinstance(modes, YieldingBuilding):
        return max(ratio(modes.modes, 1.0), ratio(modes, 1.0))
    return ratio(modes, 1.0)


def ground_curve_risk(cases: pd.DataFrame, motions: dict, sources: dict, modes, hazard, runner,
                      progress=lambda message: None, record_pairs: dict | None = None,
                      level_label: str = "", numbering: str = "ground_0") -> CurveRisk:
    """Fragility per item and failure mode over stripes of ground acceleration through the building
    (module docstring), integrated over ``hazard``; ``sources`` from :func:`ground_sources`."""
    levels_g, rates_per_yr = checked_curve(hazard)
    record_pairs = record_pairs or {}
    floors, stripes_by_floor = {}, {}
    for floor in sorted(set(int(f) for f in cases["floor"])):
        ground = ground_histories(cases, floor, motions, sources, record_pairs)
        through = "" if floor == 0 else " and passed through the building"  # the ground floor stands on them
        floors[floor] = {"pfa_per_pga": 1.0, "max_peak_ratio": max_peak_ratio(modes, ground, floor),
                         "basis": (f"floor {floor_text(floor, numbering)}: stripes of ground acceleration, the ground "
                                   f"suite of level {level_label} scaled{through}")}
        stripes_by_floor[floor] = stripe_levels_g(1.0)
    progress(f"fragilities over the hazard curve: {N_STRIPES} stripes of ground acceleration "
             f"({STRIPE_PGA_G[0]:g} to {STRIPE_PGA_G[1]:g} g) passed through the building to "
             f"{len(floors)} floors")

    beyond = {}

    bound = ElasticBound()  # what the stick did under each ground history, from one stripe to the next

    def run_plan(plan, report=None):
        return ground_stripe_runs(cases, motions, sources, modes, plan, runner, progress=report,
                                  record_pairs=record_pairs, say=progress, beyond=beyond, bound=bound)

    prefix = f"{NOTE}, from the stripes of level {level_label}'s suite; " if level_label else f"{NOTE}; "
    risk = fit_and_integrate(cases, hazard, levels_g, rates_per_yr, floors, stripes_by_floor, run_plan, progress,
                             intensity="PGA", note_prefix=prefix)
    note = beyond_drift_note(beyond, getattr(modes, "drift_limit", None))
    if note:
        risk.notes.append(note)
    return risk


def beyond_drift_note(beyond: dict, drift_limit: float | None) -> str:
    """The curve's note on the stripes whose pass took a yielding building's storey drift past ``drift_limit``
    (``beyond``: ``{pga_g: [flag per ground history]}`` as :func:`ground_stripe_runs` gathers it); empty where
    none did.

    >>> beyond_drift_note({0.5: [False, False], 2.0: [True, False], 1.0: [False, True]},
    ...                   0.02)  # doctest: +NORMALIZE_WHITESPACE
    "the yielding building's storey drift passed its limit (2 %) at the stripes of 1 and 2 g (under 1 of 2 ground
    histories at 2 g): its floors' motions there come from a model past what it is trusted to, and those stripes'
    outcomes still count in the fragilities and rates"
    """
    passed = {pga: flags for pga, flags in sorted(beyond.items()) if any(flags)}
    if not passed or drift_limit is None:
        return ""
    levels = [f"{pga:.3g}" for pga in passed]
    top = max(passed)
    named = levels[0] if len(levels) == 1 else ", ".join(levels[:-1]) + " and " + levels[-1]
    return (f"the yielding building's storey drift passed its limit ({100 * drift_limit:g} %) at the stripe"
            f"{'s' if len(levels) > 1 else ''} of {named} g (under {sum(passed[top])} of {len(passed[top])} ground "
            f"histories at {top:.3g} g): its floors' motions there come from a model past what it is trusted to, "
            "and those stripes' outcomes still count in the fragilities and rates")
