"""The caveats of an item's result: what the decisions, the calibration and the demand stage attach to an
item for the report and the CSVs to show (the ``flags`` column of summary.csv, docs/outputs.md)."""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Flag:
    """A caveat attached to one item's result (shown in the report and the CSVs)."""

    item_id: str
    code: str  # e.g. "uplift", "im_outside_fit", "derived_floor_motion"
    message: str
    #: What is this item's own in a few words ("46 in", "IM 0.06–0.16"), shown beside its id where the report
    #: gathers the flags of one cause into one (:func:`assess.report.sentences.flag_groups`); "" for none.
    detail: str = ""
    #: A length of the item's own [cm] that ``message`` and ``detail`` name as ``{length}``, written in the
    #: report's units by the report (:func:`assess.report.sentences.flag_text`); None for none.
    length_cm: float | None = None
