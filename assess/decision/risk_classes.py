"""The risk class of an item: each failure mode's probability against a threshold, the worst class wins.

An item can fail in three ways over its suite of motions (its governing demand,
:mod:`assess.fragility.governing`), each with its probability:

* it **overturns** (``p_overturn``);
* it **slides past its room** (``p_beyond_clearance``): it hits a wall or a neighbour, pulls its
  lines, blocks a door;
* it **rocks and harms itself or its contents** without overturning (``p_rocking_harm``: its peak
  rotation reaches ``rocking_harm_theta_over_alpha`` of its tipping angle,
  :func:`assess.fragility.governing.rocking_harm`).

Each mode gives a class from its own thresholds (settings, docs/workbook.md), and the item takes the
worst. **Rocking that does not overturn is never** ``high`` **by itself**: at most ``moderate``.

Which modes count follows the item's performance objective, from its ``consequence``, with the
nonstructural performance levels of ASCE/SEI 41-17 §2.3.3 (and FEMA E-74, 2012, ch. 4):

* ``critical`` → **operational** (N-A): the item keeps working, so damage to it or its contents counts;
* ``hazardous``, ``valuable`` → **position retention** (N-B): it stays in place and its contents stay
  in it (a spill, a broken instrument counts);
* ``life-safety`` → **life safety** (N-C): it must not fall on people or block an exit; what falls
  out of it when it rocks hard (stock off a shelf) is the hazard, so rocking harm counts;
* ``ordinary`` → **life safety** (N-C): damage to an ordinary item that stays upright endangers
  nobody, so its rocking harm does not count (it is still reported).

Thresholds (defaults, assess/data/defaults.toml): overturning is ``high`` from 10 % and ``moderate``
from 2.5 %, the conditional probabilities of collapse given MCE_R shaking that ASCE 7-16 Table
C1.3.1(b) targets for Risk Categories I-II and IV (an overturn is the item's collapse); sliding past
the room keeps 50 % and 10 % (``risk_pf_*``); rocking harm is ``moderate`` from 10 %, the tolerance of
sliding past the room, another failure that damages without toppling.
"""
from __future__ import annotations

from dataclasses import dataclass

from assess.quantity_text import percent_text
from assess.inventory.settings import Settings

#: Share of an overturning's cost that sliding past the room carries (it hits, pulls its lines, blocks):
#: the weight of that mode in the order of action (:func:`assess.decision.decisions.priority_score`) and in the
#: loss (:mod:`assess.decision.costs`). A judgement.
SLIDING_SEVERITY = 0.5
#: Share of an overturning's cost that rocking which harms the item or its contents carries: it damages
#: the item or what it holds where it stands, without toppling or moving it (half of sliding's share: a
#: judgement, as the one above).
ROCKING_HARM_SEVERITY = 0.25

OPERATIONAL, POSITION_RETENTION, LIFE_SAFETY = "operational", "position retention", "life safety"
#: The performance objective (ASCE 41-17 nonstructural performance level) of each consequence.
OBJECTIVES = {"critical": OPERATIONAL, "hazardous": POSITION_RETENTION, "valuable": POSITION_RETENTION,
              "life-safety": LIFE_SAFETY, "ordinary": LIFE_SAFETY}
#: Classes in increasing order.
CLASS_ORDER = ("low", "moderate", "high")
#: The failure modes, in the order a reason lists them, and how a sentence names them.
MODE_WORDS = {"overturn": "overturning", "beyond_clearance": "sliding past its room",
              "rocking_harm": "rocking that harms it or its contents"}


@dataclass(frozen=True)
class Chances:
    """The probabilities of an item's failure modes over its suite [-] (:mod:`assess.fragility.governing`)."""

    overturn: float
    beyond_clearance: float
    rocking_harm: float

    @classmethod
    def of(cls, row, suffix: str = "") -> "Chances":
        """From a demand row's ``p_overturn<suffix>``, ``p_beyond_clearance<suffix>``, ``p_rocking_harm<suffix>``
        (``suffix`` ``""``, ``"_low"`` or ``"_high"`` for the ends of their intervals)."""
        return cls(float(row[f"p_overturn{suffix}"]), float(row[f"p_beyond_clearance{suffix}"]),
                   float(row[f"p_rocking_harm{suffix}"]))


def performance_objective(consequence: str) -> str:
    """The item's performance objective from its consequence (module docstring); ``life safety`` for an
    unknown one.

    >>> performance_objective("critical"), performance_objective("ordinary")
    ('operational', 'life safety')
    """
    return OBJECTIVES.get(str(consequence), LIFE_SAFETY)


def rocking_harm_counts(consequence: str) -> bool:
    """Whether rocking that harms the item or its contents counts towards its class: for every
    consequence but ``ordinary`` (module docstring)."""
    return str(consequence) != "ordinary"


def _class_from(probability: float, moderate: float, high: float | None) -> str:
    if high is not None and probability >= high:
        return "high"
    return "moderate" if probability >= moderate else "low"


def mode_classes(chances: Chances, consequence: str, settings: Settings) -> dict[str, str]:
    """The class each failure mode gives on its own (``overturn``, ``beyond_clearance``, ``rocking_harm``).

    >>> s = Settings(risk_overturn_high=0.1, risk_overturn_moderate=0.025, risk_pf_high=0.5,
    ...              risk_pf_moderate=0.1, risk_rocking_moderate=0.1)
    >>> mode_classes(Chances(0.05, 0.6, 1.0), "critical", s)
    {'overturn': 'moderate', 'beyond_clearance': 'high', 'rocking_harm': 'moderate'}
    """
    harm = (_class_from(chances.rocking_harm, settings.risk_rocking_moderate, None)
            if rocking_harm_counts(consequence) else "low")
    return {
        "overturn": _class_from(chances.overturn, settings.risk_overturn_moderate,
                                settings.risk_overturn_high),
        "beyond_clearance": _class_from(chances.beyond_clearance, settings.risk_pf_moderate,
                                        settings.risk_pf_high),
        "rocking_harm": harm,
    }


def classify_risk(chances: Chances, consequence: str, settings: Settings) -> str:
    """The item's risk class: the worst of its failure modes' classes (:func:`mode_classes`).

    The pharmacy's two-door refrigerator (critical) that slides 1-2 cm, never passes its room nor
    overturns and rocks to 0.05 of its tipping angle is low; shelving that overturns in 87 % of runs is high:

    >>> s = Settings(risk_overturn_high=0.1, risk_overturn_moderate=0.025, risk_pf_high=0.5,
    ...              risk_pf_moderate=0.1, risk_rocking_moderate=0.1)
    >>> classify_risk(Chances(0.0, 0.0, 0.0), "critical", s), classify_risk(Chances(0.87, 0.0, 0.1), "life-safety", s)
    ('low', 'high')
    """
    return max(mode_classes(chances, consequence, settings).values(), key=CLASS_ORDER.index)


def deciding_mode(chances: Chances, consequence: str, settings: Settings) -> str:
    """The failure mode that decides the class (``overturn``, ``beyond_clearance`` or ``rocking_harm``): the
    one with the largest chance among those at the item's class (for a low item, among those that count for
    it); overturning first among equals.

    >>> s = Settings(risk_overturn_high=0.1, risk_overturn_moderate=0.025, risk_pf_high=0.5,
    ...              risk_pf_moderate=0.1, risk_rocking_moderate=0.1)
    >>> deciding_mode(Chances(0.004, 0.78, 0.0), "critical", s), deciding_mode(Chances(0.2, 0.3, 0.0), "critical", s)
    ('beyond_clearance', 'overturn')
    """
    classes = mode_classes(chances, consequence, settings)
    risk = max(classes.values(), key=CLASS_ORDER.index)
    values = {"overturn": chances.overturn, "beyond_clearance": chances.beyond_clearance,
              "rocking_harm": chances.rocking_harm}
    candidates = [mode for mode in MODE_WORDS if classes[mode] == risk
                  and (mode != "rocking_harm" or rocking_harm_counts(consequence))]
    return max(candidates, key=lambda m: values[m])  # max keeps the first of equals: overturning first


def deciding_chance(chances: Chances, consequence: str, settings: Settings) -> str:
    """The one chance that decides the class, in a few words (:func:`deciding_mode`).

    >>> s = Settings(risk_overturn_high=0.1, risk_overturn_moderate=0.025, risk_pf_high=0.5,
    ...              risk_pf_moderate=0.1, risk_rocking_moderate=0.1)
    >>> deciding_chance(Chances(0.0, 0.69, 0.0), "critical", s), deciding_chance(Chances(0.0, 0.004, 0.0),
    ...                                                                         "critical", s)
    ('69% chance of sliding past its room', '<1% chance of sliding past its room')
    """
    mode = deciding_mode(chances, consequence, settings)
    value = {"overturn": chances.overturn, "beyond_clearance": chances.beyond_clearance,
             "rocking_harm": chances.rocking_harm}[mode]
    return f"{percent_text(value)} chance of {MODE_WORDS[mode]}"


def risk_range(risk: str, classes: set) -> str:
    """The classes the 90 % intervals of the item's chances span, when they span more than ``risk``
    (``classes``: :func:`classify_risk` at the lower and at the upper ends of every interval).

    >>> risk_range("moderate", {"low", "high"}), risk_range("low", {"low"})
    ('low to high', '')
    """
    classes = classes | {risk}
    if len(classes) == 1:
        return ""
    spanned = sorted(classes, key=CLASS_ORDER.index)
    return f"{spanned[0]} to {spanned[-1]}"


def rule_text(settings: Settings) -> str:
    """The class rule with the run's thresholds, in one sentence for the report's method.

    >>> s = Settings(risk_overturn_high=0.1, risk_overturn_moderate=0.025, risk_pf_high=0.5,
    ...              risk_pf_moderate=0.1, risk_rocking_moderate=0.1, rocking_harm_theta_over_alpha=0.5)
    >>> rule_text(s)[:96]
    'Each failure mode gives a class and the item takes the worst: overturning moderate from 2.5%, hi'
    """
    def pct(key):
        return f"{100.0 * getattr(settings, key):g}%"
    return (f"Each failure mode gives a class and the item takes the worst: overturning moderate from "
            f"{pct('risk_overturn_moderate')}, high from {pct('risk_overturn_high')} (ASCE 7-16 Table C1.3.1(b): "
            f"collapse given MCE_R shaking, Risk Category IV and I-II); sliding past the clearance moderate from "
            f"{pct('risk_pf_moderate')}, high from {pct('risk_pf_high')}; rocking that harms the item or its "
            f"contents (a peak rotation of {settings.rocking_harm_theta_over_alpha:g} of its tipping "
            f"angle or more without overturning) moderate from {pct('risk_rocking_moderate')} and never high, "
            "counted for every consequence but ordinary (ASCE 41-17 nonstructural performance levels: "
            "operational for critical items, position retention for hazardous and valuable ones, life safety "
            "for the others).")
