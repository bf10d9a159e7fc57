"""What to do about each item, from its governing demand: the decisions stage of an assessment.

- :mod:`assess.decision.decisions`: the stage itself (:func:`~assess.decision.decisions.decide`), a pure
  function of an item's demand and the settings; it calls the three modules below.
- :mod:`assess.decision.risk_classes`: the risk class, each failure mode's probability against a threshold.
- :mod:`assess.decision.actions`: the action that fits the item, what it would change, the work orders.

Everything here is numbers (SI) and kinds; the words are :mod:`assess.report.advice`'s.
- :mod:`assess.decision.costs`: expected loss, expected annual loss and the action's benefit-cost ratio.

The anchorage design forces (ASCE 7 Chapter 13) the decisions quote are :mod:`assess.anchorage`, beside
this package: the workbook reader checks component types against its table before anything is decided.
"""
