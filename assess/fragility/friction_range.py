"""The friction coefficient as a range: μ over ``mu_low``–``mu_high``, propagated to the governing demand.

μ is the least certain input of an item: Konstantinidis & Makris (2010) measured
0.23–0.31 by slow pull on their three prototypes and needed 0.13–0.20 to match
the shake table ([1] Table 3 and p.1470). An item whose workbook row gives
``mu_low`` and ``mu_high`` (docs/workbook.md) has its μ taken as a **triangular
distribution** on [``mu_low``, ``mu_high``] with its mode at the row's ``mu``:
the three-point estimate an engineer gives (least, most likely, most), and the
one distribution that uses all three numbers and no others. The workbook's
``mu`` stays the nominal value: the paper's regression columns beside the
governing demand, ``im`` and ``motions.csv`` are at ``mu``.

Representation
--------------
The distribution is carried by a few μ values (nodes) that always include
``mu_low``, ``mu`` and ``mu_high`` (so the class at either end is read off
runs at that end), spaced evenly on [``mu_low``, ``mu``] and on [``mu``,
``mu_high``], :data:`NODES_PER_SIDE_SLIDING` intervals a side for an item that
cannot uplift anywhere in the range, :data:`NODES_PER_SIDE_UPLIFT` for one
that can. The weight of a node is the probability the triangular density gives
to its hat function (the piecewise-linear interpolant of a function of μ
through the nodes, integrated exactly: Simpson's rule is exact for the
product of two linear functions on each interval), so that
Σ w = 1 and Σ w μ = (``mu_low`` + ``mu`` + ``mu_high``)/3, the mean.

Every case of the item runs at every node, ``mu_static`` scaled with μ
(μs/μ of the row kept: the static excess is a property of the surfaces, not
of the measurement), and the governing demand weighs each run by its motion's
weight × its history's share × its node's weight
(:func:`assess.fragility.governing.governing_demand`).

Is the response monotone in μ? Not in general, so no μ value is left out on
that ground. Measured (``benchmarks/bench_mu_monotone.py``: lab.xlsx's 33
freestanding items × 2 directions × pyslammer's 18 records at PGA 0.5 and
1.0 g, 9 μ values over each item's range): where the item cannot uplift
(exact sliding kernel), the peak sliding grows somewhere in the range in 218
of 1584 sequences (14 %) and a μ inside the range slides farther than both
ends in 91 (6 %), by up to 20 % of the larger end (4.7 cm): two-way Coulomb
sliding depends on when the block stops, and a slightly larger μ can stop it
at a moment that lets the next pulse carry it farther. Where rocking can take
over it is far from monotone: the mode changes within the range in 412 of
792 sequences and the item overturns at a μ and not at a smaller one in 53.
Hence :data:`NODES_PER_SIDE_SLIDING` = 4 where the item cannot uplift (on
lab.xlsx's six prototypes, P(sliding > clearance) then lies within 0.013 of
its value with 8 a side; 1 a side was 0.12 off and changed a class) and
:data:`NODES_PER_SIDE_UPLIFT` = 8 where it can. The class "at ``mu_low``" and
"at ``mu_high``" the report gives are the ends' own (every run at that μ);
the non-monotonicity means the range's worst μ may lie inside, which the
weighted class over all nodes takes in.

References
----------
.. [1] Konstantinidis, D., Makris, N. (2010). Experimental and analytical
   studies on the response of 1/4-scale models of freestanding laboratory
   equipment subjected to strong earthquake shaking. Bull. Earthquake Eng.
   8:1457-1477, Table 3 p.1467. doi:10.1007/s10518-010-9192-8
"""
from __future__ import annotations

import numpy as np
import pandas as pd

from assess.fragility.governing import ROCKING_HARM_THETA_OVER_ALPHA, governing_demand
from assess.mechanics.gateway import pure_sliding_proved

#: Intervals a side of the nominal μ for an item that cannot uplift anywhere in its range.
NODES_PER_SIDE_SLIDING = 4
#: Intervals a side for an item that may uplift inside its range (the response is not monotone in μ).
NODES_PER_SIDE_UPLIFT = 8
#: Columns :func:`expand_cases` adds to the cases.
NODE_COLUMNS = ("mu_node", "mu_weight", "mu_nominal", "mu_end")


def triangular_density(mu, mu_low, mu_mode, mu_high):
    """Density of the triangular distribution on [``mu_low``, ``mu_high``] with mode ``mu_mode`` [1/-].

    .. math:: p(\\mu) = \\frac{2(\\mu - a)}{(c - a)(m - a)}\\ (a \\le \\mu \\le m),\\quad
              \\frac{2(c - \\mu)}{(c - a)(c - m)}\\ (m < \\mu \\le c)

    >>> float(triangular_density(0.18, 0.13, 0.13, 0.23))  # mode at the low end: 2/(c-a) * (c-mu)/(c-a)
    10.000000000000002
    """
    mu = np.asarray(mu, dtype=float)
    a, m, c = float(mu_low), float(mu_mode), float(mu_high)
    with np.errstate(divide="ignore", invalid="ignore"):
        rising = 2.0 * (mu - a) / ((c - a) * (m - a))
        falling = 2.0 * (c - mu) / ((c - a) * (c - m))
    on_rise = (mu >= a) & (mu <= m) & (m > a)
    on_fall = (mu >= m) & (mu <= c) & (c > m) & ~on_rise
    return np.where(on_rise, rising, np.where(on_fall, falling, 0.0))


def friction_nodes(mu_low: float, mu: float, mu_high: float, per_side: int = NODES_PER_SIDE_SLIDING):
    """The μ values and weights standing for the triangular distribution (``mu_low``, mode ``mu``, ``mu_high``).

    Returns ``(nodes, weights)``, ascending, the ends and ``mu`` among the
    nodes; weights sum to 1 (module docstring).

    >>> nodes, weights = friction_nodes(0.13, 0.13, 0.23, per_side=1)
    >>> nodes.tolist(), weights.round(12).tolist()  # mode at the low end: 2/3 and 1/3
    ([0.13, 0.23], [0.666666666667, 0.333333333333])
    """
    if not mu_low <= mu <= mu_high:
        raise ValueError("mu_low <= mu <= mu_high is required")
    if mu_high == mu_low:
        return np.array([float(mu)]), np.array([1.0])
    left = np.linspace(mu_low, mu, per_side + 1) if mu > mu_low else np.array([mu])
    right = np.linspace(mu, mu_high, per_side + 1)[1:] if mu_high > mu else np.array([])
    nodes = np.concatenate([left, right]).astype(float)
    weights = np.zeros(nodes.size)
    for j in range(nodes.size - 1):
        a, b = nodes[j], nodes[j + 1]
        pa, pm, pb = (float(triangular_density(x, mu_low, mu, mu_high)) for x in (a, 0.5 * (a + b), b))
        weights[j] += (b - a) / 6.0 * (pa + 2.0 * pm)  # hat 1, 1/2, 0 at a, mid, b (Simpson)
        weights[j + 1] += (b - a) / 6.0 * (2.0 * pm + pb)  # hat 0, 1/2, 1
    return nodes, weights


def has_range(cases: pd.DataFrame) -> pd.Series:
    """Rows whose item gives a μ range (``mu_low`` < ``mu_high``)."""
    if "mu_low" not in cases:
        return pd.Series(False, index=cases.index)
    return (np.isfinite(cases["mu_low"]) & np.isfinite(cases["mu_high"])
            & (cases["mu_high"] > cases["mu_low"]))


def expand_cases(cases: pd.DataFrame) -> pd.DataFrame:
    """Every case of an item with a μ range repeated at its μ nodes (:func:`friction_nodes`).

    Adds :data:`NODE_COLUMNS`: ``mu_node`` (0, 1, ... in ascending μ),
    ``mu_weight`` (the node's probability), ``mu_nominal`` (the node at the
    row's ``mu``: the case ``motions.csv`` and the regression columns show),
    ``mu_end`` (``low``, ``high`` or ""). ``mu`` and ``mu_static`` are the
    node's (μs scaled with μ); ``mu_range_nodes`` the item's node count.
    Items without a range keep one row per case, weight 1. Row order: the
    nominal cases first, in their order, then the other nodes.
    """
    ranged = has_range(cases)
    nominal = cases.assign(mu_node=0, mu_weight=1.0, mu_nominal=True, mu_end="", mu_range_nodes=1)
    if not ranged.any():
        return nominal
    slender = cases.groupby("id")["b_over_h"].transform("min")
    extra = []
    # the cases of one item share its range and its b/h: its nodes are computed once
    for _, rows in cases[ranged].groupby("id", sort=False):
        first = rows.iloc[0]
        mu, ratio = float(first["mu"]), float(first["mu_static"]) / float(first["mu"])
        proved = bool(pure_sliding_proved(float(first["mu_high"]) * ratio, float(slender[rows.index[0]])))
        nodes, weights = friction_nodes(float(first["mu_low"]), mu, float(first["mu_high"]),
                                        NODES_PER_SIDE_SLIDING if proved else NODES_PER_SIDE_UPLIFT)
        ends = ["low"] + [""] * (nodes.size - 2) + ["high"]
        for node, (value, weight) in enumerate(zip(nodes, weights)):
            fields = {"mu_node": node, "mu_weight": float(weight), "mu_end": ends[node], "mu_range_nodes": nodes.size}
            if np.isclose(value, mu, rtol=0.0, atol=1e-12):
                for column, field in fields.items():
                    nominal.loc[rows.index, column] = field
                continue
            extra.append(rows.assign(**fields, mu=float(value), mu_static=float(value) * ratio, mu_nominal=False))
    out = pd.concat([nominal, *extra], ignore_index=True)
    return out.astype({"mu_node": "int64", "mu_weight": "float64", "mu_nominal": "bool",
                       "mu_range_nodes": "int64"})


def at_end(cases: pd.DataFrame, runs: pd.DataFrame, end: str):
    """The cases and runs of the items with a μ range, all at one end of it (``low`` or ``high``), weight 1.

    ``runs['case']`` is renumbered to the returned cases' rows.
    """
    keep = has_range(cases) & (cases["mu_end"] == end)
    if end == "low":  # the nominal node holds the end where mu = mu_low
        keep |= has_range(cases) & cases["mu_nominal"] & np.isclose(cases["mu"], cases["mu_low"])
    if end == "high":
        keep |= has_range(cases) & cases["mu_nominal"] & np.isclose(cases["mu"], cases["mu_high"])
    positions = np.flatnonzero(keep.to_numpy())
    subset = cases.iloc[positions].assign(mu_weight=1.0).reset_index(drop=True)
    renumber = pd.Series(np.arange(positions.size), index=positions)
    chosen = runs[runs["case"].isin(positions)]
    return subset, chosen.assign(case=renumber[chosen["case"]].to_numpy())


def mu_dependence_sentence(item_id: str, mu_low: float, mu_high: float, risk: str, risk_low: str,
                           risk_high: str, why_low: str, why_high: str) -> str:
    """Whether the item's advice depends on where μ lies in its range, in one sentence from its numbers
    (``why_low``, ``why_high``: why it is in its class at each end, :func:`assess.decision.risk_classes.risk_reason`).

    >>> mu_dependence_sentence("INC-G-01", 0.13, 0.23, "high", "high", "low",
    ...                        "60% chance of sliding past its room",  # doctest: +NORMALIZE_WHITESPACE
    ...                        "0% chance of overturning, 0% of sliding past its room")
    'Its risk class depends on where mu lies in 0.13-0.23: high at mu = 0.13 (60% chance of sliding past its room), low
    at mu = 0.23 (0% chance of overturning, 0% of sliding past its room); over the range, weighted, high.'
    >>> mu_dependence_sentence("X", 0.2, 0.3, "low", "low", "low", "", "")
    'Its risk class is low wherever mu lies in 0.20-0.30.'
    """
    span = f"{mu_low:.2f}-{mu_high:.2f}"
    if risk_low == risk_high == risk:
        return f"Its risk class is {risk} wherever mu lies in {span}."
    return (f"Its risk class depends on where mu lies in {span}: {risk_low} at mu = {mu_low:.2f} "
            f"({why_low}), {risk_high} at mu = {mu_high:.2f} ({why_high}); over the range, weighted, {risk}.")


#: Columns the decisions add to the summary for an item with a range of friction
#: (:func:`assess.decision.decisions.mu_range_decisions`).
MU_RANGE_COLUMNS = ("mu_low", "mu_high", "risk_mu_low", "risk_mu_high", "p_beyond_clearance_mu_low",
                    "p_beyond_clearance_mu_high", "mu_range_note")


#: The governing demand's columns :func:`demand_at_ends` gives at each end of a μ range.
END_COLUMNS = ("p_beyond_clearance", "p_overturn", "p_rocking_harm", "demand_uplift")


def demand_at_ends(cases: pd.DataFrame, runs: pd.DataFrame, planar, constants,
                   room_quantile: float, harm_theta_over_alpha: float = ROCKING_HARM_THETA_OVER_ALPHA) -> pd.DataFrame:
    """Per item with a μ range (index ``id``): its range (``mu_low``, ``mu_high``) and its governing demand
    with every run at each end (:func:`at_end`, :func:`assess.fragility.governing.governing_demand`):
    ``<name>_<end>`` for ``name`` in :data:`END_COLUMNS` and ``end`` in low, high.
    Empty when no item gives a range."""
    ranged = cases[has_range(cases)]
    columns = ["mu_low", "mu_high"] + [f"{name}_{end}" for end in ("low", "high") for name in END_COLUMNS]
    if ranged.empty:
        return pd.DataFrame(columns=columns)
    ranges = ranged.drop_duplicates("id").set_index("id")[["mu_low", "mu_high"]]
    at = {end: governing_demand(*at_end(cases, runs, end), constants, room_quantile=room_quantile, planar=planar,
                                harm_theta_over_alpha=harm_theta_over_alpha)
          for end in ("low", "high")}
    ids = [item_id for item_id in ranges.index if item_id in at["low"].index]
    table = ranges.loc[ids].copy()
    for end in ("low", "high"):
        for name in END_COLUMNS:
            table[f"{name}_{end}"] = at[end].loc[ids, name].to_numpy()
    return table[columns]


def items_whose_class_changes(summary: pd.DataFrame) -> list[str]:
    """Ids of the items whose risk class at ``mu_low`` differs from that at ``mu_high``."""
    if "risk_mu_low" not in summary:
        return []
    changes = (summary["risk_mu_low"] != "") & (summary["risk_mu_low"] != summary["risk_mu_high"])
    return summary.loc[changes, "id"].astype(str).tolist()


def method_text(summary: pd.DataFrame) -> str:
    """The report's method paragraph on μ ranges ("" when no item gives one), from the summary."""
    if "mu_low" not in summary or not np.isfinite(summary["mu_low"].astype(float)).any():
        return ""
    count = int(np.isfinite(summary["mu_low"].astype(float)).sum())
    changing = items_whose_class_changes(summary)
    text = (f"{count} item{'s give' if count != 1 else ' gives'} a range for the friction coefficient (mu_low to "
            "mu_high). There mu is taken as a triangular distribution over the range with its mode at the "
            "item's mu, carried by several values that include both ends and mu (the response is not monotone "
            "in mu, so none is skipped: 9 values a range where the item cannot uplift, 17 where it can, fewer "
            "where mu is at an end); every case runs at each value, mu_s "
            "scaled with mu, and the governing demand weighs each run by its motion's weight times its mu "
            "value's weight. The risk class is also computed with every run at mu_low and at mu_high: ")
    if changing:
        text += (f"it changes for {len(changing)} item{'s' if len(changing) != 1 else ''} "
                 f"({', '.join(changing)}), whose advice therefore depends on where mu lies in the range "
                 "(each item's details say how).")
    else:
        text += "it is the same at both ends for every such item."
    return text
